// Generic vertex attributes (GL 2.1 §2.7, §2.8): VertexAttrib* (attribute 0 is the vertex),
// VertexAttribPointer and the generic arrays, their fetch for the draws, and the queries
// GetVertexAttrib* (§6.1.15).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "core/normalize.h"
#include "dispatch.h"
#include "state/api_util.h"
#include "state/fetch.h"
#include "state/program_internal.h"

namespace pineda {

namespace {

// VertexAttrib with index `index` and (x, y, z, w): attribute 0 is Vertex (§2.7), the others
// set the current value.
void attrib(const char* func, GLuint index, float x, float y, float z, float w) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  if (index >= static_cast<GLuint>(kMaxVertexAttribs))
    return record_error(ctx, GL_INVALID_VALUE, func);
  if (index == 0) return exec::Vertex4f(x, y, z, w);
  float* v = ctx->vertex_attrib.value[index];
  v[0] = x, v[1] = y, v[2] = z, v[3] = w;
}

template <typename T> void attrib_n(const char* func, GLuint index, int n, const T* v) {
  if (v == nullptr) return;
  float f[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  for (int i = 0; i < n; ++i)
    f[i] = static_cast<float>(v[i]);
  attrib(func, index, f[0], f[1], f[2], f[3]);
}

template <typename T> void attrib_norm(const char* func, GLuint index, const T* v) {
  if (v == nullptr) return;
  attrib(func, index, norm_divided(v[0]), norm_divided(v[1]), norm_divided(v[2]),
         norm_divided(v[3]));
}

GenericArray* generic_array(Context* ctx, GLuint index, const char* func) {
  if (index >= static_cast<GLuint>(kMaxVertexAttribs)) {
    record_error(ctx, GL_INVALID_VALUE, func);
    return nullptr;
  }
  return &ctx->attrib_arrays.array[index];
}

size_t generic_stride(const GenericArray& a) {
  return a.stride != 0 ? static_cast<size_t>(a.stride)
                       : static_cast<size_t>(a.size) * type_size(a.type);
}

// Where the array's data starts, or null when a buffer-backed array would read past its
// buffer's storage for element `max_element`.
const uint8_t* generic_base(Context* ctx, const GenericArray& a, size_t max_element) {
  if (a.buffer == 0) return static_cast<const uint8_t*>(a.pointer);
  auto it = ctx->buffers.find(a.buffer);
  if (it == ctx->buffers.end()) return nullptr;
  const std::vector<uint8_t>& data = it->second->data;
  const size_t offset = reinterpret_cast<uintptr_t>(a.pointer);
  const size_t need =
      offset + max_element * generic_stride(a) + static_cast<size_t>(a.size) * type_size(a.type);
  if (need > data.size() || need < offset) return nullptr;
  return data.data() + offset;
}

template <typename T> float component(const uint8_t* p, bool normalized) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return normalized ? norm_divided(v) : static_cast<float>(v);
}

float read_component(GLenum type, const uint8_t* p, bool normalized) {
  switch (type) {
  case GL_BYTE:
    return component<GLbyte>(p, normalized);
  case GL_UNSIGNED_BYTE:
    return component<GLubyte>(p, normalized);
  case GL_SHORT:
    return component<GLshort>(p, normalized);
  case GL_UNSIGNED_SHORT:
    return component<GLushort>(p, normalized);
  case GL_INT:
    return component<GLint>(p, normalized);
  case GL_UNSIGNED_INT:
    return component<GLuint>(p, normalized);
  case GL_DOUBLE:
    return static_cast<float>(component<GLdouble>(p, false));
  default:
    return component<GLfloat>(p, false);
  }
}

// Element el(k) of every array of `mask` into out (4 floats per attribute per vertex); the
// attributes of `mask` without an enabled array take their current values.
template <typename Elements>
bool fetch_generic(Context* ctx, uint32_t mask, Elements el, size_t n, size_t max_element,
                   float* out) {
  const int per_vertex = 4 * std::popcount(mask);
  int slot = 0;
  for (uint32_t m = mask; m != 0; m &= m - 1, ++slot) {
    const int i = std::countr_zero(m);
    const GenericArray& a = ctx->attrib_arrays.array[i];
    float* dst = out + 4 * slot;
    if (!a.enabled) {
      const float* cur = ctx->vertex_attrib.value[i];
      for (size_t k = 0; k < n; ++k)
        std::copy(cur, cur + 4, dst + k * static_cast<size_t>(per_vertex));
      continue;
    }
    const uint8_t* base = generic_base(ctx, a, max_element);
    if (base == nullptr) return false;
    const size_t stride = generic_stride(a), size = type_size(a.type);
    for (size_t k = 0; k < n; ++k) {
      const uint8_t* src = base + el(k) * stride;
      float* d = dst + k * static_cast<size_t>(per_vertex);
      d[0] = 0.0f, d[1] = 0.0f, d[2] = 0.0f, d[3] = 1.0f;
      for (int c = 0; c < a.size; ++c)
        d[c] = read_component(a.type, src + static_cast<size_t>(c) * size, a.normalized);
    }
  }
  return true;
}

bool valid_pointer_type(GLenum type) {
  switch (type) {
  case GL_BYTE:
  case GL_UNSIGNED_BYTE:
  case GL_SHORT:
  case GL_UNSIGNED_SHORT:
  case GL_INT:
  case GL_UNSIGNED_INT:
  case GL_FLOAT:
  case GL_DOUBLE:
    return true;
  default:
    return false;
  }
}

// GetVertexAttrib{d,f,i}v: up to four values; false with the error set.
bool vertex_attrib_values(Context* ctx, GLuint index, GLenum pname, double* out, int* n,
                          const char* func) {
  const GenericArray* a = generic_array(ctx, index, func);
  if (a == nullptr) return false;
  *n = 1;
  switch (pname) {
  case GL_VERTEX_ATTRIB_ARRAY_ENABLED:
    out[0] = a->enabled ? 1 : 0;
    return true;
  case GL_VERTEX_ATTRIB_ARRAY_SIZE:
    out[0] = a->size;
    return true;
  case GL_VERTEX_ATTRIB_ARRAY_STRIDE:
    out[0] = a->stride;
    return true;
  case GL_VERTEX_ATTRIB_ARRAY_TYPE:
    out[0] = a->type;
    return true;
  case GL_VERTEX_ATTRIB_ARRAY_NORMALIZED:
    out[0] = a->normalized ? 1 : 0;
    return true;
  case GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING:
    out[0] = a->buffer;
    return true;
  case GL_CURRENT_VERTEX_ATTRIB:
    // §6.1.15: attribute 0 has no current value.
    if (index == 0) {
      record_error(ctx, GL_INVALID_OPERATION, func);
      return false;
    }
    *n = 4;
    for (int c = 0; c < 4; ++c)
      out[c] = ctx->vertex_attrib.value[index][c];
    return true;
  default:
    record_error(ctx, GL_INVALID_ENUM, func, pname);
    return false;
  }
}

} // namespace

bool fetch_generic_range(Context* ctx, uint32_t mask, size_t first, size_t n, float* out) {
  if (n == 0) return true;
  return fetch_generic(
      ctx, mask, [first](size_t k) { return first + k; }, n, first + n - 1, out);
}

bool fetch_generic_list(Context* ctx, uint32_t mask, const uint32_t* elements, size_t n,
                        float* out) {
  if (n == 0) return true;
  const size_t max_element = *std::max_element(elements, elements + n);
  return fetch_generic(
      ctx, mask, [elements](size_t k) { return static_cast<size_t>(elements[k]); }, n, max_element,
      out);
}

uint32_t enabled_generic_arrays(const Context* ctx) {
  uint32_t m = 0;
  for (int i = 1; i < kMaxVertexAttribs; ++i)
    if (ctx->attrib_arrays.array[i].enabled) m |= 1u << i;
  return m;
}

bool generic_array0_enabled(const Context* ctx) {
  return ctx->attrib_arrays.array[0].enabled;
}

namespace exec {

#define PINEDA_ATTRIB(N, S, T)                                                                     \
  void GLAPIENTRY VertexAttrib##N##S##v(GLuint index, const T* v) {                                \
    attrib_n("glVertexAttrib" #N #S "v", index, N, v);                                             \
  }
PINEDA_ATTRIB(1, s, GLshort)
PINEDA_ATTRIB(1, f, GLfloat)
PINEDA_ATTRIB(1, d, GLdouble)
PINEDA_ATTRIB(2, s, GLshort)
PINEDA_ATTRIB(2, f, GLfloat)
PINEDA_ATTRIB(2, d, GLdouble)
PINEDA_ATTRIB(3, s, GLshort)
PINEDA_ATTRIB(3, f, GLfloat)
PINEDA_ATTRIB(3, d, GLdouble)
PINEDA_ATTRIB(4, s, GLshort)
PINEDA_ATTRIB(4, f, GLfloat)
PINEDA_ATTRIB(4, d, GLdouble)
PINEDA_ATTRIB(4, b, GLbyte)
PINEDA_ATTRIB(4, i, GLint)
PINEDA_ATTRIB(4, ub, GLubyte)
PINEDA_ATTRIB(4, us, GLushort)
PINEDA_ATTRIB(4, ui, GLuint)
#undef PINEDA_ATTRIB

#define PINEDA_ATTRIB_N(S, T)                                                                      \
  void GLAPIENTRY VertexAttrib4N##S##v(GLuint index, const T* v) {                                 \
    attrib_norm("glVertexAttrib4N" #S "v", index, v);                                              \
  }
PINEDA_ATTRIB_N(b, GLbyte)
PINEDA_ATTRIB_N(s, GLshort)
PINEDA_ATTRIB_N(i, GLint)
PINEDA_ATTRIB_N(ub, GLubyte)
PINEDA_ATTRIB_N(us, GLushort)
PINEDA_ATTRIB_N(ui, GLuint)
#undef PINEDA_ATTRIB_N

void GLAPIENTRY VertexAttrib1s(GLuint index, GLshort x) {
  attrib("glVertexAttrib1s", index, x, 0.0f, 0.0f, 1.0f);
}
void GLAPIENTRY VertexAttrib1f(GLuint index, GLfloat x) {
  attrib("glVertexAttrib1f", index, x, 0.0f, 0.0f, 1.0f);
}
void GLAPIENTRY VertexAttrib1d(GLuint index, GLdouble x) {
  attrib("glVertexAttrib1d", index, static_cast<float>(x), 0.0f, 0.0f, 1.0f);
}
void GLAPIENTRY VertexAttrib2s(GLuint index, GLshort x, GLshort y) {
  attrib("glVertexAttrib2s", index, x, y, 0.0f, 1.0f);
}
void GLAPIENTRY VertexAttrib2f(GLuint index, GLfloat x, GLfloat y) {
  attrib("glVertexAttrib2f", index, x, y, 0.0f, 1.0f);
}
void GLAPIENTRY VertexAttrib2d(GLuint index, GLdouble x, GLdouble y) {
  attrib("glVertexAttrib2d", index, static_cast<float>(x), static_cast<float>(y), 0.0f, 1.0f);
}
void GLAPIENTRY VertexAttrib3s(GLuint index, GLshort x, GLshort y, GLshort z) {
  attrib("glVertexAttrib3s", index, x, y, z, 1.0f);
}
void GLAPIENTRY VertexAttrib3f(GLuint index, GLfloat x, GLfloat y, GLfloat z) {
  attrib("glVertexAttrib3f", index, x, y, z, 1.0f);
}
void GLAPIENTRY VertexAttrib3d(GLuint index, GLdouble x, GLdouble y, GLdouble z) {
  attrib("glVertexAttrib3d", index, static_cast<float>(x), static_cast<float>(y),
         static_cast<float>(z), 1.0f);
}
void GLAPIENTRY VertexAttrib4s(GLuint index, GLshort x, GLshort y, GLshort z, GLshort w) {
  attrib("glVertexAttrib4s", index, x, y, z, w);
}
void GLAPIENTRY VertexAttrib4f(GLuint index, GLfloat x, GLfloat y, GLfloat z, GLfloat w) {
  attrib("glVertexAttrib4f", index, x, y, z, w);
}
void GLAPIENTRY VertexAttrib4d(GLuint index, GLdouble x, GLdouble y, GLdouble z, GLdouble w) {
  attrib("glVertexAttrib4d", index, static_cast<float>(x), static_cast<float>(y),
         static_cast<float>(z), static_cast<float>(w));
}
void GLAPIENTRY VertexAttrib4Nub(GLuint index, GLubyte x, GLubyte y, GLubyte z, GLubyte w) {
  const GLubyte v[4] = {x, y, z, w};
  attrib_norm("glVertexAttrib4Nub", index, v);
}

void GLAPIENTRY VertexAttribPointer(GLuint index, GLint size, GLenum type, GLboolean normalized,
                                    GLsizei stride, const void* pointer) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  GenericArray* a = generic_array(ctx, index, "glVertexAttribPointer");
  if (a == nullptr) return;
  if (size < 1 || size > 4 || stride < 0)
    return record_error(ctx, GL_INVALID_VALUE, "glVertexAttribPointer");
  if (!valid_pointer_type(type))
    return record_error(ctx, GL_INVALID_ENUM, "glVertexAttribPointer", type);
  a->size = size;
  a->type = type;
  a->normalized = normalized != GL_FALSE;
  a->stride = stride;
  a->pointer = pointer;
  a->buffer = ctx->arrays.array_buffer; // §2.9: the binding when the pointer is specified
}

void GLAPIENTRY EnableVertexAttribArray(GLuint index) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  if (GenericArray* a = generic_array(ctx, index, "glEnableVertexAttribArray")) a->enabled = true;
}

void GLAPIENTRY DisableVertexAttribArray(GLuint index) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  if (GenericArray* a = generic_array(ctx, index, "glDisableVertexAttribArray")) a->enabled = false;
}

void GLAPIENTRY GetVertexAttribdv(GLuint index, GLenum pname, GLdouble* params) {
  PINEDA_CTX_OUTSIDE("glGetVertexAttribdv");
  double v[4];
  int n = 0;
  if (!vertex_attrib_values(ctx, index, pname, v, &n, "glGetVertexAttribdv") || !params) return;
  for (int i = 0; i < n; ++i)
    params[i] = v[i];
}

void GLAPIENTRY GetVertexAttribfv(GLuint index, GLenum pname, GLfloat* params) {
  PINEDA_CTX_OUTSIDE("glGetVertexAttribfv");
  double v[4];
  int n = 0;
  if (!vertex_attrib_values(ctx, index, pname, v, &n, "glGetVertexAttribfv") || !params) return;
  for (int i = 0; i < n; ++i)
    params[i] = static_cast<GLfloat>(v[i]);
}

void GLAPIENTRY GetVertexAttribiv(GLuint index, GLenum pname, GLint* params) {
  PINEDA_CTX_OUTSIDE("glGetVertexAttribiv");
  double v[4];
  int n = 0;
  if (!vertex_attrib_values(ctx, index, pname, v, &n, "glGetVertexAttribiv") || !params) return;
  // §6.1.2: floating-point state (the current value) is rounded to the nearest integer.
  for (int i = 0; i < n; ++i)
    params[i] = static_cast<GLint>(std::lround(v[i]));
}

void GLAPIENTRY GetVertexAttribPointerv(GLuint index, GLenum pname, void** pointer) {
  PINEDA_CTX_OUTSIDE("glGetVertexAttribPointerv");
  const GenericArray* a = generic_array(ctx, index, "glGetVertexAttribPointerv");
  if (a == nullptr) return;
  if (pname != GL_VERTEX_ATTRIB_ARRAY_POINTER)
    return record_error(ctx, GL_INVALID_ENUM, "glGetVertexAttribPointerv", pname);
  if (pointer != nullptr) *pointer = const_cast<void*>(a->pointer);
}

} // namespace exec
} // namespace pineda
