// glBegin/glEnd, glVertex and the current attributes, glRect (GL 2.1 §2.6, §2.7, §2.10), and
// the current-values area (Table 6.5, current.h): its queries and CURRENT_BIT.
#include <cstdint>

#include "state/api_util.h"
#include "core/normalize.h"
#include "dispatch.h"
#include "state/draw_call.h"
#include "state/area.h"

namespace pineda {

namespace {

// A vertex appended to the primitive being assembled with the current attributes (GL 2.1
// §2.7); the caller sets its position. Inline here: glVertex is the hottest entry point.
inline InputVertex& push_current_vertex(Context* ctx) {
  InputVertex& v = ctx->imm.verts.emplace_back();
  for (int i = 0; i < 4; ++i)
    v.color[i] = ctx->current.color[i];
  for (int i = 0; i < 3; ++i)
    v.normal[i] = ctx->current.normal[i];
  for (int i = 0; i < 3; ++i)
    v.color2[i] = ctx->current.color2[i];
  v.fog = ctx->current.fog_coord;
  v.edge = ctx->current.edge ? 1u : 0u;
  // Only the units this primitive's draw reads (usually none): the rest of the vertex's
  // second cache line is never touched.
  for (uint32_t units = ctx->imm.tex_units; units != 0; units &= units - 1) {
    const int u = __builtin_ctz(units);
    for (int i = 0; i < 4; ++i)
      v.tex[u][i] = ctx->current.tex[u][i];
  }
  if (ctx->imm.generic_mask != 0) append_current_generics(ctx);
  return v;
}

inline void vertex(float x, float y, float z, float w) {
  Context* ctx = current_context();
  // GL 2.1 §2.7: a Vertex outside Begin/End has undefined effect; Pineda ignores it.
  if (ctx == nullptr || ctx->imm.mode == kOutsideBeginEnd) return;
  InputVertex& v = push_current_vertex(ctx);
  v.pos[0] = x, v.pos[1] = y, v.pos[2] = z, v.pos[3] = w;
}

inline void color(float r, float g, float b, float a) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  ctx->current.color[0] = r, ctx->current.color[1] = g, ctx->current.color[2] = b,
  ctx->current.color[3] = a;
  // GL 2.1 §2.14.3: tracked material properties follow every change of the current colour.
  if (ctx->lighting.color_material) update_color_material(ctx);
}

// GL 2.1 §2.7: SecondaryColor3 sets R, G and B of the current secondary colour; A stays 1.
inline void secondary_color(float r, float g, float b) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  ctx->current.color2[0] = r, ctx->current.color2[1] = g, ctx->current.color2[2] = b;
}

inline void normal(float x, float y, float z) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  ctx->current.normal[0] = x, ctx->current.normal[1] = y, ctx->current.normal[2] = z;
}

inline void texcoord(float s, float t, float r, float q) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  float* tc = ctx->current.tex[0];
  tc[0] = s, tc[1] = t, tc[2] = r, tc[3] = q;
}

template <typename T> void rect(T x1, T y1, T x2, T y2) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  if (ctx->imm.mode != kOutsideBeginEnd) {
    record_error(ctx, GL_INVALID_OPERATION, "glRect");
    return;
  }
  // GL 2.1 §2.10: Rect is Begin(POLYGON), four Vertex2 calls, End.
  exec::Begin(GL_POLYGON);
  vertex(static_cast<float>(x1), static_cast<float>(y1), 0.0f, 1.0f);
  vertex(static_cast<float>(x2), static_cast<float>(y1), 0.0f, 1.0f);
  vertex(static_cast<float>(x2), static_cast<float>(y2), 0.0f, 1.0f);
  vertex(static_cast<float>(x1), static_cast<float>(y2), 0.0f, 1.0f);
  exec::End();
}

// Table 6.5: the current values and the current raster position (§2.13) with its data.
bool get_current(Context& ctx, GLenum pname, QueryValues& out) {
  const CurrentGroup& c = ctx.current;
  const RasterPos& rp = c.raster_pos;
  switch (pname) {
  case GL_CURRENT_COLOR:
    out.normalized(c.color, 4);
    return true;
  case GL_CURRENT_SECONDARY_COLOR:
    out.normalized(c.color2, 4);
    return true;
  case GL_CURRENT_NORMAL:
    out.normalized(c.normal, 3);
    return true;
  case GL_CURRENT_TEXTURE_COORDS:
    // §6.1.2: INVALID_OPERATION for an active texture without a coordinate set.
    if (ctx.texture.active >= GLuint(kMaxTexCoordSets))
      out.error = GL_INVALID_OPERATION;
    else
      out.floats(c.tex[ctx.texture.active], 4);
    return true;
  case GL_CURRENT_FOG_COORD:
    out.floats({c.fog_coord});
    return true;
  // A float like the current colour (GetIntegerv rounds it, §6.1.2).
  case GL_CURRENT_INDEX:
    out.floats({c.index});
    return true;
  case GL_EDGE_FLAG:
    out.boolean(c.edge);
    return true;
  case GL_CURRENT_RASTER_POSITION:
    out.floats(rp.win, 4);
    return true;
  case GL_CURRENT_RASTER_POSITION_VALID:
    out.boolean(rp.valid);
    return true;
  case GL_CURRENT_RASTER_DISTANCE:
    out.floats({rp.distance});
    return true;
  case GL_CURRENT_RASTER_COLOR:
    out.normalized(rp.color, 4);
    return true;
  case GL_CURRENT_RASTER_SECONDARY_COLOR:
    out.normalized(rp.color2, 4);
    return true;
  case GL_CURRENT_RASTER_INDEX:
    out.floats({rp.index});
    return true;
  case GL_CURRENT_RASTER_TEXTURE_COORDS:
    if (ctx.texture.active >= GLuint(kMaxTexCoordSets))
      out.error = GL_INVALID_OPERATION;
    else
      out.floats(rp.tex[ctx.texture.active], 4);
    return true;
  default:
    return false;
  }
}

constexpr AttribGroup kCurrentGroups[] = {
    member_group<&Context::current>(GL_CURRENT_BIT, 0),
};

} // namespace

const StateArea kCurrentArea = {
    .name = "current values (GL 2.1 §2.7, Table 6.5)",
    .get = get_current,
    .groups = kCurrentGroups,
};

InputVertex& append_current_vertex(Context* ctx) {
  return push_current_vertex(ctx);
}

void append_current_generics(Context* ctx) {
  for (uint32_t m = ctx->imm.generic_mask; m != 0; m &= m - 1) {
    const float* v = ctx->vertex_attrib.value[__builtin_ctz(m)];
    ctx->imm.generic.insert(ctx->imm.generic.end(), v, v + 4);
  }
}

namespace exec {

void GLAPIENTRY Begin(GLenum mode) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  if (ctx->imm.mode != kOutsideBeginEnd) {
    record_error(ctx, GL_INVALID_OPERATION, "glBegin");
    return;
  }
  if (mode > GL_POLYGON) {
    record_error(ctx, GL_INVALID_ENUM, "glBegin", mode);
    return;
  }
  ctx->imm.mode = mode;
  ctx->imm.verts.clear();
  // GL 2.1 §2.6.3: no command between Begin and End changes what the draw at End reads from
  // the texture coordinates, so the set of units it reads is fixed here.
  ctx->imm.tex_units = input_tex_units(ctx);
  // §2.7: each vertex takes the generic attributes' current values, as the other attributes.
  const LinkedProgram* program = active_program(ctx);
  ctx->imm.generic_mask = program != nullptr ? program->generic_inputs & ~1u : 0;
  ctx->imm.generic.clear();
}

void GLAPIENTRY End() {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  if (ctx->imm.mode == kOutsideBeginEnd) {
    record_error(ctx, GL_INVALID_OPERATION, "glEnd");
    return;
  }
  const GLenum mode = ctx->imm.mode;
  ctx->imm.mode = kOutsideBeginEnd;
  if (!ctx->imm.verts.empty())
    draw_vertices(ctx, mode, ctx->imm.verts.data(), ctx->imm.verts.size(), nullptr,
                  ctx->imm.verts.size(), {ctx->imm.generic.data(), ctx->imm.generic_mask});
  ctx->imm.verts.clear();
  ctx->imm.generic.clear();
  ctx->imm.material_changes.clear(); // Material calls of this primitive have been applied
}

// Each macro line spells out one family of GL 1.0 attribute commands; they differ only in
// the component type and count.
#define PINEDA_VERTEX(T, S)                                                                        \
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
PINEDA_VERTEX(GLshort, s)
PINEDA_VERTEX(GLint, i)
PINEDA_VERTEX(GLfloat, f)
PINEDA_VERTEX(GLdouble, d)
#undef PINEDA_VERTEX

#define PINEDA_COLOR(T, S)                                                                         \
  void GLAPIENTRY Color3##S(T r, T g, T b) {                                                       \
    color(norm(r), norm(g), norm(b), 1.0f);                                                        \
  }                                                                                                \
  void GLAPIENTRY Color4##S(T r, T g, T b, T a) {                                                  \
    color(norm(r), norm(g), norm(b), norm(a));                                                     \
  }                                                                                                \
  void GLAPIENTRY Color3##S##v(const T* v) {                                                       \
    if (v) color(norm(v[0]), norm(v[1]), norm(v[2]), 1.0f);                                        \
  }                                                                                                \
  void GLAPIENTRY Color4##S##v(const T* v) {                                                       \
    if (v) color(norm(v[0]), norm(v[1]), norm(v[2]), norm(v[3]));                                  \
  }
PINEDA_COLOR(GLbyte, b)
PINEDA_COLOR(GLshort, s)
PINEDA_COLOR(GLint, i)
PINEDA_COLOR(GLfloat, f)
PINEDA_COLOR(GLdouble, d)
PINEDA_COLOR(GLubyte, ub)
PINEDA_COLOR(GLushort, us)
PINEDA_COLOR(GLuint, ui)
#undef PINEDA_COLOR

#define PINEDA_SECONDARY_COLOR(T, S)                                                               \
  void GLAPIENTRY SecondaryColor3##S(T r, T g, T b) {                                              \
    secondary_color(norm(r), norm(g), norm(b));                                                    \
  }                                                                                                \
  void GLAPIENTRY SecondaryColor3##S##v(const T* v) {                                              \
    if (v) secondary_color(norm(v[0]), norm(v[1]), norm(v[2]));                                    \
  }
PINEDA_SECONDARY_COLOR(GLbyte, b)
PINEDA_SECONDARY_COLOR(GLshort, s)
PINEDA_SECONDARY_COLOR(GLint, i)
PINEDA_SECONDARY_COLOR(GLfloat, f)
PINEDA_SECONDARY_COLOR(GLdouble, d)
PINEDA_SECONDARY_COLOR(GLubyte, ub)
PINEDA_SECONDARY_COLOR(GLushort, us)
PINEDA_SECONDARY_COLOR(GLuint, ui)
#undef PINEDA_SECONDARY_COLOR

#define PINEDA_NORMAL(T, S)                                                                        \
  void GLAPIENTRY Normal3##S(T x, T y, T z) {                                                      \
    normal(norm(x), norm(y), norm(z));                                                             \
  }                                                                                                \
  void GLAPIENTRY Normal3##S##v(const T* v) {                                                      \
    if (v) normal(norm(v[0]), norm(v[1]), norm(v[2]));                                             \
  }
PINEDA_NORMAL(GLbyte, b)
PINEDA_NORMAL(GLshort, s)
PINEDA_NORMAL(GLint, i)
PINEDA_NORMAL(GLfloat, f)
PINEDA_NORMAL(GLdouble, d)
#undef PINEDA_NORMAL

// Texture coordinates are not normalized (GL 2.1 §2.7): integers convert directly.
#define PINEDA_TEXCOORD(T, S)                                                                      \
  void GLAPIENTRY TexCoord1##S(T s) {                                                              \
    texcoord(float(s), 0.0f, 0.0f, 1.0f);                                                          \
  }                                                                                                \
  void GLAPIENTRY TexCoord2##S(T s, T t) {                                                         \
    texcoord(float(s), float(t), 0.0f, 1.0f);                                                      \
  }                                                                                                \
  void GLAPIENTRY TexCoord3##S(T s, T t, T r) {                                                    \
    texcoord(float(s), float(t), float(r), 1.0f);                                                  \
  }                                                                                                \
  void GLAPIENTRY TexCoord4##S(T s, T t, T r, T q) {                                               \
    texcoord(float(s), float(t), float(r), float(q));                                              \
  }                                                                                                \
  void GLAPIENTRY TexCoord1##S##v(const T* v) {                                                    \
    if (v) texcoord(float(v[0]), 0.0f, 0.0f, 1.0f);                                                \
  }                                                                                                \
  void GLAPIENTRY TexCoord2##S##v(const T* v) {                                                    \
    if (v) texcoord(float(v[0]), float(v[1]), 0.0f, 1.0f);                                         \
  }                                                                                                \
  void GLAPIENTRY TexCoord3##S##v(const T* v) {                                                    \
    if (v) texcoord(float(v[0]), float(v[1]), float(v[2]), 1.0f);                                  \
  }                                                                                                \
  void GLAPIENTRY TexCoord4##S##v(const T* v) {                                                    \
    if (v) texcoord(float(v[0]), float(v[1]), float(v[2]), float(v[3]));                           \
  }
PINEDA_TEXCOORD(GLshort, s)
PINEDA_TEXCOORD(GLint, i)
PINEDA_TEXCOORD(GLfloat, f)
PINEDA_TEXCOORD(GLdouble, d)
#undef PINEDA_TEXCOORD

#define PINEDA_RECT(T, S)                                                                          \
  void GLAPIENTRY Rect##S(T x1, T y1, T x2, T y2) {                                                \
    rect(x1, y1, x2, y2);                                                                          \
  }                                                                                                \
  void GLAPIENTRY Rect##S##v(const T* a, const T* b) {                                             \
    if (a && b) rect(a[0], a[1], b[0], b[1]);                                                      \
  }
PINEDA_RECT(GLshort, s)
PINEDA_RECT(GLint, i)
PINEDA_RECT(GLfloat, f)
PINEDA_RECT(GLdouble, d)
#undef PINEDA_RECT

void GLAPIENTRY EdgeFlag(GLboolean flag) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  ctx->current.edge = flag != GL_FALSE;
}

void GLAPIENTRY EdgeFlagv(const GLboolean* flag) {
  if (flag) EdgeFlag(*flag);
}

} // namespace exec
} // namespace pineda
