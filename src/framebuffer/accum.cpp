// Accumulation buffer operations (GL 2.1 §4.2.4). The buffer holds RGBA as signed 16-bit
// fixed point (v / 32767), the format Mesa gives OSMesa contexts, and every step rounds the
// way Mesa's software path (what llvmpipe runs for glAccum) does: products truncate toward
// zero into 16 bits, RETURN rounds to the nearest colour value. Values that leave the 16-bit
// range wrap, as Mesa's do on x86; GL 2.1 §4.2.4 leaves such results undefined.
#include "framebuffer/accum.h"

#include <cmath>
#include <cstddef>

namespace pineda {

namespace {

// Byte offsets of R, G, B, A in a stored colour pixel (framebuffer.h ColorFormat); -1 for a
// channel the format does not store.
struct ColorLayout {
  int off[4];
  int bpp;
};

ColorLayout layout_of(ColorFormat f) {
  switch (f) {
  case ColorFormat::BGRA8:
    return {{2, 1, 0, 3}, 4};
  case ColorFormat::ARGB8:
    return {{1, 2, 3, 0}, 4};
  case ColorFormat::RGB8:
    return {{0, 1, 2, -1}, 3};
  case ColorFormat::RGBA8:
    break;
  }
  return {{0, 1, 2, 3}, 4};
}

// C's (short) of a float as x86 computes it: truncation to a 32-bit integer (out-of-range
// and NaN give INT32_MIN), then the low 16 bits. Written without undefined behaviour.
int16_t trunc_short(float f) {
  int32_t i = INT32_MIN;
  if (f > -2147483648.0f && f < 2147483648.0f) i = static_cast<int32_t>(f);
  return static_cast<int16_t>(static_cast<uint16_t>(static_cast<uint32_t>(i)));
}

int16_t wrap_add(int16_t a, int16_t b) {
  return static_cast<int16_t>(static_cast<uint16_t>(static_cast<uint32_t>(a + b)));
}

// Colour value to 8 bits: clamp to [0, 1], then round half to even (Mesa's float_to_unorm).
uint8_t to_unorm8(float f) {
  if (!(f > 0.0f)) return 0;
  if (f >= 1.0f) return 255;
  return static_cast<uint8_t>(std::nearbyint(f * 255.0f));
}

int16_t* accum_row(const Framebuffer& fb, int y) {
  return fb.accum + static_cast<ptrdiff_t>(y) * fb.width * 4;
}

} // namespace

int16_t accum_clear_value(float c) {
  // Mesa's FLOAT_TO_SHORT: ((int)(65535 c) - 1) / 2 in integer arithmetic.
  const int32_t i = static_cast<int32_t>(65535.0f * c);
  return static_cast<int16_t>((i - 1) / 2);
}

void accum_fill(Framebuffer& fb, const float c[4], const AccumRect& r) {
  if (fb.accum == nullptr) return;
  int16_t v[4];
  for (int k = 0; k < 4; ++k)
    v[k] = accum_clear_value(c[k]);
  for (int y = r.y0; y < r.y1; ++y) {
    int16_t* row = accum_row(fb, y);
    for (int x = r.x0; x < r.x1; ++x)
      for (int k = 0; k < 4; ++k)
        row[4 * x + k] = v[k];
  }
}

void accum_apply(Framebuffer& fb, GLenum op, float value, const AccumRect& r,
                 const bool color_write[4]) {
  if (fb.accum == nullptr || r.x0 >= r.x1 || r.y0 >= r.y1) return;
  const ColorLayout L = layout_of(fb.color_format);
  switch (op) {
  case GL_ACCUM:
  case GL_LOAD: {
    if (fb.color == nullptr) return;
    // Colours from the buffer as floats c / 255 (alpha 1 without alpha bits), times
    // value * 32767, truncated.
    const float scale = value * 32767.0f;
    const bool has_alpha = L.off[3] >= 0 && fb.alpha_bits > 0;
    for (int y = r.y0; y < r.y1; ++y) {
      int16_t* acc = accum_row(fb, y);
      const uint8_t* src = fb.color_row(y);
      for (int x = r.x0; x < r.x1; ++x) {
        const uint8_t* px = src + static_cast<ptrdiff_t>(x) * L.bpp;
        for (int k = 0; k < 4; ++k) {
          const float c = (k == 3 && !has_alpha) ? 1.0f : static_cast<float>(px[L.off[k]]) / 255.0f;
          const int16_t t = trunc_short(c * scale);
          int16_t& a = acc[4 * x + k];
          a = op == GL_LOAD ? t : wrap_add(a, t);
        }
      }
    }
    break;
  }
  case GL_ADD: {
    const int16_t incr = trunc_short(value * 32767.0f);
    for (int y = r.y0; y < r.y1; ++y) {
      int16_t* acc = accum_row(fb, y);
      for (int i = 4 * r.x0; i < 4 * r.x1; ++i)
        acc[i] = wrap_add(acc[i], incr);
    }
    break;
  }
  case GL_MULT:
    for (int y = r.y0; y < r.y1; ++y) {
      int16_t* acc = accum_row(fb, y);
      for (int i = 4 * r.x0; i < 4 * r.x1; ++i)
        acc[i] = trunc_short(static_cast<float>(acc[i]) * value);
    }
    break;
  case GL_RETURN: {
    if (fb.color == nullptr) return;
    // value / 32767 times the stored value, clamped to [0, 1], through the colour mask.
    const float scale = value / 32767.0f;
    for (int y = r.y0; y < r.y1; ++y) {
      const int16_t* acc = accum_row(fb, y);
      uint8_t* dst = fb.color_row(y);
      for (int x = r.x0; x < r.x1; ++x) {
        uint8_t* px = dst + static_cast<ptrdiff_t>(x) * L.bpp;
        for (int k = 0; k < 4; ++k)
          if (L.off[k] >= 0 && color_write[k])
            px[L.off[k]] = to_unorm8(static_cast<float>(acc[4 * x + k]) * scale);
      }
    }
    break;
  }
  default:
    break;
  }
}

} // namespace pineda
