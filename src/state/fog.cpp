// Fog parameters (GL 2.1 §3.10, glFog) and the current fog coordinate (GL 1.4 §2.7,
// glFogCoord); the fog area (Table 6.11, fog.h): FOG and COLOR_SUM, the fog queries and
// FOG_BIT.
#include "state/api_util.h"
#include "dispatch.h"
#include "state/area.h"

namespace pineda {

namespace {

// GL 2.1 Table 2.9: signed integer colour components map to [-1,1].
inline float int_color(GLint c) {
  return static_cast<float>((2.0 * c + 1.0) / 4294967295.0);
}

// glFog with the value(s) as doubles (colours already converted); `vector` for the v forms.
void fog(const char* func, GLenum pname, const double* v, const float* color, bool vector) {
  PINEDA_CTX_OUTSIDE(func);
  FogGroup& f = ctx->fog;
  const auto as_enum = [](double d) {
    const auto e = static_cast<GLenum>(d >= 0.0 && d < 4294967296.0 ? d : 0.0);
    return static_cast<double>(e) == d ? e : GLenum{0};
  };
  switch (pname) {
  case GL_FOG_MODE: {
    const GLenum mode = as_enum(v[0]);
    if (mode != GL_LINEAR && mode != GL_EXP && mode != GL_EXP2)
      return record_error(ctx, GL_INVALID_ENUM, func, mode);
    f.mode = mode;
    break;
  }
  case GL_FOG_COORD_SRC: {
    const GLenum src = as_enum(v[0]);
    if (src != GL_FOG_COORD && src != GL_FRAGMENT_DEPTH)
      return record_error(ctx, GL_INVALID_ENUM, func, src);
    f.coord_src = src;
    break;
  }
  case GL_FOG_DENSITY:
    // §3.10: a negative density is INVALID_VALUE.
    if (v[0] < 0.0) return record_error(ctx, GL_INVALID_VALUE, func);
    f.density = static_cast<float>(v[0]);
    break;
  case GL_FOG_START:
    f.start = static_cast<float>(v[0]);
    break;
  case GL_FOG_END:
    f.end = static_cast<float>(v[0]);
    break;
  case GL_FOG_INDEX:
    f.index = static_cast<float>(v[0]);
    break;
  case GL_FOG_COLOR:
    if (!vector) return record_error(ctx, GL_INVALID_ENUM, func, pname);
    // §3.10: the fog colour is clamped to [0,1] when specified.
    for (int i = 0; i < 4; ++i)
      f.color[i] = clampf01(color[i]);
    break;
  default:
    return record_error(ctx, GL_INVALID_ENUM, func, pname);
  }
  mark_dirty(ctx, kDirtyFog);
}

inline void fog_coord(float c) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  ctx->current.fog_coord = c;
}

bool get_fog(Context& ctx, GLenum pname, QueryValues& out) {
  const FogGroup& fog = ctx.fog;
  switch (pname) {
  case GL_FOG_COLOR:
    out.normalized(fog.color, 4);
    return true;
  case GL_FOG_INDEX:
    out.floats({fog.index});
    return true;
  case GL_FOG_DENSITY:
    out.floats({fog.density});
    return true;
  case GL_FOG_START:
    out.floats({fog.start});
    return true;
  case GL_FOG_END:
    out.floats({fog.end});
    return true;
  case GL_FOG_MODE:
    out.ints({double(fog.mode)});
    return true;
  case GL_FOG_COORD_SRC:
    out.ints({double(fog.coord_src)});
    return true;
  default:
    return false;
  }
}

constexpr Capability kFogCaps[] = {
    {GL_FOG, 1, CapabilityKind::kServer, kDirtyFog,
     [](Context& c, unsigned, unsigned) { return &c.fog.enabled; }},
    // §3.9: the colour sum is folded into the vertex colours with the lit secondary colour
    // (geometry/transform.cpp), so it invalidates the lighting-derived state.
    {GL_COLOR_SUM, 1, CapabilityKind::kServer, kDirtyLighting,
     [](Context& c, unsigned, unsigned) { return &c.fog.color_sum; }},
};

constexpr AttribGroup kFogGroups[] = {
    member_group<&Context::fog>(GL_FOG_BIT, kDirtyFog | kDirtyLighting),
};

} // namespace

const StateArea kFogArea = {
    .name = "fog (GL 2.1 §3.9, §3.10, Table 6.11)",
    .capabilities = kFogCaps,
    .get = get_fog,
    .groups = kFogGroups,
};

namespace exec {

void GLAPIENTRY Fogf(GLenum pname, GLfloat param) {
  const double v = param;
  fog("glFogf", pname, &v, nullptr, false);
}
void GLAPIENTRY Fogi(GLenum pname, GLint param) {
  const double v = param;
  fog("glFogi", pname, &v, nullptr, false);
}
void GLAPIENTRY Fogfv(GLenum pname, const GLfloat* params) {
  if (params == nullptr) return;
  const double v = params[0];
  float color[4] = {params[0], 0, 0, 0};
  if (pname == GL_FOG_COLOR)
    for (int i = 1; i < 4; ++i)
      color[i] = params[i];
  fog("glFogfv", pname, &v, color, true);
}
void GLAPIENTRY Fogiv(GLenum pname, const GLint* params) {
  if (params == nullptr) return;
  const double v = params[0];
  float color[4] = {0, 0, 0, 0};
  if (pname == GL_FOG_COLOR)
    for (int i = 0; i < 4; ++i)
      color[i] = int_color(params[i]);
  fog("glFogiv", pname, &v, color, true);
}

void GLAPIENTRY FogCoordf(GLfloat coord) {
  fog_coord(coord);
}
void GLAPIENTRY FogCoordd(GLdouble coord) {
  fog_coord(static_cast<float>(coord));
}
void GLAPIENTRY FogCoordfv(const GLfloat* coord) {
  if (coord) fog_coord(coord[0]);
}
void GLAPIENTRY FogCoorddv(const GLdouble* coord) {
  if (coord) fog_coord(static_cast<float>(coord[0]));
}

} // namespace exec
} // namespace pineda
