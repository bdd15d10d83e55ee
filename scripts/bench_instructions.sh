#!/usr/bin/env bash
# Instructions executed per bench scene (valgrind's callgrind, counting only the scene's draw
# function), for one or two Pineda library directories: a measure of work that, unlike time,
# does not move with the load of a shared machine. Used to check that a change costs nothing on
# scenes that do not use it (issue 3: "features off runs no slower than before").
# Usage: scripts/bench_instructions.sh LIBDIR_A [LIBDIR_B] [-- SCENE...]
#   LIBDIR: a directory holding Pineda's libOSMesa.so.8 (e.g. build/lib, or an older build's).
# Scenes default to the bench scenes that use no texturing.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD_DIR:-build}
RUNNER="$BUILD/conformance/pineda_bench_runner"
libs=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do libs+=("$1"); shift; done
[ "${1:-}" = "--" ] && shift
scenes=("$@")
[ ${#scenes[@]} -eq 0 ] && scenes=(bench_tiny_tris bench_overdraw_depth bench_lit_mesh bench_immediate
                                   bench_gears_lists bench_blend_heavy bench_textured_mesh)
if [ ${#libs[@]} -lt 1 ] || [ ${#libs[@]} -gt 2 ]; then
  sed -n 2,8p "$0" >&2
  exit 2
fi
for l in "${libs[@]}"; do
  [ -e "$l/libOSMesa.so.8" ] || { echo "bench_instructions: no libOSMesa.so.8 in '$l'" >&2; exit 2; }
done
command -v valgrind >/dev/null || { echo "bench_instructions: valgrind is not installed" >&2; exit 2; }
[ -x "$RUNNER" ] || { echo "bench_instructions: build $RUNNER first (target pineda_bench_runner)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# One thread: the count follows the scene's draw function on the calling thread, and work handed
# to worker threads would not be counted.
count() { # lib scene -> instructions
  PINEDA_THREADS=1 LD_LIBRARY_PATH="$1" valgrind --tool=callgrind --callgrind-out-file="$tmp/cg" \
    --toggle-collect="scene_draw_$2*" "$RUNNER" --scene "$2" --out "$tmp/img.rgba" --reps 1 2>&1 |
    sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
if [ ${#libs[@]} -eq 1 ]; then
  printf '%-24s %16s\n' scene instructions
  for s in "${scenes[@]}"; do printf '%-24s %16s\n' "$s" "$(count "${libs[0]}" "$s")"; done
else
  printf '%-24s %16s %16s %9s\n' scene A B "B/A-1"
  for s in "${scenes[@]}"; do
    a=$(count "${libs[0]}" "$s" || true)
    b=$(count "${libs[1]}" "$s" || true)
    if [ -z "$a" ] || [ -z "$b" ] || [ "$a" = 0 ]; then
      # The runner failed or the scene never entered its draw function with one of the builds.
      printf '%-24s %16s %16s %9s\n' "$s" "${a:--}" "${b:--}" "-"
      continue
    fi
    printf '%-24s %16s %16s %+8.2f%%\n' "$s" "$a" "$b" "$(echo "100 * ($b / $a - 1)" | bc -l)"
  done
fi
