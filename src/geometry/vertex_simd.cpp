// Four vertices at a time (vertex_simd.h, bodies in vertex_simd_impl.h), eight on CPUs with
// AVX2 (vertex_simd_avx2.cpp), sixteen with AVX-512 (vertex_simd_avx512.cpp), chosen at run
// time; a draw's vertices go through the widest lanes first, what is left through the
// narrower ones, the last few through the scalar functions, whose results the lanes reproduce
// bit for bit.
#include "geometry/vertex_simd.h"

#include "core/simd_level.h"
#include "geometry/vertex_simd_impl.h"
#include "raster/raster.h"

namespace pineda {

void transform_positions(const float* m, const ClipSetup& cs, const Viewport& vp,
                         const InputVertex* in, PVertex* out, size_t n) {
  size_t i = 0;
#if defined(PINEDA_VERTEX_AVX2)
  // core/simd_level.h; PINEDA_SIMD=avx2 or sse2 keeps the narrower lanes, to compare them.
  const SimdLevel level = simd_level();
  if (level >= SimdLevel::Avx512) i = transform_positions_avx512(m, cs, vp, in, out, n);
  if (level >= SimdLevel::Avx2) i += transform_positions_avx2(m, cs, vp, in + i, out + i, n - i);
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
  const SimdLevel level = simd_level();
  if (level >= SimdLevel::Avx512) i = light_vertices_avx512(s, faces, in, out, n);
  if (level >= SimdLevel::Avx2) i += light_vertices_avx2(s, faces, in + i, out + i, n - i);
#endif
  for (; i + 4 <= n; i += 4)
    Simd<4>::light(s, faces, in + i, out + i);
  for (; i < n; ++i)
    light_vertex_faces(s, faces, in[i].pos, in[i].normal, out[i].attr);
}

} // namespace pineda
