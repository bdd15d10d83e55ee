// Selection (GL 2.1 §5.2) and feedback (§5.3): glRenderMode, the selection array and name
// stack, the feedback array and glPassThrough, and the helpers that write hit records and
// feedback values. The primitives themselves come from the draw home (draw/feedback.cpp).
#include <cmath>

#include "state/api_util.h"
#include "dispatch.h"
#include "state/area.h"
#include "state/select.h"

namespace pineda {

namespace {

void select_value(RenderModeState& rm, GLuint v) {
  if (rm.select_buffer != nullptr && rm.select_count < rm.select_size) {
    rm.select_buffer[rm.select_count++] = v;
  } else {
    rm.select_overflow = true;
  }
}

// GL 2.1 §5.2: min and max window z, in [0, 1], times 2^32 - 1, rounded to the nearest
// unsigned integer. Double precision makes the product and its rounding exact enough that
// every float z gets its correctly rounded value.
GLuint scale_z(float z) {
  const double d = z > 0.0f ? (z < 1.0f ? static_cast<double>(z) : 1.0) : 0.0;
  return static_cast<GLuint>(std::llround(d * 4294967295.0));
}

// GL 2.1 §5.2: the hit record (name count, min z, max z, names bottom first), as much of it
// as fits; then the hit flag and the depth range start over.
void write_hit_record(RenderModeState& rm) {
  select_value(rm, static_cast<GLuint>(rm.name_depth));
  select_value(rm, scale_z(rm.hit_min_z));
  select_value(rm, scale_z(rm.hit_max_z));
  for (int i = 0; i < rm.name_depth; ++i)
    select_value(rm, rm.names[i]);
  ++rm.hits;
  rm.hit = false;
  rm.hit_min_z = 1.0f;
  rm.hit_max_z = 0.0f;
}

void flush_hit(RenderModeState& rm) {
  if (rm.hit) write_hit_record(rm);
}

// The value count per feedback vertex (GL 2.1 Table 5.2, RGBA mode).
bool feedback_type_valid(GLenum type) {
  switch (type) {
  case GL_2D:
  case GL_3D:
  case GL_3D_COLOR:
  case GL_3D_COLOR_TEXTURE:
  case GL_4D_COLOR_TEXTURE:
    return true;
  default:
    return false;
  }
}

// The name stack commands act only in SELECT mode (GL 2.1 §5.2: "has no effect" otherwise).
Context* name_stack_context(const char* func) {
  Context* ctx = outside_begin_end(func);
  if (ctx == nullptr || ctx->render_mode.mode != GL_SELECT) return nullptr;
  return ctx;
}

void select_record_hit(RenderModeState& rm, float zmin, float zmax) {
  rm.hit = true;
  if (zmin < rm.hit_min_z) rm.hit_min_z = zmin;
  if (zmax > rm.hit_max_z) rm.hit_max_z = zmax;
}

void feedback_value(RenderModeState& rm, float v) {
  if (rm.feedback_buffer != nullptr && rm.feedback_count < rm.feedback_size) {
    rm.feedback_buffer[rm.feedback_count++] = v;
  } else {
    rm.feedback_overflow = true;
  }
}

void feedback_vertex(RenderModeState& rm, const float win[3], float clip_w, const float color[4],
                     const float tex[4]) {
  feedback_value(rm, win[0]);
  feedback_value(rm, win[1]);
  const GLenum t = rm.feedback_type;
  if (t == GL_2D) return;
  feedback_value(rm, win[2]);
  if (t == GL_4D_COLOR_TEXTURE) feedback_value(rm, clip_w);
  if (t == GL_3D) return;
  for (int k = 0; k < 4; ++k)
    feedback_value(rm, color[k]);
  if (t == GL_3D_COLOR) return;
  for (int k = 0; k < 4; ++k)
    feedback_value(rm, tex[k]);
}

} // namespace

bool render_mode_is_render(const Context* ctx) {
  return ctx->render_mode.mode == GL_RENDER;
}

void RenderModeRecords::hit(float zmin, float zmax) {
  select_record_hit(rm_, zmin, zmax);
}
void RenderModeRecords::value(float v) {
  feedback_value(rm_, v);
}
void RenderModeRecords::vertex(const float win[3], float clip_w, const float color[4],
                               const float tex[4]) {
  feedback_vertex(rm_, win, clip_w, color, tex);
}

void feedback_raster_token(Context* ctx, GLenum token, const float win[4], const float color[4],
                           const float tex[4]) {
  RenderModeState& rm = ctx->render_mode;
  if (rm.mode != GL_FEEDBACK) return;
  feedback_value(rm, static_cast<float>(token));
  feedback_vertex(rm, win, win[3], color, tex);
}

void select_raster_hit(Context* ctx, float win_z) {
  RenderModeState& rm = ctx->render_mode;
  if (rm.mode != GL_SELECT) return;
  select_record_hit(rm, win_z, win_z);
}

namespace {

// Table 6.31: selection and feedback.
bool get_select(Context& ctx, GLenum pname, QueryValues& out) {
  const RenderModeState& rm = ctx.render_mode;
  switch (pname) {
  case GL_RENDER_MODE:
    out.ints({double(rm.mode)});
    return true;
  case GL_NAME_STACK_DEPTH:
    out.ints({double(rm.name_depth)});
    return true;
  case GL_MAX_NAME_STACK_DEPTH:
    out.ints({kMaxNameStackDepth});
    return true;
  case GL_SELECTION_BUFFER_SIZE:
    out.ints({double(rm.select_size)});
    return true;
  case GL_FEEDBACK_BUFFER_SIZE:
    out.ints({double(rm.feedback_size)});
    return true;
  case GL_FEEDBACK_BUFFER_TYPE:
    out.ints({double(rm.feedback_type)});
    return true;
  default:
    return false;
  }
}

bool get_select_pointer(Context& ctx, GLenum pname, void** out) {
  switch (pname) {
  case GL_SELECTION_BUFFER_POINTER:
    *out = ctx.render_mode.select_buffer;
    return true;
  case GL_FEEDBACK_BUFFER_POINTER:
    *out = ctx.render_mode.feedback_buffer;
    return true;
  default:
    return false;
  }
}

} // namespace

const StateArea kSelectArea = {
    .name = "selection and feedback (GL 2.1 §5.2, §5.3, Table 6.31)",
    .get = get_select,
    .get_pointer = get_select_pointer,
};

namespace exec {

GLint GLAPIENTRY RenderMode(GLenum mode) {
  Context* ctx = outside_begin_end("glRenderMode");
  if (ctx == nullptr) return 0;
  RenderModeState& rm = ctx->render_mode;
  if (mode != GL_RENDER && mode != GL_SELECT && mode != GL_FEEDBACK) {
    record_error(ctx, GL_INVALID_ENUM, "glRenderMode", mode);
    return 0;
  }
  // GL 2.1 §5.2, §5.3: entering SELECT or FEEDBACK before the array has been specified is
  // INVALID_OPERATION (and, as an error, leaves the mode as it was).
  if ((mode == GL_SELECT && !rm.select_buffer_set) ||
      (mode == GL_FEEDBACK && !rm.feedback_buffer_set)) {
    record_error(ctx, GL_INVALID_OPERATION, "glRenderMode", mode);
    return 0;
  }
  GLint result = 0;
  switch (rm.mode) {
  case GL_SELECT:
    // §5.2: a pending hit is recorded; the result is the hit record count, or -1 when the
    // array overflowed, which clears the flag.
    flush_hit(rm);
    result = rm.select_overflow ? -1 : rm.hits;
    break;
  case GL_FEEDBACK:
    result = rm.feedback_overflow ? -1 : rm.feedback_count;
    break;
  default:
    break;
  }
  // The arrays' pointers go back to their starts, the flags are reset, and the name stack is
  // cleared whenever RenderMode is called (§5.2).
  rm.select_count = 0;
  rm.hits = 0;
  rm.select_overflow = false;
  rm.hit = false;
  rm.hit_min_z = 1.0f;
  rm.hit_max_z = 0.0f;
  rm.name_depth = 0;
  rm.feedback_count = 0;
  rm.feedback_overflow = false;
  rm.mode = mode;
  mark_dirty(ctx, kDirtyRenderMode);
  return result;
}

void GLAPIENTRY SelectBuffer(GLsizei size, GLuint* buffer) {
  PINEDA_CTX_OUTSIDE("glSelectBuffer");
  if (size < 0) return record_error(ctx, GL_INVALID_VALUE, "glSelectBuffer");
  RenderModeState& rm = ctx->render_mode;
  if (rm.mode == GL_SELECT) return record_error(ctx, GL_INVALID_OPERATION, "glSelectBuffer");
  rm.select_buffer = buffer;
  rm.select_size = size;
  rm.select_buffer_set = true;
}

void GLAPIENTRY FeedbackBuffer(GLsizei size, GLenum type, GLfloat* buffer) {
  PINEDA_CTX_OUTSIDE("glFeedbackBuffer");
  RenderModeState& rm = ctx->render_mode;
  // Checked in Mesa's order; a null array with a positive size is refused as Mesa does (the
  // spec leaves it undefined).
  if (rm.mode == GL_FEEDBACK) return record_error(ctx, GL_INVALID_OPERATION, "glFeedbackBuffer");
  if (size < 0 || (buffer == nullptr && size > 0))
    return record_error(ctx, GL_INVALID_VALUE, "glFeedbackBuffer");
  if (!feedback_type_valid(type))
    return record_error(ctx, GL_INVALID_ENUM, "glFeedbackBuffer", type);
  rm.feedback_buffer = buffer;
  rm.feedback_size = size;
  rm.feedback_type = type;
  rm.feedback_buffer_set = true;
  mark_dirty(ctx, kDirtyRenderMode);
}

void GLAPIENTRY PassThrough(GLfloat token) {
  PINEDA_CTX_OUTSIDE("glPassThrough");
  RenderModeState& rm = ctx->render_mode;
  if (rm.mode != GL_FEEDBACK) return; // §5.3: no effect outside feedback mode
  feedback_value(rm, static_cast<float>(GL_PASS_THROUGH_TOKEN));
  feedback_value(rm, token);
}

void GLAPIENTRY InitNames() {
  Context* ctx = name_stack_context("glInitNames");
  if (ctx == nullptr) return;
  RenderModeState& rm = ctx->render_mode;
  flush_hit(rm);
  rm.name_depth = 0;
}

void GLAPIENTRY PushName(GLuint name) {
  Context* ctx = name_stack_context("glPushName");
  if (ctx == nullptr) return;
  RenderModeState& rm = ctx->render_mode;
  if (rm.name_depth >= kMaxNameStackDepth)
    return record_error(ctx, GL_STACK_OVERFLOW, "glPushName");
  flush_hit(rm);
  rm.names[rm.name_depth++] = name;
}

void GLAPIENTRY PopName() {
  Context* ctx = name_stack_context("glPopName");
  if (ctx == nullptr) return;
  RenderModeState& rm = ctx->render_mode;
  if (rm.name_depth == 0) return record_error(ctx, GL_STACK_UNDERFLOW, "glPopName");
  flush_hit(rm);
  --rm.name_depth;
}

void GLAPIENTRY LoadName(GLuint name) {
  Context* ctx = name_stack_context("glLoadName");
  if (ctx == nullptr) return;
  RenderModeState& rm = ctx->render_mode;
  if (rm.name_depth == 0) return record_error(ctx, GL_INVALID_OPERATION, "glLoadName");
  flush_hit(rm);
  rm.names[rm.name_depth - 1] = name;
}

} // namespace exec
} // namespace pineda
