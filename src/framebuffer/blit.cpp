// BlitFramebuffer's copies (blit.h).
#include "framebuffer/blit.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pineda {

namespace {

// Byte offsets of R, G, B, A in a stored pixel; -1 for a channel the format does not store.
struct Channels {
  int off[4];
  int bpp;
};

Channels channels_of(ColorFormat f) {
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

// The destination pixels [d0, d1) of one axis and, for each, the source coordinate of its
// centre (ARB_framebuffer_object §4.3.3: the destination rectangle is mapped onto the source
// rectangle, reversed ends mirror).
struct Axis {
  int d0 = 0, d1 = 0;
  double scale = 1.0; // source pixels per destination pixel, signed
  double origin = 0;  // source coordinate of destination coordinate 0
  double at(int d) const { return origin + (double(d) + 0.5) * scale; }
};

Axis make_axis(int s0, int s1, int d0, int d1, int lo, int hi) {
  Axis a;
  a.scale = double(s1 - s0) / double(d1 - d0);
  a.origin = double(s0) - double(d0) * a.scale;
  a.d0 = std::max(std::min(d0, d1), lo);
  a.d1 = std::min(std::max(d0, d1), hi);
  return a;
}

// The nearest source pixel of a coordinate, or -1 outside [0, size).
int nearest(double u, int size) {
  const double f = std::floor(u);
  return f >= 0.0 && f < double(size) ? int(f) : -1;
}

void read_rgba(const Framebuffer& fb, const Channels& c, int x, int y, float out[4]) {
  const uint8_t* p = fb.color_row(y) + ptrdiff_t(x) * c.bpp;
  for (int k = 0; k < 4; ++k)
    out[k] = c.off[k] >= 0 ? float(p[c.off[k]]) : 255.0f;
  if (fb.alpha_bits == 0) out[3] = 255.0f;
}

} // namespace

void blit_framebuffer(const Framebuffer& src, const Framebuffer& dst, const BlitRequest& r) {
  int lo_x = 0, lo_y = 0, hi_x = dst.width, hi_y = dst.height;
  if (r.scissor_test) {
    lo_x = std::max(lo_x, r.scissor[0]);
    lo_y = std::max(lo_y, r.scissor[1]);
    hi_x = int(std::min<int64_t>(hi_x, int64_t{r.scissor[0]} + r.scissor[2]));
    hi_y = int(std::min<int64_t>(hi_y, int64_t{r.scissor[1]} + r.scissor[3]));
  }
  if (r.dst[0] == r.dst[2] || r.dst[1] == r.dst[3] || r.src[0] == r.src[2] || r.src[1] == r.src[3])
    return;
  const Axis ax = make_axis(r.src[0], r.src[2], r.dst[0], r.dst[2], lo_x, hi_x);
  const Axis ay = make_axis(r.src[1], r.src[3], r.dst[1], r.dst[3], lo_y, hi_y);
  if (ax.d0 >= ax.d1 || ay.d0 >= ay.d1) return;
  const int w = ax.d1 - ax.d0, h = ay.d1 - ay.d0;
  // Source pixel of each destination column and row (-1: outside the read framebuffer).
  std::vector<int> sx(static_cast<size_t>(w)), sy(static_cast<size_t>(h));
  for (int i = 0; i < w; ++i)
    sx[size_t(i)] = nearest(ax.at(ax.d0 + i), src.width);
  for (int j = 0; j < h; ++j)
    sy[size_t(j)] = nearest(ay.at(ay.d0 + j), src.height);
  const size_t n = size_t(w) * size_t(h);

  if (r.color && src.color != nullptr && dst.color != nullptr) {
    // The whole source first, as 8-bit RGBA (every colour buffer stores 8-bit channels).
    const Channels sc = channels_of(src.color_format);
    std::vector<uint8_t> rgba(n * 4);
    std::vector<uint8_t> valid(n);
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const size_t o = size_t(j) * size_t(w) + size_t(i);
        const int x = sx[size_t(i)], y = sy[size_t(j)];
        if (x < 0 || y < 0) continue;
        valid[o] = 1;
        float c[4];
        if (!r.linear) {
          read_rgba(src, sc, x, y, c);
        } else {
          // Bilinear between the four pixels around the centre's source coordinate, clamped
          // to the read framebuffer's edges.
          const double u = ax.at(ax.d0 + i) - 0.5, v = ay.at(ay.d0 + j) - 0.5;
          const double fu = std::floor(u), fv = std::floor(v);
          const float wu = float(u - fu), wv = float(v - fv);
          const int x0 = std::clamp(int(fu), 0, src.width - 1);
          const int x1 = std::clamp(int(fu) + 1, 0, src.width - 1);
          const int y0 = std::clamp(int(fv), 0, src.height - 1);
          const int y1 = std::clamp(int(fv) + 1, 0, src.height - 1);
          float c00[4], c10[4], c01[4], c11[4];
          read_rgba(src, sc, x0, y0, c00);
          read_rgba(src, sc, x1, y0, c10);
          read_rgba(src, sc, x0, y1, c01);
          read_rgba(src, sc, x1, y1, c11);
          for (int k = 0; k < 4; ++k) {
            const float a = c00[k] + wu * (c10[k] - c00[k]);
            const float b = c01[k] + wu * (c11[k] - c01[k]);
            c[k] = a + wv * (b - a);
          }
        }
        for (int k = 0; k < 4; ++k)
          rgba[o * 4 + size_t(k)] = uint8_t(std::clamp(std::nearbyint(c[k]), 0.0f, 255.0f));
      }
    const Channels dc = channels_of(dst.color_format);
    const auto write = [&](uint8_t* base, ptrdiff_t stride) {
      for (int j = 0; j < h; ++j) {
        uint8_t* row = base + ptrdiff_t(ay.d0 + j) * stride + ptrdiff_t(ax.d0) * dc.bpp;
        for (int i = 0; i < w; ++i, row += dc.bpp) {
          const size_t o = size_t(j) * size_t(w) + size_t(i);
          if (!valid[o]) continue;
          for (int k = 0; k < 4; ++k)
            if (dc.off[k] >= 0) row[dc.off[k]] = rgba[o * 4 + size_t(k)];
        }
      }
    };
    write(dst.color, dst.color_stride);
    for (int t = 0; t < dst.more_count; ++t)
      write(dst.more[t].data, dst.more[t].stride);
  }

  if (r.depth && src.depth != nullptr && dst.depth != nullptr) {
    std::vector<uint32_t> z(n);
    std::vector<uint8_t> valid(n);
    // Equal formats are required (the state layer checks), so values copy as they are.
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const int x = sx[size_t(i)], y = sy[size_t(j)];
        if (x < 0 || y < 0) continue;
        const size_t o = size_t(j) * size_t(w) + size_t(i);
        z[o] = src.depth[ptrdiff_t(y) * src.depth_stride + x];
        valid[o] = 1;
      }
    for (int j = 0; j < h; ++j) {
      uint32_t* row = dst.depth + ptrdiff_t(ay.d0 + j) * dst.depth_stride + ax.d0;
      for (int i = 0; i < w; ++i) {
        const size_t o = size_t(j) * size_t(w) + size_t(i);
        if (valid[o]) row[i] = z[o];
      }
    }
  }

  if (r.stencil && src.stencil != nullptr && dst.stencil != nullptr) {
    std::vector<uint8_t> s(n);
    std::vector<uint8_t> valid(n);
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const int x = sx[size_t(i)], y = sy[size_t(j)];
        if (x < 0 || y < 0) continue;
        const size_t o = size_t(j) * size_t(w) + size_t(i);
        s[o] = src.stencil[ptrdiff_t(y) * src.stencil_stride + x];
        valid[o] = 1;
      }
    for (int j = 0; j < h; ++j) {
      uint8_t* row = dst.stencil + ptrdiff_t(ay.d0 + j) * dst.stencil_stride + ax.d0;
      for (int i = 0; i < w; ++i) {
        const size_t o = size_t(j) * size_t(w) + size_t(i);
        if (valid[o]) row[i] = s[o];
      }
    }
  }
}

} // namespace pineda
