# The GLFW demos and what they need; included by demos/ (which builds them) and by
# tests/programs/ (which runs them on Pineda and on Mesa).
set(PINEDA_DEMO_NAMES gears cube terrain particles picking viewer)
find_package(glfw3 QUIET)
# LEGACY: OpenGL::GL is libGL.so itself (DT_NEEDED libGL.so.1), the library Pineda replaces;
# GLVND would link libOpenGL.so.0 + libGLX.so.0 instead.
set(OpenGL_GL_PREFERENCE LEGACY)
find_package(OpenGL QUIET)
find_package(PNG QUIET)
set(PINEDA_GLFW_DEMOS OFF)
if((PINEDA_DEMOS OR PINEDA_X11_TESTS) AND glfw3_FOUND AND OpenGL_FOUND AND PNG_FOUND)
  set(PINEDA_GLFW_DEMOS ON)
endif()
