// Property tests of the clipper (GL 2.1 §2.12) on extreme input: clip coordinates up to 1e30,
// w from -1e30 to 1e30 including 0, denormal and tiny w, triangles crossing the near plane
// next to far-away vertices. Whatever it is given, clip_polygon and clip_segment return
// vertices the rasterizer can take (w > 0, finite window coordinates within the guard band)
// that lie inside every plane; on finite input the window-space area matches a
// double-precision reference; and the whole back end never fails on it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "../unit/backend/raster_test_util.h"
#include "geometry/assemble.h"
#include "geometry/clip.h"
#include "geometry/cull.h"

namespace pineda {
namespace {

using DVec = std::array<double, 4>;

ClipSetup make_setup(uint32_t user_mask, std::mt19937& rng) {
  RasterState rs;
  rs.viewport = {3.0f, 5.0f, 400.0f, 300.0f, 0.0f, 1.0f};
  rs.attr_count = 4;
  rs.user_clip_mask = user_mask;
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 4; ++k)
      rs.user_planes[i][k] = u(rng);
  ClipSetup cs;
  init_clip_setup(cs, rs);
  return cs;
}

PVertex make_vertex(const ClipSetup& cs, const float c[4]) {
  PVertex v{};
  for (int k = 0; k < 4; ++k) {
    v.clip[k] = c[k];
    v.attr[k] = 0.5f;
  }
  v.edgeflag = 1;
  v.clipmask = clip_code(cs, v.clip);
  if (v.clipmask == 0) to_window(v, cs.viewport);
  return v;
}

std::string describe(const PVertex& v) {
  std::ostringstream o;
  o.precision(9);
  o << " (" << v.clip[0] << ", " << v.clip[1] << ", " << v.clip[2] << ", " << v.clip[3] << ")";
  return o.str();
}

// A coordinate of any magnitude from 1e-30 to 1e30, either sign, sometimes exactly 0.
float wild(std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const int kind = static_cast<int>(rng() % 8);
  if (kind == 0) return 0.0f;
  const float mag = kind < 4 ? u(rng) * 4.0f : std::pow(10.0f, u(rng) * 60.0f - 30.0f);
  return (rng() & 1) ? mag : -mag;
}

float wild_w(std::mt19937& rng) {
  switch (rng() % 6) {
  case 0:
    return 0.0f;
  case 1:
    return std::numeric_limits<float>::denorm_min() * static_cast<float>(1 + rng() % 1000);
  case 2:
    return ((rng() & 1) ? 1.0f : -1.0f) * std::pow(10.0f, -static_cast<float>(rng() % 38));
  default:
    return wild(rng);
  }
}

// The output contract of the clipper for whatever went in.
// `input_scale` is the largest input coordinate magnitude: float arithmetic bounds how far
// outside a plane a result may land relative to it.
void expect_rasterizable(const ClipSetup& cs, uint32_t planes, const PVertex* const* v, int n,
                         int iter, float input_scale) {
  ASSERT_GE(n, 3);
  ASSERT_LE(n, kMaxClipVerts);
  for (int i = 0; i < n; ++i) {
    const PVertex& p = *v[i];
    ASSERT_GT(p.clip[3], 0.0f) << "iteration " << iter;
    for (int k = 0; k < 4; ++k)
      ASSERT_TRUE(std::isfinite(p.win[k])) << "iteration " << iter;
    ASSERT_LE(std::fabs(p.win[0]), 2.0f * kGuardBand) << "iteration " << iter;
    ASSERT_LE(std::fabs(p.win[1]), 2.0f * kGuardBand) << "iteration " << iter;
    const float scale = std::fabs(p.clip[0]) + std::fabs(p.clip[1]) + std::fabs(p.clip[2]) +
                        std::fabs(p.clip[3]) + input_scale;
    for (int pl = 0; pl < kNumClipPlanes; ++pl)
      if (planes & (1u << pl)) {
        // User planes have coefficients up to 1, so rounding scales with the coordinates.
        ASSERT_GE(plane_distance(cs, pl, p), -1e-5f * scale)
            << "plane " << pl << " iteration " << iter;
      }
  }
}

TEST(PropertyClip, ExtremeInputGivesRasterizableOutput) {
  std::mt19937 rng(2024);
  int kept = 0;
  for (int iter = 0; iter < 150000; ++iter) {
    const ClipSetup cs = make_setup(static_cast<uint32_t>(rng() % 64) * ((iter % 3) == 0), rng);
    PVertex v[3];
    for (auto& vx : v) {
      const float c[4] = {wild(rng), wild(rng), wild(rng), wild_w(rng)};
      vx = make_vertex(cs, c);
    }
    const uint32_t planes = planes_for_mask(v[0].clipmask | v[1].clipmask | v[2].clipmask);
    float input_scale = 0.0f;
    for (const PVertex& p : v)
      for (const float c : p.clip)
        input_scale = std::max(input_scale, std::fabs(c));
    ClipPolygon poly;
    poly.n = 3;
    for (int i = 0; i < 3; ++i) {
      poly.v[i] = &v[i];
      poly.edge[i] = true;
    }
    ClipScratch scratch;
    if (planes == 0 || !clip_polygon(cs, planes, poly, scratch)) continue;
    ++kept;
    SCOPED_TRACE(describe(v[0]) + describe(v[1]) + describe(v[2]));
    expect_rasterizable(cs, planes, poly.v, poly.n, iter, input_scale);
    if (HasFatalFailure()) return;

    const PVertex* a = nullptr;
    const PVertex* b = nullptr;
    if (clip_segment(cs, planes_for_mask(v[0].clipmask | v[1].clipmask), v[0], v[1], scratch, &a,
                     &b)) {
      const PVertex* seg[3] = {a, b, b};
      expect_rasterizable(cs, planes_for_mask(v[0].clipmask | v[1].clipmask), seg, 3, iter,
                          input_scale);
      if (HasFatalFailure()) return;
    }
  }
  EXPECT_GT(kept, 8000);
}

// Sutherland-Hodgman in double against the six frustum planes.
// `min_w` receives the smallest |w| of any vertex the clip creates on the way.
std::vector<DVec> reference_clip(std::vector<DVec> poly, double& min_w) {
  min_w = 1e300;
  for (int p = 0; p < 6; ++p) {
    const int axis = p >> 1;
    const double sign = (p & 1) ? -1.0 : 1.0;
    auto dist = [&](const DVec& v) { return v[3] + sign * v[axis]; };
    std::vector<DVec> out;
    for (size_t i = 0; i < poly.size(); ++i) {
      const DVec& a = poly[i];
      const DVec& b = poly[(i + 1) % poly.size()];
      const double da = dist(a), db = dist(b);
      if (da >= 0) out.push_back(a);
      if ((da >= 0) != (db >= 0)) {
        // From the nearer end: a + t (b - a) loses everything to cancellation when the
        // crossing is within 1e-16 of b and a is 1e26 away.
        const double t = da / (da - db), u = -db / (da - db);
        DVec x;
        for (int k = 0; k < 4; ++k)
          x[k] = t <= 0.5 ? a[k] + t * (b[k] - a[k]) : b[k] + u * (a[k] - b[k]);
        min_w = std::min(min_w, std::fabs(x[3]));
        out.push_back(x);
      }
    }
    poly = out;
    if (poly.size() < 3) return {};
  }
  return poly;
}

// Area and perimeter of a clip-space polygon in window space (viewport 3,5 400x300).
void window_measure(const std::vector<DVec>& poly, double& area, double& perimeter) {
  area = perimeter = 0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const DVec& p = poly[i];
    const DVec& q = poly[(i + 1) % poly.size()];
    const double px = 200.0 * (p[0] / p[3] + 1.0), py = 150.0 * (p[1] / p[3] + 1.0);
    const double qx = 200.0 * (q[0] / q[3] + 1.0), qy = 150.0 * (q[1] / q[3] + 1.0);
    area += 0.5 * (px * qy - qx * py);
    perimeter += std::hypot(qx - px, qy - py);
  }
}

// Triangles with one vertex near the viewport and the others anywhere within a dynamic range
// of 1e6 (w of both signs, down to 1e-6 and 0): the surviving area agrees with the
// double-precision reference. Wider ranges within one triangle are covered by the test
// above only: float clip coordinates cannot place a crossing accurately when the ends
// differ by 1e12 or more.
float ranged(std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  if (rng() % 8 == 0) return 0.0f;
  const float mag = std::pow(10.0f, u(rng) * 12.0f - 6.0f);
  return (rng() & 1) ? mag : -mag;
}

TEST(PropertyClip, ExtremeTrianglesMatchDoubleReference) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<float> near_u(-0.9f, 0.9f), wn(0.5f, 2.0f);
  int compared = 0;
  RasterState rs;
  rs.viewport = {3.0f, 5.0f, 400.0f, 300.0f, 0.0f, 1.0f};
  ClipSetup cs;
  init_clip_setup(cs, rs);
  for (int iter = 0; iter < 100000; ++iter) {
    PVertex v[3];
    std::vector<DVec> ref_in;
    for (int i = 0; i < 3; ++i) {
      float c[4];
      if (i == 0) {
        c[3] = wn(rng);
        for (int k = 0; k < 3; ++k)
          c[k] = near_u(rng) * c[3];
      } else {
        for (int k = 0; k < 4; ++k)
          c[k] = ranged(rng);
      }
      v[i] = make_vertex(cs, c);
      ref_in.push_back({c[0], c[1], c[2], c[3]});
    }
    double created_w = 0;
    const std::vector<DVec> ref = reference_clip(ref_in, created_w);
    // Crossings that approach the clip-space origin (x, y, z, w all near 0) have no
    // meaningful projection even in double; only well-conditioned references are compared.
    bool conditioned = true;
    for (const DVec& r : ref)
      conditioned =
          conditioned && std::fabs(r[0]) <= 1.001 * r[3] && std::fabs(r[1]) <= 1.001 * r[3];
    if (!conditioned) continue;
    double ref_area = 0, perimeter = 0;
    if (!ref.empty()) window_measure(ref, ref_area, perimeter);
    if (!std::isfinite(ref_area) || !std::isfinite(perimeter)) continue; // w = 0 at a corner
    ClipPolygon poly;
    poly.n = 3;
    for (int i = 0; i < 3; ++i) {
      poly.v[i] = &v[i];
      poly.edge[i] = true;
    }
    ClipScratch scratch;
    const uint32_t planes = planes_for_mask(v[0].clipmask | v[1].clipmask | v[2].clipmask);
    double area = 0;
    if (planes == 0) {
      area = static_cast<double>(fixed_area2(v[0], v[1], v[2])) / 2.0 / 65536.0;
    } else if (clip_polygon(cs, planes, poly, scratch)) {
      area = static_cast<double>(polygon_area2(poly.v, poly.n)) / 2.0 / 65536.0;
    }
    // Snapping moves each vertex by up to half a 1/256 step. The clipper's plane distances are
    // floats, off by up to 6e-8 of the largest input coordinate M; a crossing with clip w
    // moves in window space by that over w, relative (the crossing of the near plane close to
    // the eye is ill-conditioned in any precision that starts from float distances).
    double input_max = 0.0, min_w = 1e300;
    for (const DVec& r : ref_in)
      for (const double c : r)
        input_max = std::max(input_max, std::fabs(c));
    for (const DVec& r : ref)
      min_w = std::min(min_w, r[3]);
    // A crossing made next to the eye (w tiny against the inputs) projects anywhere.
    if (created_w < 1e-4 * input_max) continue;
    const double tol = 0.004 * perimeter + 1e-4 * std::fabs(ref_area) + 0.05 +
                       perimeter * 4e-7 * input_max / min_w;
    ASSERT_NEAR(std::fabs(area), std::fabs(ref_area), tol)
        << "iteration " << iter << " vertices " << describe(v[0]) << describe(v[1])
        << describe(v[2]);
    compared += ref_area != 0.0;
  }
  EXPECT_GT(compared, 8000);
}

// Regression: a triangle with one vertex behind the eye and one at w = 2.6e18. The crossing
// of the near plane on the far edge is 3e-18 of the way from the vertex behind the eye; with
// 1 - t rounded to 0 the new vertex landed on that vertex (w < 0) and the polygon folded
// over itself, so one triangle covered pixels twice (found by PropertyWatertight).
TEST(PropertyClip, NearCrossingNextToFarVertexStaysInFront) {
  RasterState rs;
  rs.viewport = {0.0f, 0.0f, 61.0f, 47.0f, 0.0f, 1.0f};
  ClipSetup cs;
  init_clip_setup(cs, rs);
  const float c[3][4] = {{12.7469f, 25.0012f, 28.889f, 28.9021f},
                         {55.8544f, 58.5027f, -7.86958f, -7.85654f},
                         {1.22035e18f, 2.36958e18f, 2.58574e18f, 2.58574e18f}};
  PVertex v[3];
  for (int i = 0; i < 3; ++i)
    v[i] = make_vertex(cs, c[i]);
  ClipPolygon poly;
  poly.n = 3;
  for (int i = 0; i < 3; ++i) {
    poly.v[i] = &v[i];
    poly.edge[i] = true;
  }
  ClipScratch scratch;
  const uint32_t planes = planes_for_mask(v[0].clipmask | v[1].clipmask | v[2].clipmask);
  ASSERT_TRUE(clip_polygon(cs, planes, poly, scratch));
  expect_rasterizable(cs, planes, poly.v, poly.n, 0, 0.0f);
  // The fan of the clipped polygon covers each pixel at most once.
  test::TestFb t(61, 47, ColorFormat::RGBA8, 0);
  RasterState count = test::counting_state();
  count.viewport = rs.viewport;
  DrawCall dc{&count, &t.fb};
  for (int i = 0; i < poly.n; ++i) {
    PVertex& p = const_cast<PVertex&>(*poly.v[i]);
    for (int k = 0; k < 4; ++k)
      p.attr[k] = test::kCountColor[k];
  }
  for (int i = 1; i + 1 < poly.n; ++i)
    raster_triangle(dc, *poly.v[0], *poly.v[i], *poly.v[i + 1], *poly.v[0], false);
  for (int y = 0; y < 47; ++y)
    for (int x = 0; x < 61; ++x)
      ASSERT_LE(t.rgba(x, y)[0], 1) << x << "," << y;
}

// Regression: a denormal w passes every frustum test, but 1/w overflows, so the vertex used
// to reach the rasterizer with infinite window coordinates (found by the fuzzer: UBSan,
// float-to-int overflow in to_fixed). It now goes to the clipper, which drops what it cannot
// project.
TEST(PropertyClip, DenormalWIsNotProjected) {
  RasterState rs;
  rs.viewport = {0.0f, 0.0f, 32.0f, 32.0f, 0.0f, 1.0f};
  ClipSetup cs;
  init_clip_setup(cs, rs);
  const float d = std::numeric_limits<float>::denorm_min();
  const float c[4] = {0.0f, 0.0f, 0.0f, 4 * d};
  EXPECT_NE(clip_code(cs, c) & kClipGuard, 0u);
  const float n[4] = {0.0f, 0.0f, 0.0f, std::numeric_limits<float>::min()};
  EXPECT_EQ(clip_code(cs, n), 0u);
  PVertex v[3];
  const float cs3[3][4] = {{0, 0, 0, 4 * d}, {d, 0, 0, 4 * d}, {0, d, 0, 4 * d}};
  for (int i = 0; i < 3; ++i)
    v[i] = make_vertex(cs, cs3[i]);
  test::TestFb t(32, 32, ColorFormat::RGBA8, 24);
  RasterState draw = rs;
  DrawCall dc{&draw, &t.fb};
  for (const GLenum mode : {GL_TRIANGLES, GL_LINE_LOOP, GL_POINTS})
    draw_primitives(dc, mode, v, nullptr, 3);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      EXPECT_EQ(t.rgba(x, y)[0], 0);
}

} // namespace
} // namespace pineda
