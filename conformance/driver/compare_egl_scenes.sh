#!/usr/bin/env bash
# Every conformance scene rendered by Pineda twice: through OSMesa (pineda_scene_runner with
# Pineda's libOSMesa.so.8) and through EGL on the surfaceless platform (pineda_scene_runner_egl
# through glvnd's libEGL with Pineda as the vendor). The two images must be equal byte for byte.
# Scenes EGL cannot express (an accumulation buffer) are skipped and counted.
# Usage: compare_egl_scenes.sh OSMESA_RUNNER EGL_RUNNER LIB_DIR GLVND_DIR OUT_DIR
set -u
osmesa_runner=$1 egl_runner=$2 lib_dir=$3 glvnd_dir=$4 out_dir=$5
mkdir -p "$out_dir"
passed=0 failed=0 skipped=0
failures=()
scenes=$(LD_LIBRARY_PATH="$lib_dir" "$osmesa_runner" --list | awk '{print $1}')
for scene in $scenes; do
  a="$out_dir/$scene.osmesa.rgba" b="$out_dir/$scene.egl.rgba"
  if ! LD_LIBRARY_PATH="$lib_dir" "$osmesa_runner" --scene "$scene" --out "$a" --reps 0 \
      >"$out_dir/$scene.osmesa.log" 2>&1; then
    echo "$scene: the OSMesa run failed: $(cat "$out_dir/$scene.osmesa.log")"
    failed=$((failed + 1)); failures+=("$scene"); continue
  fi
  LD_LIBRARY_PATH="$glvnd_dir" __EGL_VENDOR_LIBRARY_FILENAMES="$glvnd_dir/50_pineda.json" \
    "$egl_runner" --scene "$scene" --out "$b" --reps 0 >"$out_dir/$scene.egl.log" 2>&1
  rc=$?
  if [ $rc -eq 3 ] && grep -q "status=unsupported" "$out_dir/$scene.egl.log"; then
    skipped=$((skipped + 1)); continue
  fi
  if [ $rc -ne 0 ] || ! grep -q "renderer=Pineda" "$out_dir/$scene.egl.log"; then
    echo "$scene: the EGL run failed: $(cat "$out_dir/$scene.egl.log")"
    failed=$((failed + 1)); failures+=("$scene"); continue
  fi
  if cmp -s "$a" "$b"; then
    passed=$((passed + 1)); rm -f "$a" "$b"
  else
    echo "$scene: the EGL image differs from the OSMesa image ($a, $b)"
    failed=$((failed + 1)); failures+=("$scene")
  fi
done
echo "EGL surfaceless against OSMesa: $passed identical, $failed different, $skipped skipped" \
     "(accumulation buffers)"
[ $failed -eq 0 ]
