// The hand-written display-list savers (pineda::saver, listed in src/api/dlist_savers.txt):
// vertices and current attributes, which compile into vertex blocks (dlist.cpp); vertex array
// draws, dereferenced at compile time (GL 2.1 §5.4); parameters of computed size; CallList
// and CallLists. Each saver compiles the command and, in COMPILE_AND_EXECUTE mode, executes it
// through pineda::exec as well.
#include <algorithm>
#include <cstring>
#include <utility>
#include <vector>

#include "state/api_util.h"
#include "core/normalize.h"
#include "dispatch.h"
#include "state/fetch.h"
#include "state/dlist_internal.h"

namespace pineda {

namespace {

// Whether a saver must also execute its command: COMPILE_AND_EXECUTE, or no list at all.
bool executes(const Context* ctx) {
  return ctx == nullptr || list_executes(ctx);
}

// ---- vertices and current attributes ----------------------------------------------------

void attrib(uint32_t bit, float a, float b, float c, float d) {
  Context* ctx = compiling_list();
  const float v[4] = {a, b, c, d};
  if (ctx != nullptr) compile_attrib(ctx, bit, v);
  if (!executes(ctx)) return;
  switch (bit) {
  case kListColor:
    exec::Color4f(a, b, c, d);
    break;
  case kListColor2:
    exec::SecondaryColor3f(a, b, c);
    break;
  case kListNormal:
    exec::Normal3f(a, b, c);
    break;
  case kListTex:
    exec::TexCoord4f(a, b, c, d);
    break;
  case kListEdge:
    exec::EdgeFlag(a != 0.0f ? GL_TRUE : GL_FALSE);
    break;
  case kListFog:
    exec::FogCoordf(a);
    break;
  default: // kListTex1 .. kListTex3
    for (int u = 1; u < kMaxTexUnits; ++u)
      if (bit == list_tex_bit(u))
        exec::MultiTexCoord4f(GL_TEXTURE0 + static_cast<GLenum>(u), a, b, c, d);
    break;
  }
}

void vertex(float x, float y, float z, float w) {
  Context* ctx = compiling_list();
  if (ctx != nullptr) compile_vertex(ctx, x, y, z, w);
  if (executes(ctx)) exec::Vertex4f(x, y, z, w);
}

struct RectArgs {
  float x1, y1, x2, y2;
};

void replay_rect(const void* p) {
  RectArgs a;
  std::memcpy(&a, p, sizeof a);
  exec::Rectf(a.x1, a.y1, a.x2, a.y2);
}

// GL 2.1 §2.10: Rect is Begin(POLYGON), four vertices, End; Rect between Begin and End is an
// error, which the recorded call generates when the list executes.
template <typename T> void rect(T x1, T y1, T x2, T y2) {
  const RectArgs r{static_cast<float>(x1), static_cast<float>(y1), static_cast<float>(x2),
                   static_cast<float>(y2)};
  Context* ctx = compiling_list();
  if (ctx != nullptr) {
    if (ctx->dlist.block != nullptr) {
      dlist_record(&replay_rect, &r, sizeof r);
    } else {
      compile_begin(ctx, GL_POLYGON);
      compile_vertex(ctx, r.x1, r.y1, 0.0f, 1.0f);
      compile_vertex(ctx, r.x2, r.y1, 0.0f, 1.0f);
      compile_vertex(ctx, r.x2, r.y2, 0.0f, 1.0f);
      compile_vertex(ctx, r.x1, r.y2, 0.0f, 1.0f);
      mark_rect_block(ctx);
      compile_end(ctx);
    }
  }
  if (executes(ctx)) exec::Rectf(r.x1, r.y1, r.x2, r.y2);
}

void replay_begin(const void* p) {
  GLenum mode;
  std::memcpy(&mode, p, sizeof mode);
  exec::Begin(mode);
}

void replay_end(const void*) {
  exec::End();
}

// ---- vertex arrays ----------------------------------------------------------------------

bool valid_mode(GLenum mode) {
  return mode <= GL_POLYGON;
}

// GL 1.5 §2.9: drawing from a mapped buffer is INVALID_OPERATION.
bool arrays_mapped(Context* ctx, bool with_elements) {
  auto mapped = [ctx](GLuint name) {
    if (name == 0) return false;
    auto it = ctx->buffers.find(name);
    return it != ctx->buffers.end() && it->second->mapped;
  };
  const VertexArrayGroup& a = ctx->arrays;
  for (const ClientArray* array :
       {&a.vertex, &a.color, &a.normal, &a.texcoord[0], &a.texcoord[1], &a.texcoord[2],
        &a.texcoord[3], &a.edgeflag, &a.secondary, &a.fog})
    if (array->enabled && mapped(array->buffer)) return true;
  return with_elements && mapped(ctx->arrays.element_array_buffer);
}

// Elements [first, first + count) of the enabled arrays, compiled (§5.4: dereferenced now).
// A draw that yields no vertex (no vertex array, nothing in range) still compiles an empty
// array block: executed between Begin and End it is INVALID_OPERATION all the same (§2.6.3).
void compile_range(Context* ctx, GLenum mode, size_t first, size_t count) {
  if (enabled_generic_arrays(ctx) != 0 || generic_array0_enabled(ctx)) {
    std::vector<uint32_t> elements(count);
    for (size_t k = 0; k < count; ++k)
      elements[k] = static_cast<uint32_t>(first + k);
    return compile_generic_draw(ctx, mode, elements.data(), count);
  }
  std::vector<InputVertex> verts;
  if (count != 0 && ctx->arrays.vertex.enabled && arrays_hold(ctx, first + count - 1)) {
    verts.resize(count);
    if (!fetch_range(ctx, first, count, verts.data())) verts.clear();
  }
  compile_array_block(ctx, mode, std::move(verts), {});
}

// The indices of a DrawElements call as 32-bit values; false when they cannot be read.
bool read_indices(Context* ctx, GLsizei count, GLenum type, const void* indices,
                  std::vector<uint32_t>& out) {
  const auto* src = static_cast<const uint8_t*>(indices);
  const size_t size = type == GL_UNSIGNED_BYTE ? 1 : type == GL_UNSIGNED_SHORT ? 2 : 4;
  const size_t bytes = static_cast<size_t>(count) * size;
  if (ctx->arrays.element_array_buffer != 0) {
    auto it = ctx->buffers.find(ctx->arrays.element_array_buffer);
    if (it == ctx->buffers.end()) return false;
    const size_t offset = reinterpret_cast<uintptr_t>(indices);
    const std::vector<uint8_t>& data = it->second->data;
    if (offset > data.size() || bytes > data.size() - offset) return false;
    src = data.data() + offset;
  } else if (src == nullptr) {
    return false;
  }
  out.resize(static_cast<size_t>(count));
  for (size_t i = 0; i < out.size(); ++i) {
    if (size == 1) {
      out[i] = src[i];
    } else if (size == 2) {
      GLushort v;
      std::memcpy(&v, src + 2 * i, 2);
      out[i] = v;
    } else {
      std::memcpy(&out[i], src + 4 * i, 4);
    }
  }
  return true;
}

// The elements a DrawElements call names, compiled: the range they span when it is compact
// (the block keeps the indices, so shared vertices are transformed once), else one vertex per
// index.
// As compile_range, a draw that yields no vertex compiles an empty array block.
void compile_elements(Context* ctx, GLenum mode, GLsizei count, GLenum type, const void* indices) {
  std::vector<uint32_t> idx;
  if (enabled_generic_arrays(ctx) != 0 || generic_array0_enabled(ctx)) {
    if (count > 0 && read_indices(ctx, count, type, indices, idx))
      compile_generic_draw(ctx, mode, idx.data(), idx.size());
    else
      compile_array_block(ctx, mode, {}, {});
    return;
  }
  if (count == 0 || !ctx->arrays.vertex.enabled || !read_indices(ctx, count, type, indices, idx))
    return compile_array_block(ctx, mode, {}, {});
  const auto [lo_it, hi_it] = std::minmax_element(idx.begin(), idx.end());
  const uint32_t lo = *lo_it, hi = *hi_it;
  if (!arrays_hold(ctx, hi)) return compile_array_block(ctx, mode, {}, {});
  const size_t span = static_cast<size_t>(hi) - lo + 1;
  if (span <= 4 * idx.size() + 1024) {
    std::vector<InputVertex> verts(span);
    if (!fetch_range(ctx, lo, span, verts.data())) return compile_array_block(ctx, mode, {}, {});
    for (uint32_t& i : idx)
      i -= lo;
    compile_array_block(ctx, mode, std::move(verts), std::move(idx));
  } else {
    std::vector<InputVertex> verts(idx.size());
    if (!fetch_list(ctx, idx.data(), idx.size(), verts.data())) verts.clear();
    compile_array_block(ctx, mode, std::move(verts), {});
  }
}

// The errors DrawElements, DrawRangeElements and MultiDrawElements check (as varray.cpp
// does); 0 when there is none.
GLenum elements_error(Context* ctx, GLenum mode, GLsizei count, GLenum type) {
  if (!valid_mode(mode)) return GL_INVALID_ENUM;
  if (count < 0) return GL_INVALID_VALUE;
  if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT)
    return GL_INVALID_ENUM;
  if (arrays_mapped(ctx, true)) return GL_INVALID_OPERATION;
  return 0;
}

// ---- parameters of computed size --------------------------------------------------------

// Values each command's parameter vector holds for `pname` (GL 2.1 §2.14.2 Table 2.10):
// per command, so that a pname another command takes more values for (COLOR_INDEXES given to
// Lightfv) does not read past the array; 0 for a pname the command does not take.
int light_count(GLenum pname) {
  switch (pname) {
  case GL_AMBIENT:
  case GL_DIFFUSE:
  case GL_SPECULAR:
  case GL_POSITION:
    return 4;
  case GL_SPOT_DIRECTION:
    return 3;
  case GL_SPOT_EXPONENT:
  case GL_SPOT_CUTOFF:
  case GL_CONSTANT_ATTENUATION:
  case GL_LINEAR_ATTENUATION:
  case GL_QUADRATIC_ATTENUATION:
    return 1;
  default:
    return 0;
  }
}
int material_count(GLenum pname) {
  switch (pname) {
  case GL_AMBIENT:
  case GL_DIFFUSE:
  case GL_SPECULAR:
  case GL_EMISSION:
  case GL_AMBIENT_AND_DIFFUSE:
    return 4;
  case GL_COLOR_INDEXES:
    return 3;
  case GL_SHININESS:
    return 1;
  default:
    return 0;
  }
}
int light_model_count(GLenum pname) {
  switch (pname) {
  case GL_LIGHT_MODEL_AMBIENT:
    return 4;
  case GL_LIGHT_MODEL_LOCAL_VIEWER:
  case GL_LIGHT_MODEL_TWO_SIDE:
  case GL_LIGHT_MODEL_COLOR_CONTROL:
    return 1;
  default:
    return 0;
  }
}

template <typename T> struct ParamArgs {
  GLenum target; // light or face; unused by LightModel
  GLenum pname;
  T v[4];
};

template <typename T, void(GLAPIENTRY* Fn)(GLenum, GLenum, const T*)>
void replay_params(const void* p) {
  ParamArgs<T> a;
  std::memcpy(&a, p, sizeof a);
  Fn(a.target, a.pname, a.v);
}

template <typename T, void(GLAPIENTRY* Fn)(GLenum, const T*)>
void replay_model_params(const void* p) {
  ParamArgs<T> a;
  std::memcpy(&a, p, sizeof a);
  Fn(a.pname, a.v);
}

// A null pointer makes the command do nothing (as pineda::exec treats it), so nothing is
// compiled.
template <typename T>
bool record_params(ReplayFn fn, int (*count)(GLenum), GLenum target, GLenum pname,
                   const T* params) {
  if (params == nullptr) return false;
  ParamArgs<T> a{target, pname, {}};
  std::copy(params, params + count(pname), a.v);
  return dlist_record(fn, &a, sizeof a);
}

template <typename T> struct ScalarArgs {
  GLenum face;
  GLenum pname;
  T value;
};

template <typename T, void(GLAPIENTRY* Fn)(GLenum, GLenum, T)> void replay_scalar(const void* p) {
  ScalarArgs<T> a;
  std::memcpy(&a, p, sizeof a);
  Fn(a.face, a.pname, a.value);
}

// ---- display lists calling display lists ------------------------------------------------

struct CallListsData final : DlistObject {
  std::vector<GLuint> offsets;
};

void replay_call_list(const void* p) {
  GLuint list;
  std::memcpy(&list, p, sizeof list);
  exec::CallList(list);
}

// §5.4: the offsets were taken at compile time; the base is the one current at execution.
void replay_call_lists(const void* p) {
  const CallListsData* data;
  std::memcpy(&data, p, sizeof data);
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  const GLuint base = ctx->list.base;
  for (GLuint offset : data->offsets)
    call_list(ctx, base + offset);
}

struct CallListsError {
  GLsizei n;
  GLenum type;
};

void replay_call_lists_error(const void* p) {
  CallListsError a;
  std::memcpy(&a, p, sizeof a);
  exec::CallLists(a.n, a.type, nullptr);
}

void replay_pop_attrib(const void*) {
  exec::PopAttrib();
}

} // namespace

void compile_array_attribs(Context* ctx, const InputVertex& v) {
  const VertexArrayGroup& a = ctx->arrays;
  if (a.color.enabled) compile_attrib(ctx, kListColor, v.color);
  if (a.secondary.enabled) compile_attrib(ctx, kListColor2, v.color2);
  if (a.normal.enabled) compile_attrib(ctx, kListNormal, v.normal);
  for (int u = 0; u < kMaxTexUnits; ++u)
    if (a.texcoord[u].enabled) compile_attrib(ctx, list_tex_bit(u), v.tex[u]);
  if (a.fog.enabled) compile_attrib(ctx, kListFog, &v.fog);
  if (a.edgeflag.enabled) {
    const float edge = v.edge != 0 ? 1.0f : 0.0f;
    compile_attrib(ctx, kListEdge, &edge);
  }
}

namespace saver {

void GLAPIENTRY Begin(GLenum mode) {
  Context* ctx = compiling_list();
  if (ctx != nullptr) {
    // An invalid mode, or Begin inside a block, is compiled as the call: its error comes
    // when the list executes.
    if (!valid_mode(mode) || ctx->dlist.block != nullptr)
      dlist_record(&replay_begin, &mode, sizeof mode);
    else
      compile_begin(ctx, mode);
  }
  if (executes(ctx)) exec::Begin(mode);
}

void GLAPIENTRY End() {
  Context* ctx = compiling_list();
  if (ctx != nullptr) {
    if (ctx->dlist.block != nullptr)
      compile_end(ctx);
    else
      dlist_record(&replay_end, nullptr, 0);
  }
  if (executes(ctx)) exec::End();
}

#define PINEDA_SAVE_VERTEX(T, S)                                                                   \
  void GLAPIENTRY Vertex2##S(T x, T y) {                                                           \
    vertex(float(x), float(y), 0.0f, 1.0f);                                                        \
  }                                                                                                \
  void GLAPIENTRY Vertex3##S(T x, T y, T z) {                                                      \
    vertex(float(x), float(y), float(z), 1.0f);                                                    \
  }                                                                                                \
  void GLAPIENTRY Vertex4##S(T x, T y, T z, T w) {                                                 \
    vertex(float(x), float(y), float(z), float(w));                                                \
  }                                                                                                \
  void GLAPIENTRY Vertex2##S##v(const T* v) {                                                      \
    if (v) vertex(float(v[0]), float(v[1]), 0.0f, 1.0f);                                           \
  }                                                                                                \
  void GLAPIENTRY Vertex3##S##v(const T* v) {                                                      \
    if (v) vertex(float(v[0]), float(v[1]), float(v[2]), 1.0f);                                    \
  }                                                                                                \
  void GLAPIENTRY Vertex4##S##v(const T* v) {                                                      \
    if (v) vertex(float(v[0]), float(v[1]), float(v[2]), float(v[3]));                             \
  }
PINEDA_SAVE_VERTEX(GLshort, s)
PINEDA_SAVE_VERTEX(GLint, i)
PINEDA_SAVE_VERTEX(GLfloat, f)
PINEDA_SAVE_VERTEX(GLdouble, d)
#undef PINEDA_SAVE_VERTEX

#define PINEDA_SAVE_COLOR(T, S)                                                                    \
  void GLAPIENTRY Color3##S(T r, T g, T b) {                                                       \
    attrib(kListColor, norm(r), norm(g), norm(b), 1.0f);                                           \
  }                                                                                                \
  void GLAPIENTRY Color4##S(T r, T g, T b, T a) {                                                  \
    attrib(kListColor, norm(r), norm(g), norm(b), norm(a));                                        \
  }                                                                                                \
  void GLAPIENTRY Color3##S##v(const T* v) {                                                       \
    if (v) attrib(kListColor, norm(v[0]), norm(v[1]), norm(v[2]), 1.0f);                           \
  }                                                                                                \
  void GLAPIENTRY Color4##S##v(const T* v) {                                                       \
    if (v) attrib(kListColor, norm(v[0]), norm(v[1]), norm(v[2]), norm(v[3]));                     \
  }                                                                                                \
  void GLAPIENTRY SecondaryColor3##S(T r, T g, T b) {                                              \
    attrib(kListColor2, norm(r), norm(g), norm(b), 1.0f);                                          \
  }                                                                                                \
  void GLAPIENTRY SecondaryColor3##S##v(const T* v) {                                              \
    if (v) attrib(kListColor2, norm(v[0]), norm(v[1]), norm(v[2]), 1.0f);                          \
  }
PINEDA_SAVE_COLOR(GLbyte, b)
PINEDA_SAVE_COLOR(GLshort, s)
PINEDA_SAVE_COLOR(GLint, i)
PINEDA_SAVE_COLOR(GLfloat, f)
PINEDA_SAVE_COLOR(GLdouble, d)
PINEDA_SAVE_COLOR(GLubyte, ub)
PINEDA_SAVE_COLOR(GLushort, us)
PINEDA_SAVE_COLOR(GLuint, ui)
#undef PINEDA_SAVE_COLOR

#define PINEDA_SAVE_NORMAL(T, S)                                                                   \
  void GLAPIENTRY Normal3##S(T x, T y, T z) {                                                      \
    attrib(kListNormal, norm(x), norm(y), norm(z), 0.0f);                                          \
  }                                                                                                \
  void GLAPIENTRY Normal3##S##v(const T* v) {                                                      \
    if (v) attrib(kListNormal, norm(v[0]), norm(v[1]), norm(v[2]), 0.0f);                          \
  }
PINEDA_SAVE_NORMAL(GLbyte, b)
PINEDA_SAVE_NORMAL(GLshort, s)
PINEDA_SAVE_NORMAL(GLint, i)
PINEDA_SAVE_NORMAL(GLfloat, f)
PINEDA_SAVE_NORMAL(GLdouble, d)
#undef PINEDA_SAVE_NORMAL

// Texture coordinates are not normalized (GL 2.1 §2.7).
#define PINEDA_SAVE_TEXCOORD(T, S)                                                                 \
  void GLAPIENTRY TexCoord1##S(T s) {                                                              \
    attrib(kListTex, float(s), 0.0f, 0.0f, 1.0f);                                                  \
  }                                                                                                \
  void GLAPIENTRY TexCoord2##S(T s, T t) {                                                         \
    attrib(kListTex, float(s), float(t), 0.0f, 1.0f);                                              \
  }                                                                                                \
  void GLAPIENTRY TexCoord3##S(T s, T t, T r) {                                                    \
    attrib(kListTex, float(s), float(t), float(r), 1.0f);                                          \
  }                                                                                                \
  void GLAPIENTRY TexCoord4##S(T s, T t, T r, T q) {                                               \
    attrib(kListTex, float(s), float(t), float(r), float(q));                                      \
  }                                                                                                \
  void GLAPIENTRY TexCoord1##S##v(const T* v) {                                                    \
    if (v) attrib(kListTex, float(v[0]), 0.0f, 0.0f, 1.0f);                                        \
  }                                                                                                \
  void GLAPIENTRY TexCoord2##S##v(const T* v) {                                                    \
    if (v) attrib(kListTex, float(v[0]), float(v[1]), 0.0f, 1.0f);                                 \
  }                                                                                                \
  void GLAPIENTRY TexCoord3##S##v(const T* v) {                                                    \
    if (v) attrib(kListTex, float(v[0]), float(v[1]), float(v[2]), 1.0f);                          \
  }                                                                                                \
  void GLAPIENTRY TexCoord4##S##v(const T* v) {                                                    \
    if (v) attrib(kListTex, float(v[0]), float(v[1]), float(v[2]), float(v[3]));                   \
  }
PINEDA_SAVE_TEXCOORD(GLshort, s)
PINEDA_SAVE_TEXCOORD(GLint, i)
PINEDA_SAVE_TEXCOORD(GLfloat, f)
PINEDA_SAVE_TEXCOORD(GLdouble, d)
#undef PINEDA_SAVE_TEXCOORD

// GL 1.3 §2.7: MultiTexCoord sets unit `target`'s current coordinates; a target that names no
// unit is INVALID_ENUM when the list executes.
inline void multi_tex(GLenum target, float s, float t, float r, float q) {
  const GLenum unit = target - GL_TEXTURE0;
  if (unit < static_cast<GLenum>(kMaxTexUnits))
    return attrib(list_tex_bit(static_cast<int>(unit)), s, t, r, q);
  if (Context* ctx = compiling_list())
    record_error_at_execution(ctx, GL_INVALID_ENUM, "glMultiTexCoord");
  if (executes(compiling_list())) exec::MultiTexCoord4f(target, s, t, r, q);
}

#define PINEDA_SAVE_MULTITEXCOORD(T, S)                                                            \
  void GLAPIENTRY MultiTexCoord1##S(GLenum u, T s) {                                               \
    multi_tex(u, float(s), 0.0f, 0.0f, 1.0f);                                                      \
  }                                                                                                \
  void GLAPIENTRY MultiTexCoord2##S(GLenum u, T s, T t) {                                          \
    multi_tex(u, float(s), float(t), 0.0f, 1.0f);                                                  \
  }                                                                                                \
  void GLAPIENTRY MultiTexCoord3##S(GLenum u, T s, T t, T r) {                                     \
    multi_tex(u, float(s), float(t), float(r), 1.0f);                                              \
  }                                                                                                \
  void GLAPIENTRY MultiTexCoord4##S(GLenum u, T s, T t, T r, T q) {                                \
    multi_tex(u, float(s), float(t), float(r), float(q));                                          \
  }                                                                                                \
  void GLAPIENTRY MultiTexCoord1##S##v(GLenum u, const T* v) {                                     \
    if (v) multi_tex(u, float(v[0]), 0.0f, 0.0f, 1.0f);                                            \
  }                                                                                                \
  void GLAPIENTRY MultiTexCoord2##S##v(GLenum u, const T* v) {                                     \
    if (v) multi_tex(u, float(v[0]), float(v[1]), 0.0f, 1.0f);                                     \
  }                                                                                                \
  void GLAPIENTRY MultiTexCoord3##S##v(GLenum u, const T* v) {                                     \
    if (v) multi_tex(u, float(v[0]), float(v[1]), float(v[2]), 1.0f);                              \
  }                                                                                                \
  void GLAPIENTRY MultiTexCoord4##S##v(GLenum u, const T* v) {                                     \
    if (v) multi_tex(u, float(v[0]), float(v[1]), float(v[2]), float(v[3]));                       \
  }
PINEDA_SAVE_MULTITEXCOORD(GLshort, s)
PINEDA_SAVE_MULTITEXCOORD(GLint, i)
PINEDA_SAVE_MULTITEXCOORD(GLfloat, f)
PINEDA_SAVE_MULTITEXCOORD(GLdouble, d)
#undef PINEDA_SAVE_MULTITEXCOORD

// GL 1.4 §2.7: the fog coordinate is a current attribute like the others.
void GLAPIENTRY FogCoordf(GLfloat coord) {
  attrib(kListFog, coord, 0.0f, 0.0f, 0.0f);
}
void GLAPIENTRY FogCoordd(GLdouble coord) {
  attrib(kListFog, float(coord), 0.0f, 0.0f, 0.0f);
}
void GLAPIENTRY FogCoordfv(const GLfloat* coord) {
  if (coord) FogCoordf(coord[0]);
}
void GLAPIENTRY FogCoorddv(const GLdouble* coord) {
  if (coord) FogCoordd(coord[0]);
}

#define PINEDA_SAVE_RECT(T, S)                                                                     \
  void GLAPIENTRY Rect##S(T x1, T y1, T x2, T y2) {                                                \
    rect(x1, y1, x2, y2);                                                                          \
  }                                                                                                \
  void GLAPIENTRY Rect##S##v(const T* a, const T* b) {                                             \
    if (a && b) rect(a[0], a[1], b[0], b[1]);                                                      \
  }
PINEDA_SAVE_RECT(GLshort, s)
PINEDA_SAVE_RECT(GLint, i)
PINEDA_SAVE_RECT(GLfloat, f)
PINEDA_SAVE_RECT(GLdouble, d)
#undef PINEDA_SAVE_RECT

void GLAPIENTRY EdgeFlag(GLboolean flag) {
  attrib(kListEdge, flag != GL_FALSE ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f);
}

void GLAPIENTRY EdgeFlagv(const GLboolean* flag) {
  if (flag) EdgeFlag(*flag);
}

// GL 2.1 §2.8, §5.4: ArrayElement compiles as the attribute and vertex commands it stands
// for, with the array contents of now.
void GLAPIENTRY ArrayElement(GLint i) {
  Context* ctx = compiling_list();
  if (ctx != nullptr) {
    InputVertex v;
    if (i < 0) {
      record_error_at_execution(ctx, GL_INVALID_VALUE, "glArrayElement");
    } else if (enabled_generic_arrays(ctx) != 0 || generic_array0_enabled(ctx)) {
      const uint32_t element = static_cast<uint32_t>(i);
      compile_generic_elements(ctx, &element, 1);
    } else if (fetch_range(ctx, static_cast<size_t>(i), 1, &v)) {
      compile_array_attribs(ctx, v);
      if (ctx->arrays.vertex.enabled) compile_vertex(ctx, v.pos[0], v.pos[1], v.pos[2], v.pos[3]);
    }
  }
  if (executes(ctx)) exec::ArrayElement(i);
}

void GLAPIENTRY DrawArrays(GLenum mode, GLint first, GLsizei count) {
  Context* ctx = compiling_list();
  if (ctx != nullptr) {
    if (!valid_mode(mode))
      record_error_at_execution(ctx, GL_INVALID_ENUM, "glDrawArrays");
    else if (count < 0 || first < 0)
      record_error_at_execution(ctx, GL_INVALID_VALUE, "glDrawArrays");
    else if (arrays_mapped(ctx, false))
      record_error_at_execution(ctx, GL_INVALID_OPERATION, "glDrawArrays");
    else
      compile_range(ctx, mode, static_cast<size_t>(first), static_cast<size_t>(count));
  }
  if (executes(ctx)) exec::DrawArrays(mode, first, count);
}

void GLAPIENTRY DrawElements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
  Context* ctx = compiling_list();
  if (ctx != nullptr) {
    if (const GLenum err = elements_error(ctx, mode, count, type))
      record_error_at_execution(ctx, err, "glDrawElements");
    else
      compile_elements(ctx, mode, count, type, indices);
  }
  if (executes(ctx)) exec::DrawElements(mode, count, type, indices);
}

void GLAPIENTRY DrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type,
                                  const void* indices) {
  Context* ctx = compiling_list();
  if (ctx != nullptr) {
    const GLenum err =
        end < start ? GLenum{GL_INVALID_VALUE} : elements_error(ctx, mode, count, type);
    if (err != 0)
      record_error_at_execution(ctx, err, "glDrawRangeElements");
    else
      compile_elements(ctx, mode, count, type, indices);
  }
  if (executes(ctx)) exec::DrawRangeElements(mode, start, end, count, type, indices);
}

void GLAPIENTRY MultiDrawArrays(GLenum mode, const GLint* first, const GLsizei* count,
                                GLsizei drawcount) {
  Context* ctx = compiling_list();
  if (ctx != nullptr) {
    GLenum err = 0;
    if (!valid_mode(mode))
      err = GL_INVALID_ENUM;
    else if (drawcount < 0)
      err = GL_INVALID_VALUE;
    const bool any = err == 0 && drawcount > 0 && first != nullptr && count != nullptr;
    for (GLsizei i = 0; any && err == 0 && i < drawcount; ++i)
      if (count[i] < 0 || first[i] < 0) err = GL_INVALID_VALUE;
    if (err == 0 && any && arrays_mapped(ctx, false)) err = GL_INVALID_OPERATION;
    if (err != 0) {
      record_error_at_execution(ctx, err, "glMultiDrawArrays");
    } else if (any) {
      for (GLsizei i = 0; i < drawcount; ++i)
        compile_range(ctx, mode, static_cast<size_t>(first[i]), static_cast<size_t>(count[i]));
    }
  }
  if (executes(ctx)) exec::MultiDrawArrays(mode, first, count, drawcount);
}

void GLAPIENTRY MultiDrawElements(GLenum mode, const GLsizei* count, GLenum type,
                                  const void* const* indices, GLsizei drawcount) {
  Context* ctx = compiling_list();
  if (ctx != nullptr) {
    GLenum err = drawcount < 0 ? GLenum{GL_INVALID_VALUE} : elements_error(ctx, mode, 0, type);
    const bool any = err == 0 && drawcount > 0 && count != nullptr && indices != nullptr;
    for (GLsizei i = 0; any && err == 0 && i < drawcount; ++i)
      if (count[i] < 0) err = GL_INVALID_VALUE;
    if (err != 0) {
      record_error_at_execution(ctx, err, "glMultiDrawElements");
    } else if (any) {
      for (GLsizei i = 0; i < drawcount; ++i)
        compile_elements(ctx, mode, count[i], type, indices[i]);
    }
  }
  if (executes(ctx)) exec::MultiDrawElements(mode, count, type, indices, drawcount);
}

void GLAPIENTRY Lightfv(GLenum light, GLenum pname, const GLfloat* params) {
  Context* ctx = compiling_list();
  if (ctx == nullptr ||
      record_params(&replay_params<GLfloat, &exec::Lightfv>, &light_count, light, pname, params))
    exec::Lightfv(light, pname, params);
}

void GLAPIENTRY Lightiv(GLenum light, GLenum pname, const GLint* params) {
  Context* ctx = compiling_list();
  if (ctx == nullptr ||
      record_params(&replay_params<GLint, &exec::Lightiv>, &light_count, light, pname, params))
    exec::Lightiv(light, pname, params);
}

void GLAPIENTRY LightModelfv(GLenum pname, const GLfloat* params) {
  Context* ctx = compiling_list();
  if (ctx == nullptr || record_params(&replay_model_params<GLfloat, &exec::LightModelfv>,
                                      &light_model_count, 0, pname, params))
    exec::LightModelfv(pname, params);
}

void GLAPIENTRY LightModeliv(GLenum pname, const GLint* params) {
  Context* ctx = compiling_list();
  if (ctx == nullptr || record_params(&replay_model_params<GLint, &exec::LightModeliv>,
                                      &light_model_count, 0, pname, params))
    exec::LightModeliv(pname, params);
}

// Material is legal between Begin and End (§2.14.2): inside a compiled block it ends the
// block's fast form (the block then executes call by call, with the Material in its place).
void GLAPIENTRY Materialfv(GLenum face, GLenum pname, const GLfloat* params) {
  Context* ctx = compiling_list();
  if (ctx == nullptr || record_params(&replay_params<GLfloat, &exec::Materialfv>, &material_count,
                                      face, pname, params))
    exec::Materialfv(face, pname, params);
}

void GLAPIENTRY Materialiv(GLenum face, GLenum pname, const GLint* params) {
  Context* ctx = compiling_list();
  if (ctx == nullptr ||
      record_params(&replay_params<GLint, &exec::Materialiv>, &material_count, face, pname, params))
    exec::Materialiv(face, pname, params);
}

void GLAPIENTRY Materialf(GLenum face, GLenum pname, GLfloat param) {
  const ScalarArgs<GLfloat> a{face, pname, param};
  if (compiling_list() == nullptr ||
      dlist_record(&replay_scalar<GLfloat, &exec::Materialf>, &a, sizeof a))
    exec::Materialf(face, pname, param);
}

void GLAPIENTRY Materiali(GLenum face, GLenum pname, GLint param) {
  const ScalarArgs<GLint> a{face, pname, param};
  if (compiling_list() == nullptr ||
      dlist_record(&replay_scalar<GLint, &exec::Materiali>, &a, sizeof a))
    exec::Materiali(face, pname, param);
}

// PopAttrib may restore the current values (CURRENT_BIT): the list no longer knows them.
void GLAPIENTRY PopAttrib() {
  Context* ctx = compiling_list();
  const bool run = ctx == nullptr || dlist_record(&replay_pop_attrib, nullptr, 0);
  if (ctx != nullptr) forget_attribs(ctx);
  if (run) exec::PopAttrib();
}

// §5.4: the CallList itself is compiled, not the commands of the list it calls.
void GLAPIENTRY CallList(GLuint list) {
  Context* ctx = compiling_list();
  const bool run = ctx == nullptr || dlist_record(&replay_call_list, &list, sizeof list);
  if (ctx != nullptr) forget_attribs(ctx);
  if (run) exec::CallList(list);
}

void GLAPIENTRY CallLists(GLsizei n, GLenum type, const void* lists) {
  Context* ctx = compiling_list();
  if (ctx != nullptr) {
    if (!valid_call_lists_type(type) || n < 0) {
      const CallListsError a{n, type};
      dlist_record(&replay_call_lists_error, &a, sizeof a);
    } else if (n > 0 && lists != nullptr) {
      // The array is read now (§5.4: pointers are dereferenced when the command is issued).
      auto data = std::make_unique<CallListsData>();
      data->offsets.resize(static_cast<size_t>(n));
      for (size_t i = 0; i < data->offsets.size(); ++i)
        data->offsets[i] = call_lists_offset(type, lists, i);
      const CallListsData* raw = data.get();
      dlist_record(&replay_call_lists, &raw, sizeof raw);
      ctx->dlist.list->objects.push_back(std::move(data));
      forget_attribs(ctx);
    }
  }
  if (executes(ctx)) exec::CallLists(n, type, lists);
}

} // namespace saver
} // namespace pineda
