// The draw path in SELECT and FEEDBACK mode (GL 2.1 §5.2, §5.3): the same assembly,
// clipping, culling and polygon-mode interpretation as a rendered draw (geometry/assemble.cpp,
// clip.cpp, cull.h), with sinks that record selection hits or write feedback values instead
// of rasterizing, into the records the state layer handed down (draw.h RenderRecords).
#include <algorithm>
#include <initializer_list>

#include "draw/feedback.h"
#include "geometry/assemble.h"
#include "geometry/cull.h"

namespace pineda {

namespace {

// GL 2.1 §5.2: every primitive that survives clipping (and, for polygons, culling) is a hit;
// its depth range is that of its post-clipping vertices.
class SelectSink final : public PrimitiveSink {
public:
  explicit SelectSink(RenderRecords& records) : records_(records) {}
  void triangle(const PVertex& a, const PVertex& b, const PVertex& c, const PVertex&,
                bool) override {
    const float zmin = std::min({a.win[2], b.win[2], c.win[2]});
    const float zmax = std::max({a.win[2], b.win[2], c.win[2]});
    records_.hit(zmin, zmax);
  }
  void line(const PVertex& a, const PVertex& b, const PVertex&, bool) override {
    records_.hit(std::min(a.win[2], b.win[2]), std::max(a.win[2], b.win[2]));
  }
  void point(const PVertex& p, bool) override { records_.hit(p.win[2], p.win[2]); }

private:
  RenderRecords& records_;
};

// GL 2.1 §5.3, Figure 5.2: POINT_TOKEN vertex, LINE_TOKEN or LINE_RESET_TOKEN and two
// vertices, POLYGON_TOKEN n and n vertices. Under flat shading every vertex reports the
// provoking vertex's colour (§2.14.7 comes before clipping, whose results feedback returns).
class FeedbackSink final : public PrimitiveSink {
public:
  FeedbackSink(RenderRecords& records, bool flat) : records_(records), flat_(flat) {}

  // The next line segment starts with a reset line stipple counter (GL 2.1 §3.4.2, §3.5.4).
  void reset_stipple() { reset_ = true; }

  void triangle(const PVertex& a, const PVertex& b, const PVertex& c, const PVertex& pv,
                bool) override {
    records_.value(static_cast<float>(GL_POLYGON_TOKEN));
    records_.value(3.0f);
    vertex(a, pv);
    vertex(b, pv);
    vertex(c, pv);
  }
  void line(const PVertex& a, const PVertex& b, const PVertex& pv, bool) override {
    records_.value(static_cast<float>(reset_ ? GL_LINE_RESET_TOKEN : GL_LINE_TOKEN));
    reset_ = false;
    vertex(a, pv);
    vertex(b, pv);
  }
  void point(const PVertex& p, bool) override {
    records_.value(static_cast<float>(GL_POINT_TOKEN));
    vertex(p, p);
  }

private:
  // Window x, y, z, clip w (§5.3: "if w is returned, it is in clip coordinates"), the primary
  // colour and the unit 0 texture coordinates.
  void vertex(const PVertex& v, const PVertex& pv) {
    const float* color = (flat_ ? pv : v).attr + kAttrColor;
    records_.vertex(v.win, v.clip[3], color, v.attr + kAttrTex0);
  }

  RenderRecords& records_;
  bool flat_;
  bool reset_ = false;
};

// Feeds the primitives of a draw to the feedback sink one GL primitive at a time, so that the
// sink knows where the line stipple counter restarts: at Begin (the first segment of a strip
// or loop), before every independent segment, and at the first edge of each polygon drawn in
// LINE mode (GL 2.1 §3.4.2, §3.5.4). Each piece goes through the ordinary assembler with an
// index list naming the primitive's vertices in the order the whole draw would use.
void feedback_primitives(FeedbackSink& sink, const DrawCall& dc, GLenum mode, const PVertex* v,
                         const uint32_t* indices, size_t count) {
  const auto at = [indices](size_t i) {
    return indices != nullptr ? indices[i] : static_cast<uint32_t>(i);
  };
  const auto piece = [&](GLenum m, std::initializer_list<size_t> pos) {
    uint32_t idx[4];
    size_t k = 0;
    for (const size_t p : pos)
      idx[k++] = at(p);
    sink.reset_stipple();
    draw_primitives_to(sink, dc, m, v, idx, k);
  };
  switch (mode) {
  case GL_LINES:
    for (size_t i = 0; i + 1 < count; i += 2)
      piece(GL_LINES, {i, i + 1});
    break;
  case GL_TRIANGLES:
    for (size_t i = 0; i + 2 < count; i += 3)
      piece(GL_TRIANGLES, {i, i + 1, i + 2});
    break;
  case GL_TRIANGLE_STRIP:
    // The strip's odd triangles are (i+1, i, i+2) (assemble.cpp); as the first triangle of a
    // strip of three they keep that order and the strip's edge handling.
    for (size_t i = 0; i + 2 < count; ++i) {
      if (i & 1)
        piece(GL_TRIANGLE_STRIP, {i + 1, i, i + 2});
      else
        piece(GL_TRIANGLE_STRIP, {i, i + 1, i + 2});
    }
    break;
  case GL_TRIANGLE_FAN:
    for (size_t i = 0; i + 2 < count; ++i)
      piece(GL_TRIANGLE_FAN, {0, i + 1, i + 2});
    break;
  case GL_QUADS:
    // As the polygon q3 q0 q1 q2: the triangles (q0, q1, q3) and (q1, q2, q3), with the
    // quad's own edge flags, q3 provoking and LINE mode walking q3q0, q0q1, q1q2, q2q3, which
    // is how Mesa's feedback reports quads (its rasterizer splits them the other way, which
    // draws follow: assemble.cpp).
    for (size_t i = 0; i + 3 < count; i += 4)
      piece(GL_POLYGON, {i + 3, i, i + 1, i + 2});
    break;
  case GL_QUAD_STRIP:
    for (size_t i = 0; i + 3 < count; i += 2)
      piece(GL_QUAD_STRIP, {i, i + 1, i + 2, i + 3});
    break;
  default: // points, line strips and loops, polygons: one Begin, one primitive
    sink.reset_stipple();
    draw_primitives_to(sink, dc, mode, v, indices, count);
    break;
  }
}

} // namespace

void select_feedback_draw(const DrawInput& in, const DrawSources& src, PVertex* verts) {
  RenderRecords& records = *in.records;
  RasterState rs = *src.raster;
  DrawCall dc;
  dc.state = &rs;
  dc.fb = src.fb;
  if (records.selecting()) {
    // §5.2: selection is based on the polygon itself, whatever the polygon mode.
    rs.polygon_mode[0] = rs.polygon_mode[1] = GL_FILL;
    SelectSink sink(records);
    draw_primitives_to(sink, dc, in.mode, verts, in.indices, in.count);
    return;
  }
  constexpr int kTexEnd = kAttrTex0 + 4;
  if (in.vertex_program != nullptr) {
    // GL 2.1 §2.20.2, §5.3: the shader's outputs are the processed vertex (its stage kept the
    // primary colour and unit 0's coordinates for feedback); the outputs it does not write
    // report the current values.
    for (size_t i = 0; i < in.n; ++i) {
      if (in.feedback_color != nullptr)
        std::copy(in.feedback_color, in.feedback_color + 4, verts[i].attr + kAttrColor);
      if (in.feedback_tex != nullptr)
        std::copy(in.feedback_tex, in.feedback_tex + 4, verts[i].attr + kAttrTex0);
    }
    rs.attr_count = std::max(rs.attr_count, kTexEnd);
  } else if (records.textured() && rs.attr_count < kTexEnd) {
    // Unit 0's coordinates are not live in this draw (texturing is off): compute them here,
    // through the texture matrix (GL 2.1 §2.11.4), for feedback to report.
    const glm::mat4& tm = *in.texture0;
    for (size_t i = 0; i < in.n; ++i) {
      const float* t = in.in[i].tex[0];
      for (int r = 0; r < 4; ++r)
        verts[i].attr[kAttrTex0 + r] =
            tm[0][r] * t[0] + tm[1][r] * t[1] + tm[2][r] * t[2] + tm[3][r] * t[3];
    }
    rs.attr_count = kTexEnd; // clipping interpolates them (§2.14.8)
  }
  FeedbackSink sink(records, rs.flat);
  feedback_primitives(sink, dc, in.mode, verts, in.indices, in.count);
}

} // namespace pineda
