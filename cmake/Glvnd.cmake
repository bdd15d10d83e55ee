# glvnd vendor libraries and EGL (issue 18).
#
#   build/glvnd/libGLX_pineda.so.0  Pineda's GLX behind glvnd's libGLX (__glx_Main)
#   build/glvnd/libEGL_pineda.so.0  Pineda's EGL 1.5 behind glvnd's libEGL (__egl_Main)
#   build/glvnd/50_pineda.json      the EGL vendor file naming the library
#   build/pineda-run                runs a program on Pineda (scripts/pineda-run.in)
#
# The folder has no libGL.so.1, so glvnd's own front libraries (libGL.so.1, libOpenGL.so.0,
# libGLX.so.0, libEGL.so.1) stay in use and load these by name. Each vendor library is the
# whole of Pineda linked again with a version script that exports only glvnd's entry point.
#
# Defines PINEDA_EGL (the EGL objects exist: pineda_egl), PINEDA_GLVND_DIR.

set(PINEDA_GLVND_DIR ${CMAKE_BINARY_DIR}/glvnd)
get_filename_component(PINEDA_SOURCE_ROOT ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)

# egl.xml (PINEDA_EGL_XML), EGL/eglext.h and glvnd's ABI headers are checked by
# cmake/Dependencies.cmake when PINEDA_GLVND is on.
set(PINEDA_EGL ${PINEDA_GLVND})
if(NOT PINEDA_GLVND)
  return()
endif()

if(PINEDA_EGL)
  set(PINEDA_EGL_GENERATED_DIR ${CMAKE_BINARY_DIR}/generated/egl)
  set(PINEDA_EGL_GENERATOR ${PINEDA_SOURCE_ROOT}/tools/gen/gen_egl.py)
  set(PINEDA_EGL_EXTENSIONS ${PINEDA_SOURCE_ROOT}/src/winsys/egl/egl_extensions.txt)
  set(PINEDA_EGL_STAMP ${PINEDA_EGL_GENERATED_DIR}/generate.stamp)
  set(PINEDA_EGL_GENERATED_SOURCES
    ${PINEDA_EGL_GENERATED_DIR}/egl_procs.cpp ${PINEDA_EGL_GENERATED_DIR}/egl_enum_names.cpp)
  add_custom_command(
    OUTPUT ${PINEDA_EGL_STAMP}
    BYPRODUCTS ${PINEDA_EGL_GENERATED_SOURCES} ${PINEDA_EGL_GENERATED_DIR}/egl_generated.h
    COMMAND ${CMAKE_COMMAND} -E make_directory ${PINEDA_EGL_GENERATED_DIR}
    COMMAND ${Python3_EXECUTABLE} ${PINEDA_EGL_GENERATOR} --registry ${PINEDA_EGL_XML}
      --extensions ${PINEDA_EGL_EXTENSIONS} --out-dir ${PINEDA_EGL_GENERATED_DIR}
      --stamp ${PINEDA_EGL_STAMP}
    DEPENDS ${PINEDA_EGL_GENERATOR} ${PINEDA_SOURCE_ROOT}/tools/gen/registry_util.py
      ${PINEDA_EGL_EXTENSIONS} ${PINEDA_EGL_XML}
    COMMENT "Generating the EGL tables from ${PINEDA_EGL_XML}"
    VERBATIM)
  add_custom_target(pineda_egl_generate DEPENDS ${PINEDA_EGL_STAMP})

  # Pineda's EGL, with the standard entry point names (hidden in the vendor library; the
  # in-process tests call them directly).
  file(GLOB PINEDA_EGL_SOURCES CONFIGURE_DEPENDS ${PINEDA_SOURCE_ROOT}/src/winsys/egl/*.cpp)
  add_library(pineda_egl OBJECT ${PINEDA_EGL_SOURCES} ${PINEDA_EGL_GENERATED_SOURCES})
  target_include_directories(pineda_egl PUBLIC ${PINEDA_EGL_GENERATED_DIR}
    ${PINEDA_SOURCE_ROOT}/include ${PINEDA_GENERATED_DIR}/include ${PINEDA_GENERATED_DIR}
    ${PINEDA_SOURCE_ROOT}/src)
  add_dependencies(pineda_egl pineda_egl_generate pineda_generate)
  target_link_libraries(pineda_egl PUBLIC X11::X11 X11::Xext)
  pineda_set_warnings(pineda_egl)
  # Tests link Pineda and its EGL statically (the sanitizer build runs them in process).
  add_library(pineda_egl_static STATIC $<TARGET_OBJECTS:pineda_egl>)
  target_link_libraries(pineda_egl_static PUBLIC pineda_static X11::X11 X11::Xext)
  target_include_directories(pineda_egl_static PUBLIC ${PINEDA_EGL_GENERATED_DIR})
endif()


# pineda_vendor_library(TARGET NAME MAP SOURCES...): the whole of Pineda as lib<NAME>.so.0 in
# build/glvnd, exporting what MAP lists. -Bsymbolic keeps every reference inside the library
# bound to its own definitions, whatever the application's libraries export; glslang is linked
# in with none of its symbols exported (--exclude-libs), as in libOSMesa.so.8.
function(pineda_vendor_library target name map)
  add_library(${target} SHARED $<TARGET_OBJECTS:pineda_backend> $<TARGET_OBJECTS:pineda_frontend>
    ${ARGN})
  set_target_properties(${target} PROPERTIES OUTPUT_NAME ${name} VERSION 0.0.0 SOVERSION 0
    LIBRARY_OUTPUT_DIRECTORY ${PINEDA_GLVND_DIR} LINK_DEPENDS ${map})
  target_include_directories(${target} PRIVATE ${PINEDA_GLVND_INCLUDE_DIR}
    ${PINEDA_SOURCE_ROOT}/include ${PINEDA_GENERATED_DIR}/include ${PINEDA_GENERATED_DIR}
    ${PINEDA_SOURCE_ROOT}/src)
  target_link_libraries(${target} PRIVATE Threads::Threads X11::X11 X11::Xext glslang::glslang
    glslang::glslang-default-resource-limits)
  target_link_options(${target} PRIVATE "-Wl,--version-script=${map}" "-Wl,--no-undefined"
    "-Wl,-Bsymbolic" "-Wl,--exclude-libs,ALL")
  add_dependencies(${target} pineda_generate)
  pineda_set_warnings(${target})
endfunction()

pineda_vendor_library(pineda_glx_vendor GLX_pineda
  ${PINEDA_SOURCE_ROOT}/src/winsys/glvnd/glx_vendor.map
  ${PINEDA_SOURCE_ROOT}/src/winsys/glvnd/glx_vendor.cpp)

if(PINEDA_EGL)
  pineda_vendor_library(pineda_egl_vendor EGL_pineda
    ${PINEDA_SOURCE_ROOT}/src/winsys/glvnd/egl_vendor.map
    ${PINEDA_SOURCE_ROOT}/src/winsys/glvnd/egl_vendor.cpp $<TARGET_OBJECTS:pineda_egl>)
  target_include_directories(pineda_egl_vendor PRIVATE ${PINEDA_EGL_GENERATED_DIR})
  add_dependencies(pineda_egl_vendor pineda_egl_generate)
  # The vendor file of the build tree names the library beside it (glvnd reads a relative
  # path with a separator from the file's folder), so EGL needs no LD_LIBRARY_PATH.
  set(PINEDA_EGL_LIBRARY_PATH "./libEGL_pineda.so.0")
  configure_file(${PINEDA_SOURCE_ROOT}/cmake/50_pineda.json.in ${PINEDA_GLVND_DIR}/50_pineda.json
    @ONLY)
  # Installed: a path relative to the vendor file's folder (glvnd reads a relative path with a
  # separator that way), so that `cmake --install --prefix DIR` gives a working file; an
  # absolute libdir or datadir is named as it is.
  if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}" OR IS_ABSOLUTE "${CMAKE_INSTALL_DATADIR}")
    set(PINEDA_EGL_LIBRARY_PATH "${CMAKE_INSTALL_FULL_LIBDIR}/libEGL_pineda.so.0")
  else()
    file(RELATIVE_PATH PINEDA_EGL_LIBRARY_PATH "/root/${CMAKE_INSTALL_DATADIR}/glvnd/egl_vendor.d"
      "/root/${CMAKE_INSTALL_LIBDIR}/libEGL_pineda.so.0")
  endif()
  configure_file(${PINEDA_SOURCE_ROOT}/cmake/50_pineda.json.in
    ${CMAKE_BINARY_DIR}/install/50_pineda.json @ONLY)
endif()

# pineda-run: in the build tree it points at build/lib and build/glvnd, installed at the
# installed libraries.
set(PINEDA_RUN_LIB_DIR ${PINEDA_LIB_DIR})
set(PINEDA_RUN_GLVND_DIR ${PINEDA_GLVND_DIR})
set(PINEDA_RUN_JSON ${PINEDA_GLVND_DIR}/50_pineda.json)
set(PINEDA_RUN_INSTALLED 0)
configure_file(${PINEDA_SOURCE_ROOT}/scripts/pineda-run.in ${CMAKE_BINARY_DIR}/pineda-run @ONLY
  FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ
  WORLD_EXECUTE)
# Installed, the paths are found from the script's own folder ($here), so that the prefix
# can be chosen at install time.
if(IS_ABSOLUTE "${CMAKE_INSTALL_BINDIR}" OR IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}"
   OR IS_ABSOLUTE "${CMAKE_INSTALL_DATADIR}")
  set(PINEDA_RUN_LIB_DIR ${CMAKE_INSTALL_FULL_LIBDIR})
  set(PINEDA_RUN_JSON ${CMAKE_INSTALL_FULL_DATADIR}/glvnd/egl_vendor.d/50_pineda.json)
else()
  file(RELATIVE_PATH _lib "/root/${CMAKE_INSTALL_BINDIR}" "/root/${CMAKE_INSTALL_LIBDIR}")
  file(RELATIVE_PATH _json "/root/${CMAKE_INSTALL_BINDIR}"
    "/root/${CMAKE_INSTALL_DATADIR}/glvnd/egl_vendor.d/50_pineda.json")
  set(PINEDA_RUN_LIB_DIR "\$here/${_lib}")
  set(PINEDA_RUN_JSON "\$here/${_json}")
endif()
set(PINEDA_RUN_GLVND_DIR ${PINEDA_RUN_LIB_DIR})
set(PINEDA_RUN_INSTALLED 1)
configure_file(${PINEDA_SOURCE_ROOT}/scripts/pineda-run.in ${CMAKE_BINARY_DIR}/install/pineda-run
  @ONLY)
