// The depth and stencil snapshot of a FRONT_AND_BACK draw's region (draw_buffers.h).
#include "draw/draw_buffers.h"

#include <algorithm>

namespace pineda {

void DepthStencilSnapshot::save(const Framebuffer& fb, const RasterState& rs,
                                const DrawRegion& region) {
  region_.x0 = std::max(region.x0, 0);
  region_.y0 = std::max(region.y0, 0);
  region_.x1 = std::min(region.x1, fb.width);
  region_.y1 = std::min(region.y1, fb.height);
  if (region_.empty()) return;
  const auto w = static_cast<size_t>(region_.x1 - region_.x0);
  const auto rows = static_cast<size_t>(region_.y1 - region_.y0);
  const auto at = [&](int y, int stride) {
    return static_cast<size_t>(y) * static_cast<size_t>(stride) + static_cast<size_t>(region_.x0);
  };
  if (fb.depth != nullptr && rs.depth_test && rs.depth_write) {
    depth_.resize(w * rows);
    for (int y = region_.y0; y < region_.y1; ++y)
      std::copy_n(fb.depth + at(y, fb.depth_stride), w,
                  depth_.data() + static_cast<size_t>(y - region_.y0) * w);
  }
  if (fb.stencil != nullptr && rs.stencil_test &&
      ((rs.stencil.writemask | rs.stencil_back.writemask) & 0xffu) != 0) {
    stencil_.resize(w * rows);
    for (int y = region_.y0; y < region_.y1; ++y)
      std::copy_n(fb.stencil + at(y, fb.stencil_stride), w,
                  stencil_.data() + static_cast<size_t>(y - region_.y0) * w);
  }
}

void DepthStencilSnapshot::restore(const Framebuffer& fb) const {
  if (region_.empty()) return;
  const auto w = static_cast<size_t>(region_.x1 - region_.x0);
  const auto at = [&](int y, int stride) {
    return static_cast<size_t>(y) * static_cast<size_t>(stride) + static_cast<size_t>(region_.x0);
  };
  for (int y = region_.y0; y < region_.y1 && !depth_.empty(); ++y)
    std::copy_n(depth_.data() + static_cast<size_t>(y - region_.y0) * w, w,
                fb.depth + at(y, fb.depth_stride));
  for (int y = region_.y0; y < region_.y1 && !stencil_.empty(); ++y)
    std::copy_n(stencil_.data() + static_cast<size_t>(y - region_.y0) * w, w,
                fb.stencil + at(y, fb.stencil_stride));
}

} // namespace pineda
