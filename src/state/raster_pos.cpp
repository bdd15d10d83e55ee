// The current raster position (GL 2.1 §2.13): glRasterPos transforms a point like a vertex,
// tests it against the clip volume and lights it; glWindowPos (GL 1.4) sets window
// coordinates directly.
#include <cmath>

#include <glm/vec4.hpp>

#include "state/api_util.h"
#include "dispatch.h"
#include "state/draw_call.h"
#include "state/program_draw.h"
#include "state/validate.h"
#include "geometry/light_eval.h"
#include "state/select.h"

namespace pineda {

namespace {

inline float clamp01(float v) {
  return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
}

void raster_pos(float x, float y, float z, float w) {
  PINEDA_CTX_OUTSIDE("glRasterPos");
  check_program_link(ctx);
  validate_state(ctx);
  RasterPos& rp = ctx->current.raster_pos;
  if (ctx->program_draw->has_vertex) {
    const float obj[4] = {x, y, z, w};
    if (!program_raster_pos(ctx, obj, rp)) return;
    select_raster_hit(ctx, rp.win[2]); // §5.2
    mark_dirty(ctx, kDirtyPixel);
    return;
  }
  const glm::vec4 obj(x, y, z, w);
  const glm::vec4 eye = ctx->modelview.top() * obj;
  // The composite matrix, as the vertex path uses, so a raster position lands where a point
  // drawn at the same coordinates would.
  const glm::vec4 clip = ctx->mvp * obj;
  // §2.13: the "point" is clipped against the view volume (§2.12) and the user clip planes,
  // which are tested in eye coordinates.
  // w = 0 has no window coordinates: only (0, 0, 0, 0) would pass, and it is refused too.
  bool inside = clip.w > 0.0f && -clip.w <= clip.x && clip.x <= clip.w && -clip.w <= clip.y &&
                clip.y <= clip.w && -clip.w <= clip.z && clip.z <= clip.w;
  for (int i = 0; i < kMaxClipPlanes && inside; ++i) {
    if (!ctx->transform.clip_enabled[i]) continue;
    const double* p = ctx->transform.clip_plane[i];
    inside = p[0] * eye.x + p[1] * eye.y + p[2] * eye.z + p[3] * eye.w >= 0.0;
  }
  if (!inside) {
    rp.valid = false;
    return;
  }
  PVertex v;
  for (int i = 0; i < 4; ++i)
    v.clip[i] = clip[i];
  to_window(v, ctx->raster.viewport);
  rp.win[0] = v.win[0];
  rp.win[1] = v.win[1];
  rp.win[2] = v.win[2];
  rp.win[3] = clip.w;
  rp.valid = true;
  // §5.2: in selection mode a valid raster position is a hit.
  select_raster_hit(ctx, rp.win[2]);
  // §2.13: with fog source FOG_COORD the current fog coordinate, otherwise the distance from
  // the eye-coordinate origin. A coordinate under every FOG_HINT: the raster position keeps
  // no fog factor.
  rp.distance = ctx->fog.coord_src == GL_FOG_COORD
                    ? ctx->current.fog_coord
                    : std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
  // Colours "just as is done for a vertex" (§2.14): lit, or the clamped current colours.
  // Raster positions have no facing; the front colours are the ones kept.
  const LightingGroup& ls = ctx->lighting;
  if (ls.enabled) {
    float attr[kMaxAttr] = {};
    light_vertex(ctx->light_setup, ls.material, &obj[0], ctx->current.normal, ctx->current.color,
                 attr);
    for (int c = 0; c < 4; ++c)
      rp.color[c] = attr[kAttrColor + c];
    for (int c = 0; c < 3; ++c)
      rp.color2[c] = ctx->light_setup.separate_specular ? attr[kAttrColor2 + c] : 0.0f;
    rp.color2[3] = 1.0f;
  } else {
    for (int c = 0; c < 4; ++c)
      rp.color[c] = clamp01(ctx->current.color[c]);
    for (int c = 0; c < 4; ++c)
      rp.color2[c] = clamp01(ctx->current.color2[c]);
  }
  // Texture coordinates through each unit's texture matrix (§2.11.4).
  for (int u = 0; u < kMaxTexUnits; ++u) {
    const float* t = ctx->current.tex[u];
    const glm::vec4 tc = ctx->texture_matrix[u].top() * glm::vec4(t[0], t[1], t[2], t[3]);
    for (int i = 0; i < 4; ++i)
      rp.tex[u][i] = tc[i];
  }
  mark_dirty(ctx, kDirtyPixel);
}

// §2.13 WindowPos: window coordinates as given, z through the depth range; no
// transformation, lighting or clipping; the valid bit is set.
void window_pos(float x, float y, float z) {
  PINEDA_CTX_OUTSIDE("glWindowPos");
  RasterPos& rp = ctx->current.raster_pos;
  const double n = ctx->viewport.near, f = ctx->viewport.far;
  rp.win[0] = x;
  rp.win[1] = y;
  rp.win[2] = static_cast<float>(z <= 0.0f ? n : z >= 1.0f ? f : n + z * (f - n));
  rp.win[3] = 1.0f;
  rp.valid = true;
  select_raster_hit(ctx, rp.win[2]); // §5.2, as for RasterPos
  // §2.13: the current fog coordinate with fog source FOG_COORD, otherwise 0.
  rp.distance = ctx->fog.coord_src == GL_FOG_COORD ? ctx->current.fog_coord : 0.0f;
  for (int c = 0; c < 4; ++c)
    rp.color[c] = clamp01(ctx->current.color[c]);
  for (int c = 0; c < 4; ++c)
    rp.color2[c] = clamp01(ctx->current.color2[c]);
  for (int u = 0; u < kMaxTexUnits; ++u)
    for (int i = 0; i < 4; ++i)
      rp.tex[u][i] = ctx->current.tex[u][i];
  mark_dirty(ctx, kDirtyPixel);
}

template <typename T> float f(T v) {
  return static_cast<float>(v);
}

} // namespace

namespace exec {

#define PINEDA_RASTER_POS(S, T)                                                                    \
  void GLAPIENTRY RasterPos2##S(T x, T y) {                                                        \
    raster_pos(f(x), f(y), 0.0f, 1.0f);                                                            \
  }                                                                                                \
  void GLAPIENTRY RasterPos3##S(T x, T y, T z) {                                                   \
    raster_pos(f(x), f(y), f(z), 1.0f);                                                            \
  }                                                                                                \
  void GLAPIENTRY RasterPos4##S(T x, T y, T z, T w) {                                              \
    raster_pos(f(x), f(y), f(z), f(w));                                                            \
  }                                                                                                \
  void GLAPIENTRY RasterPos2##S##v(const T* v) {                                                   \
    raster_pos(f(v[0]), f(v[1]), 0.0f, 1.0f);                                                      \
  }                                                                                                \
  void GLAPIENTRY RasterPos3##S##v(const T* v) {                                                   \
    raster_pos(f(v[0]), f(v[1]), f(v[2]), 1.0f);                                                   \
  }                                                                                                \
  void GLAPIENTRY RasterPos4##S##v(const T* v) {                                                   \
    raster_pos(f(v[0]), f(v[1]), f(v[2]), f(v[3]));                                                \
  }                                                                                                \
  void GLAPIENTRY WindowPos2##S(T x, T y) {                                                        \
    window_pos(f(x), f(y), 0.0f);                                                                  \
  }                                                                                                \
  void GLAPIENTRY WindowPos3##S(T x, T y, T z) {                                                   \
    window_pos(f(x), f(y), f(z));                                                                  \
  }                                                                                                \
  void GLAPIENTRY WindowPos2##S##v(const T* v) {                                                   \
    window_pos(f(v[0]), f(v[1]), 0.0f);                                                            \
  }                                                                                                \
  void GLAPIENTRY WindowPos3##S##v(const T* v) {                                                   \
    window_pos(f(v[0]), f(v[1]), f(v[2]));                                                         \
  }

PINEDA_RASTER_POS(s, GLshort)
PINEDA_RASTER_POS(i, GLint)
PINEDA_RASTER_POS(f, GLfloat)
PINEDA_RASTER_POS(d, GLdouble)

#undef PINEDA_RASTER_POS

} // namespace exec
} // namespace pineda
