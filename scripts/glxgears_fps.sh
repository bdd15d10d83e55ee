#!/usr/bin/env bash
# Runs unmodified glxgears (mesa-utils) for about 10 s under a private Xvfb, once on Pineda's
# libGL.so.1 and once on Mesa llvmpipe, and prints both frame rates. Swap interval 0 in both, so
# neither is paced to a display. glxgears prints "N frames in 5.0 seconds = X FPS" every 5 s;
# the figure reported is the last such line.
# Usage: scripts/glxgears_fps.sh [BUILD_DIR] [SECONDS]   (default build, 11)
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
seconds=${2:-11}
lib_dir=$build/lib
glxgears=$(command -v glxgears) || { echo "glxgears_fps: glxgears not found (apt-get install mesa-utils)" >&2; exit 1; }
xvfb=$(command -v Xvfb) || { echo "glxgears_fps: Xvfb not found (apt-get install xvfb)" >&2; exit 1; }
if [ ! -e "$lib_dir/libGL.so.1" ]; then
  echo "glxgears_fps: $lib_dir/libGL.so.1 missing: build Pineda first (cmake --build $build --target pineda)" >&2
  exit 1
fi

# One run: prints the renderer and the last FPS line. Called inside run_with_xvfb.sh.
measure() {
  local label=$1
  shift
  local out
  out=$(env "$@" timeout -s INT "$seconds" "$glxgears" -info -swapinterval 0 2>&1)
  local renderer fps
  renderer=$(sed -n 's/^GL_RENDERER *= *//p' <<<"$out" | head -n1)
  fps=$(grep -E "frames in [0-9.]+ seconds" <<<"$out" | tail -n1)
  if [ -z "$fps" ]; then
    echo "$label: no FPS figure (renderer: ${renderer:-none})"
    grep -v "^GL_EXTENSIONS" <<<"$out" | tail -n 5 | sed 's/^/  /'
    return 1
  fi
  printf '%-7s %-45s %s\n' "$label" "${renderer}" "$fps"
}
export -f measure
export glxgears seconds

status=0
"$root/tests/glx/run_with_xvfb.sh" "$xvfb" bash -c "measure Pineda LD_LIBRARY_PATH='$lib_dir'" || status=1
"$root/tests/glx/run_with_xvfb.sh" "$xvfb" bash -c "measure Mesa -u LD_LIBRARY_PATH GALLIUM_DRIVER=llvmpipe LIBGL_ALWAYS_SOFTWARE=1" || status=1
exit $status
