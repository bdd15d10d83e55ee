#!/usr/bin/env bash
# Builds Pineda and its threads and API tests with ThreadSanitizer in build-tsan/ and runs them.
# Not part of scripts/test.sh (ThreadSanitizer cannot share a build with ASan); run it when
# threading code changes.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD_DIR:-build-tsan}
JOBS=${JOBS:-2}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPINEDA_TSAN=ON -DPINEDA_CONFORMANCE=OFF
cmake --build "$BUILD" -j "$JOBS" --target threads_tests api_tests
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1}
"$BUILD/tests/threads/threads_tests"
"$BUILD/tests/api_tests"
