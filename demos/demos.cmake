# The GLFW demos and what they need; included by demos/ (which builds them) and by
# tests/programs/ (which runs them on Pineda and on Mesa).
set(PINEDA_DEMO_NAMES gears cube terrain particles picking viewer)
find_package(glfw3 QUIET)
set(OpenGL_GL_PREFERENCE GLVND)
find_package(OpenGL QUIET)
find_package(PNG QUIET)
set(PINEDA_GLFW_DEMOS OFF)
if(glfw3_FOUND AND OpenGL_FOUND AND PNG_FOUND)
  set(PINEDA_GLFW_DEMOS ON)
endif()
