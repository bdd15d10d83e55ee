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
  void line(const PVertex& a, const PVertex& b, const PVertex& provoking) {
    raster_line(dc, a, b, provoking);
  }
  void point(const PVertex& p) { raster_point(dc, p); }
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
  void line(const PVertex&, const PVertex&, const PVertex&) {
    assert(false && "binned draws have no lines");
  }
  void point(const PVertex&) { assert(false && "binned draws have no points"); }
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
    if (p.clipmask == 0) sink_.point(p);
  }

  // Segment a-b; GL 2.1 §2.14.7: the second vertex provokes.
  void line(const PVertex& a, const PVertex& b) {
    if ((a.clipmask & b.clipmask & kClipRejectMask) != 0) return;
    if ((a.clipmask | b.clipmask) == 0) {
      sink_.line(a, b, b);
      return;
    }
    line_clipped(a, b);
  }

  // Triangle a, b, c with c provoking.
  void triangle(const PVertex& a, const PVertex& b, const PVertex& c, unsigned edges) {
    triangle(a, b, c, edges, c);
  }

  // Triangle a, b, c whose flat colour comes from `pv`. The all-inside FILL case is the hot
  // path: snap, area, cull, rasterize.
  void triangle(const PVertex& a, const PVertex& b, const PVertex& c, unsigned edges,
                const PVertex& pv) {
    if ((a.clipmask & b.clipmask & c.clipmask & kClipRejectMask) != 0) return;
    if ((a.clipmask | b.clipmask | c.clipmask) != 0) {
      triangle_clipped(a, b, c, edges, pv);
      return;
    }
    // A worker sharing the draw (draw_shared) skips at once the filled triangles that lie
    // outside its rows, whichever way they face: raster_triangle would draw nothing of them.
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
  sink_.line(*ca, *cb, b);
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
void Assembler<Sink>::run(GLenum mode, const Fetch& f, size_t count, size_t lo, size_t hi) {
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
void assemble(Sink& sink, const DrawCall& dc, GLenum mode, const PVertex* verts,
              const uint32_t* indices, size_t count) {
  if (verts == nullptr || count == 0 || dc.state == nullptr) return;
  Assembler<Sink> as(dc, sink);
  if (indices != nullptr)
    as.run(mode, IndexedFetch{verts, indices}, count);
  else
    as.run(mode, DirectFetch{verts}, count);
}

// Sharing a draw among the worker threads (raster/workers.h) costs each worker the assembly
// and setup of every primitive and the caller a wake-up and a wait, some microseconds: only
// draws with many vertices or a large window area are shared. One triangle per Begin/End
// (immediate mode) stays on the calling thread.
constexpr size_t kShareVertices = 1024;
constexpr int64_t kShareArea = 32768; // pixels of the draw's window bounding box

bool worth_sharing(const RasterState& rs, const FragCtx& frag, GLenum mode, const PVertex* verts,
                   const uint32_t* indices, size_t count) {
  if (count >= kShareVertices) return true;
  const RasterModes& m = rs.modes;
  // Lines and points cover little of their bounding box unless wide or smooth.
  float pad = 1.0f;
  if (mode == GL_POINTS) {
    if (!m.point_smooth && (m.point_attenuated ? m.point_size_max : m.point_size) <= 2.0f)
      return false;
    pad += 0.5f * (m.point_attenuated ? m.point_size_max : m.point_size) + 1.0f;
  } else if (mode == GL_LINES || mode == GL_LINE_STRIP || mode == GL_LINE_LOOP) {
    if (!m.line_smooth && m.line_width < 2.5f) return false;
    pad += 0.5f * m.line_width + 1.0f;
  }
  // The window bounding box of the vertices, clamped to the clip rectangle. A vertex outside
  // the clip volume has no window position yet: its clip coordinates are projected here, and
  // one with w <= 0 (whose primitives may reach anywhere) stands for the whole rectangle.
  const Viewport& vp = rs.viewport;
  const float cx0 = static_cast<float>(frag.clip_x0), cx1 = static_cast<float>(frag.clip_x1) + 1;
  const float cy0 = static_cast<float>(frag.clip_y0), cy1 = static_cast<float>(frag.clip_y1) + 1;
  float x0 = cx1, y0 = cy1, x1 = cx0, y1 = cy0;
  for (size_t i = 0; i < count; ++i) {
    const PVertex& v = verts[indices != nullptr ? indices[i] : i];
    float x = v.win[0], y = v.win[1];
    if (v.clipmask != 0) {
      const float w = v.clip[3];
      x = vp.x + (v.clip[0] / w + 1.0f) * 0.5f * vp.w;
      y = vp.y + (v.clip[1] / w + 1.0f) * 0.5f * vp.h;
      if (!(w > 0.0f) || !std::isfinite(x) || !std::isfinite(y)) {
        x0 = cx0, y0 = cy0, x1 = cx1, y1 = cy1;
        break;
      }
    }
    x0 = std::min(x0, x - pad);
    x1 = std::max(x1, x + pad);
    y0 = std::min(y0, y - pad);
    y1 = std::max(y1, y + pad);
  }
  x0 = std::max(x0, cx0), x1 = std::min(x1, cx1);
  y0 = std::max(y0, cy0), y1 = std::min(y1, cy1);
  if (!(x1 > x0 && y1 > y0)) return false;
  const int64_t w = static_cast<int64_t>(x1 - x0), h = static_cast<int64_t>(y1 - y0);
  return w > 0 && h > 0 && w * h >= kShareArea;
}

// Runs the draw on `n` threads: each assembles every primitive in order (with its own
// fragment context, stipple counter and sample count) and rasterizes its bands' rows only.
void draw_shared(const DrawCall& dc, const FragCtx& frag, int n, GLenum mode, const PVertex* verts,
                 const uint32_t* indices, size_t count) {
  uint64_t samples[kMaxRasterThreads] = {};
  auto job = [&](int i) {
    FragCtx local = frag;
    DrawCall share = dc;
    share.frag = &local;
    float stipple_counter = 0.0f;
    share.stipple_counter = &stipple_counter;
    share.bands = Bands{n, i};
    RasterSink sink{share};
    assemble(sink, share, mode, verts, indices, count);
    samples[i] = local.samples_passed;
  };
  dc.workers->run(job);
  if (dc.samples_passed != nullptr)
    for (int i = 0; i < n; ++i)
      *dc.samples_passed += samples[i];
}

// Triangles each thread sets up per batch (bin.h). Measured on bench_lit_mesh at two threads:
// 1024 per batch 16.5 ms, 4096 15.5 ms, 16384 14.1 ms: fewer barriers matter more than records
// that stay in the cache.
constexpr size_t kBatchTriangles = 16384;
// Draws of at most this many units are set up by the calling thread alone before the workers
// are woken: a full-screen quad would otherwise wait for a worker to wake up and set it up.
constexpr size_t kCallerSetupUnits = 32;

// Runs a draw of filled triangles on `n` threads in batches of two phases (bin.h): setup into
// each thread's bins, then the tiles. Each thread has two sets of bins and sets up batch k + 1
// into one while the tiles of batch k are drawn from the other, so one barrier per batch
// separates the phases: when a thread passes barrier k, every thread has finished drawing
// batch k - 1 (whose set batch k + 1 reuses) and setting up batch k.
void draw_binned(const DrawCall& dc, const FragCtx& frag, int n, GLenum mode, const PVertex* verts,
                 const uint32_t* indices, size_t count) {
  const size_t units = unit_count(mode, count);
  const size_t per_thread =
      mode == GL_QUADS || mode == GL_QUAD_STRIP ? kBatchTriangles / 2 : kBatchTriangles;
  const size_t batch = per_thread * static_cast<size_t>(n);
  const size_t batches = (units + batch - 1) / batch;
  const bool caller_setup = units <= kCallerSetupUnits;
  const TileGrid grid = make_tile_grid(frag);
  BinStore& store = dc.workers->bin_store();
  uint64_t samples[kMaxRasterThreads] = {};
  // The next tile of batch k to hand out, in next_tile[k & 1]: reset for batch k + 2 by
  // thread 0 once barrier k + 1 shows every thread done with batch k.
  std::atomic<int> next_tile[2] = {0, 0};
  SpinBarrier barrier(n);
  const auto nt = static_cast<size_t>(n);
  // Phase 1 of batch k for thread i: its contiguous share of the batch's primitives.
  const auto set_up = [&](int i, size_t k, size_t share_of, size_t shares) {
    TriBins& b = store.sets[k & 1][i];
    b.reset(grid);
    DrawCall setup_dc = dc;
    setup_dc.bands = Bands{};
    setup_dc.stipple_counter = nullptr; // filled polygons have no stipple counter
    const size_t first = k * batch, m = std::min(batch, units - first);
    const size_t lo = first + m * share_of / shares, hi = first + m * (share_of + 1) / shares;
    BinSink sink{setup_dc, b};
    Assembler<BinSink> as(setup_dc, sink);
    if (indices != nullptr)
      as.run(mode, IndexedFetch{verts, indices}, count, lo, hi);
    else
      as.run(mode, DirectFetch{verts}, count, lo, hi);
    b.link_shades();
  };
  if (caller_setup) {
    set_up(0, 0, 0, 1);
    for (int i = 1; i < n; ++i)
      store.sets[0][i].reset(grid);
  }
  auto job = [&](int i) {
    FragCtx local = frag;
    DrawCall share = dc;
    share.frag = &local;
    share.bands = Bands{};
    // Phase 2 of batch k: the tiles inside the union of the threads' binned ranges, handed
    // out a run at a time, so a thread that started late (a worker waking up) takes fewer.
    const auto draw_tiles = [&](size_t k) {
      const TriBins* set[kMaxRasterThreads];
      int tx0 = grid.tiles_x, ty0 = grid.tiles_y, tx1 = -1, ty1 = -1;
      for (int t = 0; t < n; ++t) {
        set[t] = &store.sets[k & 1][t];
        tx0 = std::min(tx0, set[t]->tx0), tx1 = std::max(tx1, set[t]->tx1);
        ty0 = std::min(ty0, set[t]->ty0), ty1 = std::max(ty1, set[t]->ty1);
      }
      if (tx1 < tx0 || ty1 < ty0) return;
      const int w = tx1 - tx0 + 1, total = w * (ty1 - ty0 + 1);
      const int run = std::max(1, total / (8 * n));
      std::atomic<int>& next = next_tile[k & 1];
      for (int j = next.fetch_add(run, std::memory_order_relaxed); j < total;
           j = next.fetch_add(run, std::memory_order_relaxed))
        for (int e = std::min(j + run, total); j < e; ++j) {
          const auto tile = static_cast<size_t>((ty0 + j / w) * grid.tiles_x + tx0 + j % w);
          bool empty = true;
          for (int t = 0; t < n; ++t)
            empty &= set[t]->head[tile] == kNoIndex;
          if (!empty) raster_tile(share, local, set, n, static_cast<int>(tile));
        }
    };
    if (!caller_setup) {
      set_up(i, 0, static_cast<size_t>(i), nt);
      barrier.arrive_and_wait();
    }
    for (size_t k = 0; k < batches; ++k) {
      draw_tiles(k);
      if (k + 1 < batches) {
        if (i == 0 && k >= 1) next_tile[(k + 1) & 1].store(0, std::memory_order_relaxed);
        set_up(i, k + 1, static_cast<size_t>(i), nt);
        barrier.arrive_and_wait();
      }
    }
    samples[i] = local.samples_passed;
  };
  dc.workers->run(job);
  if (dc.samples_passed != nullptr)
    for (int i = 0; i < n; ++i)
      *dc.samples_passed += samples[i];
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
  // with the draw (the context's draw cache).
  if (dc.frag == nullptr) return draw_with_local_frag(dc, mode, verts, indices, count);
  const FragCtx* frag = dc.frag;
  frag->samples_passed = 0;
  // The thread count first: with one thread (PINEDA_THREADS=1) no draw pays for the estimate.
  const int n = dc.workers != nullptr ? dc.workers->threads() : 1;
  if (n > 1 && !frag->noop && verts != nullptr &&
      worth_sharing(*dc.state, *frag, mode, verts, indices, count)) {
    // Filled triangles are set up once and binned into tiles; lines, points and outlined
    // polygons (whose stipple counter runs through the draw) are shared by bands.
    const RasterState& rs = *dc.state;
    if (dc.workers->binned() && unit_count(mode, count) != 0 && rs.polygon_mode[0] == GL_FILL &&
        rs.polygon_mode[1] == GL_FILL)
      return draw_binned(dc, *frag, n, mode, verts, indices, count);
    return draw_shared(dc, *frag, n, mode, verts, indices, count);
  }
  DrawCall prepared = dc;
  prepared.frag = frag;
  float stipple_counter = 0.0f;
  prepared.stipple_counter = &stipple_counter;
  RasterSink sink{prepared};
  assemble(sink, prepared, mode, verts, indices, count);
  if (dc.samples_passed != nullptr) *dc.samples_passed += frag->samples_passed;
}

void draw_primitives_to(PrimitiveSink& sink, const DrawCall& dc, GLenum mode, const PVertex* verts,
                        const uint32_t* indices, size_t count) {
  assemble(sink, dc, mode, verts, indices, count);
}

} // namespace pineda
