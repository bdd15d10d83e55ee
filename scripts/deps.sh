#!/usr/bin/env bash
# Install the Debian 12 packages Pineda needs to build, test and run its conformance diff.
# Idempotent: installs only what is missing.
set -euo pipefail

PACKAGES=(
  build-essential libc6-dev cmake ninja-build pkg-config python3
  khronos-api            # gl.xml / glx.xml: the generator's input
  libglm-dev             # matrix math outside the hot loops
  libgtest-dev libgmock-dev googletest
  libbenchmark-dev
  clang libclang-rt-14-dev # scripts/fuzz.sh: libFuzzer, ASan, UBSan runtimes (a short run in the tests)
  valgrind bc            # scripts/bench_instructions.sh: instruction counts per bench scene
  libosmesa6-dev         # Mesa's OSMesa: the conformance oracle (never linked into Pineda)
  libpng-dev zlib1g-dev  # conformance images
  libx11-dev libxext-dev # GLX over Xlib, presenting with MIT-SHM (XShm)
  xvfb mesa-utils        # GLX tests: a private X server; unmodified glxinfo
  libglfw3-dev           # GLX tests: an unmodified GLFW program; the demos (demos/)
  libgl-dev              # the demos link the system's libGL.so (Pineda replaces it at run time)
  libxrandr-dev          # GLFW/glfw3native.h includes X11/extensions/Xrandr.h (tests/glx)
  glslang-dev glslang-tools # GLSL front end (static libraries) and glslangValidator
  libglvnd-core-dev libegl-dev # glvnd's vendor ABI headers (GLX, EGL); EGL/eglext.h
  librust-khronos-api-dev # egl.xml, the EGL registry (khronos-api has only gl.xml, glx.xml)
  freeglut3-dev          # tests/programs: a freeglut program on Pineda
  piglit                 # conformance/piglit: the GL 1.x and GLSL lists; ctest piglit.glsl_sample
  python3-matplotlib     # scripts/sweep.sh, scaling.sh: charts (run with /usr/bin/python3)
  mmdebstrap             # scripts/fresh_root.sh: the quick start on a fresh Debian 12 root
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
