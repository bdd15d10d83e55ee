// The block loops compiled for AVX2 (fragment_ops_avx2.cpp) against the baseline ones, byte
// for byte: random triangles through every depth path and buffer size, blend path, colour
// format and mask, shade path (constant, smooth, perspective, per fragment with fog), and the
// extended operations (alpha test, stencil, logical operation, sample counting). Also the
// whole-block depth rejection (block_loop_impl.h block_fails_depth) against the same block
// drawn one row at a time, which never takes that shortcut, with stored depths right at the
// plane's values.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "fragment/fragment_ops.h"
#include "fragment/shade.h"
#include "core/simd_level.h"
#include "core/vertex.h"
#include "raster/raster.h"
#include "raster_test_util.h"

namespace pineda {
namespace {

using test::TestFb;
using test::vtx;

// Puts the level back when a test ends.
struct LevelGuard {
  SimdLevel saved = simd_level();
  ~LevelGuard() { set_simd_level(saved); }
};

struct Case {
  std::string name;
  RasterState rs;
  ColorFormat format = ColorFormat::RGBA8;
  int depth_bits = 24;
  bool fog = false;
};

std::vector<Case> make_cases() {
  std::vector<Case> cases;
  const auto add = [&](std::string name, auto edit) {
    Case c;
    c.name = std::move(name);
    edit(c);
    cases.push_back(c);
  };
  add("plain", [](Case&) {});
  for (int bits : {16, 24, 32}) {
    add("less" + std::to_string(bits), [bits](Case& c) {
      c.rs.depth_test = true;
      c.depth_bits = bits;
    });
  }
  add("lequal", [](Case& c) {
    c.rs.depth_test = true;
    c.rs.depth_func = GL_LEQUAL;
  });
  for (GLenum f = GL_NEVER; f <= GL_ALWAYS; ++f) {
    for (bool write : {false, true}) {
      add("func" + std::to_string(f - GL_NEVER) + (write ? "w" : ""), [f, write](Case& c) {
        c.rs.depth_test = true;
        c.rs.depth_func = f;
        c.rs.depth_write = write;
        c.depth_bits = f % 2 ? 32 : 24;
      });
    }
  }
  add("depth_only", [](Case& c) {
    c.rs.depth_test = true;
    for (bool& w : c.rs.color_write)
      w = false;
  });
  for (ColorFormat f :
       {ColorFormat::RGBA8, ColorFormat::BGRA8, ColorFormat::ARGB8, ColorFormat::RGB8}) {
    const std::string fs = std::to_string(static_cast<int>(f));
    add("over" + fs, [f](Case& c) {
      c.format = f;
      c.rs.depth_test = true;
      c.rs.blend = true;
      c.rs.blend_state.src_rgb = c.rs.blend_state.src_a = GL_SRC_ALPHA;
      c.rs.blend_state.dst_rgb = c.rs.blend_state.dst_a = GL_ONE_MINUS_SRC_ALPHA;
    });
    add("fixed" + fs, [f](Case& c) {
      c.format = f;
      c.rs.blend = true;
      c.rs.blend_state.src_rgb = GL_DST_COLOR;
      c.rs.blend_state.dst_rgb = GL_ONE_MINUS_SRC_COLOR;
      c.rs.blend_state.src_a = GL_SRC_ALPHA_SATURATE;
      c.rs.blend_state.dst_a = GL_ONE;
      c.rs.blend_state.eq_a = GL_FUNC_REVERSE_SUBTRACT;
    });
    add("const" + fs, [f](Case& c) {
      c.format = f;
      c.rs.blend = true;
      c.rs.blend_state.src_rgb = c.rs.blend_state.src_a = GL_CONSTANT_COLOR;
      c.rs.blend_state.dst_rgb = c.rs.blend_state.dst_a = GL_ONE_MINUS_CONSTANT_ALPHA;
      c.rs.blend_state.color[0] = 0.3f;
      c.rs.blend_state.color[1] = 0.6f;
      c.rs.blend_state.color[2] = 0.9f;
      c.rs.blend_state.color[3] = 0.45f;
    });
    add("mask" + fs, [f](Case& c) {
      c.format = f;
      c.rs.depth_test = true;
      c.rs.color_write[1] = false;
    });
    add("fog" + fs, [f](Case& c) {
      c.format = f;
      c.rs.depth_test = true;
      c.fog = true;
    });
  }
  add("minmax", [](Case& c) {
    c.rs.blend = true;
    c.rs.blend_state.eq_rgb = GL_MIN;
    c.rs.blend_state.eq_a = GL_MAX;
  });
  add("alpha", [](Case& c) {
    c.rs.depth_test = true;
    c.rs.alpha_test = true;
    c.rs.alpha_func = GL_GEQUAL;
    c.rs.alpha_ref = 0.5f;
  });
  add("stencil", [](Case& c) {
    c.rs.depth_test = true;
    c.rs.stencil_test = true;
    c.rs.stencil.func = GL_LEQUAL;
    c.rs.stencil.ref = 100;
    c.rs.stencil.fail = GL_INCR;
    c.rs.stencil.depth_fail = GL_DECR_WRAP;
    c.rs.stencil.depth_pass = GL_INVERT;
  });
  add("logic", [](Case& c) {
    c.rs.logic_op = true;
    c.rs.logic_op_mode = GL_XOR;
  });
  add("logic_rgb", [](Case& c) {
    c.format = ColorFormat::RGB8;
    c.rs.logic_op = true;
    c.rs.logic_op_mode = GL_NAND;
  });
  add("samples", [](Case& c) {
    c.rs.depth_test = true;
    c.rs.count_samples = true;
  });
  add("scissor", [](Case& c) {
    c.rs.depth_test = true;
    c.rs.scissor_test = true;
    c.rs.scissor[0] = 5;
    c.rs.scissor[1] = 3;
    c.rs.scissor[2] = 30;
    c.rs.scissor[3] = 20;
  });
  return cases;
}

// A framebuffer with the same pseudo-random contents for every level, drawn with the same
// random triangles: big ones covering whole blocks (and whole screens, at constant or sloped
// z), small ones, perspective ones, flat ones, colours beyond [0,1].
struct Result {
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;
  std::vector<uint8_t> stencil;
  uint64_t samples = 0;
};

Result render(const Case& c, SimdLevel level) {
  set_simd_level(level);
  constexpr int kW = 61, kH = 45; // not multiples of 8: partial rows and columns
  TestFb t(kW, kH, c.format, c.depth_bits);
  std::mt19937 rng(1234);
  for (uint8_t& b : t.color_mem)
    b = static_cast<uint8_t>(rng());
  const uint32_t dmax = TestFb::fb_depth_max(c.depth_bits);
  for (uint32_t& d : t.depth_mem)
    d = static_cast<uint32_t>(rng()) & dmax;
  for (uint8_t& s : t.stencil_mem)
    s = static_cast<uint8_t>(rng() % 200);
  RasterState rs = c.rs;
  ShadeSetup ss;
  if (c.fog) {
    ss.fog = true;
    ss.fog_per_vertex = true; // kAttrFog holds the factor
    ss.fog_color[0] = 0.2f;
    ss.fog_color[1] = 0.7f;
    ss.fog_color[2] = 0.4f;
    ss.fog_color[3] = 1.0f;
    rs.shade = &ss;
    rs.attr_count = kAttrFog + 1;
  }
  FragCtx fc;
  prepare_fragments(rs, t.fb, fc);
  DrawCall dc{&rs, &t.fb};
  dc.frag = &fc;
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const auto color = [&] {
    return std::array<float, 4>{unit(rng) * 1.4f - 0.2f, unit(rng) * 1.4f - 0.2f,
                                unit(rng) * 1.4f - 0.2f, unit(rng)};
  };
  for (int i = 0; i < 60; ++i) {
    const int kind = i % 5;
    PVertex v[4];
    if (kind == 0) {
      // The whole screen at one z (near or far of what is stored) or a sloped z.
      const float z0 = unit(rng) * 1.2f - 0.1f;
      const float z1 = (i % 10 == 0) ? z0 : unit(rng);
      const std::array<float, 4> col = color();
      v[0] = vtx(-3, -3, z0, 1, col);
      v[1] = vtx(kW + 3, -3, z1, 1, color());
      v[2] = vtx(kW + 3, kH + 3, z0, 1, col);
      v[3] = vtx(-3, kH + 3, z1, 1, col);
    } else {
      const float s = kind == 1 ? 3.0f : 70.0f;
      for (auto& p : v) {
        const float inv_w = kind == 2 ? 0.2f + 2.0f * unit(rng) : 1.0f;
        p = vtx(unit(rng) * (kW + 20) - 10, unit(rng) * (kH + 20) - 10, unit(rng), inv_w, color());
      }
      v[1].win[0] = v[0].win[0] + s * (unit(rng) - 0.2f);
      v[1].win[1] = v[0].win[1] + s * (unit(rng) - 0.5f);
      v[2].win[0] = v[0].win[0] + s * (unit(rng) - 0.5f);
      v[2].win[1] = v[0].win[1] + s * (unit(rng) - 0.2f);
    }
    for (auto& p : v)
      p.attr[kAttrFog] = unit(rng);
    rs.flat = kind == 3;
    raster_triangle(dc, v[0], v[1], v[2], v[2], false);
    raster_triangle(dc, v[0], v[2], v[3], v[3], false);
  }
  return Result{t.color_mem, t.depth_mem, t.stencil_mem, fc.samples_passed};
}

void expect_level_matches_baseline(SimdLevel level) {
  LevelGuard guard;
  for (const Case& c : make_cases()) {
    SCOPED_TRACE(c.name);
    const Result base = render(c, SimdLevel::Baseline);
    const Result wide = render(c, level);
    EXPECT_EQ(base.color, wide.color);
    EXPECT_EQ(base.depth, wide.depth);
    EXPECT_EQ(base.stencil, wide.stencil);
    EXPECT_EQ(base.samples, wide.samples);
  }
}

TEST(SimdPaths, Avx2BlockLoopsMatchBaseline) {
  if (simd_level_supported() < SimdLevel::Avx2) GTEST_SKIP() << "no AVX2 on this machine";
  expect_level_matches_baseline(SimdLevel::Avx2);
}

TEST(SimdPaths, Avx512BlockLoopsMatchBaseline) {
  if (simd_level_supported() < SimdLevel::Avx512) GTEST_SKIP() << "no AVX-512 on this machine";
  expect_level_matches_baseline(SimdLevel::Avx512);
}

TEST(SimdPaths, LevelSelectsTable) {
  LevelGuard guard;
  RasterState rs;
  rs.depth_test = true;
  TestFb t(16, 16);
  const StateKey key = make_state_key(rs, t.fb);
  set_simd_level(SimdLevel::Baseline);
  EXPECT_EQ(simd_level(), SimdLevel::Baseline);
  EXPECT_EQ(select_block_fn(key, ShadePath::Smooth),
            select_block_fn_baseline(key, ShadePath::Smooth));
  set_simd_level(SimdLevel::Avx2);
  EXPECT_EQ(simd_level(), std::min(SimdLevel::Avx2, simd_level_supported()));
#if PINEDA_HAVE_AVX2
  if (simd_level_supported() >= SimdLevel::Avx2) {
    EXPECT_EQ(select_block_fn(key, ShadePath::Smooth),
              select_block_fn_avx2(key, ShadePath::Smooth));
    EXPECT_NE(select_block_fn(key, ShadePath::Smooth),
              select_block_fn_baseline(key, ShadePath::Smooth));
  }
#endif
  set_simd_level(SimdLevel::Avx512);
  EXPECT_EQ(simd_level(), simd_level_supported());
#if PINEDA_HAVE_AVX512
  if (simd_level_supported() >= SimdLevel::Avx512) {
    EXPECT_EQ(select_block_fn(key, ShadePath::Smooth),
              select_block_fn_avx512(key, ShadePath::Smooth));
    EXPECT_NE(select_block_fn(key, ShadePath::Smooth),
              select_block_fn_avx2(key, ShadePath::Smooth));
  }
#endif
}

// set_simd_level and PINEDA_SIMD never go above what the processor has, and PINEDA_SIMD caps
// the level at the one it names.
TEST(SimdPaths, LevelIsClamped) {
  LevelGuard guard;
  const SimdLevel top = simd_level_supported();
  for (SimdLevel level : {SimdLevel::Baseline, SimdLevel::Avx2, SimdLevel::Avx512}) {
    set_simd_level(level);
    EXPECT_EQ(simd_level(), std::min(level, top));
  }
  EXPECT_EQ(simd_level_from_env(nullptr, top), top);
  EXPECT_EQ(simd_level_from_env("sse2", top), SimdLevel::Baseline);
  EXPECT_EQ(simd_level_from_env("baseline", top), SimdLevel::Baseline);
  EXPECT_EQ(simd_level_from_env("avx2", top), std::min(SimdLevel::Avx2, top));
  EXPECT_EQ(simd_level_from_env("avx512", top), top);
  EXPECT_EQ(simd_level_from_env("", top), top);
  // On processors of every level.
  EXPECT_EQ(simd_level_from_env("avx2", SimdLevel::Avx512), SimdLevel::Avx2);
  EXPECT_EQ(simd_level_from_env("avx2", SimdLevel::Baseline), SimdLevel::Baseline);
  EXPECT_EQ(simd_level_from_env("avx512", SimdLevel::Avx2), SimdLevel::Avx2);
  EXPECT_EQ(simd_level_from_env("sse2", SimdLevel::Avx512), SimdLevel::Baseline);
}

// z of the plane at pixel (px, py) as the block loop stores it (depth_values): the same double
// arithmetic in the same order.
uint32_t stored_z(const FragInputs& in, double dmax, int px, int py) {
  const int di = (px & ~7) - in.ox, dj = py - in.oy;
  const double zr = in.z.v0 + di * in.z.dx + dj * in.z.dy;
  double z = zr + static_cast<double>(px & 7) * in.z.dx;
  z = z > 0.0 ? z : 0.0; // maxpd(z, 0) gives 0 for NaN as well
  z = (z < dmax ? z : dmax) + 0.5;
  return static_cast<uint32_t>(static_cast<int64_t>(z));
}

TEST(SimdPaths, WholeBlockDepthRejectionIsExact) {
  LevelGuard guard;
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const GLenum funcs[] = {GL_LESS, GL_LEQUAL, GL_GREATER, GL_GEQUAL, GL_EQUAL, GL_NEVER};
  int skipped_blocks = 0, drawn_blocks = 0;
  for (SimdLevel level : {SimdLevel::Baseline, SimdLevel::Avx2, SimdLevel::Avx512}) {
    if (level > simd_level_supported()) continue;
    set_simd_level(level);
    for (int bits : {16, 24, 32}) {
      for (GLenum func : funcs) {
        for (bool write : {true, false}) {
          for (int iter = 0; iter < 40; ++iter) {
            TestFb a(16, 16, ColorFormat::RGBA8, bits), b(16, 16, ColorFormat::RGBA8, bits);
            RasterState rs;
            rs.depth_test = true;
            rs.depth_func = func;
            rs.depth_write = write;
            FragCtx ctx;
            prepare_fragments(rs, a.fb, ctx);
            FragInputs in;
            in.ox = static_cast<int>(rng() % 9);
            in.oy = static_cast<int>(rng() % 9);
            const double dmax = ctx.depth_max;
            in.z.v0 = (unit(rng) * 1.2 - 0.1) * dmax;
            const double slope = iter % 4 == 0 ? 0.0 : (unit(rng) - 0.5) * dmax * 1e-3;
            in.z.dx = slope * unit(rng);
            in.z.dy = iter % 3 == 0 ? 0.0 : slope * unit(rng);
            in.inv_w = PlaneF{1, 0, 0};
            for (int k = 0; k < 4; ++k)
              in.color_w[k] = PlaneF{static_cast<float>(unit(rng)), 0.01f, -0.01f};
            // Stored values at, just below or just above each fragment's own value, or all at
            // the block's extreme value: the cases a loose bound would get wrong.
            const int mode = iter % 4;
            const int bx = 8, by = 8;
            uint32_t extreme = stored_z(in, dmax, bx, by);
            for (int j = 0; j < 8; ++j)
              for (int i = 0; i < 8; ++i) {
                const uint32_t z = stored_z(in, dmax, bx + i, by + j);
                const bool lowfunc = func == GL_LESS || func == GL_LEQUAL;
                extreme = lowfunc ? std::min(extreme, z) : std::max(extreme, z);
              }
            for (int j = 0; j < 8; ++j) {
              for (int i = 0; i < 8; ++i) {
                const uint32_t z = stored_z(in, dmax, bx + i, by + j);
                int64_t v = mode == 3 ? extreme : z;
                if (mode == 1) v -= rng() % 2;
                if (mode == 2) v += rng() % 2;
                v = std::max<int64_t>(0, std::min<int64_t>(v, static_cast<int64_t>(dmax)));
                a.depth_mem[static_cast<size_t>(by + j) * 16 + bx + i] = static_cast<uint32_t>(v);
                b.depth_mem[static_cast<size_t>(by + j) * 16 + bx + i] = static_cast<uint32_t>(v);
              }
            }
            FragCtx cb;
            prepare_fragments(rs, b.fb, cb);
            ctx.fn[static_cast<int>(ShadePath::Smooth)](ctx, in, bx, by, ~uint64_t{0});
            for (int j = 0; j < 8; ++j)
              cb.fn[static_cast<int>(ShadePath::Smooth)](cb, in, bx, by, uint64_t{0xff} << (8 * j));
            ASSERT_EQ(a.depth_mem, b.depth_mem) << bits << " " << func << " " << iter;
            ASSERT_EQ(a.color_mem, b.color_mem) << bits << " " << func << " " << iter;
            bool any = false;
            for (uint8_t byte : a.color_mem)
              any |= byte != 0;
            (any ? drawn_blocks : skipped_blocks) += 1;
          }
        }
      }
    }
  }
  // Both outcomes occurred.
  EXPECT_GT(skipped_blocks, 0);
  EXPECT_GT(drawn_blocks, 0);
}

} // namespace
} // namespace pineda
