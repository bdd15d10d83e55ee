#!/usr/bin/env bash
# Unmodified glxgears (mesa-utils) on Pineda's libGL.so.1: its gears are display lists. It runs
# until killed, so it gets a few seconds; it must report Pineda as the renderer, print a frame
# count, and generate no GL error (PINEDA_DEBUG=1 logs every error as "pineda: ...").
# Usage: check_glxgears.sh GLXGEARS_PATH LIB_DIR
set -u
out=$(PINEDA_DEBUG=1 LD_LIBRARY_PATH="$2" timeout 7 "$1" -info 2>&1)
rc=$?
echo "$out" | head -n 30
# timeout's 124 is the expected way for glxgears to end.
if [ $rc -ne 124 ] && [ $rc -ne 0 ]; then
  echo "check_glxgears: glxgears exited with $rc" >&2
  exit 1
fi
if ! grep -qF "GL_RENDERER   = Pineda" <<<"$out"; then
  echo "check_glxgears: GL_RENDERER is not Pineda" >&2
  exit 1
fi
if ! grep -qE "^[0-9]+ frames in [0-9.]+ seconds" <<<"$out"; then
  echo "check_glxgears: no frame count printed" >&2
  exit 1
fi
if grep -q "^pineda: " <<<"$out"; then
  echo "check_glxgears: glxgears caused GL errors" >&2
  exit 1
fi
