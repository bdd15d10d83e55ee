// glEnable/glDisable/glIsEnabled, client-state enables, hints, glFlush/glFinish
// (GL 2.1 §2.11.4, §2.8, §5.6, §5.5). Capabilities Pineda does not implement yet give
// GL_INVALID_ENUM rather than being silently accepted.
#include "core/api_util.h"
#include "dispatch.h"
#include "state/raster_modes_hooks.h"

namespace pineda {

bool* texpipe_capability(Context* ctx, GLenum cap, uint32_t* dirty); // texenv.cpp
bool* eval_capability(Context* ctx, GLenum cap); // eval.cpp: MAP1_*, MAP2_*, AUTO_NORMAL

namespace {

// The boolean behind a server-side capability and what it invalidates; nullptr when the
// capability is not implemented.
bool* capability(Context* ctx, GLenum cap, uint32_t* dirty) {
  *dirty = 0;
  if (cap >= GL_CLIP_PLANE0 && cap < GL_CLIP_PLANE0 + kMaxClipPlanes) {
    *dirty = kDirtyClipPlanes;
    return &ctx->clip_enabled[cap - GL_CLIP_PLANE0];
  }
  if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + kMaxLights) {
    *dirty = kDirtyLighting;
    return &ctx->lighting.light[cap - GL_LIGHT0].enabled;
  }
  if (bool* flag = raster_mode_capability(ctx, cap)) { // raster_modes.cpp
    *dirty = kDirtyRasterMode;
    return flag;
  }
  if (bool* flag = eval_capability(ctx, cap)) return flag; // no derived state depends on it
  switch (cap) {
  case GL_CULL_FACE: *dirty = kDirtyPolygon; return &ctx->cull_enabled;
  // Lighting (GL 2.1 §2.14.1, §2.14.3).
  case GL_LIGHTING: *dirty = kDirtyLighting; return &ctx->lighting.enabled;
  case GL_COLOR_MATERIAL: *dirty = kDirtyLighting; return &ctx->lighting.color_material;
  case GL_COLOR_SUM: *dirty = kDirtyLighting; return &ctx->lighting.color_sum; // §3.9
  case GL_DEPTH_TEST: *dirty = kDirtyFragment; return &ctx->depth_test;
  case GL_BLEND: *dirty = kDirtyFragment; return &ctx->blend;
  // GL 2.1 §4.1.2, §4.1.4, §4.1.5, §4.1.10.
  case GL_SCISSOR_TEST: *dirty = kDirtyFragment; return &ctx->scissor_test;
  case GL_ALPHA_TEST: *dirty = kDirtyFragment; return &ctx->alpha_test;
  case GL_STENCIL_TEST: *dirty = kDirtyFragment; return &ctx->stencil_test;
  case GL_COLOR_LOGIC_OP: *dirty = kDirtyFragment; return &ctx->color_logic_op;
  // GL_LOGIC_OP is the same enum. Index logic ops have no effect in RGBA mode, but the
  // enable is state all the same.
  case GL_INDEX_LOGIC_OP: return &ctx->index_logic_op;
  // GL 2.1 §4.1.9: dithering may be a no-op; the flag is still state.
  case GL_DITHER: return &ctx->dither;
  // GL 2.1 §2.11.3: normals are rescaled or normalized before lighting.
  case GL_NORMALIZE: *dirty = kDirtyLighting; return &ctx->normalize;
  case GL_RESCALE_NORMAL: *dirty = kDirtyLighting; return &ctx->rescale_normal;
  // Multisample enables, without effect (src/state/multisample.cpp).
  case GL_MULTISAMPLE:
  case GL_SAMPLE_ALPHA_TO_COVERAGE:
  case GL_SAMPLE_ALPHA_TO_ONE:
  case GL_SAMPLE_COVERAGE: return multisample_capability(ctx, cap);
  // Texture target and coordinate-generation enables, fog (src/state/texenv.cpp).
  default: return texpipe_capability(ctx, cap, dirty);
  }
}

ClientArray* client_array(Context* ctx, GLenum array) {
  switch (array) {
  case GL_VERTEX_ARRAY: return &ctx->arrays.vertex;
  case GL_COLOR_ARRAY: return &ctx->arrays.color;
  case GL_NORMAL_ARRAY: return &ctx->arrays.normal;
  case GL_TEXTURE_COORD_ARRAY: return &ctx->arrays.texcoord[ctx->client_active_texture];
  case GL_EDGE_FLAG_ARRAY: return &ctx->arrays.edgeflag;
  case GL_SECONDARY_COLOR_ARRAY: return &ctx->arrays.secondary;
  case GL_FOG_COORD_ARRAY: return &ctx->arrays.fog;
  case GL_INDEX_ARRAY: return &ctx->arrays.index; // color_index.cpp
  default: return nullptr;
  }
}

void set_capability(const char* func, GLenum cap, bool value) {
  PINEDA_CTX_OUTSIDE(func);
  uint32_t dirty = 0;
  bool* flag = capability(ctx, cap, &dirty);
  if (flag == nullptr) {
    // GL 2.1 §2.8 enables the client arrays with EnableClientState only, but Mesa (the
    // tie-breaker) also takes them in Enable/Disable, and programs rely on it (piglit
    // gl-1.1-color-material-array does glEnable(GL_VERTEX_ARRAY)).
    if (ClientArray* a = client_array(ctx, cap)) {
      a->enabled = value;
      return;
    }
    record_error(ctx, GL_INVALID_ENUM, func, cap);
    return;
  }
  if (*flag == value) return;
  *flag = value;
  mark_dirty(ctx, dirty);
  // GL 2.1 §2.14.3: enabling COLOR_MATERIAL makes the tracked properties take the current
  // colour at once.
  if (cap == GL_COLOR_MATERIAL && value) update_color_material(ctx);
}

void set_client_state(const char* func, GLenum array, bool value) {
  PINEDA_CTX_OUTSIDE(func);
  ClientArray* a = client_array(ctx, array);
  if (a == nullptr) {
    record_error(ctx, GL_INVALID_ENUM, func, array);
    return;
  }
  a->enabled = value;
}

} // namespace

// Used by glGet for GL_<cap> queries, which return the same value as glIsEnabled.
bool query_enabled(Context* ctx, GLenum cap, bool* value) {
  uint32_t dirty = 0;
  if (bool* flag = capability(ctx, cap, &dirty)) {
    *value = *flag;
    return true;
  }
  if (ClientArray* a = client_array(ctx, cap)) {
    *value = a->enabled;
    return true;
  }
  return false;
}

namespace exec {

void GLAPIENTRY Enable(GLenum cap) { set_capability("glEnable", cap, true); }
void GLAPIENTRY Disable(GLenum cap) { set_capability("glDisable", cap, false); }

GLboolean GLAPIENTRY IsEnabled(GLenum cap) {
  Context* ctx = outside_begin_end("glIsEnabled");
  if (ctx == nullptr) return GL_FALSE;
  bool value = false;
  if (!query_enabled(ctx, cap, &value)) {
    record_error(ctx, GL_INVALID_ENUM, "glIsEnabled", cap);
    return GL_FALSE;
  }
  return value ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY EnableClientState(GLenum array) {
  set_client_state("glEnableClientState", array, true);
}
void GLAPIENTRY DisableClientState(GLenum array) {
  set_client_state("glDisableClientState", array, false);
}

void GLAPIENTRY Hint(GLenum target, GLenum mode) {
  PINEDA_CTX_OUTSIDE("glHint");
  if (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE) {
    record_error(ctx, GL_INVALID_ENUM, "glHint", mode);
    return;
  }
  GLenum* slot = nullptr;
  switch (target) {
  case GL_PERSPECTIVE_CORRECTION_HINT: slot = &ctx->hint_perspective; break;
  case GL_POINT_SMOOTH_HINT: slot = &ctx->hint_point_smooth; break;
  case GL_LINE_SMOOTH_HINT: slot = &ctx->hint_line_smooth; break;
  case GL_POLYGON_SMOOTH_HINT: slot = &ctx->hint_polygon_smooth; break;
  case GL_FOG_HINT: slot = &ctx->hint_fog; break;
  case GL_GENERATE_MIPMAP_HINT: slot = &ctx->hint_generate_mipmap; break;
  case GL_TEXTURE_COMPRESSION_HINT: slot = &ctx->hint_texture_compression; break;
  default: record_error(ctx, GL_INVALID_ENUM, "glHint", target); return;
  }
  if (*slot == mode) return;
  *slot = mode;
  // The fog hint chooses per-vertex or per-fragment fog (state/validate_texpipe.cpp).
  if (target == GL_FOG_HINT) mark_dirty(ctx, kDirtyFog);
}

// Rendering is synchronous: every command has completed when it returns (GL 2.1 §5.5).
// Rendering is synchronous, so both only hand the front buffer to the window system.
void GLAPIENTRY Flush() {
  Context* ctx = outside_begin_end("glFlush");
  if (ctx != nullptr && ctx->present_front != nullptr) ctx->present_front(ctx);
}
void GLAPIENTRY Finish() {
  Context* ctx = outside_begin_end("glFinish");
  if (ctx != nullptr && ctx->present_front != nullptr) ctx->present_front(ctx);
}

} // namespace exec
} // namespace pineda
