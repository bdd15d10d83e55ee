#!/usr/bin/env bash
# Time against error (issue 6): the quality variants of bench/scenes/sweep_scenes.cpp and
# shader_scenes.cpp (filters, mipmaps, hints, shade model, fewer shader lights) rendered by Pineda
# and Mesa llvmpipe, alternating, several rounds (medians). Each variant's error is measured
# against llvmpipe's render of its family's accurate variant. Writes bench-out/sweep.csv, the
# chart bench-out/time_vs_error.png and the images under bench-out/sweep/. Not in the test run.
# Usage: scripts/sweep.sh [--rounds N] [--reps N] [--filter SUBSTR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD_DIR:-build}
rounds=3 reps=5 filter=sweep_
while [ $# -gt 0 ]; do
  case "$1" in
    --rounds) rounds=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    --filter) filter=$2; shift 2 ;;
    -h|--help) sed -n 2,7p "$0"; exit 0 ;;
    *) echo "sweep.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" -j "${JOBS:-2}" --target pineda pineda_conformance pineda_bench_runner
out=bench-out/sweep
runner="$BUILD/conformance/pineda_bench_runner"
mkdir -p "$out"
"$runner" --manifest >"$out/manifest.tsv"
# Exit status 1 only says that some variant differs from llvmpipe's render of the same variant,
# which the table reports; 2 and above are setup failures.
status=0
"$BUILD/conformance/pineda_conformance" --runner "$runner" --out "$out" --filter "$filter" \
  --no-softpipe --rounds "$rounds" --reps "$reps" --timeout 600 --csv "$out/driver.csv" ||
  status=$?
if [ "$status" -gt 1 ]; then exit "$status"; fi
/usr/bin/python3 scripts/plot_sweep.py --dir "$out" --csv bench-out/sweep.csv \
  --png bench-out/time_vs_error.png
