# Install rules: the public headers, libOSMesa.so.8 with its libGL.so.1 alias, a pkg-config
# file and a CMake package (find_package(Pineda) -> Pineda::OSMesa).

include(CMakePackageConfigHelpers)

# Paths are taken from this file's location, not CMAKE_SOURCE_DIR, so that the rules also work
# when Pineda is a subproject of another build.
get_filename_component(PINEDA_SOURCE_ROOT ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)

set(PINEDA_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Pineda)

# Headers: the hand-written ones and the two that gl.h and glext.h include from the build tree.
install(FILES
    ${PINEDA_SOURCE_ROOT}/include/GL/gl.h
    ${PINEDA_SOURCE_ROOT}/include/GL/glext.h
    ${PINEDA_SOURCE_ROOT}/include/GL/osmesa.h
    ${PINEDA_SOURCE_ROOT}/include/GL/glx.h
    ${PINEDA_GENERATED_HEADERS}
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/GL)

# The library keeps Mesa's file names so that existing binaries find it: libOSMesa.so.8 (real
# file libOSMesa.so.8.0.0, development link libOSMesa.so), exported as Pineda::OSMesa.
set_target_properties(pineda PROPERTIES EXPORT_NAME OSMesa)
install(TARGETS pineda EXPORT PinedaTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

# libGL.so.1 -> libOSMesa.so.8 and libGL.so -> libGL.so.1: the same library answers to both
# sonames. The links are made next to the library at build time (CMakeLists.txt);
# file(INSTALL) copies a symbolic link as a link, so they arrive as relative links.
install(FILES ${PINEDA_LIB_DIR}/libGL.so.1 ${PINEDA_LIB_DIR}/libGL.so
  DESTINATION ${CMAKE_INSTALL_LIBDIR})

# pkg-config. The prefix is found from the .pc file's own location (${pcfiledir}, known to
# pkg-config and pkgconf), so `cmake --install --prefix DIR` gives a working file without
# reconfiguring. An absolute libdir or includedir cannot be made relative and is kept as is.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(PINEDA_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
  set(PINEDA_PC_LIBDIR "${CMAKE_INSTALL_LIBDIR}")
  set(PINEDA_PC_PCDIR "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
else()
  file(RELATIVE_PATH PINEDA_PC_UP "/root/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/root")
  string(REGEX REPLACE "/$" "" PINEDA_PC_UP "${PINEDA_PC_UP}")
  set(PINEDA_PC_PREFIX "\${pcfiledir}/${PINEDA_PC_UP}")
  set(PINEDA_PC_LIBDIR "\${prefix}/${CMAKE_INSTALL_LIBDIR}")
  set(PINEDA_PC_PCDIR "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
endif()
if(IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
  set(PINEDA_PC_INCLUDEDIR "${CMAKE_INSTALL_INCLUDEDIR}")
else()
  set(PINEDA_PC_INCLUDEDIR "\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}")
endif()
configure_file(${PINEDA_SOURCE_ROOT}/cmake/pineda.pc.in ${CMAKE_BINARY_DIR}/pineda.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/pineda.pc DESTINATION ${PINEDA_PC_PCDIR})

# CMake package: PinedaConfig.cmake, its version file and the exported target.
configure_package_config_file(${PINEDA_SOURCE_ROOT}/cmake/PinedaConfig.cmake.in
  ${CMAKE_BINARY_DIR}/PinedaConfig.cmake
  INSTALL_DESTINATION ${PINEDA_CMAKE_INSTALL_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/PinedaConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_BINARY_DIR}/PinedaConfig.cmake ${CMAKE_BINARY_DIR}/PinedaConfigVersion.cmake
  DESTINATION ${PINEDA_CMAKE_INSTALL_DIR})
install(EXPORT PinedaTargets
  NAMESPACE Pineda::
  FILE PinedaTargets.cmake
  DESTINATION ${PINEDA_CMAKE_INSTALL_DIR})

# glvnd vendor libraries (cmake/Glvnd.cmake): libGLX_pineda.so.0 and libEGL_pineda.so.0 in
# libdir, where glvnd's libGLX and the vendor file's path find them; the EGL vendor file where
# glvnd's libEGL looks (share/glvnd/egl_vendor.d, under a /usr prefix); pineda-run in bindir.
if(TARGET pineda_glx_vendor)
  install(TARGETS pineda_glx_vendor LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} NAMELINK_SKIP)
endif()
if(TARGET pineda_egl_vendor)
  install(TARGETS pineda_egl_vendor LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} NAMELINK_SKIP)
  install(FILES ${CMAKE_BINARY_DIR}/install/50_pineda.json
    DESTINATION ${CMAKE_INSTALL_DATADIR}/glvnd/egl_vendor.d)
endif()
if(EXISTS ${CMAKE_BINARY_DIR}/install/pineda-run OR PINEDA_GLX)
  install(PROGRAMS ${CMAKE_BINARY_DIR}/install/pineda-run DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
