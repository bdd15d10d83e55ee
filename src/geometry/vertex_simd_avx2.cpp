// The eight-lane instances of vertex_simd_impl.h, compiled with -mavx2 -ffp-contract=off on
// x86-64 (CMakeLists.txt) and called only when the CPU has AVX2 (vertex_simd.cpp). Elsewhere
// the file is empty.
#if defined(__AVX2__)
#include "geometry/vertex_simd.h"
#include "geometry/vertex_simd_impl.h"

namespace pineda {

size_t transform_positions_avx2(const float* m, const ClipSetup& cs, const Viewport& vp,
                                const InputVertex* in, PVertex* out, size_t n) {
  size_t i = 0;
  for (; i + 8 <= n; i += 8)
    Simd<8>::transform(m, cs, vp, in + i, out + i);
  return i;
}

size_t light_vertices_avx2(const LightSetup& s, const LitFaces& faces, const InputVertex* in,
                           PVertex* out, size_t n) {
  size_t i = 0;
  for (; i + 8 <= n; i += 8)
    Simd<8>::light(s, faces, in + i, out + i);
  return i;
}

} // namespace pineda
#endif
