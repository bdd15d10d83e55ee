# Every external dependency of the configured build, checked once before any target is defined,
# each with the Debian 12 package that provides it (scripts/deps.sh installs them all). A missing
# one stops the configure step with the list of packages to install, instead of a compiler error
# later in the build. The parts of the build that need them are options, so a smaller build can
# turn a part off instead:
#   PINEDA_GLX          GLX over Xlib in libGL.so.1                     (X11, Xext/XShm)
#   PINEDA_GLVND        EGL and the glvnd vendor libraries              (egl.xml, EGL and glvnd
#                                                                        headers)
#   PINEDA_TESTS        unit/API/property/thread tests                  (GoogleTest)
#   PINEDA_X11_TESTS    the GLX tests, real programs and piglit under   (Xvfb, mesa-utils, GLFW,
#                       Xvfb                                             freeglut, libGL, libpng,
#                                                                        piglit)
#   PINEDA_DEMOS        the GLFW demos                                  (GLFW, libGL, libpng)
#   PINEDA_CONFORMANCE  the conformance diff against Mesa's OSMesa      (libOSMesa, libpng)
#   PINEDA_BENCH        the micro-benchmarks                            (Google Benchmark)
#   PINEDA_FUZZ         the libFuzzer harness                           (clang's runtimes)

set(PINEDA_MISSING_PACKAGES "")
set(PINEDA_MISSING_WHAT "")

# pineda_missing(WHAT PACKAGE): record that WHAT is missing and PACKAGE provides it.
macro(pineda_missing what package)
  list(APPEND PINEDA_MISSING_WHAT "  ${what} (Debian package ${package})")
  list(APPEND PINEDA_MISSING_PACKAGES ${package})
endmacro()

# pineda_require_header(VAR HEADER PACKAGE): HEADER must be on the system include path.
function(pineda_require_header var header package)
  find_path(${var} NAMES ${header})
  if(NOT ${var})
    pineda_missing("header ${header}" ${package})
    set(PINEDA_MISSING_WHAT "${PINEDA_MISSING_WHAT}" PARENT_SCOPE)
    set(PINEDA_MISSING_PACKAGES "${PINEDA_MISSING_PACKAGES}" PARENT_SCOPE)
  endif()
endfunction()

# pineda_require_library(VAR NAME PACKAGE): the development library libNAME.so must exist.
function(pineda_require_library var name package)
  find_library(${var} NAMES ${name})
  if(NOT ${var})
    pineda_missing("library lib${name}.so" ${package})
    set(PINEDA_MISSING_WHAT "${PINEDA_MISSING_WHAT}" PARENT_SCOPE)
    set(PINEDA_MISSING_PACKAGES "${PINEDA_MISSING_PACKAGES}" PARENT_SCOPE)
  endif()
endfunction()

# pineda_require_program(VAR NAME PACKAGE): the program NAME must be on PATH.
function(pineda_require_program var name package)
  find_program(${var} NAMES ${name})
  if(NOT ${var})
    pineda_missing("program ${name}" ${package})
    set(PINEDA_MISSING_WHAT "${PINEDA_MISSING_WHAT}" PARENT_SCOPE)
    set(PINEDA_MISSING_PACKAGES "${PINEDA_MISSING_PACKAGES}" PARENT_SCOPE)
  endif()
endfunction()

# pineda_require_file(PATH PACKAGE WHAT): a data file another package installs.
function(pineda_require_file path package what)
  if(NOT EXISTS "${path}")
    pineda_missing("${what} ${path}" ${package})
    set(PINEDA_MISSING_WHAT "${PINEDA_MISSING_WHAT}" PARENT_SCOPE)
    set(PINEDA_MISSING_PACKAGES "${PINEDA_MISSING_PACKAGES}" PARENT_SCOPE)
  endif()
endfunction()

# ---- always: the generator and its registry, the matrix library, threads ----
find_package(Python3 COMPONENTS Interpreter)
if(NOT Python3_Interpreter_FOUND)
  pineda_missing("program python3" python3)
endif()
# The registry is a Debian package (khronos-api); another copy can be chosen at configure time.
set(PINEDA_GL_XML "/usr/share/khronos-api/gl.xml" CACHE FILEPATH "Khronos OpenGL registry (gl.xml)")
pineda_require_file("${PINEDA_GL_XML}" khronos-api "the OpenGL registry (or set PINEDA_GL_XML)")
pineda_require_header(PINEDA_GLM_INCLUDE glm/mat4x4.hpp libglm-dev)
pineda_require_header(PINEDA_PTHREAD_INCLUDE pthread.h libc6-dev)
# glslang parses and links GLSL (src/glsl). Debian's glslang-dev ships static, position
# independent libraries (linked into libGL with their symbols hidden) and a CMake package, which
# needs Threads first.
find_package(Threads)
find_package(glslang CONFIG QUIET)
if(NOT TARGET glslang::glslang OR NOT TARGET glslang::glslang-default-resource-limits)
  pineda_missing("glslang's CMake package and static libraries" glslang-dev)
endif()

# ---- GLX over Xlib ----
if(PINEDA_GLX)
  pineda_require_header(PINEDA_XLIB_INCLUDE X11/Xlib.h libx11-dev)
  pineda_require_library(PINEDA_XLIB_LIBRARY X11 libx11-dev)
  pineda_require_header(PINEDA_XSHM_INCLUDE X11/extensions/XShm.h libxext-dev)
  pineda_require_library(PINEDA_XEXT_LIBRARY Xext libxext-dev)
endif()

# ---- EGL and the glvnd vendor libraries (cmake/Glvnd.cmake) ----
if(PINEDA_GLVND)
  # EGL's registry: Debian's khronos-api has no egl.xml; librust-khronos-api-dev ships one.
  file(GLOB _pineda_egl_xml /usr/share/khronos-api/egl.xml
    /usr/share/cargo/registry/khronos_api-*/api_egl/api/egl.xml)
  set(_pineda_egl_xml_default /usr/share/cargo/registry/khronos_api-3.1.0/api_egl/api/egl.xml)
  if(_pineda_egl_xml)
    list(SORT _pineda_egl_xml)
    list(GET _pineda_egl_xml -1 _pineda_egl_xml_default)
  endif()
  set(PINEDA_EGL_XML "${_pineda_egl_xml_default}" CACHE FILEPATH "Khronos EGL registry (egl.xml)")
  pineda_require_file("${PINEDA_EGL_XML}" librust-khronos-api-dev
    "the EGL registry (or set PINEDA_EGL_XML)")
  pineda_require_header(PINEDA_EGL_INCLUDE_DIR EGL/eglext.h libegl-dev)
  pineda_require_header(PINEDA_GLVND_INCLUDE_DIR glvnd/libglxabi.h libglvnd-core-dev)
endif()

# ---- tests ----
if(PINEDA_TESTS)
  pineda_require_header(PINEDA_GTEST_INCLUDE gtest/gtest.h libgtest-dev)
  pineda_require_header(PINEDA_GMOCK_INCLUDE gmock/gmock.h libgmock-dev)
endif()

# ---- GLFW demos, and the real programs the X11 tests run ----
if(PINEDA_DEMOS OR PINEDA_X11_TESTS)
  pineda_require_header(PINEDA_GLFW_INCLUDE GLFW/glfw3.h libglfw3-dev)
  # GLFW/glfw3native.h (tests/glx/glfw_smoke.cpp) includes Xrandr.h for the X11 natives.
  pineda_require_header(PINEDA_XRANDR_INCLUDE X11/extensions/Xrandr.h libxrandr-dev)
  # The demos link libGL.so (OpenGL::GL, LEGACY), the library Pineda replaces at run time.
  pineda_require_library(PINEDA_SYSTEM_GL_LIBRARY GL libgl-dev)
  pineda_require_header(PINEDA_PNG_INCLUDE png.h libpng-dev)
endif()
if(PINEDA_X11_TESTS)
  pineda_require_program(PINEDA_XVFB Xvfb xvfb)
  pineda_require_program(PINEDA_GLXINFO glxinfo mesa-utils)
  pineda_require_program(PINEDA_GLXGEARS glxgears mesa-utils)
  pineda_require_header(PINEDA_FREEGLUT_INCLUDE GL/freeglut.h freeglut3-dev)
  # piglit's shader_runner for the sample of piglit's GLSL tests (conformance/piglit).
  pineda_require_file(/usr/lib/x86_64-linux-gnu/piglit/bin/shader_runner piglit "piglit's")
  if(PINEDA_GLVND)
    pineda_require_program(PINEDA_EGLINFO eglinfo mesa-utils)
  endif()
endif()

# ---- the conformance diff: Mesa's OSMesa is the oracle (never linked into Pineda) ----
if(PINEDA_CONFORMANCE)
  pineda_require_header(PINEDA_MESA_OSMESA_HEADER GL/osmesa.h libosmesa6-dev)
  pineda_require_library(PINEDA_MESA_OSMESA_LIB OSMesa libosmesa6-dev)
  pineda_require_header(PINEDA_PNG_INCLUDE png.h libpng-dev)
  pineda_require_header(PINEDA_ZLIB_INCLUDE zlib.h zlib1g-dev)
endif()

if(PINEDA_BENCH)
  pineda_require_header(PINEDA_BENCHMARK_INCLUDE benchmark/benchmark.h libbenchmark-dev)
endif()

if(PINEDA_FUZZ)
  # libFuzzer's and the sanitizers' runtimes come with clang's compiler-rt.
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libclang_rt.fuzzer-x86_64.a
    OUTPUT_VARIABLE PINEDA_LIBFUZZER OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT IS_ABSOLUTE "${PINEDA_LIBFUZZER}" OR NOT EXISTS "${PINEDA_LIBFUZZER}")
    pineda_missing("libFuzzer runtime libclang_rt.fuzzer-x86_64.a" libclang-rt-14-dev)
  endif()
endif()

if(PINEDA_MISSING_PACKAGES)
  list(REMOVE_DUPLICATES PINEDA_MISSING_PACKAGES)
  list(JOIN PINEDA_MISSING_WHAT "\n" _pineda_what)
  list(JOIN PINEDA_MISSING_PACKAGES " " _pineda_packages)
  message(FATAL_ERROR "Missing dependencies:\n${_pineda_what}\n"
    "Install them with:\n  sudo apt-get install ${_pineda_packages}\n"
    "or run scripts/deps.sh, which installs everything Pineda needs; or turn off the part that "
    "needs them (options at the top of cmake/Dependencies.cmake).")
endif()
