#!/usr/bin/env bash
# Runs egl_scene KIND on Pineda (glvnd's libEGL with Pineda's vendor file) and on Mesa
# llvmpipe (Mesa's vendor file), checks that each ran on the vendor it should, and compares the
# two images with png_compare at the conformance tolerance.
# Usage: compare_egl.sh EGL_SCENE PNG_COMPARE GLVND_DIR OUT_DIR KIND
set -u
scene=$1 compare=$2 glvnd_dir=$3 out_dir=$4 kind=$5
mkdir -p "$out_dir"
mesa_json=/usr/share/glvnd/egl_vendor.d/50_mesa.json
run() { # NAME ENV...
  local name=$1
  shift
  env "$@" "$scene" "$kind" "$out_dir/$name.png" >"$out_dir/$name.log" 2>&1
  local rc=$?
  sed "s/^/[$name] /" "$out_dir/$name.log"
  if [ $rc -ne 0 ]; then
    echo "compare_egl: the $name run exited with status $rc" >&2
    exit 1
  fi
}
run pineda __EGL_VENDOR_LIBRARY_FILENAMES="$glvnd_dir/50_pineda.json" LD_LIBRARY_PATH="$glvnd_dir"
grep -q "^EGL_VENDOR: Pineda" "$out_dir/pineda.log" || { echo "compare_egl: not Pineda" >&2; exit 1; }
run mesa __EGL_VENDOR_LIBRARY_FILENAMES="$mesa_json" LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe
grep -q "^GL_RENDERER: llvmpipe" "$out_dir/mesa.log" || { echo "compare_egl: not llvmpipe" >&2; exit 1; }
"$compare" "$out_dir/pineda.png" "$out_dir/mesa.png" --diff "$out_dir/diff.png"
