#!/usr/bin/env bash
# Unmodified eglinfo (mesa-utils) through glvnd's libEGL with Pineda as the EGL vendor: the X11
# and surfaceless platforms must both list Pineda, EGL 1.5 and OpenGL configs.
# Usage: check_eglinfo.sh EGLINFO_PATH (the environment names the vendor)
set -u
out=$("$1" 2>&1)
rc=$?
echo "$out" | head -n 60
if [ $rc -ne 0 ]; then
  echo "check_eglinfo: eglinfo exited with $rc" >&2
  exit 1
fi
for platform in "X11 platform" "Surfaceless platform"; do
  section=$(awk -v p="$platform:" '$0 == p {on = 1; next} /^[A-Za-z].* platform:$/ {on = 0} on' <<<"$out")
  for want in "EGL vendor string: Pineda" "EGL version string: 1.5" "EGL client APIs: OpenGL" \
              "EGL_KHR_create_context"; do
    if ! grep -qF "$want" <<<"$section"; then
      echo "check_eglinfo: the $platform section lacks \"$want\"" >&2
      exit 1
    fi
  done
  if ! grep -qE '^0x01 ' <<<"$section"; then
    echo "check_eglinfo: the $platform section lists no configs" >&2
    exit 1
  fi
done
