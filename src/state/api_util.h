// The pieces of every entry point's skeleton (DEVELOPERS.md): current context, outside-
// Begin/End check, validate, return early if unchanged, change state, mark dirty.
#pragma once

#include <GL/gl.h>

#include "state/context.h"

namespace pineda {

// Record `err` unless an earlier error is still pending (GL 2.1 §2.5: the first error wins).
// With PINEDA_DEBUG set in the environment every error is logged with the call and the
// offending enum's name.
void record_error(Context* ctx, GLenum err, const char* func, GLenum offending = 0);

// The current context for a command that is illegal between Begin and End (GL 2.1 §2.6.3):
// nullptr when there is no context or when inside Begin/End (then INVALID_OPERATION is set).
inline Context* outside_begin_end(const char* func) {
  Context* ctx = current_context();
  if (ctx != nullptr && ctx->imm.mode != kOutsideBeginEnd) {
    record_error(ctx, GL_INVALID_OPERATION, func);
    return nullptr;
  }
  return ctx;
}

// Shorthand: `CTX_OUTSIDE_BEGIN_END("glFoo");` declares ctx or returns.
#define PINEDA_CTX_OUTSIDE(func)                                                                   \
  Context* ctx = outside_begin_end(func);                                                          \
  if (ctx == nullptr) return

// Clamp to [0,1] (GL 2.1 §2.14: clampf parameters). NaN becomes 0: GL 2.1 §2.1.1 leaves the
// result open but forbids interruption, and a NaN clear depth or depth range would reach
// float-to-integer conversions whose behaviour is undefined.
inline float clampf01(float v) {
  return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
}
inline double clampd01(double v) {
  return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;
}

} // namespace pineda
