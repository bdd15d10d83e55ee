// sample_quads (texture/sampler.h), the sampler's vector path for 2x2 quads, against
// sample_texture on the same fragments: the results must be the same bit for bit for every
// filter, wrap, level of detail and coordinate, including those the vector path hands back to
// the general one (NEAREST, MIRRORED_REPEAT, non-power-of-two REPEAT, huge and NaN coordinates).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "core/simd_level.h"
#include "texture/sampler.h"

namespace pineda {
namespace {

struct Rng {
  uint32_t s = 987654321u;
  uint32_t next() {
    s ^= s << 13;
    s ^= s >> 17;
    s ^= s << 5;
    return s;
  }
  float range(float lo, float hi) {
    return lo + (hi - lo) * static_cast<float>(next() >> 8) / 16777216.0f;
  }
};

// A complete mipmapped 2D RGBA texture of random texels, sampled through a SamplerView.
struct Texture {
  std::vector<std::vector<uint8_t>> data;
  SamplerView view;

  Texture(int w, int h, Rng& rng) {
    view.target = GL_TEXTURE_2D;
    view.base = TexBase::RGBA;
    view.width = w, view.height = h, view.depth = 1;
    int level = 0;
    for (int lw = w, lh = h;; lw = std::max(1, lw / 2), lh = std::max(1, lh / 2), ++level) {
      data.emplace_back(static_cast<size_t>(lw * lh * 4));
      for (uint8_t& b : data.back())
        b = static_cast<uint8_t>(rng.next() >> 24);
      view.levels[0][level] =
          SamplerLevel{.rgba = data.back().data(), .width = lw, .height = lh, .depth = 1};
      if (lw == 1 && lh == 1) break;
    }
    view.max_level = level;
  }
};

void expect_same(const SamplerView& v, const std::vector<float>& s, const std::vector<float>& t,
                 const std::vector<float>& lambda, float bias) {
  const int nq = static_cast<int>(lambda.size());
  float planes[4][64];
  sample_quads(v, nq, s.data(), t.data(), lambda.data(), bias, planes);
  for (int q = 0; q < nq; ++q) {
    const float lam[4] = {lambda[q], lambda[q], lambda[q], lambda[q]};
    float ref[4][4];
    sample_texture(v, 4, &s[4 * q], &t[4 * q], nullptr, lam, bias, ref);
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 4; ++c)
        ASSERT_EQ(std::memcmp(&planes[c][4 * q + k], &ref[k][c], sizeof(float)), 0)
            << "quad " << q << " fragment " << k << " channel " << c << " s " << s[4 * q + k]
            << " t " << t[4 * q + k] << " lambda " << lambda[q];
  }
}

// srgb: the views are of an sRGB texture (GL 2.1 §3.8.15), decoded and filtered in float.
void check_matches_sample_texture_for_every_filter_and_wrap(bool srgb) {
  Rng rng;
  const GLenum min_filters[] = {GL_NEAREST,
                                GL_LINEAR,
                                GL_NEAREST_MIPMAP_NEAREST,
                                GL_LINEAR_MIPMAP_NEAREST,
                                GL_NEAREST_MIPMAP_LINEAR,
                                GL_LINEAR_MIPMAP_LINEAR};
  const GLenum wraps[] = {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_MIRRORED_REPEAT, GL_CLAMP};
  const int sizes[][2] = {{16, 8}, {1, 4}, {12, 6}, {64, 64}};
  int vector_views = 0;
  for (const auto& size : sizes) {
    Texture tex(size[0], size[1], rng);
    for (GLenum minf : min_filters)
      for (GLenum magf : {GL_NEAREST, GL_LINEAR})
        for (GLenum ws : wraps)
          for (GLenum wt : wraps) {
            SamplerView& v = tex.view;
            v.min_filter = minf, v.mag_filter = magf, v.wrap_s = ws, v.wrap_t = wt;
            v.srgb = srgb;
            v.quads = quad_sampling_supported(v);
            vector_views += v.quads ? 1 : 0;
            std::vector<float> s(64), t(64), lambda(16);
            for (int round = 0; round < 8; ++round) {
              for (int q = 0; q < 16; ++q) {
                lambda[q] = rng.range(-3.0f, 8.0f);
                const float s0 = rng.range(-3.0f, 3.0f), t0 = rng.range(-3.0f, 3.0f);
                for (int k = 0; k < 4; ++k) {
                  s[4 * q + k] = s0 + rng.range(-0.2f, 0.2f);
                  t[4 * q + k] = t0 + rng.range(-0.2f, 0.2f);
                }
              }
              expect_same(v, s, t, lambda, round % 2 ? 0.0f : rng.range(-2.0f, 2.0f));
            }
          }
  }
  EXPECT_GT(vector_views, 0);
}

// Every instruction-set level (core/simd_level.h): the SSE2 lanes and, where the processor has
// them, the AVX2 and AVX-512 ones.
TEST(SampleQuads, MatchesSampleTextureForEveryFilterAndWrap) {
  const pineda::SimdLevel saved = pineda::simd_level();
  for (const pineda::SimdLevel level :
       {pineda::SimdLevel::Baseline, pineda::SimdLevel::Avx2, pineda::SimdLevel::Avx512}) {
    if (level > pineda::simd_level_supported()) continue;
    pineda::set_simd_level(level);
    SCOPED_TRACE(level == pineda::SimdLevel::Avx512 ? "AVX-512"
                 : level == pineda::SimdLevel::Avx2 ? "AVX2"
                                                    : "baseline");
    check_matches_sample_texture_for_every_filter_and_wrap(false);
  }
  pineda::set_simd_level(saved);
}

TEST(SampleQuads, SrgbMatchesSampleTextureForEveryFilterAndWrap) {
  const pineda::SimdLevel saved = pineda::simd_level();
  for (const pineda::SimdLevel level :
       {pineda::SimdLevel::Baseline, pineda::SimdLevel::Avx2, pineda::SimdLevel::Avx512}) {
    if (level > pineda::simd_level_supported()) continue;
    pineda::set_simd_level(level);
    check_matches_sample_texture_for_every_filter_and_wrap(true);
  }
  pineda::set_simd_level(saved);
}

void check_extreme_coordinates_and_levels_of_detail(bool srgb) {
  Rng rng;
  Texture tex(32, 16, rng);
  SamplerView& v = tex.view;
  v.srgb = srgb;
  v.min_filter = GL_LINEAR_MIPMAP_LINEAR;
  v.mag_filter = GL_LINEAR;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const float extremes[] = {0.0f,   1.0f,    -1.0f,    0.5f / 32.0f, 1.0e5f,   -1.0e5f,
                            1.0e6f, -1.0e6f, 3.0e6f,   1.0e9f,       -1.0e20f, nan,
                            inf,    -inf,    1.0e-30f, 4095.99f};
  for (GLenum wrap : {GL_REPEAT, GL_CLAMP_TO_EDGE}) {
    v.wrap_s = v.wrap_t = wrap;
    v.quads = quad_sampling_supported(v);
    ASSERT_TRUE(v.quads);
    std::vector<float> s, t, lambda;
    for (float e : extremes)
      for (float lam : {-64.0f, 0.0f, 0.3f, 2.5f, 64.0f, nan}) {
        for (int k = 0; k < 4; ++k) {
          s.push_back(k == 1 ? e : rng.range(0.0f, 1.0f));
          t.push_back(k == 2 ? e : rng.range(0.0f, 1.0f));
        }
        lambda.push_back(lam);
        if (lambda.size() == 16) {
          expect_same(v, s, t, lambda, 0.0f);
          s.clear(), t.clear(), lambda.clear();
        }
      }
    if (!lambda.empty()) expect_same(v, s, t, lambda, 0.0f);
  }
}

// Every instruction-set level (core/simd_level.h): the SSE2 lanes and, where the processor has
// them, the AVX2 and AVX-512 ones.
TEST(SampleQuads, ExtremeCoordinatesAndLevelsOfDetail) {
  const pineda::SimdLevel saved = pineda::simd_level();
  for (const pineda::SimdLevel level :
       {pineda::SimdLevel::Baseline, pineda::SimdLevel::Avx2, pineda::SimdLevel::Avx512}) {
    if (level > pineda::simd_level_supported()) continue;
    pineda::set_simd_level(level);
    SCOPED_TRACE(level == pineda::SimdLevel::Avx512 ? "AVX-512"
                 : level == pineda::SimdLevel::Avx2 ? "AVX2"
                                                    : "baseline");
    check_extreme_coordinates_and_levels_of_detail(false);
    check_extreme_coordinates_and_levels_of_detail(true);
  }
  pineda::set_simd_level(saved);
}

} // namespace
} // namespace pineda
