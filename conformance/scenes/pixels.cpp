// Pixel rectangles and bitmaps (GL 2.1 §2.13, §3.6, §3.7, §4.3): glDrawPixels in every format
// and type, packed types, unpack state, zoom, pixel transfer scale/bias and maps, colour
// indices, glBitmap, glCopyPixels (colour, depth, stencil; overlapping), depth and stencil
// images, glWindowPos, clipped raster positions, and the per-fragment operations on pixel
// fragments. glWindowPos is GL 1.4, so it is looked up with proc().
#include "scene_util.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

using namespace scenes;

namespace {

// The pixel state these scenes change, back at its defaults (reset_state does not know it).
void reset_pixels() {
  glPixelZoom(1.0f, 1.0f);
  for (GLenum p : {GL_RED_SCALE, GL_GREEN_SCALE, GL_BLUE_SCALE, GL_ALPHA_SCALE, GL_DEPTH_SCALE})
    glPixelTransferf(p, 1.0f);
  for (GLenum p : {GL_RED_BIAS, GL_GREEN_BIAS, GL_BLUE_BIAS, GL_ALPHA_BIAS, GL_DEPTH_BIAS})
    glPixelTransferf(p, 0.0f);
  glPixelTransferi(GL_MAP_COLOR, 0);
  glPixelTransferi(GL_MAP_STENCIL, 0);
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, 0);
  glPixelStorei(GL_UNPACK_LSB_FIRST, 0);
  glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
}

// A smooth test pattern: channel c of pixel (x, y) of a w x h image, in [0, 1].
float pattern(int x, int y, int c, int w, int h) {
  const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(w);
  const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(h);
  switch (c) {
  case 0:
    return u;
  case 1:
    return v;
  case 2:
    return 0.5f + 0.5f * std::sin(6.0f * (u + v));
  default:
    return 0.25f + 0.75f * u * v;
  }
}

// An image of `comps` components per pixel of element type T (alignment 1), each component the
// pattern's channel map[k] scaled to the type's range by `conv`.
template <typename T, typename Conv>
std::vector<T> image(int w, int h, int comps, const int* map, Conv conv) {
  std::vector<T> out;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < comps; ++k)
        out.push_back(conv(pattern(x, y, map[k], w, h)));
  return out;
}

const int kRGBA[4] = {0, 1, 2, 3};
const int kBGRA[4] = {2, 1, 0, 3};

GLubyte to_ub(float f) {
  return static_cast<GLubyte>(f * 255.0f + 0.5f);
}

} // namespace

PINEDA_SCENE(pixels_draw_formats,
             "glDrawPixels: every format with UNSIGNED_BYTE and every component type with RGBA") {
  clear_frame(0.1f, 0.1f, 0.15f);
  reset_pixels();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const int w = 27, h = 21; // odd sizes: rows not multiples of the alignment
  const int r0[1] = {0}, r1[1] = {1}, r2[1] = {2}, r3[1] = {3};
  const int la[2] = {0, 3};
  struct Item {
    GLenum format;
    int comps;
    const int* map;
  };
  const Item items[] = {
      {GL_RED, 1, r0},       {GL_GREEN, 1, r1},          {GL_BLUE, 1, r2},   {GL_ALPHA, 1, r3},
      {GL_RGB, 3, kRGBA},    {GL_RGBA, 4, kRGBA},        {GL_BGR, 3, kBGRA}, {GL_BGRA, 4, kBGRA},
      {GL_LUMINANCE, 1, r0}, {GL_LUMINANCE_ALPHA, 2, la}};
  int i = 0;
  for (const Item& it : items) {
    glRasterPos2i(4 + (i % 6) * 42, 8 + (i / 6) * 30);
    const auto img = image<GLubyte>(w, h, it.comps, it.map, to_ub);
    glDrawPixels(w, h, it.format, GL_UNSIGNED_BYTE, img.data());
    ++i;
  }
  // Types, all RGBA, along the top half.
  int j = 0;
  const auto at = [&]() {
    glRasterPos2i(4 + (j % 6) * 42, 140 + (j / 6) * 30);
    ++j;
  };
  at();
  auto b = image<GLbyte>(w, h, 4, kRGBA, [](float f) { return static_cast<GLbyte>(f * 127.0f); });
  glDrawPixels(w, h, GL_RGBA, GL_BYTE, b.data());
  at();
  auto us =
      image<GLushort>(w, h, 4, kRGBA, [](float f) { return static_cast<GLushort>(f * 65535.0f); });
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_SHORT, us.data());
  at();
  auto s =
      image<GLshort>(w, h, 4, kRGBA, [](float f) { return static_cast<GLshort>(f * 32767.0f); });
  glDrawPixels(w, h, GL_RGBA, GL_SHORT, s.data());
  at();
  auto ui =
      image<GLuint>(w, h, 4, kRGBA, [](float f) { return static_cast<GLuint>(f * 4294967040.0f); });
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_INT, ui.data());
  at();
  auto si =
      image<GLint>(w, h, 4, kRGBA, [](float f) { return static_cast<GLint>(f * 2147483520.0f); });
  glDrawPixels(w, h, GL_RGBA, GL_INT, si.data());
  at();
  auto fl = image<GLfloat>(w, h, 4, kRGBA, [](float f) { return f * 1.4f - 0.2f; }); // clamped
  glDrawPixels(w, h, GL_RGBA, GL_FLOAT, fl.data());
  at();
  glPixelStorei(GL_UNPACK_SWAP_BYTES, 1);
  auto sw = image<GLushort>(w, h, 3, kRGBA, [](float f) {
    const GLushort v = static_cast<GLushort>(f * 65535.0f);
    return static_cast<GLushort>((v >> 8) | (v << 8));
  });
  glDrawPixels(w, h, GL_RGB, GL_UNSIGNED_SHORT, sw.data());
}

PINEDA_SCENE(pixels_packed_types,
             "glDrawPixels with the twelve packed types (RGB, RGBA and BGRA)") {
  clear_frame(0.0f, 0.0f, 0.0f);
  reset_pixels();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const int w = 30, h = 26;
  struct Packed {
    GLenum type;
    GLenum format;
    int bits[4];
    int shift[4];
    int bytes;
  };
  // Fields in group order (Tables 3.9-3.12); the image data is built from the same table.
  const Packed types[] = {
      {GL_UNSIGNED_BYTE_3_3_2, GL_RGB, {3, 3, 2, 0}, {5, 2, 0, 0}, 1},
      {GL_UNSIGNED_BYTE_2_3_3_REV, GL_RGB, {3, 3, 2, 0}, {0, 3, 6, 0}, 1},
      {GL_UNSIGNED_SHORT_5_6_5, GL_RGB, {5, 6, 5, 0}, {11, 5, 0, 0}, 2},
      {GL_UNSIGNED_SHORT_5_6_5_REV, GL_RGB, {5, 6, 5, 0}, {0, 5, 11, 0}, 2},
      {GL_UNSIGNED_SHORT_4_4_4_4, GL_RGBA, {4, 4, 4, 4}, {12, 8, 4, 0}, 2},
      {GL_UNSIGNED_SHORT_4_4_4_4_REV, GL_BGRA, {4, 4, 4, 4}, {0, 4, 8, 12}, 2},
      {GL_UNSIGNED_SHORT_5_5_5_1, GL_RGBA, {5, 5, 5, 1}, {11, 6, 1, 0}, 2},
      {GL_UNSIGNED_SHORT_1_5_5_5_REV, GL_BGRA, {5, 5, 5, 1}, {0, 5, 10, 15}, 2},
      {GL_UNSIGNED_INT_8_8_8_8, GL_RGBA, {8, 8, 8, 8}, {24, 16, 8, 0}, 4},
      {GL_UNSIGNED_INT_8_8_8_8_REV, GL_BGRA, {8, 8, 8, 8}, {0, 8, 16, 24}, 4},
      {GL_UNSIGNED_INT_10_10_10_2, GL_RGBA, {10, 10, 10, 2}, {22, 12, 2, 0}, 4},
      {GL_UNSIGNED_INT_2_10_10_10_REV, GL_BGRA, {10, 10, 10, 2}, {0, 10, 20, 30}, 4},
  };
  int i = 0;
  for (const Packed& p : types) {
    const int* map = p.format == GL_BGRA ? kBGRA : kRGBA;
    const int comps = p.format == GL_RGB ? 3 : 4;
    std::vector<unsigned char> data(static_cast<size_t>(w * h * p.bytes) + 8);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        uint32_t word = 0;
        for (int k = 0; k < comps; ++k) {
          const uint32_t max = (1u << p.bits[k]) - 1u;
          word |= static_cast<uint32_t>(pattern(x, y, map[k], w, h) * max + 0.5f) << p.shift[k];
        }
        unsigned char* dst = data.data() + static_cast<size_t>((y * w + x) * p.bytes);
        if (p.bytes == 1)
          *dst = static_cast<unsigned char>(word);
        else if (p.bytes == 2) {
          const uint16_t v = static_cast<uint16_t>(word);
          std::memcpy(dst, &v, 2);
        } else
          std::memcpy(dst, &word, 4);
      }
    glRasterPos2i(6 + (i % 4) * 62, 10 + (i / 4) * 80);
    glDrawPixels(w, h, p.format, p.type, data.data());
    // The same image through ROW_LENGTH and SKIP_PIXELS / SKIP_ROWS: its upper right part.
    glPixelStorei(GL_UNPACK_ROW_LENGTH, w);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 7);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 5);
    glRasterPos2i(6 + (i % 4) * 62, 42 + (i / 4) * 80);
    glDrawPixels(w - 7, h - 5, p.format, p.type, data.data());
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    ++i;
  }
}

// Fractional zooms are even tenths (0.6, 1.4, ...): group edges then never fall on a pixel
// centre, where llvmpipe's textured-quad implementation decides by the rounding of its
// texture coordinates.
PINEDA_SCENE(pixels_zoom,
             "glPixelZoom: magnification, reduction, fractional and negative factors") {
  clear_frame(0.05f, 0.05f, 0.05f);
  reset_pixels();
  const int w = 16, h = 12;
  const auto img = image<GLubyte>(w, h, 4, kRGBA, to_ub);
  const float zooms[][2] = {{1, 1},  {2, 2},      {3, 1.4f},    {0.6f, 0.8f}, {-2, 2},
                            {2, -2}, {-1.6f, -3}, {2.4f, 0.6f}, {1.2f, 4}};
  const int pos[][2] = {{8, 8},    {40, 8},    {90, 8},    {150, 8},  {230, 50},
                        {10, 120}, {120, 140}, {150, 160}, {200, 150}};
  for (int i = 0; i < 9; ++i) {
    glPixelZoom(zooms[i][0], zooms[i][1]);
    glRasterPos2f(static_cast<float>(pos[i][0]) + 0.25f, static_cast<float>(pos[i][1]) + 0.3f);
    glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  }
  glPixelZoom(1.0f, 1.0f);
}

PINEDA_SCENE(pixels_transfer, "Pixel transfer: scale and bias, MAP_COLOR tables, colour indices "
                              "through the I_TO_RGBA maps") {
  clear_frame(0.0f, 0.0f, 0.0f);
  reset_pixels();
  const int w = 40, h = 40;
  const auto img = image<GLubyte>(w, h, 4, kRGBA, to_ub);
  glRasterPos2i(8, 8);
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glPixelTransferf(GL_RED_SCALE, 2.0f);
  glPixelTransferf(GL_GREEN_BIAS, -0.25f);
  glPixelTransferf(GL_BLUE_SCALE, -1.0f);
  glPixelTransferf(GL_BLUE_BIAS, 1.0f);
  glRasterPos2i(60, 8);
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  // MAP_COLOR after scale/bias: a posterizing red map, an inverting green map.
  // Two-entry maps: the spec's address round(c (size - 1)) and llvmpipe's lookup texture
  // (about floor(c size)) pick the same entries only for sizes 2 and 256.
  const GLfloat r_map[2] = {0.3f, 0.9f};
  const GLfloat g_map[2] = {1.0f, 0.0f};
  // B and A maps given as ushort and uint entries. llvmpipe's mapped blue and alpha ignore
  // B_TO_B and A_TO_A (blue comes out as 3 + 249 b / 255), so both are masked off here.
  const GLushort b_map[2] = {26214, 39321};           // 0.4, 0.6
  const GLuint a_map[2] = {1717986918u, 2576980377u}; // 0.4, 0.6
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, r_map);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, g_map);
  glPixelMapusv(GL_PIXEL_MAP_B_TO_B, 2, b_map);
  glPixelMapuiv(GL_PIXEL_MAP_A_TO_A, 2, a_map);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glPixelTransferf(GL_BLUE_SCALE, 0.0f);
  glPixelTransferf(GL_BLUE_BIAS, 0.0f);
  glPixelTransferf(GL_ALPHA_SCALE, 0.0f);
  glPixelTransferf(GL_ALPHA_BIAS, 1.0f);
  glRasterPos2i(112, 8);
  glColorMask(GL_TRUE, GL_TRUE, GL_FALSE, GL_FALSE);
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  reset_pixels();
  // Colour indices through a 16-entry palette. INDEX_SHIFT and INDEX_OFFSET are left out:
  // llvmpipe ignores them on DrawPixels (GL 2.1 §3.6.5 applies them; the API tests check
  // Pineda does).
  GLfloat pr[16], pg[16], pb[16], pa[16];
  for (int i = 0; i < 16; ++i) {
    const float* c = palette(i);
    pr[i] = c[0], pg[i] = c[1], pb[i] = c[2], pa[i] = 1.0f;
  }
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 16, pr);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 16, pg);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 16, pb);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 16, pa);
  std::vector<GLubyte> idx8;
  std::vector<GLushort> idx16;
  std::vector<GLfloat> idxf;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      idx8.push_back(static_cast<GLubyte>((x / 4 + y / 4) % 256));
      idx16.push_back(static_cast<GLushort>(x * 3 + y));
      idxf.push_back(static_cast<GLfloat>(x / 5 * 2 + y / 5) + 0.4f);
    }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(8, 70);
  glDrawPixels(w, h, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx8.data());
  glRasterPos2i(60, 70);
  glDrawPixels(w, h, GL_COLOR_INDEX, GL_UNSIGNED_SHORT, idx16.data());
  glRasterPos2i(112, 70);
  glDrawPixels(w, h, GL_COLOR_INDEX, GL_FLOAT, idxf.data());
  // Scale/bias does not touch colour indices (GL 2.1 Figure 3.7).
  glPixelTransferf(GL_RED_SCALE, 0.0f);
  glRasterPos2i(164, 70);
  glDrawPixels(w, h, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx8.data());
  // A BITMAP-typed colour index image: two-colour checker from the first two palette entries.
  const GLubyte checker[8] = {0xCC, 0xCC, 0x33, 0x33, 0xCC, 0xCC, 0x33, 0x33};
  glPixelZoom(4.0f, 4.0f);
  glRasterPos2i(8, 130);
  glDrawPixels(8, 8, GL_COLOR_INDEX, GL_BITMAP, checker);
  reset_pixels();
}

PINEDA_SCENE(pixels_bitmap, "glBitmap: text-like glyphs with GLUT's unpack state, LSB_FIRST, "
                            "skips, origins, moves and colours") {
  clear_frame(0.0f, 0.0f, 0.2f);
  reset_pixels();
  // An 8 x 13 glyph set in the style of GLUT's bitmap fonts (rows bottom-up, MSB first).
  const GLubyte glyphs[4][13] = {
      {0x00, 0xc3, 0xc3, 0xc3, 0xff, 0xc3, 0xc3, 0xc3, 0x66, 0x3c, 0x18, 0x00, 0x00}, // A
      {0x00, 0xfe, 0xc3, 0xc3, 0xc3, 0xfe, 0xc3, 0xc3, 0xc3, 0xfe, 0x00, 0x00, 0x00}, // B
      {0x00, 0x7e, 0xe7, 0xc0, 0xc0, 0xc0, 0xc0, 0xc0, 0xe7, 0x7e, 0x00, 0x00, 0x00}, // C
      {0x00, 0x18, 0x18, 0x00, 0x18, 0x18, 0x18, 0x18, 0x18, 0x18, 0x00, 0x00, 0x00}, // !
  };
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int line = 0; line < 12; ++line) {
    palette_color(line);
    glRasterPos2f(4.0f + static_cast<float>(line), 8.0f + 20.0f * static_cast<float>(line));
    for (int k = 0; k < 24; ++k)
      glBitmap(8, 13, 0.0f, 2.0f, 9.0f + static_cast<float>(line % 3), 0.0f,
               glyphs[(k + line) % 4]);
  }
  // A wider bitmap with LSB_FIRST and skips, origin offsets and a diagonal move.
  std::vector<GLubyte> big(8 * 40);
  for (size_t i = 0; i < big.size(); ++i)
    big[i] = static_cast<GLubyte>((i * 37u) ^ (i >> 3));
  glPixelStorei(GL_UNPACK_LSB_FIRST, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 64);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 5);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
  glColor3f(1.0f, 1.0f, 0.0f);
  glRasterPos2f(230.0f, 200.0f);
  glBitmap(45, 30, 10.5f, -3.0f, -20.0f, -40.0f, big.data());
  glColor3f(0.0f, 1.0f, 1.0f); // only a new raster position picks this colour up
  glBitmap(45, 30, 0.0f, 0.0f, 0.0f, 0.0f, big.data());
  glRasterPos2f(200.0f, 100.0f);
  glBitmap(45, 30, 0.0f, 0.0f, 0.0f, 0.0f, big.data());
  reset_pixels();
}

PINEDA_SCENE(pixels_copy,
             "glCopyPixels: overlapping copies in four directions, zoomed and scaled copies, "
             "sources partly outside",
             .stencil_bits = 8) {
  clear_frame(0.0f, 0.0f, 0.0f);
  reset_pixels();
  // Source art: a smooth triangle fan.
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 6; ++i) {
    palette_color(i);
    glVertex2f(10.0f + 10.0f * static_cast<float>(i), 10.0f);
    palette_color(i + 3);
    glVertex2f(70.0f, 12.0f + 8.0f * static_cast<float>(i));
    palette_color(i + 7);
    glVertex2f(15.0f + 6.0f * static_cast<float>(i), 70.0f);
  }
  glEnd();
  glRasterPos2i(20, 15); // overlapping, up and right
  glCopyPixels(10, 10, 60, 60, GL_COLOR);
  glRasterPos2i(90, 10);
  glCopyPixels(10, 10, 80, 70, GL_COLOR);
  glRasterPos2i(85, 5); // overlapping, down and left
  glCopyPixels(90, 10, 80, 70, GL_COLOR);
  glPixelZoom(1.4f, -1.0f);
  glRasterPos2i(10, 200);
  glCopyPixels(20, 15, 60, 60, GL_COLOR);
  glPixelZoom(-1.0f, 1.0f);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferf(GL_BLUE_BIAS, 0.3f);
  glRasterPos2i(250, 130);
  glCopyPixels(85, 5, 80, 70, GL_COLOR);
  reset_pixels();
  // Source partly outside the window: those pixels make no fragments here and in Mesa alike
  // only where both leave the destination alone, so the copy lands inside the frame.
  glRasterPos2i(180, 200);
  glCopyPixels(-20, 30, 60, 50, GL_COLOR);
}

// clang-format off
PINEDA_SCENE(pixels_depth, "Depth DrawPixels and CopyPixels with the depth test: raster colour, depth scale/bias") {
  // clang-format on
  clear_frame(0.0f, 0.0f, 0.0f);
  reset_pixels();
  glEnable(GL_DEPTH_TEST);
  // A tilted quad across the middle, z from 0.2 to 0.8 (window).
  glBegin(GL_QUADS);
  glColor3f(0.2f, 0.4f, 0.9f);
  glVertex3f(0.0f, 60.0f, 0.6f);
  glVertex3f(256.0f, 60.0f, -0.6f);
  glVertex3f(256.0f, 200.0f, -0.6f);
  glVertex3f(0.0f, 200.0f, 0.6f);
  glEnd();
  // Depth images: a horizontal ramp 0..1 in several types.
  const int w = 200, h = 24;
  std::vector<GLfloat> zf;
  std::vector<GLushort> zus;
  std::vector<GLuint> zui;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float z = (static_cast<float>(x) + 0.5f) / static_cast<float>(w);
      zf.push_back(z);
      zus.push_back(static_cast<GLushort>(z * 65535.0f));
      zui.push_back(static_cast<GLuint>(static_cast<double>(z) * 4294967295.0));
    }
  glColor3f(1.0f, 0.3f, 0.2f);
  glRasterPos2i(28, 70);
  glDrawPixels(w, h, GL_DEPTH_COMPONENT, GL_FLOAT, zf.data());
  glColor3f(0.3f, 1.0f, 0.2f);
  glRasterPos2i(28, 100);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  glDrawPixels(w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, zus.data());
  glColor3f(1.0f, 1.0f, 0.2f);
  glRasterPos2i(28, 130);
  glPixelTransferf(GL_DEPTH_SCALE, -1.0f);
  glPixelTransferf(GL_DEPTH_BIAS, 1.0f);
  glDrawPixels(w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, zui.data());
  reset_pixels();
  // Colour images take the raster position's z: in front of part of the quad only.
  const auto img = image<GLubyte>(64, 40, 4, kRGBA, to_ub);
  glRasterPos3f(100.0f, 180.0f, 0.1f); // window z 0.45
  glDrawPixels(64, 40, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  // Copy a band of depth (with the raster colour) below the quad, then compare against it.
  glColor3f(1.0f, 0.0f, 1.0f);
  glRasterPos2i(28, 20);
  glDepthFunc(GL_ALWAYS);
  glCopyPixels(28, 100, w, 24, GL_DEPTH);
  glDepthFunc(GL_LESS);
  glBegin(GL_QUADS);
  glColor3f(0.9f, 0.9f, 0.9f);
  glVertex3f(0.0f, 10.0f, 0.0f);
  glVertex3f(256.0f, 10.0f, 0.0f);
  glVertex3f(256.0f, 50.0f, 0.0f);
  glVertex3f(0.0f, 50.0f, 0.0f);
  glEnd();
}

// MAP_STENCIL and INDEX_SHIFT/OFFSET are not used: llvmpipe ignores them when drawing and
// copying stencil indices (GL 2.1 §3.6.5 applies them; the API tests check Pineda does).
// clang-format off
PINEDA_SCENE(pixels_stencil, "Stencil DrawPixels (write mask, scissor, zoom) and CopyPixels, then stencil-tested quads", .stencil_bits = 8) {
  // clang-format on
  clear_frame(0.0f, 0.0f, 0.0f);
  reset_pixels();
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  const int w = 100, h = 80;
  std::vector<GLubyte> s8;
  std::vector<GLuint> s32;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      s8.push_back(static_cast<GLubyte>(((x / 10) ^ (y / 10)) & 3));
      s32.push_back(static_cast<GLuint>((x + y) / 12));
    }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(10, 10);
  glDrawPixels(w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s8.data());
  glStencilMask(0x06);
  glRasterPos2i(130, 10);
  glDrawPixels(w, h, GL_STENCIL_INDEX, GL_UNSIGNED_INT, s32.data());
  glStencilMask(0xff);
  glEnable(GL_SCISSOR_TEST);
  glScissor(20, 120, 60, 60);
  glRasterPos2i(10, 110);
  glDrawPixels(w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s8.data());
  glDisable(GL_SCISSOR_TEST);
  reset_pixels();
  glPixelZoom(1.0f, 0.6f);
  glRasterPos2i(130, 110);
  glCopyPixels(130, 10, 100, 80, GL_STENCIL);
  reset_pixels();
  // Show stencil values 0..3 (and more) as colours.
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  for (int v = 0; v < 8; ++v) {
    glStencilFunc(GL_EQUAL, v, 0xff);
    palette_color(v);
    glRecti(0, 0, 256, 256);
  }
  glDisable(GL_STENCIL_TEST);
}

// clang-format off
PINEDA_SCENE(pixels_window_pos, "glWindowPos2/3 in every type: images and bitmaps at window coordinates, depth from z") {
  // clang-format on
  clear_frame(0.1f, 0.1f, 0.1f);
  reset_pixels();
  const auto wp2i = proc<PFNGLWINDOWPOS2IPROC>("glWindowPos2i");
  const auto wp2f = proc<PFNGLWINDOWPOS2FPROC>("glWindowPos2f");
  const auto wp2d = proc<PFNGLWINDOWPOS2DPROC>("glWindowPos2d");
  const auto wp2s = proc<PFNGLWINDOWPOS2SPROC>("glWindowPos2s");
  const auto wp3f = proc<PFNGLWINDOWPOS3FPROC>("glWindowPos3f");
  const auto wp3iv = proc<PFNGLWINDOWPOS3IVPROC>("glWindowPos3iv");
  const auto img = image<GLubyte>(40, 30, 4, kRGBA, to_ub);
  // A projection that would move glRasterPos elsewhere: WindowPos ignores it.
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(50.0f, 20.0f, 0.0f);
  glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
  wp2i(10, 10);
  glDrawPixels(40, 30, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  wp2f(60.25f, 10.75f);
  glDrawPixels(40, 30, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  wp2d(110.0, 10.0);
  glDrawPixels(40, 30, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  wp2s(160, 10);
  glDrawPixels(40, 30, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  // Depth: two overlapping images at z 0.7 then 0.3 / 0.9 with the depth test on.
  glEnable(GL_DEPTH_TEST);
  wp3f(20.0f, 80.0f, 0.7f);
  glDrawPixels(40, 30, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glPixelZoom(2.0f, 2.0f);
  const GLint p3[3] = {30, 90, 1};
  wp3iv(p3);
  glDrawPixels(40, 30, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  wp3f(40.0f, 100.0f, 0.3f);
  glPixelZoom(1.0f, 1.0f);
  glDrawPixels(40, 30, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glDisable(GL_DEPTH_TEST);
  // Bitmaps with the colour current at WindowPos time, moving past the right edge.
  const GLubyte bar[4] = {0xff, 0x81, 0x81, 0xff};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glColor3f(1.0f, 0.5f, 0.0f);
  wp2f(150.0f, 200.0f);
  for (int i = 0; i < 20; ++i)
    glBitmap(8, 4, 0.0f, 0.0f, 7.0f, 1.0f, bar);
  reset_pixels();
}

PINEDA_SCENE(pixels_raster_pos, "glRasterPos through transforms: clipped (invalid) positions draw "
                                "nothing, lit raster colours, w") {
  clear_frame(0.0f, 0.0f, 0.0f);
  reset_pixels();
  const auto img = image<GLubyte>(24, 24, 4, kRGBA, to_ub);
  const GLubyte glyph[8] = {0x18, 0x3c, 0x7e, 0xff, 0xff, 0x7e, 0x3c, 0x18};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Positions outside the view volume: invalid, nothing drawn, bitmaps do not move.
  glRasterPos2f(-5.0f, 100.0f);
  glDrawPixels(24, 24, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glBitmap(8, 8, 0, 0, 300.0f, 0.0f, glyph);
  glRasterPos3f(100.0f, 100.0f, 2.0f); // behind the far plane
  glDrawPixels(24, 24, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  // A valid position just inside the left edge: the image extends past the window and is
  // clipped there like any fragments.
  glRasterPos2f(0.0f, 40.0f);
  glPixelZoom(-1.0f, 1.0f);
  glDrawPixels(24, 24, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glPixelZoom(1.0f, 1.0f);
  glRasterPos2f(240.0f, 40.0f);
  glDrawPixels(24, 24, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  // Perspective: positions through a frustum, w != 1.
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  for (int i = 0; i < 8; ++i) {
    const float a = 0.785f * static_cast<float>(i);
    palette_color(i);
    glRasterPos4f(0.6f * std::cos(a), 0.6f * std::sin(a), -2.0f - 0.3f * static_cast<float>(i),
                  1.0f);
    glBitmap(8, 8, 4.0f, 4.0f, 0.0f, 0.0f, glyph);
    glRasterPos4f(2.0f * std::cos(a), 2.0f * std::sin(a), -4.0f, 2.0f); // w = 2
    glDrawPixels(12, 12, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  }
  // A user clip plane invalidates positions in front of it.
  const GLdouble plane[4] = {1.0, 0.0, 0.0, 0.0}; // keep x >= 0 (eye space)
  glClipPlane(GL_CLIP_PLANE0, plane);
  glEnable(GL_CLIP_PLANE0);
  glColor3f(1.0f, 1.0f, 1.0f);
  for (int i = -3; i <= 3; ++i) {
    glRasterPos3f(0.2f * static_cast<float>(i), -0.7f, -2.0f);
    glBitmap(8, 8, 4.0f, 4.0f, 0.0f, 0.0f, glyph);
  }
  glDisable(GL_CLIP_PLANE0);
  // Lighting colours the raster position.
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat light_pos[4] = {0.0f, 1.0f, 1.0f, 0.0f};
  const GLfloat diffuse[4] = {0.9f, 0.6f, 0.2f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  for (int i = 0; i < 6; ++i) {
    const float a = 1.0f * static_cast<float>(i);
    glNormal3f(std::cos(a), std::sin(a), 0.5f);
    glRasterPos3f(-0.8f + 0.3f * static_cast<float>(i), 0.8f, -2.0f);
    glBitmap(8, 8, 4.0f, 4.0f, 0.0f, 0.0f, glyph);
  }
  glDisable(GL_LIGHTING);
  glDisable(GL_LIGHT0);
}

PINEDA_SCENE(pixels_fragment_ops,
             "Pixel fragments through blending, alpha test, scissor, logic op and colour mask",
             .stencil_bits = 8) {
  clear_frame(0.3f, 0.3f, 0.3f);
  reset_pixels();
  const int w = 60, h = 50;
  const auto img = image<GLubyte>(w, h, 4, kRGBA, to_ub);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glRasterPos2i(10, 10);
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glBlendFunc(GL_ONE, GL_ONE);
  glRasterPos2i(40, 30);
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glDisable(GL_BLEND);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  glRasterPos2i(120, 10);
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glDisable(GL_ALPHA_TEST);
  glEnable(GL_SCISSOR_TEST);
  glScissor(195, 20, 40, 30);
  glRasterPos2i(190, 10);
  glPixelZoom(1.0f, 1.4f);
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glPixelZoom(1.0f, 1.0f);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_XOR);
  glRasterPos2i(10, 100);
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glRasterPos2i(30, 110);
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glDisable(GL_COLOR_LOGIC_OP);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glRasterPos2i(120, 100);
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  // Bitmaps through blending: the raster colour with alpha 0.5.
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(1.0f, 1.0f, 0.0f, 0.5f);
  glRasterPos2i(190, 100);
  std::vector<GLubyte> bits(8 * 64);
  for (size_t i = 0; i < bits.size(); ++i)
    bits[i] = static_cast<GLubyte>(i % 3 ? 0xf0 : 0x3c);
  glBitmap(64, 64, 0.0f, 0.0f, 0.0f, 0.0f, bits.data());
  glDisable(GL_BLEND);
}

PINEDA_SCENE(pixels_read_transfer,
             "glReadPixels through scale/bias and maps, drawn back with glDrawPixels") {
  clear_frame(0.0f, 0.0f, 0.0f);
  reset_pixels();
  const auto img = image<GLubyte>(64, 64, 4, kRGBA, to_ub);
  glRasterPos2i(10, 10);
  glDrawPixels(64, 64, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  std::vector<GLubyte> back(64 * 64 * 4);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferf(GL_GREEN_BIAS, 0.2f);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(10, 10, 64, 64, GL_RGBA, GL_UNSIGNED_BYTE, back.data());
  reset_pixels();
  glRasterPos2i(90, 10);
  glDrawPixels(64, 64, GL_RGBA, GL_UNSIGNED_BYTE, back.data());
  // Luminance reads sum R + G + B after the transfer; a short type and a packed one.
  glPixelTransferf(GL_BLUE_SCALE, 0.0f);
  std::vector<GLushort> lum(64 * 64);
  glReadPixels(10, 10, 64, 64, GL_LUMINANCE, GL_UNSIGNED_SHORT, lum.data());
  std::vector<GLushort> packed(64 * 64);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  const GLfloat ramp[3] = {1.0f, 0.0f, 1.0f};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 3, ramp);
  glReadPixels(10, 10, 64, 64, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, packed.data());
  reset_pixels();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  glRasterPos2i(170, 10);
  glDrawPixels(64, 64, GL_LUMINANCE, GL_UNSIGNED_SHORT, lum.data());
  glRasterPos2i(10, 90);
  glDrawPixels(64, 64, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, packed.data());
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  reset_pixels();
}

// GL 2.1 §3.9: the colour sum applies to bitmap fragments, which take the raster position's
// secondary colour (llvmpipe leaves DrawPixels fragments alone, and so does Pineda). One
// secondary colour for the whole scene: llvmpipe caches bitmaps and draws them with the
// secondary colour current when its cache is flushed.
// clang-format off
PINEDA_SCENE(pixels_color_sum, "Bitmaps with COLOR_SUM: raster colour plus raster secondary colour; DrawPixels unchanged") {
  // clang-format on
  clear_frame(0.0f, 0.0f, 0.0f);
  reset_pixels();
  const auto secondary = proc<PFNGLSECONDARYCOLOR3FPROC>("glSecondaryColor3f");
  glEnable(GL_COLOR_SUM);
  secondary(0.25f, 0.0f, 0.375f);
  std::vector<GLubyte> bits(8 * 32);
  for (size_t i = 0; i < bits.size(); ++i)
    bits[i] = static_cast<GLubyte>(i % 2 ? 0xf0 : 0x5a);
  for (int i = 0; i < 6; ++i) {
    const float* c = palette(i + 10);
    glColor3f(c[0] * 0.6f, c[1] * 0.6f, c[2] * 0.6f);
    glRasterPos2i(10 + 40 * i, 10);
    glBitmap(32, 32, 0, 0, 0, 0, bits.data());
  }
  const auto img = image<GLubyte>(32, 32, 4, kRGBA, to_ub);
  glRasterPos2i(60, 60);
  glDrawPixels(32, 32, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glDisable(GL_COLOR_SUM);
}
