#!/usr/bin/env bash
# Scaling (issue 6): time against triangle count (scale_tris_*: 1k to 1M triangles covering the
# same 1024x1024 window) and against resolution (scale_res_*: one textured scene at 256x256 to
# 2048x2048), Pineda and Mesa llvmpipe side by side, each with one and with two threads
# (PINEDA_THREADS for Pineda, LP_NUM_THREADS for llvmpipe). A Pineda build without worker
# threads ignores PINEDA_THREADS; the chart's labels say so. Writes bench-out/scaling.csv and
# bench-out/scaling_tris.png, bench-out/scaling_res.png. Not part of the test run.
# Usage: scripts/scaling.sh [--rounds N] [--reps N] [--threads "1 2"] [--filter SUBSTR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD_DIR:-build}
rounds=3 reps=3 threads="1 2" filter=scale_
while [ $# -gt 0 ]; do
  case "$1" in
    --rounds) rounds=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --filter) filter=$2; shift 2 ;;
    -h|--help) sed -n 2,9p "$0"; exit 0 ;;
    *) echo "scaling.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" -j "${JOBS:-2}" --target pineda pineda_conformance pineda_bench_runner
runner="$BUILD/conformance/pineda_bench_runner"
# The worker-thread code reads PINEDA_THREADS; a library without that string has no workers.
honoured=0
if grep -qa PINEDA_THREADS "$BUILD/lib/libOSMesa.so.8"; then honoured=1; fi
inputs=()
for t in $threads; do
  out=bench-out/scaling/threads$t
  mkdir -p "$out"
  "$runner" --manifest >"$out/manifest.tsv"
  status=0
  PINEDA_THREADS=$t "$BUILD/conformance/pineda_conformance" --runner "$runner" --out "$out" \
    --filter "$filter" --no-softpipe --threads "$t" --rounds "$rounds" --reps "$reps" \
    --timeout 900 --csv "$out/driver.csv" || status=$?
  if [ "$status" -gt 1 ]; then exit "$status"; fi
  inputs+=(--run "$t:$out")
done
/usr/bin/python3 scripts/plot_scaling.py "${inputs[@]}" --honoured "$honoured" \
  --csv bench-out/scaling.csv --png-tris bench-out/scaling_tris.png \
  --png-res bench-out/scaling_res.png
