// The texture sampler (GL 2.1 §3.8.8-§3.8.10, §3.8.14), the back end of texturing: a per-draw
// snapshot of a texture object (SamplerView, made by state/texture_view.cpp) and the filtering
// of up to 64 fragments at a time. It sees no GL object: the texture objects are state
// (state/texture_object.h). The fragment texturing path (texture environments, coordinates)
// lives elsewhere and calls only what this header declares.
#pragma once

#include <GL/gl.h>

#include <bit>
#include <cmath>
#include <cstdint>

#include "core/limits.h"

namespace pineda {

// The base internal format of a texture as the sampler sees it (GL 2.1 Table 3.15). Depth
// textures appear as the base DEPTH_TEXTURE_MODE selects (§3.8.14).
enum class TexBase : uint8_t { Alpha, Luminance, LuminanceAlpha, Intensity, RGB, RGBA };

constexpr int kMaxSampleBatch = 64;

// log2 as llvmpipe's level-of-detail computation takes it: exact at powers of two and linear
// in between (floor(log2 x) + x / 2^floor(log2 x) - 1). Its integer part is the exact one, so
// nearest-level selection is unaffected; the fraction that weighs two levels (§3.8.10
// LINEAR_MIPMAP_*) follows llvmpipe's.
inline float lod_log2(float x) {
  int e = 0;
  float m;
  const uint32_t bits = std::bit_cast<uint32_t>(x);
  const uint32_t biased = (bits >> 23) & 0xffu;
  if (biased != 0 && biased != 0xff) {
    // A normal number: frexp's m and e read straight from the fields (no library call).
    e = static_cast<int>(biased) - 126;
    m = std::bit_cast<float>((bits & 0x807fffffu) | (126u << 23));
  } else {
    m = std::frexp(x, &e); // x = m 2^e, m in [1/2, 1)
  }
  return static_cast<float>(e - 2) + 2.0f * m;
}

// The dimensionality of a texture target: 1 for TEXTURE_1D, 3 for TEXTURE_3D, else 2 (2D and
// cube maps, whose faces are 2D images).
inline int texture_dims(GLenum target) {
  return target == GL_TEXTURE_1D ? 1 : target == GL_TEXTURE_3D ? 3 : 2;
}

// One mipmap level of one face as the sampler reads it. Sizes include the border.
struct SamplerLevel {
  const uint8_t* rgba = nullptr; // colour: 4 bytes per texel, expanded by Table 3.23
  const uint32_t* z = nullptr;   // depth textures: one value per texel, in [0, z_max]
  double z_max = 1.0;            // 2^bits - 1 of the depth image
  int width = 0, height = 0, depth = 0;
};

// The largest value of a depth texel of `bits` bits (unsigned normalized, GL 2.1 §2.14.9 eq.
// 2.3): depth images are stored as the depth buffer stores depth, so that a framebuffer
// object can render into them (ARB_framebuffer_object).
inline double depth_texel_max(int bits) {
  return bits >= 32 ? 4294967295.0 : double((uint64_t{1} << bits) - 1);
}

struct SamplerView {
  GLenum target = GL_TEXTURE_2D;
  TexBase base = TexBase::RGBA;
  int width = 0, height = 0, depth = 0; // base level size without border

  // ---- level and face data ----
  int border = 0;
  int base_level = 0; // level_base (§3.8.8)
  int max_level = 0;  // q (§3.8.10): the last level sampled
  int faces = 1;      // 6 for cube maps
  // levels[face][level]; valid for face < faces and base_level <= level <= max_level.
  SamplerLevel levels[6][kMaxTexLevels];
  bool is_depth = false;
  // An sRGB internal format (GL 2.1 §3.8.15, EXT_texture_sRGB): the stored R, G, B (or L) are
  // sRGB-encoded and are decoded to linear before filtering; alpha is linear.
  bool srgb = false;

  // ---- parameters (Table 6.19) ----
  GLenum min_filter = GL_NEAREST_MIPMAP_LINEAR, mag_filter = GL_LINEAR;
  GLenum wrap_s = GL_REPEAT, wrap_t = GL_REPEAT, wrap_r = GL_REPEAT;
  float border_color[4] = {0, 0, 0, 0}; // already expanded by base format
  float min_lod = -1000.0f, max_lod = 1000.0f;
  float lod_bias = 0.0f; // the object's TEXTURE_LOD_BIAS
  float c = 0.0f;        // §3.8.9: the minification/magnification switch-over point
  bool compare = false;  // TEXTURE_COMPARE_MODE == COMPARE_R_TO_TEXTURE
  GLenum compare_func = GL_LEQUAL;
  bool quads = false; // sample_quads has a vector path for this view (quad_sampling_supported)
};

// Samples n <= 64 fragments. s, t, r: coordinates already divided by q (cube maps: the
// direction (s,t,r) before face selection, §3.8.6). lambda: log2 of the scale factor rho
// (§3.8.8) before any bias; `bias` is the texture unit's TEXTURE_LOD_BIAS (glTexEnv), the
// sampler adds the object's bias, clamps (MIN/MAX_LOD), chooses mag or min filter (with §3.8.9's
// c), levels, wraps, borders, depth comparison (§3.8.14 compare mode/func). Output RGBA in
// [0,1], already expanded by base format as GL 2.1 Table 3.23 says (ALPHA -> (0,0,0,A),
// LUMINANCE -> (L,L,L,1), INTENSITY -> (I,I,I,I), RGB -> (R,G,B,1)).
// `t` may be null for 1D textures and `r` for 1D/2D ones.
void sample_texture(const SamplerView& v, int n, const float* s, const float* t, const float* r,
                    const float* lambda, float bias, float (*rgba)[4]);

// GL 2.1 §3.8.15 eq. 3.28: the linear value of each 8-bit sRGB-encoded component c / 255.
const float* srgb_decode_table();

// Whether sample_quads filters `v` in vectors (2D colour texture, LINEAR minification,
// CLAMP_TO_EDGE or power-of-two REPEAT wraps); make_sampler_view records it in `quads`.
bool quad_sampling_supported(const SamplerView& v);

// Samples nq 2x2 quads: s[4q + k], t[4q + k] are the coordinates (already divided by q) of
// fragment k of quad q, lambda[q] the quad's log2 rho as for sample_texture, `bias` the unit's
// TEXTURE_LOD_BIAS. Writes rgba[c][4q + k], channel c of fragment k, exactly the values
// sample_texture gives with lambda[q] for each of the quad's fragments. Any 2D view works;
// those without `quads` take sample_texture's path.
void sample_quads(const SamplerView& v, int nq, const float* s, const float* t, const float* lambda,
                  float bias, float (*rgba)[64]);

// One texture image as the mipmap filter reads or writes it: sizes include the border;
// colour images have `rgba` (4 bytes per texel, expanded by base format), depth images `z`.
// A destination has the texel storage to write (rgba_out or z_out) instead.
struct TexelImage {
  int width = 0, height = 0, depth = 0, border = 0;
  bool is_depth = false;
  const uint8_t* rgba = nullptr;
  const uint32_t* z = nullptr;
  double z_max = 1.0; // depth_texel_max of the depth image (source and destination alike)
  uint8_t* rgba_out = nullptr;
  uint32_t* z_out = nullptr;
};

// The next level of GENERATE_MIPMAP (GL 2.1 §3.8.8): each texel of `dst` is the bilinear
// (trilinear for 3D) sample of `src` at the texel's centre with CLAMP_TO_EDGE, in llvmpipe's
// 8-bit fixed point, which for halved power-of-two sizes is the 2x2 (2x2x2) box filter. Border
// texels come from the source border. `dims` is 1, 2 or 3.
void downsample_texels(const TexelImage& src, const TexelImage& dst, int dims);

} // namespace pineda
