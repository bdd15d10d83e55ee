#!/usr/bin/env bash
# Builds the libFuzzer harness (tests/fuzz) with clang, ASan and UBSan in build-fuzz/ and fuzzes
# for the given number of seconds (default 600), starting from the seed corpus. New inputs go to
# build-fuzz/corpus (the checked-in seeds stay untouched); crashes are written to
# build-fuzz/artifacts/ and make the script fail (TIMEOUT=<s> raises the per-input limit of 10 s
# on a loaded machine). Replay one with:
#   build-fuzz/tests/fuzz/gl_fuzzer build-fuzz/artifacts/crash-...
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_TO_RUN=${1:-600}
BUILD=${BUILD_DIR:-build-fuzz}
JOBS=${JOBS:-2}

CC=clang CXX=clang++ cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPINEDA_FUZZ=ON -DPINEDA_CONFORMANCE=OFF
cmake --build "$BUILD" -j "$JOBS" --target gl_fuzzer egl_fuzzer

mkdir -p "$BUILD/corpus" "$BUILD/artifacts"
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# A sixth of the time goes to the EGL API (egl_fuzzer, surfaceless platform), the rest to GL.
EGL_SECONDS=$((SECONDS_TO_RUN / 6 > 0 ? SECONDS_TO_RUN / 6 : 1))
GL_SECONDS=$((SECONDS_TO_RUN - EGL_SECONDS > 0 ? SECONDS_TO_RUN - EGL_SECONDS : 1))
mkdir -p "$BUILD/egl_corpus"
DISPLAY= "$BUILD/tests/fuzz/egl_fuzzer" "$BUILD/egl_corpus" tests/fuzz/egl_corpus \
  -max_total_time="$EGL_SECONDS" -max_len=2048 -timeout="${TIMEOUT:-10}" -rss_limit_mb=4096 \
  -artifact_prefix="$BUILD/artifacts/" -print_final_stats=1
"$BUILD/tests/fuzz/gl_fuzzer" "$BUILD/corpus" tests/fuzz/corpus \
  -max_total_time="$GL_SECONDS" -max_len=4096 -timeout="${TIMEOUT:-10}" -rss_limit_mb=4096 \
  -artifact_prefix="$BUILD/artifacts/" -print_final_stats=1
