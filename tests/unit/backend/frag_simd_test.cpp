// The SIMD paths of the fragment stage against scalar references, bit for bit: the 16-bit
// SRC_ALPHA / ONE_MINUS_SRC_ALPHA blend (every source, destination and alpha value, and the
// float blend path it replaces), the byte packing helpers, the smooth colour rows of the block
// loop (the perspective-correct formula evaluated one fragment at a time) and the packed depth
// conversion and test of whole rows for 16-, 24- and 32-bit buffers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <random>

#include "fragment/blend.h"
#include "fragment/blend_simd.h"
#include "fragment/fragment_ops.h"
#include "core/simd.h"
#include "raster/raster.h"
#include "raster_test_util.h"

namespace pineda {
namespace {

using test::TestFb;

u32x4 load4(const uint8_t* p) {
  u32x4 v;
  std::memcpy(&v, p, sizeof(v));
  return v;
}

// Every (source, destination, alpha) triple, with alpha first (A = 0) and last (A = 3).
template <int A> void check_over_exhaustive() {
  uint8_t src[16], dst[16], out[16];
  for (int a = 0; a < 256; ++a) {
    for (int s = 0; s < 256; ++s) {
      for (int d0 = 0; d0 < 256; d0 += 4) {
        for (int p = 0; p < 4; ++p) {
          for (int k = 0; k < 4; ++k) {
            src[4 * p + k] = static_cast<uint8_t>(k == A ? a : s);
            dst[4 * p + k] = static_cast<uint8_t>(d0 + p);
          }
        }
        const u32x4 r = blend_over4<A>(load4(src), load4(dst));
        std::memcpy(out, &r, sizeof(out));
        for (int p = 0; p < 4; ++p) {
          for (int k = 0; k < 4; ++k) {
            const unsigned sv = k == A ? a : s;
            const uint8_t want = blend_over_channel(sv, static_cast<unsigned>(d0 + p), a);
            if (out[4 * p + k] != want) {
              FAIL() << "s " << sv << " d " << d0 + p << " a " << a << " got "
                     << int(out[4 * p + k]) << " want " << int(want);
            }
          }
        }
      }
    }
  }
}

TEST(FragSimd, BlendOverMatchesScalarForEveryInput) {
  check_over_exhaustive<3>();
  check_over_exhaustive<0>();
}

TEST(FragSimd, BlendOverMatchesFloatBlendPath) {
  // The float path (blend_pixel) with the same factors gives the same bytes.
  BlendParams bp;
  bp.src_rgb = bp.src_a = BlendFactor::SrcAlpha;
  bp.dst_rgb = bp.dst_a = BlendFactor::OneMinusSrcAlpha;
  std::mt19937 rng(11);
  uint8_t src[16], dst[16], out[16];
  for (int iter = 0; iter < 200000; ++iter) {
    for (int i = 0; i < 16; ++i) {
      src[i] = static_cast<uint8_t>(rng());
      dst[i] = static_cast<uint8_t>(rng());
    }
    const u32x4 r = blend_over4<3>(load4(src), load4(dst));
    std::memcpy(out, &r, sizeof(out));
    for (int p = 0; p < 4; ++p) {
      uint8_t want[4];
      blend_pixel(bp, src + 4 * p, dst + 4 * p, want);
      for (int k = 0; k < 4; ++k)
        ASSERT_EQ(out[4 * p + k], want[k]) << iter;
    }
  }
}

// Every factor pair without the constant colour, every equation, for colour and alpha
// separately, with and without destination alpha: the same bytes as the float path.
template <int A> void check_fixed_blend(std::mt19937& rng) {
  constexpr BlendFactor kFactors[] = {BlendFactor::Zero,
                                      BlendFactor::One,
                                      BlendFactor::SrcColor,
                                      BlendFactor::OneMinusSrcColor,
                                      BlendFactor::DstColor,
                                      BlendFactor::OneMinusDstColor,
                                      BlendFactor::SrcAlpha,
                                      BlendFactor::OneMinusSrcAlpha,
                                      BlendFactor::DstAlpha,
                                      BlendFactor::OneMinusDstAlpha,
                                      BlendFactor::SrcAlphaSaturate};
  constexpr BlendEq kEqs[] = {BlendEq::Add, BlendEq::Subtract, BlendEq::ReverseSubtract,
                              BlendEq::Min, BlendEq::Max};
  uint8_t src[16], dst[16], out[16];
  for (BlendFactor fs : kFactors) {
    for (BlendFactor fd : kFactors) {
      for (BlendEq eq : kEqs) {
        BlendParams bp;
        bp.src_rgb = fs;
        bp.dst_rgb = fd;
        bp.src_a = kFactors[rng() % std::size(kFactors)];
        bp.dst_a = kFactors[rng() % std::size(kFactors)];
        bp.eq_rgb = eq;
        bp.eq_a = kEqs[rng() % std::size(kEqs)];
        ASSERT_TRUE(blend_params_fixed(bp));
        for (int iter = 0; iter < 300; ++iter) {
          const bool has_alpha = iter % 3 != 0;
          for (int i = 0; i < 16; ++i) {
            src[i] = static_cast<uint8_t>(rng());
            dst[i] = static_cast<uint8_t>(rng());
          }
          const u32x4 r = blend_fixed4<A>(bp, has_alpha, load4(src), load4(dst));
          std::memcpy(out, &r, sizeof(out));
          for (int p = 0; p < 4; ++p) {
            // blend_pixel takes R, G, B, A: the three colour bytes in order, then alpha.
            uint8_t sc[4], dc[4], want[4];
            int pos[4], c = 0;
            for (int k = 0; k < 4; ++k)
              if (k != A) pos[c++] = k;
            pos[3] = A;
            for (int k = 0; k < 4; ++k) {
              sc[k] = src[4 * p + pos[k]];
              dc[k] = dst[4 * p + pos[k]];
            }
            if (!has_alpha) dc[3] = 255;
            blend_pixel(bp, sc, dc, want);
            for (int k = 0; k < 4; ++k)
              ASSERT_EQ(out[4 * p + pos[k]], want[k])
                  << "factors " << int(fs) << " " << int(fd) << " " << int(bp.src_a) << " "
                  << int(bp.dst_a) << " eqs " << int(eq) << " " << int(bp.eq_a) << " ch " << k
                  << " s " << int(sc[k]) << " d " << int(dc[k]);
          }
        }
      }
    }
  }
}

TEST(FragSimd, FixedBlendMatchesFloatBlendPath) {
  std::mt19937 rng(21);
  check_fixed_blend<3>(rng);
  check_fixed_blend<0>(rng);
}

TEST(FragSimd, FixedBlendExcludesConstantFactors) {
  BlendParams bp;
  EXPECT_TRUE(blend_params_fixed(bp));
  bp.dst_a = BlendFactor::OneMinusConstAlpha;
  EXPECT_FALSE(blend_params_fixed(bp));
  bp.dst_a = BlendFactor::Zero;
  bp.src_rgb = BlendFactor::ConstColor;
  EXPECT_FALSE(blend_params_fixed(bp));
}

TEST(FragSimd, WidenNarrowAndPackPixels) {
  std::mt19937 rng(5);
  for (int iter = 0; iter < 1000; ++iter) {
    uint8_t b[16];
    for (uint8_t& v : b)
      v = static_cast<uint8_t>(rng());
    u8x16 v;
    std::memcpy(&v, b, 16);
    const u16x8 lo = widen_lo(v), hi = widen_hi(v);
    for (int i = 0; i < 8; ++i) {
      ASSERT_EQ(lo[i], b[i]);
      ASSERT_EQ(hi[i], b[8 + i]);
    }
    const u8x16 n = narrow(lo, hi);
    for (int i = 0; i < 16; ++i)
      ASSERT_EQ(n[i], b[i]);
    i32x4 px[4];
    for (int p = 0; p < 4; ++p)
      px[p] = i32x4{b[4 * p], b[4 * p + 1], b[4 * p + 2], b[4 * p + 3]};
    const u32x4 packed = pack_pixels(px[0], px[1], px[2], px[3]);
    uint8_t pb[16];
    std::memcpy(pb, &packed, 16);
    for (int i = 0; i < 16; ++i)
      ASSERT_EQ(pb[i], b[i]);
  }
}

TEST(FragSimd, Lerp8LanesMatchesScalarForEveryInput) {
  for (int w = 0; w < 256; ++w) {
    for (int a = 0; a < 256; ++a) {
      for (int b0 = 0; b0 < 256; b0 += 8) {
        i16x8 va = {}, vb = {};
        for (int k = 0; k < 8; ++k) {
          va[k] = static_cast<int16_t>(a);
          vb[k] = static_cast<int16_t>(b0 + k);
        }
        const i16x8 r = lerp8_lanes(va, vb, w);
        for (int k = 0; k < 8; ++k) {
          const int want = a + (((b0 + k - a) * w + 128) >> 8);
          if (r[k] != want) FAIL() << a << " " << b0 + k << " " << w;
        }
      }
    }
  }
}

uint8_t ref_unorm8(float v) {
  v = v > 0.0f ? v : 0.0f;
  v = v < 1.0f ? v : 1.0f;
  return static_cast<uint8_t>(static_cast<int32_t>(v * 255.0f + 0.5f));
}

// Random colour planes over 8x8 blocks, with and without perspective: every byte the Smooth
// instance writes equals the scalar formula ((v0 + di dx + dj dy) + i dx) / (1/w).
TEST(FragSimd, SmoothRowsMatchScalarFormula) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-0.2f, 1.2f), slope(-0.05f, 0.05f);
  for (ColorFormat fmt :
       {ColorFormat::RGBA8, ColorFormat::BGRA8, ColorFormat::ARGB8, ColorFormat::RGB8}) {
    for (int iter = 0; iter < 400; ++iter) {
      const bool unit_w = iter % 2 == 0;
      TestFb t(16, 16, fmt, 0);
      RasterState rs;
      FragCtx ctx;
      prepare_fragments(rs, t.fb, ctx);
      FragInputs in;
      in.ox = static_cast<int>(rng() % 5);
      in.oy = static_cast<int>(rng() % 5);
      if (unit_w) {
        in.inv_w = PlaneF{1.0f, 0.0f, 0.0f};
      } else {
        in.inv_w = PlaneF{0.5f + static_cast<float>(rng() % 100) / 100.0f, slope(rng) * 0.1f,
                          slope(rng) * 0.1f};
      }
      for (PlaneF& p : in.color_w)
        p = PlaneF{u(rng), slope(rng), slope(rng)};
      const int bx = 8 * static_cast<int>(rng() % 2), by = 8 * static_cast<int>(rng() % 2);
      const uint64_t mask = (static_cast<uint64_t>(rng()) << 32) | rng();
      ctx.fn[static_cast<int>(ShadePath::Smooth)](ctx, in, bx, by, mask);
      for (int j = 0; j < 8; ++j) {
        for (int i = 0; i < 8; ++i) {
          const auto c = t.rgba(bx + i, by + j);
          if (((mask >> (8 * j + i)) & 1u) == 0) {
            ASSERT_EQ(c[0], 0);
            continue;
          }
          const float fi = static_cast<float>(bx - in.ox), fj = static_cast<float>(by + j - in.oy);
          const float iwr = in.inv_w.v0 + fi * in.inv_w.dx + fj * in.inv_w.dy;
          const float w = 1.0f / (iwr + static_cast<float>(i) * in.inv_w.dx);
          for (int k = 0; k < 4; ++k) {
            if (k == 3 && fmt == ColorFormat::RGB8) continue;
            const PlaneF& p = in.color_w[k];
            const float cr = p.v0 + fi * p.dx + fj * p.dy;
            const uint8_t want = ref_unorm8((cr + static_cast<float>(i) * p.dx) * w);
            ASSERT_EQ(c[k], want) << "fmt " << int(fmt) << " iter " << iter << " px " << i << ","
                                  << j << " ch " << k;
          }
        }
      }
    }
  }
}

// Random depth planes against random stored values: the LESS test and write of whole rows and
// of the partial last block, with the scalar conversion clamp(z) + 0.5 truncated.
TEST(FragSimd, DepthRowsMatchScalarConversion) {
  std::mt19937 rng(9);
  for (int bits : {16, 24, 32}) {
    const double zmax = bits >= 32 ? 4294967295.0 : static_cast<double>((1u << bits) - 1);
    for (int iter = 0; iter < 300; ++iter) {
      TestFb t(13, 8, ColorFormat::RGBA8, bits);
      for (uint32_t& d : t.depth_mem) {
        d = static_cast<uint32_t>(rng());
        if (bits < 32) d &= (1u << bits) - 1;
      }
      const std::vector<uint32_t> before = t.depth_mem;
      RasterState rs;
      rs.depth_test = true;
      rs.depth_func = GL_LESS;
      rs.depth_write = true;
      FragCtx ctx;
      prepare_fragments(rs, t.fb, ctx);
      FragInputs in;
      std::uniform_real_distribution<double> uz(-0.1 * zmax, 1.1 * zmax), dz(-zmax / 50, zmax / 50);
      in.z = PlaneD{uz(rng), dz(rng), dz(rng)};
      const int bx = 8 * static_cast<int>(rng() % 2);
      // Rasterizers hand over only fragments inside the buffer.
      const uint64_t mask =
          ((static_cast<uint64_t>(rng()) << 32) | rng()) & block_clip_mask(ctx, bx, 0);
      ctx.fn[static_cast<int>(ShadePath::Const)](ctx, in, bx, 0, mask);
      for (int j = 0; j < 8; ++j) {
        for (int i = 0; i < 8; ++i) {
          const int x = bx + i;
          if (x >= 13) continue;
          const uint32_t old = before[static_cast<size_t>(j) * 13 + x];
          uint32_t want = old;
          if ((mask >> (8 * j + i)) & 1u) {
            const double zr = in.z.v0 + (bx - in.ox) * in.z.dx + (j - in.oy) * in.z.dy;
            double z = zr + static_cast<double>(i) * in.z.dx;
            z = z > 0.0 ? z : 0.0;
            z = z < zmax ? z : zmax;
            const uint32_t q = static_cast<uint32_t>(static_cast<int64_t>(z + 0.5));
            if (q < old) want = q;
          }
          ASSERT_EQ(t.depth(x, j), want) << "bits " << bits << " iter " << iter;
        }
      }
    }
  }
}

} // namespace
} // namespace pineda
