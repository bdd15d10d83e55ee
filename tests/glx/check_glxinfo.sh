#!/usr/bin/env bash
# Unmodified glxinfo (mesa-utils) on Pineda's libGL.so.1: it must create a context through
# GLX and print Pineda's renderer string. Usage: check_glxinfo.sh GLXINFO_PATH LIB_DIR [ARGS...]
# (with ARGS, GLXINFO_PATH is a wrapper such as pineda-run and ARGS the glxinfo command line)
set -u
out=$(LD_LIBRARY_PATH="$2" "$1" "${@:3}" 2>&1)
rc=$?
echo "$out" | head -n 30
if [ $rc -ne 0 ]; then
  echo "check_glxinfo: glxinfo exited with $rc" >&2
  exit 1
fi
for want in "OpenGL renderer string: Pineda" "server glx vendor string: Pineda" "GLX version: 1.4"; do
  if ! grep -qF "$want" <<<"$out"; then
    echo "check_glxinfo: missing \"$want\"" >&2
    exit 1
  fi
done
