// Vertex transformation (GL 2.1 §2.11, §2.12, §2.14.6): object coordinates to clip
// coordinates through the composite matrix, clip codes, window coordinates for vertices that
// need no clipping, and the vertex colours: lit (§2.14.1, light_eval.cpp) or the clamped
// current colours, with the colour sum (§3.9) folded in unless texturing or fog is on; texture
// and fog coordinates (texcoord.cpp); derived point sizes (GL 1.4 point parameters).
#include <algorithm>
#include <cmath>

#include "geometry/clip.h"
#include "geometry/draw_cache.h"
#include "geometry/geometry.h"
#include "geometry/light_eval.h"
#include "geometry/texcoord.h"
#include "geometry/vertex_simd.h"
#include "raster/raster.h"
#include "raster/workers.h"
#include "state/draw_read_buffer.h"

namespace pineda {

namespace {

// GL 2.1 §3.9 colour sum, folded into the primary colour at the vertex: the fragment's colour
// is clamp(c_pri + c_sec) with both colours interpolated, and interpolation (clipping, eq.
// 3.9) is linear, so interpolating the unclamped per-vertex sum and clamping per fragment (as
// the fragment stage does) gives the same value. With texturing (§3.8.13 precedes the colour
// sum) or fog on, the fragment stage adds it instead.
inline void add_secondary(float* attr, bool back) {
  for (int c = 0; c < 3; ++c)
    attr[kAttrColor + c] += attr[kAttrColor2 + c];
  if (back)
    for (int c = 0; c < 3; ++c)
      attr[kAttrBackColor + c] += attr[kAttrBackColor2 + c];
}

// The clip planes and the fragment stage's setup for the current state and framebuffer,
// rebuilt only when either changed since the last draw.
DrawCache& current_draw_cache(Context* ctx) {
  if (!ctx->draw_cache) ctx->draw_cache = std::make_unique<DrawCache>();
  DrawCache& c = *ctx->draw_cache;
  if (c.serial != ctx->raster_serial || !same_surfaces(c.surfaces, ctx->fb)) {
    // The clip codes come from the clipper's own plane setup (guard band, user planes), so
    // a vertex's code and the clipper's distances always agree.
    init_clip_setup(c.clip, ctx->raster);
    prepare_fragments(ctx->raster, ctx->fb, c.frag);
    c.surfaces = ctx->fb;
    c.serial = ctx->raster_serial;
  }
  return c;
}

// Draws with at least this many vertices have them transformed and lit by every worker
// thread; below it, waking the workers costs more than it saves.
constexpr size_t kShareVertexCount = 4096;

// Vertices per slice of a large draw of independent primitives (draw_vertices_once): a
// multiple of 1, 2, 3 and 4 vertices, and at least kShareVertexCount so that a slice's
// transform is still shared among the workers.
constexpr size_t kSliceVertices = 12 * 2048;
static_assert(kSliceVertices >= kShareVertexCount);

// What the per-vertex loop reads, gathered once per draw.
struct VertexJob {
  const InputVertex* in;
  PVertex* out;
  size_t n;
  const float* m; // composite matrix, column-major
  const ClipSetup* cs;
  const Viewport* vp;
  const LightSetup* light;
  const MaterialChange* changes;
  size_t change_count;
  const Material* material;
  bool color_sum, fold_sum, two_sided;
  const TexVertexSetup* tvs;
  bool tex_live;
  const RasterModes* modes;
  const glm::mat4* mv;
};

// Everything of vertex i but its clip and window coordinates and lit colours: the unlit
// colours, the colour sum, the edge flag, texture and fog coordinates and the point size.
template <bool kLit, bool kExtra>
[[gnu::always_inline]] inline void finish_vertex(const VertexJob& job, size_t i) {
  const InputVertex& v = job.in[i];
  PVertex& p = job.out[i];
  if constexpr (kLit) {
    if (job.fold_sum) add_secondary(p.attr, job.two_sided);
  } else {
    // GL 2.1 §2.14.6: with lighting off the primary colour is the current colour, clamped.
    for (int c = 0; c < 4; ++c) {
      const float col = v.color[c];
      p.attr[kAttrColor + c] = col > 0.0f ? (col < 1.0f ? col : 1.0f) : 0.0f;
    }
    if (job.color_sum) {
      for (int c = 0; c < 3; ++c) {
        const float col = v.color2[c];
        p.attr[kAttrColor2 + c] = col > 0.0f ? (col < 1.0f ? col : 1.0f) : 0.0f;
      }
      if (job.fold_sum) add_secondary(p.attr, false);
    }
  }
  p.edgeflag = v.edge;
  p.point_size = 1.0f;
  if constexpr (kExtra) {
    if (job.tex_live) tex_vertex(*job.tvs, v.pos, v.normal, v.tex, v.fog, p.attr);
    const RasterModes& modes = *job.modes;
    if (modes.point_attenuated) {
      const glm::mat4& mv = *job.mv;
      const float x = v.pos[0], y = v.pos[1], z = v.pos[2], w = v.pos[3];
      const float ez = mv[0][2] * x + mv[1][2] * y + mv[2][2] * z + mv[3][2] * w;
      const float d = ez < 0.0f ? -ez : ez;
      const float* a = modes.point_attenuation;
      const float size = modes.point_size / std::sqrt(a[0] + a[1] * d + a[2] * d * d);
      // A NaN (attenuation <= 0) becomes the minimum.
      p.point_size = size >= modes.point_size_min
                         ? (size < modes.point_size_max ? size : modes.point_size_max)
                         : modes.point_size_min;
    }
  }
}

// Vertices per pass of the vector functions (vertex_simd.h): the pass's vertices stay in the
// cache between transform, lighting and finish_vertex.
constexpr size_t kVertexChunk = 128;

// The per-vertex loop, instantiated for lighting on or off and for whether any of texture
// coordinates, fog or point attenuation is live, so the common draws carry no test for
// what they do not use.
template <bool kLit, bool kExtra> void transform_vertices(const VertexJob& job) {
  const float* m = job.m;
  const Material* material = job.material;
  size_t next_change = 0;
  // Without COLOR_MATERIAL the material terms change only with the material (§2.14.2).
  LitFaces faces;
  bool tracking = false;
  if constexpr (kLit) {
    const LightSetup& ls = *job.light;
    tracking = ls.track[0] || ls.track[1];
    if (!tracking) prepare_lit_faces(ls, material, nullptr, faces);
  }
  // One material for the whole draw: several vertices at a time (vertex_simd.h). A single
  // primitive of immediate mode (a few vertices) stays on the plain loop.
  if (job.n >= 8 && (!kLit || (!tracking && job.change_count == 0))) {
    for (size_t i0 = 0; i0 < job.n; i0 += kVertexChunk) {
      const size_t count = std::min(kVertexChunk, job.n - i0);
      transform_positions(m, *job.cs, *job.vp, job.in + i0, job.out + i0, count);
      if constexpr (kLit) light_vertices(*job.light, faces, job.in + i0, job.out + i0, count);
      for (size_t i = i0; i < i0 + count; ++i)
        finish_vertex<kLit, kExtra>(job, i);
    }
    return;
  }
  for (size_t i = 0; i < job.n; ++i) {
    const InputVertex& v = job.in[i];
    PVertex& p = job.out[i];
    const float x = v.pos[0], y = v.pos[1], z = v.pos[2], w = v.pos[3];
    for (int r = 0; r < 4; ++r)
      p.clip[r] = m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r] * w;
    p.clipmask = clip_code(*job.cs, p.clip);
    if (p.clipmask == 0) to_window(p, *job.vp);
    if constexpr (kLit) {
      const LightSetup& ls = *job.light;
      if (next_change < job.change_count && job.changes[next_change].vertex <= i) {
        while (next_change < job.change_count && job.changes[next_change].vertex <= i)
          material = job.changes[next_change++].material;
        if (!tracking) prepare_lit_faces(ls, material, nullptr, faces);
      }
      if (tracking) prepare_lit_faces(ls, material, v.color, faces);
      light_vertex_faces(ls, faces, v.pos, v.normal, p.attr);
    }
    finish_vertex<kLit, kExtra>(job, i);
  }
}

void draw_vertices_once(Context* ctx, GLenum mode, const InputVertex* in, size_t n,
                        const uint32_t* indices, size_t count) {
  validate_state(ctx);
  const RasterState& rs = ctx->raster;
  const Viewport& vp = rs.viewport;
  if (vp.w <= 0.0f || vp.h <= 0.0f) return;
  DrawCache& cache = current_draw_cache(ctx);

  std::vector<PVertex>& out = ctx->pvert_scratch;
  VertexJob job;
  job.in = in;
  job.out = nullptr; // set once `out` has its size
  job.n = n;
  job.m = &ctx->mvp[0][0];
  job.cs = &cache.clip;
  job.vp = &vp;
  // GL 2.1 §2.14.1: lighting replaces the current colour. Material calls between Begin and
  // End (§2.14.2) change the material from a given vertex of the primitive on.
  const LightingGroup& lighting = ctx->lighting;
  const bool lit = lighting.enabled;
  job.light = &ctx->light_setup;
  job.changes = ctx->imm.material_changes.data();
  job.change_count = lit ? ctx->imm.material_changes.size() : 0;
  job.material = job.change_count != 0 ? ctx->imm.begin_material : lighting.material;
  // §3.9: with lighting on the colour sum always applies and the secondary colour is zero
  // unless the specular term is separate; otherwise COLOR_SUM adds the current secondary
  // colour.
  // Feedback returns the primary colour alone (GL 2.1 §5.3), so nothing is folded in there.
  job.color_sum =
      (lit ? ctx->light_setup.separate_specular : ctx->fog.color_sum) && render_mode_is_render(ctx);
  // With texturing or fog on, the fragment stage adds the secondary colour after the texture
  // environments (fragment/shade.cpp); otherwise it is folded in here.
  job.fold_sum = job.color_sum && rs.shade == nullptr;
  job.two_sided = rs.two_sided;
  job.tvs = &ctx->texpipe.vertex;
  job.tex_live = rs.shade != nullptr && (job.tvs->units != 0 || job.tvs->fog);
  // GL 1.4 point parameters (GL 2.1 §3.3 eq 3.1): with distance attenuation every vertex gets
  // its derived size. Mesa takes the distance as |z| in eye coordinates rather than the
  // Euclidean distance the spec names; Pineda follows llvmpipe.
  job.modes = &rs.modes;
  job.mv = &ctx->modelview.top();
  const bool extra = job.tex_live || rs.modes.point_attenuated;
  const auto transform = [lit, extra](const VertexJob& j) {
    if (lit)
      extra ? transform_vertices<true, true>(j) : transform_vertices<true, false>(j);
    else
      extra ? transform_vertices<false, true>(j) : transform_vertices<false, false>(j);
  };
  // Vertices are independent of each other, so a large draw's are split into one contiguous
  // range per worker thread (raster/workers.h). Material changes between Begin and End
  // (immediate mode, a few vertices) depend on the vertex index: they stay on one thread.
  const auto transform_all = [&](const VertexJob& range) {
    const size_t m = range.n;
    const int threads =
        m >= kShareVertexCount && range.change_count == 0 ? ctx->workers.threads() : 1;
    if (threads <= 1) return transform(range);
    auto part = [&](int i) {
      VertexJob j = range;
      const auto t = static_cast<size_t>(threads);
      const size_t lo = m * static_cast<size_t>(i) / t, hi = m * static_cast<size_t>(i + 1) / t;
      j.in = range.in + lo;
      j.out = range.out + lo;
      j.n = hi - lo;
      transform(j);
    };
    ctx->workers.run(part);
  };

  Framebuffer& fb = ctx->fb;
  DrawCall dc;
  dc.state = &rs;
  dc.fb = &fb;
  dc.frag = &cache.frag;
  if (rs.count_samples) dc.samples_passed = &ctx->queries.samples_passed;
  dc.workers = &ctx->workers;

  // Independent points, segments, triangles and quads in order (a large glBegin/glEnd or
  // DrawArrays) are transformed and drawn a slice at a time, so that the processed vertices
  // are still in the cache when they are drawn. Each slice holds whole primitives and the
  // primitives reach the rasterizer in the same order; no state crosses a slice boundary
  // (the line stipple restarts with every independent segment and outlined polygon).
  const bool independent =
      mode == GL_POINTS || mode == GL_LINES || mode == GL_TRIANGLES || mode == GL_QUADS;
  if (n > kSliceVertices && independent && indices == nullptr && count == n &&
      job.change_count == 0 && render_mode_is_render(ctx)) {
    if (out.size() < kSliceVertices) out.resize(kSliceVertices);
    for (size_t first = 0; first < n; first += kSliceVertices) {
      VertexJob slice = job;
      slice.in = in + first;
      slice.out = out.data();
      slice.n = std::min(kSliceVertices, n - first);
      transform_all(slice);
      draw_primitives(dc, mode, out.data(), nullptr, slice.n);
    }
    return;
  }

  if (out.size() < n) out.resize(n);
  job.out = out.data();
  transform_all(job);
  // GL 2.1 §5.2, §5.3: in SELECT and FEEDBACK mode the primitives go to selection or
  // feedback instead of the rasterizer.
  if (!render_mode_is_render(ctx)) {
    select_feedback_draw(ctx, in, out.data(), n, mode, indices, count);
    return;
  }
  draw_primitives(dc, mode, out.data(), indices, count);
}

} // namespace

uint32_t input_tex_units(Context* ctx) {
  validate_state(ctx);
  const TexVertexSetup& tvs = ctx->texpipe.vertex;
  // As draw_vertices_once decides which units tex_vertex reads.
  uint32_t units = ctx->raster.shade != nullptr ? tvs.units : 0;
  // Feedback of the COLOR_TEXTURE types reports unit 0's coordinates (GL 2.1 §5.3).
  if (!render_mode_is_render(ctx)) units |= 1u;
  return units;
}

// GL 2.1 §4.2.1: with FRONT_AND_BACK the primitives reach both colour buffers.
void draw_vertices(Context* ctx, GLenum mode, const InputVertex* in, size_t n,
                   const uint32_t* indices, size_t count) {
  if (ctx->fb.color == nullptr || n == 0) return;
  for_each_draw_buffer(ctx, [&] { draw_vertices_once(ctx, mode, in, n, indices, count); });
}

} // namespace pineda
