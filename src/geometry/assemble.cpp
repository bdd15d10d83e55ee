// Primitive assembly (GL 2.1 §2.6.1): the ten Begin modes become points, segments and
// triangles; then clip codes, clipping (clip.cpp), facing, culling and polygon mode
// (cull.h), and the rasterizer.
//
// Quads, quad strips and polygons are split into triangles before clipping, exactly as Mesa
// splits them (same diagonals, same vertex order, interior edges flagged non-boundary): the
// split decides how a smooth-shaded quad's colours are interpolated, and clipping a triangle
// leaves its interpolation unchanged, so a quad shades the same whether or not it is clipped.
// Every emitted triangle lists its provoking vertex (GL 2.1 §2.14.7, Table 2.12) last.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "geometry/assemble.h"

#include "fragment/fragment_ops.h"
#include "geometry/clip.h"
#include "geometry/cull.h"
#include "raster/bin.h"
#include "raster/raster.h"
#include "raster/setup.h"

namespace pineda {

namespace {

// Edge bits of a triangle a, b, c: which of a->b, b->c, c->a are boundary edges (§2.6.2).
constexpr unsigned kEdgeAB = 1u, kEdgeBC = 2u, kEdgeCA = 4u;
constexpr unsigned kEdgeAll = 7u;

// Bits whose AND over a primitive's vertices proves it lies outside one plane. kClipGuard
// stands for four planes at once, so a shared guard bit proves nothing; the guard band
// encloses the frustum, so whatever is outside one guard plane is outside a frustum plane too.
constexpr uint32_t kClipRejectMask = ~static_cast<uint32_t>(kClipGuard);

inline unsigned flag_bit(const PVertex& v, unsigned bit) {
  return v.edgeflag ? bit : 0u;
}

// Production sink: straight to the rasterizer.
struct RasterSink {
  // A zero-area polygon in FILL mode covers no pixel: it is dropped before the rasterizer.
  static constexpr bool kKeepsZeroArea = false;
  const DrawCall& dc;
  void triangle(const PVertex& a, const PVertex& b, const PVertex& c, const PVertex& provoking,
                bool back) {
    raster_triangle(dc, a, b, c, provoking, back);
  }
  // The hot path: the positions come snapped from the facing test.
  void triangle_snapped(const SnappedTri& t, const PVertex& a, const PVertex& b, const PVertex& c,
                        const PVertex& provoking, bool back) {
    raster_triangle_snapped(dc, t, a, b, c, provoking, back);
  }
  void line(const PVertex& a, const PVertex& b, const PVertex& provoking, bool back) {
    raster_line(dc, a, b, provoking, back);
  }
  void point(const PVertex& p, bool back) { raster_point(dc, p, back); }
};

// Binned draws (raster/bin.h): setup into the calling thread's bins.
struct BinSink {
  static constexpr bool kKeepsZeroArea = false;
  const DrawCall& dc;
  TriBins& bins;
  void triangle(const PVertex& a, const PVertex& b, const PVertex& c, const PVertex& provoking,
                bool back) {
    bin_triangle(bins, dc, snap_triangle(a, b, c), a, b, c, provoking, back);
  }
  void triangle_snapped(const SnappedTri& t, const PVertex& a, const PVertex& b, const PVertex& c,
                        const PVertex& provoking, bool back) {
    bin_triangle(bins, dc, t, a, b, c, provoking, back);
  }
  // Only draws that fill both faces are binned (draw_primitives): no outline reaches here.
  void line(const PVertex&, const PVertex&, const PVertex&, bool) {
    assert(false && "binned draws have no lines");
  }
  void point(const PVertex&, bool) { assert(false && "binned draws have no points"); }
};

// The units a triangle mode's primitives are counted in, for splitting a draw among threads:
// triangles, or quads for QUADS and QUAD_STRIP (two triangles each). 0 for other modes.
size_t unit_count(GLenum mode, size_t count) {
  switch (mode) {
  case GL_TRIANGLES:
    return count / 3;
  case GL_TRIANGLE_STRIP:
  case GL_TRIANGLE_FAN:
  case GL_POLYGON:
    return count >= 3 ? count - 2 : 0;
  case GL_QUADS:
    return count / 4;
  case GL_QUAD_STRIP:
    return count >= 4 ? (count - 4) / 2 + 1 : 0;
  default:
    return 0;
  }
}

// Vertex fetch with and without an index list.
struct DirectFetch {
  const PVertex* v;
  const PVertex& operator()(size_t i) const { return v[i]; }
};
struct IndexedFetch {
  const PVertex* v;
  const uint32_t* idx;
  const PVertex& operator()(size_t i) const { return v[idx[i]]; }
};

template <class Sink> class Assembler {
public:
  Assembler(const DrawCall& dc, Sink& sink)
      : sink_(sink), stipple_counter_(dc.stipple_counter), state_(*dc.state), bands_(dc.bands) {
    const RasterState& rs = *dc.state;
    init_face_state(face_, rs);
    fill_fast_ = rs.polygon_mode[0] == GL_FILL && rs.polygon_mode[1] == GL_FILL && !rs.two_sided;
    outlined_ = rs.polygon_mode[0] != GL_FILL || rs.polygon_mode[1] != GL_FILL;
  }

  // Assembles primitives of `mode` from `count` vertices. In the triangle modes only the
  // units [lo, hi) are assembled (unit_count, for binned draws); points and lines are
  // assembled whole.
  template <class Fetch>
  void run(GLenum mode, const Fetch& f, size_t count, size_t lo = 0, size_t hi = SIZE_MAX);

private:
  void point(const PVertex& p) {
    // GL 2.1 §2.12: a point is passed iff it lies inside the clip volume. A clip code of zero
    // also keeps it inside the guard band with w > 0.
    if (p.clipmask == 0) sink_.point(p, false);
  }

  // Segment a-b; GL 2.1 §2.14.7: the second vertex provokes.
  void line(const PVertex& a, const PVertex& b) {
    if ((a.clipmask & b.clipmask & kClipRejectMask) != 0) return;
    if ((a.clipmask | b.clipmask) == 0) {
      sink_.line(a, b, b, false);
      return;
    }
    line_clipped(a, b);
  }

  // Triangle a, b, c with c provoking.
  [[gnu::always_inline]] void triangle(const PVertex& a, const PVertex& b, const PVertex& c,
                                       unsigned edges) {
    triangle(a, b, c, edges, c);
  }

  // Triangle a, b, c whose flat colour comes from `pv`. The all-inside FILL case is the hot
  // path: snap, area, cull, rasterize.
  [[gnu::always_inline]] void triangle(const PVertex& a, const PVertex& b, const PVertex& c,
                                       unsigned edges, const PVertex& pv) {
    if ((a.clipmask & b.clipmask & c.clipmask & kClipRejectMask) != 0) return;
    if ((a.clipmask | b.clipmask | c.clipmask) != 0) {
      triangle_clipped(a, b, c, edges, pv);
      return;
    }
    // A worker sharing the draw by bands (raster/schedule.cpp) skips at once the filled triangles
    // that lie outside its rows, whichever way they face: raster_triangle would draw nothing of
    // them.
    if (fill_fast_ && bands_.count > 1 && !rows_owned(a, b, c)) return;
    const SnappedTri t = snap_triangle(a, b, c);
    const int64_t area2 = snapped_area2(t);
    const bool back = is_back_facing(face_, area2);
    if (is_culled(face_, back)) return;
    if (fill_fast_) {
      if (area2 != 0 || Sink::kKeepsZeroArea) {
        if constexpr (requires { sink_.triangle_snapped(t, a, b, c, pv, back); })
          sink_.triangle_snapped(t, a, b, c, pv, back);
        else
          sink_.triangle(a, b, c, pv, back);
      }
      return;
    }
    const PVertex* v[3] = {&a, &b, &c};
    const bool e[3] = {(edges & kEdgeAB) != 0, (edges & kEdgeBC) != 0, (edges & kEdgeCA) != 0};
    // Mesa outlines an unclipped triangle starting with its closing edge c->a.
    emit_polygon(face_, sink_, v, e, 3, 2, pv, back, area2);
  }

  // Whether any pixel row a triangle of unclipped vertices may cover is this worker's: the
  // rows of its window y range, widened by one each way for the snapping.
  bool rows_owned(const PVertex& a, const PVertex& b, const PVertex& c) const {
    const float y0 = std::min({a.win[1], b.win[1], c.win[1]});
    const float y1 = std::max({a.win[1], b.win[1], c.win[1]});
    // Inside the guard band (clip code zero), so the conversions are in range.
    return bands_own_rows(bands_, static_cast<int>(y0) - 1, static_cast<int>(y1) + 1);
  }

  void line_clipped(const PVertex& a, const PVertex& b);
  void triangle_clipped(const PVertex& a, const PVertex& b, const PVertex& c, unsigned edges,
                        const PVertex& pv);

  // GL 2.1 §3.4.2: the stipple counter restarts with each independent segment and with each
  // strip or loop. Polygon outlines (LINE mode) restart it with every triangle, quad and
  // polygon, within strips and fans too, as Mesa does (measured against llvmpipe).
  void reset_stipple() {
    if (stipple_counter_ != nullptr) *stipple_counter_ = 0.0f;
  }
  void reset_stipple_outline() {
    if (outlined_) reset_stipple();
  }

  // The clipper's setup, made when the draw's first primitive needs clipping: a draw of one
  // unclipped triangle (immediate mode) does not pay for it.
  const ClipSetup& clip_setup() {
    if (!clip_ready_) {
      init_clip_setup(clip_, state_);
      clip_ready_ = true;
    }
    return clip_;
  }

  Sink& sink_;
  float* stipple_counter_ = nullptr;
  const RasterState& state_;
  Bands bands_;
  FaceState face_;
  ClipSetup clip_;
  bool clip_ready_ = false;
  // Both faces FILL and one-sided colours: an unclipped triangle needs no edge flags, no
  // colour swap and no fan, only the rasterizer call.
  bool fill_fast_ = true;
  // Some face is drawn in LINE or POINT mode (GL 2.1 §3.5.4).
  bool outlined_ = false;
};

template <class Sink>
[[gnu::noinline]] void Assembler<Sink>::line_clipped(const PVertex& a, const PVertex& b) {
  ClipScratch scratch;
  const PVertex* ca = nullptr;
  const PVertex* cb = nullptr;
  if (!clip_segment(clip_setup(), planes_for_mask(a.clipmask | b.clipmask), a, b, scratch, &ca,
                    &cb))
    return;
  // The original second vertex keeps supplying the flat colour.
  sink_.line(*ca, *cb, b, false);
}

template <class Sink>
[[gnu::noinline]] void Assembler<Sink>::triangle_clipped(const PVertex& a, const PVertex& b,
                                                         const PVertex& c, unsigned edges,
                                                         const PVertex& pv) {
  ClipScratch scratch;
  ClipPolygon poly;
  poly.n = 3;
  poly.v[0] = &a;
  poly.v[1] = &b;
  poly.v[2] = &c;
  poly.edge[0] = (edges & kEdgeAB) != 0;
  poly.edge[1] = (edges & kEdgeBC) != 0;
  poly.edge[2] = (edges & kEdgeCA) != 0;
  if (!clip_polygon(clip_setup(), planes_for_mask(a.clipmask | b.clipmask | c.clipmask), poly,
                    scratch))
    return;
  // Facing of what remains (GL 2.1 §3.5.1: facing is decided after clipping), from the same
  // snapped coordinates the rasterizer sees.
  const int64_t area2 = polygon_area2(poly.v, poly.n);
  const bool back = is_back_facing(face_, area2);
  if (is_culled(face_, back)) return;
  // The provoking vertex stays even when clipping removed it (GL 2.1 §2.14.7).
  emit_polygon(face_, sink_, poly.v, poly.edge, poly.n, 0, pv, back, area2);
}

template <class Sink>
template <class Fetch>
[[gnu::always_inline]] inline void Assembler<Sink>::run(GLenum mode, const Fetch& f, size_t count,
                                                        size_t lo, size_t hi) {
  hi = std::min(hi, unit_count(mode, count));
  switch (mode) {
  case GL_POINTS:
    for (size_t i = 0; i < count; ++i)
      point(f(i));
    break;
  case GL_LINES:
    for (size_t i = 0; i + 1 < count; i += 2) {
      reset_stipple();
      line(f(i), f(i + 1));
    }
    break;
  case GL_LINE_STRIP:
  case GL_LINE_LOOP:
    if (count < 2) break;
    reset_stipple();
    for (size_t i = 1; i < count; ++i)
      line(f(i - 1), f(i));
    // The closing segment runs from the last vertex to the first, which as its second
    // vertex provokes (GL 2.1 §2.14.7).
    if (mode == GL_LINE_LOOP) line(f(count - 1), f(0));
    break;
  case GL_TRIANGLES:
    // Table 2.12: vertex 3i provokes. Edge flags apply (§2.6.2).
    for (size_t u = lo; u < hi; ++u) {
      const size_t i = 3 * u;
      reset_stipple_outline();
      const PVertex& a = f(i);
      const PVertex& b = f(i + 1);
      const PVertex& c = f(i + 2);
      triangle(a, b, c, flag_bit(a, kEdgeAB) | flag_bit(b, kEdgeBC) | flag_bit(c, kEdgeCA));
    }
    break;
  case GL_TRIANGLE_STRIP:
    // §2.6.1: odd triangles are (A, B, current) with A and B swapped relative to the even
    // ones, which keeps the strip's orientation; vertex i+2 provokes (Table 2.12).
    for (size_t i = lo; i < hi; ++i) {
      reset_stipple_outline();
      if (i & 1)
        triangle(f(i + 1), f(i), f(i + 2), kEdgeAll);
      else
        triangle(f(i), f(i + 1), f(i + 2), kEdgeAll);
    }
    break;
  case GL_TRIANGLE_FAN:
    for (size_t i = lo; i < hi; ++i) {
      reset_stipple_outline();
      triangle(f(0), f(i + 1), f(i + 2), kEdgeAll);
    }
    break;
  case GL_QUADS:
    // Vertex 4i provokes (Table 2.12). Split as a fan from q0, along q0-q2, as llvmpipe does
    // (the conformance scene quad_split_colors pins it); the diagonal is not an edge.
    for (size_t u = lo; u < hi; ++u) {
      const size_t i = 4 * u;
      reset_stipple_outline();
      const PVertex& q0 = f(i);
      const PVertex& q1 = f(i + 1);
      const PVertex& q2 = f(i + 2);
      const PVertex& q3 = f(i + 3);
      if (!outlined_) {
        triangle(q0, q1, q2, flag_bit(q0, kEdgeAB) | flag_bit(q1, kEdgeBC), q3);
        triangle(q0, q2, q3, flag_bit(q2, kEdgeBC) | flag_bit(q3, kEdgeCA), q3);
      } else {
        // Outlined (LINE or POINT on some face), Mesa's draw module splits along q1-q3, so the
        // edges come in its order (which the line stipple counter shows): q3-q0, q0-q1, then
        // q1-q2, q2-q3.
        triangle(q0, q1, q3, flag_bit(q0, kEdgeAB) | flag_bit(q3, kEdgeCA), q3);
        triangle(q1, q2, q3, flag_bit(q1, kEdgeAB) | flag_bit(q2, kEdgeBC), q3);
      }
    }
    break;
  case GL_QUAD_STRIP:
    // Quad j is v2j, v2j+1, v2j+3, v2j+2 (§2.6.1); vertex 2j+3 (Table 2.12's 2i+2, counted
    // from one) provokes. Split along v2j-v2j+3 as Mesa does. Edge flags do not apply.
    for (size_t u = lo; u < hi; ++u) {
      const size_t i = 2 * u;
      const PVertex& v0 = f(i);
      const PVertex& v1 = f(i + 1);
      const PVertex& v2 = f(i + 2);
      const PVertex& v3 = f(i + 3);
      reset_stipple_outline(); // each quad restarts an outline's stipple, as in Mesa
      triangle(v2, v0, v3, kEdgeAB | kEdgeCA);
      triangle(v0, v1, v3, kEdgeAB | kEdgeBC);
    }
    break;
  case GL_POLYGON: {
    // Vertex 1 provokes (Table 2.12). Fan around v0, each triangle v(i+1), v(i+2), v0 so the
    // provoking vertex is last; only the polygon's own edges are boundary edges.
    if (count < 3) break;
    reset_stipple_outline();
    const PVertex& v0 = f(0);
    for (size_t i = lo; i < hi; ++i) {
      const PVertex& a = f(i + 1);
      const PVertex& b = f(i + 2);
      unsigned e = flag_bit(a, kEdgeAB);
      if (i + 3 == count) e |= flag_bit(b, kEdgeBC);
      if (i == 0) e |= flag_bit(v0, kEdgeCA);
      triangle(a, b, v0, e);
    }
    break;
  }
  default:
    break;
  }
}

template <class Sink>
[[gnu::noinline]] void assemble(Sink& sink, const DrawCall& dc, GLenum mode, const PVertex* verts,
                                const uint32_t* indices, size_t count) {
  if (verts == nullptr || count == 0 || dc.state == nullptr) return;
  Assembler<Sink> as(dc, sink);
  if (indices != nullptr)
    as.run(mode, IndexedFetch{verts, indices}, count);
  else
    as.run(mode, DirectFetch{verts}, count);
}

} // namespace

// A draw without the context's fragment setup (tests calling the back end directly): made
// here, out of the line of the common path, whose FragCtx would otherwise be built per draw.
[[gnu::noinline]] static void draw_with_local_frag(const DrawCall& dc, GLenum mode,
                                                   const PVertex* verts, const uint32_t* indices,
                                                   size_t count) {
  FragCtx local;
  prepare_fragments(*dc.state, *dc.fb, local);
  DrawCall with = dc;
  with.frag = &local;
  draw_primitives(with, mode, verts, indices, count);
}

void draw_primitives(const DrawCall& dc, GLenum mode, const PVertex* verts, const uint32_t* indices,
                     size_t count) {
  // The fragment stage is set up once for the whole draw, not once per primitive, or comes
  // with the draw (the draw home's cache).
  if (dc.frag == nullptr) return draw_with_local_frag(dc, mode, verts, indices, count);
  const FragCtx* frag = dc.frag;
  frag->samples_passed = 0;
  DrawCall prepared = dc;
  float stipple_counter = 0.0f;
  prepared.stipple_counter = &stipple_counter;
  RasterSink sink{prepared};
  assemble(sink, prepared, mode, verts, indices, count);
  if (dc.samples_passed != nullptr) *dc.samples_passed += frag->samples_passed;
}

size_t primitive_units(GLenum mode, size_t count) {
  return unit_count(mode, count);
}

void assemble_to_bins(TriBins& bins, const DrawCall& dc, GLenum mode, const PVertex* verts,
                      const uint32_t* indices, size_t count, size_t lo, size_t hi) {
  BinSink sink{dc, bins};
  Assembler<BinSink> as(dc, sink);
  if (indices != nullptr)
    as.run(mode, IndexedFetch{verts, indices}, count, lo, hi);
  else
    as.run(mode, DirectFetch{verts}, count, lo, hi);
}

void draw_primitives_to(PrimitiveSink& sink, const DrawCall& dc, GLenum mode, const PVertex* verts,
                        const uint32_t* indices, size_t count) {
  assemble(sink, dc, mode, verts, indices, count);
}

} // namespace pineda
