// Fill rule and coverage of raster_triangle (GL 2.1 §3.5.1): shared edges in every
// direction, shared vertices, ties on pixel centres, watertight meshes, and agreement with a
// brute-force reference for thousands of random triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
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

struct Counter {
  RasterState rs = counting_state();
  TestFb t;
  DrawCall dc;
  Counter(int w, int h) : t(w, h, ColorFormat::RGBA8, 0) { dc = {&rs, &t.fb}; }
  void tri(float x0, float y0, float x1, float y1, float x2, float y2) {
    const PVertex a = vtx(x0, y0, 0.5f, 1, kCountColor), b = vtx(x1, y1, 0.5f, 1, kCountColor),
                  c = vtx(x2, y2, 0.5f, 1, kCountColor);
    raster_triangle(dc, a, b, c, c, false);
  }
  int hits(int x, int y) { return t.rgba(x, y)[0]; }
};

TEST(FillRule, RightTrianglesOnPixelCentres) {
  Counter c(8, 8);
  // Legs along y = 0.5 (bottom edge, owned) and x = 0.5 (left edge, owned); the hypotenuse
  // through centres with i + j = 4 is a right/top edge and is not owned.
  c.tri(0.5f, 0.5f, 4.5f, 0.5f, 0.5f, 4.5f);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_EQ(c.hits(x, y), (x + y <= 3) ? 1 : 0) << x << "," << y;
  // The other half of the square, clockwise: x = 4.5 and y = 4.5 are its right and top edges.
  c.tri(4.5f, 0.5f, 0.5f, 4.5f, 4.5f, 4.5f);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_EQ(c.hits(x, y), (x < 4 && y < 4) ? 1 : 0);
}

TEST(FillRule, HorizontalAndVerticalSharedEdges) {
  // Two rectangles split by a horizontal line through centres, then by a vertical one.
  Counter c(16, 16);
  c.tri(2.5f, 2.5f, 12.5f, 2.5f, 12.5f, 7.5f);
  c.tri(2.5f, 2.5f, 12.5f, 7.5f, 2.5f, 7.5f);
  c.tri(2.5f, 7.5f, 12.5f, 7.5f, 12.5f, 12.5f);
  c.tri(2.5f, 7.5f, 12.5f, 12.5f, 2.5f, 12.5f);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      EXPECT_EQ(c.hits(x, y), (x >= 2 && x < 12 && y >= 2 && y < 12) ? 1 : 0) << x << "," << y;
}

// A fan of triangles around `centre` whose outer vertices are `centre` + integer offsets
// (so every spoke passes exactly through pixel centres or corners, depending on centre).
void check_fan(float cx, float cy, int radius, int spokes, bool reverse) {
  const int size = 2 * radius + 16;
  Counter c(size, size);
  std::vector<std::pair<int, int>> pts;
  for (int i = 0; i < spokes; ++i) {
    const double a = 2 * std::numbers::pi * i / spokes;
    const std::pair<int, int> p{static_cast<int>(std::lround(radius * std::cos(a))),
                                static_cast<int>(std::lround(radius * std::sin(a)))};
    if (std::find(pts.begin(), pts.end(), p) == pts.end()) pts.push_back(p);
  }
  const int n = static_cast<int>(pts.size());
  std::vector<int64_t> fx, fy; // snapped outer polygon, for the reference
  for (int i = 0; i < n; ++i) {
    const auto& p = pts[i];
    const auto& q = pts[(i + 1) % n];
    const float px = cx + p.first, py = cy + p.second, qx = cx + q.first, qy = cy + q.second;
    if (reverse)
      c.tri(cx, cy, qx, qy, px, py);
    else
      c.tri(cx, cy, px, py, qx, qy);
  }
  int covered = 0, expected = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const int h = c.hits(x, y);
      ASSERT_LE(h, 1) << "pixel hit twice at " << x << "," << y;
      covered += h;
      // Reference: union of the fan's triangles, each tested independently.
      int ref = 0;
      for (int i = 0; i < n; ++i) {
        const auto& p = pts[i];
        const auto& q = pts[(i + 1) % n];
        const int64_t X[3] = {to_fixed(cx), to_fixed(cx + p.first), to_fixed(cx + q.first)};
        const int64_t Y[3] = {to_fixed(cy), to_fixed(cy + p.second), to_fixed(cy + q.second)};
        ref += ref_covers(X, Y, x, y) ? 1 : 0;
      }
      ASSERT_LE(ref, 1);
      EXPECT_EQ(h, ref) << x << "," << y;
      expected += ref;
      // Well inside the outer polygon every pixel is covered.
      const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
      if (std::sqrt(dx * dx + dy * dy) < radius * std::cos(std::numbers::pi / n) - 1.5) {
        EXPECT_EQ(h, 1) << x << "," << y;
      }
    }
  }
  EXPECT_EQ(covered, expected);
}

TEST(FillRule, FanAroundPixelCentre) { check_fan(32.5f, 32.5f, 24, 96, false); }
TEST(FillRule, FanAroundPixelCorner) { check_fan(32.0f, 32.0f, 24, 96, true); }
TEST(FillRule, FanAroundSubpixelPoint) { check_fan(32.25f, 31.75f, 20, 40, false); }
TEST(FillRule, FanManySpokes) { check_fan(40.5f, 40.0f, 32, 400, true); }

TEST(FillRule, SharedEdgesAllSlopes) {
  // Quads split along a diagonal of every integer direction (dx, dy) with |dx|,|dy| <= 6,
  // placed on pixel centres: the diagonal passes through many centres.
  for (int dx = -6; dx <= 6; ++dx) {
    for (int dy = -6; dy <= 6; ++dy) {
      if (dx == 0 && dy == 0) continue;
      Counter c(48, 48);
      const float ax = 24.5f - 3 * dx, ay = 24.5f - 3 * dy; // shared edge a -> b
      const float bx = 24.5f + 3 * dx, by = 24.5f + 3 * dy;
      // Apexes on both sides of the edge, perpendicular.
      const float px = 24.5f - 3 * dy, py = 24.5f + 3 * dx;
      const float qx = 24.5f + 3 * dy, qy = 24.5f - 3 * dx;
      c.tri(ax, ay, bx, by, px, py);
      c.tri(bx, by, ax, ay, qx, qy);
      for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x) {
          const int64_t X1[3] = {to_fixed(ax), to_fixed(bx), to_fixed(px)};
          const int64_t Y1[3] = {to_fixed(ay), to_fixed(by), to_fixed(py)};
          const int64_t X2[3] = {to_fixed(bx), to_fixed(ax), to_fixed(qx)};
          const int64_t Y2[3] = {to_fixed(by), to_fixed(ay), to_fixed(qy)};
          const int ref = (ref_covers(X1, Y1, x, y) ? 1 : 0) + (ref_covers(X2, Y2, x, y) ? 1 : 0);
          ASSERT_LE(ref, 1);
          ASSERT_EQ(c.hits(x, y), ref) << dx << "," << dy << " at " << x << "," << y;
          // Centres on the shared edge strictly between a and b belong to exactly one side.
          const int64_t cx = x * 2 + 1, cy = y * 2 + 1; // doubled centre coordinates
          const int64_t cross = (int64_t{2} * dx) * (cy - int64_t(2 * ay)) -
                                (int64_t{2} * dy) * (cx - int64_t(2 * ax));
          const double t =
              ((x + 0.5 - ax) * dx + (y + 0.5 - ay) * dy) / (6.0 * (dx * dx + dy * dy));
          if (cross == 0 && t > 0.0 && t < 1.0) {
            ASSERT_EQ(c.hits(x, y), 1);
          }
        }
    }
  }
}

TEST(FillRule, WatertightJitteredMesh) {
  std::mt19937 rng(1234);
  for (int round = 0; round < 6; ++round) {
    const int w = 67, h = 53, cells = 6 + round * 3;
    Counter c(w, h);
    const float x0 = -5, y0 = -5, span_x = w + 10.0f, span_y = h + 10.0f;
    const float step_x = span_x / cells, step_y = span_y / cells;
    std::uniform_real_distribution<float> jit(-0.25f, 0.25f);
    std::uniform_int_distribution<int> pick(0, 3);
    std::vector<float> gx((cells + 1) * (cells + 1)), gy(gx.size());
    for (int j = 0; j <= cells; ++j)
      for (int i = 0; i <= cells; ++i) {
        float x = x0 + i * step_x, y = y0 + j * step_y;
        const int mode = pick(rng);
        if (i > 0 && i < cells && j > 0 && j < cells) {
          if (mode == 0) { // exactly on a pixel centre
            x = std::floor(x) + 0.5f;
            y = std::floor(y) + 0.5f;
          } else if (mode == 1) { // exactly on a pixel corner
            x = std::floor(x);
            y = std::floor(y);
          } else {
            x += jit(rng) * step_x;
            y += jit(rng) * step_y;
          }
        }
        gx[j * (cells + 1) + i] = x;
        gy[j * (cells + 1) + i] = y;
      }
    for (int j = 0; j < cells; ++j)
      for (int i = 0; i < cells; ++i) {
        const int v00 = j * (cells + 1) + i, v10 = v00 + 1, v01 = v00 + cells + 1, v11 = v01 + 1;
        const bool diag = pick(rng) & 1;
        const int ta[3] = {v00, v10, diag ? v11 : v01};
        const int tb[3] = {diag ? v00 : v10, v11, v01};
        for (const int* t : {ta, tb}) {
          if (pick(rng) & 1)
            c.tri(gx[t[0]], gy[t[0]], gx[t[1]], gy[t[1]], gx[t[2]], gy[t[2]]);
          else
            c.tri(gx[t[0]], gy[t[0]], gx[t[2]], gy[t[2]], gx[t[1]], gy[t[1]]);
        }
      }
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) ASSERT_EQ(c.hits(x, y), 1) << "round " << round << " " << x << "," << y;
  }
}

// Random triangles of all sizes against the brute-force reference, on a framebuffer whose
// size is not a multiple of the block size.
TEST(FillRule, MatchesBruteForceReference) {
  std::mt19937 rng(42);
  const int w = 61, h = 47;
  TestFb t(w, h, ColorFormat::RGBA8, 0);
  RasterState rs;
  DrawCall dc{&rs, &t.fb};
  std::uniform_int_distribution<int> kind(0, 5);
  int mismatches = 0, total_covered = 0;
  for (int iter = 0; iter < 4000; ++iter) {
    float vx[3], vy[3];
    const int k = kind(rng);
    for (int i = 0; i < 3; ++i) {
      float x, y;
      if (k == 0) { // tiny, near one point
        std::uniform_real_distribution<float> u(-2, 2);
        x = 30 + u(rng) + (i ? vx[0] - 30 : 0);
        y = 20 + u(rng) + (i ? vy[0] - 20 : 0);
      } else if (k == 1) { // medium
        std::uniform_real_distribution<float> ux(-10, w + 10), uy(-10, h + 10);
        x = ux(rng);
        y = uy(rng);
      } else if (k == 2) { // snapped to pixel centres and corners (ties)
        std::uniform_int_distribution<int> ux(-4, 2 * w + 8), uy(-4, 2 * h + 8);
        x = ux(rng) * 0.5f;
        y = uy(rng) * 0.5f;
      } else if (k == 3) { // huge, up to the guard band
        std::uniform_real_distribution<float> u(-kGuardBand, kGuardBand);
        x = u(rng);
        y = u(rng);
      } else if (k == 4) { // long and thin through the framebuffer
        std::uniform_real_distribution<float> u(-kGuardBand, kGuardBand), s(-1.5f, 1.5f);
        if (i == 0) {
          x = u(rng);
          y = u(rng);
        } else if (i == 1) {
          x = w - vx[0] + s(rng) * 40;
          y = h - vy[0] + s(rng) * 40;
        } else {
          x = vx[0] + s(rng);
          y = vy[0] + s(rng);
        }
      } else { // exactly at the guard band corners and edges
        const float g = kGuardBand;
        const float choices[] = {-g, g, 0.0f, 30.5f, -g + 0.00390625f, g - 1};
        std::uniform_int_distribution<int> c(0, 5);
        x = choices[c(rng)];
        y = choices[c(rng)];
      }
      vx[i] = x;
      vy[i] = y;
    }
    t.fill_color(0);
    const PVertex a = vtx(vx[0], vy[0]), b = vtx(vx[1], vy[1]), c = vtx(vx[2], vy[2]);
    raster_triangle(dc, a, b, c, a, false);
    const int64_t X[3] = {to_fixed(vx[0]), to_fixed(vx[1]), to_fixed(vx[2])};
    const int64_t Y[3] = {to_fixed(vy[0]), to_fixed(vy[1]), to_fixed(vy[2])};
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const bool want = ref_covers(X, Y, x, y);
        const bool got = t.rgba(x, y)[0] == 255;
        total_covered += got;
        if (want != got && ++mismatches < 10)
          ADD_FAILURE() << "iter " << iter << " pixel " << x << "," << y << " want " << want
                        << " tri (" << vx[0] << "," << vy[0] << ") (" << vx[1] << "," << vy[1]
                        << ") (" << vx[2] << "," << vy[2] << ")";
      }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(total_covered, 100000); // the set is not trivially empty
}

TEST(FillRule, ZeroAreaDrawsNothing) {
  Counter c(16, 16);
  c.tri(1.5f, 1.5f, 8.5f, 8.5f, 4.5f, 4.5f); // collinear through centres
  c.tri(3.5f, 3.5f, 3.5f, 3.5f, 9.5f, 2.5f); // two equal vertices
  c.tri(0, 4.5f, 15, 4.5f, 7, 4.5f);         // horizontal sliver of zero height
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) EXPECT_EQ(c.hits(x, y), 0);
}

} // namespace
} // namespace pineda
