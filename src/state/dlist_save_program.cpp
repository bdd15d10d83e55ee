// Display-list savers (GL 2.1 §5.4) for the generic vertex attributes and the uniform arrays.
// VertexAttrib with index 0 is a vertex (§2.7) and compiles into the open vertex block like
// Vertex; the other indices are recorded as calls (a vertex block open at that point is then
// executed call by call, so that each vertex sees the generic values set before it). Uniform*v
// and UniformMatrix*fv copy their count * N values when compiled; arguments the command will
// reject are recorded as they are and fail when the list executes.
#include <algorithm>
#include <bit>
#include <cstring>
#include <type_traits>
#include <vector>

#include "core/normalize.h"
#include "dispatch.h"
#include "state/api_util.h"
#include "state/dlist_internal.h"
#include "state/fetch.h"

namespace pineda {

namespace {

bool executes(const Context* ctx) {
  return ctx == nullptr || list_executes(ctx);
}

struct AttribArgs {
  GLuint index;
  float v[4];
};

void replay_attrib(const void* p) {
  AttribArgs a;
  std::memcpy(&a, p, sizeof a);
  exec::VertexAttrib4f(a.index, a.v[0], a.v[1], a.v[2], a.v[3]);
}

void attrib(GLuint index, float x, float y, float z, float w) {
  Context* ctx = compiling_list();
  if (ctx != nullptr) {
    if (index == 0) {
      compile_vertex(ctx, x, y, z, w);
    } else {
      const AttribArgs a{index, {x, y, z, w}};
      // dlist_record closes an open vertex block first (prepare_command).
      prepare_command(ctx);
      append_record(ctx, &replay_attrib, &a, sizeof a);
    }
  }
  if (executes(ctx)) exec::VertexAttrib4f(index, x, y, z, w);
}

template <typename T> void attrib_v(GLuint index, int n, const T* v) {
  if (v == nullptr) return;
  float f[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  for (int i = 0; i < n; ++i)
    f[i] = static_cast<float>(v[i]);
  attrib(index, f[0], f[1], f[2], f[3]);
}

template <typename T> void attrib_nv(GLuint index, const T* v) {
  if (v == nullptr) return;
  attrib(index, norm_divided(v[0]), norm_divided(v[1]), norm_divided(v[2]), norm_divided(v[3]));
}

// Uniform*v and UniformMatrix*fv: the header, then the copied values.
struct UniformHeader {
  GLint location;
  GLsizei count;
  GLboolean transpose;
  bool has_values;
};
constexpr size_t kHeaderWords = (sizeof(UniformHeader) + 7) / 8;

// No uniform has more than kMaxUniformComponents elements, and Uniform* ignores elements past
// the end of an array (§2.15.3), so a larger count loads what this many would.
constexpr GLsizei kMaxCopiedElements = 4096;

template <typename T, int N>
std::vector<uint64_t> uniform_record(const UniformHeader& h, const T* v) {
  const size_t values = h.has_values ? static_cast<size_t>(h.count) * N : 0;
  std::vector<uint64_t> rec(kHeaderWords + (values * sizeof(T) + 7) / 8);
  std::memcpy(rec.data(), &h, sizeof h);
  if (values != 0) std::memcpy(rec.data() + kHeaderWords, v, values * sizeof(T));
  return rec;
}

template <typename T, void(GLAPIENTRY* Fn)(GLint, GLsizei, const T*)>
void replay_uniform(const void* p) {
  UniformHeader h;
  std::memcpy(&h, p, sizeof h);
  const auto* values = reinterpret_cast<const T*>(static_cast<const uint64_t*>(p) + kHeaderWords);
  Fn(h.location, h.count, h.has_values ? values : nullptr);
}

template <void(GLAPIENTRY* Fn)(GLint, GLsizei, GLboolean, const GLfloat*)>
void replay_matrix(const void* p) {
  UniformHeader h;
  std::memcpy(&h, p, sizeof h);
  const auto* values =
      reinterpret_cast<const GLfloat*>(static_cast<const uint64_t*>(p) + kHeaderWords);
  Fn(h.location, h.count, h.transpose, h.has_values ? values : nullptr);
}

template <typename T, int N, void(GLAPIENTRY* Fn)(GLint, GLsizei, const T*)>
void save_uniform(GLint location, GLsizei count, const T* value) {
  Context* ctx = compiling_list();
  if (ctx != nullptr) {
    const UniformHeader h{location, std::min(count, kMaxCopiedElements), GL_FALSE,
                          value != nullptr && count > 0};
    const std::vector<uint64_t> rec = uniform_record<T, N>(h, value);
    dlist_record(&replay_uniform<T, Fn>, rec.data(), rec.size() * sizeof(uint64_t));
  }
  if (executes(ctx)) Fn(location, count, value);
}

template <int N, void(GLAPIENTRY* Fn)(GLint, GLsizei, GLboolean, const GLfloat*)>
void save_matrix(GLint location, GLsizei count, GLboolean transpose, const GLfloat* value) {
  Context* ctx = compiling_list();
  if (ctx != nullptr) {
    const UniformHeader h{location, std::min(count, kMaxCopiedElements), transpose,
                          value != nullptr && count > 0};
    const std::vector<uint64_t> rec = uniform_record<GLfloat, N>(h, value);
    dlist_record(&replay_matrix<Fn>, rec.data(), rec.size() * sizeof(uint64_t));
  }
  if (executes(ctx)) Fn(location, count, transpose, value);
}

void replay_end(const void*) {
  exec::End();
}

} // namespace

void compile_generic_elements(Context* ctx, const uint32_t* elements, size_t count) {
  const uint32_t generic = enabled_generic_arrays(ctx);
  const bool vertex0 = generic_array0_enabled(ctx);
  float values[4 * kMaxVertexAttribs];
  for (size_t k = 0; k < count; ++k) {
    const size_t e = elements[k];
    InputVertex v;
    // §5.4: the arrays are dereferenced now; elements they do not hold end the draw.
    if (!fetch_range(ctx, e, 1, &v)) return;
    if (generic != 0 && !fetch_generic_range(ctx, generic, e, 1, values)) return;
    if (vertex0 && !fetch_generic_range(ctx, 1u, e, 1, v.pos)) return;
    compile_array_attribs(ctx, v);
    int slot = 0;
    for (uint32_t m = generic; m != 0; m &= m - 1, ++slot) {
      const AttribArgs a{
          static_cast<GLuint>(std::countr_zero(m)),
          {values[4 * slot], values[4 * slot + 1], values[4 * slot + 2], values[4 * slot + 3]}};
      prepare_command(ctx);
      append_record(ctx, &replay_attrib, &a, sizeof a);
    }
    if (vertex0 || ctx->arrays.vertex.enabled)
      compile_vertex(ctx, v.pos[0], v.pos[1], v.pos[2], v.pos[3]);
  }
}

void compile_generic_draw(Context* ctx, GLenum mode, const uint32_t* elements, size_t count) {
  compile_begin(ctx, mode);
  compile_generic_elements(ctx, elements, count);
  // The block is still open unless a generic attribute closed it (its calls then replay one
  // by one, §5.4 leaves the draw's meaning unchanged).
  if (ctx->dlist.block)
    compile_end(ctx);
  else
    append_record(ctx, &replay_end, nullptr, 0);
}

namespace saver {

#define PINEDA_SAVE_ATTRIB_V(N, S, T)                                                              \
  void GLAPIENTRY VertexAttrib##N##S##v(GLuint index, const T* v) {                                \
    attrib_v(index, N, v);                                                                         \
  }
PINEDA_SAVE_ATTRIB_V(1, s, GLshort)
PINEDA_SAVE_ATTRIB_V(1, f, GLfloat)
PINEDA_SAVE_ATTRIB_V(1, d, GLdouble)
PINEDA_SAVE_ATTRIB_V(2, s, GLshort)
PINEDA_SAVE_ATTRIB_V(2, f, GLfloat)
PINEDA_SAVE_ATTRIB_V(2, d, GLdouble)
PINEDA_SAVE_ATTRIB_V(3, s, GLshort)
PINEDA_SAVE_ATTRIB_V(3, f, GLfloat)
PINEDA_SAVE_ATTRIB_V(3, d, GLdouble)
PINEDA_SAVE_ATTRIB_V(4, s, GLshort)
PINEDA_SAVE_ATTRIB_V(4, f, GLfloat)
PINEDA_SAVE_ATTRIB_V(4, d, GLdouble)
PINEDA_SAVE_ATTRIB_V(4, b, GLbyte)
PINEDA_SAVE_ATTRIB_V(4, i, GLint)
PINEDA_SAVE_ATTRIB_V(4, ub, GLubyte)
PINEDA_SAVE_ATTRIB_V(4, us, GLushort)
PINEDA_SAVE_ATTRIB_V(4, ui, GLuint)
#undef PINEDA_SAVE_ATTRIB_V

#define PINEDA_SAVE_ATTRIB_NV(S, T)                                                                \
  void GLAPIENTRY VertexAttrib4N##S##v(GLuint index, const T* v) {                                 \
    attrib_nv(index, v);                                                                           \
  }
PINEDA_SAVE_ATTRIB_NV(b, GLbyte)
PINEDA_SAVE_ATTRIB_NV(s, GLshort)
PINEDA_SAVE_ATTRIB_NV(i, GLint)
PINEDA_SAVE_ATTRIB_NV(ub, GLubyte)
PINEDA_SAVE_ATTRIB_NV(us, GLushort)
PINEDA_SAVE_ATTRIB_NV(ui, GLuint)
#undef PINEDA_SAVE_ATTRIB_NV

void GLAPIENTRY VertexAttrib1s(GLuint index, GLshort x) {
  attrib(index, x, 0.0f, 0.0f, 1.0f);
}
void GLAPIENTRY VertexAttrib1f(GLuint index, GLfloat x) {
  attrib(index, x, 0.0f, 0.0f, 1.0f);
}
void GLAPIENTRY VertexAttrib1d(GLuint index, GLdouble x) {
  attrib(index, static_cast<float>(x), 0.0f, 0.0f, 1.0f);
}
void GLAPIENTRY VertexAttrib2s(GLuint index, GLshort x, GLshort y) {
  attrib(index, x, y, 0.0f, 1.0f);
}
void GLAPIENTRY VertexAttrib2f(GLuint index, GLfloat x, GLfloat y) {
  attrib(index, x, y, 0.0f, 1.0f);
}
void GLAPIENTRY VertexAttrib2d(GLuint index, GLdouble x, GLdouble y) {
  attrib(index, static_cast<float>(x), static_cast<float>(y), 0.0f, 1.0f);
}
void GLAPIENTRY VertexAttrib3s(GLuint index, GLshort x, GLshort y, GLshort z) {
  attrib(index, x, y, z, 1.0f);
}
void GLAPIENTRY VertexAttrib3f(GLuint index, GLfloat x, GLfloat y, GLfloat z) {
  attrib(index, x, y, z, 1.0f);
}
void GLAPIENTRY VertexAttrib3d(GLuint index, GLdouble x, GLdouble y, GLdouble z) {
  attrib(index, static_cast<float>(x), static_cast<float>(y), static_cast<float>(z), 1.0f);
}
void GLAPIENTRY VertexAttrib4s(GLuint index, GLshort x, GLshort y, GLshort z, GLshort w) {
  attrib(index, x, y, z, w);
}
void GLAPIENTRY VertexAttrib4f(GLuint index, GLfloat x, GLfloat y, GLfloat z, GLfloat w) {
  attrib(index, x, y, z, w);
}
void GLAPIENTRY VertexAttrib4d(GLuint index, GLdouble x, GLdouble y, GLdouble z, GLdouble w) {
  attrib(index, static_cast<float>(x), static_cast<float>(y), static_cast<float>(z),
         static_cast<float>(w));
}
void GLAPIENTRY VertexAttrib4Nub(GLuint index, GLubyte x, GLubyte y, GLubyte z, GLubyte w) {
  const GLubyte v[4] = {x, y, z, w};
  attrib_nv(index, v);
}

#define PINEDA_SAVE_UNIFORM(N, S, T)                                                               \
  void GLAPIENTRY Uniform##N##S##v(GLint location, GLsizei count, const T* value) {                \
    save_uniform<T, N, &exec::Uniform##N##S##v>(location, count, value);                           \
  }
PINEDA_SAVE_UNIFORM(1, f, GLfloat)
PINEDA_SAVE_UNIFORM(2, f, GLfloat)
PINEDA_SAVE_UNIFORM(3, f, GLfloat)
PINEDA_SAVE_UNIFORM(4, f, GLfloat)
PINEDA_SAVE_UNIFORM(1, i, GLint)
PINEDA_SAVE_UNIFORM(2, i, GLint)
PINEDA_SAVE_UNIFORM(3, i, GLint)
PINEDA_SAVE_UNIFORM(4, i, GLint)
#undef PINEDA_SAVE_UNIFORM

#define PINEDA_SAVE_MATRIX(NAME, N)                                                                \
  void GLAPIENTRY UniformMatrix##NAME##fv(GLint location, GLsizei count, GLboolean transpose,      \
                                          const GLfloat* value) {                                  \
    save_matrix<N, &exec::UniformMatrix##NAME##fv>(location, count, transpose, value);             \
  }
PINEDA_SAVE_MATRIX(2, 4)
PINEDA_SAVE_MATRIX(3, 9)
PINEDA_SAVE_MATRIX(4, 16)
PINEDA_SAVE_MATRIX(2x3, 6)
PINEDA_SAVE_MATRIX(3x2, 6)
PINEDA_SAVE_MATRIX(2x4, 8)
PINEDA_SAVE_MATRIX(4x2, 8)
PINEDA_SAVE_MATRIX(3x4, 12)
PINEDA_SAVE_MATRIX(4x3, 12)
#undef PINEDA_SAVE_MATRIX

} // namespace saver
} // namespace pineda
