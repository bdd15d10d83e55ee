// The colour buffers drawing writes and reading reads (GL 2.1 §4.2.1, §4.3.2), for
// window-system layers that give a context a front and a back buffer.
#pragma once

#include "core/context.h"
#include "geometry/geometry.h"
#include "state/select.h"

namespace pineda {

// Points ctx->fb.color, color_also and read_color at the buffers DRAW_BUFFER and READ_BUFFER
// name. Call when either changes or when the window-system layer attaches new buffers; does
// nothing for a framebuffer with a single colour buffer.
void select_color_buffers(Context* ctx);

// Runs `draw` (a command that rasterizes fragments through ctx->fb and ctx->raster) once per
// draw buffer. With FRONT_AND_BACK on a double-buffered drawable it first draws into the
// second buffer with depth, stencil and sample-count updates off, so that both passes see the
// same depth and stencil values and the final pass alone updates them.
template <typename F> void for_each_draw_buffer(Context* ctx, F&& draw) {
  Framebuffer& fb = ctx->fb;
  if (fb.color_also != nullptr && render_mode_is_render(ctx)) {
    validate_state(ctx); // the passes change ctx->raster, so it must be current
    RasterState saved = ctx->raster;
    uint8_t* const primary = fb.color;
    ctx->raster.depth_write = false;
    ctx->raster.stencil_writemask = 0;
    ctx->raster.count_samples = false;
    fb.color = fb.color_also;
    draw();
    fb.color = primary;
    ctx->raster = saved;
  }
  draw();
}

} // namespace pineda
