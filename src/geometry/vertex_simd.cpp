// Four vertices at a time (vertex_simd.h, bodies in vertex_simd_impl.h), or eight on CPUs with
// AVX2 (vertex_simd_avx2.cpp, chosen at run time); the last few vertices of a draw take the
// scalar functions, whose results the lanes reproduce bit for bit.
#include "geometry/vertex_simd.h"

#include "core/simd_level.h"
#include "geometry/vertex_simd_impl.h"
#include "raster/raster.h"

namespace pineda {

#if defined(PINEDA_VERTEX_AVX2)
// vertex_simd_avx2.cpp: whole groups of eight vertices; they return how many they did.
size_t transform_positions_avx2(const float* m, const ClipSetup& cs, const Viewport& vp,
                                const InputVertex* in, PVertex* out, size_t n);
size_t light_vertices_avx2(const LightSetup& s, const LitFaces& faces, const InputVertex* in,
                           PVertex* out, size_t n);

namespace {
// The eight-lane code where the processor has AVX2 (core/simd_level.h; PINEDA_SIMD=sse2 keeps
// the four-lane code, to compare both).
bool use_avx2() {
  return simd_level() == SimdLevel::Avx2;
}
} // namespace
#endif

void transform_positions(const float* m, const ClipSetup& cs, const Viewport& vp,
                         const InputVertex* in, PVertex* out, size_t n) {
  size_t i = 0;
#if defined(PINEDA_VERTEX_AVX2)
  if (use_avx2()) i = transform_positions_avx2(m, cs, vp, in, out, n);
#endif
  for (; i + 4 <= n; i += 4)
    Simd<4>::transform(m, cs, vp, in + i, out + i);
  for (; i < n; ++i) {
    const float* pos = in[i].pos;
    PVertex& p = out[i];
    for (int r = 0; r < 4; ++r)
      p.clip[r] = m[r] * pos[0] + m[4 + r] * pos[1] + m[8 + r] * pos[2] + m[12 + r] * pos[3];
    p.clipmask = clip_code(cs, p.clip);
    if (p.clipmask == 0) to_window(p, vp);
  }
}

void light_vertices(const LightSetup& s, const LitFaces& faces, const InputVertex* in, PVertex* out,
                    size_t n) {
  size_t i = 0;
#if defined(PINEDA_VERTEX_AVX2)
  if (use_avx2()) i = light_vertices_avx2(s, faces, in, out, n);
#endif
  for (; i + 4 <= n; i += 4)
    Simd<4>::light(s, faces, in + i, out + i);
  for (; i < n; ++i)
    light_vertex_faces(s, faces, in[i].pos, in[i].normal, out[i].attr);
}

} // namespace pineda
