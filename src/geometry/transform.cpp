// The per-vertex loop of the geometry stage (transform.h).
#include "geometry/transform.h"

#include <algorithm>
#include <cmath>

#include "geometry/vertex_simd.h"

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

} // namespace

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

template void transform_vertices<false, false>(const VertexJob&);
template void transform_vertices<false, true>(const VertexJob&);
template void transform_vertices<true, false>(const VertexJob&);
template void transform_vertices<true, true>(const VertexJob&);

} // namespace pineda
