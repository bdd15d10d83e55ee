#!/usr/bin/env bash
# Runs a program headless twice, on Pineda's libGL.so.1 (LD_LIBRARY_PATH=LIB_DIR) and on Mesa
# llvmpipe (the system libGL, no LD_LIBRARY_PATH), checks that each run used the renderer it
# should (GL_RENDERER, printed by --verbose), that both print the same "picked:" lines (the
# picking demo's selection results) and compares the two screenshots with png_compare.
# Usage: compare_demo.sh PROGRAM PNG_COMPARE LIB_DIR OUT_DIR "COMPARE_OPTIONS" [PROGRAM_ARGS...]
# The program gets PROGRAM_ARGS --verbose --screenshot OUT_DIR/{pineda,mesa}.png.
# Run under tests/glx/run_with_xvfb.sh (needs DISPLAY).
# With PINEDA_COMPARE_GLVND=DIR in the environment the Pineda run goes through glvnd's own
# libraries instead, with the vendor libraries of DIR (libGLX_pineda.so.0, libEGL_pineda.so.0).
set -u
program=$1 compare=$2 lib_dir=$3 out_dir=$4 compare_options=$5
shift 5
mkdir -p "$out_dir"
rm -f "$out_dir/pineda.png" "$out_dir/mesa.png" "$out_dir/diff.png"

run() { # run NAME ENV... : runs the program with the environment given, output to NAME.log
  local name=$1
  shift
  env "$@" "$program" "${args[@]}" --verbose --screenshot "$out_dir/$name.png" >"$out_dir/$name.log" 2>&1
  local rc=$?
  sed "s/^/[$name] /" "$out_dir/$name.log"
  if [ $rc -ne 0 ]; then
    echo "compare_demo: the $name run exited with status $rc" >&2
    exit 1
  fi
}

args=("$@")
if [ -n "${PINEDA_COMPARE_GLVND:-}" ]; then
  run pineda LD_LIBRARY_PATH="$PINEDA_COMPARE_GLVND" __GLX_VENDOR_LIBRARY_NAME=pineda \
    __EGL_VENDOR_LIBRARY_FILENAMES="$PINEDA_COMPARE_GLVND/50_pineda.json"
else
  run pineda LD_LIBRARY_PATH="$lib_dir"
fi
if ! grep -q "^GL_RENDERER: Pineda" "$out_dir/pineda.log"; then
  echo "compare_demo: the Pineda run did not render on Pineda (GL_RENDERER above)" >&2
  exit 1
fi
run mesa -u LD_LIBRARY_PATH -u PINEDA_COMPARE_GLVND GALLIUM_DRIVER=llvmpipe LIBGL_ALWAYS_SOFTWARE=1
if ! grep -q "^GL_RENDERER: llvmpipe" "$out_dir/mesa.log"; then
  echo "compare_demo: the Mesa run did not render on llvmpipe (GL_RENDERER above)" >&2
  exit 1
fi
if ! diff <(grep "^picked:" "$out_dir/pineda.log") <(grep "^picked:" "$out_dir/mesa.log"); then
  echo "compare_demo: Pineda and Mesa picked different objects" >&2
  exit 1
fi
# shellcheck disable=SC2086 # the options are words
"$compare" "$out_dir/pineda.png" "$out_dir/mesa.png" $compare_options --diff "$out_dir/diff.png"
