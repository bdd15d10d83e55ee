# The generated half of the API layer: tools/gen/gen_gl.py reads the Khronos registry and
# src/api/entry_points.txt and writes headers, dispatch tables, thunks and the linker version
# script into the build tree.
#
# Defines:
#   PINEDA_GENERATED_DIR      root of the generated files (dispatch.h lives here, the public
#                             headers under include/GL/)
#   PINEDA_GENERATED_SOURCES  the generated .cpp files, to compile into the library
#   PINEDA_GENERATED_HEADERS  the generated public headers (installed next to include/GL/*.h)
#   PINEDA_EXPORTS_MAP        the generated linker version script
#   pineda_generate           custom target that brings all of them up to date

find_package(Python3 REQUIRED COMPONENTS Interpreter)

# PINEDA_GL_XML, the registry (khronos-api), is checked by cmake/Dependencies.cmake.

# Paths are taken from this file's location, not CMAKE_SOURCE_DIR, so that the rules also work
# when Pineda is a subproject of another build.
get_filename_component(PINEDA_SOURCE_ROOT ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
set(PINEDA_GENERATED_DIR ${CMAKE_BINARY_DIR}/generated)
set(PINEDA_GENERATOR ${PINEDA_SOURCE_ROOT}/tools/gen/gen_gl.py)
set(PINEDA_ENTRY_POINTS ${PINEDA_SOURCE_ROOT}/src/api/entry_points.txt)
# The extensions GL_EXTENSIONS lists; their aliases are exported from the same list.
set(PINEDA_EXTENSIONS ${PINEDA_SOURCE_ROOT}/src/api/extensions.txt)
# How each command behaves while a display list is compiled (GL 2.1 §5.4).
set(PINEDA_DLIST_IMMEDIATE ${PINEDA_SOURCE_ROOT}/src/api/dlist_immediate.txt)
set(PINEDA_DLIST_SAVERS ${PINEDA_SOURCE_ROOT}/src/api/dlist_savers.txt)

set(PINEDA_GENERATED_SOURCES
  ${PINEDA_GENERATED_DIR}/dispatch_tables.cpp
  ${PINEDA_GENERATED_DIR}/dlist_save.cpp
  ${PINEDA_GENERATED_DIR}/api_thunks.cpp
  ${PINEDA_GENERATED_DIR}/proc_table.cpp
  ${PINEDA_GENERATED_DIR}/enum_names.cpp)
set(PINEDA_GENERATED_HEADERS
  ${PINEDA_GENERATED_DIR}/include/GL/pineda_gl_api.h
  ${PINEDA_GENERATED_DIR}/include/GL/pineda_glext_api.h)
set(PINEDA_EXPORTS_MAP ${PINEDA_GENERATED_DIR}/exports.map)

# The generator rewrites a file only when its content changes, so the files themselves cannot
# be the command's OUTPUT (an untouched output would look stale and rerun the command on every
# build). The stamp is the output; the files are byproducts whose timestamps move only when
# their content does, which is what keeps an edit to entry_points.txt from recompiling
# everything that includes the public headers.
set(PINEDA_GENERATE_STAMP ${PINEDA_GENERATED_DIR}/generate.stamp)
add_custom_command(
  OUTPUT ${PINEDA_GENERATE_STAMP}
  BYPRODUCTS ${PINEDA_GENERATED_SOURCES} ${PINEDA_GENERATED_HEADERS}
    ${PINEDA_GENERATED_DIR}/dispatch.h ${PINEDA_GENERATED_DIR}/extensions.h ${PINEDA_EXPORTS_MAP}
  COMMAND ${Python3_EXECUTABLE} ${PINEDA_GENERATOR}
    --registry ${PINEDA_GL_XML}
    --entry-points ${PINEDA_ENTRY_POINTS}
    --extensions ${PINEDA_EXTENSIONS}
    --dlist-immediate ${PINEDA_DLIST_IMMEDIATE}
    --dlist-savers ${PINEDA_DLIST_SAVERS}
    --out-dir ${PINEDA_GENERATED_DIR}
    --stamp ${PINEDA_GENERATE_STAMP}
  DEPENDS ${PINEDA_GENERATOR} ${PINEDA_SOURCE_ROOT}/tools/gen/registry_util.py
    ${PINEDA_ENTRY_POINTS} ${PINEDA_EXTENSIONS} ${PINEDA_DLIST_IMMEDIATE}
    ${PINEDA_DLIST_SAVERS} ${PINEDA_GL_XML}
  COMMENT "Generating the GL API layer from ${PINEDA_GL_XML}"
  VERBATIM)
add_custom_target(pineda_generate DEPENDS ${PINEDA_GENERATE_STAMP})
