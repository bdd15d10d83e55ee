// The per-vertex transform (GL 2.1 §2.11, §2.12) and lighting (§2.14.1) several vertices at
// a time: the vertices are transposed into one vector per component (x of 4, 8 or 16
// vertices, y of them, ...) and every operation of the scalar code (transform.cpp, clip.cpp
// clip_code, raster.h to_window, light_eval.cpp light_vertex_faces) runs on the lanes in the
// same order, so the results are the scalar ones bit for bit. Four lanes with SSE2 (or any
// target), eight with AVX2, sixteen with AVX-512 when the CPU has them (vertex_simd.cpp
// chooses at run time).
#pragma once

#include <cstddef>

#include "geometry/input_vertex.h"
#include "geometry/clip.h"
#include "geometry/light_eval.h"
#include "core/vertex.h"

namespace pineda {

// out[k].clip, clipmask and (for a zero clip code) win of in[k], k < n, under the column-major
// composite matrix `m`.
void transform_positions(const float* m, const ClipSetup& cs, const Viewport& vp,
                         const InputVertex* in, PVertex* out, size_t n);

// The lit colours of in[k] written to out[k].attr as light_vertex_faces writes them.
void light_vertices(const LightSetup& s, const LitFaces& faces, const InputVertex* in, PVertex* out,
                    size_t n);

// The wider instances, called only at their SIMD level (core/simd_level.h): whole groups of
// eight vertices (vertex_simd_avx2.cpp) or sixteen (vertex_simd_avx512.cpp); they return how
// many they did.
size_t transform_positions_avx2(const float* m, const ClipSetup& cs, const Viewport& vp,
                                const InputVertex* in, PVertex* out, size_t n);
size_t light_vertices_avx2(const LightSetup& s, const LitFaces& faces, const InputVertex* in,
                           PVertex* out, size_t n);
size_t transform_positions_avx512(const float* m, const ClipSetup& cs, const Viewport& vp,
                                  const InputVertex* in, PVertex* out, size_t n);
size_t light_vertices_avx512(const LightSetup& s, const LitFaces& faces, const InputVertex* in,
                             PVertex* out, size_t n);

} // namespace pineda
