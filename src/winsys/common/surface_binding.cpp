// The window systems' access to a Context (surface_binding.h).
#include "winsys/common/surface_binding.h"

#include "state/context.h"
#include "state/framebuffer_object.h"

namespace pineda::winsys {

void bind_buffers(Context* ctx, const SurfaceBuffers& b) {
  Framebuffer& fb = ctx->window;
  fb = Framebuffer{};
  fb.width = b.width;
  fb.height = b.height;
  fb.color_format = b.format;
  fb.alpha_bits = b.alpha_bits;
  fb.color = b.color;
  fb.color_stride = b.stride;
  fb.depth_bits = b.depth_bits;
  fb.depth = b.depth;
  fb.depth_stride = b.width;
  fb.stencil_bits = b.stencil_bits;
  fb.stencil = b.stencil;
  fb.stencil_stride = b.width;
  fb.accum_bits = b.accum_bits;
  fb.accum = b.accum;
  // GL 2.1 table 4.4: a double-buffered window has a front and a back buffer; a pbuffer only
  // its back buffer (it is never shown); a single-buffered window or a pixmap its front buffer.
  if (b.front != nullptr) {
    ctx->color_buffers = kColorBufferFrontLeft | kColorBufferBackLeft;
    fb.back_color = fb.color;
    fb.front_color = b.front;
  } else {
    ctx->color_buffers = b.back ? kColorBufferBackLeft : kColorBufferFrontLeft;
  }
  // The window system is in the middle of its own call: the front_selected hook is not run.
  framebuffers_changed(ctx);
  sync_framebuffers(ctx);
}

void unbind_buffers(Context* ctx) {
  ctx->window = Framebuffer{};
  framebuffers_changed(ctx);
  sync_framebuffers(ctx);
}

bool never_current(const Context* ctx) {
  return !ctx->ever_current;
}

void first_make_current(Context* ctx, int width, int height, bool has_back) {
  if (ctx->ever_current) return;
  ctx->ever_current = true;
  ctx->viewport.w = width;
  ctx->viewport.h = height;
  ctx->scissor.box[2] = width;
  ctx->scissor.box[3] = height;
  const GLenum initial = has_back ? GL_BACK : GL_FRONT;
  ctx->color_buffer.draw_buffers[0] = initial;
  ctx->pixel.read_buffer = initial;
  mark_dirty(ctx, kDirtyViewport | kDirtyFragment);
  framebuffers_changed(ctx);
  sync_framebuffers(ctx);
}

void set_hooks(Context* ctx, void (*present_front)(Context*), void (*front_selected)(Context*)) {
  ctx->present_front = present_front;
  ctx->front_selected = front_selected;
}

bool draws_front(const Context* ctx) {
  const Framebuffer& fb = ctx->fb;
  const uint8_t* front = ctx->window.front_color;
  if (front == nullptr || ctx->fbo.draw_binding != 0) return false;
  if (fb.color == front) return true;
  for (int i = 0; i < fb.more_count; ++i)
    if (fb.more[i].data == front) return true;
  return false;
}

bool uses_front(const Context* ctx) {
  const uint8_t* front = ctx->window.front_color;
  return draws_front(ctx) ||
         (front != nullptr && ctx->fbo.read_binding == 0 && ctx->read_fb.color == front);
}

} // namespace pineda::winsys
