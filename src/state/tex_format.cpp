// Texture internal formats (GL 2.1 §3.8.1 Tables 3.15-3.17).
#include "state/tex_format.h"

#include <GL/glext.h>

#include <algorithm>
#include <cmath>

namespace pineda {

namespace {

TexFormatInfo colour(TexBase base, int r, int g, int b, int a, int l = 0, int i = 0) {
  TexFormatInfo f;
  f.base = base;
  f.r = uint8_t(r), f.g = uint8_t(g), f.b = uint8_t(b), f.a = uint8_t(a);
  f.l = uint8_t(l), f.i = uint8_t(i);
  return f;
}

TexFormatInfo depth(int bits) {
  TexFormatInfo f;
  f.depth = true;
  f.base = TexBase::Luminance;
  f.d = uint8_t(bits);
  return f;
}

// [0,1] to an unsigned normalized integer of `bits` bits, back to 8 bits (GL 2.1 §2.14.9 eq.
// 2.3 both ways, rounding to nearest).
uint8_t quantize(float x, int bits) {
  x = std::clamp(x, 0.0f, 1.0f);
  if (!(x == x)) x = 0.0f;
  const int stored = std::min(bits, 8);
  if (stored <= 0) return 0;
  const float max = float((1 << stored) - 1);
  // Round half up of a non-negative float, as lround: the sum is exact in double.
  const auto round = [](float v) { return int(double(v) + 0.5); };
  const int v = round(x * max);
  if (stored == 8) return uint8_t(v);
  return uint8_t(round(float(v) * 255.0f / max));
}

} // namespace

GLenum uncompressed_internal_format(GLenum internalformat) {
  switch (internalformat) {
  case GL_COMPRESSED_ALPHA:
    return GL_ALPHA;
  case GL_COMPRESSED_LUMINANCE:
    return GL_LUMINANCE;
  case GL_COMPRESSED_LUMINANCE_ALPHA:
    return GL_LUMINANCE_ALPHA;
  case GL_COMPRESSED_INTENSITY:
    return GL_INTENSITY;
  case GL_COMPRESSED_RGB:
    return GL_RGB;
  case GL_COMPRESSED_RGBA:
    return GL_RGBA;
  case GL_COMPRESSED_SRGB:
    return GL_SRGB;
  case GL_COMPRESSED_SRGB_ALPHA:
    return GL_SRGB_ALPHA;
  case GL_COMPRESSED_SLUMINANCE:
    return GL_SLUMINANCE;
  case GL_COMPRESSED_SLUMINANCE_ALPHA:
    return GL_SLUMINANCE_ALPHA;
  default:
    return internalformat;
  }
}

bool lookup_internal_format(GLint internalformat, TexFormatInfo& out) {
  using B = TexBase;
  switch (internalformat) {
  // The generic compressed formats (§3.8.1 Table 3.17) are stored uncompressed.
  case GL_COMPRESSED_ALPHA:
  case GL_ALPHA:
  case GL_ALPHA4:
  case GL_ALPHA8:
    out = colour(B::Alpha, 0, 0, 0, 8);
    return true;
  case GL_ALPHA12:
  case GL_ALPHA16:
    out = colour(B::Alpha, 0, 0, 0, 16);
    return true;
  case 1:
  case GL_COMPRESSED_LUMINANCE:
  case GL_LUMINANCE:
  case GL_LUMINANCE4:
  case GL_LUMINANCE8:
    out = colour(B::Luminance, 0, 0, 0, 0, 8);
    return true;
  case GL_LUMINANCE12:
  case GL_LUMINANCE16:
    out = colour(B::Luminance, 0, 0, 0, 0, 16);
    return true;
  case 2:
  case GL_COMPRESSED_LUMINANCE_ALPHA:
  case GL_LUMINANCE_ALPHA:
  case GL_LUMINANCE6_ALPHA2:
  case GL_LUMINANCE8_ALPHA8:
    out = colour(B::LuminanceAlpha, 0, 0, 0, 8, 8);
    return true;
  case GL_LUMINANCE4_ALPHA4:
    out = colour(B::LuminanceAlpha, 0, 0, 0, 4, 4);
    return true;
  case GL_LUMINANCE12_ALPHA4:
  case GL_LUMINANCE12_ALPHA12:
  case GL_LUMINANCE16_ALPHA16:
    out = colour(B::LuminanceAlpha, 0, 0, 0, 16, 16);
    return true;
  case GL_COMPRESSED_INTENSITY:
  case GL_INTENSITY:
  case GL_INTENSITY4:
  case GL_INTENSITY8:
    out = colour(B::Intensity, 0, 0, 0, 0, 0, 8);
    return true;
  case GL_INTENSITY12:
  case GL_INTENSITY16:
    out = colour(B::Intensity, 0, 0, 0, 0, 0, 16);
    return true;
  case GL_R3_G3_B2:
    out = colour(B::RGB, 3, 3, 2, 0);
    return true;
  case 3:
  case GL_COMPRESSED_RGB:
  case GL_RGB:
  case GL_RGB8:
    out = colour(B::RGB, 8, 8, 8, 0);
    return true;
  case GL_RGB4:
    out = colour(B::RGB, 4, 4, 4, 0);
    return true;
  case GL_RGB5:
    out = colour(B::RGB, 5, 5, 5, 0);
    return true;
  case GL_RGB10:
    out = colour(B::RGB, 10, 10, 10, 0);
    return true;
  case GL_RGB12:
  case GL_RGB16:
    out = colour(B::RGB, 16, 16, 16, 0);
    return true;
  case 4:
  case GL_COMPRESSED_RGBA:
  case GL_RGBA:
  case GL_RGBA8:
    out = colour(B::RGBA, 8, 8, 8, 8);
    return true;
  case GL_RGBA2:
  case GL_RGBA4:
    out = colour(B::RGBA, 4, 4, 4, 4);
    return true;
  case GL_RGB5_A1:
    out = colour(B::RGBA, 5, 5, 5, 1);
    return true;
  case GL_RGB10_A2:
    out = colour(B::RGBA, 10, 10, 10, 2);
    return true;
  case GL_RGBA12:
  case GL_RGBA16:
    out = colour(B::RGBA, 16, 16, 16, 16);
    return true;
  // GL 2.1 Tables 3.16, 3.17: the sRGB formats (their generic compressed forms stored
  // uncompressed, as the others).
  case GL_COMPRESSED_SRGB:
  case GL_SRGB:
  case GL_SRGB8:
    out = colour(B::RGB, 8, 8, 8, 0);
    out.srgb = true;
    return true;
  case GL_COMPRESSED_SRGB_ALPHA:
  case GL_SRGB_ALPHA:
  case GL_SRGB8_ALPHA8:
    out = colour(B::RGBA, 8, 8, 8, 8);
    out.srgb = true;
    return true;
  case GL_COMPRESSED_SLUMINANCE:
  case GL_SLUMINANCE:
  case GL_SLUMINANCE8:
    out = colour(B::Luminance, 0, 0, 0, 0, 8);
    out.srgb = true;
    return true;
  case GL_COMPRESSED_SLUMINANCE_ALPHA:
  case GL_SLUMINANCE_ALPHA:
  case GL_SLUMINANCE8_ALPHA8:
    out = colour(B::LuminanceAlpha, 0, 0, 0, 8, 8);
    out.srgb = true;
    return true;
  case GL_DEPTH_COMPONENT:
  case GL_DEPTH_COMPONENT24:
    out = depth(24);
    return true;
  case GL_DEPTH_COMPONENT16:
    out = depth(16);
    return true;
  case GL_DEPTH_COMPONENT32:
    out = depth(32);
    return true;
  // EXT_packed_depth_stencil.
  case GL_DEPTH_STENCIL:
  case GL_DEPTH24_STENCIL8:
    out = depth(24);
    out.s = 8;
    return true;
  default:
    return false;
  }
}

void rgba_to_texels(const TexFormatInfo& f, const float* rgba, int n, uint8_t* texels) {
  for (int k = 0; k < n; ++k, rgba += 4, texels += 4) {
    uint8_t* t = texels;
    switch (f.base) {
    case TexBase::Alpha:
      t[0] = t[1] = t[2] = 0;
      t[3] = quantize(rgba[3], f.a);
      break;
    case TexBase::Luminance:
      t[0] = t[1] = t[2] = quantize(rgba[0], f.l);
      t[3] = 255;
      break;
    case TexBase::LuminanceAlpha:
      t[0] = t[1] = t[2] = quantize(rgba[0], f.l);
      t[3] = quantize(rgba[3], f.a);
      break;
    case TexBase::Intensity:
      t[0] = t[1] = t[2] = t[3] = quantize(rgba[0], f.i);
      break;
    case TexBase::RGB:
      t[0] = quantize(rgba[0], f.r);
      t[1] = quantize(rgba[1], f.g);
      t[2] = quantize(rgba[2], f.b);
      t[3] = 255;
      break;
    case TexBase::RGBA:
      t[0] = quantize(rgba[0], f.r);
      t[1] = quantize(rgba[1], f.g);
      t[2] = quantize(rgba[2], f.b);
      t[3] = quantize(rgba[3], f.a);
      break;
    }
  }
}

void depth_to_texels(const TexFormatInfo& f, const float* z, int n, uint32_t* out) {
  const double max = depth_texel_max(f.d);
  for (int k = 0; k < n; ++k) {
    const float v = z[k] == z[k] ? std::clamp(z[k], 0.0f, 1.0f) : 0.0f;
    out[k] = uint32_t(std::nearbyint(double(v) * max));
  }
}

void texel_to_rgba(TexBase base, const uint8_t* t, float* rgba) {
  const float k = 1.0f / 255.0f;
  switch (base) {
  case TexBase::Alpha:
    rgba[0] = rgba[1] = rgba[2] = 0.0f, rgba[3] = t[3] * k;
    break;
  case TexBase::Luminance:
  case TexBase::Intensity:
    rgba[0] = t[0] * k, rgba[1] = rgba[2] = 0.0f, rgba[3] = 1.0f;
    break;
  case TexBase::LuminanceAlpha:
    rgba[0] = t[0] * k, rgba[1] = rgba[2] = 0.0f, rgba[3] = t[3] * k;
    break;
  case TexBase::RGB:
    rgba[0] = t[0] * k, rgba[1] = t[1] * k, rgba[2] = t[2] * k, rgba[3] = 1;
    break;
  case TexBase::RGBA:
    rgba[0] = t[0] * k, rgba[1] = t[1] * k, rgba[2] = t[2] * k, rgba[3] = t[3] * k;
    break;
  }
}

} // namespace pineda
