// The sixteen-lane instances of vertex_simd_impl.h, compiled with AVX-512 F, DQ, BW and VL and
// -ffp-contract=off on x86-64 (CMakeLists.txt) and called only when simd_level() is Avx512
// (vertex_simd.cpp). One vector holds a component of sixteen vertices: half the instructions
// of the AVX2 lanes, which matters on Zen 4 (512-bit operations issue as two 256-bit halves).
// Elsewhere the file is empty.
#if defined(__AVX512F__)
#include "geometry/vertex_simd.h"
#include "geometry/vertex_simd_impl.h"

namespace pineda {

size_t transform_positions_avx512(const float* m, const ClipSetup& cs, const Viewport& vp,
                                  const InputVertex* in, PVertex* out, size_t n) {
  size_t i = 0;
  for (; i + 16 <= n; i += 16)
    Simd<16>::transform(m, cs, vp, in + i, out + i);
  return i;
}

size_t light_vertices_avx512(const LightSetup& s, const LitFaces& faces, const InputVertex* in,
                             PVertex* out, size_t n) {
  size_t i = 0;
  for (; i + 16 <= n; i += 16)
    Simd<16>::light(s, faces, in + i, out + i);
  return i;
}

} // namespace pineda
#endif
