#!/usr/bin/env bash
# Renders the README's screenshots (demos/screenshots/NAME.png) headless under a private Xvfb:
# on Pineda (LD_LIBRARY_PATH=BUILD/lib) with --pineda, on Mesa llvmpipe with --mesa. Prints the
# renderer of each picture, which the README's captions name.
# Usage: demos/make_screenshots.sh --pineda|--mesa [BUILD_DIR] [NAME...]
# PINEDA_LIB_DIR overrides BUILD_DIR/lib as the place of Pineda's libGL.so.1.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
mode=${1:-}
shift || true
build=${1:-$root/build}
shift || true
names=("$@")
[ ${#names[@]} -eq 0 ] && names=(gears cube terrain particles picking viewer)
case $mode in
--pineda) env_args=(LD_LIBRARY_PATH="${PINEDA_LIB_DIR:-$build/lib}") ;;
--mesa) env_args=(-u LD_LIBRARY_PATH GALLIUM_DRIVER=llvmpipe LIBGL_ALWAYS_SOFTWARE=1) ;;
*) echo "usage: $0 --pineda|--mesa [BUILD_DIR] [NAME...]" >&2; exit 2 ;;
esac
declare -A frames=([gears]=40 [cube]=50 [terrain]=120 [particles]=120 [picking]=30 [viewer]=30)
out_dir=$root/demos/screenshots
mkdir -p "$out_dir"
status=0
for name in "${names[@]}"; do
  exe=$build/demos/$name
  if [ ! -x "$exe" ]; then echo "$name: $exe not built" >&2; status=1; continue; fi
  log=$("$root/tests/glx/run_with_xvfb.sh" "$(command -v Xvfb)" env "${env_args[@]}" "$exe" \
    --frames "${frames[$name]:-30}" --size 480x360 --verbose --screenshot "$out_dir/$name.png" 2>&1)
  rc=$?
  echo "$name: $(sed -n 's/^GL_RENDERER: //p' <<<"$log") (exit $rc)"
  [ $rc -eq 0 ] || { sed 's/^/  /' <<<"$log" | tail -n 3; status=1; }
done
exit $status
