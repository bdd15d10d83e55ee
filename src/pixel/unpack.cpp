// Client-memory pixel images: unpacking to float RGBA, depth and indices, and packing back.
// Elements are read and written one by one through memcpy (client data need not be aligned);
// layout, type and format decisions are made once per call.
#include "pixel/unpack.h"

#include <GL/glext.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <vector>

#include "framebuffer/read_pixels.h"

namespace pineda {

namespace {

// Where the elements of a group go in RGBA (Table 3.6): channel 0-3, or kLum for the
// luminance element that fills R, G and B (§3.6.4 "Conversion to RGB").
constexpr int8_t kLum = 4;

struct FormatMap {
  int n = 0;
  int8_t dst[4] = {};
};

bool format_map(GLenum format, FormatMap& m) {
  const auto set = [&](std::initializer_list<int8_t> d) {
    m.n = static_cast<int>(d.size());
    std::copy(d.begin(), d.end(), m.dst);
    return true;
  };
  switch (format) {
  case GL_RED:
    return set({0});
  case GL_GREEN:
    return set({1});
  case GL_BLUE:
    return set({2});
  case GL_ALPHA:
    return set({3});
  case GL_RGB:
    return set({0, 1, 2});
  case GL_RGBA:
    return set({0, 1, 2, 3});
  case GL_BGR:
    return set({2, 1, 0});
  case GL_BGRA:
    return set({2, 1, 0, 3});
  case GL_LUMINANCE:
    return set({kLum});
  case GL_LUMINANCE_ALPHA:
    return set({kLum, 3});
  default:
    return false;
  }
}

uint16_t load16(const uint8_t* p, bool swap) {
  uint16_t v;
  std::memcpy(&v, p, 2);
  return swap ? static_cast<uint16_t>((v >> 8) | (v << 8)) : v;
}

uint32_t load32(const uint8_t* p, bool swap) {
  uint32_t v;
  std::memcpy(&v, p, 4);
  return swap ? __builtin_bswap32(v) : v;
}

void store16(uint8_t* p, uint16_t v, bool swap) {
  if (swap) v = static_cast<uint16_t>((v >> 8) | (v << 8));
  std::memcpy(p, &v, 2);
}

void store32(uint8_t* p, uint32_t v, bool swap) {
  if (swap) v = __builtin_bswap32(v);
  std::memcpy(p, &v, 4);
}

// One element of a non-packed type as a float component (GL 2.1 Table 2.9).
float element_to_float(const uint8_t* p, GLenum type, bool swap) {
  switch (type) {
  case GL_UNSIGNED_BYTE:
    return static_cast<float>(p[0]) / 255.0f;
  case GL_BYTE:
    return (2.0f * static_cast<float>(static_cast<int8_t>(p[0])) + 1.0f) / 255.0f;
  case GL_UNSIGNED_SHORT:
    return static_cast<float>(load16(p, swap)) / 65535.0f;
  case GL_SHORT:
    return (2.0f * static_cast<float>(static_cast<int16_t>(load16(p, swap))) + 1.0f) / 65535.0f;
  case GL_UNSIGNED_INT:
    return static_cast<float>(static_cast<double>(load32(p, swap)) / 4294967295.0);
  case GL_INT:
    return static_cast<float>(
        (2.0 * static_cast<double>(static_cast<int32_t>(load32(p, swap))) + 1.0) / 4294967295.0);
  case GL_FLOAT:
    return std::bit_cast<float>(load32(p, swap));
  default:
    return 0.0f;
  }
}

// A float index as the integer §3.6.5 works with: the integer part, wrapped to 32 bits like
// the integer types (NaN and values beyond +-2^40 have no meaningful index and give 0).
uint32_t float_to_index(float f) {
  if (!(std::fabs(f) < 1099511627776.0f)) return 0;
  return static_cast<uint32_t>(static_cast<int64_t>(f));
}

// One element of any non-packed type (or one bit of BITMAP) as an index.
uint32_t element_to_index(const uint8_t* p, GLenum type, bool swap) {
  switch (type) {
  case GL_UNSIGNED_BYTE:
    return p[0];
  case GL_BYTE:
    return static_cast<uint32_t>(static_cast<int32_t>(static_cast<int8_t>(p[0])));
  case GL_UNSIGNED_SHORT:
    return load16(p, swap);
  case GL_SHORT:
    return static_cast<uint32_t>(static_cast<int32_t>(static_cast<int16_t>(load16(p, swap))));
  case GL_UNSIGNED_INT:
  case GL_INT:
    return load32(p, swap);
  case GL_FLOAT:
    return float_to_index(std::bit_cast<float>(load32(p, swap)));
  default:
    return 0;
  }
}

// Calls fn(row_pointer, first_output_group) for every row of every image.
template <typename Fn> void for_each_row(const ClientLayout& l, int w, int h, int d, Fn fn) {
  size_t group = 0;
  for (int z = 0; z < d; ++z)
    for (int y = 0; y < h; ++y, group += static_cast<size_t>(w))
      fn(l.row_offset(y, z), group);
}

void put_component(float* px, int8_t dst, float v) {
  if (dst == kLum)
    px[0] = px[1] = px[2] = v;
  else
    px[dst] = v;
}

// One row of component groups to RGBA (conversion to float, to RGB, final expansion).
void decode_color_row(const uint8_t* row, int w, GLenum type, const FormatMap& fm, bool swap,
                      float* rgba) {
  for (int i = 0; i < w; ++i) {
    float* px = rgba + static_cast<size_t>(i) * 4;
    px[0] = px[1] = px[2] = 0.0f;
    px[3] = 1.0f;
  }
  PackedLayout pl;
  if (packed_layout(type, pl)) {
    // §3.6.4: byte swapping comes before the fields are extracted; each field is c / (2^N - 1).
    for (int i = 0; i < w; ++i) {
      const uint8_t* p = row + static_cast<size_t>(i) * static_cast<size_t>(pl.bytes);
      const uint32_t word = pl.bytes == 1   ? p[0]
                            : pl.bytes == 2 ? load16(p, swap)
                                            : load32(p, swap);
      for (int c = 0; c < pl.components; ++c) {
        const uint32_t max = (1u << pl.bits[c]) - 1u;
        const float v = static_cast<float>((word >> pl.shift[c]) & max) / static_cast<float>(max);
        put_component(rgba + static_cast<size_t>(i) * 4, fm.dst[c], v);
      }
    }
    return;
  }
  if (type == GL_UNSIGNED_BYTE) { // the common case, without the per-element type switch
    for (int i = 0; i < w; ++i) {
      const uint8_t* p = row + static_cast<size_t>(i) * static_cast<size_t>(fm.n);
      for (int c = 0; c < fm.n; ++c)
        put_component(rgba + static_cast<size_t>(i) * 4, fm.dst[c],
                      static_cast<float>(p[c]) / 255.0f);
    }
    return;
  }
  const size_t s = static_cast<size_t>(pixel_type_size(type));
  for (int i = 0; i < w; ++i) {
    const uint8_t* p = row + static_cast<size_t>(i) * static_cast<size_t>(fm.n) * s;
    for (int c = 0; c < fm.n; ++c)
      put_component(rgba + static_cast<size_t>(i) * 4, fm.dst[c],
                    element_to_float(p + c * s, type, swap));
  }
}

// One row of indices; BITMAP elements are bits ordered by LSB_FIRST (§3.6.4).
void decode_index_row(const uint8_t* row, size_t first_bit, int w, GLenum type, bool swap,
                      bool lsb_first, uint32_t* out) {
  if (type == GL_BITMAP) {
    for (int i = 0; i < w; ++i) {
      const size_t bit = first_bit + static_cast<size_t>(i);
      const unsigned shift = lsb_first ? bit % 8 : 7 - bit % 8;
      out[i] = (row[bit / 8] >> shift) & 1u;
    }
    return;
  }
  const size_t s = static_cast<size_t>(pixel_type_size(type));
  for (int i = 0; i < w; ++i)
    out[i] = element_to_index(row + static_cast<size_t>(i) * s, type, swap);
}

float clamp01(float v) {
  return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
}

// Table 4.7 for a component already clamped to [0, 1]. Unsigned types round to nearest; the
// signed ones compute [(2^b - 1) f - 1] / 2 rounded with halves up, which is
// floor((2^b - 1) f / 2), as read_pixels.cpp does for the framebuffer's values.
uint32_t unorm(float f, double max) {
  return static_cast<uint32_t>(std::floor(static_cast<double>(f) * max + 0.5));
}
uint32_t snorm(float f, double unsigned_max) {
  return static_cast<uint32_t>(std::floor(static_cast<double>(f) * unsigned_max * 0.5));
}

void store_component(uint8_t* p, GLenum type, float f, bool swap) {
  switch (type) {
  case GL_UNSIGNED_BYTE:
    p[0] = static_cast<uint8_t>(unorm(f, 255.0));
    return;
  case GL_BYTE:
    p[0] = static_cast<uint8_t>(snorm(f, 255.0));
    return;
  case GL_UNSIGNED_SHORT:
    store16(p, static_cast<uint16_t>(unorm(f, 65535.0)), swap);
    return;
  case GL_SHORT:
    store16(p, static_cast<uint16_t>(snorm(f, 65535.0)), swap);
    return;
  case GL_UNSIGNED_INT:
    store32(p, unorm(f, 4294967295.0), swap);
    return;
  case GL_INT:
    store32(p, snorm(f, 4294967295.0), swap);
    return;
  case GL_FLOAT:
    store32(p, std::bit_cast<uint32_t>(f), swap);
    return;
  default:
    return;
  }
}

bool is_index_format(GLenum format) {
  return format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX;
}

} // namespace

GLenum check_pixel_format_type(GLenum format, GLenum type) {
  if (!is_valid_type(type)) return GL_INVALID_ENUM;
  // A packed type with a format it does not fit is INVALID_OPERATION even when the format is
  // no format at all: both errors apply, §2.5 leaves the choice open, and Mesa checks the
  // packed type first (piglit draw-pixels draws GL_RG with packed types and expects it).
  PackedLayout pl;
  if (packed_layout(type, pl)) {
    const bool ok =
        pl.components == 3 ? format == GL_RGB : (format == GL_RGBA || format == GL_BGRA);
    if (!ok) return GL_INVALID_OPERATION;
  }
  // EXT_packed_depth_stencil: UNSIGNED_INT_24_8 with DEPTH_STENCIL only, and no other type
  // with DEPTH_STENCIL.
  if (type == GL_UNSIGNED_INT_24_8 && format != GL_DEPTH_STENCIL) return GL_INVALID_OPERATION;
  if (!is_valid_read_format(format)) return GL_INVALID_ENUM;
  if (format == GL_DEPTH_STENCIL && type != GL_UNSIGNED_INT_24_8) return GL_INVALID_ENUM;
  if (type == GL_BITMAP && !is_index_format(format)) return GL_INVALID_ENUM;
  return GL_NO_ERROR;
}

bool client_layout(int w, int h, GLenum format, GLenum type, const PixelStore& st,
                   ClientLayout& out) {
  if (check_pixel_format_type(format, type) != GL_NO_ERROR) return false;
  const size_t a = st.alignment > 0 ? static_cast<size_t>(st.alignment) : 1;
  const size_t l = static_cast<size_t>(st.row_length > 0 ? st.row_length : std::max(w, 0));
  const size_t rows = static_cast<size_t>(st.image_height > 0 ? st.image_height : std::max(h, 0));
  const size_t skip_pixels = static_cast<size_t>(std::max(st.skip_pixels, 0));
  const size_t skip_rows = static_cast<size_t>(std::max(st.skip_rows, 0));
  const size_t skip_images = static_cast<size_t>(std::max(st.skip_images, 0));
  out = ClientLayout{};
  if (type == GL_BITMAP) {
    // Eq. 3.14: k = a ceil(l / 8a) ubytes; SKIP_PIXELS counts bits.
    out.row_stride = a * ((l + 8 * a - 1) / (8 * a));
    out.origin_bit = skip_pixels;
  } else {
    // A packed type is one element per group (§3.6.4, after Table 3.12).
    const size_t s = static_cast<size_t>(pixel_type_size(type));
    out.group_bytes =
        is_packed_pixel_type(type) ? s : s * static_cast<size_t>(pixel_format_components(format));
    // Eq. 3.13: sizes and alignments are powers of two, so when s >= a the row n l s is a
    // multiple of a already and both cases round it up to a.
    out.row_stride = (l * out.group_bytes + a - 1) / a * a;
  }
  out.image_stride = out.row_stride * rows;
  out.origin =
      skip_images * out.image_stride + skip_rows * out.row_stride + skip_pixels * out.group_bytes;
  return true;
}

size_t client_image_bytes(int w, int h, int d, GLenum format, GLenum type, const PixelStore& st) {
  if (w <= 0 || h <= 0 || d <= 0) return 0;
  ClientLayout l;
  if (!client_layout(w, h, format, type, st, l)) return 0;
  const size_t last_row = l.row_offset(h - 1, d - 1);
  if (type == GL_BITMAP) return last_row + (l.origin_bit + static_cast<size_t>(w) + 7) / 8;
  return last_row + static_cast<size_t>(w) * l.group_bytes;
}

void unpack_rgba(const void* pixels, int w, int h, int d, GLenum format, GLenum type,
                 const PixelStore& st, const PixelTransferView& xfer, float* out) {
  ClientLayout l;
  if (w <= 0 || h <= 0 || d <= 0 || !client_layout(w, h, format, type, st, l)) return;
  const uint8_t* base = static_cast<const uint8_t*>(pixels);
  if (format == GL_COLOR_INDEX) {
    std::vector<uint32_t> index(static_cast<size_t>(w));
    for_each_row(l, w, h, d, [&](size_t row, size_t group) {
      decode_index_row(base + row, l.origin_bit, w, type, st.swap_bytes, st.lsb_first,
                       index.data());
      color_index_to_rgba(xfer, index.data(), index.size(), out + group * 4);
    });
    return;
  }
  FormatMap fm;
  if (!format_map(format, fm)) return;
  const bool active = rgba_transfer_active(xfer);
  for_each_row(l, w, h, d, [&](size_t row, size_t group) {
    decode_color_row(base + row, w, type, fm, st.swap_bytes, out + group * 4);
    if (active) transfer_rgba(xfer, out + group * 4, static_cast<size_t>(w));
  });
}

void unpack_depth(const void* pixels, int w, int h, int d, GLenum type, const PixelStore& st,
                  const PixelTransferView& xfer, float* out) {
  ClientLayout l;
  if (w <= 0 || h <= 0 || d <= 0 || type == GL_BITMAP || is_packed_pixel_type(type) ||
      !client_layout(w, h, GL_DEPTH_COMPONENT, type, st, l))
    return;
  const uint8_t* base = static_cast<const uint8_t*>(pixels);
  const size_t s = static_cast<size_t>(pixel_type_size(type));
  for_each_row(l, w, h, d, [&](size_t row, size_t group) {
    for (int i = 0; i < w; ++i)
      out[group + static_cast<size_t>(i)] =
          element_to_float(base + row + static_cast<size_t>(i) * s, type, st.swap_bytes);
    transfer_depth(xfer, out + group, static_cast<size_t>(w));
  });
}

void unpack_depth_stencil(const void* pixels, int w, int h, int d, const PixelStore& st,
                          const PixelTransferView& xfer, float* depth, uint32_t* stencil) {
  ClientLayout l;
  if (w <= 0 || h <= 0 || d <= 0 ||
      !client_layout(w, h, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, st, l))
    return;
  const uint8_t* base = static_cast<const uint8_t*>(pixels);
  for_each_row(l, w, h, d, [&](size_t row, size_t group) {
    for (int i = 0; i < w; ++i) {
      const uint32_t v = load32(base + row + static_cast<size_t>(i) * 4, st.swap_bytes);
      depth[group + static_cast<size_t>(i)] = static_cast<float>(double(v >> 8) / 16777215.0);
      stencil[group + static_cast<size_t>(i)] = v & 0xffu;
    }
    transfer_depth(xfer, depth + group, static_cast<size_t>(w));
    transfer_stencil(xfer, stencil + group, static_cast<size_t>(w));
  });
}

void pack_depth_stencil(const float* depth, const uint32_t* stencil, int w, int h, int d,
                        const PixelStore& st, void* pixels) {
  ClientLayout l;
  if (w <= 0 || h <= 0 || d <= 0 ||
      !client_layout(w, h, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, st, l))
    return;
  uint8_t* base = static_cast<uint8_t*>(pixels);
  for_each_row(l, w, h, d, [&](size_t row, size_t group) {
    for (int i = 0; i < w; ++i) {
      const size_t g = group + static_cast<size_t>(i);
      const uint32_t z = uint32_t(std::nearbyint(double(clamp01(depth[g])) * 16777215.0));
      store32(base + row + static_cast<size_t>(i) * 4, (z << 8) | (stencil[g] & 0xffu),
              st.swap_bytes);
    }
  });
}

void unpack_index(const void* pixels, int w, int h, int d, GLenum format, GLenum type,
                  const PixelStore& st, const PixelTransferView& xfer, uint32_t* out) {
  ClientLayout l;
  if (w <= 0 || h <= 0 || d <= 0 || !is_index_format(format) ||
      !client_layout(w, h, format, type, st, l))
    return;
  const uint8_t* base = static_cast<const uint8_t*>(pixels);
  for_each_row(l, w, h, d, [&](size_t row, size_t group) {
    uint32_t* dst = out + group;
    decode_index_row(base + row, l.origin_bit, w, type, st.swap_bytes, st.lsb_first, dst);
    if (format == GL_STENCIL_INDEX) {
      transfer_stencil(xfer, dst, static_cast<size_t>(w));
    } else {
      for (int i = 0; i < w; ++i)
        dst[i] = shift_offset_index(xfer, dst[i]);
    }
  });
}

void pack_rgba(const float* rgba, int w, int h, int d, GLenum format, GLenum type,
               const PixelStore& st, void* pixels) {
  ClientLayout l;
  FormatMap fm;
  if (w <= 0 || h <= 0 || d <= 0 || !format_map(format, fm) ||
      !client_layout(w, h, format, type, st, l))
    return;
  uint8_t* base = static_cast<uint8_t*>(pixels);
  PackedLayout pl;
  const bool packed = packed_layout(type, pl);
  const size_t s = packed ? 0 : static_cast<size_t>(pixel_type_size(type));
  const bool swap = st.swap_bytes;
  for_each_row(l, w, h, d, [&](size_t row, size_t group) {
    uint8_t* out = base + row;
    for (int i = 0; i < w; ++i, out += l.group_bytes) {
      const float* px = rgba + (group + static_cast<size_t>(i)) * 4;
      // §4.3.2 "Conversion to L" (on the unclamped values), then "Final Conversion".
      float v[5];
      for (int c = 0; c < 4; ++c)
        v[c] = clamp01(px[c]);
      v[kLum] = clamp01(px[0] + px[1] + px[2]);
      if (packed) {
        uint32_t word = 0;
        for (int c = 0; c < pl.components; ++c)
          word |= unorm(v[fm.dst[c]], static_cast<double>((1u << pl.bits[c]) - 1u)) << pl.shift[c];
        if (pl.bytes == 1)
          out[0] = static_cast<uint8_t>(word);
        else if (pl.bytes == 2)
          store16(out, static_cast<uint16_t>(word), swap);
        else
          store32(out, word, swap);
      } else {
        for (int c = 0; c < fm.n; ++c)
          store_component(out + c * s, type, v[fm.dst[c]], swap);
      }
    }
  });
}

void pack_depth(const float* depth, int w, int h, int d, GLenum type, const PixelStore& st,
                void* pixels) {
  ClientLayout l;
  if (w <= 0 || h <= 0 || d <= 0 || type == GL_BITMAP || is_packed_pixel_type(type) ||
      !client_layout(w, h, GL_DEPTH_COMPONENT, type, st, l))
    return;
  uint8_t* base = static_cast<uint8_t*>(pixels);
  for_each_row(l, w, h, d, [&](size_t row, size_t group) {
    for (int i = 0; i < w; ++i)
      store_component(base + row + static_cast<size_t>(i) * l.group_bytes, type,
                      clamp01(depth[group + static_cast<size_t>(i)]), st.swap_bytes);
  });
}

void pack_index(const uint32_t* index, int w, int h, int d, GLenum type, const PixelStore& st,
                void* pixels) {
  ClientLayout l;
  if (w <= 0 || h <= 0 || d <= 0 || !client_layout(w, h, GL_STENCIL_INDEX, type, st, l)) return;
  uint8_t* base = static_cast<uint8_t*>(pixels);
  const bool swap = st.swap_bytes;
  for_each_row(l, w, h, d, [&](size_t row, size_t group) {
    uint8_t* out = base + row;
    for (int i = 0; i < w; ++i) {
      const uint32_t v = index[group + static_cast<size_t>(i)];
      uint8_t* p = out + static_cast<size_t>(i) * l.group_bytes;
      switch (type) {
      case GL_UNSIGNED_BYTE:
        p[0] = static_cast<uint8_t>(v);
        break;
      case GL_BYTE:
        p[0] = static_cast<uint8_t>(v & 0x7fu);
        break;
      case GL_UNSIGNED_SHORT:
        store16(p, static_cast<uint16_t>(v), swap);
        break;
      case GL_SHORT:
        store16(p, static_cast<uint16_t>(v & 0x7fffu), swap);
        break;
      case GL_UNSIGNED_INT:
        store32(p, v, swap);
        break;
      case GL_INT:
        store32(p, v & 0x7fffffffu, swap);
        break;
      case GL_FLOAT:
        store32(p, std::bit_cast<uint32_t>(static_cast<float>(v)), swap);
        break;
      case GL_BITMAP: {
        // §3.6.4 BITMAP placement with PACK_LSB_FIRST; the index is masked to 1 bit.
        const size_t bit = l.origin_bit + static_cast<size_t>(i);
        const uint8_t mask =
            static_cast<uint8_t>(st.lsb_first ? 1u << (bit % 8) : 0x80u >> (bit % 8));
        uint8_t& byte = out[bit / 8];
        byte = static_cast<uint8_t>((v & 1u) ? byte | mask : byte & ~mask);
        break;
      }
      default:
        break;
      }
    }
  });
}

} // namespace pineda
