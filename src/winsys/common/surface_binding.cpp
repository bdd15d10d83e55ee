// The window systems' access to a Context (surface_binding.h).
#include "winsys/common/surface_binding.h"

#include "state/context.h"
#include "state/draw_read_buffer.h"

namespace pineda::winsys {

void bind_buffers(Context* ctx, const SurfaceBuffers& b) {
  Framebuffer& fb = ctx->fb;
  fb.width = b.width;
  fb.height = b.height;
  fb.color_format = b.format;
  fb.alpha_bits = b.alpha_bits;
  fb.color = b.color;
  fb.color_stride = b.stride;
  fb.depth_bits = b.depth_bits;
  fb.depth = b.depth;
  fb.stencil_bits = b.stencil_bits;
  fb.stencil = b.stencil;
  fb.accum_bits = b.accum_bits;
  fb.accum = b.accum;
  // GL 2.1 table 4.4: a double-buffered window has a front and a back buffer; a pbuffer only
  // its back buffer (it is never shown); a single-buffered window or a pixmap its front buffer.
  fb.front_color = fb.back_color = fb.color_also = fb.read_color = nullptr;
  if (b.front != nullptr) {
    ctx->color_buffers = kColorBufferFrontLeft | kColorBufferBackLeft;
    fb.back_color = fb.color;
    fb.front_color = b.front;
    // The window system is in the middle of its own call: the hook is not run from here.
    auto* const hook = ctx->front_selected;
    ctx->front_selected = nullptr;
    select_color_buffers(ctx);
    ctx->front_selected = hook;
  } else {
    ctx->color_buffers = b.back ? kColorBufferBackLeft : kColorBufferFrontLeft;
  }
  mark_dirty(ctx, kDirtyFramebuffer);
}

void unbind_buffers(Context* ctx) {
  ctx->fb = Framebuffer{};
  mark_dirty(ctx, kDirtyFramebuffer);
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
  ctx->color_buffer.draw_buffer = initial;
  ctx->pixel.read_buffer = initial;
  mark_dirty(ctx, kDirtyViewport | kDirtyFragment);
}

void set_hooks(Context* ctx, void (*present_front)(Context*), void (*front_selected)(Context*)) {
  ctx->present_front = present_front;
  ctx->front_selected = front_selected;
}

bool draws_front(const Context* ctx) {
  const Framebuffer& fb = ctx->fb;
  return fb.front_color != nullptr &&
         (fb.color == fb.front_color || fb.color_also == fb.front_color);
}

bool uses_front(const Context* ctx) {
  const Framebuffer& fb = ctx->fb;
  return draws_front(ctx) || (fb.front_color != nullptr && fb.read_color == fb.front_color);
}

} // namespace pineda::winsys
