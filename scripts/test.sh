#!/usr/bin/env bash
# Quick start, step 2: the tests. Builds Release and runs every ctest test (unit tests and the
# conformance scenes against OSMesa llvmpipe), then builds with ASan+UBSan and runs the same
# tests again, then replays the fuzzer's seed corpus and fuzzes for FUZZ_SECONDS (default 60).
# .ci/run runs exactly this.
set -euo pipefail
cd "$(dirname "$0")/.."
JOBS=${JOBS:-$(nproc)}

scripts/deps.sh

echo "== Release build and tests"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$JOBS"
ctest --test-dir build -j "$JOBS" --output-on-failure

echo "== ASan+UBSan build and tests"
# Line tables only (-g1): sanitizer reports still give file and line, and the template-heavy
# back end compiles much faster than with full debug information. Only the executables this job
# runs are built (the sanitize_tests target).
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPINEDA_SANITIZE=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG"
cmake --build build-asan -j "$JOBS" --target sanitize_tests
export ASAN_OPTIONS=abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# The GLX tests also start Xvfb and unmodified programs (glxinfo, libglfw), which are not
# instrumented and cannot load an instrumented libGL.so.1; they run in the Release half only.
ctest --test-dir build-asan -j "$JOBS" --output-on-failure -L sanitize -LE glx

echo "== Fuzzing: the seed corpus, then ${FUZZ_SECONDS:-60} s of new inputs (clang, ASan+UBSan)"
JOBS=$JOBS scripts/fuzz.sh "${FUZZ_SECONDS:-60}"
