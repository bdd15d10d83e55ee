#!/usr/bin/env bash
# Unmodified glxgears (mesa-utils) on Pineda's libGL.so.1 for a few seconds: it must report
# Pineda as GL_RENDERER (-info) and print at least one "N frames in 5.0 seconds = X FPS" line.
# glxgears runs until killed: timeout stops it with SIGINT after SECONDS.
# Usage: check_glxgears.sh GLXGEARS LIB_DIR [SECONDS]
set -u
glxgears=$1 lib_dir=$2 seconds=${3:-8}
out=$(LD_LIBRARY_PATH="$lib_dir" timeout -s INT "$seconds" "$glxgears" -info -swapinterval 0 2>&1)
rc=$?
echo "$out" | grep -v "^GL_EXTENSIONS"
# 124: stopped by timeout, the normal end.
if [ $rc -ne 124 ] && [ $rc -ne 0 ]; then
  echo "check_glxgears: glxgears exited with status $rc" >&2
  exit 1
fi
if ! grep -q "^GL_RENDERER *= Pineda" <<<"$out"; then
  echo "check_glxgears: GL_RENDERER is not Pineda" >&2
  exit 1
fi
if ! grep -qE "[0-9]+ frames in [0-9.]+ seconds = [0-9.]+ FPS" <<<"$out"; then
  echo "check_glxgears: no FPS line within $seconds s" >&2
  exit 1
fi
