// The back end's rasterization modes (GL 2.1 §3.3-§3.5): polygon offset arithmetic against a
// double reference, polygon stipple masks, smooth point coverage and the depth a polygon offset
// writes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "raster/raster.h"
#include "raster_test_util.h"

namespace pineda::test {
namespace {

TEST(RasterModesOffset, ArithmeticMatchesReference) {
  RasterModes m;
  for (int bits : {16, 24}) {
    const double depth_max = std::pow(2.0, bits) - 1.0;
    m.depth_mrd = 1.0 / depth_max;
    for (float factor : {0.0f, 1.0f, -2.5f, 4.0f})
      for (float units : {0.0f, 1.0f, -3.0f, 100.0f})
        for (double dzdx : {0.0, 12.5, -300.0})
          for (double dzdy : {0.0, -7.25, 1000.0}) {
            m.offset_factor = factor;
            m.offset_units = units;
            // o = m * factor + r * units with m = max(|dz/dx|, |dz/dy|) and r = 2 steps.
            const double ref = factor * std::max(std::fabs(dzdx), std::fabs(dzdy)) + 2.0 * units;
            EXPECT_NEAR(polygon_offset_depth(m, dzdx, dzdy, depth_max), ref, 1e-9)
                << bits << " " << factor << " " << units << " " << dzdx << " " << dzdy;
          }
  }
}

// Draw a triangle pair covering the whole buffer with the given state.
void fill_all(TestFb& t, const RasterState& rs, float z = 0.5f) {
  DrawCall dc;
  dc.state = &rs;
  dc.fb = &t.fb;
  const PVertex a = vtx(0, 0, z), b = vtx(40, 0, z), c = vtx(40, 40, z), d = vtx(0, 40, z);
  raster_triangle(dc, a, b, c, c, false);
  raster_triangle(dc, a, c, d, d, false);
}

TEST(RasterModesStipple, MaskFollowsWindowPosition) {
  TestFb t(40, 40);
  RasterState rs;
  rs.modes.polygon_stipple = true;
  for (int r = 0; r < 32; ++r)
    rs.modes.polygon_stipple_rows[r] = 0x9e3779b9u * (r + 1);
  fill_all(t, rs);
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x) {
      const bool on = (rs.modes.polygon_stipple_rows[y % 32] >> (x % 32)) & 1u;
      EXPECT_EQ(t.rgba(x, y)[0] != 0, on) << x << "," << y;
    }
}

TEST(RasterModesOffset, FillMovesDepth) {
  TestFb t(40, 40);
  RasterState rs;
  rs.depth_test = true;
  rs.depth_func = GL_ALWAYS;
  rs.modes.offset_fill = true;
  rs.modes.offset_units = 3.0f;
  rs.modes.depth_mrd = 1.0 / 16777215.0;
  fill_all(t, rs, 0.25f);
  const double ref = std::nearbyint(0.25 * 16777215.0 + 6.0);
  EXPECT_EQ(t.depth(5, 5), static_cast<uint32_t>(ref));
  // Clamped to the depth range's end.
  rs.modes.offset_units = -1e7f;
  fill_all(t, rs, 0.25f);
  EXPECT_EQ(t.depth(5, 5), 0u);
}

TEST(RasterModesPoint, SmoothDiscAsLlvmpipe) {
  TestFb t(40, 40);
  RasterState rs;
  rs.modes.point_smooth = true;
  rs.modes.point_size = 10.0f;
  DrawCall dc;
  dc.state = &rs;
  dc.fb = &t.fb;
  const PVertex p = vtx(20.0f, 20.0f, 0.5f, 1.0f, {1.0f, 1.0f, 1.0f, 0.5f});
  raster_point(dc, p);
  // r = 5, k = (1 - 1/r)^2; alpha 0.5 times (1 - d) / (1 - k) inside k, times 1 up to d = 1.
  const double r = 5.0, k = (1.0 - 1.0 / r) * (1.0 - 1.0 / r);
  for (int y = 10; y < 30; ++y)
    for (int x = 10; x < 30; ++x) {
      const double dx = x + 0.5 - 20.0, dy = y + 0.5 - 20.0;
      const double d = (dx * dx + dy * dy) / (r * r);
      const double f = d <= k ? (1.0 - d) / (1.0 - k) : 1.0;
      const int want = d > 1.0 ? 0 : static_cast<int>(std::min(0.5 * f, 1.0) * 255.0 + 0.5);
      EXPECT_NEAR(t.rgba(x, y)[3], want, 1) << x << "," << y;
      EXPECT_EQ(t.rgba(x, y)[0], d > 1.0 ? 0 : 255) << x << "," << y;
    }
}

} // namespace
} // namespace pineda::test
