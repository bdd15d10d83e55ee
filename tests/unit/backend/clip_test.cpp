// Clipper tests (GL 2.1 §2.12): every plane, every in/out combination, degenerate w, huge and
// non-finite coordinates, the guard band, bit-identical shared edges, edge flags, segments,
// and a comparison with a double-precision reference clipper on random triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "geometry/clip.h"
#include "geometry/cull.h"

namespace pineda {
namespace {

RasterState make_state(float vx = 0, float vy = 0, float vw = 100, float vh = 100) {
  RasterState rs;
  rs.viewport.x = vx;
  rs.viewport.y = vy;
  rs.viewport.w = vw;
  rs.viewport.h = vh;
  rs.attr_count = 8;
  return rs;
}

// A vertex whose first four attributes equal its clip coordinates, so that interpolation in
// clip space can be checked against the position.
PVertex make_vertex(const ClipSetup& cs, float x, float y, float z, float w) {
  PVertex v{};
  const float c[4] = {x, y, z, w};
  for (int k = 0; k < 4; ++k) {
    v.clip[k] = c[k];
    v.attr[k] = c[k];
  }
  v.attr[4] = 0.25f;
  v.edgeflag = 1;
  v.clipmask = clip_code(cs, v.clip);
  if (v.clipmask == 0) to_window(v, cs.viewport);
  return v;
}

ClipPolygon make_poly(const PVertex& a, const PVertex& b, const PVertex& c, bool e0 = true,
                      bool e1 = true, bool e2 = true) {
  ClipPolygon p;
  p.n = 3;
  p.v[0] = &a;
  p.v[1] = &b;
  p.v[2] = &c;
  p.edge[0] = e0;
  p.edge[1] = e1;
  p.edge[2] = e2;
  return p;
}

uint32_t planes_of(const PVertex& a, const PVertex& b, const PVertex& c) {
  return planes_for_mask(a.clipmask | b.clipmask | c.clipmask);
}

// Every vertex inside every plane in `planes` (up to rounding) and usable by the rasterizer.
void expect_inside(const ClipSetup& cs, uint32_t planes, const ClipPolygon& p) {
  for (int i = 0; i < p.n; ++i) {
    const PVertex& v = *p.v[i];
    EXPECT_GT(v.clip[3], 0.0f);
    const float scale =
        std::fabs(v.clip[0]) + std::fabs(v.clip[1]) + std::fabs(v.clip[2]) + std::fabs(v.clip[3]);
    for (int pl = 0; pl < kNumClipPlanes; ++pl) {
      if (planes & (1u << pl)) {
        EXPECT_GE(plane_distance(cs, pl, v), -1e-5f * scale) << pl;
      }
    }
    for (int k = 0; k < 4; ++k)
      EXPECT_TRUE(std::isfinite(v.win[k]));
    // Attributes were interpolated in clip space like the position (snapping moves the
    // position onto the plane by at most rounding).
    for (int k = 0; k < 4; ++k)
      EXPECT_NEAR(v.attr[k], v.clip[k], 1e-4f * scale + 1e-6f);
    EXPECT_FLOAT_EQ(v.attr[4], 0.25f);
  }
}

TEST(Clip, EveryFrustumPlaneEveryInOutCombination) {
  const RasterState rs = make_state();
  ClipSetup cs;
  init_clip_setup(cs, rs);
  // Positions along the two other axes, distinct so the triangle is never degenerate.
  const float other[3][2] = {{0.3f, 0.1f}, {-0.2f, 0.4f}, {0.1f, -0.5f}};
  for (int p = 0; p < 6; ++p) {
    const int axis = p >> 1;
    const float sign = (p & 1) ? 1.0f : -1.0f; // the outside direction
    for (int outside = 0; outside < 8; ++outside) {
      PVertex v[3];
      for (int k = 0; k < 3; ++k) {
        float c[4] = {0, 0, 0, 1};
        c[(axis + 1) % 3] = other[k][0];
        c[(axis + 2) % 3] = other[k][1];
        c[axis] = (outside & (1 << k)) ? sign * (2.0f + 0.5f * k) : -sign * 0.2f * k;
        v[k] = make_vertex(cs, c[0], c[1], c[2], c[3]);
      }
      const uint32_t planes = planes_of(v[0], v[1], v[2]);
      EXPECT_EQ(planes, outside ? (1u << p) : 0u);
      ClipPolygon poly = make_poly(v[0], v[1], v[2]);
      ClipScratch scratch;
      const bool ok = clip_polygon(cs, planes, poly, scratch);
      const int n_out = __builtin_popcount(static_cast<unsigned>(outside));
      if (n_out == 3) {
        EXPECT_FALSE(ok);
        continue;
      }
      ASSERT_TRUE(ok) << p << " " << outside;
      EXPECT_EQ(poly.n, n_out == 1 ? 4 : 3) << p << " " << outside;
      expect_inside(cs, 1u << p, poly);
      // New vertices lie exactly on the plane.
      int on_plane = 0;
      for (int i = 0; i < poly.n; ++i)
        if (plane_distance(cs, p, *poly.v[i]) == 0.0f) ++on_plane;
      EXPECT_EQ(on_plane, n_out == 0 ? 0 : 2);
      if (n_out == 0) {
        for (int i = 0; i < 3; ++i)
          EXPECT_EQ(poly.v[i], &v[i]);
      }
    }
  }
}

TEST(Clip, UserPlanesEveryInOutCombination) {
  RasterState rs = make_state();
  for (int u = 0; u < 6; ++u) {
    rs.user_clip_mask = 1u << u;
    rs.user_planes[u][0] = 1.0f; // x + 0.5 y + 0.1 >= 0
    rs.user_planes[u][1] = 0.5f;
    rs.user_planes[u][2] = 0.0f;
    rs.user_planes[u][3] = 0.1f;
    ClipSetup cs;
    init_clip_setup(cs, rs);
    for (int outside = 0; outside < 8; ++outside) {
      PVertex v[3];
      const float ys[3] = {0.5f, -0.3f, 0.1f};
      for (int k = 0; k < 3; ++k)
        v[k] = make_vertex(cs, (outside & (1 << k)) ? -0.9f : 0.6f - 0.1f * k, ys[k], 0, 1);
      const uint32_t planes = planes_of(v[0], v[1], v[2]);
      EXPECT_EQ(planes, outside ? (1u << (kFirstUserPlane + u)) : 0u);
      ClipPolygon poly = make_poly(v[0], v[1], v[2]);
      ClipScratch scratch;
      const bool ok = clip_polygon(cs, planes, poly, scratch);
      const int n_out = __builtin_popcount(static_cast<unsigned>(outside));
      ASSERT_EQ(ok, n_out != 3);
      if (!ok) continue;
      EXPECT_EQ(poly.n, n_out == 1 ? 4 : 3);
      expect_inside(cs, planes, poly);
    }
    rs.user_planes[u][0] = rs.user_planes[u][1] = rs.user_planes[u][3] = 0.0f;
  }
}

// With a vertex shader the user planes cut where the distances the vertex stage computed
// from gl_ClipVertex say (GL 2.1 §2.20.3), whatever the clip coordinates: the clipper reads
// and interpolates them, and new vertices lie at distance zero.
TEST(Clip, UserPlaneDistancesFromTheVertexStage) {
  RasterState rs = make_state();
  rs.user_clip_mask = 1u << 2;
  rs.user_dist = kAttrClipDist;
  rs.user_planes[2][0] = 1.0f; // would keep the right side if tested on the clip coordinates
  ClipSetup cs;
  init_clip_setup(cs, rs);
  EXPECT_EQ(cs.user_dist, kAttrClipDist);
  EXPECT_GE(cs.lerp_count, kAttrClipDist + kMaxClipPlanes);
  PVertex v[3] = {make_vertex(cs, -0.5f, -0.5f, 0, 1), make_vertex(cs, 0.5f, -0.5f, 0, 1),
                  make_vertex(cs, 0.0f, 0.5f, 0, 1)};
  // The clip codes leave the user planes to the vertex stage.
  for (const PVertex& p : v)
    EXPECT_EQ(p.clipmask, 0u);
  // Distances 0.5 - 2x: the part left of x = 0.25 stays.
  for (PVertex& p : v) {
    p.attr[kAttrClipDist + 2] = 0.5f - 2.0f * p.clip[0];
    if (p.attr[kAttrClipDist + 2] < 0.0f) p.clipmask |= kClipUser0 << 2;
  }
  const uint32_t planes = planes_of(v[0], v[1], v[2]);
  EXPECT_EQ(planes, 1u << (kFirstUserPlane + 2));
  ClipPolygon poly = make_poly(v[0], v[1], v[2]);
  ClipScratch scratch;
  ASSERT_TRUE(clip_polygon(cs, planes, poly, scratch));
  EXPECT_EQ(poly.n, 4);
  for (int i = 0; i < poly.n; ++i) {
    EXPECT_LE(poly.v[i]->clip[0], 0.25f + 1e-6f) << i;
    EXPECT_GE(poly.v[i]->attr[kAttrClipDist + 2], -1e-6f) << i;
  }
}

TEST(Clip, VertexBehindTheEye) {
  const RasterState rs = make_state();
  ClipSetup cs;
  init_clip_setup(cs, rs);
  const PVertex a = make_vertex(cs, 0.0f, 0.0f, 0.5f, 1.0f);
  const PVertex b = make_vertex(cs, 0.5f, 0.0f, 0.5f, 1.0f);
  const PVertex c = make_vertex(cs, 0.1f, 0.5f, -2.0f, -1.0f); // w < 0
  ClipPolygon poly = make_poly(a, b, c);
  ClipScratch scratch;
  const uint32_t planes = planes_of(a, b, c);
  ASSERT_TRUE(clip_polygon(cs, planes, poly, scratch));
  expect_inside(cs, planes, poly);
  for (int i = 0; i < poly.n; ++i) {
    EXPECT_GE(poly.v[i]->win[0], -1e-3f);
    EXPECT_LE(poly.v[i]->win[0], 100.001f);
    EXPECT_GE(poly.v[i]->win[2], -1e-6f);
    EXPECT_LE(poly.v[i]->win[2], 1.000001f);
  }
}

TEST(Clip, ZeroW) {
  const RasterState rs = make_state();
  ClipSetup cs;
  init_clip_setup(cs, rs);
  // w == 0 away from the origin is outside a frustum plane and clips normally.
  const PVertex a = make_vertex(cs, 0.0f, 0.0f, 0.0f, 1.0f);
  const PVertex b = make_vertex(cs, 0.5f, -0.5f, 0.0f, 1.0f);
  const PVertex c = make_vertex(cs, 0.5f, 0.5f, 0.0f, 0.0f);
  EXPECT_NE(c.clipmask & kClipRight, 0u);
  ClipPolygon poly = make_poly(a, b, c);
  ClipScratch scratch;
  ASSERT_TRUE(clip_polygon(cs, planes_of(a, b, c), poly, scratch));
  expect_inside(cs, planes_of(a, b, c), poly);
  // The clip-space origin is inside every frustum plane but has no projection: it is coded
  // kClipGuard and a triangle through it (which projects to a segment) is dropped.
  const PVertex o = make_vertex(cs, 0.0f, 0.0f, 0.0f, 0.0f);
  EXPECT_EQ(o.clipmask, static_cast<uint32_t>(kClipGuard));
  ClipPolygon poly2 = make_poly(a, b, o);
  EXPECT_FALSE(clip_polygon(cs, planes_of(a, b, o), poly2, scratch));
  // Everything at w <= 0 is outside.
  const PVertex n1 = make_vertex(cs, 0.0f, 0.0f, 0.0f, -1.0f);
  const PVertex n2 = make_vertex(cs, 0.1f, 0.0f, 0.0f, -1.0f);
  const PVertex n3 = make_vertex(cs, 0.0f, 0.1f, 0.0f, -1.0f);
  ClipPolygon poly3 = make_poly(n1, n2, n3);
  EXPECT_FALSE(clip_polygon(cs, planes_of(n1, n2, n3), poly3, scratch));
}

TEST(Clip, HugeCoordinates) {
  const RasterState rs = make_state();
  ClipSetup cs;
  init_clip_setup(cs, rs);
  const PVertex a = make_vertex(cs, 1e30f, 0.0f, 0.0f, 1.0f);
  const PVertex b = make_vertex(cs, 0.0f, 1e30f, 0.0f, 1.0f);
  const PVertex c = make_vertex(cs, -1e30f, -1e30f, 0.0f, 1.0f);
  ClipPolygon poly = make_poly(a, b, c);
  ClipScratch scratch;
  const uint32_t planes = planes_of(a, b, c);
  ASSERT_TRUE(clip_polygon(cs, planes, poly, scratch));
  // The triangle covers the whole view volume: what is left is the viewport square.
  for (int i = 0; i < poly.n; ++i) {
    EXPECT_GE(poly.v[i]->win[0], -1e-3f);
    EXPECT_LE(poly.v[i]->win[0], 100.001f);
    EXPECT_GE(poly.v[i]->win[1], -1e-3f);
    EXPECT_LE(poly.v[i]->win[1], 100.001f);
  }
  const double area = static_cast<double>(polygon_area2(poly.v, poly.n)) / 2.0 / 65536.0;
  EXPECT_NEAR(area, 10000.0, 1.0);

  // Huge w as well.
  const PVertex d = make_vertex(cs, 1e30f, 1e30f, 0.0f, 1e30f);
  const PVertex e = make_vertex(cs, -3e30f, 1e30f, 0.0f, 1e30f);
  const PVertex f = make_vertex(cs, 0.0f, -1e30f, 0.5e30f, 1e30f);
  ClipPolygon poly2 = make_poly(d, e, f);
  ASSERT_TRUE(clip_polygon(cs, planes_of(d, e, f), poly2, scratch));
  expect_inside(cs, planes_of(d, e, f), poly2);
}

TEST(Clip, NonFiniteInputIsDropped) {
  const RasterState rs = make_state();
  ClipSetup cs;
  init_clip_setup(cs, rs);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const PVertex a = make_vertex(cs, 0.0f, 0.0f, 0.0f, 1.0f);
  const PVertex b = make_vertex(cs, 0.5f, 0.0f, 0.0f, 1.0f);
  for (const float bad : {nan, inf, -inf}) {
    for (int k = 0; k < 4; ++k) {
      float c[4] = {0.2f, 2.0f, 0.0f, 1.0f}; // outside top, so the clipper runs
      c[k] = bad;
      const PVertex v = make_vertex(cs, c[0], c[1], c[2], c[3]);
      EXPECT_NE(v.clipmask, 0u);
      ClipPolygon poly = make_poly(a, b, v);
      ClipScratch scratch;
      const uint32_t planes = planes_of(a, b, v);
      if (clip_polygon(cs, planes, poly, scratch)) {
        // Only possible when the bad value ends up on a plane the clipper never evaluates;
        // whatever is returned must still be usable.
        for (int i = 0; i < poly.n; ++i)
          EXPECT_TRUE(std::isfinite(poly.v[i]->win[0]));
      }
      const PVertex* sa = nullptr;
      const PVertex* sb = nullptr;
      EXPECT_FALSE(clip_segment(cs, planes_for_mask(a.clipmask | v.clipmask) | 0x3fu, a, v, scratch,
                                &sa, &sb));
    }
  }
  // A NaN vertex is outside everything, so its code never lets it through unclipped.
  const PVertex n = make_vertex(cs, nan, nan, nan, nan);
  EXPECT_EQ(n.clipmask & 0x3fu, 0x3fu);
  ClipPolygon poly = make_poly(a, b, n);
  ClipScratch scratch;
  EXPECT_FALSE(clip_polygon(cs, planes_of(a, b, n), poly, scratch));
}

TEST(Clip, GuardBand) {
  // A viewport far to the right: some of the view volume maps beyond +-kGuardBand.
  const RasterState rs = make_state(10000.0f, 0.0f, 16384.0f, 100.0f);
  ClipSetup cs;
  init_clip_setup(cs, rs);
  const PVertex a = make_vertex(cs, -0.9f, 0.0f, 0.0f, 1.0f);
  const PVertex b = make_vertex(cs, 0.9f, -0.5f, 0.0f, 1.0f); // window x ~ 25000
  const PVertex c = make_vertex(cs, 0.9f, 0.5f, 0.0f, 1.0f);
  EXPECT_EQ(a.clipmask, 0u);
  EXPECT_EQ(b.clipmask, static_cast<uint32_t>(kClipGuard));
  ClipPolygon poly = make_poly(a, b, c);
  ClipScratch scratch;
  const uint32_t planes = planes_of(a, b, c);
  EXPECT_EQ(planes, kGuardPlaneBits);
  ASSERT_TRUE(clip_polygon(cs, planes, poly, scratch));
  EXPECT_EQ(poly.n, 3);
  float max_x = -1e9f;
  for (int i = 0; i < poly.n; ++i) {
    EXPECT_LE(poly.v[i]->win[0], kGuardBand + 0.01f);
    max_x = std::max(max_x, poly.v[i]->win[0]);
    EXPECT_FALSE(poly.edge[i] && poly.v[i]->win[0] > kGuardBand - 0.01f &&
                 poly.v[(i + 1) % poly.n]->win[0] > kGuardBand - 0.01f)
        << "the guard band must not create boundary edges";
  }
  EXPECT_NEAR(max_x, kGuardBand, 0.01f);

  // A huge triangle in a normal viewport: guard-band planes alone keep it in range.
  const RasterState rs2 = make_state();
  ClipSetup cs2;
  init_clip_setup(cs2, rs2);
  const PVertex d = make_vertex(cs2, -1000.0f, -1000.0f, 0.0f, 1.0f);
  const PVertex e = make_vertex(cs2, 1000.0f, -1000.0f, 0.0f, 1.0f);
  const PVertex f = make_vertex(cs2, 0.0f, 1000.0f, 0.0f, 1.0f);
  ClipPolygon poly2 = make_poly(d, e, f);
  ASSERT_TRUE(clip_polygon(cs2, kGuardPlaneBits, poly2, scratch));
  for (int i = 0; i < poly2.n; ++i) {
    EXPECT_LE(std::fabs(poly2.v[i]->win[0]), kGuardBand + 0.01f);
    EXPECT_LE(std::fabs(poly2.v[i]->win[1]), kGuardBand + 0.01f);
  }
}

TEST(Clip, EdgeFlags) {
  RasterState rs = make_state();
  rs.user_clip_mask = 1;
  rs.user_planes[0][0] = -1.0f; // x <= 0.5 w
  rs.user_planes[0][3] = 0.5f;
  ClipSetup cs;
  init_clip_setup(cs, rs);
  // v1 is outside the right plane (and the user plane); v0, v2 inside both.
  const PVertex v0 = make_vertex(cs, -0.5f, -0.5f, 0.0f, 1.0f);
  const PVertex v1 = make_vertex(cs, 2.0f, 0.0f, 0.0f, 1.0f);
  const PVertex v2 = make_vertex(cs, -0.5f, 0.5f, 0.0f, 1.0f);
  for (const uint32_t planes : {1u << 1, 1u << kFirstUserPlane}) {
    ClipPolygon poly = make_poly(v0, v1, v2, false, true, true);
    ClipScratch scratch;
    ASSERT_TRUE(clip_polygon(cs, planes, poly, scratch));
    ASSERT_EQ(poly.n, 4);
    EXPECT_EQ(poly.v[0], &v0);
    EXPECT_EQ(poly.v[3], &v2);
    EXPECT_FALSE(poly.edge[0]); // what is left of v0->v1 keeps its flag
    // The new edge along the plane: boundary for a user plane only (Mesa's rule).
    EXPECT_EQ(poly.edge[1], planes == (1u << kFirstUserPlane));
    EXPECT_TRUE(poly.edge[2]); // what is left of v1->v2 keeps its flag
    EXPECT_TRUE(poly.edge[3]);
  }
}

// Two triangles share edge a-c, walked c->a by the first and a->c by the second; clipping
// must produce bit-identical vertices on it.
bool same_bits(const PVertex& x, const PVertex& y, int attrs) {
  return std::memcmp(x.clip, y.clip, sizeof x.clip) == 0 &&
         std::memcmp(x.win, y.win, sizeof x.win) == 0 &&
         std::memcmp(x.attr, y.attr, sizeof(float) * static_cast<size_t>(attrs)) == 0;
}

bool on_segment(const PVertex& v, const PVertex& a, const PVertex& c) {
  // v - a parallel to c - a, in 4D, relative tolerance.
  double d[4], e[4];
  double nd = 0, ne = 0;
  for (int k = 0; k < 4; ++k) {
    d[k] = static_cast<double>(v.clip[k]) - a.clip[k];
    e[k] = static_cast<double>(c.clip[k]) - a.clip[k];
    nd += d[k] * d[k];
    ne += e[k] * e[k];
  }
  if (nd == 0) return true;
  double dot = 0;
  for (int k = 0; k < 4; ++k)
    dot += d[k] * e[k];
  const double cos2 = dot * dot / (nd * ne);
  return dot > 0 && cos2 > 1.0 - 1e-9 && nd <= ne * (1 + 1e-6);
}

TEST(Clip, SharedEdgesAreBitIdentical) {
  const RasterState rs = make_state(3.0f, 7.0f, 640.0f, 480.0f);
  ClipSetup cs;
  init_clip_setup(cs, rs);
  std::mt19937 rng(1234);
  std::uniform_real_distribution<float> coord(-3.0f, 3.0f);
  std::uniform_real_distribution<float> wdist(-0.5f, 2.0f);
  int checked = 0;
  for (int iter = 0; iter < 4000; ++iter) {
    auto rv = [&] { return make_vertex(cs, coord(rng), coord(rng), coord(rng), wdist(rng)); };
    const PVertex a = rv(), b = rv(), c = rv(), d = rv();
    ClipPolygon p1 = make_poly(a, b, c); // walks c -> a
    ClipPolygon p2 = make_poly(a, c, d); // walks a -> c
    ClipScratch s1, s2;
    const bool ok1 = clip_polygon(cs, planes_of(a, b, c), p1, s1);
    const bool ok2 = clip_polygon(cs, planes_of(a, c, d), p2, s2);
    if (!ok1 || !ok2) continue;
    for (int i = 0; i < p1.n; ++i) {
      const PVertex& v = *p1.v[i];
      if (&v == &a || &v == &c || !on_segment(v, a, c)) continue;
      bool found = false;
      for (int j = 0; j < p2.n && !found; ++j)
        found = same_bits(v, *p2.v[j], cs.lerp_count);
      EXPECT_TRUE(found) << "iteration " << iter;
      ++checked;
    }
  }
  EXPECT_GT(checked, 500);
}

// Reference: Sutherland-Hodgman in double against the six frustum planes.
using DVec = std::array<double, 4>;
std::vector<DVec> reference_clip(std::vector<DVec> poly) {
  for (int p = 0; p < 6; ++p) {
    const int axis = p >> 1;
    const double s = (p & 1) ? -1.0 : 1.0;
    auto dist = [&](const DVec& v) { return v[3] + s * v[axis]; };
    std::vector<DVec> out;
    for (size_t i = 0; i < poly.size(); ++i) {
      const DVec& u = poly[i];
      const DVec& v = poly[(i + 1) % poly.size()];
      const double du = dist(u), dv = dist(v);
      if (du >= 0) out.push_back(u);
      if ((du >= 0) != (dv >= 0)) {
        const double t = du / (du - dv);
        DVec x;
        for (int k = 0; k < 4; ++k)
          x[k] = u[k] + t * (v[k] - u[k]);
        out.push_back(x);
      }
    }
    poly = out;
    if (poly.size() < 3) return {};
  }
  return poly;
}

TEST(Clip, MatchesDoublePrecisionReference) {
  const RasterState rs = make_state(0.0f, 0.0f, 512.0f, 512.0f);
  ClipSetup cs;
  init_clip_setup(cs, rs);
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> coord(-4.0f, 4.0f);
  std::uniform_real_distribution<float> wdist(-1.0f, 3.0f);
  int compared = 0;
  for (int iter = 0; iter < 5000; ++iter) {
    PVertex v[3];
    std::vector<DVec> ref_in;
    for (int k = 0; k < 3; ++k) {
      v[k] = make_vertex(cs, coord(rng), coord(rng), coord(rng), wdist(rng));
      ref_in.push_back({v[k].clip[0], v[k].clip[1], v[k].clip[2], v[k].clip[3]});
    }
    const std::vector<DVec> ref = reference_clip(ref_in);
    double ref_area = 0;
    for (size_t i = 0; i < ref.size(); ++i) {
      const DVec& p = ref[i];
      const DVec& q = ref[(i + 1) % ref.size()];
      const double px = 256.0 * (p[0] / p[3] + 1.0), py = 256.0 * (p[1] / p[3] + 1.0);
      const double qx = 256.0 * (q[0] / q[3] + 1.0), qy = 256.0 * (q[1] / q[3] + 1.0);
      ref_area += px * qy - qx * py;
    }
    ref_area *= 0.5;
    double perimeter = 0;
    for (size_t i = 0; i < ref.size(); ++i) {
      const DVec& p = ref[i];
      const DVec& q = ref[(i + 1) % ref.size()];
      const double dx = 256.0 * (q[0] / q[3] - p[0] / p[3]);
      const double dy = 256.0 * (q[1] / q[3] - p[1] / p[3]);
      perimeter += std::sqrt(dx * dx + dy * dy);
    }
    ClipPolygon poly = make_poly(v[0], v[1], v[2]);
    ClipScratch scratch;
    const uint32_t planes = planes_of(v[0], v[1], v[2]) & 0x3fu;
    const bool ok = clip_polygon(cs, planes, poly, scratch);
    if (!ok) {
      // Only slivers may disagree about existing at all.
      EXPECT_LT(std::fabs(ref_area), 0.5) << "iteration " << iter;
      continue;
    }
    expect_inside(cs, planes, poly);
    const double area = static_cast<double>(polygon_area2(poly.v, poly.n)) / 2.0 / 65536.0;
    // Snapping to 1/256 pixel moves each vertex by up to half a step in x and y.
    const double tol = 0.003 * perimeter + 1e-4 * std::fabs(ref_area) + 0.01;
    EXPECT_NEAR(area, ref_area, tol) << "iteration " << iter;
    ++compared;
  }
  EXPECT_GT(compared, 1000);
}

TEST(Clip, Segments) {
  const RasterState rs = make_state();
  ClipSetup cs;
  init_clip_setup(cs, rs);
  ClipScratch scratch;
  const PVertex* a = nullptr;
  const PVertex* b = nullptr;
  // Inside: unchanged.
  const PVertex i0 = make_vertex(cs, -0.5f, 0.0f, 0.0f, 1.0f);
  const PVertex i1 = make_vertex(cs, 0.5f, 0.2f, 0.0f, 1.0f);
  ASSERT_TRUE(clip_segment(cs, 0x3fu, i0, i1, scratch, &a, &b));
  EXPECT_EQ(a, &i0);
  EXPECT_EQ(b, &i1);
  // Crossing the right plane: the new end lies exactly on it, window x = 100.
  const PVertex o1 = make_vertex(cs, 3.0f, 0.2f, 0.0f, 1.0f);
  ASSERT_TRUE(clip_segment(cs, planes_for_mask(o1.clipmask), i0, o1, scratch, &a, &b));
  EXPECT_EQ(a, &i0);
  EXPECT_EQ(b->clip[0], b->clip[3]);
  EXPECT_FLOAT_EQ(b->win[0], 100.0f);
  EXPECT_NEAR(b->attr[1], b->clip[1], 1e-6f);
  // Through the volume, both ends outside different planes.
  const PVertex o0 = make_vertex(cs, -3.0f, -0.4f, 0.0f, 1.0f);
  ASSERT_TRUE(
      clip_segment(cs, planes_for_mask(o0.clipmask | o1.clipmask), o0, o1, scratch, &a, &b));
  EXPECT_FLOAT_EQ(a->win[0], 0.0f);
  EXPECT_FLOAT_EQ(b->win[0], 100.0f);
  // Both outside the same plane, or passing by a corner: nothing.
  const PVertex p0 = make_vertex(cs, 2.0f, -3.0f, 0.0f, 1.0f);
  const PVertex p1 = make_vertex(cs, 3.0f, 0.5f, 0.0f, 1.0f);
  EXPECT_FALSE(clip_segment(cs, 0x3fu, p0, p1, scratch, &a, &b));
  const PVertex q0 = make_vertex(cs, 0.0f, 3.0f, 0.0f, 1.0f);
  const PVertex q1 = make_vertex(cs, 3.0f, 0.0f, 0.0f, 1.0f);
  EXPECT_FALSE(clip_segment(cs, 0x3fu, q0, q1, scratch, &a, &b));
  // One end behind the eye.
  const PVertex r1 = make_vertex(cs, 0.2f, 0.1f, -3.0f, -1.0f);
  ASSERT_TRUE(clip_segment(cs, planes_for_mask(r1.clipmask), i0, r1, scratch, &a, &b));
  EXPECT_GT(b->clip[3], 0.0f);
  EXPECT_FLOAT_EQ(b->clip[2], -b->clip[3]); // on the near plane
  EXPECT_FLOAT_EQ(b->win[2], 0.0f);
}

} // namespace
} // namespace pineda
