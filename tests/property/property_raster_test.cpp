// Property tests of triangle rasterization (GL 2.1 §3.5.1): coverage equals an exact integer
// reference on the same snapped vertices for random triangles of every slope and size from
// sub-pixel to the whole guard band; interpolated depth stays within the triangle's range and
// is monotone along rows and columns.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "../unit/backend/raster_test_util.h"
#include "raster/raster.h"

namespace pineda {
namespace {

using test::TestFb;
using test::ref_covers;
using test::vtx;

// A random window coordinate pair near an anchor at distance `size` in a random direction;
// clamped to the guard band the rasterizer accepts.
struct TriGen {
  std::mt19937 rng;
  int w, h;

  float clamp_guard(float v) { return std::clamp(v, -kGuardBand, kGuardBand); }

  // One of several shapes, all overlapping [0,w]x[0,h] often enough to matter.
  void make(float vx[3], float vy[3]) {
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::uniform_real_distribution<float> ux(-2.0f, w + 2.0f), uy(-2.0f, h + 2.0f);
    // Log-uniform size from 1/256 pixel to 16384 pixels.
    const float size = std::exp2(u01(rng) * 22.0f - 8.0f);
    const int shape = static_cast<int>(rng() % 6);
    const float ax = ux(rng), ay = uy(rng);
    for (int i = 0; i < 3; ++i) {
      const float ang = u01(rng) * 6.2831853f;
      float r = size * (0.2f + u01(rng));
      if (shape == 1 && i == 2) r = size * 1e-3f; // a vertex close to the anchor: thin sliver
      vx[i] = ax + r * std::cos(ang);
      vy[i] = ay + r * std::sin(ang);
    }
    if (shape == 2) { // nearly horizontal or vertical edges: slopes near 0 and infinity
      const int k = static_cast<int>(rng() % 3);
      const float eps = (u01(rng) - 0.5f) * 4.0f / 256.0f;
      if (rng() & 1) vy[(k + 1) % 3] = vy[k] + eps;
      else vx[(k + 1) % 3] = vx[k] + eps;
    } else if (shape == 3) { // vertices on the 1/256 grid at pixel centres, corners, halves
      for (int i = 0; i < 3; ++i) {
        vx[i] = std::round(vx[i] * 2.0f) * 0.5f;
        vy[i] = std::round(vy[i] * 2.0f) * 0.5f;
      }
    } else if (shape == 4) { // a long edge through the framebuffer from the guard band
      vx[0] = (rng() & 1) ? -kGuardBand : kGuardBand;
      vy[0] = (u01(rng) * 2.0f - 1.0f) * kGuardBand;
      vx[1] = ax;
      vy[1] = ay;
      vx[2] = ax + (u01(rng) - 0.5f) * 8.0f;
      vy[2] = ay + (u01(rng) - 0.5f) * 8.0f;
    } else if (shape == 5) { // collinear or repeated vertices: zero area
      vx[2] = vx[0] + (vx[1] - vx[0]) * 0.5f;
      vy[2] = vy[0] + (vy[1] - vy[0]) * 0.5f;
      if (rng() & 1) {
        vx[2] = vx[1];
        vy[2] = vy[1];
      }
    }
    for (int i = 0; i < 3; ++i) {
      vx[i] = clamp_guard(vx[i]);
      vy[i] = clamp_guard(vy[i]);
    }
  }
};

// Random triangles against the reference. The framebuffer is small (sizes not multiples of
// the 8x8 block) and only its pixels are compared; triangles up to the guard band reach the
// 64-bit edge path, small ones the 32-bit one.
void check_coverage(uint32_t seed, int w, int h, int cases) {
  TestFb t(w, h, ColorFormat::RGBA8, 0);
  RasterState rs;
  DrawCall dc{&rs, &t.fb};
  TriGen gen{std::mt19937(seed), w, h};
  int failures = 0;
  long covered = 0;
  for (int iter = 0; iter < cases && failures < 5; ++iter) {
    float vx[3], vy[3];
    gen.make(vx, vy);
    t.fill_color(0);
    const PVertex a = vtx(vx[0], vy[0]), b = vtx(vx[1], vy[1]), c = vtx(vx[2], vy[2]);
    raster_triangle(dc, a, b, c, a, false);
    const int64_t X[3] = {to_fixed(vx[0]), to_fixed(vx[1]), to_fixed(vx[2])};
    const int64_t Y[3] = {to_fixed(vy[0]), to_fixed(vy[1]), to_fixed(vy[2])};
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const bool want = ref_covers(X, Y, x, y);
        const bool got = t.rgba(x, y)[0] != 0;
        covered += got;
        if (want != got) {
          ++failures;
          ADD_FAILURE() << "seed " << seed << " case " << iter << " pixel (" << x << "," << y
                        << ") want " << want << " triangle (" << vx[0] << "," << vy[0] << ") ("
                        << vx[1] << "," << vy[1] << ") (" << vx[2] << "," << vy[2] << ")";
          y = h;
          break;
        }
      }
  }
  EXPECT_GT(covered, cases / 20); // the cases are not trivially empty
}

TEST(PropertyCoverage, RandomTrianglesMatchExactReference) {
  check_coverage(1, 37, 29, 20000);
  check_coverage(2, 64, 64, 8000);
  check_coverage(3, 9, 70, 8000);
  check_coverage(4, 1, 1, 8000);
}

// GL 2.1 §3.5.1 eq 3.10: window z is linear in window space, so over a triangle it lies
// between the smallest and largest vertex z and changes monotonically along every row and
// column, in one direction for the whole triangle.
TEST(PropertyDepth, InterpolatedDepthStaysInRangeAndMonotone) {
  const int w = 48, h = 40;
  for (const int bits : {16, 24, 32}) {
    TestFb t(w, h, ColorFormat::RGBA8, bits);
    RasterState rs;
    rs.depth_test = true;
    rs.depth_func = GL_ALWAYS;
    DrawCall dc{&rs, &t.fb};
    TriGen gen{std::mt19937(100 + bits), w, h};
    std::mt19937 zr(7 + bits);
    std::uniform_real_distribution<float> uz(0.0f, 1.0f);
    const double dmax = TestFb::fb_depth_max(bits);
    int drawn = 0;
    for (int iter = 0; iter < 8000; ++iter) {
      float vx[3], vy[3];
      gen.make(vx, vy);
      float z[3] = {uz(zr), uz(zr), uz(zr)};
      if (iter % 5 == 0) z[1] = z[2] = z[0]; // constant depth
      if (iter % 7 == 0) { z[0] = 0.0f; z[1] = 1.0f; }
      const PVertex a = vtx(vx[0], vy[0], z[0]), b = vtx(vx[1], vy[1], z[1]),
                    c = vtx(vx[2], vy[2], z[2]);
      raster_triangle(dc, a, b, c, a, false);
      const double lo = *std::min_element(z, z + 3) * dmax, hi = *std::max_element(z, z + 3) * dmax;
      int dir_x = 0, dir_y = 0;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          if (t.rgba(x, y)[0] == 0) continue; // not covered
          const uint32_t d = t.depth(x, y);
          ++drawn;
          ASSERT_GE(d + 1.0, lo) << "bits " << bits << " case " << iter;
          ASSERT_LE(d - 1.0, hi) << "bits " << bits << " case " << iter;
          if (x + 1 < w && t.rgba(x + 1, y)[0] != 0) {
            const uint32_t n = t.depth(x + 1, y);
            const int s = n > d ? 1 : (n < d ? -1 : 0);
            if (s != 0) {
              ASSERT_TRUE(dir_x == 0 || dir_x == s) << "row not monotone, case " << iter;
              dir_x = s;
            }
          }
          if (y + 1 < h && t.rgba(x, y + 1)[0] != 0) {
            const uint32_t n = t.depth(x, y + 1);
            const int s = n > d ? 1 : (n < d ? -1 : 0);
            if (s != 0) {
              ASSERT_TRUE(dir_y == 0 || dir_y == s) << "column not monotone, case " << iter;
              dir_y = s;
            }
          }
        }
      t.fill_color(0);
    }
    EXPECT_GT(drawn, 10000);
  }
}

} // namespace
} // namespace pineda
