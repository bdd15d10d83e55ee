// Texture units (GL 2.1 §2.7 ActiveTexture, §2.8 ClientActiveTexture, MultiTexCoord), the
// texture target and coordinate-generation enables (§3.8.15, §2.11.4), the texture
// environment (§3.8.13, TexEnv and GetTexEnv) and coordinate generation (§2.11.4, TexGen and
// GetTexGen); the texture-unit area (texenv.h): its capabilities, queries, TEXTURE_BIT group
// and the derived texturing setup (validate_texpipe.cpp).
#include <cmath>
#include <limits>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "state/api_util.h"
#include "dispatch.h"
#include "state/area.h"

namespace pineda {

namespace {

// GL 2.1 Table 2.9: signed integer colour components map to [-1,1].
inline float int_color(GLint c) {
  return static_cast<float>((2.0 * c + 1.0) / 4294967295.0);
}

// GL 2.1 §6.1.2: colours read back as integers map [-1,1] onto the integer range.
GLint color_to_int(float c) {
  const double scaled = static_cast<double>(c) * 2147483647.0;
  if (scaled >= 2147483647.0) return std::numeric_limits<GLint>::max();
  if (scaled <= -2147483648.0) return std::numeric_limits<GLint>::min();
  return static_cast<GLint>(std::llround(scaled));
}

// Other values read back as integers round to the nearest integer (§6.1.2).
GLint float_to_int(double v) {
  if (!(v == v)) return 0;
  if (v >= 2147483647.0) return std::numeric_limits<GLint>::max();
  if (v <= -2147483648.0) return std::numeric_limits<GLint>::min();
  return static_cast<GLint>(std::lround(v));
}

TexUnit& active_unit(Context* ctx) {
  return ctx->texture.unit[ctx->texture.active];
}

// GL 2.1 §2.7: the active texture selects a texture coordinate set, a texture image unit and,
// for fixed-function texturing, a conventional unit. Commands on state the active one lacks are
// INVALID_OPERATION: TexEnv's environment and point sprite coordinate replacement (MAX_TEXTURE_
// UNITS, as Mesa limits them), TexGen (MAX_TEXTURE_COORDS); TEXTURE_FILTER_CONTROL is image
// unit state, which every active texture has.
bool env_unit_ok(Context* ctx, GLenum target, const char* func) {
  if (target == GL_TEXTURE_FILTER_CONTROL || ctx->texture.active < GLuint(kMaxTexUnits))
    return true;
  record_error(ctx, GL_INVALID_OPERATION, func);
  return false;
}

// ---- texture environment (GL 2.1 §3.8.13) ----

bool valid_env_mode(GLenum m) {
  return m == GL_MODULATE || m == GL_DECAL || m == GL_BLEND || m == GL_REPLACE || m == GL_ADD ||
         m == GL_COMBINE;
}

// Table 3.24 / 3.25: the RGB functions include DOT3_RGB and DOT3_RGBA, the alpha ones not.
bool valid_combine(GLenum f, bool rgb) {
  switch (f) {
  case GL_REPLACE:
  case GL_MODULATE:
  case GL_ADD:
  case GL_ADD_SIGNED:
  case GL_INTERPOLATE:
  case GL_SUBTRACT:
    return true;
  case GL_DOT3_RGB:
  case GL_DOT3_RGBA:
    return rgb;
  default:
    return false;
  }
}

// Table 3.26 sources; TEXTUREn (the GL 1.4 crossbar) for the units that exist.
bool valid_source(GLenum s) {
  return s == GL_TEXTURE || s == GL_CONSTANT || s == GL_PRIMARY_COLOR || s == GL_PREVIOUS ||
         (s >= GL_TEXTURE0 && s < GL_TEXTURE0 + kMaxTexUnits);
}

bool valid_operand(GLenum o, bool rgb) {
  if (o == GL_SRC_ALPHA || o == GL_ONE_MINUS_SRC_ALPHA) return true;
  return rgb && (o == GL_SRC_COLOR || o == GL_ONE_MINUS_SRC_COLOR);
}

// The enum-valued environment parameters: where each lives.
GLenum* env_enum(TexEnv& e, GLenum pname, int* kind) {
  // kind: 0 mode, 1 combine rgb, 2 combine alpha, 3 source, 4 operand rgb, 5 operand alpha
  switch (pname) {
  case GL_TEXTURE_ENV_MODE:
    *kind = 0;
    return &e.mode;
  case GL_COMBINE_RGB:
    *kind = 1;
    return &e.combine_rgb;
  case GL_COMBINE_ALPHA:
    *kind = 2;
    return &e.combine_alpha;
  case GL_SRC0_RGB:
    *kind = 3;
    return &e.src_rgb[0];
  case GL_SRC1_RGB:
    *kind = 3;
    return &e.src_rgb[1];
  case GL_SRC2_RGB:
    *kind = 3;
    return &e.src_rgb[2];
  case GL_SRC0_ALPHA:
    *kind = 3;
    return &e.src_alpha[0];
  case GL_SRC1_ALPHA:
    *kind = 3;
    return &e.src_alpha[1];
  case GL_SRC2_ALPHA:
    *kind = 3;
    return &e.src_alpha[2];
  case GL_OPERAND0_RGB:
    *kind = 4;
    return &e.op_rgb[0];
  case GL_OPERAND1_RGB:
    *kind = 4;
    return &e.op_rgb[1];
  case GL_OPERAND2_RGB:
    *kind = 4;
    return &e.op_rgb[2];
  case GL_OPERAND0_ALPHA:
    *kind = 5;
    return &e.op_alpha[0];
  case GL_OPERAND1_ALPHA:
    *kind = 5;
    return &e.op_alpha[1];
  case GL_OPERAND2_ALPHA:
    *kind = 5;
    return &e.op_alpha[2];
  default:
    return nullptr;
  }
}

bool valid_env_enum(int kind, GLenum v) {
  switch (kind) {
  case 0:
    return valid_env_mode(v);
  case 1:
    return valid_combine(v, true);
  case 2:
    return valid_combine(v, false);
  case 3:
    return valid_source(v);
  case 4:
    return valid_operand(v, true);
  default:
    return valid_operand(v, false);
  }
}

// TexEnv with the parameter values as doubles (enums converted exactly) and colours already
// converted to floats; `n` is 1 for the scalar forms.
void tex_env(const char* func, GLenum target, GLenum pname, const double* v, const float* color,
             bool vector) {
  PINEDA_CTX_OUTSIDE(func);
  if (!env_unit_ok(ctx, target, func)) return;
  if (target == GL_TEXTURE_FILTER_CONTROL) {
    if (pname != GL_TEXTURE_LOD_BIAS) return record_error(ctx, GL_INVALID_ENUM, func, pname);
    const auto bias = static_cast<float>(v[0]);
    float& unit_bias = ctx->texture.lod_bias[ctx->texture.active];
    if (unit_bias == bias) return;
    unit_bias = bias;
    return mark_dirty(ctx, kDirtyTexture);
  }
  TexEnv& e = active_unit(ctx).env;
  if (target == GL_POINT_SPRITE) {
    // GL 2.1 §3.3, §3.8.13: COORD_REPLACE of the active unit, TRUE or FALSE (another value is
    // INVALID_VALUE, as in Mesa). It is point state (Table 6.12).
    if (pname != GL_COORD_REPLACE) return record_error(ctx, GL_INVALID_ENUM, func, pname);
    if (v[0] != GL_TRUE && v[0] != GL_FALSE) return record_error(ctx, GL_INVALID_VALUE, func);
    bool& replace = ctx->point.coord_replace[ctx->texture.active];
    if (replace == (v[0] == GL_TRUE)) return;
    replace = v[0] == GL_TRUE;
    return mark_dirty(ctx, kDirtyRasterMode);
  }
  if (target != GL_TEXTURE_ENV) return record_error(ctx, GL_INVALID_ENUM, func, target);
  if (pname == GL_TEXTURE_ENV_COLOR) {
    if (!vector) return record_error(ctx, GL_INVALID_ENUM, func, pname);
    // §3.8.13: the environment colour is clamped to [0,1] when specified.
    for (int i = 0; i < 4; ++i)
      e.color[i] = clampf01(color[i]);
    return mark_dirty(ctx, kDirtyTexture);
  }
  if (pname == GL_RGB_SCALE || pname == GL_ALPHA_SCALE) {
    // §3.8.13: the scales are 1.0, 2.0 or 4.0; anything else is INVALID_VALUE.
    if (v[0] != 1.0 && v[0] != 2.0 && v[0] != 4.0) return record_error(ctx, GL_INVALID_VALUE, func);
    (pname == GL_RGB_SCALE ? e.rgb_scale : e.alpha_scale) = static_cast<float>(v[0]);
    return mark_dirty(ctx, kDirtyTexture);
  }
  int kind = 0;
  GLenum* slot = env_enum(e, pname, &kind);
  if (slot == nullptr) return record_error(ctx, GL_INVALID_ENUM, func, pname);
  const double d = v[0];
  const auto value = static_cast<GLenum>(d >= 0.0 && d < 4294967296.0 ? d : 0.0);
  if (static_cast<double>(value) != d || !valid_env_enum(kind, value))
    return record_error(ctx, GL_INVALID_ENUM, func, value);
  if (*slot == value) return;
  *slot = value;
  mark_dirty(ctx, kDirtyTexture);
}

// GetTexEnv: the values of one parameter; `is_color` for the normalized TEXTURE_ENV_COLOR.
int get_tex_env(const char* func, GLenum target, GLenum pname, double* out, bool* is_color,
                Context** ctx_out) {
  *ctx_out = nullptr;
  Context* ctx = outside_begin_end(func);
  if (ctx == nullptr) return 0;
  *ctx_out = ctx;
  *is_color = false;
  if (!env_unit_ok(ctx, target, func)) return 0;
  if (target == GL_TEXTURE_FILTER_CONTROL) {
    if (pname != GL_TEXTURE_LOD_BIAS) {
      record_error(ctx, GL_INVALID_ENUM, func, pname);
      return 0;
    }
    out[0] = ctx->texture.lod_bias[ctx->texture.active];
    return 1;
  }
  TexEnv& e = active_unit(ctx).env;
  if (target == GL_POINT_SPRITE) {
    if (pname != GL_COORD_REPLACE) {
      record_error(ctx, GL_INVALID_ENUM, func, pname);
      return 0;
    }
    out[0] = ctx->point.coord_replace[ctx->texture.active] ? 1.0 : 0.0;
    return 1;
  }
  if (target != GL_TEXTURE_ENV) {
    record_error(ctx, GL_INVALID_ENUM, func, target);
    return 0;
  }
  if (pname == GL_TEXTURE_ENV_COLOR) {
    *is_color = true;
    for (int i = 0; i < 4; ++i)
      out[i] = e.color[i];
    return 4;
  }
  if (pname == GL_RGB_SCALE || pname == GL_ALPHA_SCALE) {
    out[0] = pname == GL_RGB_SCALE ? e.rgb_scale : e.alpha_scale;
    return 1;
  }
  int kind = 0;
  const GLenum* slot = env_enum(e, pname, &kind);
  if (slot == nullptr) {
    record_error(ctx, GL_INVALID_ENUM, func, pname);
    return 0;
  }
  out[0] = *slot;
  return 1;
}

// ---- coordinate generation (GL 2.1 §2.11.4) ----

int gen_coord(GLenum coord) {
  switch (coord) {
  case GL_S:
    return 0;
  case GL_T:
    return 1;
  case GL_R:
    return 2;
  case GL_Q:
    return 3;
  default:
    return -1;
  }
}

// §2.11.4: SPHERE_MAP is only for s and t, REFLECTION_MAP and NORMAL_MAP not for q.
bool valid_gen_mode(int c, GLenum mode) {
  switch (mode) {
  case GL_OBJECT_LINEAR:
  case GL_EYE_LINEAR:
    return true;
  case GL_SPHERE_MAP:
    return c < 2;
  case GL_NORMAL_MAP:
  case GL_REFLECTION_MAP:
    return c < 3;
  default:
    return false;
  }
}

void tex_gen(const char* func, GLenum coord, GLenum pname, const double* v, bool vector) {
  PINEDA_CTX_OUTSIDE(func);
  const int c = gen_coord(coord);
  if (c < 0) return record_error(ctx, GL_INVALID_ENUM, func, coord);
  if (ctx->texture.active >= GLuint(kMaxTexCoordSets))
    return record_error(ctx, GL_INVALID_OPERATION, func);
  TexGenCoord& g = active_unit(ctx).gen[c];
  if (pname == GL_TEXTURE_GEN_MODE) {
    const double d = v[0];
    const auto mode = static_cast<GLenum>(d >= 0.0 && d < 4294967296.0 ? d : 0.0);
    if (static_cast<double>(mode) != d || !valid_gen_mode(c, mode))
      return record_error(ctx, GL_INVALID_ENUM, func, mode);
    if (g.mode == mode) return;
    g.mode = mode;
    return mark_dirty(ctx, kDirtyTexture);
  }
  if ((pname != GL_OBJECT_PLANE && pname != GL_EYE_PLANE) || !vector)
    return record_error(ctx, GL_INVALID_ENUM, func, pname);
  if (pname == GL_OBJECT_PLANE) {
    for (int i = 0; i < 4; ++i)
      g.object_plane[i] = static_cast<float>(v[i]);
  } else {
    // §2.11.4: the eye plane is stored as (p1 p2 p3 p4) M^-1, M the model-view matrix when
    // the plane is specified.
    const glm::dmat4 inv = glm::inverse(glm::dmat4(ctx->modelview.top()));
    const glm::dvec4 p = glm::dvec4(v[0], v[1], v[2], v[3]) * inv;
    for (int i = 0; i < 4; ++i)
      g.eye_plane[i] = static_cast<float>(p[i]);
  }
  mark_dirty(ctx, kDirtyTexture);
}

int get_tex_gen(const char* func, GLenum coord, GLenum pname, double* out, Context** ctx_out) {
  *ctx_out = nullptr;
  Context* ctx = outside_begin_end(func);
  if (ctx == nullptr) return 0;
  *ctx_out = ctx;
  const int c = gen_coord(coord);
  if (c < 0) {
    record_error(ctx, GL_INVALID_ENUM, func, coord);
    return 0;
  }
  if (ctx->texture.active >= GLuint(kMaxTexCoordSets)) {
    record_error(ctx, GL_INVALID_OPERATION, func);
    return 0;
  }
  const TexGenCoord& g = active_unit(ctx).gen[c];
  switch (pname) {
  case GL_TEXTURE_GEN_MODE:
    out[0] = g.mode;
    return 1;
  case GL_OBJECT_PLANE:
    for (int i = 0; i < 4; ++i)
      out[i] = g.object_plane[i];
    return 4;
  case GL_EYE_PLANE:
    for (int i = 0; i < 4; ++i)
      out[i] = g.eye_plane[i];
    return 4;
  default:
    record_error(ctx, GL_INVALID_ENUM, func, pname);
    return 0;
  }
}

// ---- current texture coordinates (GL 2.1 §2.7) ----

inline void multi_texcoord(GLenum target, float s, float t, float r, float q) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  // §2.7: target is TEXTUREi for a unit that exists; otherwise INVALID_ENUM.
  if (target < GL_TEXTURE0 || target >= GL_TEXTURE0 + kMaxTexCoordSets)
    return record_error(ctx, GL_INVALID_ENUM, "glMultiTexCoord", target);
  float* tc = ctx->current.tex[target - GL_TEXTURE0];
  tc[0] = s, tc[1] = t, tc[2] = r, tc[3] = q;
}

} // namespace

namespace {

bool get_texenv(Context& ctx, GLenum pname, QueryValues& out) {
  switch (pname) {
  case GL_ACTIVE_TEXTURE:
    out.ints({double(GL_TEXTURE0 + ctx.texture.active)});
    return true;
  case GL_MAX_TEXTURE_UNITS:
    out.ints({kMaxTexUnits});
    return true;
  default:
    return false;
  }
}

// The target and coordinate-generation enables of a unit (§3.8.15, §2.11.4); Enable acts on
// the active unit.
constexpr Capability kTextureEnvCaps[] = {
    {GL_TEXTURE_1D, 1, CapabilityKind::kPerUnit, kDirtyTexture,
     [](Context& c, unsigned, unsigned u) { return &c.texture.unit[u].enable_1d; }},
    {GL_TEXTURE_2D, 1, CapabilityKind::kPerUnit, kDirtyTexture,
     [](Context& c, unsigned, unsigned u) { return &c.texture.unit[u].enable_2d; }},
    {GL_TEXTURE_3D, 1, CapabilityKind::kPerUnit, kDirtyTexture,
     [](Context& c, unsigned, unsigned u) { return &c.texture.unit[u].enable_3d; }},
    {GL_TEXTURE_CUBE_MAP, 1, CapabilityKind::kPerUnit, kDirtyTexture,
     [](Context& c, unsigned, unsigned u) { return &c.texture.unit[u].enable_cube; }},
    // TEXTURE_GEN_S, T, R, Q are consecutive enums.
    {GL_TEXTURE_GEN_S, 4, CapabilityKind::kPerUnit, kDirtyTexture,
     [](Context& c, unsigned i, unsigned u) { return &c.texture.unit[u].gen_enabled[i]; }},
};

constexpr AttribGroup kTextureEnvGroups[] = {
    member_group<&Context::texture>(GL_TEXTURE_BIT, kDirtyTexture),
};

// Texture objects change without the context's dirty bits (share groups): the sampler
// snapshots are redone when the share group's generation moved.
uint32_t texture_stale(const Context& ctx) {
  const bool stale = ctx.texpipe.any_target_enabled &&
                     ctx.shared->texture_generation != ctx.texpipe.seen_generation;
  return stale ? uint32_t{kDirtyTexture} : 0u;
}

} // namespace

const StateArea kTextureEnvArea = {
    .name = "texture units (GL 2.1 §2.11.4, §3.8.13, §3.8.15, Tables 6.15-6.19)",
    .capabilities = kTextureEnvCaps,
    .get = get_texenv,
    .groups = kTextureEnvGroups,
    .derive_on = kDirtyTexture | kDirtyFog | kDirtyLighting | kDirtyTransform | kDirtyProgram,
    .derive = validate_texpipe,
    .stale = texture_stale,
};

namespace exec {

// GL 2.1 §2.7, §3.8: the unit that texture state commands address.
void GLAPIENTRY ActiveTexture(GLenum texture) {
  PINEDA_CTX_OUTSIDE("glActiveTexture");
  if (texture < GL_TEXTURE0 || texture >= GL_TEXTURE0 + kMaxActiveTexture)
    return record_error(ctx, GL_INVALID_ENUM, "glActiveTexture", texture);
  ctx->texture.active = texture - GL_TEXTURE0;
}

// GL 2.1 §2.8: the unit whose texture coordinate array TexCoordPointer and the client state
// commands address.
void GLAPIENTRY ClientActiveTexture(GLenum texture) {
  PINEDA_CTX_OUTSIDE("glClientActiveTexture");
  if (texture < GL_TEXTURE0 || texture >= GL_TEXTURE0 + kMaxTexCoordSets)
    return record_error(ctx, GL_INVALID_ENUM, "glClientActiveTexture", texture);
  ctx->arrays.client_active_texture = texture - GL_TEXTURE0;
}

// Texture coordinates are not normalized (GL 2.1 §2.7): integers convert directly.
#define PINEDA_MULTITEXCOORD(T, S)                                                                 \
  void GLAPIENTRY MultiTexCoord1##S(GLenum u, T s) {                                               \
    multi_texcoord(u, float(s), 0.0f, 0.0f, 1.0f);                                                 \
  }                                                                                                \
  void GLAPIENTRY MultiTexCoord2##S(GLenum u, T s, T t) {                                          \
    multi_texcoord(u, float(s), float(t), 0.0f, 1.0f);                                             \
  }                                                                                                \
  void GLAPIENTRY MultiTexCoord3##S(GLenum u, T s, T t, T r) {                                     \
    multi_texcoord(u, float(s), float(t), float(r), 1.0f);                                         \
  }                                                                                                \
  void GLAPIENTRY MultiTexCoord4##S(GLenum u, T s, T t, T r, T q) {                                \
    multi_texcoord(u, float(s), float(t), float(r), float(q));                                     \
  }                                                                                                \
  void GLAPIENTRY MultiTexCoord1##S##v(GLenum u, const T* v) {                                     \
    if (v) multi_texcoord(u, float(v[0]), 0.0f, 0.0f, 1.0f);                                       \
  }                                                                                                \
  void GLAPIENTRY MultiTexCoord2##S##v(GLenum u, const T* v) {                                     \
    if (v) multi_texcoord(u, float(v[0]), float(v[1]), 0.0f, 1.0f);                                \
  }                                                                                                \
  void GLAPIENTRY MultiTexCoord3##S##v(GLenum u, const T* v) {                                     \
    if (v) multi_texcoord(u, float(v[0]), float(v[1]), float(v[2]), 1.0f);                         \
  }                                                                                                \
  void GLAPIENTRY MultiTexCoord4##S##v(GLenum u, const T* v) {                                     \
    if (v) multi_texcoord(u, float(v[0]), float(v[1]), float(v[2]), float(v[3]));                  \
  }
PINEDA_MULTITEXCOORD(GLshort, s)
PINEDA_MULTITEXCOORD(GLint, i)
PINEDA_MULTITEXCOORD(GLfloat, f)
PINEDA_MULTITEXCOORD(GLdouble, d)
#undef PINEDA_MULTITEXCOORD

void GLAPIENTRY TexEnvf(GLenum target, GLenum pname, GLfloat param) {
  const double v = param;
  tex_env("glTexEnvf", target, pname, &v, nullptr, false);
}
void GLAPIENTRY TexEnvi(GLenum target, GLenum pname, GLint param) {
  const double v = param;
  tex_env("glTexEnvi", target, pname, &v, nullptr, false);
}
void GLAPIENTRY TexEnvfv(GLenum target, GLenum pname, const GLfloat* params) {
  if (params == nullptr) return;
  const double v = params[0];
  float color[4] = {params[0], 0, 0, 0};
  if (pname == GL_TEXTURE_ENV_COLOR)
    for (int i = 1; i < 4; ++i)
      color[i] = params[i];
  tex_env("glTexEnvfv", target, pname, &v, color, true);
}
void GLAPIENTRY TexEnviv(GLenum target, GLenum pname, const GLint* params) {
  if (params == nullptr) return;
  const double v = params[0];
  float color[4] = {0, 0, 0, 0};
  if (pname == GL_TEXTURE_ENV_COLOR)
    for (int i = 0; i < 4; ++i)
      color[i] = int_color(params[i]);
  tex_env("glTexEnviv", target, pname, &v, color, true);
}

void GLAPIENTRY GetTexEnvfv(GLenum target, GLenum pname, GLfloat* params) {
  double v[4];
  bool is_color = false;
  Context* ctx = nullptr;
  const int n = get_tex_env("glGetTexEnvfv", target, pname, v, &is_color, &ctx);
  if (params == nullptr) return;
  for (int i = 0; i < n; ++i)
    params[i] = static_cast<float>(v[i]);
}
void GLAPIENTRY GetTexEnviv(GLenum target, GLenum pname, GLint* params) {
  double v[4];
  bool is_color = false;
  Context* ctx = nullptr;
  const int n = get_tex_env("glGetTexEnviv", target, pname, v, &is_color, &ctx);
  if (params == nullptr) return;
  for (int i = 0; i < n; ++i)
    params[i] = is_color ? color_to_int(static_cast<float>(v[i])) : float_to_int(v[i]);
}

// Values the vector forms of glTexGen read (GL 2.1 §2.11.4): four for a plane, one for the
// mode, none for an unknown pname (INVALID_ENUM without touching the array).
static int tex_gen_param_count(GLenum pname) {
  if (pname == GL_OBJECT_PLANE || pname == GL_EYE_PLANE) return 4;
  return pname == GL_TEXTURE_GEN_MODE ? 1 : 0;
}

void GLAPIENTRY TexGeni(GLenum coord, GLenum pname, GLint param) {
  const double v = param;
  tex_gen("glTexGeni", coord, pname, &v, false);
}
void GLAPIENTRY TexGenf(GLenum coord, GLenum pname, GLfloat param) {
  const double v = param;
  tex_gen("glTexGenf", coord, pname, &v, false);
}
void GLAPIENTRY TexGend(GLenum coord, GLenum pname, GLdouble param) {
  tex_gen("glTexGend", coord, pname, &param, false);
}
void GLAPIENTRY TexGeniv(GLenum coord, GLenum pname, const GLint* params) {
  if (params == nullptr) return;
  const int n = tex_gen_param_count(pname);
  double v[4] = {};
  for (int i = 0; i < n; ++i)
    v[i] = params[i];
  tex_gen("glTexGeniv", coord, pname, v, true);
}
void GLAPIENTRY TexGenfv(GLenum coord, GLenum pname, const GLfloat* params) {
  if (params == nullptr) return;
  const int n = tex_gen_param_count(pname);
  double v[4] = {};
  for (int i = 0; i < n; ++i)
    v[i] = params[i];
  tex_gen("glTexGenfv", coord, pname, v, true);
}
void GLAPIENTRY TexGendv(GLenum coord, GLenum pname, const GLdouble* params) {
  if (params == nullptr) return;
  const int n = tex_gen_param_count(pname);
  double v[4] = {};
  for (int i = 0; i < n; ++i)
    v[i] = params[i];
  tex_gen("glTexGendv", coord, pname, v, true);
}

void GLAPIENTRY GetTexGeniv(GLenum coord, GLenum pname, GLint* params) {
  double v[4];
  Context* ctx = nullptr;
  const int n = get_tex_gen("glGetTexGeniv", coord, pname, v, &ctx);
  if (params == nullptr) return;
  for (int i = 0; i < n; ++i)
    params[i] = float_to_int(v[i]);
}
void GLAPIENTRY GetTexGenfv(GLenum coord, GLenum pname, GLfloat* params) {
  double v[4];
  Context* ctx = nullptr;
  const int n = get_tex_gen("glGetTexGenfv", coord, pname, v, &ctx);
  if (params == nullptr) return;
  for (int i = 0; i < n; ++i)
    params[i] = static_cast<float>(v[i]);
}
void GLAPIENTRY GetTexGendv(GLenum coord, GLenum pname, GLdouble* params) {
  double v[4];
  Context* ctx = nullptr;
  const int n = get_tex_gen("glGetTexGendv", coord, pname, v, &ctx);
  if (params == nullptr) return;
  for (int i = 0; i < n; ++i)
    params[i] = v[i];
}

} // namespace exec
} // namespace pineda
