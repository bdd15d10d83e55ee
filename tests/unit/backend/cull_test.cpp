// Facing, culling, polygon mode, edge flags and two-sided colours (GL 2.1 §3.5.1, §3.5.4,
// §2.6.2, §2.14.1), through the assembler with a recording sink instead of the rasterizer.
#include <gtest/gtest.h>

#include <vector>

#include "geometry/assemble.h"
#include "geometry/clip.h"
#include "geometry/cull.h"

namespace pineda {
namespace {

// Attribute slot holding the vertex's index, for identification: past the colours, which
// flat shading and two-sided lighting overwrite.
constexpr int kTag = kAttrTex0;

struct Recorder : PrimitiveSink {
  struct Tri {
    PVertex a, b, c, prov;
    bool back;
  };
  struct Seg {
    PVertex a, b, prov;
  };
  std::vector<Tri> tris;
  std::vector<Seg> lines;
  std::vector<PVertex> points;
  void triangle(const PVertex& a, const PVertex& b, const PVertex& c, const PVertex& prov,
                bool back) override {
    tris.push_back({a, b, c, prov, back});
  }
  void line(const PVertex& a, const PVertex& b, const PVertex& prov, bool) override {
    lines.push_back({a, b, prov});
  }
  void point(const PVertex& p, bool) override { points.push_back(p); }
};

RasterState make_state() {
  RasterState rs;
  rs.viewport.w = 100;
  rs.viewport.h = 100;
  rs.attr_count = kAttrTex0 + 4;
  return rs;
}

// A vertex at window position (x, y) of the 100x100 viewport, w = 1; window coordinates
// outside the viewport give clip coordinates outside the frustum.
PVertex win_vertex(const RasterState& rs, float x, float y, int tag, bool edge = true) {
  ClipSetup cs;
  init_clip_setup(cs, rs);
  PVertex v{};
  v.clip[0] = x / 50.0f - 1.0f;
  v.clip[1] = y / 50.0f - 1.0f;
  v.clip[2] = 0.0f;
  v.clip[3] = 1.0f;
  for (int k = 0; k < 4; ++k) {
    v.attr[kAttrColor + k] = 0.1f * static_cast<float>(tag + 1);         // front colour
    v.attr[kAttrBackColor + k] = 0.5f + 0.01f * static_cast<float>(tag); // back colour
  }
  v.attr[kTag] = static_cast<float>(tag);
  v.edgeflag = edge ? 1 : 0;
  v.clipmask = clip_code(cs, v.clip);
  if (v.clipmask == 0) to_window(v, cs.viewport);
  return v;
}

Recorder draw(const RasterState& rs, GLenum mode, const std::vector<PVertex>& v) {
  DrawCall dc;
  dc.state = &rs;
  Recorder r;
  draw_primitives_to(r, dc, mode, v.data(), nullptr, v.size());
  return r;
}

int tag(const PVertex& v) {
  return static_cast<int>(v.attr[kTag]);
}

TEST(Cull, AreaSign) {
  const RasterState rs = make_state();
  const PVertex a = win_vertex(rs, 10, 10, 0), b = win_vertex(rs, 50, 10, 1),
                c = win_vertex(rs, 10, 50, 2);
  const PVertex* v[3] = {&a, &b, &c};
  EXPECT_GT(polygon_area2(v, 3), 0); // counter-clockwise in GL's window space
  EXPECT_EQ(polygon_area2(v, 3), fixed_area2(a, b, c));
  const PVertex* w[3] = {&a, &c, &b};
  EXPECT_EQ(polygon_area2(w, 3), -fixed_area2(a, b, c));
}

TEST(Cull, EveryFrontFaceAndCullFaceCombination) {
  for (const bool clipped : {false, true}) {
    for (const GLenum front : {GL_CCW, GL_CW}) {
      for (const GLenum cull : {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK}) {
        for (const bool enabled : {false, true}) {
          for (const bool ccw : {true, false}) {
            RasterState rs = make_state();
            rs.front_face = front;
            rs.cull_face = cull;
            rs.cull_enabled = enabled;
            // The clipped variant reaches past the right edge of the viewport.
            const float far_x = clipped ? 180.0f : 50.0f;
            PVertex a = win_vertex(rs, 10, 10, 0), b = win_vertex(rs, far_x, 10, 1),
                    c = win_vertex(rs, 10, 50, 2);
            const std::vector<PVertex> v =
                ccw ? std::vector<PVertex>{a, b, c} : std::vector<PVertex>{a, c, b};
            const Recorder r = draw(rs, GL_TRIANGLES, v);
            const bool front_facing = ccw == (front == GL_CCW);
            const bool culled = enabled && (front_facing ? cull != GL_BACK : cull != GL_FRONT);
            ASSERT_EQ(r.tris.empty(), culled)
                << clipped << " " << front << " " << cull << " " << enabled << " " << ccw;
            const size_t expect = culled ? 0u : (clipped ? 2u : 1u);
            ASSERT_EQ(r.tris.size(), expect);
            for (const auto& t : r.tris) {
              EXPECT_EQ(t.back, !front_facing);
              // The fan keeps the input's winding.
              EXPECT_EQ(fixed_area2(t.a, t.b, t.c) > 0, ccw);
              EXPECT_EQ(tag(t.prov), ccw ? 2 : 1);
            }
          }
        }
      }
    }
  }
}

TEST(Cull, ZeroAreaIsBackFacing) {
  for (const GLenum front : {GL_CCW, GL_CW}) {
    RasterState rs = make_state();
    rs.front_face = front;
    const std::vector<PVertex> v = {win_vertex(rs, 10, 10, 0), win_vertex(rs, 20, 20, 1),
                                    win_vertex(rs, 30, 30, 2)};
    // FILL: covers nothing. The rasterizer's sink drops it at compile time
    // (RasterSink::kKeepsZeroArea); this sink, the one of selection and feedback, receives it
    // (GL 2.1 §5.2, §5.3), as llvmpipe reports it.
    EXPECT_EQ(draw(rs, GL_TRIANGLES, v).tris.size(), 1u);
    // LINE: a back-facing polygon still outlines...
    rs.polygon_mode[0] = GL_FILL;
    rs.polygon_mode[1] = GL_LINE;
    EXPECT_EQ(draw(rs, GL_TRIANGLES, v).lines.size(), 3u);
    // ...unless back faces are culled.
    rs.cull_enabled = true;
    rs.cull_face = GL_BACK;
    EXPECT_TRUE(draw(rs, GL_TRIANGLES, v).lines.empty());
    rs.polygon_mode[1] = GL_FILL;
    EXPECT_TRUE(draw(rs, GL_TRIANGLES, v).tris.empty());
    rs.polygon_mode[1] = GL_LINE;
    rs.cull_face = GL_FRONT;
    EXPECT_EQ(draw(rs, GL_TRIANGLES, v).lines.size(), 3u);
  }
}

TEST(Cull, PolygonModePerFace) {
  RasterState rs = make_state();
  rs.polygon_mode[0] = GL_LINE;  // front
  rs.polygon_mode[1] = GL_POINT; // back
  const PVertex a = win_vertex(rs, 10, 10, 0), b = win_vertex(rs, 50, 10, 1),
                c = win_vertex(rs, 10, 50, 2);
  Recorder r = draw(rs, GL_TRIANGLES, {a, b, c});
  EXPECT_EQ(r.lines.size(), 3u);
  EXPECT_TRUE(r.points.empty());
  EXPECT_TRUE(r.tris.empty());
  r = draw(rs, GL_TRIANGLES, {a, c, b});
  EXPECT_TRUE(r.lines.empty());
  EXPECT_EQ(r.points.size(), 3u);
}

TEST(Cull, LineModeEdgeFlagsTriangles) {
  RasterState rs = make_state();
  rs.polygon_mode[0] = rs.polygon_mode[1] = GL_LINE;
  // a->b boundary, b->c not, c->a boundary.
  const PVertex a = win_vertex(rs, 10, 10, 0, true), b = win_vertex(rs, 50, 10, 1, false),
                c = win_vertex(rs, 10, 50, 2, true);
  const Recorder r = draw(rs, GL_TRIANGLES, {a, b, c});
  ASSERT_EQ(r.lines.size(), 2u);
  // Mesa's order for an unclipped triangle: c->a first, then a->b.
  EXPECT_EQ(tag(r.lines[0].a), 2);
  EXPECT_EQ(tag(r.lines[0].b), 0);
  EXPECT_EQ(tag(r.lines[1].a), 0);
  EXPECT_EQ(tag(r.lines[1].b), 1);
  // Flat shading colours come from the polygon's provoking vertex (the third).
  for (const auto& l : r.lines)
    EXPECT_EQ(tag(l.prov), 2);

  rs.polygon_mode[0] = rs.polygon_mode[1] = GL_POINT;
  rs.flat = true;
  const Recorder p = draw(rs, GL_TRIANGLES, {a, b, c});
  ASSERT_EQ(p.points.size(), 2u); // the vertices that start a boundary edge: a and c
  EXPECT_EQ(tag(p.points[0]), 0);
  EXPECT_EQ(tag(p.points[1]), 2);
  for (const auto& pt : p.points)
    EXPECT_FLOAT_EQ(pt.attr[kAttrColor], c.attr[kAttrColor]);
}

TEST(Cull, LineModeQuadsPolygonsAndStrips) {
  RasterState rs = make_state();
  rs.polygon_mode[0] = rs.polygon_mode[1] = GL_LINE;
  const std::vector<PVertex> quad = {win_vertex(rs, 10, 10, 0), win_vertex(rs, 40, 10, 1),
                                     win_vertex(rs, 40, 40, 2), win_vertex(rs, 10, 40, 3)};
  // A quad outlines its four edges and not the diagonal it is split along.
  Recorder r = draw(rs, GL_QUADS, quad);
  ASSERT_EQ(r.lines.size(), 4u);
  for (const auto& l : r.lines)
    EXPECT_EQ((tag(l.a) + 1) % 4, tag(l.b));
  for (const auto& l : r.lines)
    EXPECT_EQ(tag(l.prov), 3);

  // A polygon with the edge from vertex 2 switched off.
  std::vector<PVertex> poly = {win_vertex(rs, 10, 10, 0), win_vertex(rs, 40, 5, 1),
                               win_vertex(rs, 60, 30, 2, false), win_vertex(rs, 40, 60, 3),
                               win_vertex(rs, 10, 40, 4)};
  r = draw(rs, GL_POLYGON, poly);
  ASSERT_EQ(r.lines.size(), 4u);
  for (const auto& l : r.lines) {
    EXPECT_EQ((tag(l.a) + 1) % 5, tag(l.b));
    EXPECT_NE(tag(l.a), 2);
    EXPECT_EQ(tag(l.prov), 0);
  }

  // Edge flags do not apply to strips, fans and quad strips (GL 2.1 §2.6.2).
  std::vector<PVertex> strip;
  for (int i = 0; i < 4; ++i)
    strip.push_back(win_vertex(rs, 10.0f + 10.0f * static_cast<float>(i / 2),
                               (i & 1) ? 10.0f : 40.0f, i, false));
  EXPECT_EQ(draw(rs, GL_TRIANGLE_STRIP, strip).lines.size(), 6u);
  EXPECT_EQ(draw(rs, GL_QUAD_STRIP, strip).lines.size(), 4u);
}

TEST(Cull, LineModeClippedEdges) {
  RasterState rs = make_state();
  rs.polygon_mode[0] = rs.polygon_mode[1] = GL_LINE;
  // b is beyond the right edge: the clipped polygon has four vertices; the edge along the
  // frustum plane is not a boundary edge (Mesa), so three lines are drawn.
  const PVertex a = win_vertex(rs, 10, 10, 0), b = win_vertex(rs, 180, 30, 1),
                c = win_vertex(rs, 10, 50, 2);
  Recorder r = draw(rs, GL_TRIANGLES, {a, b, c});
  ASSERT_EQ(r.lines.size(), 3u);
  for (const auto& l : r.lines) {
    EXPECT_FALSE(l.a.win[0] == 100.0f && l.b.win[0] == 100.0f);
    EXPECT_EQ(tag(l.prov), 2);
  }
  // Against a user plane (x <= 0.6 w, window x <= 80) the new edge is a boundary edge.
  rs.user_clip_mask = 1;
  rs.user_planes[0][0] = -1.0f;
  rs.user_planes[0][3] = 0.6f;
  const PVertex a2 = win_vertex(rs, 10, 10, 0), b2 = win_vertex(rs, 95, 30, 1),
                c2 = win_vertex(rs, 10, 50, 2);
  r = draw(rs, GL_TRIANGLES, {a2, b2, c2});
  EXPECT_EQ(r.lines.size(), 4u);
}

TEST(Cull, TwoSidedColours) {
  RasterState rs = make_state();
  rs.two_sided = true;
  const PVertex a = win_vertex(rs, 10, 10, 0), b = win_vertex(rs, 50, 10, 1),
                c = win_vertex(rs, 10, 50, 2);
  // Front facing: front colours.
  Recorder r = draw(rs, GL_TRIANGLES, {a, b, c});
  ASSERT_EQ(r.tris.size(), 1u);
  EXPECT_FALSE(r.tris[0].back);
  EXPECT_FLOAT_EQ(r.tris[0].a.attr[kAttrColor], a.attr[kAttrColor]);
  // Back facing: back colours, also in the provoking vertex used for flat shading.
  r = draw(rs, GL_TRIANGLES, {a, c, b});
  ASSERT_EQ(r.tris.size(), 1u);
  EXPECT_TRUE(r.tris[0].back);
  EXPECT_FLOAT_EQ(r.tris[0].a.attr[kAttrColor], a.attr[kAttrBackColor]);
  EXPECT_FLOAT_EQ(r.tris[0].b.attr[kAttrColor + 3], c.attr[kAttrBackColor + 3]);
  EXPECT_FLOAT_EQ(r.tris[0].prov.attr[kAttrColor], b.attr[kAttrBackColor]);
  // Clipped and back facing: the interpolated back colours.
  const PVertex far_b = win_vertex(rs, 180, 10, 1);
  r = draw(rs, GL_TRIANGLES, {a, c, far_b});
  ASSERT_EQ(r.tris.size(), 2u);
  for (const auto& t : r.tris) {
    EXPECT_TRUE(t.back);
    for (const PVertex* v : {&t.a, &t.b, &t.c}) {
      EXPECT_GE(v->attr[kAttrColor], 0.5f); // between the back colours 0.50 .. 0.52
      EXPECT_LE(v->attr[kAttrColor], 0.52f + 1e-6f);
    }
    EXPECT_FLOAT_EQ(t.prov.attr[kAttrColor], far_b.attr[kAttrBackColor]);
  }
}

} // namespace
} // namespace pineda
