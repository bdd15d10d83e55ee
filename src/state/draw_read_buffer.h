// The colour buffers drawing writes and reading reads (GL 2.1 §4.2.1, §4.3.2), for
// window-system layers that give a context a front and a back buffer.
#pragma once

#include <cstdint>
#include <vector>

#include "state/context.h"
#include "geometry/geometry.h"
#include "state/select.h"

namespace pineda {

// Points ctx->fb.color, color_also and read_color at the buffers DRAW_BUFFER and READ_BUFFER
// name. Call when either changes or when the window-system layer attaches new buffers; does
// nothing for a framebuffer with a single colour buffer.
void select_color_buffers(Context* ctx);

struct StateArea;
extern const StateArea kFramebufferArea; // draw_read_buffer.cpp

// The depth and stencil values a FRONT_AND_BACK pass may change, kept so that the next pass
// starts from the same values.
struct DepthStencilSnapshot {
  std::vector<uint32_t> depth;
  std::vector<uint8_t> stencil;
  void save(const Context* ctx);
  void restore(Context* ctx) const;
};

// Runs `draw` (a command that rasterizes fragments through ctx->fb and ctx->raster) once per
// draw buffer (GL 2.1 §4.2.1). With FRONT_AND_BACK on a double-buffered drawable it first
// draws into the second buffer and then puts the depth and stencil buffers back, so that the
// final pass, into the primary buffer, meets every fragment with the same depth and stencil
// values and so makes the same decisions; samples are counted in the final pass only.
template <typename F> void for_each_draw_buffer(Context* ctx, F&& draw) {
  Framebuffer& fb = ctx->fb;
  if (fb.color_also != nullptr && render_mode_is_render(ctx)) {
    validate_state(ctx); // the pass changes ctx->raster, so it must be current
    DepthStencilSnapshot snapshot;
    snapshot.save(ctx);
    const bool count = ctx->raster.count_samples;
    uint8_t* const primary = fb.color;
    ctx->raster.count_samples = false;
    ++ctx->raster_serial;
    fb.color = fb.color_also;
    draw();
    fb.color = primary;
    ctx->raster.count_samples = count;
    ++ctx->raster_serial;
    snapshot.restore(ctx);
  }
  draw();
}

} // namespace pineda
