// Drawing into every draw buffer (GL 2.1 §4.2.1). With FRONT_AND_BACK on a double-buffered
// drawable a draw is rasterized twice, first into the second colour buffer and then into the
// primary one; both passes must meet every fragment with the same depth and stencil values
// and so make the same decisions, so the depth and stencil values the first pass may change
// are kept and put back. Only the draw's region is kept: the window rectangle its primitives
// or pixels can reach.
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
  void restore(Framebuffer& fb) const;

private:
  DrawRegion region_;
  std::vector<uint32_t> depth_;
  std::vector<uint8_t> stencil_;
};

// Runs pass(primary) once per draw buffer: with a second colour buffer (fb.color_also), first
// pass(false) into it, the depth and stencil values of `region` put back afterwards, then
// pass(true) into the primary buffer (fb.color). Occlusion queries count the primary pass only.
template <typename Pass>
void for_each_draw_buffer(Framebuffer& fb, const RasterState& rs, const DrawRegion& region,
                          Pass&& pass) {
  if (fb.color_also != nullptr) {
    DepthStencilSnapshot snapshot;
    snapshot.save(fb, rs, region);
    uint8_t* const primary = fb.color;
    fb.color = fb.color_also;
    pass(false);
    fb.color = primary;
    snapshot.restore(fb);
  }
  pass(true);
}

} // namespace pineda
