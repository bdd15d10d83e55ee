// Per-fragment operations (GL 2.1 §4.1) and clears (§4.2.3): depth functions and masks, the
// depth buffer scales, blending against a double reference for every factor and equation,
// colour masks, the four colour byte orders, negative strides, and clears with masks.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "fragment/blend.h"
#include "fragment/fragment_ops.h"
#include "framebuffer/clear.h"
#include "raster/raster.h"
#include "raster_test_util.h"

namespace pineda {
namespace {

using test::TestFb;
using test::vtx;

constexpr ColorFormat kFormats[] = {ColorFormat::RGBA8, ColorFormat::BGRA8, ColorFormat::ARGB8,
                                    ColorFormat::RGB8};

// A screen-covering pair of triangles at constant z and colour.
void fill_screen(const DrawCall& dc, float z, std::array<float, 4> c) {
  const float w = static_cast<float>(dc.fb->width), h = static_cast<float>(dc.fb->height);
  const PVertex a = vtx(0, 0, z, 1, c), b = vtx(w, 0, z, 1, c), d = vtx(w, h, z, 1, c),
                e = vtx(0, h, z, 1, c);
  raster_triangle(dc, a, b, d, d, false);
  raster_triangle(dc, a, d, e, e, false);
}

TEST(Fragment, AllDepthFunctions) {
  const GLenum funcs[] = {GL_NEVER,   GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                          GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
  const float zs[] = {0.25f, 0.5f, 0.75f}; // less, equal, greater than the stored 0.5
  for (GLenum f : funcs) {
    for (bool write : {true, false}) {
      for (int zi = 0; zi < 3; ++zi) {
        TestFb t(8, 8);
        ClearState cs;
        cs.depth = 0.5;
        clear_buffers(t.fb, cs, GL_DEPTH_BUFFER_BIT);
        const uint32_t stored = t.depth(0, 0);
        RasterState rs;
        rs.depth_test = true;
        rs.depth_func = f;
        rs.depth_write = write;
        DrawCall dc{&rs, &t.fb};
        fill_screen(dc, zs[zi], {1, 0, 0, 1});
        const unsigned bit = 1u << zi;
        const bool pass = ((f - GL_NEVER) & bit) != 0;
        const uint32_t zq = static_cast<uint32_t>(std::lround(zs[zi] * 16777215.0));
        for (int y = 0; y < 8; ++y)
          for (int x = 0; x < 8; ++x) {
            ASSERT_EQ(t.rgba(x, y)[0], pass ? 255 : 0) << std::hex << f << " z " << zs[zi];
            ASSERT_EQ(t.depth(x, y), pass && write ? zq : stored);
          }
      }
    }
  }
}

TEST(Fragment, DepthTestOffNeitherTestsNorWrites) {
  TestFb t(8, 8);
  ClearState cs;
  cs.depth = 0.0; // everything would fail GL_LESS
  clear_buffers(t.fb, cs, GL_DEPTH_BUFFER_BIT);
  RasterState rs;
  rs.depth_test = false;
  DrawCall dc{&rs, &t.fb};
  fill_screen(dc, 0.5f, {0, 1, 0, 1});
  EXPECT_EQ(t.rgba(3, 3)[1], 255);
  EXPECT_EQ(t.depth(3, 3), 0u);
}

TEST(Fragment, NoDepthBufferAlwaysPasses) {
  TestFb t(8, 8, ColorFormat::RGBA8, 0);
  RasterState rs;
  rs.depth_test = true;
  rs.depth_func = GL_NEVER;
  DrawCall dc{&rs, &t.fb};
  fill_screen(dc, 0.5f, {0, 0, 1, 1});
  EXPECT_EQ(t.rgba(5, 5)[2], 255);
}

TEST(Fragment, DepthScaleForEachBufferSize) {
  for (int bits : {16, 24, 32}) {
    TestFb t(4, 4, ColorFormat::RGBA8, bits);
    RasterState rs;
    rs.depth_test = true;
    rs.depth_func = GL_ALWAYS;
    DrawCall dc{&rs, &t.fb};
    for (double z : {0.0, 1.0, 0.3, 0.5, 0.999}) {
      fill_screen(dc, static_cast<float>(z), {1, 1, 1, 1});
      const double maxv = bits == 32 ? 4294967295.0 : std::ldexp(1.0, bits) - 1;
      const double want = std::floor(static_cast<double>(static_cast<float>(z)) * maxv + 0.5);
      EXPECT_EQ(static_cast<double>(t.depth(1, 2)), want) << bits << " " << z;
    }
    // Out-of-range window z is clamped to [0,1].
    fill_screen(dc, 1.5f, {1, 1, 1, 1});
    EXPECT_EQ(t.depth(0, 0), TestFb::fb_depth_max(bits));
    fill_screen(dc, -0.5f, {1, 1, 1, 1});
    EXPECT_EQ(t.depth(0, 0), 0u);
  }
}

// Double-precision reference of GL 2.1 §4.1.8 on [0,1] values.
double ref_factor(GLenum f, int ch, const double s[4], const double d[4], const double k[4]) {
  const bool alpha = ch == 3;
  switch (f) {
  case GL_ZERO:
    return 0;
  case GL_ONE:
    return 1;
  case GL_SRC_COLOR:
    return s[ch];
  case GL_ONE_MINUS_SRC_COLOR:
    return 1 - s[ch];
  case GL_DST_COLOR:
    return d[ch];
  case GL_ONE_MINUS_DST_COLOR:
    return 1 - d[ch];
  case GL_SRC_ALPHA:
    return s[3];
  case GL_ONE_MINUS_SRC_ALPHA:
    return 1 - s[3];
  case GL_DST_ALPHA:
    return d[3];
  case GL_ONE_MINUS_DST_ALPHA:
    return 1 - d[3];
  case GL_CONSTANT_COLOR:
    return k[ch];
  case GL_ONE_MINUS_CONSTANT_COLOR:
    return 1 - k[ch];
  case GL_CONSTANT_ALPHA:
    return k[3];
  case GL_ONE_MINUS_CONSTANT_ALPHA:
    return 1 - k[3];
  case GL_SRC_ALPHA_SATURATE:
    return alpha ? 1 : std::min(s[3], 1 - d[3]);
  }
  return -1;
}

double ref_blend(GLenum eq, double s, double d, double fs, double fd) {
  double v = 0;
  switch (eq) {
  case GL_FUNC_ADD:
    v = s * fs + d * fd;
    break;
  case GL_FUNC_SUBTRACT:
    v = s * fs - d * fd;
    break;
  case GL_FUNC_REVERSE_SUBTRACT:
    v = d * fd - s * fs;
    break;
  case GL_MIN:
    v = std::min(s, d);
    break;
  case GL_MAX:
    v = std::max(s, d);
    break;
  }
  return std::clamp(v, 0.0, 1.0) * 255.0;
}

TEST(Fragment, BlendEveryFactorAndEquationMatchesReference) {
  const GLenum factors[] = {GL_ZERO,
                            GL_ONE,
                            GL_SRC_COLOR,
                            GL_ONE_MINUS_SRC_COLOR,
                            GL_DST_COLOR,
                            GL_ONE_MINUS_DST_COLOR,
                            GL_SRC_ALPHA,
                            GL_ONE_MINUS_SRC_ALPHA,
                            GL_DST_ALPHA,
                            GL_ONE_MINUS_DST_ALPHA,
                            GL_CONSTANT_COLOR,
                            GL_ONE_MINUS_CONSTANT_COLOR,
                            GL_CONSTANT_ALPHA,
                            GL_ONE_MINUS_CONSTANT_ALPHA,
                            GL_SRC_ALPHA_SATURATE};
  const GLenum eqs[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
  const std::array<float, 4> srcs[] = {{0.8f, 0.3f, 0.55f, 0.6f}, {0.1f, 0.9f, 0.45f, 0.2f}};
  const uint8_t dsts[][4] = {{40, 200, 128, 100}, {250, 10, 77, 230}};
  const float konst[4] = {0.25f, 0.5f, 0.9f, 0.35f};
  int checked = 0;
  for (ColorFormat fmt : {ColorFormat::RGBA8, ColorFormat::RGB8}) {
    for (size_t fi = 0; fi < std::size(factors); ++fi) {
      for (size_t fj = 0; fj < std::size(factors); ++fj) {
        for (size_t ei = 0; ei < std::size(eqs); ++ei) {
          RasterState rs;
          rs.blend = true;
          rs.blend_state.src_rgb = factors[fi];
          rs.blend_state.dst_rgb = factors[fj];
          // Separate alpha factors and equation, rotated through the lists.
          rs.blend_state.src_a = factors[(fi + 3 * fj + 1) % std::size(factors)];
          rs.blend_state.dst_a = factors[(fi * 7 + fj + 5) % std::size(factors)];
          rs.blend_state.eq_rgb = eqs[ei];
          rs.blend_state.eq_a = eqs[(ei + fi + fj) % std::size(eqs)];
          std::copy(konst, konst + 4, rs.blend_state.color);
          for (int si = 0; si < 2; ++si) {
            for (int di = 0; di < 2; ++di) {
              TestFb t(2, 1, fmt, 0);
              uint8_t* p = t.pixel(0, 0);
              const bool has_alpha = fmt != ColorFormat::RGB8;
              for (int k = 0; k < (has_alpha ? 4 : 3); ++k)
                p[k] = dsts[di][k];
              DrawCall dc{&rs, &t.fb};
              const PVertex v = vtx(0.5f, 0.5f, 0.5f, 1, srcs[si]);
              raster_point(dc, v);
              double s[4], d[4], k[4];
              for (int c = 0; c < 4; ++c) {
                // GL 2.1 §4.1.8: source components are fixed-point values like the
                // destination's, so the reference rounds them to 8 bits first (in float,
                // as the fragment colour is computed).
                s[c] = std::floor(srcs[si][c] * 255.0f + 0.5f) / 255.0;
                d[c] = (c == 3 && !has_alpha) ? 1.0 : dsts[di][c] / 255.0;
                k[c] = konst[c];
              }
              const auto got = t.rgba(0, 0);
              for (int c = 0; c < (has_alpha ? 4 : 3); ++c) {
                const GLenum sf = c == 3 ? rs.blend_state.src_a : rs.blend_state.src_rgb;
                const GLenum df = c == 3 ? rs.blend_state.dst_a : rs.blend_state.dst_rgb;
                const GLenum eq = c == 3 ? rs.blend_state.eq_a : rs.blend_state.eq_rgb;
                const double want = ref_blend(eq, s[c], d[c], ref_factor(sf, c, s, d, k),
                                              ref_factor(df, c, s, d, k));
                ASSERT_NEAR(got[c], want, 1.0) << "channel " << c << " src " << std::hex << sf
                                               << " dst " << df << " eq " << eq;
                ++checked;
              }
            }
          }
        }
      }
    }
  }
  EXPECT_GT(checked, 10000);
}

TEST(Fragment, BlendOverFastPathIsExact) {
  // SRC_ALPHA, ONE_MINUS_SRC_ALPHA in unorm8: round((s*a + d*(255-a)) / 255), in every
  // format, on full rows (width 16) and on the partial last block of a 13-pixel row.
  for (ColorFormat fmt : kFormats) {
    for (int width : {16, 13}) {
      for (int a = 0; a <= 255; a += 15) {
        TestFb t(width, 1, fmt, 0);
        for (int x = 0; x < width; ++x) {
          uint8_t* p = t.pixel(x, 0);
          const int d = (x * 37) % 256;
          for (int k = 0; k < bytes_per_pixel(fmt); ++k)
            p[k] = static_cast<uint8_t>(d);
        }
        RasterState rs;
        rs.blend = true;
        rs.blend_state.src_rgb = rs.blend_state.src_a = GL_SRC_ALPHA;
        rs.blend_state.dst_rgb = rs.blend_state.dst_a = GL_ONE_MINUS_SRC_ALPHA;
        DrawCall dc{&rs, &t.fb};
        fill_screen(dc, 0.5f, {200 / 255.0f, 10 / 255.0f, 1.0f, a / 255.0f});
        const double ar = a / 255.0;
        for (int x = 0; x < width; ++x) {
          const int d = (x * 37) % 256;
          const auto c = t.rgba(x, 0);
          ASSERT_EQ(c[0], std::lround(200 * ar + d * (1 - ar))) << int(fmt) << " x " << x;
          ASSERT_EQ(c[1], std::lround(10 * ar + d * (1 - ar)));
          ASSERT_EQ(c[2], std::lround(255 * ar + d * (1 - ar)));
          if (fmt != ColorFormat::RGB8) {
            ASSERT_EQ(c[3], std::lround(a * ar + d * (1 - ar)));
          }
        }
      }
    }
  }
}

TEST(Fragment, DepthOnlyWhenColorMaskIsOff) {
  TestFb t(12, 10);
  t.fill_color(9);
  RasterState rs;
  rs.depth_test = true;
  for (bool& w : rs.color_write)
    w = false;
  DrawCall dc{&rs, &t.fb};
  fill_screen(dc, 0.25f, {1, 1, 1, 1});
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 12; ++x) {
      ASSERT_EQ(t.depth(x, y), static_cast<uint32_t>(std::lround(0.25 * 16777215.0)));
      ASSERT_EQ(t.rgba(x, y)[0], 9);
    }
}

TEST(Fragment, ColorMaskEveryCombinationEveryFormat) {
  for (ColorFormat fmt : kFormats) {
    for (int mask = 0; mask < 16; ++mask) {
      for (bool blend : {false, true}) {
        TestFb t(9, 9, fmt, 0);
        t.fill_color(0x40);
        RasterState rs;
        for (int k = 0; k < 4; ++k)
          rs.color_write[k] = (mask >> k) & 1;
        rs.blend = blend; // ONE, ZERO: must behave like no blending
        if (blend) {
          rs.blend_state.src_rgb = GL_SRC_ALPHA;
          rs.blend_state.dst_rgb = GL_ZERO;
          rs.blend_state.src_a = GL_ONE;
          rs.blend_state.dst_a = GL_ZERO;
        }
        DrawCall dc{&rs, &t.fb};
        fill_screen(dc, 0.5f, {1.0f, 0.5f, 0.0f, 1.0f});
        const uint8_t want[4] = {255, 128, 0, 255};
        for (int y = 0; y < 9; ++y)
          for (int x = 0; x < 9; ++x) {
            const auto c = t.rgba(x, y);
            for (int k = 0; k < 3; ++k)
              ASSERT_EQ(c[k], ((mask >> k) & 1) ? want[k] : 0x40) << int(fmt) << " mask " << mask;
            if (fmt != ColorFormat::RGB8) {
              ASSERT_EQ(c[3], ((mask >> 3) & 1) ? 255 : 0x40);
            }
          }
      }
    }
  }
}

TEST(Fragment, ByteOrdersAndNegativeStride) {
  for (ColorFormat fmt : kFormats) {
    for (bool top_down : {false, true}) {
      TestFb t(10, 6, fmt, 24, top_down);
      RasterState rs;
      DrawCall dc{&rs, &t.fb};
      // A triangle covering only the bottom-left pixel's centre region.
      raster_triangle(dc, vtx(0, 0, 0.5f, 1, {0.2f, 0.4f, 0.6f, 0.8f}),
                      vtx(1.2f, 0, 0.5f, 1, {0.2f, 0.4f, 0.6f, 0.8f}),
                      vtx(0, 1.2f, 0.5f, 1, {0.2f, 0.4f, 0.6f, 0.8f}), vtx(0, 0), false);
      // Pixel (0,0) is the first pixel of the last memory row for top-down memory.
      const int bpp = bytes_per_pixel(fmt);
      const uint8_t* mem = t.color_mem.data() + (top_down ? (6 - 1) * 10 * bpp : 0);
      const uint8_t r = 51, g = 102, b = 153, a = 204;
      switch (fmt) {
      case ColorFormat::RGBA8:
        EXPECT_EQ(std::vector<uint8_t>(mem, mem + 4), (std::vector<uint8_t>{r, g, b, a}));
        break;
      case ColorFormat::BGRA8:
        EXPECT_EQ(std::vector<uint8_t>(mem, mem + 4), (std::vector<uint8_t>{b, g, r, a}));
        break;
      case ColorFormat::ARGB8:
        EXPECT_EQ(std::vector<uint8_t>(mem, mem + 4), (std::vector<uint8_t>{a, r, g, b}));
        break;
      case ColorFormat::RGB8:
        EXPECT_EQ(std::vector<uint8_t>(mem, mem + 4), (std::vector<uint8_t>{r, g, b, 0}));
        break;
      }
      // Nothing else was written.
      size_t nonzero = 0;
      for (uint8_t v : t.color_mem)
        nonzero += v != 0;
      EXPECT_EQ(nonzero, fmt == ColorFormat::RGB8 ? 3u : 4u);
    }
  }
}

TEST(Clear, ColorEveryFormatAndMask) {
  for (ColorFormat fmt : kFormats) {
    for (bool top_down : {false, true}) {
      for (int mask = 0; mask < 16; ++mask) {
        TestFb t(13, 7, fmt, 24, top_down);
        t.fill_color(0x11);
        ClearState cs;
        cs.color[0] = 1.0f;
        cs.color[1] = 0.5f;
        cs.color[2] = 0.25f;
        cs.color[3] = 2.0f; // clamped
        for (int k = 0; k < 4; ++k)
          cs.color_write[k] = (mask >> k) & 1;
        clear_buffers(t.fb, cs, GL_COLOR_BUFFER_BIT);
        const uint8_t want[4] = {255, 128, 64, 255};
        for (int y = 0; y < 7; ++y)
          for (int x = 0; x < 13; ++x) {
            const auto c = t.rgba(x, y);
            for (int k = 0; k < (fmt == ColorFormat::RGB8 ? 3 : 4); ++k)
              ASSERT_EQ(c[k], ((mask >> k) & 1) ? want[k] : 0x11) << int(fmt) << " " << mask;
          }
      }
    }
  }
}

TEST(Clear, UniformBytesAndPatterns) {
  for (ColorFormat fmt : kFormats) {
    TestFb t(5, 3, fmt);
    ClearState cs;
    for (float v : {0.0f, 1.0f}) {
      for (float& c : cs.color)
        c = v;
      clear_buffers(t.fb, cs, GL_COLOR_BUFFER_BIT);
      for (uint8_t b : t.color_mem)
        ASSERT_EQ(b, v > 0 ? 255 : 0);
    }
  }
}

TEST(Clear, DepthAndStencilWithMasks) {
  for (int bits : {16, 24, 32}) {
    TestFb t(9, 5, ColorFormat::RGBA8, bits);
    ClearState cs;
    cs.depth = 0.25;
    clear_buffers(t.fb, cs, GL_DEPTH_BUFFER_BIT);
    const double maxv = bits == 32 ? 4294967295.0 : std::ldexp(1.0, bits) - 1;
    const uint32_t want = static_cast<uint32_t>(std::floor(0.25 * maxv + 0.5));
    EXPECT_EQ(t.depth(8, 4), want);
    cs.depth = 1.0;
    cs.depth_write = false;
    clear_buffers(t.fb, cs, GL_DEPTH_BUFFER_BIT);
    EXPECT_EQ(t.depth(0, 0), want);
  }
  TestFb t(9, 5);
  ClearState cs;
  cs.stencil = 0x1a5; // masked to 8 bits: 0xa5
  clear_buffers(t.fb, cs, GL_STENCIL_BUFFER_BIT);
  EXPECT_EQ(t.stencil_mem[44], 0xa5);
  cs.stencil = 0x0f;
  cs.stencil_writemask = 0x3c;
  clear_buffers(t.fb, cs, GL_STENCIL_BUFFER_BIT);
  EXPECT_EQ(t.stencil_mem[0], (0xa5 & ~0x3c) | (0x0f & 0x3c));
  // Only the named buffers are cleared.
  t.fill_color(7);
  cs.color[0] = 1;
  clear_buffers(t.fb, cs, GL_DEPTH_BUFFER_BIT);
  EXPECT_EQ(t.color_mem[0], 7);
}

TEST(Fragment, KeySelection) {
  Framebuffer fb;
  uint8_t pixel[4];
  uint32_t depth = 0;
  fb.width = fb.height = 1;
  fb.color = pixel;
  fb.depth = &depth;
  fb.depth_bits = 24;
  fb.depth_stride = 1;
  RasterState rs;
  StateKey k = make_state_key(rs, fb);
  EXPECT_EQ(k.depth_path(), DepthPath::Off);
  EXPECT_EQ(k.color_path(), ColorPath::All);
  EXPECT_EQ(k.blend_path(), BlendPath::Off);
  rs.depth_test = true;
  EXPECT_EQ(make_state_key(rs, fb).depth_path(), DepthPath::LessWrite);
  rs.depth_func = GL_LEQUAL;
  EXPECT_EQ(make_state_key(rs, fb).depth_path(), DepthPath::LequalWrite);
  rs.depth_write = false;
  EXPECT_EQ(make_state_key(rs, fb).depth_path(), DepthPath::Generic);
  rs.blend = true; // ONE, ZERO, ADD is a plain store
  EXPECT_EQ(make_state_key(rs, fb).blend_path(), BlendPath::Off);
  rs.blend_state.src_rgb = rs.blend_state.src_a = GL_SRC_ALPHA;
  rs.blend_state.dst_rgb = rs.blend_state.dst_a = GL_ONE_MINUS_SRC_ALPHA;
  EXPECT_EQ(make_state_key(rs, fb).blend_path(), BlendPath::Over);
  rs.blend_state.eq_a = GL_MAX;
  EXPECT_EQ(make_state_key(rs, fb).blend_path(), BlendPath::Generic);
  rs.color_write[3] = false;
  EXPECT_EQ(make_state_key(rs, fb).color_path(), ColorPath::Partial);
  fb.color_format = ColorFormat::RGB8; // no alpha: RGB is every channel
  fb.alpha_bits = 0;
  EXPECT_EQ(make_state_key(rs, fb).color_path(), ColorPath::All);
  for (bool& w : rs.color_write)
    w = false;
  EXPECT_EQ(make_state_key(rs, fb).color_path(), ColorPath::None);
  fb.depth = nullptr;
  FragCtx ctx;
  rs.depth_test = true;
  prepare_fragments(rs, fb, ctx);
  EXPECT_TRUE(ctx.noop); // nothing to write and no depth buffer
}

} // namespace
} // namespace pineda
