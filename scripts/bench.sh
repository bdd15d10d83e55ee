#!/usr/bin/env bash
# The scene benchmark (issue 6): Pineda, Mesa llvmpipe and Mesa softpipe render the heavy scenes
# of bench/scenes in one run, alternating, several rounds; prints medians, the Pineda/llvmpipe and
# Pineda/softpipe ratios and each scene's error against llvmpipe, and writes bench-out/ (images,
# report.html, bench.csv). Not part of the test run: it takes a few minutes.
# Usage: scripts/bench.sh [--rounds N] [--reps N] [--filter SUBSTR] [--no-softpipe]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD_DIR:-build}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" -j "${JOBS:-2}" --target pineda pineda_conformance pineda_bench_runner
rounds=3 reps=5 extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --rounds) rounds=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    --filter) extra+=(--filter "$2"); shift 2 ;;
    --no-softpipe) extra+=(--no-softpipe); shift ;;
    -h|--help) sed -n 2,6p "$0"; exit 0 ;;
    *) echo "bench.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
# The runner also holds the sweep_ and scale_ scenes of scripts/sweep.sh and scripts/scaling.sh.
[[ " ${extra[*]} " == *" --filter "* ]] || extra+=(--filter bench_)
mkdir -p bench-out
"$BUILD/conformance/pineda_conformance" --runner "$BUILD/conformance/pineda_bench_runner" \
  --out bench-out --rounds "$rounds" --reps "$reps" --timeout 600 --csv bench-out/bench.csv \
  "${extra[@]}"
