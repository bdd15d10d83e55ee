#!/usr/bin/env bash
# Quick start, step 1: install what is needed, build Release, and run the main job: the
# conformance diff of every scene against Mesa's OSMesa (llvmpipe and softpipe). Prints the
# table and writes conformance-out/report.html.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
JOBS=${JOBS:-$(nproc)}

scripts/deps.sh
cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD" -j "$JOBS"
"$BUILD"/conformance/pineda_conformance --out conformance-out "$@"
