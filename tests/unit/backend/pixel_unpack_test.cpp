// The pixel conversion module (src/pixel): format/type checks (GL 2.1 §3.6.4, Table 3.8),
// client layout (eq. 3.12-3.14 and 3D images), conversion to float of every type (Table 2.9,
// packed fields c / (2^N - 1)), formats to RGBA, the §3.6.5 transfer operations, and packing
// back (§4.3.2, Tables 4.6 and 4.7). Expected values are worked out by hand from the tables.
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "pixel/transfer.h"
#include "pixel/unpack.h"

namespace pineda {
namespace {

// The transfer modes and the maps in one value, as the tests set them up.
struct Transfer : PixelTransfer, PixelMaps {
  operator PixelTransferView() const { return {*this, *this}; }
};

PixelStore tight() {
  PixelStore p;
  p.alignment = 1;
  return p;
}

template <typename T>
std::vector<float> rgba_of(const std::vector<T>& data, int w, GLenum format, GLenum type,
                           PixelStore st = tight(), const Transfer& xfer = Transfer{}) {
  std::vector<float> out(static_cast<size_t>(w) * 4, -99.0f);
  unpack_rgba(data.data(), w, 1, 1, format, type, st, xfer, out.data());
  return out;
}

void expect_rgba(const std::vector<float>& got, size_t px, double r, double g, double b, double a) {
  const double want[4] = {r, g, b, a};
  for (int c = 0; c < 4; ++c)
    EXPECT_NEAR(got[px * 4 + c], want[c], 1e-7) << "pixel " << px << " channel " << c;
}

TEST(PixelFormatType, Errors) {
  EXPECT_EQ(check_pixel_format_type(GL_RGBA, GL_UNSIGNED_BYTE), GLenum(GL_NO_ERROR));
  EXPECT_EQ(check_pixel_format_type(GL_COLOR_INDEX, GL_BITMAP), GLenum(GL_NO_ERROR));
  EXPECT_EQ(check_pixel_format_type(GL_STENCIL_INDEX, GL_BITMAP), GLenum(GL_NO_ERROR));
  EXPECT_EQ(check_pixel_format_type(GL_DEPTH_COMPONENT, GL_FLOAT), GLenum(GL_NO_ERROR));
  EXPECT_EQ(check_pixel_format_type(GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV), GLenum(GL_NO_ERROR));
  EXPECT_EQ(check_pixel_format_type(GL_RGB, GL_UNSIGNED_SHORT_5_6_5), GLenum(GL_NO_ERROR));
  EXPECT_EQ(check_pixel_format_type(GL_RGBA, GL_UNSIGNED_SHORT_5_6_5),
            GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(check_pixel_format_type(GL_BGR, GL_UNSIGNED_BYTE_3_3_2), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(check_pixel_format_type(GL_RGB, GL_UNSIGNED_INT_8_8_8_8), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(check_pixel_format_type(GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_8_8_8_8),
            GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(check_pixel_format_type(GL_RGBA, GL_BITMAP), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(check_pixel_format_type(GL_RGBA, GL_DOUBLE), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(check_pixel_format_type(GL_INTENSITY, GL_FLOAT), GLenum(GL_INVALID_ENUM));
}

TEST(PixelLayout, RowsImagesAndSkips) {
  PixelStore st; // alignment 4
  // RGB ubyte, 3 wide: 9 bytes a row, padded to 12.
  EXPECT_EQ(client_image_bytes(3, 2, 1, GL_RGB, GL_UNSIGNED_BYTE, st), 21u);
  st.row_length = 5;
  st.skip_pixels = 1;
  st.skip_rows = 1;
  // Rows of 15 bytes padded to 16; origin 16 + 3.
  EXPECT_EQ(client_image_bytes(3, 2, 1, GL_RGB, GL_UNSIGNED_BYTE, st), 19u + 16u + 9u);
  st.image_height = 3;
  st.skip_images = 1;
  // Images of 48 bytes: origin 48 + 16 + 3, last row one image and one row further.
  EXPECT_EQ(client_image_bytes(3, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, st), 67u + 48u + 16u + 9u);
  // Shorts with alignment 8: 3 * 2 * 2 = 12 bytes padded to 16.
  PixelStore s8;
  s8.alignment = 8;
  EXPECT_EQ(client_image_bytes(3, 2, 1, GL_LUMINANCE_ALPHA, GL_SHORT, s8), 16u + 12u);
  // Packed: one element per group.
  EXPECT_EQ(client_image_bytes(3, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, tight()), 6u);
  // BITMAP: 10 bits a row with alignment 1 is 2 bytes; 3 skipped bits push row 1 onto a third.
  PixelStore b = tight();
  b.skip_pixels = 3;
  EXPECT_EQ(client_image_bytes(10, 2, 1, GL_COLOR_INDEX, GL_BITMAP, b), 2u + 2u);
  EXPECT_EQ(client_image_bytes(0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, st), 0u);
  EXPECT_EQ(client_image_bytes(2, 2, 1, GL_RGBA, GL_BITMAP, st), 0u);
}

TEST(PixelUnpack, UnsignedAndSignedTypes) {
  expect_rgba(rgba_of(std::vector<uint8_t>{0, 51, 255, 128}, 1, GL_RGBA, GL_UNSIGNED_BYTE), 0, 0,
              0.2, 1, 128.0 / 255);
  // Table 2.9: signed c -> (2c + 1) / (2^b - 1).
  expect_rgba(rgba_of(std::vector<int8_t>{-128, -1, 0, 127}, 1, GL_RGBA, GL_BYTE), 0, -1,
              -1.0 / 255, 1.0 / 255, 1);
  expect_rgba(rgba_of(std::vector<uint16_t>{0, 65535, 13107, 32768}, 1, GL_RGBA, GL_UNSIGNED_SHORT),
              0, 0, 1, 0.2, 32768.0 / 65535);
  expect_rgba(rgba_of(std::vector<int16_t>{-32768, 32767, 0, -1}, 1, GL_RGBA, GL_SHORT), 0, -1, 1,
              1.0 / 65535, -1.0 / 65535);
  expect_rgba(rgba_of(std::vector<uint32_t>{0, 0xffffffffu, 0x80000000u, 0x40000000u}, 1, GL_RGBA,
                      GL_UNSIGNED_INT),
              0, 0, 1, 2147483648.0 / 4294967295.0, 1073741824.0 / 4294967295.0);
  expect_rgba(rgba_of(std::vector<int32_t>{INT_MIN, INT_MAX, 0, -1}, 1, GL_RGBA, GL_INT), 0, -1, 1,
              1.0 / 4294967295.0, -1.0 / 4294967295.0);
  expect_rgba(rgba_of(std::vector<float>{-2.0f, 0.5f, 3.0f, 0.25f}, 1, GL_RGBA, GL_FLOAT), 0, -2,
              0.5, 3, 0.25);
}

TEST(PixelUnpack, PackedTypes) {
  expect_rgba(rgba_of(std::vector<uint8_t>{0xAE}, 1, GL_RGB, GL_UNSIGNED_BYTE_3_3_2), 0, 5.0 / 7,
              3.0 / 7, 2.0 / 3, 1);
  expect_rgba(rgba_of(std::vector<uint8_t>{0xAE}, 1, GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV), 0,
              6.0 / 7, 5.0 / 7, 2.0 / 3, 1);
  expect_rgba(rgba_of(std::vector<uint16_t>{0x1234}, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5), 0,
              2.0 / 31, 17.0 / 63, 20.0 / 31, 1);
  expect_rgba(rgba_of(std::vector<uint16_t>{0x1234}, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV), 0,
              20.0 / 31, 17.0 / 63, 2.0 / 31, 1);
  expect_rgba(rgba_of(std::vector<uint16_t>{0x1234}, 1, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4), 0,
              1.0 / 15, 2.0 / 15, 3.0 / 15, 4.0 / 15);
  expect_rgba(rgba_of(std::vector<uint16_t>{0x1234}, 1, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_REV), 0,
              4.0 / 15, 3.0 / 15, 2.0 / 15, 1.0 / 15);
  // Table 3.12: with BGRA the first component is blue.
  expect_rgba(rgba_of(std::vector<uint16_t>{0x1234}, 1, GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4), 0,
              3.0 / 15, 2.0 / 15, 1.0 / 15, 4.0 / 15);
  expect_rgba(rgba_of(std::vector<uint16_t>{0x1235}, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1), 0,
              2.0 / 31, 8.0 / 31, 26.0 / 31, 1);
  expect_rgba(rgba_of(std::vector<uint16_t>{0x1235}, 1, GL_RGBA, GL_UNSIGNED_SHORT_1_5_5_5_REV), 0,
              21.0 / 31, 17.0 / 31, 4.0 / 31, 0);
  expect_rgba(rgba_of(std::vector<uint32_t>{0x11223344u}, 1, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8), 0,
              0x11 / 255.0, 0x22 / 255.0, 0x33 / 255.0, 0x44 / 255.0);
  expect_rgba(rgba_of(std::vector<uint32_t>{0x11223344u}, 1, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8_REV),
              0, 0x44 / 255.0, 0x33 / 255.0, 0x22 / 255.0, 0x11 / 255.0);
  expect_rgba(rgba_of(std::vector<uint32_t>{0xD2345679u}, 1, GL_RGBA, GL_UNSIGNED_INT_10_10_10_2),
              0, 840.0 / 1023, 837.0 / 1023, 414.0 / 1023, 1.0 / 3);
  expect_rgba(
      rgba_of(std::vector<uint32_t>{0xD2345679u}, 1, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV), 0,
      633.0 / 1023, 277.0 / 1023, 291.0 / 1023, 1);
}

TEST(PixelUnpack, Formats) {
  const std::vector<uint8_t> v{51, 102, 153, 204};
  expect_rgba(rgba_of(v, 1, GL_RED, GL_UNSIGNED_BYTE), 0, 0.2, 0, 0, 1);
  expect_rgba(rgba_of(v, 1, GL_GREEN, GL_UNSIGNED_BYTE), 0, 0, 0.2, 0, 1);
  expect_rgba(rgba_of(v, 1, GL_BLUE, GL_UNSIGNED_BYTE), 0, 0, 0, 0.2, 1);
  expect_rgba(rgba_of(v, 1, GL_ALPHA, GL_UNSIGNED_BYTE), 0, 0, 0, 0, 0.2);
  expect_rgba(rgba_of(v, 1, GL_RGB, GL_UNSIGNED_BYTE), 0, 0.2, 0.4, 0.6, 1);
  expect_rgba(rgba_of(v, 1, GL_BGR, GL_UNSIGNED_BYTE), 0, 0.6, 0.4, 0.2, 1);
  expect_rgba(rgba_of(v, 1, GL_BGRA, GL_UNSIGNED_BYTE), 0, 0.6, 0.4, 0.2, 0.8);
  expect_rgba(rgba_of(v, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE), 0, 0.2, 0.2, 0.2, 1);
  expect_rgba(rgba_of(v, 1, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE), 0, 0.2, 0.2, 0.2, 0.4);
  // Several groups in a row.
  const auto two = rgba_of(v, 2, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE);
  expect_rgba(two, 1, 0.6, 0.6, 0.6, 0.8);
}

TEST(PixelUnpack, SwapBytes) {
  PixelStore st = tight();
  st.swap_bytes = true;
  expect_rgba(rgba_of(std::vector<uint16_t>{0x3412}, 1, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, st), 0,
              1.0 / 15, 2.0 / 15, 3.0 / 15, 4.0 / 15);
  expect_rgba(rgba_of(std::vector<uint16_t>{0xffff, 0x0000, 0x3333, 0xff00}, 1, GL_RGBA,
                      GL_UNSIGNED_SHORT, st),
              0, 1, 0, 0.2, 255.0 / 65535);
  expect_rgba(rgba_of(std::vector<uint32_t>{0x44332211u}, 1, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, st),
              0, 0x11 / 255.0, 0x22 / 255.0, 0x33 / 255.0, 0x44 / 255.0);
  float f = 0.75f;
  uint32_t u;
  std::memcpy(&u, &f, 4);
  u = __builtin_bswap32(u);
  const std::vector<uint32_t> fl{u};
  std::vector<float> out(4);
  unpack_rgba(fl.data(), 1, 1, 1, GL_RED, GL_FLOAT, st, Transfer{}, out.data());
  EXPECT_EQ(out[0], 0.75f);
  // Bytes are not swapped.
  expect_rgba(rgba_of(std::vector<uint8_t>{255, 0, 0, 255}, 1, GL_RGBA, GL_UNSIGNED_BYTE, st), 0, 1,
              0, 0, 1);
}

TEST(PixelUnpack, AlignmentRowLengthSkipsAndImages) {
  // Two rows of one RGB pixel with alignment 4: the second starts at byte 4.
  const std::vector<uint8_t> a{255, 0, 0, 99, 0, 255, 0, 99};
  PixelStore st; // alignment 4
  std::vector<float> out(8);
  unpack_rgba(a.data(), 1, 2, 1, GL_RGB, GL_UNSIGNED_BYTE, st, Transfer{}, out.data());
  expect_rgba(out, 0, 1, 0, 0, 1);
  expect_rgba(out, 1, 0, 1, 0, 1);

  // A 4 x 3 x 3 luminance volume of value 10 * image + 4 * row + column (in 1/255 steps); take
  // the 2 x 1 x 2 box at column 1, row 2, image 1.
  std::vector<uint8_t> vol(36);
  for (int i = 0; i < 3; ++i)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c)
        vol[static_cast<size_t>(i * 12 + r * 4 + c)] = static_cast<uint8_t>(10 * i + 4 * r + c);
  PixelStore v = tight();
  v.row_length = 4;
  v.image_height = 3;
  v.skip_pixels = 1;
  v.skip_rows = 2;
  v.skip_images = 1;
  std::vector<float> box(16);
  unpack_rgba(vol.data(), 2, 1, 2, GL_LUMINANCE, GL_UNSIGNED_BYTE, v, Transfer{}, box.data());
  EXPECT_NEAR(box[0], (10 + 8 + 1) / 255.0, 1e-7);
  EXPECT_NEAR(box[4], (10 + 8 + 2) / 255.0, 1e-7);
  EXPECT_NEAR(box[8], (20 + 8 + 1) / 255.0, 1e-7);
  EXPECT_NEAR(box[12], (20 + 8 + 2) / 255.0, 1e-7);
  EXPECT_EQ(client_image_bytes(2, 1, 2, GL_LUMINANCE, GL_UNSIGNED_BYTE, v),
            12u + 8u + 1u + 12u + 2u);
}

TEST(PixelUnpack, ScaleBiasAndColorMap) {
  Transfer x;
  x.scale[0] = 2.0f;
  x.bias[1] = 0.5f;
  x.scale[3] = -1.0f;
  x.bias[3] = 1.0f;
  expect_rgba(
      rgba_of(std::vector<uint8_t>{51, 51, 51, 51}, 1, GL_RGBA, GL_UNSIGNED_BYTE, tight(), x), 0,
      0.4, 0.7, 0.2, 0.8);
  // MAP_COLOR after scale/bias: clamp, times (size - 1), round, look up.
  x = Transfer{};
  x.map_color = true;
  x.maps[kMapRtoR].size = 3;
  x.maps[kMapRtoR].values[0] = 0.9f;
  x.maps[kMapRtoR].values[1] = 0.5f;
  x.maps[kMapRtoR].values[2] = 0.1f;
  x.maps[kMapGtoG].values[0] = 0.25f; // size 1: everything maps to entry 0
  x.maps[kMapBtoB].size = 2;
  x.maps[kMapBtoB].values[1] = 1.0f;
  x.maps[kMapAtoA].values[0] = 0.75f;
  x.scale[0] = 10.0f; // 0.2 * 10 clamps to 1: entry 2
  const auto m = rgba_of(std::vector<uint8_t>{51, 200, 128, 0, 0, 0, 127, 0}, 2, GL_RGBA,
                         GL_UNSIGNED_BYTE, tight(), x);
  expect_rgba(m, 0, 0.1f, 0.25f, 1.0f, 0.75f);
  expect_rgba(m, 1, 0.9f, 0.25f, 0.0f, 0.75f); // 127/255 * 1 = 0.498 rounds to entry 0
}

TEST(PixelUnpack, ColorIndexThroughMaps) {
  Transfer x;
  for (int m = kMapItoR; m <= kMapItoA; ++m) {
    x.maps[m].size = 4;
    for (int i = 0; i < 4; ++i)
      x.maps[m].values[i] = static_cast<float>(i + (m - kMapItoR) * 4) / 16.0f;
  }
  x.index_shift = 1;
  x.index_offset = 1;
  // Index 1 -> (1 << 1) + 1 = 3; index 6 -> 13 & 3 = 1. Scale/bias does not apply (Figure 3.7).
  x.scale[0] = 100.0f;
  const auto out =
      rgba_of(std::vector<uint8_t>{1, 6}, 2, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, tight(), x);
  expect_rgba(out, 0, 3 / 16.0, 7 / 16.0, 11 / 16.0, 15 / 16.0);
  expect_rgba(out, 1, 1 / 16.0, 5 / 16.0, 9 / 16.0, 13 / 16.0);
  // Negative shift shifts right; FLOAT indices are truncated.
  x.index_shift = -2;
  x.index_offset = 0;
  const auto f = rgba_of(std::vector<float>{13.9f}, 1, GL_COLOR_INDEX, GL_FLOAT, tight(), x);
  expect_rgba(f, 0, 3 / 16.0, 7 / 16.0, 11 / 16.0, 15 / 16.0);
}

TEST(PixelUnpack, BitmapBitOrder) {
  Transfer x;
  x.maps[kMapItoR].size = 2;
  x.maps[kMapItoR].values[1] = 1.0f;
  // 0xA0 = 1010 0000: MSB first gives 1, 0, 1, 0; LSB first reads bits 0.. of the byte.
  const std::vector<uint8_t> bits{0xA0, 0x05};
  std::vector<float> out(4 * 4);
  PixelStore st = tight();
  unpack_rgba(bits.data(), 4, 1, 1, GL_COLOR_INDEX, GL_BITMAP, st, x, out.data());
  EXPECT_EQ(out[0], 1.0f);
  EXPECT_EQ(out[4], 0.0f);
  EXPECT_EQ(out[8], 1.0f);
  EXPECT_EQ(out[12], 0.0f);
  std::vector<uint32_t> idx(12);
  st.lsb_first = true;
  st.skip_pixels = 6;
  // Bits 6, 7 of 0xA0 then bits 0-3 of 0x05 (LSB first): 0, 1, 1, 0, 1, 0.
  unpack_index(bits.data(), 6, 1, 1, GL_STENCIL_INDEX, GL_BITMAP, st, Transfer{}, idx.data());
  const uint32_t want[6] = {0, 1, 1, 0, 1, 0};
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ(idx[static_cast<size_t>(i)], want[i]) << i;
}

TEST(PixelUnpack, DepthAndStencil) {
  Transfer x;
  std::vector<float> z(3);
  const std::vector<uint16_t> d16{0, 65535, 13107};
  unpack_depth(d16.data(), 3, 1, 1, GL_UNSIGNED_SHORT, tight(), x, z.data());
  EXPECT_FLOAT_EQ(z[0], 0.0f);
  EXPECT_FLOAT_EQ(z[1], 1.0f);
  EXPECT_FLOAT_EQ(z[2], 0.2f);
  x.depth_scale = 0.5f;
  x.depth_bias = 0.25f;
  const std::vector<float> df{0.5f, 2.0f, -1.0f};
  unpack_depth(df.data(), 3, 1, 1, GL_FLOAT, tight(), x, z.data());
  EXPECT_FLOAT_EQ(z[0], 0.5f);
  EXPECT_FLOAT_EQ(z[1], 1.25f); // not clamped here
  EXPECT_FLOAT_EQ(z[2], -0.25f);

  Transfer s;
  s.index_shift = 2;
  s.index_offset = -1;
  std::vector<uint32_t> idx(3);
  const std::vector<int16_t> si{3, -1, 100};
  unpack_index(si.data(), 3, 1, 1, GL_STENCIL_INDEX, GL_SHORT, tight(), s, idx.data());
  EXPECT_EQ(idx[0], 11u);
  EXPECT_EQ(idx[1], 0xfffffffbu); // -1 << 2 - 1 = -5 in 32 bits
  EXPECT_EQ(idx[2], 399u);
  s.map_stencil = true;
  s.maps[kMapStoS].size = 4;
  for (int i = 0; i < 4; ++i)
    s.maps[kMapStoS].values[i] = static_cast<float>(100 + i);
  unpack_index(si.data(), 3, 1, 1, GL_STENCIL_INDEX, GL_SHORT, tight(), s, idx.data());
  EXPECT_EQ(idx[0], 103u); // 11 & 3
  EXPECT_EQ(idx[1], 103u); // -5 & 3
  EXPECT_EQ(idx[2], 103u); // 399 & 3
}

TEST(PixelPack, EveryType) {
  const std::vector<float> px{0.2f, 1.5f, -0.5f, 0.5f};
  auto pack = [&](GLenum format, GLenum type, size_t bytes, PixelStore st = tight()) {
    std::vector<uint8_t> out(bytes, 0xcc);
    pack_rgba(px.data(), 1, 1, 1, format, type, st, out.data());
    return out;
  };
  EXPECT_EQ(pack(GL_RGBA, GL_UNSIGNED_BYTE, 4), (std::vector<uint8_t>{51, 255, 0, 128}));
  // Signed: floor((2^b - 1) f / 2).
  EXPECT_EQ(pack(GL_RGBA, GL_BYTE, 4), (std::vector<uint8_t>{25, 127, 0, 63}));
  auto u16 = pack(GL_RGBA, GL_UNSIGNED_SHORT, 8);
  uint16_t s[4];
  std::memcpy(s, u16.data(), 8);
  EXPECT_EQ(s[0], 13107);
  EXPECT_EQ(s[1], 65535);
  EXPECT_EQ(s[2], 0);
  EXPECT_EQ(s[3], 32768);
  auto i16 = pack(GL_RGBA, GL_SHORT, 8);
  std::memcpy(s, i16.data(), 8);
  EXPECT_EQ(s[0], 6553);
  EXPECT_EQ(s[1], 32767);
  EXPECT_EQ(s[3], 16383);
  auto u32 = pack(GL_RGBA, GL_UNSIGNED_INT, 16);
  uint32_t w[4];
  std::memcpy(w, u32.data(), 16);
  EXPECT_EQ(w[1], 0xffffffffu);
  EXPECT_EQ(w[2], 0u);
  EXPECT_EQ(w[3], 0x80000000u);
  auto i32 = pack(GL_RGBA, GL_INT, 16);
  std::memcpy(w, i32.data(), 16);
  EXPECT_EQ(w[1], 0x7fffffffu);
  EXPECT_EQ(w[3], 0x3fffffffu);
  auto f32 = pack(GL_RGBA, GL_FLOAT, 16);
  float f[4];
  std::memcpy(f, f32.data(), 16);
  EXPECT_EQ(f[0], 0.2f);
  EXPECT_EQ(f[1], 1.0f);
  EXPECT_EQ(f[2], 0.0f);
  // Packed: r = round(0.2 * 7) = 1, g = 7, b = 0 -> 001 111 00.
  EXPECT_EQ(pack(GL_RGB, GL_UNSIGNED_BYTE_3_3_2, 1)[0], 0x3C);
  EXPECT_EQ(pack(GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV, 1)[0], 0x39);
  auto p16 = [&](GLenum format, GLenum type) {
    const auto b = pack(format, type, 2);
    uint16_t v;
    std::memcpy(&v, b.data(), 2);
    return v;
  };
  // r = round(0.2 * 31) = 6, g = 63 / 31, b = 0, a = round(0.5 * 15) = 8, a1 = 1.
  EXPECT_EQ(p16(GL_RGB, GL_UNSIGNED_SHORT_5_6_5), (6 << 11) | (63 << 5));
  EXPECT_EQ(p16(GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV), 6 | (63 << 5));
  EXPECT_EQ(p16(GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4), (3 << 12) | (15 << 8) | 8);
  EXPECT_EQ(p16(GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_REV), 3 | (15 << 4) | (8 << 12));
  EXPECT_EQ(p16(GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4), (15 << 8) | (3 << 4) | 8);
  EXPECT_EQ(p16(GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1), (6 << 11) | (31 << 6) | 1);
  EXPECT_EQ(p16(GL_RGBA, GL_UNSIGNED_SHORT_1_5_5_5_REV), 6 | (31 << 5) | (1 << 15));
  auto p32 = [&](GLenum format, GLenum type) {
    const auto b = pack(format, type, 4);
    uint32_t v;
    std::memcpy(&v, b.data(), 4);
    return v;
  };
  EXPECT_EQ(p32(GL_RGBA, GL_UNSIGNED_INT_8_8_8_8), 0x33ff0080u);
  EXPECT_EQ(p32(GL_RGBA, GL_UNSIGNED_INT_8_8_8_8_REV), 0x8000ff33u);
  // 10 bits: round(0.2 * 1023) = 205, 2 bits: round(0.5 * 3) = 2.
  EXPECT_EQ(p32(GL_RGBA, GL_UNSIGNED_INT_10_10_10_2), (205u << 22) | (1023u << 12) | 2u);
  EXPECT_EQ(p32(GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV), 205u | (1023u << 10) | (2u << 30));
  // L = R + G + B before the clamp: 0.2 + 1.5 - 0.5 = 1.2 -> 1.
  EXPECT_EQ(pack(GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, 2), (std::vector<uint8_t>{255, 128}));
  EXPECT_EQ(pack(GL_BGR, GL_UNSIGNED_BYTE, 3), (std::vector<uint8_t>{0, 255, 51}));
  PixelStore sw = tight();
  sw.swap_bytes = true;
  const auto swapped = pack(GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, 2, sw);
  EXPECT_EQ(swapped[0], 0x3F);
  EXPECT_EQ(swapped[1], 0x08);
}

TEST(PixelPack, LayoutDepthAndIndices) {
  // Two rows of one RGB ubyte pixel, alignment 4: padding bytes stay untouched.
  const std::vector<float> px{1, 0, 0, 1, 0, 1, 0, 1};
  std::vector<uint8_t> out(8, 0xcc);
  pack_rgba(px.data(), 1, 2, 1, GL_RGB, GL_UNSIGNED_BYTE, PixelStore{}, out.data());
  EXPECT_EQ(out, (std::vector<uint8_t>{255, 0, 0, 0xcc, 0, 255, 0, 0xcc}));

  const std::vector<float> z{0.5f, 2.0f, -1.0f};
  std::vector<uint16_t> d(3);
  pack_depth(z.data(), 3, 1, 1, GL_UNSIGNED_SHORT, tight(), d.data());
  EXPECT_EQ(d, (std::vector<uint16_t>{32768, 65535, 0}));

  const std::vector<uint32_t> idx{0x1ff, 0x1ffff, 3};
  std::vector<uint8_t> b(3);
  pack_index(idx.data(), 3, 1, 1, GL_BYTE, tight(), b.data());
  EXPECT_EQ(b, (std::vector<uint8_t>{0x7f, 0x7f, 3}));
  std::vector<int16_t> sh(3);
  pack_index(idx.data(), 3, 1, 1, GL_SHORT, tight(), sh.data());
  EXPECT_EQ(sh, (std::vector<int16_t>{0x1ff, 0x7fff, 3}));
  std::vector<float> fl(3);
  pack_index(idx.data(), 3, 1, 1, GL_FLOAT, tight(), fl.data());
  EXPECT_EQ(fl[1], 131071.0f);
  std::vector<uint8_t> bits(1, 0);
  pack_index(idx.data(), 3, 1, 1, GL_BITMAP, tight(), bits.data());
  EXPECT_EQ(bits[0], 0xE0);
}

TEST(PixelRoundTrip, EveryTypeThroughPackAndUnpack) {
  const GLenum types[] = {GL_UNSIGNED_BYTE,
                          GL_UNSIGNED_SHORT,
                          GL_UNSIGNED_INT,
                          GL_FLOAT,
                          GL_UNSIGNED_SHORT_4_4_4_4,
                          GL_UNSIGNED_SHORT_4_4_4_4_REV,
                          GL_UNSIGNED_SHORT_5_5_5_1,
                          GL_UNSIGNED_SHORT_1_5_5_5_REV,
                          GL_UNSIGNED_INT_8_8_8_8,
                          GL_UNSIGNED_INT_8_8_8_8_REV,
                          GL_UNSIGNED_INT_10_10_10_2,
                          GL_UNSIGNED_INT_2_10_10_10_REV};
  const std::vector<float> px{0, 1, 1.0f / 3, 1, 1, 0, 0, 0};
  for (GLenum t : types) {
    for (GLenum f : {GL_RGBA, GL_BGRA}) {
      PixelStore st;
      st.row_length = 3;
      st.skip_pixels = 1;
      st.swap_bytes = true;
      std::vector<uint8_t> mem(64, 0);
      pack_rgba(px.data(), 2, 1, 1, f, t, st, mem.data());
      std::vector<float> back(8);
      unpack_rgba(mem.data(), 2, 1, 1, f, t, st, Transfer{}, back.data());
      for (size_t i = 0; i < 8; ++i) {
        // 1/3 quantized to the smallest field (1 bit of 5_5_5_1 alpha is not involved).
        EXPECT_NEAR(back[i], px[i], 1.0 / 30) << std::hex << t << " " << f << " " << i;
      }
    }
  }
}

// client_image_bytes covers every byte the unpackers read and the packers write, for every
// format/type pair and a spread of store parameters (the sanitizer build checks the reads; the
// guard bytes check the writes here).
TEST(PixelLayout, AccessesStayInsideClientImageBytes) {
  const GLenum formats[] = {GL_COLOR_INDEX,
                            GL_STENCIL_INDEX,
                            GL_DEPTH_COMPONENT,
                            GL_RED,
                            GL_GREEN,
                            GL_BLUE,
                            GL_ALPHA,
                            GL_RGB,
                            GL_RGBA,
                            GL_BGR,
                            GL_BGRA,
                            GL_LUMINANCE,
                            GL_LUMINANCE_ALPHA};
  const GLenum types[] = {GL_UNSIGNED_BYTE,
                          GL_BYTE,
                          GL_UNSIGNED_SHORT,
                          GL_SHORT,
                          GL_UNSIGNED_INT,
                          GL_INT,
                          GL_FLOAT,
                          GL_BITMAP,
                          GL_UNSIGNED_BYTE_3_3_2,
                          GL_UNSIGNED_BYTE_2_3_3_REV,
                          GL_UNSIGNED_SHORT_5_6_5,
                          GL_UNSIGNED_SHORT_5_6_5_REV,
                          GL_UNSIGNED_SHORT_4_4_4_4,
                          GL_UNSIGNED_SHORT_4_4_4_4_REV,
                          GL_UNSIGNED_SHORT_5_5_5_1,
                          GL_UNSIGNED_SHORT_1_5_5_5_REV,
                          GL_UNSIGNED_INT_8_8_8_8,
                          GL_UNSIGNED_INT_8_8_8_8_REV,
                          GL_UNSIGNED_INT_10_10_10_2,
                          GL_UNSIGNED_INT_2_10_10_10_REV};
  uint32_t seed = 12345;
  const auto rnd = [&](int n) {
    seed = seed * 1664525u + 1013904223u;
    return static_cast<int>((seed >> 8) % static_cast<uint32_t>(n));
  };
  const int aligns[4] = {1, 2, 4, 8};
  int checked = 0;
  for (GLenum f : formats) {
    for (GLenum t : types) {
      if (check_pixel_format_type(f, t) != GL_NO_ERROR) continue;
      for (int rep = 0; rep < 6; ++rep) {
        const int w = 1 + rnd(13), h = 1 + rnd(5), d = 1 + rnd(3);
        PixelStore st;
        st.alignment = aligns[rnd(4)];
        st.row_length = rnd(2) ? 0 : w + rnd(5);
        st.skip_pixels = rnd(4);
        st.skip_rows = rnd(3);
        st.image_height = rnd(2) ? 0 : h + rnd(3);
        st.skip_images = rnd(2);
        st.swap_bytes = rnd(2) != 0;
        st.lsb_first = rnd(2) != 0;
        const size_t bytes = client_image_bytes(w, h, d, f, t, st);
        ASSERT_GT(bytes, 0u);
        const size_t groups = static_cast<size_t>(w * h * d);
        std::vector<uint8_t> mem(bytes + 16, 0x5a);
        std::vector<float> rgba(groups * 4), depth(groups);
        std::vector<uint32_t> index(groups, 1);
        const Transfer x;
        const bool index_format = f == GL_COLOR_INDEX || f == GL_STENCIL_INDEX;
        if (f == GL_DEPTH_COMPONENT) {
          unpack_depth(mem.data(), w, h, d, t, st, x, depth.data());
          pack_depth(depth.data(), w, h, d, t, st, mem.data());
        } else if (index_format) {
          unpack_index(mem.data(), w, h, d, f, t, st, x, index.data());
          pack_index(index.data(), w, h, d, t, st, mem.data());
        }
        if (f != GL_DEPTH_COMPONENT && f != GL_STENCIL_INDEX) {
          unpack_rgba(mem.data(), w, h, d, f, t, st, x, rgba.data());
          if (f != GL_COLOR_INDEX) pack_rgba(rgba.data(), w, h, d, f, t, st, mem.data());
        }
        for (size_t i = bytes; i < mem.size(); ++i)
          ASSERT_EQ(mem[i], 0x5a) << std::hex << f << " " << t << std::dec << " byte " << i;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 300);
}

} // namespace
} // namespace pineda
