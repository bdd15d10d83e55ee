// Primitive assembly (GL 2.1 §2.6.1): primitive counts for the ten modes, incomplete
// primitives, provoking vertices (§2.14.7 Table 2.12), strip winding, index lists, trivial
// accept and reject, and points and lines through the clipper.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry/assemble.h"
#include "geometry/clip.h"
#include "geometry/cull.h"

namespace pineda {
namespace {

constexpr int kTag = kAttrTex0; // the vertex's index, for identification

struct Recorder : PrimitiveSink {
  struct Tri {
    const PVertex *a, *b, *c, *prov;
    PVertex va, vb, vc;
    bool back;
  };
  struct Seg {
    const PVertex *a, *b, *prov; // identities; new vertices die with the draw call
    PVertex va, vb;
  };
  std::vector<Tri> tris;
  std::vector<Seg> lines;
  std::vector<const PVertex*> points;
  void triangle(const PVertex& a, const PVertex& b, const PVertex& c, const PVertex& prov,
                bool back) override {
    tris.push_back({&a, &b, &c, &prov, a, b, c, back});
  }
  void line(const PVertex& a, const PVertex& b, const PVertex& prov, bool) override {
    lines.push_back({&a, &b, &prov, a, b});
  }
  void point(const PVertex& p, bool) override { points.push_back(&p); }
};

RasterState make_state() {
  RasterState rs;
  rs.viewport.w = 100;
  rs.viewport.h = 100;
  rs.attr_count = kAttrTex0 + 4;
  return rs;
}

PVertex win_vertex(const RasterState& rs, float x, float y, int tag) {
  ClipSetup cs;
  init_clip_setup(cs, rs);
  PVertex v{};
  v.clip[0] = x / 50.0f - 1.0f;
  v.clip[1] = y / 50.0f - 1.0f;
  v.clip[3] = 1.0f;
  v.attr[kTag] = static_cast<float>(tag);
  v.edgeflag = 1;
  v.clipmask = clip_code(cs, v.clip);
  if (v.clipmask == 0) to_window(v, cs.viewport);
  return v;
}

// n vertices on a circle, counter-clockwise: no three are collinear.
std::vector<PVertex> circle(const RasterState& rs, int n) {
  std::vector<PVertex> v;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * 3.14159265358979 * i / (n < 3 ? 3 : n);
    v.push_back(win_vertex(rs, static_cast<float>(50 + 40 * std::cos(a)),
                           static_cast<float>(50 + 40 * std::sin(a)), i));
  }
  return v;
}

// A zig-zag whose strip triangles and quad-strip quads are all counter-clockwise.
std::vector<PVertex> zigzag(const RasterState& rs, int n) {
  std::vector<PVertex> v;
  for (int i = 0; i < n; ++i)
    v.push_back(
        win_vertex(rs, 5.0f + 8.0f * static_cast<float>(i / 2), (i & 1) ? 10.0f : 40.0f, i));
  return v;
}

Recorder draw(const RasterState& rs, GLenum mode, const std::vector<PVertex>& v,
              const std::vector<uint32_t>* idx = nullptr) {
  DrawCall dc;
  dc.state = &rs;
  Recorder r;
  draw_primitives_to(r, dc, mode, v.data(), idx ? idx->data() : nullptr,
                     idx ? idx->size() : v.size());
  return r;
}

int tag(const PVertex* v) {
  return static_cast<int>(v->attr[kTag]);
}

TEST(Assemble, CountsForEveryMode) {
  const RasterState rs = make_state();
  for (int n = 0; n <= 13; ++n) {
    const std::vector<PVertex> v = circle(rs, n);
    EXPECT_EQ(draw(rs, GL_POINTS, v).points.size(), static_cast<size_t>(n));
    EXPECT_EQ(draw(rs, GL_LINES, v).lines.size(), static_cast<size_t>(n / 2));
    EXPECT_EQ(draw(rs, GL_LINE_STRIP, v).lines.size(), static_cast<size_t>(n >= 2 ? n - 1 : 0));
    EXPECT_EQ(draw(rs, GL_LINE_LOOP, v).lines.size(), static_cast<size_t>(n >= 2 ? n : 0));
    EXPECT_EQ(draw(rs, GL_TRIANGLES, v).tris.size(), static_cast<size_t>(n / 3));
    EXPECT_EQ(draw(rs, GL_TRIANGLE_STRIP, v).tris.size(), static_cast<size_t>(n >= 3 ? n - 2 : 0));
    EXPECT_EQ(draw(rs, GL_TRIANGLE_FAN, v).tris.size(), static_cast<size_t>(n >= 3 ? n - 2 : 0));
    EXPECT_EQ(draw(rs, GL_QUADS, v).tris.size(), static_cast<size_t>(2 * (n / 4)));
    EXPECT_EQ(draw(rs, GL_QUAD_STRIP, v).tris.size(),
              static_cast<size_t>(n >= 4 ? 2 * ((n - 2) / 2) : 0));
    EXPECT_EQ(draw(rs, GL_POLYGON, v).tris.size(), static_cast<size_t>(n >= 3 ? n - 2 : 0));
  }
  // Not a primitive mode: nothing.
  EXPECT_TRUE(draw(rs, GL_LINE, circle(rs, 6)).tris.empty());
}

// Table 2.12 (and §2.14.7 for lines), with vertices counted from zero.
TEST(Assemble, ProvokingVertex) {
  const RasterState rs = make_state();
  const std::vector<PVertex> v = circle(rs, 12);
  auto tri_prov = [&](GLenum mode) {
    std::vector<int> p;
    for (const auto& t : draw(rs, mode, v).tris) {
      // The provoking vertex is also the last one emitted, except in the first triangle of a
      // quad, which llvmpipe's split (q0 q1 q2, q0 q2 q3) leaves without q3.
      if (mode != GL_QUADS) {
        EXPECT_EQ(t.prov, t.c);
      }
      p.push_back(tag(t.prov));
    }
    return p;
  };
  EXPECT_EQ(tri_prov(GL_TRIANGLES), (std::vector<int>{2, 5, 8, 11}));
  EXPECT_EQ(tri_prov(GL_TRIANGLE_STRIP), (std::vector<int>{2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
  EXPECT_EQ(tri_prov(GL_TRIANGLE_FAN), (std::vector<int>{2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
  EXPECT_EQ(tri_prov(GL_QUADS), (std::vector<int>{3, 3, 7, 7, 11, 11}));
  EXPECT_EQ(tri_prov(GL_QUAD_STRIP), (std::vector<int>{3, 3, 5, 5, 7, 7, 9, 9, 11, 11}));
  EXPECT_EQ(tri_prov(GL_POLYGON), (std::vector<int>(10, 0)));

  auto line_prov = [&](GLenum mode) {
    std::vector<int> p;
    for (const auto& l : draw(rs, mode, v).lines) {
      EXPECT_EQ(l.prov, l.b); // the segment's second vertex
      p.push_back(tag(l.prov));
    }
    return p;
  };
  EXPECT_EQ(line_prov(GL_LINES), (std::vector<int>{1, 3, 5, 7, 9, 11}));
  EXPECT_EQ(line_prov(GL_LINE_STRIP), (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
  EXPECT_EQ(line_prov(GL_LINE_LOOP), (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 0}));
}

TEST(Assemble, TriangleVerticesPerMode) {
  const RasterState rs = make_state();
  const std::vector<PVertex> v = circle(rs, 6);
  auto tris = [&](GLenum mode) {
    std::vector<std::vector<int>> out;
    for (const auto& t : draw(rs, mode, v).tris)
      out.push_back({tag(t.a), tag(t.b), tag(t.c)});
    return out;
  };
  using T = std::vector<std::vector<int>>;
  EXPECT_EQ(tris(GL_TRIANGLE_STRIP), (T{{0, 1, 2}, {2, 1, 3}, {2, 3, 4}, {4, 3, 5}}));
  EXPECT_EQ(tris(GL_TRIANGLE_FAN), (T{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}}));
  // Quads split along q0-q2 (llvmpipe), quad strips along v2j-v2j+3, polygons fan around v0.
  EXPECT_EQ(tris(GL_QUADS), (T{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(tris(GL_QUAD_STRIP), (T{{2, 0, 3}, {0, 1, 3}, {4, 2, 5}, {2, 3, 5}}));
  EXPECT_EQ(tris(GL_POLYGON), (T{{1, 2, 0}, {2, 3, 0}, {3, 4, 0}, {4, 5, 0}}));
}

TEST(Assemble, StripsKeepTheirOrientation) {
  RasterState rs = make_state();
  rs.cull_enabled = true;
  rs.cull_face = GL_BACK;
  const std::vector<PVertex> z = zigzag(rs, 12);
  const Recorder strip = draw(rs, GL_TRIANGLE_STRIP, z);
  EXPECT_EQ(strip.tris.size(), 10u); // none culled: every triangle is front facing
  for (const auto& t : strip.tris)
    EXPECT_GT(fixed_area2(t.va, t.vb, t.vc), 0);
  const Recorder qs = draw(rs, GL_QUAD_STRIP, z);
  EXPECT_EQ(qs.tris.size(), 10u);
  for (const auto& t : qs.tris)
    EXPECT_GT(fixed_area2(t.va, t.vb, t.vc), 0);
  // The same strip backwards is entirely back facing.
  rs.front_face = GL_CW;
  EXPECT_TRUE(draw(rs, GL_TRIANGLE_STRIP, z).tris.empty());
  // A fan and a polygon on a counter-clockwise circle are front facing.
  rs.front_face = GL_CCW;
  EXPECT_EQ(draw(rs, GL_TRIANGLE_FAN, circle(rs, 8)).tris.size(), 6u);
  EXPECT_EQ(draw(rs, GL_POLYGON, circle(rs, 8)).tris.size(), 6u);
  EXPECT_EQ(draw(rs, GL_QUADS, circle(rs, 8)).tris.size(), 4u);
}

TEST(Assemble, IndexedMatchesDirect) {
  const RasterState rs = make_state();
  const std::vector<PVertex> v = circle(rs, 9);
  std::vector<PVertex> reversed(v.rbegin(), v.rend());
  std::vector<uint32_t> idx;
  for (int i = 8; i >= 0; --i)
    idx.push_back(static_cast<uint32_t>(i));
  for (const GLenum mode :
       {GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON}) {
    const Recorder a = draw(rs, mode, v, &idx);
    const Recorder b = draw(rs, mode, reversed);
    ASSERT_EQ(a.tris.size(), b.tris.size());
    for (size_t i = 0; i < a.tris.size(); ++i) {
      EXPECT_EQ(tag(a.tris[i].a), tag(b.tris[i].a));
      EXPECT_EQ(tag(a.tris[i].b), tag(b.tris[i].b));
      EXPECT_EQ(tag(a.tris[i].c), tag(b.tris[i].c));
      EXPECT_EQ(tag(a.tris[i].prov), tag(b.tris[i].prov));
    }
  }
  // Indices may repeat and skip vertices.
  const std::vector<uint32_t> lines = {0, 5, 5, 2, 7};
  const Recorder l = draw(rs, GL_LINES, v, &lines);
  ASSERT_EQ(l.lines.size(), 2u);
  EXPECT_EQ(l.lines[0].a, &v[0]);
  EXPECT_EQ(l.lines[0].b, &v[5]);
  EXPECT_EQ(l.lines[1].a, &v[5]);
  EXPECT_EQ(l.lines[1].b, &v[2]);
}

TEST(Assemble, ClipCodesFirst) {
  const RasterState rs = make_state();
  // Inside: the original vertices reach the sink (the clipper was skipped).
  const std::vector<PVertex> in = {win_vertex(rs, 10, 10, 0), win_vertex(rs, 50, 10, 1),
                                   win_vertex(rs, 10, 50, 2)};
  const Recorder r = draw(rs, GL_TRIANGLES, in);
  ASSERT_EQ(r.tris.size(), 1u);
  EXPECT_EQ(r.tris[0].a, &in[0]);
  EXPECT_EQ(r.tris[0].b, &in[1]);
  EXPECT_EQ(r.tris[0].c, &in[2]);
  // Entirely beyond one plane: rejected without clipping.
  const std::vector<PVertex> out = {win_vertex(rs, 110, 10, 0), win_vertex(rs, 150, 10, 1),
                                    win_vertex(rs, 120, 200, 2)};
  EXPECT_TRUE(draw(rs, GL_TRIANGLES, out).tris.empty());
  // Outside two different planes but not the frustum: the clipper finds nothing left.
  const std::vector<PVertex> corner = {win_vertex(rs, 110, 80, 0), win_vertex(rs, 130, 150, 1),
                                       win_vertex(rs, 160, 105, 2)};
  EXPECT_TRUE(draw(rs, GL_TRIANGLES, corner).tris.empty());
}

TEST(Assemble, ClippedPrimitivesKeepTheirProvokingVertex) {
  const RasterState rs = make_state();
  // The provoking (third) vertex is outside and gets clipped away.
  const std::vector<PVertex> v = {win_vertex(rs, 10, 10, 0), win_vertex(rs, 50, 10, 1),
                                  win_vertex(rs, 150, 150, 2)};
  const Recorder r = draw(rs, GL_TRIANGLES, v);
  ASSERT_FALSE(r.tris.empty());
  for (const auto& t : r.tris) {
    EXPECT_EQ(t.prov, &v[2]);
    for (const PVertex* p : {&t.va, &t.vb, &t.vc}) {
      EXPECT_GE(p->win[0], 0.0f);
      EXPECT_LE(p->win[0], 100.0f);
      EXPECT_LE(p->win[1], 100.0f);
    }
  }
  const std::vector<PVertex> seg = {v[0], v[2]};
  const Recorder l = draw(rs, GL_LINES, seg);
  ASSERT_EQ(l.lines.size(), 1u);
  EXPECT_EQ(l.lines[0].a, &seg[0]);
  EXPECT_NE(l.lines[0].b, &seg[1]);
  EXPECT_EQ(l.lines[0].prov, &seg[1]);
  EXPECT_FLOAT_EQ(l.lines[0].vb.win[0], 100.0f);
  // A line loop's closing segment: its second vertex is the first vertex.
  const std::vector<PVertex> loop_verts = {v[2], v[0], v[1]};
  const Recorder loop = draw(rs, GL_LINE_LOOP, loop_verts);
  ASSERT_EQ(loop.lines.size(), 3u);
  EXPECT_EQ(loop.lines[2].prov, &loop_verts[0]);
}

TEST(Assemble, PointsAreClippedByTheirCentre) {
  RasterState rs = make_state();
  const std::vector<PVertex> v = {win_vertex(rs, 10, 10, 0), win_vertex(rs, 100.5f, 10, 1),
                                  win_vertex(rs, 99.5f, 99.5f, 2), win_vertex(rs, 50, -1, 3)};
  const Recorder r = draw(rs, GL_POINTS, v);
  ASSERT_EQ(r.points.size(), 2u);
  EXPECT_EQ(r.points[0], &v[0]);
  EXPECT_EQ(r.points[1], &v[2]);
  // A user plane removes points on its outside.
  rs.user_clip_mask = 1;
  rs.user_planes[0][0] = 1.0f; // x >= 0: window x >= 50
  const std::vector<PVertex> u = {win_vertex(rs, 10, 10, 0), win_vertex(rs, 60, 10, 1)};
  const Recorder ru = draw(rs, GL_POINTS, u);
  ASSERT_EQ(ru.points.size(), 1u);
  EXPECT_EQ(ru.points[0], &u[1]);
}

} // namespace
} // namespace pineda

namespace pineda {
namespace {

// Regression: vertices beyond the guard band on different sides share the kClipGuard bit,
// which must not count as "all outside one plane" (conformance scene stress_huge_triangles).
TEST(Assemble, GuardBitAloneDoesNotRejectATriangle) {
  const RasterState rs = make_state();
  const float far = 1e6f;
  const std::vector<PVertex> v = {win_vertex(rs, -far, -far, 0), win_vertex(rs, far, -far, 1),
                                  win_vertex(rs, 50.0f, far, 2)};
  for (const PVertex& p : v)
    ASSERT_NE(p.clipmask & kClipGuard, 0u);
  const Recorder r = draw(rs, GL_TRIANGLES, v);
  ASSERT_FALSE(r.tris.empty());
  // What remains is the whole viewport, split into triangles.
  double area = 0;
  for (const auto& t : r.tris)
    area += 0.5 * std::fabs((t.vb.win[0] - t.va.win[0]) * (t.vc.win[1] - t.va.win[1]) -
                            (t.vc.win[0] - t.va.win[0]) * (t.vb.win[1] - t.va.win[1]));
  EXPECT_NEAR(area, 100.0 * 100.0, 1e-3);
  // A segment between two such vertices, through the viewport's diagonal, is drawn too.
  EXPECT_EQ(draw(rs, GL_LINES, {v[0], win_vertex(rs, far, far, 3)}).lines.size(), 1u);
}

} // namespace
} // namespace pineda
