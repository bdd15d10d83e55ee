// glClear (GL 2.1 §4.2.3) on the framebuffer's colour, depth and stencil surfaces.
//
// Every clear goes through one rectangle: the whole framebuffer, narrowed by the scissor box
// when the scissor test is on. Unmasked clears are plain fills: memset when all bytes of the value
// are equal, wide pattern stores otherwise, and one fill over the whole surface when its rows are
// contiguous. Masked clears read, merge and write (GL 2.1 §4.2.2: the colour, depth and
// stencil write masks apply to clears).
#include <GL/gl.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "framebuffer/clear.h"

namespace pineda {

namespace {

uint8_t to_unorm8(float c) {
  c = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f; // clear colour is clamped (GL 2.1 §4.2.3)
  return static_cast<uint8_t>(c * 255.0f + 0.5f);
}

// Stored bytes of the clear colour and the bytes the colour mask lets through, in memory
// order for the format.
void color_pixel(const Framebuffer& fb, const ClearState& cs, uint8_t px[4], uint8_t wr[4]) {
  int off[4] = {0, 1, 2, 3};
  switch (fb.color_format) {
  case ColorFormat::RGBA8:
    break;
  case ColorFormat::BGRA8:
    off[0] = 2;
    off[2] = 0;
    break;
  case ColorFormat::ARGB8:
    off[0] = 1;
    off[1] = 2;
    off[2] = 3;
    off[3] = 0;
    break;
  case ColorFormat::RGB8:
    off[3] = -1;
    break;
  }
  for (int k = 0; k < 4; ++k) {
    px[k] = 0;
    wr[k] = 0;
  }
  for (int k = 0; k < 4; ++k) {
    if (off[k] < 0) continue;
    px[off[k]] = to_unorm8(cs.color[k]);
    wr[off[k]] = cs.color_write[k] ? 0xff : 0x00;
  }
  // A 4-byte format without alpha bits stores nothing meaningful in the alpha byte; an
  // unmasked clear may fill it so that the common case stays a plain fill.
  if (fb.color_format != ColorFormat::RGB8 && fb.alpha_bits == 0 && cs.color_write[0] &&
      cs.color_write[1] && cs.color_write[2])
    wr[off[3]] = 0xff;
}

// Fills `count` pixels of `bpp` bytes with the pattern `px`.
void fill_pattern(uint8_t* dst, size_t count, int bpp, const uint8_t px[4]) {
  if (count == 0) return;
  bool uniform = true;
  for (int k = 1; k < bpp; ++k)
    uniform = uniform && px[k] == px[0];
  if (uniform) {
    std::memset(dst, px[0], count * static_cast<size_t>(bpp));
    return;
  }
  if (bpp == 4) {
    for (size_t i = 0; i < count; ++i)
      std::memcpy(dst + 4 * i, px, 4);
    return;
  }
  // 3-byte pixels: lay down a few pixels, then double the filled prefix.
  const size_t total = count * 3;
  std::memcpy(dst, px, 3);
  size_t done = 3;
  while (done < total) {
    const size_t n = std::min(done, total - done);
    std::memcpy(dst + done, dst, n);
    done += n;
  }
}

void clear_color(Framebuffer& fb, const ClearState& cs, const ClearRect& r) {
  if (fb.color == nullptr) return;
  const int bpp = bytes_per_pixel(fb.color_format);
  uint8_t px[4], wr[4];
  color_pixel(fb, cs, px, wr);
  bool all = true, none = true;
  for (int k = 0; k < bpp; ++k) {
    all = all && wr[k] == 0xff;
    none = none && wr[k] == 0;
  }
  if (none) return;
  const ptrdiff_t row_bytes = static_cast<ptrdiff_t>(fb.width) * bpp;
  if (all) {
    const bool whole_rows = r.x0 == 0 && r.x1 == fb.width;
    if (whole_rows && (fb.color_stride == row_bytes || fb.color_stride == -row_bytes)) {
      // Contiguous rows: one fill from the lowest address.
      const int low_row = fb.color_stride > 0 ? r.y0 : r.y1 - 1;
      fill_pattern(fb.color_row(low_row), static_cast<size_t>(r.w()) * r.h(), bpp, px);
      return;
    }
    for (int y = r.y0; y < r.y1; ++y)
      fill_pattern(fb.color_row(y) + static_cast<ptrdiff_t>(r.x0) * bpp, r.w(), bpp, px);
    return;
  }
  for (int y = r.y0; y < r.y1; ++y) {
    uint8_t* p = fb.color_row(y) + static_cast<ptrdiff_t>(r.x0) * bpp;
    for (int x = r.x0; x < r.x1; ++x, p += bpp)
      for (int k = 0; k < bpp; ++k)
        p[k] = static_cast<uint8_t>((p[k] & ~wr[k]) | (px[k] & wr[k]));
  }
}

void clear_depth(Framebuffer& fb, const ClearState& cs, const ClearRect& r) {
  if (fb.depth == nullptr || fb.depth_bits <= 0 || !cs.depth_write) return;
  // The clear depth is clamped to [0,1] (GL 2.1 §4.2.3) and converted like fragment depth:
  // round(z * (2^bits - 1)), in double so that 32-bit buffers are exact.
  const double zmax = fb.depth_bits >= 32 ? 4294967295.0 : static_cast<double>(fb.depth_max());
  const double z = std::clamp(cs.depth, 0.0, 1.0) * zmax + 0.5;
  const uint32_t v = static_cast<uint32_t>(z);
  if (r.x0 == 0 && r.x1 == fb.width && fb.depth_stride == fb.width) {
    std::fill_n(fb.depth + static_cast<ptrdiff_t>(r.y0) * fb.depth_stride,
                static_cast<size_t>(r.w()) * r.h(), v);
    return;
  }
  for (int y = r.y0; y < r.y1; ++y)
    std::fill_n(fb.depth + static_cast<ptrdiff_t>(y) * fb.depth_stride + r.x0, r.w(), v);
}

void clear_stencil(Framebuffer& fb, const ClearState& cs, const ClearRect& r) {
  if (fb.stencil == nullptr || fb.stencil_bits <= 0) return;
  // GL 2.1 §4.2.3: the clear value is masked to the stencil bits, then the write mask applies.
  const uint8_t value = static_cast<uint8_t>(cs.stencil & 0xff);
  const uint8_t wm = static_cast<uint8_t>(cs.stencil_writemask & 0xff);
  if (wm == 0) return;
  for (int y = r.y0; y < r.y1; ++y) {
    uint8_t* p = fb.stencil + static_cast<ptrdiff_t>(y) * fb.stencil_stride + r.x0;
    if (wm == 0xff) {
      std::memset(p, value, static_cast<size_t>(r.w()));
    } else {
      for (int x = 0; x < r.w(); ++x)
        p[x] = static_cast<uint8_t>((p[x] & ~wm) | (value & wm));
    }
  }
}

} // namespace

ClearRect clear_rect(const Framebuffer& fb, const ClearState& cs) {
  ClearRect r{0, 0, fb.width, fb.height};
  if (cs.scissor_test) {
    // GL 2.1 §4.2.3: clears pass the scissor test (§4.1.2) like fragments. 64-bit ends, so
    // that x + width cannot overflow.
    const int64_t x1 = int64_t{cs.scissor[0]} + cs.scissor[2];
    const int64_t y1 = int64_t{cs.scissor[1]} + cs.scissor[3];
    r.x0 = std::max(r.x0, cs.scissor[0]);
    r.y0 = std::max(r.y0, cs.scissor[1]);
    r.x1 = static_cast<int>(std::min<int64_t>(r.x1, x1));
    r.y1 = static_cast<int>(std::min<int64_t>(r.y1, y1));
  }
  return r;
}

void clear_buffers(Framebuffer& fb, const ClearState& cs, GLbitfield mask, const ClearRect& r) {
  if (r.w() <= 0 || r.h() <= 0) return;
  if (mask & GL_COLOR_BUFFER_BIT) clear_color(fb, cs, r);
  if (mask & GL_DEPTH_BUFFER_BIT) clear_depth(fb, cs, r);
  if (mask & GL_STENCIL_BUFFER_BIT) clear_stencil(fb, cs, r);
}

} // namespace pineda
