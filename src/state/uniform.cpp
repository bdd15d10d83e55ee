// Uniform variables (GL 2.1 §2.15.3): loading them with Uniform* and UniformMatrix* into the
// current program's uniform buffer, and the queries GetUniformLocation, GetActiveUniform,
// GetUniformfv and GetUniformiv (§6.1.15).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "dispatch.h"
#include "state/api_util.h"
#include "state/program_internal.h"

namespace pineda {

namespace {

enum class Base : uint8_t { Float, Int, Bool, Sampler };

struct TypeInfo {
  Base base;
  int components; // per element: vector size, or columns * rows
  int cols;       // matrices: columns (1 otherwise)
};

TypeInfo type_info(GLenum type) {
  switch (type) {
  case GL_FLOAT:
    return {Base::Float, 1, 1};
  case GL_FLOAT_VEC2:
    return {Base::Float, 2, 1};
  case GL_FLOAT_VEC3:
    return {Base::Float, 3, 1};
  case GL_FLOAT_VEC4:
    return {Base::Float, 4, 1};
  case GL_INT:
    return {Base::Int, 1, 1};
  case GL_INT_VEC2:
    return {Base::Int, 2, 1};
  case GL_INT_VEC3:
    return {Base::Int, 3, 1};
  case GL_INT_VEC4:
    return {Base::Int, 4, 1};
  case GL_BOOL:
    return {Base::Bool, 1, 1};
  case GL_BOOL_VEC2:
    return {Base::Bool, 2, 1};
  case GL_BOOL_VEC3:
    return {Base::Bool, 3, 1};
  case GL_BOOL_VEC4:
    return {Base::Bool, 4, 1};
  case GL_FLOAT_MAT2:
    return {Base::Float, 4, 2};
  case GL_FLOAT_MAT3:
    return {Base::Float, 9, 3};
  case GL_FLOAT_MAT4:
    return {Base::Float, 16, 4};
  case GL_FLOAT_MAT2x3:
    return {Base::Float, 6, 2};
  case GL_FLOAT_MAT2x4:
    return {Base::Float, 8, 2};
  case GL_FLOAT_MAT3x2:
    return {Base::Float, 6, 3};
  case GL_FLOAT_MAT3x4:
    return {Base::Float, 12, 3};
  case GL_FLOAT_MAT4x2:
    return {Base::Float, 8, 4};
  case GL_FLOAT_MAT4x3:
    return {Base::Float, 12, 4};
  default:
    return {Base::Sampler, 1, 1};
  }
}

bool is_matrix(GLenum type) {
  return type_info(type).cols > 1;
}

// What the command loads: vectors of `components` floats or ints, or matrices of cols x rows.
struct Command {
  const char* name;
  int components;
  bool ints;
  int cols = 0; // matrices: columns; 0 for the vector commands
  int rows = 0;
};

// The location's uniform when `cmd` may load `count` values into it, else null with the
// error §2.15.3 names. Location -1 loads nothing, without an error.
LinkedProgram* target(Context* ctx, const Command& cmd, GLint location, GLsizei count,
                      const glsl::UniformLocation** loc_out, const glsl::ActiveUniform** u_out) {
  if (count < 0) {
    record_error(ctx, GL_INVALID_VALUE, cmd.name);
    return nullptr;
  }
  ProgramObject* p = ctx->program.object;
  if (p == nullptr || !p->active) {
    record_error(ctx, GL_INVALID_OPERATION, cmd.name);
    return nullptr;
  }
  if (location == -1) return nullptr;
  LinkedProgram& lp = *p->active;
  const auto& locations = lp.program->locations();
  if (location < 0 || static_cast<size_t>(location) >= locations.size()) {
    record_error(ctx, GL_INVALID_OPERATION, cmd.name);
    return nullptr;
  }
  const glsl::UniformLocation& loc = locations[static_cast<size_t>(location)];
  const glsl::ActiveUniform& u = lp.program->uniforms()[static_cast<size_t>(loc.uniform)];
  const TypeInfo t = type_info(u.type);
  bool ok;
  if (cmd.cols != 0) {
    // UniformMatrix{2,3,4}fv and the non-square forms: exactly the uniform's matrix type.
    ok = is_matrix(u.type) && t.cols == cmd.cols && t.components == cmd.cols * cmd.rows;
  } else if (is_matrix(u.type)) {
    ok = false;
  } else if (t.base == Base::Sampler) {
    ok = cmd.ints && cmd.components == 1; // samplers: Uniform1i{v} only
  } else {
    // Size must match; floats load float and bool types, ints int and bool types.
    ok = t.components == cmd.components &&
         (t.base == Base::Bool || (t.base == Base::Int) == cmd.ints);
  }
  // More than one value is only for arrays.
  if (ok && count > 1 && !u.array) ok = false;
  if (!ok) {
    record_error(ctx, GL_INVALID_OPERATION, cmd.name);
    return nullptr;
  }
  *loc_out = &loc;
  *u_out = &u;
  return &lp;
}

template <typename T> uint32_t to_word(Base base, T v) {
  switch (base) {
  case Base::Float:
    return std::bit_cast<uint32_t>(static_cast<float>(v));
  case Base::Bool:
    return v != T(0) ? 1u : 0u;
  default:
    return static_cast<uint32_t>(static_cast<int32_t>(v));
  }
}

// Loads count elements of the vector command's values (§2.15.3): elements past the end of
// the array are ignored.
template <typename T>
void load_vectors(Context* ctx, const Command& cmd, GLint location, GLsizei count, const T* v) {
  const glsl::UniformLocation* loc;
  const glsl::ActiveUniform* u;
  LinkedProgram* lp = target(ctx, cmd, location, count, &loc, &u);
  if (lp == nullptr || v == nullptr) return;
  const TypeInfo t = type_info(u->type);
  if (t.base == Base::Sampler) {
    for (GLsizei e = 0; e < count; ++e)
      if (v[e] < T(0) || v[e] >= T(kMaxCombinedTextureImageUnits))
        return record_error(ctx, GL_INVALID_VALUE, cmd.name);
  }
  const int elements = std::min(static_cast<int>(count), u->size - loc->element);
  for (int e = 0; e < elements; ++e)
    for (int c = 0; c < cmd.components; ++c)
      lp->uniforms[static_cast<size_t>(loc->word + e * u->stride + c)] =
          to_word(t.base, v[e * cmd.components + c]);
  ++lp->uniform_serial;
}

void load_matrices(Context* ctx, const Command& cmd, GLint location, GLsizei count,
                   GLboolean transpose, const GLfloat* v) {
  const glsl::UniformLocation* loc;
  const glsl::ActiveUniform* u;
  LinkedProgram* lp = target(ctx, cmd, location, count, &loc, &u);
  if (lp == nullptr || v == nullptr) return;
  const int n = cmd.cols * cmd.rows;
  const int elements = std::min(static_cast<int>(count), u->size - loc->element);
  for (int e = 0; e < elements; ++e)
    for (int c = 0; c < cmd.cols; ++c)
      for (int r = 0; r < cmd.rows; ++r) {
        // Column-major in the buffer; transposed input is row-major (§2.15.3).
        const float x = transpose ? v[e * n + r * cmd.cols + c] : v[e * n + c * cmd.rows + r];
        lp->uniforms[static_cast<size_t>(loc->word + e * u->stride + c * cmd.rows + r)] =
            std::bit_cast<uint32_t>(x);
      }
  ++lp->uniform_serial;
}

// GetUniform{f,i}v: the program must be linked and the location one of its (§6.1.15).
const LinkedProgram* query_target(Context* ctx, GLuint program, GLint location, const char* func,
                                  const glsl::UniformLocation** loc_out,
                                  const glsl::ActiveUniform** u_out) {
  ProgramObject* p = find_program(ctx, program, func);
  if (p == nullptr) return nullptr;
  if (!p->link_status || !p->last) {
    record_error(ctx, GL_INVALID_OPERATION, func);
    return nullptr;
  }
  const LinkedProgram& lp = *p->last;
  const auto& locations = lp.program->locations();
  if (location < 0 || static_cast<size_t>(location) >= locations.size()) {
    record_error(ctx, GL_INVALID_OPERATION, func);
    return nullptr;
  }
  *loc_out = &locations[static_cast<size_t>(location)];
  *u_out = &lp.program->uniforms()[static_cast<size_t>((*loc_out)->uniform)];
  return &lp;
}

template <typename T>
void get_uniform(GLuint program, GLint location, T* params, const char* func) {
  PINEDA_CTX_OUTSIDE(func);
  const glsl::UniformLocation* loc;
  const glsl::ActiveUniform* u;
  const LinkedProgram* lp = query_target(ctx, program, location, func, &loc, &u);
  if (lp == nullptr || params == nullptr) return;
  const TypeInfo t = type_info(u->type);
  for (int c = 0; c < t.components; ++c) {
    const uint32_t w = lp->uniforms[static_cast<size_t>(loc->word + c)];
    if (t.base == Base::Float) {
      const float f = std::bit_cast<float>(w);
      if constexpr (std::is_integral_v<T>)
        params[c] = static_cast<T>(std::lround(f)); // §6.1.2: rounded to the nearest
      else
        params[c] = f;
    } else {
      params[c] = static_cast<T>(static_cast<int32_t>(w));
    }
  }
}

} // namespace

namespace exec {

#define PINEDA_UNIFORM_VEC(N, SUFFIX, T, INTS)                                                     \
  void GLAPIENTRY Uniform##N##SUFFIX##v(GLint location, GLsizei count, const T* value) {           \
    PINEDA_CTX_OUTSIDE("glUniform" #N #SUFFIX "v");                                                \
    load_vectors(ctx, {"glUniform" #N #SUFFIX "v", N, INTS}, location, count, value);              \
  }

PINEDA_UNIFORM_VEC(1, f, GLfloat, false)
PINEDA_UNIFORM_VEC(2, f, GLfloat, false)
PINEDA_UNIFORM_VEC(3, f, GLfloat, false)
PINEDA_UNIFORM_VEC(4, f, GLfloat, false)
PINEDA_UNIFORM_VEC(1, i, GLint, true)
PINEDA_UNIFORM_VEC(2, i, GLint, true)
PINEDA_UNIFORM_VEC(3, i, GLint, true)
PINEDA_UNIFORM_VEC(4, i, GLint, true)
#undef PINEDA_UNIFORM_VEC

void GLAPIENTRY Uniform1f(GLint location, GLfloat v0) {
  PINEDA_CTX_OUTSIDE("glUniform1f");
  const GLfloat v[1] = {v0};
  load_vectors(ctx, {"glUniform1f", 1, false}, location, 1, v);
}
void GLAPIENTRY Uniform2f(GLint location, GLfloat v0, GLfloat v1) {
  PINEDA_CTX_OUTSIDE("glUniform2f");
  const GLfloat v[2] = {v0, v1};
  load_vectors(ctx, {"glUniform2f", 2, false}, location, 1, v);
}
void GLAPIENTRY Uniform3f(GLint location, GLfloat v0, GLfloat v1, GLfloat v2) {
  PINEDA_CTX_OUTSIDE("glUniform3f");
  const GLfloat v[3] = {v0, v1, v2};
  load_vectors(ctx, {"glUniform3f", 3, false}, location, 1, v);
}
void GLAPIENTRY Uniform4f(GLint location, GLfloat v0, GLfloat v1, GLfloat v2, GLfloat v3) {
  PINEDA_CTX_OUTSIDE("glUniform4f");
  const GLfloat v[4] = {v0, v1, v2, v3};
  load_vectors(ctx, {"glUniform4f", 4, false}, location, 1, v);
}
void GLAPIENTRY Uniform1i(GLint location, GLint v0) {
  PINEDA_CTX_OUTSIDE("glUniform1i");
  const GLint v[1] = {v0};
  load_vectors(ctx, {"glUniform1i", 1, true}, location, 1, v);
}
void GLAPIENTRY Uniform2i(GLint location, GLint v0, GLint v1) {
  PINEDA_CTX_OUTSIDE("glUniform2i");
  const GLint v[2] = {v0, v1};
  load_vectors(ctx, {"glUniform2i", 2, true}, location, 1, v);
}
void GLAPIENTRY Uniform3i(GLint location, GLint v0, GLint v1, GLint v2) {
  PINEDA_CTX_OUTSIDE("glUniform3i");
  const GLint v[3] = {v0, v1, v2};
  load_vectors(ctx, {"glUniform3i", 3, true}, location, 1, v);
}
void GLAPIENTRY Uniform4i(GLint location, GLint v0, GLint v1, GLint v2, GLint v3) {
  PINEDA_CTX_OUTSIDE("glUniform4i");
  const GLint v[4] = {v0, v1, v2, v3};
  load_vectors(ctx, {"glUniform4i", 4, true}, location, 1, v);
}

#define PINEDA_UNIFORM_MAT(NAME, C, R)                                                             \
  void GLAPIENTRY UniformMatrix##NAME##fv(GLint location, GLsizei count, GLboolean transpose,      \
                                          const GLfloat* value) {                                  \
    PINEDA_CTX_OUTSIDE("glUniformMatrix" #NAME "fv");                                              \
    load_matrices(ctx, {"glUniformMatrix" #NAME "fv", C * R, false, C, R}, location, count,        \
                  transpose, value);                                                               \
  }

PINEDA_UNIFORM_MAT(2, 2, 2)
PINEDA_UNIFORM_MAT(3, 3, 3)
PINEDA_UNIFORM_MAT(4, 4, 4)
PINEDA_UNIFORM_MAT(2x3, 2, 3)
PINEDA_UNIFORM_MAT(3x2, 3, 2)
PINEDA_UNIFORM_MAT(2x4, 2, 4)
PINEDA_UNIFORM_MAT(4x2, 4, 2)
PINEDA_UNIFORM_MAT(3x4, 3, 4)
PINEDA_UNIFORM_MAT(4x3, 4, 3)
#undef PINEDA_UNIFORM_MAT

GLint GLAPIENTRY GetUniformLocation(GLuint program, const GLchar* name) {
  Context* ctx = outside_begin_end("glGetUniformLocation");
  if (ctx == nullptr) return -1;
  ProgramObject* p = find_program(ctx, program, "glGetUniformLocation");
  if (p == nullptr) return -1;
  if (!p->link_status || !p->last) {
    record_error(ctx, GL_INVALID_OPERATION, "glGetUniformLocation");
    return -1;
  }
  return name != nullptr ? p->last->program->uniform_location(name) : -1;
}

void GLAPIENTRY GetActiveUniform(GLuint program, GLuint index, GLsizei bufSize, GLsizei* length,
                                 GLint* size, GLenum* type, GLchar* name) {
  PINEDA_CTX_OUTSIDE("glGetActiveUniform");
  ProgramObject* p = find_program(ctx, program, "glGetActiveUniform");
  if (p == nullptr) return;
  const glsl::Program* linked = p->link_status && p->last ? p->last->program.get() : nullptr;
  if (linked == nullptr || index >= linked->uniforms().size() || bufSize < 0)
    return record_error(ctx, GL_INVALID_VALUE, "glGetActiveUniform");
  const glsl::ActiveUniform& u = linked->uniforms()[index];
  copy_string(u.name, bufSize, length, name);
  if (size != nullptr) *size = u.size;
  if (type != nullptr) *type = u.type;
}

void GLAPIENTRY GetUniformfv(GLuint program, GLint location, GLfloat* params) {
  get_uniform(program, location, params, "glGetUniformfv");
}

void GLAPIENTRY GetUniformiv(GLuint program, GLint location, GLint* params) {
  get_uniform(program, location, params, "glGetUniformiv");
}

} // namespace exec
} // namespace pineda
