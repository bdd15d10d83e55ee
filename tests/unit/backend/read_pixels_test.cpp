// glReadPixels back end: conversions (GL 2.1 Table 4.7, Table 4.6), packed types (Tables
// 3.8-3.12), pack state (§3.6.4) and clipping to the framebuffer. Expected values are worked
// out by hand; the signed and packed conversions were also checked against Mesa's OSMesa.
#include <gtest/gtest.h>

#include <climits>
#include <cstdint>
#include <cstring>
#include <vector>

#include "framebuffer/read_pixels.h"

namespace pineda {
namespace {

// A framebuffer with its own storage. top_down stores row 0 last in memory (negative stride).
struct TestFb {
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;
  std::vector<uint8_t> stencil;
  Framebuffer fb;

  TestFb(int w, int h, ColorFormat cf = ColorFormat::RGBA8, bool top_down = false,
         int depth_bits = 24) {
    const int bpp = bytes_per_pixel(cf);
    color.assign(static_cast<size_t>(w * h * bpp), 0);
    depth.assign(static_cast<size_t>(w * h), 0);
    stencil.assign(static_cast<size_t>(w * h), 0);
    fb.width = w;
    fb.height = h;
    fb.color_format = cf;
    fb.alpha_bits = cf == ColorFormat::RGB8 ? 0 : 8;
    if (top_down) {
      fb.color = color.data() + static_cast<ptrdiff_t>((h - 1) * w * bpp);
      fb.color_stride = -static_cast<ptrdiff_t>(w * bpp);
    } else {
      fb.color = color.data();
      fb.color_stride = w * bpp;
    }
    fb.depth = depth.data();
    fb.depth_bits = depth_bits;
    fb.depth_stride = w;
    fb.stencil = stencil.data();
    fb.stencil_bits = 8;
    fb.stencil_stride = w;
  }

  void set(int x, int y, uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
    uint8_t* p = fb.color_row(y) + x * bytes_per_pixel(fb.color_format);
    switch (fb.color_format) {
    case ColorFormat::RGBA8: p[0] = r, p[1] = g, p[2] = b, p[3] = a; break;
    case ColorFormat::BGRA8: p[0] = b, p[1] = g, p[2] = r, p[3] = a; break;
    case ColorFormat::ARGB8: p[0] = a, p[1] = r, p[2] = g, p[3] = b; break;
    case ColorFormat::RGB8: p[0] = r, p[1] = g, p[2] = b; break;
    }
  }
  void set_depth(int x, int y, uint32_t d) { depth[static_cast<size_t>(y * fb.width + x)] = d; }
  void set_stencil(int x, int y, uint8_t s) { stencil[static_cast<size_t>(y * fb.width + x)] = s; }
};

PixelStore tight() {
  PixelStore p;
  p.alignment = 1;
  return p;
}

constexpr uint8_t kCanary = 0xab;

// Reads into a canary-filled buffer of `size` bytes.
std::vector<uint8_t> read(const TestFb& t, int x, int y, int w, int h, GLenum format,
                          GLenum type, const PixelStore& pack, size_t size) {
  std::vector<uint8_t> out(size, kCanary);
  EXPECT_TRUE(read_pixels(t.fb, x, y, w, h, format, type, pack, out.data()));
  return out;
}

template <typename T>
T at(const std::vector<uint8_t>& buf, size_t index) {
  T v;
  std::memcpy(&v, buf.data() + index * sizeof(T), sizeof(T));
  return v;
}

using Bytes = std::vector<uint8_t>;

// ---------------------------------------------------------------------------------------------
// Formats with GL_UNSIGNED_BYTE

TEST(ReadPixels, EveryFormatAsUnsignedByte) {
  TestFb t(2, 1);
  t.set(0, 0, 10, 20, 30, 40);
  t.set(1, 0, 200, 100, 50, 255);
  struct Case {
    GLenum format;
    Bytes expect;
  };
  const Case cases[] = {
      {GL_RED, {10, 200}},
      {GL_GREEN, {20, 100}},
      {GL_BLUE, {30, 50}},
      {GL_ALPHA, {40, 255}},
      {GL_RGB, {10, 20, 30, 200, 100, 50}},
      {GL_RGBA, {10, 20, 30, 40, 200, 100, 50, 255}},
      {GL_BGR, {30, 20, 10, 50, 100, 200}},
      {GL_BGRA, {30, 20, 10, 40, 50, 100, 200, 255}},
      // §4.3.2: L = R + G + B, clamped: 60 and 350 -> 255.
      {GL_LUMINANCE, {60, 255}},
      {GL_LUMINANCE_ALPHA, {60, 40, 255, 255}},
  };
  for (const Case& c : cases) {
    const Bytes got = read(t, 0, 0, 2, 1, c.format, GL_UNSIGNED_BYTE, tight(), c.expect.size() + 1);
    EXPECT_EQ(Bytes(got.begin(), got.end() - 1), c.expect) << std::hex << c.format;
    EXPECT_EQ(got.back(), kCanary) << std::hex << c.format;
  }
}

// ---------------------------------------------------------------------------------------------
// Table 4.7 conversions of one 8-bit component

TEST(ReadPixels, ComponentConversionsPerType) {
  const uint8_t ks[] = {0, 1, 2, 127, 128, 254, 255};
  TestFb t(7, 1);
  for (int i = 0; i < 7; ++i) t.set(i, 0, ks[i], 0, 0, 255);
  const PixelStore p = tight();

  const Bytes b = read(t, 0, 0, 7, 1, GL_RED, GL_BYTE, p, 7);
  // [(2^8 - 1) f - 1] / 2 with halves rounded up: k >> 1 (Mesa agrees).
  const int8_t expect_b[] = {0, 0, 1, 63, 64, 127, 127};
  for (int i = 0; i < 7; ++i) EXPECT_EQ(static_cast<int8_t>(b[i]), expect_b[i]) << i;

  const Bytes us = read(t, 0, 0, 7, 1, GL_RED, GL_UNSIGNED_SHORT, p, 14);
  const uint16_t expect_us[] = {0, 257, 514, 32639, 32896, 65278, 65535};
  for (int i = 0; i < 7; ++i) EXPECT_EQ(at<uint16_t>(us, i), expect_us[i]) << i;

  const Bytes s = read(t, 0, 0, 7, 1, GL_RED, GL_SHORT, p, 14);
  const int16_t expect_s[] = {0, 128, 257, 16319, 16448, 32639, 32767};
  for (int i = 0; i < 7; ++i) EXPECT_EQ(at<int16_t>(s, i), expect_s[i]) << i;

  const Bytes ui = read(t, 0, 0, 7, 1, GL_RED, GL_UNSIGNED_INT, p, 28);
  const uint32_t expect_ui[] = {0, 16843009u, 33686018u, 2139062143u, 2155905152u, 4278124286u,
                                4294967295u};
  for (int i = 0; i < 7; ++i) EXPECT_EQ(at<uint32_t>(ui, i), expect_ui[i]) << i;

  const Bytes si = read(t, 0, 0, 7, 1, GL_RED, GL_INT, p, 28);
  const int32_t expect_si[] = {0, 8421504, 16843009, 1069531071, 1077952576, 2139062143,
                               2147483647};
  for (int i = 0; i < 7; ++i) EXPECT_EQ(at<int32_t>(si, i), expect_si[i]) << i;

  const Bytes f = read(t, 0, 0, 7, 1, GL_RED, GL_FLOAT, p, 28);
  for (int i = 0; i < 7; ++i) EXPECT_EQ(at<float>(f, i), static_cast<float>(ks[i]) / 255.0f) << i;
  EXPECT_EQ(at<float>(f, 6), 1.0f);
  EXPECT_EQ(at<float>(f, 0), 0.0f);
}

// Each format with each non-packed type: the right components in the right order.
TEST(ReadPixels, EveryFormatWithEveryPlainType) {
  TestFb t(1, 1);
  t.set(0, 0, 255, 0, 128, 2);
  struct Format {
    GLenum format;
    std::vector<int> comps; // 8-bit values in memory order
  };
  const Format formats[] = {
      {GL_RED, {255}},
      {GL_GREEN, {0}},
      {GL_BLUE, {128}},
      {GL_ALPHA, {2}},
      {GL_RGB, {255, 0, 128}},
      {GL_RGBA, {255, 0, 128, 2}},
      {GL_BGR, {128, 0, 255}},
      {GL_BGRA, {128, 0, 255, 2}},
      {GL_LUMINANCE, {255}},
      {GL_LUMINANCE_ALPHA, {255, 2}},
  };
  for (const Format& f : formats) {
    const size_t n = f.comps.size();
    const Bytes ub = read(t, 0, 0, 1, 1, f.format, GL_UNSIGNED_BYTE, tight(), n);
    const Bytes b = read(t, 0, 0, 1, 1, f.format, GL_BYTE, tight(), n);
    const Bytes us = read(t, 0, 0, 1, 1, f.format, GL_UNSIGNED_SHORT, tight(), 2 * n);
    const Bytes s = read(t, 0, 0, 1, 1, f.format, GL_SHORT, tight(), 2 * n);
    const Bytes ui = read(t, 0, 0, 1, 1, f.format, GL_UNSIGNED_INT, tight(), 4 * n);
    const Bytes si = read(t, 0, 0, 1, 1, f.format, GL_INT, tight(), 4 * n);
    const Bytes fl = read(t, 0, 0, 1, 1, f.format, GL_FLOAT, tight(), 4 * n);
    for (size_t c = 0; c < n; ++c) {
      const int k = f.comps[c];
      const uint32_t uk = static_cast<uint32_t>(k);
      EXPECT_EQ(ub[c], k) << f.format;
      EXPECT_EQ(static_cast<int8_t>(b[c]), k / 2) << f.format;
      EXPECT_EQ(at<uint16_t>(us, c), uk * 257u) << f.format;
      EXPECT_EQ(at<int16_t>(s, c), static_cast<int>(uk * 257u / 2u)) << f.format;
      EXPECT_EQ(at<uint32_t>(ui, c), uk * 16843009u) << f.format;
      EXPECT_EQ(at<int32_t>(si, c), static_cast<int32_t>(uk * 16843009u / 2u)) << f.format;
      EXPECT_EQ(at<float>(fl, c), static_cast<float>(k) / 255.0f) << f.format;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Packed types: colour (255, 0, 128, 64). Rounded fields: 128 -> 2 of 3, 16 of 31, 8 of 15,
// 514 of 1023; 64 -> 4 of 15, 0 of 1, 1 of 3.

TEST(ReadPixels, PackedTypes) {
  TestFb t(1, 1);
  t.set(0, 0, 255, 0, 128, 64);
  struct Case {
    GLenum format, type;
    uint32_t expect;
  };
  const Case cases[] = {
      {GL_RGB, GL_UNSIGNED_BYTE_3_3_2, 0xe2},
      {GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV, 0x87},
      {GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 0xf810},
      {GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV, 0x801f},
      {GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, 0xf084},
      {GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_REV, 0x480f},
      {GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, 0xf820},
      {GL_RGBA, GL_UNSIGNED_SHORT_1_5_5_5_REV, 0x401f},
      {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, 0xff008040},
      {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8_REV, 0x408000ff},
      {GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, 0xffc00809},
      {GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, 0x602003ff},
      {GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4, 0x80f4},
      {GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV, 0x4f08},
      {GL_BGRA, GL_UNSIGNED_SHORT_5_5_5_1, 0x803e},
      {GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV, 0x7c10},
      {GL_BGRA, GL_UNSIGNED_INT_8_8_8_8, 0x8000ff40},
      {GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, 0x40ff0080},
      {GL_BGRA, GL_UNSIGNED_INT_10_10_10_2, 0x80800ffd},
      {GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV, 0x7ff00202},
  };
  for (const Case& c : cases) {
    const int size = pixel_type_size(c.type);
    const Bytes got = read(t, 0, 0, 1, 1, c.format, c.type, tight(), static_cast<size_t>(size) + 1);
    uint32_t v = 0;
    if (size == 1) v = got[0];
    if (size == 2) v = at<uint16_t>(got, 0);
    if (size == 4) v = at<uint32_t>(got, 0);
    EXPECT_EQ(v, c.expect) << std::hex << c.format << " " << c.type;
    EXPECT_EQ(got[static_cast<size_t>(size)], kCanary) << std::hex << c.type;
  }
}

// Field rounding on values where truncation and rounding differ (checked against Mesa).
TEST(ReadPixels, PackedFieldsRoundToNearest) {
  const uint8_t ks[] = {4, 5, 127, 128};
  TestFb t(4, 1);
  for (int i = 0; i < 4; ++i) t.set(i, 0, ks[i], ks[i], ks[i], 255);
  const Bytes got = read(t, 0, 0, 4, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, tight(), 8);
  const int expect_r[] = {0, 1, 15, 16}, expect_g[] = {1, 1, 31, 32};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(at<uint16_t>(got, i) >> 11, expect_r[i]) << i;
    EXPECT_EQ((at<uint16_t>(got, i) >> 5) & 63, expect_g[i]) << i;
  }
}

// ---------------------------------------------------------------------------------------------
// Pack state

TEST(ReadPixels, AlignmentPadsRows) {
  TestFb t(3, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      t.set(x, y, static_cast<uint8_t>(10 * y + x), 0, 0, 0);
  for (int a : {1, 2, 4, 8}) {
    PixelStore p;
    p.alignment = a;
    const size_t stride = (3 * 3 + static_cast<size_t>(a) - 1) / a * a; // 9, 10, 12, 16
    const Bytes got = read(t, 0, 0, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, p, stride + 9 + 1);
    EXPECT_EQ(got[0], 0);
    EXPECT_EQ(got[6], 2);
    EXPECT_EQ(got[stride], 10);
    EXPECT_EQ(got[stride + 6], 12);
    for (size_t i = 9; i < stride; ++i) EXPECT_EQ(got[i], kCanary) << a; // padding untouched
    EXPECT_EQ(got[stride + 9], kCanary) << a;
    EXPECT_EQ(packed_row_stride(3, GL_RGB, GL_UNSIGNED_BYTE, p), stride);
  }
}

TEST(ReadPixels, AlignmentAgainstElementSize) {
  // s >= a: k = n l elements, no padding; s < a: rounded up to a.
  PixelStore p;
  p.alignment = 2;
  EXPECT_EQ(packed_row_stride(3, GL_RGB, GL_UNSIGNED_SHORT, p), 18u);
  p.alignment = 8;
  EXPECT_EQ(packed_row_stride(3, GL_RGB, GL_UNSIGNED_SHORT, p), 24u);
  EXPECT_EQ(packed_row_stride(1, GL_RGB, GL_FLOAT, p), 16u);
  EXPECT_EQ(packed_row_stride(3, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, p), 8u);
}

TEST(ReadPixels, RowLengthAndSkips) {
  TestFb t(4, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x)
      t.set(x, y, static_cast<uint8_t>(16 * y + x), 0, 0, 0);
  PixelStore p;
  p.alignment = 1;
  p.row_length = 5;
  p.skip_pixels = 2;
  p.skip_rows = 1;
  // Groups are 1 byte (RED); row k = 5; start at 1 * 5 + 2 = 7.
  const Bytes got = read(t, 1, 1, 2, 2, GL_RED, GL_UNSIGNED_BYTE, p, 20);
  Bytes expect(20, kCanary);
  expect[7] = 17, expect[8] = 18;   // window row 1, x = 1..2
  expect[12] = 33, expect[13] = 34; // window row 2
  EXPECT_EQ(got, expect);
  EXPECT_EQ(packed_image_size(2, 2, GL_RED, GL_UNSIGNED_BYTE, p), 14u);
}

TEST(ReadPixels, SwapBytes) {
  TestFb t(1, 1);
  t.set(0, 0, 1, 128, 255, 64);
  PixelStore p = tight();
  p.swap_bytes = true;
  const Bytes us = read(t, 0, 0, 1, 1, GL_RED, GL_UNSIGNED_SHORT, p, 2);
  EXPECT_EQ(at<uint16_t>(us, 0), 0x0101); // 257 is symmetric
  const Bytes g = read(t, 0, 0, 1, 1, GL_GREEN, GL_UNSIGNED_SHORT, p, 2);
  EXPECT_EQ(at<uint16_t>(g, 0), 0x8080);
  const Bytes ui = read(t, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, p, 4);
  EXPECT_EQ(at<uint32_t>(ui, 0), 0x40ff8001u); // 0x0180ff40 swapped
  const Bytes s565 = read(t, 0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, p, 2);
  EXPECT_EQ(at<uint16_t>(s565, 0), 0x1f04); // R 0, G 32, B 31: 0x041f swapped
  const Bytes f = read(t, 0, 0, 1, 1, GL_BLUE, GL_FLOAT, p, 4);
  EXPECT_EQ(f, (Bytes{0x3f, 0x80, 0x00, 0x00})); // 1.0f big-endian
  const Bytes b = read(t, 0, 0, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, p, 3);
  EXPECT_EQ(b, (Bytes{1, 128, 255})); // bytes are not swapped
  const Bytes i = read(t, 0, 0, 1, 1, GL_BLUE, GL_INT, p, 4);
  EXPECT_EQ(i, (Bytes{0x7f, 0xff, 0xff, 0xff}));
}

// ---------------------------------------------------------------------------------------------
// Framebuffer layouts

TEST(ReadPixels, AllColorByteOrdersAndFastPaths) {
  const ColorFormat formats[] = {ColorFormat::RGBA8, ColorFormat::BGRA8, ColorFormat::ARGB8,
                                 ColorFormat::RGB8};
  for (ColorFormat cf : formats) {
    for (bool top_down : {false, true}) {
      TestFb t(3, 2, cf, top_down);
      t.set(0, 0, 1, 2, 3, 4);
      t.set(2, 1, 250, 251, 252, 253);
      const uint8_t a0 = cf == ColorFormat::RGB8 ? 255 : 4;
      const uint8_t a1 = cf == ColorFormat::RGB8 ? 255 : 253;
      for (int a : {1, 4}) {
        PixelStore p;
        p.alignment = a;
        const Bytes rgba = read(t, 0, 0, 3, 2, GL_RGBA, GL_UNSIGNED_BYTE, p, 24);
        EXPECT_EQ(Bytes(rgba.begin(), rgba.begin() + 4), (Bytes{1, 2, 3, a0}));
        EXPECT_EQ(Bytes(rgba.begin() + 20, rgba.end()), (Bytes{250, 251, 252, a1}));
        const Bytes bgra = read(t, 0, 0, 3, 2, GL_BGRA, GL_UNSIGNED_BYTE, p, 24);
        EXPECT_EQ(Bytes(bgra.begin(), bgra.begin() + 4), (Bytes{3, 2, 1, a0}));
        EXPECT_EQ(Bytes(bgra.begin() + 20, bgra.end()), (Bytes{252, 251, 250, a1}));
        const size_t stride = a == 1 ? 9 : 12;
        const Bytes rgb = read(t, 0, 0, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, p, stride + 9);
        EXPECT_EQ(Bytes(rgb.begin(), rgb.begin() + 3), (Bytes{1, 2, 3}));
        EXPECT_EQ(Bytes(rgb.begin() + static_cast<ptrdiff_t>(stride) + 6, rgb.end()),
                  (Bytes{250, 251, 252}));
        // The word types whose bytes can equal the framebuffer's.
        const Bytes w1 = read(t, 2, 1, 1, 1, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8, p, 4);
        EXPECT_EQ(at<uint32_t>(w1, 0), 0xfcfbfa00u | a1);
        const Bytes w2 = read(t, 2, 1, 1, 1, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8_REV, p, 4);
        EXPECT_EQ(at<uint32_t>(w2, 0), (uint32_t{a1} << 24) | 0x00fcfbfau);
      }
    }
  }
}

TEST(ReadPixels, MissingAlphaBitsReadAsOne) {
  for (ColorFormat cf : {ColorFormat::RGBA8, ColorFormat::BGRA8, ColorFormat::ARGB8}) {
    TestFb t(1, 1, cf);
    t.fb.alpha_bits = 0;
    t.set(0, 0, 9, 8, 7, 0);
    EXPECT_EQ(read(t, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, tight(), 4), (Bytes{9, 8, 7, 255}));
    EXPECT_EQ(read(t, 0, 0, 1, 1, GL_BGRA, GL_UNSIGNED_BYTE, tight(), 4), (Bytes{7, 8, 9, 255}));
    EXPECT_EQ(at<float>(read(t, 0, 0, 1, 1, GL_ALPHA, GL_FLOAT, tight(), 4), 0), 1.0f);
  }
}

TEST(ReadPixels, WideRowsCrossConversionChunks) {
  const int w = 600; // more than one 256-pixel chunk
  TestFb t(w, 2, ColorFormat::BGRA8);
  for (int x = 0; x < w; ++x) t.set(x, 1, static_cast<uint8_t>(x), static_cast<uint8_t>(x >> 8), 7, 9);
  const Bytes got = read(t, 0, 1, w, 1, GL_RGB, GL_UNSIGNED_BYTE, tight(), 3 * w);
  for (int x = 0; x < w; ++x) {
    ASSERT_EQ(got[static_cast<size_t>(3 * x)], static_cast<uint8_t>(x)) << x;
    ASSERT_EQ(got[static_cast<size_t>(3 * x + 1)], static_cast<uint8_t>(x >> 8)) << x;
  }
}

// ---------------------------------------------------------------------------------------------
// Clipping to the framebuffer

TEST(ReadPixels, RectanglePartlyOutsideLeavesOutsideBytes) {
  TestFb t(4, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      t.set(x, y, static_cast<uint8_t>(16 * y + x), 0, 0, 0);
  // 4x4 at (-2, -1): window x -2..1, y -1..2.
  const Bytes got = read(t, -2, -1, 4, 4, GL_RED, GL_UNSIGNED_BYTE, tight(), 16);
  Bytes expect(16, kCanary);
  for (int j = 1; j < 4; ++j)
    for (int i = 2; i < 4; ++i)
      expect[static_cast<size_t>(4 * j + i)] = static_cast<uint8_t>(16 * (j - 1) + (i - 2));
  EXPECT_EQ(got, expect);

  // Off the top-right corner; a larger rectangle than the framebuffer.
  const Bytes tr = read(t, 3, 2, 3, 3, GL_RED, GL_UNSIGNED_BYTE, tight(), 9);
  EXPECT_EQ(tr, (Bytes{35, kCanary, kCanary, 51, kCanary, kCanary, kCanary, kCanary, kCanary}));
  const Bytes big = read(t, -1, -1, 6, 6, GL_RED, GL_UNSIGNED_BYTE, tight(), 36);
  EXPECT_EQ(big[0], kCanary);
  EXPECT_EQ(big[7], 0);
  EXPECT_EQ(big[28], 51);
  EXPECT_EQ(big[29], kCanary);
  EXPECT_EQ(big[35], kCanary);
}

TEST(ReadPixels, RectanglesEntirelyOutsideOrAtIntLimitsTouchNothing) {
  TestFb t(4, 4);
  const Bytes none(64, kCanary);
  EXPECT_EQ(read(t, 4, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, tight(), 64), none);
  EXPECT_EQ(read(t, 0, -4, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, tight(), 64), none);
  EXPECT_EQ(read(t, INT_MAX - 1, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, tight(), 64), none);
  EXPECT_EQ(read(t, INT_MIN, INT_MIN, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, tight(), 64), none);
  EXPECT_EQ(read(t, 0, 0, 0, 4, GL_RGBA, GL_UNSIGNED_BYTE, tight(), 64), none);
  EXPECT_EQ(read(t, 0, 0, 4, -1, GL_RGBA, GL_UNSIGNED_BYTE, tight(), 64), none);
  // A wide rectangle starting far to the left: only the framebuffer's pixels are written.
  t.set(0, 0, 7, 0, 0, 0);
  t.set(3, 0, 9, 0, 0, 0);
  const Bytes wide = read(t, -1000, 0, 1010, 1, GL_RED, GL_UNSIGNED_BYTE, tight(), 1011);
  Bytes expect(1011, kCanary);
  expect[1000] = 7, expect[1001] = 0, expect[1002] = 0, expect[1003] = 9;
  EXPECT_EQ(wide, expect);
}

// ---------------------------------------------------------------------------------------------
// Depth: z = d / (2^m - 1) (§4.3.2), then Table 4.7.

TEST(ReadPixels, Depth16) {
  TestFb t(3, 1, ColorFormat::RGBA8, false, 16);
  t.set_depth(0, 0, 0);
  t.set_depth(1, 0, 32768);
  t.set_depth(2, 0, 65535);
  const Bytes f = read(t, 0, 0, 3, 1, GL_DEPTH_COMPONENT, GL_FLOAT, tight(), 12);
  EXPECT_EQ(at<float>(f, 0), 0.0f);
  EXPECT_EQ(at<float>(f, 1), static_cast<float>(32768.0 / 65535.0));
  EXPECT_EQ(at<float>(f, 2), 1.0f);
  const Bytes ui = read(t, 0, 0, 3, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, tight(), 12);
  EXPECT_EQ(at<uint32_t>(ui, 1), 32768u * 65537u); // exact: 2^32 - 1 = 65535 * 65537
  EXPECT_EQ(at<uint32_t>(ui, 2), 0xffffffffu);
  const Bytes us = read(t, 0, 0, 3, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, tight(), 6);
  EXPECT_EQ(at<uint16_t>(us, 1), 32768);
  EXPECT_EQ(at<uint16_t>(us, 2), 65535);
  const Bytes ub = read(t, 0, 0, 3, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, tight(), 3);
  EXPECT_EQ(ub, (Bytes{0, 128, 255})); // 127.50195 rounds up
}

TEST(ReadPixels, Depth24) {
  TestFb t(4, 1, ColorFormat::RGBA8, false, 24);
  const uint32_t ds[] = {0, 4194304, 11744050, 16777215};
  for (int i = 0; i < 4; ++i) t.set_depth(i, 0, ds[i]);
  // Values read back from Mesa's OSMesa after glClearDepth(0.25) and (0.7).
  const Bytes f = read(t, 0, 0, 4, 1, GL_DEPTH_COMPONENT, GL_FLOAT, tight(), 16);
  EXPECT_EQ(at<float>(f, 0), 0.0f);
  EXPECT_EQ(at<float>(f, 1), 0.25000003f);
  EXPECT_EQ(at<float>(f, 2), 0.7f);
  EXPECT_EQ(at<float>(f, 3), 1.0f);
  const Bytes ui = read(t, 0, 0, 4, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, tight(), 16);
  EXPECT_EQ(at<uint32_t>(ui, 1), 1073741888u);
  EXPECT_EQ(at<uint32_t>(ui, 2), 3006476979u);
  EXPECT_EQ(at<uint32_t>(ui, 3), 0xffffffffu);
  const Bytes us = read(t, 0, 0, 4, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, tight(), 8);
  EXPECT_EQ(at<uint16_t>(us, 1), 16384);
  EXPECT_EQ(at<uint16_t>(us, 2), 45874);
  EXPECT_EQ(at<uint16_t>(us, 3), 65535);
  const Bytes si = read(t, 0, 0, 4, 1, GL_DEPTH_COMPONENT, GL_INT, tight(), 16);
  EXPECT_EQ(at<int32_t>(si, 0), 0);
  EXPECT_EQ(at<int32_t>(si, 3), 2147483647);
  const Bytes ss = read(t, 0, 0, 4, 1, GL_DEPTH_COMPONENT, GL_SHORT, tight(), 8);
  EXPECT_EQ(at<int16_t>(ss, 1), 8191); // floor(65535 * 0.2500000149 / 2), as Mesa
  EXPECT_EQ(at<int16_t>(ss, 3), 32767);
}

TEST(ReadPixels, Depth32) {
  TestFb t(3, 1, ColorFormat::RGBA8, false, 32);
  t.set_depth(0, 0, 0);
  t.set_depth(1, 0, 0x80000000u);
  t.set_depth(2, 0, 0xffffffffu);
  const Bytes f = read(t, 0, 0, 3, 1, GL_DEPTH_COMPONENT, GL_FLOAT, tight(), 12);
  EXPECT_EQ(at<float>(f, 1), 0.5f);
  EXPECT_EQ(at<float>(f, 2), 1.0f);
  const Bytes ui = read(t, 0, 0, 3, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, tight(), 12);
  EXPECT_EQ(at<uint32_t>(ui, 1), 0x80000000u);
  EXPECT_EQ(at<uint32_t>(ui, 2), 0xffffffffu);
  const Bytes us = read(t, 0, 0, 3, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, tight(), 6);
  EXPECT_EQ(at<uint16_t>(us, 1), 32768); // 32767.50000763
  EXPECT_EQ(at<uint16_t>(us, 2), 65535);
}

TEST(ReadPixels, DepthPartlyOutsideAndSwapped) {
  TestFb t(2, 2, ColorFormat::RGBA8, false, 16);
  t.set_depth(1, 1, 0x1234);
  PixelStore p = tight();
  p.swap_bytes = true;
  const Bytes got = read(t, 1, 1, 2, 2, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, p, 8);
  EXPECT_EQ(got, (Bytes{0x12, 0x34, kCanary, kCanary, kCanary, kCanary, kCanary, kCanary}));
}

// ---------------------------------------------------------------------------------------------
// Stencil: indices masked per Table 4.6, FLOAT unmasked.

TEST(ReadPixels, StencilIndex) {
  TestFb t(4, 1);
  const uint8_t ss[] = {0, 1, 200, 255};
  for (int i = 0; i < 4; ++i) t.set_stencil(i, 0, ss[i]);
  EXPECT_EQ(read(t, 0, 0, 4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, tight(), 4),
            (Bytes{0, 1, 200, 255}));
  EXPECT_EQ(read(t, 0, 0, 4, 1, GL_STENCIL_INDEX, GL_BYTE, tight(), 4), (Bytes{0, 1, 72, 127}));
  const Bytes us = read(t, 0, 0, 4, 1, GL_STENCIL_INDEX, GL_SHORT, tight(), 8);
  EXPECT_EQ(at<int16_t>(us, 2), 200);
  const Bytes ui = read(t, 0, 0, 4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_INT, tight(), 16);
  EXPECT_EQ(at<uint32_t>(ui, 3), 255u);
  const Bytes si = read(t, 0, 0, 4, 1, GL_STENCIL_INDEX, GL_INT, tight(), 16);
  EXPECT_EQ(at<int32_t>(si, 2), 200);
  const Bytes f = read(t, 0, 0, 4, 1, GL_STENCIL_INDEX, GL_FLOAT, tight(), 16);
  EXPECT_EQ(at<float>(f, 2), 200.0f);
  EXPECT_EQ(at<float>(f, 3), 255.0f);
}

TEST(ReadPixels, StencilBitmap) {
  TestFb t(10, 2);
  for (int x = 0; x < 10; ++x) t.set_stencil(x, 0, static_cast<uint8_t>(x % 3 == 0 ? 1 : 2));
  t.set_stencil(9, 1, 3);
  // Bits 1,0,0,1,0,0,1,0,0,1 for row 0; row 1 only its last bit.
  PixelStore p;
  p.alignment = 1;
  std::vector<uint8_t> got(4, 0x00);
  ASSERT_TRUE(read_pixels(t.fb, 0, 0, 10, 2, GL_STENCIL_INDEX, GL_BITMAP, p, got.data()));
  EXPECT_EQ(got, (Bytes{0x92, 0x40, 0x00, 0x40}));
  p.lsb_first = true;
  std::fill(got.begin(), got.end(), 0xff);
  ASSERT_TRUE(read_pixels(t.fb, 0, 0, 10, 2, GL_STENCIL_INDEX, GL_BITMAP, p, got.data()));
  EXPECT_EQ(got, (Bytes{0x49, 0xfe, 0x00, 0xfe})); // bits past the 10th keep their value
  // SKIP_PIXELS counts bits; alignment 2 gives 2-byte rows either way here.
  p.lsb_first = false;
  p.skip_pixels = 3;
  p.alignment = 2;
  std::fill(got.begin(), got.end(), 0x00);
  ASSERT_TRUE(read_pixels(t.fb, 0, 0, 10, 2, GL_STENCIL_INDEX, GL_BITMAP, p, got.data()));
  EXPECT_EQ(got, (Bytes{0x12, 0x48, 0x00, 0x08}));
}

// ---------------------------------------------------------------------------------------------
// Sizes and validation

TEST(ReadPixels, PackedImageSize) {
  PixelStore p; // alignment 4
  EXPECT_EQ(packed_image_size(3, 2, GL_RGB, GL_UNSIGNED_BYTE, p), 12u + 9u);
  EXPECT_EQ(packed_image_size(3, 2, GL_RGB, GL_UNSIGNED_BYTE, tight()), 18u);
  EXPECT_EQ(packed_image_size(1, 1, GL_RGBA, GL_FLOAT, p), 16u);
  EXPECT_EQ(packed_image_size(0, 5, GL_RGBA, GL_UNSIGNED_BYTE, p), 0u);
  EXPECT_EQ(packed_image_size(5, 0, GL_RGBA, GL_UNSIGNED_BYTE, p), 0u);
  EXPECT_EQ(packed_image_size(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, p), 16u);
  EXPECT_EQ(packed_image_size(3, 3, GL_LUMINANCE_ALPHA, GL_SHORT, p), 12u + 12u + 12u);
  EXPECT_EQ(packed_image_size(1, 3, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, p), 4u + 4u + 2u);

  PixelStore q;
  q.alignment = 4;
  q.row_length = 5;
  q.skip_pixels = 1;
  q.skip_rows = 2;
  // Groups 4 bytes, row 20 bytes: start 4 + 40, then one more row and 3 groups.
  EXPECT_EQ(packed_image_size(3, 2, GL_RGBA, GL_UNSIGNED_BYTE, q), 44u + 20u + 12u);
  q.alignment = 8;
  // 565 groups are 2 bytes: row 10 rounded up to 16; start 2 + 32.
  EXPECT_EQ(packed_image_size(3, 3, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, q), 34u + 32u + 6u);

  PixelStore s;
  s.alignment = 4;
  s.skip_rows = 1;
  EXPECT_EQ(packed_image_size(2, 1, GL_STENCIL_INDEX, GL_FLOAT, s), 8u + 8u);

  // BITMAP: rows of a * ceil(l / 8a) bytes, SKIP_PIXELS in bits.
  PixelStore b;
  b.alignment = 1;
  b.skip_pixels = 7;
  EXPECT_EQ(packed_image_size(10, 3, GL_STENCIL_INDEX, GL_BITMAP, b), 2u * 2u + 3u);
  b.alignment = 4;
  EXPECT_EQ(packed_image_size(10, 3, GL_STENCIL_INDEX, GL_BITMAP, b), 2u * 4u + 3u);
  EXPECT_EQ(packed_image_size(2, 2, GL_RGBA, 0x1234, p), 0u);
}

TEST(ReadPixels, FormatTypeErrors) {
  EXPECT_EQ(read_format_type_error(GL_RGBA, GL_UNSIGNED_BYTE), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(read_format_type_error(GL_STENCIL_INDEX, GL_BITMAP), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(read_format_type_error(GL_DEPTH_COMPONENT, GL_FLOAT), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(read_format_type_error(GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV),
            static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(read_format_type_error(GL_RGB, GL_UNSIGNED_BYTE_3_3_2), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(read_format_type_error(GL_INTENSITY, GL_UNSIGNED_BYTE), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(read_format_type_error(GL_RGBA, GL_DOUBLE), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(read_format_type_error(GL_RGBA, GL_BITMAP), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(read_format_type_error(GL_RGBA, GL_UNSIGNED_SHORT_5_6_5),
            static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(read_format_type_error(GL_BGR, GL_UNSIGNED_SHORT_5_6_5),
            static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(read_format_type_error(GL_RGB, GL_UNSIGNED_INT_8_8_8_8),
            static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(read_format_type_error(GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT_4_4_4_4),
            static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(read_format_type_error(GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_8_8_8_8),
            static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(read_format_type_error(GL_COLOR_INDEX, GL_UNSIGNED_BYTE),
            static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_TRUE(is_valid_read_format(GL_LUMINANCE_ALPHA));
  EXPECT_FALSE(is_valid_read_format(GL_RGBA8));
  EXPECT_TRUE(is_valid_type(GL_UNSIGNED_INT_10_10_10_2));
  EXPECT_FALSE(is_valid_type(GL_2_BYTES));
  EXPECT_EQ(pixel_format_components(GL_BGRA), 4);
  EXPECT_EQ(pixel_format_components(GL_LUMINANCE_ALPHA), 2);
  EXPECT_EQ(pixel_type_size(GL_UNSIGNED_SHORT_1_5_5_5_REV), 2);
}

TEST(ReadPixels, RefusesWhatItCannotDo) {
  TestFb t(2, 2);
  std::vector<uint8_t> buf(64, kCanary);
  EXPECT_FALSE(read_pixels(t.fb, 0, 0, 2, 2, GL_BGR, GL_UNSIGNED_SHORT_5_6_5, tight(), buf.data()));
  EXPECT_FALSE(read_pixels(t.fb, 0, 0, 2, 2, GL_RGBA, GL_BITMAP, tight(), buf.data()));
  EXPECT_FALSE(read_pixels(t.fb, 0, 0, 2, 2, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, tight(), buf.data()));
  t.fb.depth = nullptr;
  t.fb.depth_bits = 0;
  EXPECT_FALSE(read_pixels(t.fb, 0, 0, 2, 2, GL_DEPTH_COMPONENT, GL_FLOAT, tight(), buf.data()));
  t.fb.stencil = nullptr;
  EXPECT_FALSE(read_pixels(t.fb, 0, 0, 2, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, tight(), buf.data()));
  EXPECT_EQ(buf, Bytes(64, kCanary));
}

} // namespace
} // namespace pineda
