#!/usr/bin/env bash
# Pineda's raw images of every conformance scene (and, with --bench, every bench scene) under
# each SIMD level and thread configuration, for a byte-for-byte comparison of two builds
# (scripts/compare_images.sh). Refactors that must not change rendering are checked this way.
# Usage: scripts/dump_images.sh [--bench] [--build DIR] LIBDIR OUTDIR
#   LIBDIR: a directory holding Pineda's libOSMesa.so.8 (e.g. build/lib).
#   OUTDIR: receives OUTDIR/<config>/<scene>.rgba (the runner's raw RGBA8, bottom-up) and
#           OUTDIR/<config>/<scene>.status (the runner's RESULT line without the timing).
# Configurations: PINEDA_SIMD=sse2 and avx2, the default level (AVX-512 where the processor has
# it), PINEDA_THREADS=1, and two threads with PINEDA_RASTER=bands and =bins.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
bench=0
while [ $# -gt 0 ]; do
  case "$1" in
  --bench) bench=1; shift ;;
  --build) build=$2; shift 2 ;;
  *) break ;;
  esac
done
if [ $# -ne 2 ]; then
  sed -n 2,10p "$0" >&2
  exit 2
fi
lib=$(cd "$1" && pwd)
out=$2
[ -e "$lib/libOSMesa.so.8" ] || { echo "dump_images: no libOSMesa.so.8 in '$lib'" >&2; exit 2; }
runners=("$build/conformance/pineda_scene_runner")
[ "$bench" = 1 ] && runners+=("$build/conformance/pineda_bench_runner")
for r in "${runners[@]}"; do
  [ -x "$r" ] || { echo "dump_images: build $r first" >&2; exit 2; }
done
configs=(
  "sse2 PINEDA_SIMD=sse2"
  "avx2 PINEDA_SIMD=avx2"
  "default"
  "t1 PINEDA_THREADS=1"
  "t2_bands PINEDA_THREADS=2 PINEDA_RASTER=bands"
  "t2_bins PINEDA_THREADS=2 PINEDA_RASTER=bins"
)
for runner in "${runners[@]}"; do
  mapfile -t scenes < <(LD_LIBRARY_PATH="$lib" "$runner" --list | awk '{print $1}')
  for c in "${configs[@]}"; do
    read -r name envs <<<"$c"
    mkdir -p "$out/$name"
    for s in "${scenes[@]}"; do
      # shellcheck disable=SC2086
      env -u PINEDA_SIMD -u PINEDA_THREADS -u PINEDA_RASTER $envs LD_LIBRARY_PATH="$lib" \
        "$runner" --scene "$s" --out "$out/$name/$s.rgba" --reps 1 2>/dev/null |
        sed -n -E 's/\t[a-z]+_ms=[^\t]*//g; /^RESULT/p' >"$out/$name/$s.status" || true
    done
    echo "dump_images: $name: ${#scenes[@]} scenes of $(basename "$runner")"
  done
done
