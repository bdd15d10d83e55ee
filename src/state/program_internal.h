// Shared by shader_object.cpp, uniform.cpp and vertex_attrib.cpp: object lookup with the
// errors of GL 2.1 §2.15, the front end's limits and the GL type helpers.
#pragma once

#include <GL/gl.h>

#include <string>

#include "glsl/glsl.h"
#include "state/context.h"

namespace pineda {

// The implementation limits the GLSL front end checks programs against (Table 6.37).
glsl::Limits glsl_limits();

// The shader (program) named `name`, or null with the error §2.15 names: INVALID_OPERATION
// for the name of the other kind of object, INVALID_VALUE for a name of neither.
ShaderObject* find_shader(Context* ctx, GLuint name, const char* func);
ProgramObject* find_program(Context* ctx, GLuint name, const char* func);

// A string query's copy into the client's buffer (§6.1.15).
void copy_string(const std::string& text, GLsizei buf_size, GLsizei* length, GLchar* out);

inline bool is_sampler_type(GLenum type) {
  switch (type) {
  case GL_SAMPLER_1D:
  case GL_SAMPLER_2D:
  case GL_SAMPLER_3D:
  case GL_SAMPLER_CUBE:
  case GL_SAMPLER_1D_SHADOW:
  case GL_SAMPLER_2D_SHADOW:
    return true;
  default:
    return false;
  }
}

} // namespace pineda
