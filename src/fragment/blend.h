// Blending (GL 2.1 §4.1.8) for 8-bit unorm colour buffers.
//
// The generic path works in float on [0,1] values: the source colour is first rounded to the
// buffer's 8 bits (as llvmpipe converts the fragment colour to the render target's format
// before blending), both colours are divided by 255, the factors and equation are applied,
// and the result is clamped and rounded once. llvmpipe does the same arithmetic in unorm8
// with a rounding per product, so the two agree within 1.
#pragma once

#include <GL/gl.h>

#include <algorithm>
#include <cstdint>

#include "core/raster_state.h"

namespace pineda {

// Blend factors of GL 2.1 table 4.2, in a dense encoding for switch tables.
enum class BlendFactor : uint8_t {
  Zero,
  One,
  SrcColor,
  OneMinusSrcColor,
  DstColor,
  OneMinusDstColor,
  SrcAlpha,
  OneMinusSrcAlpha,
  DstAlpha,
  OneMinusDstAlpha,
  ConstColor,
  OneMinusConstColor,
  ConstAlpha,
  OneMinusConstAlpha,
  SrcAlphaSaturate,
};

// Blend equations (GL 2.1 §4.1.8, table 4.1).
enum class BlendEq : uint8_t { Add, Subtract, ReverseSubtract, Min, Max };

struct BlendParams {
  BlendFactor src_rgb = BlendFactor::One, dst_rgb = BlendFactor::Zero;
  BlendFactor src_a = BlendFactor::One, dst_a = BlendFactor::Zero;
  BlendEq eq_rgb = BlendEq::Add, eq_a = BlendEq::Add;
  float constant[4] = {0, 0, 0, 0}; // glBlendColor, clamped to [0,1] (GL 2.1 §4.1.8)
};

BlendFactor blend_factor_from_gl(GLenum factor);
BlendEq blend_eq_from_gl(GLenum eq);
BlendParams make_blend_params(const RasterState& rs);

// True when the state blends like a plain store: ONE, ZERO with FUNC_ADD for colour and alpha.
bool blend_is_store(const RasterState& rs);

namespace blend_detail {

// Factor for the RGB channels: out[0..2] gets the per-channel factor.
inline void rgb_factor(BlendFactor f, const float s[4], const float d[4], const float k[4],
                       float out[3]) {
  for (int i = 0; i < 3; ++i) {
    float v = 0.0f;
    switch (f) {
    case BlendFactor::Zero:
      v = 0.0f;
      break;
    case BlendFactor::One:
      v = 1.0f;
      break;
    case BlendFactor::SrcColor:
      v = s[i];
      break;
    case BlendFactor::OneMinusSrcColor:
      v = 1.0f - s[i];
      break;
    case BlendFactor::DstColor:
      v = d[i];
      break;
    case BlendFactor::OneMinusDstColor:
      v = 1.0f - d[i];
      break;
    case BlendFactor::SrcAlpha:
      v = s[3];
      break;
    case BlendFactor::OneMinusSrcAlpha:
      v = 1.0f - s[3];
      break;
    case BlendFactor::DstAlpha:
      v = d[3];
      break;
    case BlendFactor::OneMinusDstAlpha:
      v = 1.0f - d[3];
      break;
    case BlendFactor::ConstColor:
      v = k[i];
      break;
    case BlendFactor::OneMinusConstColor:
      v = 1.0f - k[i];
      break;
    case BlendFactor::ConstAlpha:
      v = k[3];
      break;
    case BlendFactor::OneMinusConstAlpha:
      v = 1.0f - k[3];
      break;
    // GL 2.1 table 4.2: f = min(As, 1 - Ad) for R, G and B.
    case BlendFactor::SrcAlphaSaturate:
      v = std::min(s[3], 1.0f - d[3]);
      break;
    }
    out[i] = v;
  }
}

// Factor for the alpha channel: colour factors use their alpha component, and
// SRC_ALPHA_SATURATE is 1 for alpha (GL 2.1 table 4.2).
inline float alpha_factor(BlendFactor f, const float s[4], const float d[4], const float k[4]) {
  switch (f) {
  case BlendFactor::Zero:
    return 0.0f;
  case BlendFactor::One:
    return 1.0f;
  case BlendFactor::SrcColor:
  case BlendFactor::SrcAlpha:
    return s[3];
  case BlendFactor::OneMinusSrcColor:
  case BlendFactor::OneMinusSrcAlpha:
    return 1.0f - s[3];
  case BlendFactor::DstColor:
  case BlendFactor::DstAlpha:
    return d[3];
  case BlendFactor::OneMinusDstColor:
  case BlendFactor::OneMinusDstAlpha:
    return 1.0f - d[3];
  case BlendFactor::ConstColor:
  case BlendFactor::ConstAlpha:
    return k[3];
  case BlendFactor::OneMinusConstColor:
  case BlendFactor::OneMinusConstAlpha:
    return 1.0f - k[3];
  case BlendFactor::SrcAlphaSaturate:
    return 1.0f;
  }
  return 0.0f;
}

// GL 2.1 table 4.1. MIN and MAX ignore the factors.
inline float apply_eq(BlendEq eq, float s, float d, float fs, float fd) {
  switch (eq) {
  case BlendEq::Add:
    return s * fs + d * fd;
  case BlendEq::Subtract:
    return s * fs - d * fd;
  case BlendEq::ReverseSubtract:
    return d * fd - s * fs;
  case BlendEq::Min:
    return std::min(s, d);
  case BlendEq::Max:
    return std::max(s, d);
  }
  return s;
}

inline uint8_t to_unorm8(float v) {
  v = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
  return static_cast<uint8_t>(v * 255.0f + 0.5f);
}

} // namespace blend_detail

// Blends one pixel. src and dst are unorm8 R,G,B,A; dst[3] must already be 255 for formats
// without alpha ("destination alpha reads as 1", GL 2.1 §4.1.8).
inline void blend_pixel(const BlendParams& bp, const uint8_t src[4], const uint8_t dst[4],
                        uint8_t out[4]) {
  using namespace blend_detail;
  constexpr float k255 = 1.0f / 255.0f;
  const float s[4] = {src[0] * k255, src[1] * k255, src[2] * k255, src[3] * k255};
  const float d[4] = {dst[0] * k255, dst[1] * k255, dst[2] * k255, dst[3] * k255};
  float fs[3], fd[3];
  rgb_factor(bp.src_rgb, s, d, bp.constant, fs);
  rgb_factor(bp.dst_rgb, s, d, bp.constant, fd);
  for (int i = 0; i < 3; ++i)
    out[i] = to_unorm8(apply_eq(bp.eq_rgb, s[i], d[i], fs[i], fd[i]));
  const float fsa = alpha_factor(bp.src_a, s, d, bp.constant);
  const float fda = alpha_factor(bp.dst_a, s, d, bp.constant);
  out[3] = to_unorm8(apply_eq(bp.eq_a, s[3], d[3], fsa, fda));
}

// SRC_ALPHA, ONE_MINUS_SRC_ALPHA, FUNC_ADD in exact unorm8: round((s*a + d*(255-a)) / 255).
// The numerator is never k*255 + 127.5, so adding 127 and dividing rounds to nearest.
inline uint8_t blend_over_channel(unsigned s, unsigned d, unsigned a) {
  return static_cast<uint8_t>((s * a + d * (255u - a) + 127u) / 255u);
}

} // namespace pineda
