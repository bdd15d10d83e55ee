// Drawing into every draw buffer (GL 2.1 §4.2.1, GL 2.0 DrawBuffers). With FRONT_AND_BACK on a
// double-buffered drawable, or several draw buffers, a draw is rasterized once per buffer,
// first into the further colour buffers and then into the primary one; all passes must meet every
// fragment with the same depth and stencil values and so make the same decisions, so the depth and
// stencil values the first pass may change are kept and put back. Only the draw's region is kept:
// the window rectangle its primitives or pixels can reach. A fragment shader's draw of primitives
// takes one pass instead (draw.cpp rasterize_both_buffers, FragCtx::more).
#pragma once

#include <cstdint>
#include <vector>

#include "core/raster_state.h"
#include "framebuffer/framebuffer.h"

namespace pineda {

// A rectangle of window pixels, half-open: [x0, x1) x [y0, y1).
struct DrawRegion {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x0 >= x1 || y0 >= y1; }
};

// The depth and stencil values of `region` that a pass with state `rs` may change: depth with
// the test and DEPTH_WRITEMASK on, stencil with the test on and a non-zero write mask (GL 2.1
// §4.1.5, §4.1.6, §4.2.2).
class DepthStencilSnapshot {
public:
  void save(const Framebuffer& fb, const RasterState& rs, const DrawRegion& region);
  void restore(const Framebuffer& fb) const;

private:
  DrawRegion region_;
  std::vector<uint32_t> depth_;
  std::vector<uint8_t> stencil_;
};

// Runs pass(primary) once per draw buffer: for each further colour buffer (fb.more), pass(false)
// with fb.color pointing at it, the depth and stencil values of `region` put back afterwards,
// then pass(true) into the primary buffer (fb.color). Occlusion queries count the primary pass
// only.
template <typename Pass>
void for_each_draw_buffer(Framebuffer& fb, const RasterState& rs, const DrawRegion& region,
                          Pass&& pass) {
  if (fb.more_count > 0) {
    DepthStencilSnapshot snapshot;
    snapshot.save(fb, rs, region);
    const Framebuffer primary = fb;
    for (int i = 0; i < primary.more_count; ++i) {
      fb = primary.with_color(primary.more[i]);
      pass(false);
      snapshot.restore(fb);
    }
    fb = primary;
  }
  pass(true);
}

} // namespace pineda
