// glEnable/glDisable/glIsEnabled and the client-state enables (GL 2.1 §2.11.4, §2.8, §6.1.1):
// the capabilities every area lists in its StateArea (area.h). Capabilities Pineda does not
// implement give GL_INVALID_ENUM rather than being silently accepted. Also glFlush and
// glFinish (§5.5).
#include "dispatch.h"
#include "state/api_util.h"
#include "state/area.h"

namespace pineda {

namespace {

void set_capability(const char* func, GLenum cap, bool value, bool client_only) {
  PINEDA_CTX_OUTSIDE(func);
  const Capability* c = nullptr;
  bool* flag = capability_flag(*ctx, cap, &c);
  // GL 2.1 §2.8 enables the client arrays with EnableClientState only, but Mesa (the
  // tie-breaker) also takes them in Enable/Disable, and programs rely on it (piglit
  // gl-1.1-color-material-array does glEnable(GL_VERTEX_ARRAY)).
  if (c != nullptr && flag == nullptr && !client_only)
    return record_error(ctx, GL_INVALID_OPERATION, func); // a texture enable, §2.7
  if (flag == nullptr || (client_only && c->kind != CapabilityKind::kClient))
    return record_error(ctx, GL_INVALID_ENUM, func, cap);
  if (*flag == value) return;
  *flag = value;
  mark_dirty(ctx, c->dirty);
  if (c->changed != nullptr) c->changed(*ctx, value);
}

} // namespace

namespace exec {

void GLAPIENTRY Enable(GLenum cap) {
  set_capability("glEnable", cap, true, false);
}
void GLAPIENTRY Disable(GLenum cap) {
  set_capability("glDisable", cap, false, false);
}

GLboolean GLAPIENTRY IsEnabled(GLenum cap) {
  Context* ctx = outside_begin_end("glIsEnabled");
  if (ctx == nullptr) return GL_FALSE;
  const Capability* c = nullptr;
  const bool* flag = capability_flag(*ctx, cap, &c);
  if (flag == nullptr) {
    // A texture enable of an active texture above the conventional units (§2.7).
    if (c != nullptr)
      record_error(ctx, GL_INVALID_OPERATION, "glIsEnabled");
    else
      record_error(ctx, GL_INVALID_ENUM, "glIsEnabled", cap);
    return GL_FALSE;
  }
  return *flag ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY EnableClientState(GLenum array) {
  set_capability("glEnableClientState", array, true, true);
}
void GLAPIENTRY DisableClientState(GLenum array) {
  set_capability("glDisableClientState", array, false, true);
}

// Rendering is synchronous: every command has completed when it returns (GL 2.1 §5.5), so
// both only hand the front buffer to the window system.
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
