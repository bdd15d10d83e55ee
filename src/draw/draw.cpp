// The draw home (draw.h): from one validated draw to the back end.
#include "draw/draw.h"

#include <algorithm>
#include <cmath>

#include "draw/draw_buffers.h"
#include "draw/draw_cache.h"
#include "draw/feedback.h"
#include "fragment/fragment_ops.h"
#include "fragment/shade.h"
#include "geometry/assemble.h"
#include "geometry/clip.h"
#include "geometry/transform.h"
#include "raster/raster.h"
#include "raster/schedule.h"

namespace pineda {

namespace {

// The clip planes and the fragment stage's setup for the current state and framebuffer,
// rebuilt only when either changed since the last draw.
DrawCache& current_draw_cache(DrawContext& dc) {
  if (!dc.cache) dc.cache = std::make_unique<DrawCache>();
  DrawCache& c = *dc.cache;
  const DrawSources& src = dc.src;
  if (c.serial != *src.raster_serial || !same_surfaces(c.surfaces, *src.fb)) {
    // The clip codes come from the clipper's own plane setup (guard band, user planes), so
    // a vertex's code and the clipper's distances always agree.
    init_clip_setup(c.clip, *src.raster);
    prepare_fragments(*src.raster, *src.fb, c.frag);
    c.surfaces = *src.fb;
    c.serial = *src.raster_serial;
  }
  return c;
}

// The per-vertex loop's instance for the draw (geometry/transform.h).
[[gnu::always_inline]] inline void transform(const VertexJob& job, bool lit, bool extra) {
  if (lit)
    extra ? transform_vertices<true, true>(job) : transform_vertices<true, false>(job);
  else
    extra ? transform_vertices<false, true>(job) : transform_vertices<false, false>(job);
}

// Draws with at least this many vertices have them transformed and lit by every worker
// thread; below it, waking the workers costs more than it saves.
constexpr size_t kShareVertexCount = 4096;

// Vertices per slice of a large draw of independent primitives (draw_vertices): a multiple
// of 1, 2, 3 and 4 vertices, and at least kShareVertexCount so that a slice's transform is
// still shared among the workers.
constexpr size_t kSliceVertices = 12 * 2048;
static_assert(kSliceVertices >= kShareVertexCount);

// Sharing a draw among the worker threads (raster/workers.h) costs each worker the assembly
// and setup of every primitive and the caller a wake-up and a wait, some microseconds: only
// draws with many vertices or a large window area are shared. One triangle per Begin/End
// (immediate mode) stays on the calling thread.
constexpr size_t kShareVertices = 1024;
constexpr int64_t kShareArea = 32768; // pixels of the draw's window bounding box

// The window bounding box of the vertices, each widened by `pad`, clamped to the clip
// rectangle of `frag`: x0 <= x < x1, y0 <= y < y1 (empty when x1 <= x0 or y1 <= y0). A vertex
// outside the clip volume has no window position yet: its clip coordinates are projected here,
// and one with w <= 0 (whose primitives may reach anywhere) stands for the whole rectangle.
// Clipping keeps every primitive inside the projection of its vertices' convex hull.
struct WindowBox {
  float x0, y0, x1, y1;
};
WindowBox window_box(const RasterState& rs, const FragCtx& frag, const PVertex* verts,
                     const uint32_t* indices, size_t count, float pad) {
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
  return {std::max(x0, cx0), std::max(y0, cy0), std::min(x1, cx1), std::min(y1, cy1)};
}

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
  const WindowBox b = window_box(rs, frag, verts, indices, count, pad);
  if (!(b.x1 > b.x0 && b.y1 > b.y0)) return false;
  const int64_t w = static_cast<int64_t>(b.x1 - b.x0), h = static_cast<int64_t>(b.y1 - b.y0);
  return w > 0 && h > 0 && w * h >= kShareArea;
}

// The pixels the primitives of a draw can reach (FRONT_AND_BACK keeps their depth and stencil
// values, draw_buffers.h): the vertices' window box widened by half the largest point size or
// line width the draw can rasterize (points and lines, and polygons outlined in POINT or LINE
// mode, GL 2.1 §3.5.4), and by two more pixels for rounding and smooth edges.
DrawRegion draw_region(const RasterState& rs, const FragCtx& frag, GLenum mode,
                       const PVertex* verts, const uint32_t* indices, size_t count) {
  const RasterModes& m = rs.modes;
  const bool polygon = mode >= GL_TRIANGLES;
  const bool points =
      mode == GL_POINTS ||
      (polygon && (rs.polygon_mode[0] == GL_POINT || rs.polygon_mode[1] == GL_POINT));
  const bool lines = (mode >= GL_LINES && mode <= GL_LINE_STRIP) ||
                     (polygon && (rs.polygon_mode[0] == GL_LINE || rs.polygon_mode[1] == GL_LINE));
  float size = 0.0f;
  if (points) size = std::max(size, m.point_attenuated ? m.point_size_max : m.point_size);
  if (lines) size = std::max(size, m.line_width);
  const WindowBox b = window_box(rs, frag, verts, indices, count, 0.5f * size + 2.0f);
  if (!(b.x1 > b.x0 && b.y1 > b.y0)) return {};
  return {static_cast<int>(std::floor(b.x0)), static_cast<int>(std::floor(b.y0)),
          static_cast<int>(std::ceil(b.x1)), static_cast<int>(std::ceil(b.y1))};
}

// A draw shared among the worker threads, by bins of tiles or by bands of rows.
[[gnu::noinline]] void rasterize_shared(const DrawCall& dc, RasterWorkers& workers, int n,
                                        GLenum mode, const PVertex* verts, const uint32_t* indices,
                                        size_t count) {
  const FragCtx& frag = *dc.frag;
  frag.samples_passed = 0;
  const AssemblyJob job{mode,
                        verts,
                        indices,
                        count,
                        primitive_units(mode, count),
                        &draw_primitives,
                        &assemble_to_bins};
  // Filled triangles are set up once and binned into tiles; lines, points and outlined
  // polygons (whose stipple counter runs through the draw) are shared by bands.
  const RasterState& rs = *dc.state;
  if (workers.binned() && job.units != 0 && rs.polygon_mode[0] == GL_FILL &&
      rs.polygon_mode[1] == GL_FILL)
    return draw_binned(dc, frag, workers, n, job);
  draw_banded(dc, frag, workers, n, job);
}

// The primitives of one draw (or slice) into one colour buffer: on the calling thread, or
// shared among the worker threads (raster/schedule.h) when that pays.
[[gnu::always_inline]] inline void rasterize(const DrawCall& dc, RasterWorkers* workers,
                                             GLenum mode, const PVertex* verts,
                                             const uint32_t* indices, size_t count) {
  // The thread count first: with one thread (PINEDA_THREADS=1) no draw pays for the estimate.
  const int n = workers != nullptr ? workers->threads() : 1;
  if (n > 1 && !dc.frag->noop && worth_sharing(*dc.state, *dc.frag, mode, verts, indices, count))
    return rasterize_shared(dc, *workers, n, mode, verts, indices, count);
  draw_primitives(dc, mode, verts, indices, count);
}

// With FRONT_AND_BACK (GL 2.1 §4.2.1) or several draw buffers, the further buffers first, from the
// same depth and stencil values (draw_buffers.h), then the primary one. A fragment shader's draw
// instead shades each fragment once and stores it into every buffer (FragCtx::more), unless
// smooth points or lines are on (their fragments take the constant-colour path).
[[gnu::noinline]] void rasterize_both_buffers(const DrawCall& dc, RasterWorkers* workers,
                                              GLenum mode, const PVertex* verts,
                                              const uint32_t* indices, size_t count) {
  Framebuffer& fb = *dc.fb;
  const RasterState& rs = *dc.state;
  const FragCtx& frag = *dc.frag;
  if (frag.shade != nullptr && frag.shade->program != nullptr &&
      frag.key.color_path() != ColorPath::None && !rs.modes.line_smooth && !rs.modes.point_smooth) {
    FragCtx more[kMaxDrawBuffers - 1];
    FragCtx first = frag;
    for (int i = 0; i < fb.more_count; ++i) {
      prepare_fragments(rs, fb.with_color(fb.more[i]), more[i]);
      more[i].write_color = select_color_writer(more[i].key);
      if (more[i].write_color != nullptr) first.more[first.more_count++] = &more[i];
    }
    DrawCall one = dc;
    one.frag = &first;
    return rasterize(one, workers, mode, verts, indices, count);
  }
  const DrawRegion region = draw_region(rs, *dc.frag, mode, verts, indices, count);
  for_each_draw_buffer(fb, rs, region, [&](bool primary) {
    if (primary) return rasterize(dc, workers, mode, verts, indices, count);
    FragCtx second;
    prepare_fragments(rs, fb, second); // fb.color is the further buffer now
    DrawCall other = dc;
    other.frag = &second;
    other.samples_passed = nullptr; // occlusion queries count the primary pass only
    rasterize(other, workers, mode, verts, indices, count);
  });
}

// The processed vertices into every draw buffer.
[[gnu::always_inline]] inline void rasterize_all_buffers(const DrawCall& dc, RasterWorkers* workers,
                                                         GLenum mode, const PVertex* verts,
                                                         const uint32_t* indices, size_t count) {
  if (dc.fb->more_count == 0) return rasterize(dc, workers, mode, verts, indices, count);
  rasterize_both_buffers(dc, workers, mode, verts, indices, count);
}

} // namespace

DrawContext::DrawContext() = default;
DrawContext::~DrawContext() = default;

void draw_vertices(DrawContext& dc, const DrawInput& in) {
  const DrawSources& src = dc.src;
  const RasterState& rs = *src.raster;
  const Viewport& vp = rs.viewport;
  if (vp.w <= 0.0f || vp.h <= 0.0f) return;
  DrawCache& cache = current_draw_cache(dc);

  std::vector<PVertex>& out = dc.verts;
  VertexJob job;
  job.in = in.in;
  job.out = nullptr; // set once `out` has its size
  job.n = in.n;
  job.m = &(*src.mvp)[0][0];
  job.cs = &cache.clip;
  job.vp = &vp;
  // GL 2.1 §2.14.1: lighting replaces the current colour. Material calls between Begin and
  // End (§2.14.2) change the material from a given vertex of the primitive on.
  job.light = src.light;
  job.changes = in.changes;
  job.change_count = in.change_count;
  job.material = in.material;
  job.color_sum = in.color_sum;
  // With texturing or fog on, the fragment stage adds the secondary colour after the texture
  // environments (fragment/shade.cpp); otherwise it is folded in here.
  job.fold_sum = job.color_sum && rs.shade == nullptr;
  job.two_sided = rs.two_sided;
  job.tvs = src.tex;
  job.tex_live = rs.shade != nullptr && (job.tvs->units != 0 || job.tvs->fog);
  // GL 1.4 point parameters (GL 2.1 §3.3 eq 3.1): with distance attenuation every vertex gets
  // its derived size. Mesa takes the distance as |z| in eye coordinates rather than the
  // Euclidean distance the spec names; Pineda follows llvmpipe.
  job.modes = &rs.modes;
  job.mv = src.modelview;
  const bool lit = in.lit;
  const bool extra = job.tex_live || rs.modes.point_attenuated;
  // Vertices are independent of each other, so a large draw's are split into one contiguous
  // range per worker thread (raster/workers.h). Material changes between Begin and End
  // (immediate mode, a few vertices) depend on the vertex index: they stay on one thread.
  RasterWorkers* const workers = src.workers;
  // A vertex shader (geometry/vertex_program.h) or the fixed-function loop.
  const VertexProgram* const program = in.vertex_program;
  const auto process = [&](const VertexJob& j) {
    if (program != nullptr)
      return run_vertex_program(*program, *j.cs, *j.vp, j.in, static_cast<size_t>(j.in - in.in),
                                j.out, j.n);
    transform(j, lit, extra);
  };
  const auto transform_all = [&](const VertexJob& range) {
    const size_t m = range.n;
    const int threads = m >= kShareVertexCount && range.change_count == 0 && workers != nullptr
                            ? workers->threads()
                            : 1;
    if (threads <= 1) return process(range);
    auto part = [&](int i) {
      VertexJob j = range;
      const auto t = static_cast<size_t>(threads);
      const size_t lo = m * static_cast<size_t>(i) / t, hi = m * static_cast<size_t>(i + 1) / t;
      j.in = range.in + lo;
      j.out = range.out + lo;
      j.n = hi - lo;
      process(j);
    };
    workers->run(part);
  };

  DrawCall call;
  call.state = &rs;
  call.fb = src.fb;
  call.frag = &cache.frag;
  if (rs.count_samples) call.samples_passed = src.samples_passed;

  // Independent points, segments, triangles and quads in order (a large glBegin/glEnd or
  // DrawArrays) are transformed and drawn a slice at a time, so that the processed vertices
  // are still in the cache when they are drawn. Each slice holds whole primitives and the
  // primitives reach the rasterizer in the same order; no state crosses a slice boundary
  // (the line stipple restarts with every independent segment and outlined polygon).
  const GLenum mode = in.mode;
  const bool independent =
      mode == GL_POINTS || mode == GL_LINES || mode == GL_TRIANGLES || mode == GL_QUADS;
  if (in.n > kSliceVertices && independent && in.indices == nullptr && in.count == in.n &&
      job.change_count == 0 && in.records == nullptr) {
    if (out.size() < kSliceVertices) out.resize(kSliceVertices);
    for (size_t first = 0; first < in.n; first += kSliceVertices) {
      VertexJob slice = job;
      slice.in = in.in + first;
      slice.out = out.data();
      slice.n = std::min(kSliceVertices, in.n - first);
      transform_all(slice);
      rasterize_all_buffers(call, workers, mode, out.data(), nullptr, slice.n);
    }
    return;
  }

  if (out.size() < in.n) out.resize(in.n);
  job.out = out.data();
  transform_all(job);
  // GL 2.1 §5.2, §5.3: in SELECT and FEEDBACK mode the primitives go to selection or
  // feedback instead of the rasterizer.
  if (in.records != nullptr) return select_feedback_draw(in, src, out.data());
  rasterize_all_buffers(call, workers, mode, out.data(), in.indices, in.count);
}

} // namespace pineda
