#!/usr/bin/env bash
# Builds the libFuzzer harnesses (tests/fuzz) with clang, ASan and UBSan in build-fuzz/ and fuzzes
# for the given number of seconds (default 600), starting from the seed corpora. New inputs go to
# build-fuzz/corpus, egl_corpus and glsl_corpus (the checked-in seeds stay untouched); crashes
# are written to build-fuzz/artifacts/ and make the script fail (TIMEOUT=<s> raises the
# per-input limit of 10 s on a loaded machine). FUZZERS="gl egl glsl" (the default) picks the
# harnesses: the time is split 1/6 EGL, 1/3 GLSL and the rest GL among those picked. Replay one
# with:
#   build-fuzz/tests/fuzz/gl_fuzzer build-fuzz/artifacts/crash-...
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_TO_RUN=${1:-600}
BUILD=${BUILD_DIR:-build-fuzz}
JOBS=${JOBS:-2}

CC=clang CXX=clang++ cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPINEDA_FUZZ=ON -DPINEDA_CONFORMANCE=OFF
FUZZERS=${FUZZERS:-gl egl glsl}
has() { [[ " $FUZZERS " == *" $1 "* ]]; }
TARGETS=()
for f in $FUZZERS; do TARGETS+=("${f}_fuzzer"); done
cmake --build "$BUILD" -j "$JOBS" --target "${TARGETS[@]}"

mkdir -p "$BUILD/corpus" "$BUILD/egl_corpus" "$BUILD/glsl_corpus" "$BUILD/artifacts"
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# Shares of the time: EGL 1, GLSL 2, GL 3 (of those picked).
share() { has "$1" && echo "$2" || echo 0; }
PARTS=$(($(share egl 1) + $(share glsl 2) + $(share gl 3)))
seconds_for() {
  local s=$((SECONDS_TO_RUN * $1 / PARTS))
  echo $((s > 0 ? s : 1))
}
if has egl; then
  DISPLAY= "$BUILD/tests/fuzz/egl_fuzzer" "$BUILD/egl_corpus" tests/fuzz/egl_corpus \
    -max_total_time="$(seconds_for 1)" -max_len=2048 -timeout="${TIMEOUT:-10}" \
    -rss_limit_mb=4096 -artifact_prefix="$BUILD/artifacts/" -print_final_stats=1
fi
if has glsl; then
  # Seeds are piglit programs of up to 6000 bytes (tools/piglit_glsl_pairs.py --max-bytes).
  "$BUILD/tests/fuzz/glsl_fuzzer" "$BUILD/glsl_corpus" tests/fuzz/glsl_corpus \
    -max_total_time="$(seconds_for 2)" -max_len=8192 -timeout="${TIMEOUT:-10}" \
    -rss_limit_mb=4096 -artifact_prefix="$BUILD/artifacts/" -print_final_stats=1
fi
if has gl; then
  "$BUILD/tests/fuzz/gl_fuzzer" "$BUILD/corpus" tests/fuzz/corpus \
    -max_total_time="$(seconds_for 3)" -max_len=4096 -timeout="${TIMEOUT:-10}" \
    -rss_limit_mb=4096 -artifact_prefix="$BUILD/artifacts/" -print_final_stats=1
fi
