// Interpolation and primitive rules: perspective-correct colour and linear depth of
// triangles against a double reference (GL 2.1 §3.5.1), flat and two-sided colour, lines
// (§3.4.1, diamond exit) and points (§3.3.1).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "raster/raster.h"
#include "raster_test_util.h"

namespace pineda {
namespace {

using test::counting_state;
using test::kCountColor;
using test::ref_covers;
using test::TestFb;
using test::vtx;

TEST(Raster, PerspectiveCorrectColorAndLinearDepth) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> pos(-20, 84), col(0, 1), invw(0.05f, 2.0f), zr(0, 1);
  const int w = 64, h = 64;
  int checked = 0;
  for (int iter = 0; iter < 200; ++iter) {
    TestFb t(w, h);
    RasterState rs;
    rs.depth_test = true;
    rs.depth_func = GL_ALWAYS;
    DrawCall dc{&rs, &t.fb};
    PVertex v[3];
    for (auto& vi : v)
      vi = vtx(pos(rng), pos(rng), zr(rng), invw(rng), {col(rng), col(rng), col(rng), col(rng)});
    raster_triangle(dc, v[0], v[1], v[2], v[2], false);
    // Reference: screen-space barycentrics of the snapped positions.
    double X[3], Y[3];
    int64_t FX[3], FY[3];
    for (int i = 0; i < 3; ++i) {
      FX[i] = to_fixed(v[i].win[0]);
      FY[i] = to_fixed(v[i].win[1]);
      X[i] = FX[i] / 256.0;
      Y[i] = FY[i] / 256.0;
    }
    const double area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
    if (area == 0) continue;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (!ref_covers(FX, FY, x, y)) continue;
        const double px = x + 0.5, py = y + 0.5;
        double l[3];
        for (int i = 0; i < 3; ++i) {
          const int j = (i + 1) % 3, k = (i + 2) % 3;
          l[i] = ((X[k] - X[j]) * (py - Y[j]) - (Y[k] - Y[j]) * (px - X[j])) / area;
        }
        double den = 0, z = 0;
        for (int i = 0; i < 3; ++i) {
          den += l[i] * v[i].win[3];
          z += l[i] * v[i].win[2];
        }
        const auto got = t.rgba(x, y);
        for (int c = 0; c < 4; ++c) {
          double num = 0;
          for (int i = 0; i < 3; ++i) num += l[i] * v[i].win[3] * v[i].attr[kAttrColor + c];
          const double want = std::clamp(num / den, 0.0, 1.0) * 255.0;
          ASSERT_NEAR(got[c], want, 1.0) << "iter " << iter << " at " << x << "," << y;
        }
        const double zwant = std::clamp(z, 0.0, 1.0) * 16777215.0;
        ASSERT_NEAR(static_cast<double>(t.depth(x, y)), zwant, 1.0);
        ++checked;
      }
  }
  EXPECT_GT(checked, 20000);
}

TEST(Raster, FlatShadingUsesProvokingVertex) {
  TestFb t(16, 16);
  RasterState rs;
  rs.flat = true;
  DrawCall dc{&rs, &t.fb};
  const PVertex a = vtx(0, 0, 0.5f, 1, {1, 0, 0, 1}), b = vtx(16, 0, 0.5f, 1, {0, 1, 0, 1}),
                c = vtx(0, 16, 0.5f, 1, {0, 0, 1, 1});
  raster_triangle(dc, a, b, c, b, false);
  EXPECT_EQ(t.rgba(1, 1), (std::array<uint8_t, 4>{0, 255, 0, 255}));
  EXPECT_EQ(t.rgba(10, 3), (std::array<uint8_t, 4>{0, 255, 0, 255}));
}

TEST(Raster, TwoSidedTakesBackColorsForBackFaces) {
  TestFb t(8, 8);
  RasterState rs;
  rs.two_sided = true;
  rs.attr_count = kMaxAttr;
  DrawCall dc{&rs, &t.fb};
  PVertex v[3] = {vtx(0, 0), vtx(8, 0), vtx(0, 8)};
  for (auto& vi : v) {
    vi.attr[kAttrBackColor + 0] = 0.0f;
    vi.attr[kAttrBackColor + 1] = 0.0f;
    vi.attr[kAttrBackColor + 2] = 1.0f;
    vi.attr[kAttrBackColor + 3] = 1.0f;
  }
  raster_triangle(dc, v[0], v[1], v[2], v[2], true);
  EXPECT_EQ(t.rgba(1, 1), (std::array<uint8_t, 4>{0, 0, 255, 255}));
  raster_triangle(dc, v[0], v[1], v[2], v[2], false);
  EXPECT_EQ(t.rgba(1, 1), (std::array<uint8_t, 4>{255, 255, 255, 255}));
}

TEST(Raster, GuardBandTriangleInterpolatesAcrossFramebuffer) {
  // A huge triangle whose vertices sit near the guard band; colour varies along x only.
  TestFb t(32, 32);
  RasterState rs;
  DrawCall dc{&rs, &t.fb};
  const float g = kGuardBand - 1;
  const PVertex a = vtx(-g, -g, 0.5f, 1, {0, 0, 0, 1}), b = vtx(g, -g, 0.5f, 1, {1, 0, 0, 1}),
                c = vtx(0, g, 0.5f, 1, {0.5f, 0, 0, 1});
  raster_triangle(dc, a, b, c, c, false);
  for (int x = 0; x < 32; ++x) {
    const double want = (x + 0.5 + g) / (2 * g) * 255.0;
    EXPECT_NEAR(t.rgba(x, 5)[0], want, 1.0);
    EXPECT_EQ(t.rgba(x, 5)[3], 255);
  }
}

// Fragments of one line, as a set of (x, y).
std::set<std::pair<int, int>> line_pixels(float x0, float y0, float x1, float y1, int size = 24) {
  TestFb t(size, size, ColorFormat::RGBA8, 0);
  RasterState rs = counting_state();
  DrawCall dc{&rs, &t.fb};
  raster_line(dc, vtx(x0, y0, 0.5f, 1, kCountColor), vtx(x1, y1, 0.5f, 1, kCountColor),
              vtx(x1, y1, 0.5f, 1, kCountColor));
  std::set<std::pair<int, int>> s;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      EXPECT_LE(t.rgba(x, y)[0], 1);
      if (t.rgba(x, y)[0]) s.insert({x, y});
    }
  return s;
}

std::set<std::pair<int, int>> row_span(int x0, int x1, int y) {
  std::set<std::pair<int, int>> s;
  for (int x = x0; x <= x1; ++x) s.insert({x, y});
  return s;
}

// Exact diamond-exit reference (GL 2.1 §3.4.1), independent of the rasterizer: the end
// points are perturbed numerically by -(eps, eps^2), then each open diamond is tested for
// intersection with the segment by clipping the segment's parameter range against the
// diamond's four sides.
std::set<std::pair<int, int>> ref_line(float x0, float y0, float x1, float y1, int size) {
  const double eps = -1e-6, eps2 = -1e-12;
  const double ax = to_fixed(x0) / 256.0 + eps, ay = to_fixed(y0) / 256.0 + eps2;
  const double bx = to_fixed(x1) / 256.0 + eps, by = to_fixed(y1) / 256.0 + eps2;
  std::set<std::pair<int, int>> s;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const double xc = i + 0.5, yc = j + 0.5;
      if (std::abs(bx - xc) + std::abs(by - yc) < 0.5) continue; // ends inside: no fragment
      double lo = 0, hi = 1;
      bool empty = false;
      for (int sx : {-1, 1})
        for (int sy : {-1, 1}) {
          // sx (x - xc) + sy (y - yc) < 1/2 along p(t) = a + t (b - a)
          const double c0 = sx * (ax - xc) + sy * (ay - yc);
          const double c1 = sx * (bx - ax) + sy * (by - ay);
          if (c1 > 0) hi = std::min(hi, (0.5 - c0) / c1);
          else if (c1 < 0) lo = std::max(lo, (0.5 - c0) / c1);
          else if (c0 >= 0.5) empty = true;
        }
      if (!empty && lo < hi) s.insert({i, j});
    }
  return s;
}

TEST(Line, MatchesExactDiamondExitReference) {
  std::mt19937 rng(99);
  const int size = 24;
  std::uniform_int_distribution<int> kind(0, 3), fine(-4 * 256, (size + 4) * 256);
  std::uniform_int_distribution<int> half(-8, 2 * size + 8), len(-3 * 256, 3 * 256);
  int mismatches = 0;
  for (int iter = 0; iter < 6000; ++iter) {
    float p[4];
    const int k = kind(rng);
    for (int c = 0; c < 4; ++c) {
      if (k == 0) p[c] = fine(rng) / 256.0f;             // any subpixel position
      else if (k == 1) p[c] = half(rng) * 0.5f;          // centres, corners, edge midpoints
      else if (k == 2) p[c] = (c < 2 ? fine(rng) : len(rng) + p[c - 2] * 256) / 256.0f; // short
      else p[c] = half(rng) * 0.5f + (c & 1 ? 0.0f : 0.25f);
    }
    const auto got = line_pixels(p[0], p[1], p[2], p[3], size);
    const auto want = ref_line(p[0], p[1], p[2], p[3], size);
    if (got != want && ++mismatches < 8) {
      std::ostringstream g, w;
      for (auto [x, y] : got) g << ' ' << x << ',' << y;
      for (auto [x, y] : want) w << ' ' << x << ',' << y;
      ADD_FAILURE() << "(" << p[0] << "," << p[1] << ")-(" << p[2] << "," << p[3] << ")\n got "
                    << g.str() << "\nwant " << w.str();
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(Line, CentreToCentreIsHalfOpen) {
  EXPECT_EQ(line_pixels(0.5f, 0.5f, 10.5f, 0.5f), row_span(0, 9, 0));
  EXPECT_EQ(line_pixels(10.5f, 0.5f, 0.5f, 0.5f), row_span(1, 10, 0));
  std::set<std::pair<int, int>> col;
  for (int y = 0; y < 8; ++y) col.insert({3, y});
  EXPECT_EQ(line_pixels(3.5f, 0.5f, 3.5f, 8.5f), col);
}

TEST(Line, IntegerCoordinatesFollowThePerturbationRule) {
  // A horizontal segment on the boundary between rows 2 and 3 belongs to row 2 (the segment
  // is moved down by epsilon^2, GL 2.1 §3.4.1); a vertical one on a column boundary to the
  // left column. llvmpipe draws them the same way.
  EXPECT_EQ(line_pixels(1, 3, 7, 3), row_span(1, 6, 2));
  std::set<std::pair<int, int>> col;
  for (int y = 2; y < 9; ++y) col.insert({4, y});
  EXPECT_EQ(line_pixels(5, 2, 5, 9), col);
}

TEST(Line, DiagonalsAndSlopes) {
  std::set<std::pair<int, int>> diag;
  for (int i = 0; i < 5; ++i) diag.insert({i, i});
  EXPECT_EQ(line_pixels(0.5f, 0.5f, 5.5f, 5.5f), diag);
  // x-major, slope +1/2 and -1/2, starting and ending on pixel corners that lie on column
  // centre lines: corner ties go up for the positive slope and down for the negative one.
  const auto s = line_pixels(0.5f, 1.0f, 8.5f, 5.0f);
  EXPECT_EQ(s.size(), 8u);
  for (int x = 0; x < 8; ++x) {
    const double yc = 1.0 + x * 0.5; // height at the centre line of column x
    EXPECT_EQ(s.count({x, static_cast<int>(std::floor(yc))}), 1u) << x;
  }
  const auto n = line_pixels(0.5f, 5.0f, 8.5f, 1.0f);
  EXPECT_EQ(n.size(), 8u);
  for (int x = 0; x < 8; ++x) {
    const double yc = 5.0 - x * 0.5;
    const int want = yc == std::floor(yc) ? static_cast<int>(yc) - 1 : static_cast<int>(yc);
    EXPECT_EQ(n.count({x, want}), 1u) << x;
  }
  EXPECT_EQ(s, ref_line(0.5f, 1.0f, 8.5f, 5.0f, 24));
  EXPECT_EQ(n, ref_line(0.5f, 5.0f, 8.5f, 1.0f, 24));
}

TEST(Line, StripSharesEndpointsWithoutDoubleHits) {
  TestFb t(32, 32, ColorFormat::RGBA8, 0);
  RasterState rs = counting_state();
  DrawCall dc{&rs, &t.fb};
  // Every shared end point lies inside a diamond: the case where GL 2.1 §3.4.1 produces the
  // shared fragment once. (An end point just outside every diamond, such as (3.2, 20.7)
  // after the -epsilon shift, may legitimately give the same fragment to both segments.)
  const float pts[][2] = {{2.5f, 2.5f}, {20.5f, 7.5f}, {25.5f, 28.5f}, {3.3f, 20.6f},
                          {2.5f, 2.5f}};
  int total = 0;
  for (int i = 0; i < 4; ++i) {
    const PVertex a = vtx(pts[i][0], pts[i][1], 0.5f, 1, kCountColor);
    const PVertex b = vtx(pts[i + 1][0], pts[i + 1][1], 0.5f, 1, kCountColor);
    raster_line(dc, a, b, b);
    total += static_cast<int>(std::max(std::abs(std::floor(pts[i + 1][0]) - std::floor(pts[i][0])),
                                       std::abs(std::floor(pts[i + 1][1]) - std::floor(pts[i][1]))));
  }
  int hits = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      ASSERT_LE(t.rgba(x, y)[0], 1) << x << "," << y;
      hits += t.rgba(x, y)[0];
    }
  EXPECT_NEAR(hits, total, 4);
}

TEST(Line, ClippedToFramebufferAndGuardBand) {
  // A line from far outside crossing the framebuffer produces exactly the in-bounds part.
  const auto s = line_pixels(-16000.5f, 10.5f, 16000.5f, 10.5f, 24);
  EXPECT_EQ(s, row_span(0, 23, 10));
  const auto d = line_pixels(-100.5f, -100.5f, 100.5f, 100.5f, 24);
  for (int i = 0; i < 24; ++i) EXPECT_EQ(d.count({i, i}), 1u);
  EXPECT_EQ(d.size(), 24u);
}

TEST(Line, InterpolatesColorAndDepth) {
  TestFb t(16, 4);
  RasterState rs;
  rs.depth_test = true;
  rs.depth_func = GL_ALWAYS;
  DrawCall dc{&rs, &t.fb};
  // Perspective: the far end has 1/w = 0.25.
  const PVertex a = vtx(0.5f, 1.5f, 0.0f, 1.0f, {0, 0, 0, 1});
  const PVertex b = vtx(10.5f, 1.5f, 1.0f, 0.25f, {1, 0, 0, 1});
  raster_line(dc, a, b, b);
  for (int x = 0; x < 10; ++x) {
    const double tt = x / 10.0;
    const double c = (tt * 0.25) / ((1 - tt) * 1.0 + tt * 0.25);
    EXPECT_NEAR(t.rgba(x, 1)[0], c * 255, 1.0) << x;
    EXPECT_NEAR(static_cast<double>(t.depth(x, 1)), tt * 16777215.0, 1.0);
  }
  EXPECT_EQ(t.rgba(10, 1)[3], 0); // end point excluded
  rs.flat = true;
  TestFb f(16, 4);
  DrawCall df{&rs, &f.fb};
  raster_line(df, a, b, a);
  EXPECT_EQ(f.rgba(7, 1), (std::array<uint8_t, 4>{0, 0, 0, 255}));
}

TEST(Point, TruncatesToContainingPixel) {
  TestFb t(8, 8);
  RasterState rs;
  rs.depth_test = true;
  rs.depth_func = GL_ALWAYS;
  DrawCall dc{&rs, &t.fb};
  raster_point(dc, vtx(2.3f, 3.7f, 0.25f, 1, {1, 0, 0, 1}));
  raster_point(dc, vtx(5.0f, 6.0f, 0.75f, 1, {0, 1, 0, 1}));
  raster_point(dc, vtx(-0.5f, 2.0f, 0.5f, 1, {0, 0, 1, 1})); // off screen
  raster_point(dc, vtx(8.0f, 2.0f, 0.5f, 1, {0, 0, 1, 1}));  // off screen
  EXPECT_EQ(t.rgba(2, 3), (std::array<uint8_t, 4>{255, 0, 0, 255}));
  EXPECT_EQ(t.rgba(5, 6), (std::array<uint8_t, 4>{0, 255, 0, 255}));
  EXPECT_EQ(t.depth(2, 3), static_cast<uint32_t>(std::lround(0.25 * 16777215.0)));
  int written = 0;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) written += t.rgba(x, y)[3] != 0;
  EXPECT_EQ(written, 2);
}

TEST(Raster, EdgeBlocksRespectFramebufferBounds) {
  // Sizes that are not multiples of the block size, with triangles covering everything:
  // nothing outside the framebuffer is touched (the vectors have guard bytes after).
  for (int w : {1, 7, 9, 17}) {
    for (int h : {1, 5, 8, 13}) {
      std::vector<uint8_t> mem(static_cast<size_t>(w) * h * 4 + 64, 0xee);
      std::vector<uint32_t> depth(static_cast<size_t>(w) * h + 16, 0xffffffffu);
      Framebuffer fb;
      fb.width = w;
      fb.height = h;
      fb.color = mem.data();
      fb.color_stride = w * 4;
      fb.depth = depth.data();
      fb.depth_bits = 24;
      fb.depth_stride = w;
      RasterState rs;
      rs.depth_test = true;
      DrawCall dc{&rs, &fb};
      raster_triangle(dc, vtx(-50, -50, 0.5f, 1, {0, 0, 0, 0}), vtx(100, -50, 0.5f, 1, {0, 0, 0, 0}),
                      vtx(-50, 100, 0.5f, 1, {0, 0, 0, 0}), vtx(0, 0), false);
      for (size_t i = 0; i < mem.size(); ++i)
        ASSERT_EQ(mem[i], i < static_cast<size_t>(w) * h * 4 ? 0 : 0xee) << w << "x" << h;
      for (size_t i = static_cast<size_t>(w) * h; i < depth.size(); ++i)
        ASSERT_EQ(depth[i], 0xffffffffu);
    }
  }
}

} // namespace
} // namespace pineda
