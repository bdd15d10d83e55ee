// glReadPixels back end. Every colour channel of the framebuffer has 8 bits, so a colour
// component is one of 256 values k/255 and each destination type converts through a 256-entry
// table built per call. Depth and stencil values are converted one by one.
#include "framebuffer/read_pixels.h"

#include <GL/glext.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>

namespace pineda {

bool packed_layout(GLenum type, PackedLayout& out) {
  struct Entry {
    GLenum type;
    PackedLayout layout;
  };
  static constexpr Entry kTable[] = {
      {GL_UNSIGNED_BYTE_3_3_2, {3, 1, {5, 2, 0, 0}, {3, 3, 2, 0}}},
      {GL_UNSIGNED_BYTE_2_3_3_REV, {3, 1, {0, 3, 6, 0}, {3, 3, 2, 0}}},
      {GL_UNSIGNED_SHORT_5_6_5, {3, 2, {11, 5, 0, 0}, {5, 6, 5, 0}}},
      {GL_UNSIGNED_SHORT_5_6_5_REV, {3, 2, {0, 5, 11, 0}, {5, 6, 5, 0}}},
      {GL_UNSIGNED_SHORT_4_4_4_4, {4, 2, {12, 8, 4, 0}, {4, 4, 4, 4}}},
      {GL_UNSIGNED_SHORT_4_4_4_4_REV, {4, 2, {0, 4, 8, 12}, {4, 4, 4, 4}}},
      {GL_UNSIGNED_SHORT_5_5_5_1, {4, 2, {11, 6, 1, 0}, {5, 5, 5, 1}}},
      {GL_UNSIGNED_SHORT_1_5_5_5_REV, {4, 2, {0, 5, 10, 15}, {5, 5, 5, 1}}},
      {GL_UNSIGNED_INT_8_8_8_8, {4, 4, {24, 16, 8, 0}, {8, 8, 8, 8}}},
      {GL_UNSIGNED_INT_8_8_8_8_REV, {4, 4, {0, 8, 16, 24}, {8, 8, 8, 8}}},
      {GL_UNSIGNED_INT_10_10_10_2, {4, 4, {22, 12, 2, 0}, {10, 10, 10, 2}}},
      {GL_UNSIGNED_INT_2_10_10_10_REV, {4, 4, {0, 10, 20, 30}, {10, 10, 10, 2}}},
  };
  for (const Entry& e : kTable) {
    if (e.type == type) {
      out = e.layout;
      return true;
    }
  }
  return false;
}

namespace {

bool is_color_format(GLenum format) {
  switch (format) {
  case GL_RED:
  case GL_GREEN:
  case GL_BLUE:
  case GL_ALPHA:
  case GL_RGB:
  case GL_RGBA:
  case GL_BGR:
  case GL_BGRA:
  case GL_LUMINANCE:
  case GL_LUMINANCE_ALPHA: return true;
  default: return false;
  }
}

// Slots of the per-pixel component array the colour path builds: R, G, B, A, then
// L = clamp(R + G + B) (GL 2.1 §4.3.2 "Conversion to L").
enum Slot : uint8_t { kR, kG, kB, kA, kL };

// The components `format` writes, in memory order (Table 3.6).
int format_slots(GLenum format, uint8_t slots[4]) {
  auto set = [&](std::initializer_list<uint8_t> s) {
    std::copy(s.begin(), s.end(), slots);
    return static_cast<int>(s.size());
  };
  switch (format) {
  case GL_RED: return set({kR});
  case GL_GREEN: return set({kG});
  case GL_BLUE: return set({kB});
  case GL_ALPHA: return set({kA});
  case GL_RGB: return set({kR, kG, kB});
  case GL_RGBA: return set({kR, kG, kB, kA});
  case GL_BGR: return set({kB, kG, kR});
  case GL_BGRA: return set({kB, kG, kR, kA});
  case GL_LUMINANCE: return set({kL});
  case GL_LUMINANCE_ALPHA: return set({kL, kA});
  default: return 0;
  }
}

uint32_t max_of_bits(int bits) {
  return bits >= 32 ? 0xffffffffu : ((1u << bits) - 1u);
}

// Unsigned normalized conversion (Table 4.7, c = (2^N - 1) f) of f = v / src_max, rounded to
// nearest as §2.14.9 asks for colours. src_max is 2^m - 1, odd, so the quotient is never
// exactly halfway and adding (src_max - 1) / 2 before the floor division rounds correctly.
// The product stays below 2^64 for 32-bit operands.
uint32_t to_unorm(uint32_t v, uint32_t src_max, uint32_t dst_max) {
  const uint64_t num = static_cast<uint64_t>(v) * dst_max + (src_max - 1u) / 2u;
  return static_cast<uint32_t>(num / src_max);
}

// Signed conversion of Table 4.7, c = [(2^b - 1) f - 1] / 2, with f in [0, 1] after the clamp
// of §4.3.2 "Final Conversion". Rounding to nearest with halves going up turns this into
// floor((2^b - 1) f / 2), which for 8-bit colour is k >> 1, what Mesa returns as well.
uint32_t to_snorm(uint32_t v, uint32_t src_max, uint32_t dst_unsigned_max) {
  const uint64_t num = static_cast<uint64_t>(v) * dst_unsigned_max;
  return static_cast<uint32_t>(num / (2u * static_cast<uint64_t>(src_max)));
}

// Depth to UNSIGNED_INT: (2^32 - 1) f by repeating the m-bit value down the word. This is
// within one of the exact product, leaves 16- and 32-bit depth exact, and is what Mesa does
// for 24-bit depth, so GL_UNSIGNED_INT depth reads agree with it to the bit.
uint32_t replicate_to_32(uint32_t d, int bits) {
  if (bits >= 32) return d;
  uint64_t r = 0;
  for (int s = 32 - bits; s > -bits; s -= bits) r |= s >= 0 ? uint64_t{d} << s : d >> -s;
  return static_cast<uint32_t>(r);
}

uint16_t bswap(uint16_t v) { return static_cast<uint16_t>((v >> 8) | (v << 8)); }
uint32_t bswap(uint32_t v) { return __builtin_bswap32(v); }

// Stores one element at an arbitrary (possibly unaligned) address, byte-swapped when
// PACK_SWAP_BYTES asks for it (Table 3.7).
template <typename T>
void put(uint8_t* p, T value, bool swap) {
  if constexpr (sizeof(T) == 2) {
    uint16_t u = std::bit_cast<uint16_t>(value);
    if (swap) u = bswap(u);
    std::memcpy(p, &u, 2);
  } else if constexpr (sizeof(T) == 4) {
    uint32_t u = std::bit_cast<uint32_t>(value);
    if (swap) u = bswap(u);
    std::memcpy(p, &u, 4);
  } else {
    std::memcpy(p, &value, 1);
  }
}

// Where the packed image lives in client memory (§3.6.4, eq. 3.12-3.14).
struct Placement {
  size_t group_bytes = 0; // 0 for BITMAP
  size_t row_stride = 0;
  size_t origin = 0;      // byte offset of the first group of row 0 (BITMAP: of its byte)
  size_t origin_bit = 0;  // BITMAP only: bits skipped in the first byte's run
};

size_t round_up(size_t v, size_t a) { return (v + a - 1) / a * a; }

bool placement(int w, GLenum format, GLenum type, const PixelStore& pack, Placement& out) {
  const size_t a = pack.alignment > 0 ? static_cast<size_t>(pack.alignment) : 1;
  const size_t l = static_cast<size_t>(pack.row_length > 0 ? pack.row_length : std::max(w, 0));
  const size_t skip_rows = static_cast<size_t>(std::max(pack.skip_rows, 0));
  const size_t skip_pixels = static_cast<size_t>(std::max(pack.skip_pixels, 0));
  if (type == GL_BITMAP) {
    // Eq. 3.14: k = a * ceil(l / 8a) ubytes; SKIP_PIXELS counts bits.
    out.row_stride = a * ((l + 8 * a - 1) / (8 * a));
    out.group_bytes = 0;
    out.origin = skip_rows * out.row_stride;
    out.origin_bit = skip_pixels;
    return true;
  }
  const int n = pixel_format_components(format);
  const int s = pixel_type_size(type);
  if (n == 0 || s == 0) return false;
  // A packed type is a single element per group (§3.6.4, after Table 3.12).
  out.group_bytes = is_packed_pixel_type(type) ? static_cast<size_t>(s) : static_cast<size_t>(n * s);
  // Eq. 3.13: k = nl when s >= a, else (a/s) ceil(snl/a). Sizes and alignments are powers of
  // two, so s >= a makes nl s a multiple of a already and both cases round nls up to a.
  out.row_stride = round_up(l * out.group_bytes, a);
  out.origin = skip_pixels * out.group_bytes + skip_rows * out.row_stride;
  out.origin_bit = 0;
  return true;
}

// The part of the requested rectangle inside the framebuffer; x and y are in window space.
struct Span {
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  bool empty() const { return x0 >= x1 || y0 >= y1; }
};

Span clip_to(const Framebuffer& fb, int x, int y, int w, int h) {
  // 64-bit sums: x + w may overflow int.
  Span s;
  s.x0 = static_cast<int>(std::max<int64_t>(x, 0));
  s.y0 = static_cast<int>(std::max<int64_t>(y, 0));
  s.x1 = static_cast<int>(std::min<int64_t>(int64_t{x} + w, fb.width));
  s.y1 = static_cast<int>(std::min<int64_t>(int64_t{y} + h, fb.height));
  return s;
}

// Byte order of the client data as colour components, when every component is an 8-bit
// unsigned value so a framebuffer row with the same order can be copied as is. Returns the
// number of bytes per pixel described in `order`, 0 when no byte copy can produce the data.
int client_byte_order(GLenum format, GLenum type, bool swap, uint8_t order[4]) {
  uint8_t slots[4];
  const int n = format_slots(format, slots);
  if (n == 0) return 0;
  if (type == GL_UNSIGNED_BYTE) {
    if (format == GL_LUMINANCE || format == GL_LUMINANCE_ALPHA) return 0;
    std::copy(slots, slots + n, order);
    return n;
  }
  if (type != GL_UNSIGNED_INT_8_8_8_8 && type != GL_UNSIGNED_INT_8_8_8_8_REV) return 0;
  if (n != 4) return 0;
  // The uint32's bytes in memory: native order, reversed by SWAP_BYTES.
  const bool little = (std::endian::native == std::endian::little) != swap;
  PackedLayout layout;
  packed_layout(type, layout);
  for (int c = 0; c < 4; ++c) {
    const int byte_index = layout.shift[c] / 8;
    order[little ? byte_index : 3 - byte_index] = slots[c];
  }
  return 4;
}

int framebuffer_byte_order(const Framebuffer& fb, uint8_t order[4]) {
  const auto set = [&](uint8_t a, uint8_t b, uint8_t c, uint8_t d) {
    order[0] = a, order[1] = b, order[2] = c, order[3] = d;
  };
  switch (fb.color_format) {
  case ColorFormat::RGBA8: set(kR, kG, kB, kA); return 4;
  case ColorFormat::BGRA8: set(kB, kG, kR, kA); return 4;
  case ColorFormat::ARGB8: set(kA, kR, kG, kB); return 4;
  case ColorFormat::RGB8: set(kR, kG, kB, kA); return 3;
  }
  return 0;
}

// True when the client bytes equal the framebuffer bytes, so rows can be memcpy'd (the common
// glReadPixels(GL_RGBA, GL_UNSIGNED_BYTE) on an RGBA8 buffer among others). A framebuffer
// without alpha bits must report A = 1.0 (§4.3.2), which its bytes need not hold.
bool can_copy_bytes(const Framebuffer& fb, GLenum format, GLenum type, bool swap) {
  uint8_t want[4], have[4];
  const int n = client_byte_order(format, type, swap, want);
  const int bpp = framebuffer_byte_order(fb, have);
  if (n == 0 || n != bpp) return false;
  if (fb.alpha_bits == 0 && std::find(want, want + n, kA) != want + n) return false;
  return std::equal(want, want + n, have);
}

// One framebuffer row segment as R, G, B, A bytes.
void fetch_rgba(const Framebuffer& fb, int x, int y, int count, uint8_t* rgba) {
  const uint8_t* src = fb.color_row(y) + static_cast<ptrdiff_t>(x) * bytes_per_pixel(fb.color_format);
  // Byte index of R, G, B and A within a pixel; -1: no alpha byte.
  int r = 0, g = 1, b = 2, a = 3;
  switch (fb.color_format) {
  case ColorFormat::RGBA8: std::memcpy(rgba, src, static_cast<size_t>(count) * 4); break;
  case ColorFormat::BGRA8: r = 2, b = 0; break;
  case ColorFormat::ARGB8: r = 1, g = 2, b = 3, a = 0; break;
  case ColorFormat::RGB8: a = -1; break;
  }
  if (fb.color_format != ColorFormat::RGBA8) {
    const int bpp = bytes_per_pixel(fb.color_format);
    for (int i = 0; i < count; ++i) {
      const uint8_t* p = src + i * bpp;
      uint8_t* q = rgba + i * 4;
      q[0] = p[r], q[1] = p[g], q[2] = p[b], q[3] = a >= 0 ? p[a] : 255;
    }
  }
  // GL 2.1 §4.3.2: with no alpha in the framebuffer, A reads as 1.0.
  if (fb.alpha_bits == 0) {
    for (int i = 0; i < count; ++i) rgba[i * 4 + 3] = 255;
  }
}

constexpr int kChunk = 256; // pixels converted per step of the colour path

// Component array with L appended (Slot order), clamped per §4.3.2 "Final Conversion".
inline void expand(const uint8_t* rgba, uint8_t v[5]) {
  v[kR] = rgba[0], v[kG] = rgba[1], v[kB] = rgba[2], v[kA] = rgba[3];
  v[kL] = static_cast<uint8_t>(std::min(255, rgba[0] + rgba[1] + rgba[2]));
}

template <typename T>
void pack_components(const uint8_t* rgba, int count, const uint8_t* slots, int n,
                     const T* table, bool swap, uint8_t* out) {
  for (int i = 0; i < count; ++i, rgba += 4) {
    uint8_t v[5];
    expand(rgba, v);
    for (int c = 0; c < n; ++c, out += sizeof(T)) put<T>(out, table[v[slots[c]]], swap);
  }
}

template <typename T>
void pack_packed(const uint8_t* rgba, int count, const uint8_t* slots,
                 const uint32_t (*fields)[256], int n, bool swap, uint8_t* out) {
  for (int i = 0; i < count; ++i, rgba += 4, out += sizeof(T)) {
    uint8_t v[5];
    expand(rgba, v);
    uint32_t word = 0;
    for (int c = 0; c < n; ++c) word |= fields[c][v[slots[c]]];
    put<T>(out, static_cast<T>(word), swap);
  }
}

// Converts a colour chunk into client memory; `out` is where its first group goes.
class ColorPacker {
public:
  bool init(GLenum format, GLenum type, bool swap) {
    swap_ = swap;
    type_ = type;
    n_ = format_slots(format, slots_);
    if (n_ == 0) return false;
    if (is_packed_pixel_type(type)) {
      // read_format_type_error has matched the format to the type (Table 3.8).
      packed_layout(type, layout_);
      for (int c = 0; c < n_; ++c) {
        const uint32_t max = max_of_bits(layout_.bits[c]);
        for (uint32_t k = 0; k < 256; ++k) fields_[c][k] = to_unorm(k, 255, max) << layout_.shift[c];
      }
      return true;
    }
    for (uint32_t k = 0; k < 256; ++k) {
      switch (type) {
      case GL_UNSIGNED_BYTE: u8_[k] = static_cast<uint8_t>(k); break;
      case GL_BYTE: u8_[k] = static_cast<uint8_t>(to_snorm(k, 255, 0xffu)); break;
      case GL_UNSIGNED_SHORT: u16_[k] = static_cast<uint16_t>(to_unorm(k, 255, 0xffffu)); break;
      case GL_SHORT: u16_[k] = static_cast<uint16_t>(to_snorm(k, 255, 0xffffu)); break;
      case GL_UNSIGNED_INT: u32_[k] = to_unorm(k, 255, 0xffffffffu); break;
      case GL_INT: u32_[k] = to_snorm(k, 255, 0xffffffffu); break;
      // Table 4.7: c = f, and f is exactly k / 255 as the float nearest to it.
      case GL_FLOAT: f32_[k] = static_cast<float>(k) / 255.0f; break;
      default: return false;
      }
    }
    return true;
  }

  void pack(const uint8_t* rgba, int count, uint8_t* out) const {
    switch (type_) {
    case GL_UNSIGNED_BYTE:
    case GL_BYTE: pack_components(rgba, count, slots_, n_, u8_, swap_, out); return;
    case GL_UNSIGNED_SHORT:
    case GL_SHORT: pack_components(rgba, count, slots_, n_, u16_, swap_, out); return;
    case GL_UNSIGNED_INT:
    case GL_INT: pack_components(rgba, count, slots_, n_, u32_, swap_, out); return;
    case GL_FLOAT: pack_components(rgba, count, slots_, n_, f32_, swap_, out); return;
    default: break;
    }
    switch (layout_.bytes) {
    case 1: pack_packed<uint8_t>(rgba, count, slots_, fields_, n_, swap_, out); return;
    case 2: pack_packed<uint16_t>(rgba, count, slots_, fields_, n_, swap_, out); return;
    default: pack_packed<uint32_t>(rgba, count, slots_, fields_, n_, swap_, out); return;
    }
  }

private:
  GLenum type_ = 0;
  bool swap_ = false;
  int n_ = 0;
  uint8_t slots_[4] = {};
  PackedLayout layout_;
  uint8_t u8_[256];
  uint16_t u16_[256];
  uint32_t u32_[256];
  float f32_[256];
  uint32_t fields_[4][256];
};

bool read_color(const Framebuffer& fb, const Span& s, int x, int y, GLenum format, GLenum type,
                const PixelStore& pack, const Placement& pl, uint8_t* dst) {
  if (fb.color == nullptr) return false;
  const size_t count = static_cast<size_t>(s.x1 - s.x0);
  const size_t lead = static_cast<size_t>(s.x0 - x) * pl.group_bytes;
  if (can_copy_bytes(fb, format, type, pack.swap_bytes)) {
    const size_t bpp = static_cast<size_t>(bytes_per_pixel(fb.color_format));
    for (int wy = s.y0; wy < s.y1; ++wy) {
      uint8_t* out = dst + pl.origin + static_cast<size_t>(wy - y) * pl.row_stride + lead;
      std::memcpy(out, fb.color_row(wy) + static_cast<ptrdiff_t>(s.x0) * static_cast<ptrdiff_t>(bpp),
                  count * bpp);
    }
    return true;
  }
  if (format == GL_RGBA && type == GL_UNSIGNED_BYTE) {
    // The colour path's intermediate is already the client layout: fetch straight into dst.
    for (int wy = s.y0; wy < s.y1; ++wy)
      fetch_rgba(fb, s.x0, wy, s.x1 - s.x0,
                 dst + pl.origin + static_cast<size_t>(wy - y) * pl.row_stride + lead);
    return true;
  }
  ColorPacker packer; // about 7 KB of tables, on the stack
  if (!packer.init(format, type, pack.swap_bytes)) return false;
  uint8_t rgba[kChunk * 4];
  for (int wy = s.y0; wy < s.y1; ++wy) {
    uint8_t* out = dst + pl.origin + static_cast<size_t>(wy - y) * pl.row_stride + lead;
    for (int wx = s.x0; wx < s.x1; wx += kChunk) {
      const int n = std::min(kChunk, s.x1 - wx);
      fetch_rgba(fb, wx, wy, n, rgba);
      packer.pack(rgba, n, out);
      out += static_cast<size_t>(n) * pl.group_bytes;
    }
  }
  return true;
}

// Writes one scalar per pixel (depth or stencil) for every row of the span; value(v) gives the
// converted element of type T for the buffer value v.
template <typename T, typename Src, typename Fn>
void pack_scalar_rows(const Src* buffer, int width, const Span& s, int x, int y,
                      const Placement& pl, bool swap, uint8_t* dst, Fn value) {
  for (int wy = s.y0; wy < s.y1; ++wy) {
    const Src* src = buffer + static_cast<ptrdiff_t>(wy) * width;
    uint8_t* out = dst + pl.origin + static_cast<size_t>(wy - y) * pl.row_stride +
                   static_cast<size_t>(s.x0 - x) * sizeof(T);
    for (int wx = s.x0; wx < s.x1; ++wx, out += sizeof(T)) put<T>(out, value(src[wx]), swap);
  }
}

// GL 2.1 §4.3.2 "Conversion of Depth values": d is a fixed-point value in [0, 1] with
// depth_bits bits; Table 4.7 turns it into the client type.
bool read_depth(const Framebuffer& fb, const Span& s, int x, int y, GLenum type,
                const PixelStore& pack, const Placement& pl, uint8_t* dst) {
  if (fb.depth == nullptr || fb.depth_bits <= 0) return false;
  const uint32_t max = fb.depth_max();
  const int bits = fb.depth_bits;
  const bool sw = pack.swap_bytes;
  switch (type) {
  case GL_UNSIGNED_BYTE:
    pack_scalar_rows<uint8_t>(fb.depth, fb.depth_stride, s, x, y, pl, sw, dst, [&](uint32_t d) {
      return static_cast<uint8_t>(to_unorm(d, max, 0xffu));
    });
    return true;
  case GL_BYTE:
    pack_scalar_rows<int8_t>(fb.depth, fb.depth_stride, s, x, y, pl, sw, dst, [&](uint32_t d) {
      return static_cast<int8_t>(to_snorm(d, max, 0xffu));
    });
    return true;
  case GL_UNSIGNED_SHORT:
    pack_scalar_rows<uint16_t>(fb.depth, fb.depth_stride, s, x, y, pl, sw, dst, [&](uint32_t d) {
      return static_cast<uint16_t>(to_unorm(d, max, 0xffffu));
    });
    return true;
  case GL_SHORT:
    pack_scalar_rows<int16_t>(fb.depth, fb.depth_stride, s, x, y, pl, sw, dst, [&](uint32_t d) {
      return static_cast<int16_t>(to_snorm(d, max, 0xffffu));
    });
    return true;
  case GL_UNSIGNED_INT:
    pack_scalar_rows<uint32_t>(fb.depth, fb.depth_stride, s, x, y, pl, sw, dst,
                               [&](uint32_t d) { return replicate_to_32(d, bits); });
    return true;
  case GL_INT:
    pack_scalar_rows<int32_t>(fb.depth, fb.depth_stride, s, x, y, pl, sw, dst, [&](uint32_t d) {
      return static_cast<int32_t>(to_snorm(d, max, 0xffffffffu));
    });
    return true;
  case GL_FLOAT: {
    // z = d / (2^m - 1): the double quotient is within half a double ulp, so rounding it to
    // float gives the float nearest the exact value.
    pack_scalar_rows<float>(fb.depth, fb.depth_stride, s, x, y, pl, sw, dst, [&](uint32_t d) {
      return static_cast<float>(static_cast<double>(d) / max);
    });
    return true;
  }
  default: return false;
  }
}

// GL 2.1 §4.3.2 "Final Conversion" for indices: mask per Table 4.6; FLOAT is not masked.
bool read_stencil(const Framebuffer& fb, const Span& s, int x, int y, GLenum type,
                  const PixelStore& pack, const Placement& pl, uint8_t* dst) {
  if (fb.stencil == nullptr) return false;
  const bool sw = pack.swap_bytes;
  switch (type) {
  case GL_UNSIGNED_BYTE:
    pack_scalar_rows<uint8_t>(fb.stencil, fb.stencil_stride, s, x, y, pl, sw, dst,
                              [](uint8_t v) { return v; });
    return true;
  case GL_BYTE:
    pack_scalar_rows<uint8_t>(fb.stencil, fb.stencil_stride, s, x, y, pl, sw, dst,
                              [](uint8_t v) { return static_cast<uint8_t>(v & 0x7f); });
    return true;
  // The wider masks of Table 4.6 keep all 8 stencil bits.
  case GL_UNSIGNED_SHORT:
  case GL_SHORT:
    pack_scalar_rows<uint16_t>(fb.stencil, fb.stencil_stride, s, x, y, pl, sw, dst,
                               [](uint8_t v) { return static_cast<uint16_t>(v); });
    return true;
  case GL_UNSIGNED_INT:
  case GL_INT:
    pack_scalar_rows<uint32_t>(fb.stencil, fb.stencil_stride, s, x, y, pl, sw, dst,
                               [](uint8_t v) { return static_cast<uint32_t>(v); });
    return true;
  case GL_FLOAT:
    pack_scalar_rows<float>(fb.stencil, fb.stencil_stride, s, x, y, pl, sw, dst,
                            [](uint8_t v) { return static_cast<float>(v); });
    return true;
  case GL_BITMAP: {
    // §3.6.4 BITMAP placement: bit order per PACK_LSB_FIRST; the index is masked to 1 bit.
    for (int wy = s.y0; wy < s.y1; ++wy) {
      const uint8_t* src = fb.stencil + static_cast<ptrdiff_t>(wy) * fb.stencil_stride;
      uint8_t* row = dst + pl.origin + static_cast<size_t>(wy - y) * pl.row_stride;
      for (int wx = s.x0; wx < s.x1; ++wx) {
        const size_t bit = pl.origin_bit + static_cast<size_t>(wx - x);
        const uint8_t mask = static_cast<uint8_t>(pack.lsb_first ? 1u << (bit % 8) : 0x80u >> (bit % 8));
        uint8_t& byte = row[bit / 8];
        byte = static_cast<uint8_t>((src[wx] & 1) ? byte | mask : byte & ~mask);
      }
    }
    return true;
  }
  default: return false;
  }
}

// EXT_packed_depth_stencil: one UNSIGNED_INT_24_8 per pixel, depth in the high 24 bits (the
// depth value converted to 24 bits as Table 4.7 converts it to an unsigned integer) and the
// stencil index in the low 8.
bool read_depth_stencil(const Framebuffer& fb, const Span& s, int x, int y, const PixelStore& pack,
                        const Placement& pl, uint8_t* dst) {
  if (fb.depth == nullptr || fb.stencil == nullptr || fb.depth_bits <= 0) return false;
  const double max = fb.depth_bits >= 32 ? 4294967295.0 : double(fb.depth_max());
  const bool sw = pack.swap_bytes;
  for (int wy = s.y0; wy < s.y1; ++wy) {
    const uint32_t* z = fb.depth + ptrdiff_t(wy) * fb.depth_stride;
    const uint8_t* st = fb.stencil + ptrdiff_t(wy) * fb.stencil_stride;
    uint8_t* out = dst + pl.origin + size_t(wy - y) * pl.row_stride + size_t(s.x0 - x) * 4;
    for (int wx = s.x0; wx < s.x1; ++wx, out += 4) {
      const uint32_t d24 =
          fb.depth_bits == 24 ? z[wx] : uint32_t(std::nearbyint(double(z[wx]) / max * 16777215.0));
      put<uint32_t>(out, (d24 << 8) | st[wx], sw);
    }
  }
  return true;
}

} // namespace

bool is_valid_read_format(GLenum format) {
  return is_color_format(format) || format == GL_COLOR_INDEX || format == GL_DEPTH_COMPONENT ||
         format == GL_STENCIL_INDEX || format == GL_DEPTH_STENCIL;
}

bool is_packed_pixel_type(GLenum type) {
  PackedLayout layout;
  return packed_layout(type, layout);
}

bool is_valid_type(GLenum type) {
  switch (type) {
  case GL_UNSIGNED_BYTE:
  case GL_BYTE:
  case GL_UNSIGNED_SHORT:
  case GL_SHORT:
  case GL_UNSIGNED_INT:
  case GL_INT:
  case GL_FLOAT:
  case GL_BITMAP:
  case GL_UNSIGNED_INT_24_8:
    return true;
  default: return is_packed_pixel_type(type);
  }
}

int pixel_format_components(GLenum format) {
  switch (format) {
  case GL_COLOR_INDEX:
  case GL_STENCIL_INDEX:
  case GL_DEPTH_COMPONENT:
  case GL_DEPTH_STENCIL:
    return 1;
  default: {
    uint8_t slots[4];
    return format_slots(format, slots);
  }
  }
}

int pixel_type_size(GLenum type) {
  switch (type) {
  case GL_UNSIGNED_BYTE:
  case GL_BYTE: return 1;
  case GL_UNSIGNED_SHORT:
  case GL_SHORT: return 2;
  case GL_UNSIGNED_INT:
  case GL_INT:
  case GL_FLOAT:
  case GL_UNSIGNED_INT_24_8:
    return 4;
  default: {
    PackedLayout layout;
    return packed_layout(type, layout) ? layout.bytes : 0;
  }
  }
}

GLenum read_format_type_error(GLenum format, GLenum type) {
  if (!is_valid_type(type)) return GL_INVALID_ENUM;
  // Table 3.8: 3-component packed types go with RGB, 4-component ones with RGBA or BGRA.
  // Checked before the format, as check_pixel_format_type (pixel/unpack.h) does: with an
  // unknown format both errors apply and Mesa reports this one.
  PackedLayout layout;
  if (packed_layout(type, layout)) {
    const bool ok = layout.components == 3 ? format == GL_RGB
                                           : (format == GL_RGBA || format == GL_BGRA);
    if (!ok) return GL_INVALID_OPERATION;
  }
  // EXT_packed_depth_stencil: UNSIGNED_INT_24_8 goes with DEPTH_STENCIL only
  // (INVALID_OPERATION, as packed types with another format), and DEPTH_STENCIL takes no
  // other type (INVALID_ENUM).
  if (type == GL_UNSIGNED_INT_24_8 && format != GL_DEPTH_STENCIL) return GL_INVALID_OPERATION;
  if (!is_valid_read_format(format)) return GL_INVALID_ENUM;
  if (format == GL_DEPTH_STENCIL && type != GL_UNSIGNED_INT_24_8) return GL_INVALID_ENUM;
  // §3.6.4: BITMAP with a format other than COLOR_INDEX or STENCIL_INDEX.
  if (type == GL_BITMAP && format != GL_COLOR_INDEX && format != GL_STENCIL_INDEX)
    return GL_INVALID_ENUM;
  // §4.3.2: COLOR_INDEX reads fail in RGBA mode, the only mode Pineda has.
  if (format == GL_COLOR_INDEX) return GL_INVALID_OPERATION;
  return GL_NO_ERROR;
}

bool read_pixels(const Framebuffer& fb, int x, int y, int w, int h, GLenum format, GLenum type,
                 const PixelStore& pack, void* dst) {
  if (read_format_type_error(format, type) != GL_NO_ERROR) return false;
  Placement pl;
  if (!placement(w, format, type, pack, pl)) return false;
  const bool both = format == GL_DEPTH_STENCIL;
  const bool depth = format == GL_DEPTH_COMPONENT || both;
  const bool stencil = format == GL_STENCIL_INDEX || both;
  if ((depth && fb.depth == nullptr) || (stencil && fb.stencil == nullptr) ||
      (!depth && !stencil && fb.color == nullptr))
    return false;
  if (w <= 0 || h <= 0) return true;
  const Span s = clip_to(fb, x, y, w, h);
  if (s.empty()) return true;
  uint8_t* out = static_cast<uint8_t*>(dst);
  if (both) return read_depth_stencil(fb, s, x, y, pack, pl, out);
  if (depth) return read_depth(fb, s, x, y, type, pack, pl, out);
  if (stencil) return read_stencil(fb, s, x, y, type, pack, pl, out);
  return read_color(fb, s, x, y, format, type, pack, pl, out);
}

size_t packed_row_stride(int w, GLenum format, GLenum type, const PixelStore& pack) {
  Placement pl;
  return placement(w, format, type, pack, pl) ? pl.row_stride : 0;
}

size_t packed_image_size(int w, int h, GLenum format, GLenum type, const PixelStore& pack) {
  if (w <= 0 || h <= 0) return 0;
  Placement pl;
  if (!placement(w, format, type, pack, pl)) return 0;
  const size_t last_row = pl.origin + static_cast<size_t>(h - 1) * pl.row_stride;
  if (type == GL_BITMAP) return last_row + (pl.origin_bit + static_cast<size_t>(w) + 7) / 8;
  return last_row + static_cast<size_t>(w) * pl.group_bytes;
}

} // namespace pineda
