// The scissor test (GL 2.1 §4.1.2), alpha test (§4.1.4), stencil test and operations
// (§4.1.5) with the depth test's outcomes (§4.1.6), the logical operation (§4.1.10) and the
// stencil write mask (§4.2.2), each against an independent per-pixel reference, through the
// rasterizers and the block loops. Buffers 13 pixels wide exercise the partial last block.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "fragment/fragment_ops.h"
#include "fragment/per_fragment.h"
#include "framebuffer/clear.h"
#include "raster/raster.h"
#include "raster_test_util.h"

namespace pineda {
namespace {

using test::TestFb;
using test::vtx;

constexpr GLenum kFuncs[8] = {GL_NEVER,   GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                              GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
constexpr GLenum kStencilOps[8] = {GL_KEEP, GL_ZERO,   GL_REPLACE,   GL_INCR,
                                   GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};
constexpr ColorFormat kFormats[] = {ColorFormat::RGBA8, ColorFormat::BGRA8, ColorFormat::ARGB8,
                                    ColorFormat::RGB8};

// The comparison functions spelled out from GL 2.1 §4.1.4 / §4.1.5.
bool ref_compare(GLenum func, int a, int b) {
  switch (func) {
  case GL_NEVER:
    return false;
  case GL_LESS:
    return a < b;
  case GL_EQUAL:
    return a == b;
  case GL_LEQUAL:
    return a <= b;
  case GL_GREATER:
    return a > b;
  case GL_NOTEQUAL:
    return a != b;
  case GL_GEQUAL:
    return a >= b;
  default:
    return true;
  }
}

// The stencil operations of GL 2.1 §4.1.5 on an 8-bit value, in int arithmetic.
int ref_stencil_op(GLenum op, int v, int ref) {
  switch (op) {
  case GL_KEEP:
    return v;
  case GL_ZERO:
    return 0;
  case GL_REPLACE:
    return ref;
  case GL_INCR:
    return v < 255 ? v + 1 : 255;
  case GL_DECR:
    return v > 0 ? v - 1 : 0;
  case GL_INVERT:
    return 255 - v;
  case GL_INCR_WRAP:
    return (v + 1) % 256;
  case GL_DECR_WRAP:
    return (v + 255) % 256;
  default:
    return -1;
  }
}

// GL 2.1 table 4.3 on one byte.
int ref_logic(GLenum op, int s, int d) {
  int r = 0;
  switch (op) {
  case GL_CLEAR:
    r = 0;
    break;
  case GL_AND:
    r = s & d;
    break;
  case GL_AND_REVERSE:
    r = s & ~d;
    break;
  case GL_COPY:
    r = s;
    break;
  case GL_AND_INVERTED:
    r = ~s & d;
    break;
  case GL_NOOP:
    r = d;
    break;
  case GL_XOR:
    r = s ^ d;
    break;
  case GL_OR:
    r = s | d;
    break;
  case GL_NOR:
    r = ~(s | d);
    break;
  case GL_EQUIV:
    r = ~(s ^ d);
    break;
  case GL_INVERT:
    r = ~d;
    break;
  case GL_OR_REVERSE:
    r = s | ~d;
    break;
  case GL_COPY_INVERTED:
    r = ~s;
    break;
  case GL_OR_INVERTED:
    r = ~s | d;
    break;
  case GL_NAND:
    r = ~(s & d);
    break;
  case GL_SET:
    r = 0xff;
    break;
  default:
    break;
  }
  return r & 0xff;
}

// Two triangles covering the whole buffer at window depth z and one colour.
void fill_screen(const DrawCall& dc, float z, std::array<float, 4> c) {
  const float w = static_cast<float>(dc.fb->width), h = static_cast<float>(dc.fb->height);
  const PVertex a = vtx(0, 0, z, 1, c), b = vtx(w, 0, z, 1, c), d = vtx(w, h, z, 1, c),
                e = vtx(0, h, z, 1, c);
  raster_triangle(dc, a, b, d, d, false);
  raster_triangle(dc, a, d, e, e, false);
}

uint8_t stencil_at(const TestFb& t, int x, int y) {
  return t.stencil_mem[static_cast<size_t>(y) * t.fb.width + x];
}

TEST(PerFragment, StencilOpArithmetic) {
  for (GLenum op : kStencilOps)
    for (int v = 0; v < 256; v += 4)
      for (int ref : {0, 1, 0x5a, 254, 255}) {
        const i32x4 lanes = {v, v + 1, v + 2, v + 3};
        const i32x4 got = stencil_op_lanes(stencil_op_from_gl(op), lanes, i32x4{} + ref);
        for (int k = 0; k < 4; ++k)
          ASSERT_EQ(got[k], ref_stencil_op(op, v + k, ref))
              << std::hex << op << " v " << v + k << " ref " << ref;
      }
}

TEST(PerFragment, LogicOpArithmeticAllSixteen) {
  for (GLenum op = GL_CLEAR; op <= GL_SET; ++op) {
    const LogicMasks lm = logic_masks(op);
    for (int s = 0; s < 256; s += 3)
      for (int d = 0; d < 256; d += 5) {
        const uint32_t word = apply_logic(lm, static_cast<uint32_t>(s * 0x01010101u),
                                          static_cast<uint32_t>(d * 0x01010101u));
        ASSERT_EQ(word, static_cast<uint32_t>(ref_logic(op, s, d)) * 0x01010101u)
            << std::hex << op << " " << s << " " << d;
      }
  }
}

// Stencil test and update with the depth test, every function and op, masks and widths not
// a multiple of 8, against a per-pixel reference.
TEST(PerFragment, StencilWithDepthAgainstReference) {
  std::mt19937 rng(5);
  const int w = 13, h = 9;
  for (int fi = 0; fi < 8; ++fi) {
    for (int oi = 0; oi < 8; ++oi) {
      for (int variant = 0; variant < 3; ++variant) {
        TestFb t(w, h);
        std::vector<uint8_t> st0(static_cast<size_t>(w) * h), z_old(st0.size());
        for (size_t i = 0; i < st0.size(); ++i) {
          st0[i] = static_cast<uint8_t>(rng() & 0xff);
          if (i % 7 == 0) st0[i] = 0xff;
          if (i % 11 == 0) st0[i] = 0;
          t.stencil_mem[i] = st0[i];
          // Half of the pixels hold depth 0.25 (the fragment at 0.5 fails LESS there).
          z_old[i] = (rng() & 1) != 0;
          t.depth_mem[i] = z_old[i] ? 4194304u : 16777215u;
        }
        RasterState rs;
        rs.stencil_test = true;
        rs.stencil.func = kFuncs[fi];
        rs.stencil.ref = variant == 2 ? 300 : 0x5a; // 300 clamps to 255
        rs.stencil.value_mask = variant == 1 ? 0xf0u : 0xffffffffu;
        rs.stencil.writemask = variant == 1 ? 0x3cu : 0xffffffffu;
        // A different op for each outcome to tell them apart.
        rs.stencil.fail = kStencilOps[oi];
        rs.stencil.depth_fail = kStencilOps[(oi + 3) % 8];
        rs.stencil.depth_pass = kStencilOps[(oi + 5) % 8];
        rs.depth_test = variant != 2; // variant 2: depth off counts as passing
        DrawCall dc{&rs, &t.fb};
        fill_screen(dc, 0.5f, {1, 0, 0, 1});
        const int ref = variant == 2 ? 255 : 0x5a;
        const int vm = variant == 1 ? 0xf0 : 0xff, wm = variant == 1 ? 0x3c : 0xff;
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x) {
            const size_t i = static_cast<size_t>(y) * w + x;
            const bool spass = ref_compare(kFuncs[fi], ref & vm, st0[i] & vm);
            const bool zpass = !rs.depth_test || !z_old[i];
            const GLenum op =
                !spass ? rs.stencil.fail : (!zpass ? rs.stencil.depth_fail : rs.stencil.depth_pass);
            const int nv = ref_stencil_op(op, st0[i], ref);
            const int expect = (st0[i] & ~wm) | (nv & wm);
            ASSERT_EQ(stencil_at(t, x, y), expect) << "func " << fi << " op " << oi << " variant "
                                                   << variant << " at " << x << "," << y;
            ASSERT_EQ(t.rgba(x, y)[0], spass && zpass ? 255 : 0);
          }
      }
    }
  }
}

// GL 2.1 §4.1.5: without a stencil buffer the test passes and nothing is written.
TEST(PerFragment, NoStencilBufferPasses) {
  TestFb t(8, 8);
  t.fb.stencil = nullptr;
  t.fb.stencil_bits = 0;
  RasterState rs;
  rs.stencil_test = true;
  rs.stencil.func = GL_NEVER;
  DrawCall dc{&rs, &t.fb};
  fill_screen(dc, 0.5f, {0, 1, 0, 1});
  EXPECT_EQ(t.rgba(3, 3)[1], 255);
}

TEST(PerFragment, AlphaFunctionsAllEight) {
  const int refs8[] = {0, 1, 127, 128, 200, 255};
  for (GLenum f : kFuncs) {
    for (int r8 : refs8) {
      for (ColorFormat fmt : kFormats) {
        // One column per fragment alpha; the alpha of column x is a value exact in 8 bits.
        const int w = 13;
        TestFb t(w, 2, fmt);
        RasterState rs;
        rs.alpha_test = true;
        rs.alpha_func = f;
        rs.alpha_ref = static_cast<float>(r8) / 255.0f;
        DrawCall dc{&rs, &t.fb};
        const int alphas[w] = {0, 1, 2, 126, 127, 128, 129, 199, 200, 201, 254, 255, 64};
        for (int x = 0; x < w; ++x) {
          const float a = static_cast<float>(alphas[x]) / 255.0f;
          const PVertex p0 = vtx(x + 0.5f, 0.5f, 0.5f, 1, {1, 1, 1, a});
          const PVertex p1 = vtx(x + 0.5f, 1.5f, 0.5f, 1, {1, 1, 1, a});
          raster_point(dc, p0);
          raster_point(dc, p1);
        }
        for (int x = 0; x < w; ++x)
          for (int y = 0; y < 2; ++y)
            ASSERT_EQ(t.rgba(x, y)[0], ref_compare(f, alphas[x], r8) ? 255 : 0)
                << std::hex << f << std::dec << " ref " << r8 << " alpha " << alphas[x];
      }
    }
  }
}

// Smooth alpha: the comparison uses the alpha as it would be stored.
TEST(PerFragment, AlphaTestSmoothMatchesStoredAlpha) {
  TestFb t(64, 8);
  RasterState rs;
  rs.alpha_test = true;
  rs.alpha_func = GL_GEQUAL;
  rs.alpha_ref = 100.0f / 255.0f;
  DrawCall dc{&rs, &t.fb};
  const PVertex a = vtx(0, 0, 0.5f, 1, {1, 1, 1, 0}), b = vtx(64, 0, 0.5f, 1, {1, 1, 1, 1}),
                c = vtx(64, 8, 0.5f, 1, {1, 1, 1, 1}), d = vtx(0, 8, 0.5f, 1, {1, 1, 1, 0});
  raster_triangle(dc, a, b, c, c, false);
  raster_triangle(dc, a, c, d, d, false);
  // A second buffer without the test gives the stored alphas.
  TestFb u(64, 8);
  RasterState plain;
  DrawCall du{&plain, &u.fb};
  raster_triangle(du, a, b, c, c, false);
  raster_triangle(du, a, c, d, d, false);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 64; ++x) {
      const bool pass = u.rgba(x, y)[3] >= 100;
      ASSERT_EQ(t.rgba(x, y)[3], pass ? u.rgba(x, y)[3] : 0) << x << "," << y;
    }
}

// GL 2.1 §4.1.4 comes before §4.1.5 and §4.1.6: a fragment the alpha test discards touches
// neither the stencil nor the depth buffer.
TEST(PerFragment, AlphaTestBeforeStencilAndDepth) {
  TestFb t(16, 8);
  RasterState rs;
  rs.alpha_test = true;
  rs.alpha_func = GL_GREATER;
  rs.alpha_ref = 0.5f;
  rs.depth_test = true;
  rs.stencil_test = true;
  rs.stencil.depth_pass = GL_INCR;
  rs.stencil.fail = GL_INCR;
  DrawCall dc{&rs, &t.fb};
  fill_screen(dc, 0.25f, {1, 1, 1, 0.25f});
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) {
      ASSERT_EQ(t.depth(x, y), 16777215u);
      ASSERT_EQ(stencil_at(t, x, y), 0);
    }
  fill_screen(dc, 0.25f, {1, 1, 1, 0.75f});
  EXPECT_EQ(stencil_at(t, 5, 5), 1);
  EXPECT_EQ(t.depth(5, 5), 4194304u);
}

// Every logic op on every colour format, blending on (ignored), with a partial colour mask.
TEST(PerFragment, LogicOpsThroughPipeline) {
  std::mt19937 rng(9);
  for (ColorFormat fmt : kFormats) {
    for (GLenum op = GL_CLEAR; op <= GL_SET; ++op) {
      for (bool partial : {false, true}) {
        const int w = 13, h = 5;
        TestFb t(w, h, fmt);
        for (auto& b : t.color_mem)
          b = static_cast<uint8_t>(rng() & 0xff);
        std::vector<std::array<uint8_t, 4>> before;
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x)
            before.push_back(t.rgba(x, y));
        RasterState rs;
        rs.logic_op = true;
        rs.logic_op_mode = op;
        rs.blend = true;
        rs.blend_state.src_rgb = rs.blend_state.src_a = GL_ZERO;
        rs.blend_state.dst_rgb = rs.blend_state.dst_a = GL_ONE;
        if (partial) rs.color_write[1] = false;
        DrawCall dc{&rs, &t.fb};
        // 0x33, 0x5a, 0xcc, 0xa5 as colour.
        const int src[4] = {0x33, 0x5a, 0xcc, 0xa5};
        fill_screen(dc, 0.5f, {src[0] / 255.0f, src[1] / 255.0f, src[2] / 255.0f, src[3] / 255.0f});
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x) {
            const auto got = t.rgba(x, y);
            const auto old = before[static_cast<size_t>(y) * w + x];
            for (int k = 0; k < 4; ++k) {
              if (k == 3 && fmt == ColorFormat::RGB8) continue;
              const bool written = !(partial && k == 1);
              const int expect = written ? ref_logic(op, src[k], old[k]) : old[k];
              ASSERT_EQ(got[k], expect) << "fmt " << static_cast<int>(fmt) << " op " << std::hex
                                        << op << " ch " << k << " at " << x << "," << y;
            }
          }
      }
    }
  }
}

// Scissor on triangles, lines, points and clears: the image equals the unscissored image
// inside the box and the background outside it.
TEST(PerFragment, ScissorClipsEveryPrimitiveAndClear) {
  const int w = 37, h = 29;
  const int boxes[4][4] = {{5, 3, 20, 17}, {-10, -10, 20, 15}, {30, 20, 100, 100}, {8, 8, 0, 5}};
  int written_inside[4] = {0, 0, 0, 0}; // per primitive kind, so the test cannot pass empty
  for (const auto& box : boxes) {
    for (int prim = 0; prim < 4; ++prim) {
      TestFb clipped(w, h), full(w, h);
      RasterState rs_clip, rs_full;
      rs_clip.scissor_test = true;
      for (int i = 0; i < 4; ++i)
        rs_clip.scissor[i] = box[i];
      for (int pass = 0; pass < 2; ++pass) {
        TestFb& t = pass == 0 ? clipped : full;
        const RasterState& rs = pass == 0 ? rs_clip : rs_full;
        DrawCall dc{&rs, &t.fb};
        if (prim == 0) {
          raster_triangle(dc, vtx(-3, -2, 0.5f, 1, {1, 0, 0, 1}), vtx(40, 4, 0.5f, 1, {0, 1, 0, 1}),
                          vtx(12, 33, 0.5f, 1, {0, 0, 1, 1}), vtx(12, 33), false);
        } else if (prim == 1) {
          for (int i = 0; i < 12; ++i)
            raster_line(dc, vtx(18.3f, 14.2f),
                        vtx(18.3f + 25.0f * ((i % 5) - 2), 14.2f + 20.0f * ((i % 3) - 1) + i),
                        vtx(0, 0));
        } else if (prim == 2) {
          for (int y = 0; y < h; y += 2)
            for (int x = 0; x < w; x += 3)
              raster_point(dc, vtx(x + 0.5f, y + 0.5f));
        } else {
          ClearState cs;
          cs.color[0] = 1.0f;
          cs.stencil = 7;
          cs.scissor_test = pass == 0;
          for (int i = 0; i < 4; ++i)
            cs.scissor[i] = box[i];
          clear_buffers(t.fb, cs, GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        }
      }
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const bool inside =
              x >= box[0] && x < box[0] + box[2] && y >= box[1] && y < box[1] + box[3];
          const auto expect = inside ? full.rgba(x, y) : std::array<uint8_t, 4>{0, 0, 0, 0};
          ASSERT_EQ(clipped.rgba(x, y), expect) << "prim " << prim << " at " << x << "," << y;
          ASSERT_EQ(stencil_at(clipped, x, y), inside ? stencil_at(full, x, y) : 0);
          if (inside && expect[0] != 0) ++written_inside[prim];
        }
    }
  }
  for (int prim = 0; prim < 4; ++prim)
    EXPECT_GT(written_inside[prim], 10) << prim;
}

// Each operation switched on in a form that cannot change anything selects the very same
// block loop as with it off, and leaves the image unchanged.
TEST(PerFragment, OperationsOffOrInertChangeNothing) {
  RasterState base;
  base.depth_test = true;
  base.blend = true;
  base.blend_state.src_rgb = base.blend_state.src_a = GL_SRC_ALPHA;
  base.blend_state.dst_rgb = base.blend_state.dst_a = GL_ONE_MINUS_SRC_ALPHA;
  RasterState inert = base;
  inert.alpha_test = true;   // ALWAYS
  inert.stencil_test = true; // ALWAYS, KEEP
  inert.scissor_test = true;
  inert.scissor[2] = inert.scissor[3] = 1 << 20;
  RasterState stencil_nowrite = base;
  stencil_nowrite.stencil_test = true;
  stencil_nowrite.stencil.depth_pass = GL_INVERT;
  stencil_nowrite.stencil.writemask = 0xff00u; // no bit of an 8-bit buffer
  TestFb t0(16, 16);
  for (const RasterState* rs : {&inert, &stencil_nowrite}) {
    for (ShadePath s : {ShadePath::Const, ShadePath::Smooth}) {
      EXPECT_EQ(select_block_fn(make_state_key(*rs, t0.fb), s),
                select_block_fn(make_state_key(base, t0.fb), s));
    }
  }
  TestFb a(16, 16), b(16, 16);
  DrawCall da{&base, &a.fb}, db{&inert, &b.fb};
  for (DrawCall* dc : {&da, &db}) {
    raster_triangle(*dc, vtx(1, 1, 0.3f, 1, {1, 0, 0, 0.5f}), vtx(15, 2, 0.6f, 1, {0, 1, 0, 1}),
                    vtx(7, 15, 0.1f, 1, {0, 0, 1, 0.25f}), vtx(7, 15), false);
    fill_screen(*dc, 0.4f, {0.5f, 0.25f, 1.0f, 0.75f});
  }
  EXPECT_EQ(a.color_mem, b.color_mem);
  EXPECT_EQ(a.depth_mem, b.depth_mem);
  EXPECT_EQ(a.stencil_mem, b.stencil_mem);
  // Logic op COPY is a plain store, even with blending on (GL 2.1 §4.1.10).
  RasterState copy = base;
  copy.logic_op = true;
  RasterState plain;
  plain.depth_test = true;
  EXPECT_EQ(select_block_fn(make_state_key(copy, t0.fb), ShadePath::Smooth),
            select_block_fn(make_state_key(plain, t0.fb), ShadePath::Smooth));
}

} // namespace
} // namespace pineda
