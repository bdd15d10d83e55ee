// The texture sampler (src/texture/sampler.cpp) against a double-precision reference written
// from GL 2.1 §3.8.8-§3.8.10 and §3.8.14: every filter and wrap mode, borders, level of detail
// and mipmap level choice, cube face selection, depth comparison, base format expansion and
// completeness. The reference follows llvmpipe where the spec leaves room (c = 0; NEAREST_MIPMAP
// rounds half up); the fixed-point path is checked against exact llvmpipe values separately.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "texture/sampler.h"
#include "state/tex_format.h"
#include "state/texture_object.h"

namespace {

using pineda::SamplerView;
using pineda::TexBase;
using pineda::TexImage;
using pineda::TextureObject;

using RGBA = std::array<double, 4>;

// An RGBA8 image of w x h x d texels (border included) with random contents.
TexImage random_image(std::mt19937& rng, int w, int h, int d, int border = 0) {
  TexImage im;
  im.width = w, im.height = h, im.depth = d, im.border = border;
  im.internal_format = GL_RGBA8;
  im.base = TexBase::RGBA;
  im.red_size = im.green_size = im.blue_size = im.alpha_size = 8;
  im.rgba.resize(size_t(w) * h * d * 4);
  for (auto& b : im.rgba)
    b = uint8_t(rng() & 255);
  return im;
}

TexImage solid_image(int w, int h, int d, uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
  TexImage im;
  im.width = w, im.height = h, im.depth = d;
  im.internal_format = GL_RGBA8;
  im.base = TexBase::RGBA;
  im.red_size = im.green_size = im.blue_size = im.alpha_size = 8;
  for (int i = 0; i < w * h * d; ++i)
    im.rgba.insert(im.rgba.end(), {r, g, b, a});
  return im;
}

// ---- the reference ----

struct Ref {
  const TextureObject* tex;
  int dims;
  int face = 0;
};

double wrap_coord(double s, GLenum wrap, int n) {
  switch (wrap) {
  case GL_REPEAT:
    return s - std::floor(s);
  case GL_CLAMP:
    return std::clamp(s, 0.0, 1.0);
  case GL_CLAMP_TO_EDGE:
    return std::clamp(s, 0.5 / n, 1.0 - 0.5 / n);
  case GL_CLAMP_TO_BORDER:
    return std::clamp(s, -0.5 / n, 1.0 + 0.5 / n);
  default: { // MIRRORED_REPEAT
    const double f = s - std::floor(s);
    return (int64_t(std::floor(s)) & 1) ? 1.0 - f : f;
  }
  }
}

// Texel (i, j, k) with i, j, k relative to the border; the border colour outside.
RGBA texel(const Ref& r, int level, int i, int j, int k) {
  const TexImage& im = r.tex->images[r.face][level];
  const int b = im.border, bj = r.dims >= 2 ? b : 0, bk = r.dims >= 3 ? b : 0;
  const int w = im.width - 2 * b, h = im.height - 2 * bj, d = im.depth - 2 * bk;
  if (i < -b || i >= w + b || j < -bj || j >= h + bj || k < -bk || k >= d + bk) {
    const float* c = r.tex->params.border_color;
    return {c[0], c[1], c[2], c[3]};
  }
  const size_t idx = (size_t(k + bk) * im.height + size_t(j + bj)) * im.width + size_t(i + b);
  const uint8_t* t = &im.rgba[idx * 4];
  return {t[0] / 255.0, t[1] / 255.0, t[2] / 255.0, t[3] / 255.0};
}

RGBA ref_level(const Ref& r, int level, GLenum filter, double s, double t, double q) {
  const TexImage& im = r.tex->images[r.face][level];
  const int b = im.border;
  const int n[3] = {im.width - 2 * b, r.dims >= 2 ? im.height - 2 * b : 1,
                    r.dims >= 3 ? im.depth - 2 * b : 1};
  const GLenum wraps[3] = {r.tex->params.wrap_s, r.tex->params.wrap_t, r.tex->params.wrap_r};
  const double c[3] = {s, t, q};
  int i0[3] = {0, 0, 0}, i1[3] = {0, 0, 0};
  double a[3] = {0, 0, 0};
  for (int ax = 0; ax < r.dims; ++ax) {
    const double u = wrap_coord(c[ax], wraps[ax], n[ax]) * n[ax];
    if (filter == GL_NEAREST) {
      int i = int(std::floor(u));
      if (wraps[ax] == GL_CLAMP_TO_BORDER)
        i = std::clamp(i, -1, n[ax]);
      else
        i = std::min(i, n[ax] - 1);
      i0[ax] = i1[ax] = i;
    } else {
      const double f = std::floor(u - 0.5);
      i0[ax] = int(f), i1[ax] = int(f) + 1, a[ax] = u - 0.5 - f;
      if (wraps[ax] == GL_REPEAT) {
        i0[ax] = (i0[ax] % n[ax] + n[ax]) % n[ax];
        i1[ax] = (i1[ax] % n[ax] + n[ax]) % n[ax];
      } else if (wraps[ax] == GL_MIRRORED_REPEAT || wraps[ax] == GL_CLAMP_TO_EDGE) {
        i0[ax] = std::clamp(i0[ax], 0, n[ax] - 1);
        i1[ax] = std::clamp(i1[ax], 0, n[ax] - 1);
      }
    }
  }
  RGBA out{0, 0, 0, 0};
  for (int kk = 0; kk < (r.dims >= 3 ? 2 : 1); ++kk)
    for (int jj = 0; jj < (r.dims >= 2 ? 2 : 1); ++jj)
      for (int ii = 0; ii < 2; ++ii) {
        const double w = (ii ? a[0] : 1 - a[0]) * (r.dims >= 2 ? (jj ? a[1] : 1 - a[1]) : 1) *
                         (r.dims >= 3 ? (kk ? a[2] : 1 - a[2]) : 1);
        const RGBA tx = texel(r, level, ii ? i1[0] : i0[0], jj ? i1[1] : i0[1], kk ? i1[2] : i0[2]);
        for (int q2 = 0; q2 < 4; ++q2)
          out[q2] += w * tx[q2];
      }
  return out;
}

// GL 2.1 §3.8.8-§3.8.9: lod, magnification (c = 0), level choice, mipmap blend.
RGBA ref_sample(const Ref& r, double s, double t, double q, double lambda, double unit_bias,
                int q_level) {
  const auto& p = r.tex->params;
  const double bias = std::clamp(unit_bias + p.lod_bias, -16.0, 16.0);
  const double lod = std::max(std::min(lambda + bias, double(p.max_lod)), double(p.min_lod));
  const int base = p.base_level;
  const GLenum mf = p.min_filter;
  if (lod <= 0.0) return ref_level(r, base, p.mag_filter, s, t, q);
  const GLenum img =
      (mf == GL_NEAREST || mf == GL_NEAREST_MIPMAP_NEAREST || mf == GL_NEAREST_MIPMAP_LINEAR)
          ? GL_NEAREST
          : GL_LINEAR;
  if (mf == GL_NEAREST || mf == GL_LINEAR) return ref_level(r, base, img, s, t, q);
  if (mf == GL_NEAREST_MIPMAP_NEAREST || mf == GL_LINEAR_MIPMAP_NEAREST) {
    const int d = std::min(base + int(std::floor(lod + 0.5)), q_level);
    return ref_level(r, d, img, s, t, q);
  }
  const int d0 = base + int(std::floor(lod));
  if (d0 >= q_level) return ref_level(r, q_level, img, s, t, q);
  const double w = lod - std::floor(lod);
  const RGBA a = ref_level(r, d0, img, s, t, q), b = ref_level(r, d0 + 1, img, s, t, q);
  return {a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]), a[2] + w * (b[2] - a[2]),
          a[3] + w * (b[3] - a[3])};
}

RGBA sample1(const SamplerView& v, float s, float t, float r, float lambda, float bias = 0) {
  float out[1][4];
  pineda::sample_texture(v, 1, &s, &t, &r, &lambda, bias, out);
  return {out[0][0], out[0][1], out[0][2], out[0][3]};
}

// A mipmapped texture of `dims` dimensions with random levels.
TextureObject make_tex(std::mt19937& rng, GLenum target, int w, int h, int d, bool mips,
                       int border = 0) {
  TextureObject tex;
  tex.target = target;
  const int dims = target == GL_TEXTURE_1D ? 1 : target == GL_TEXTURE_3D ? 3 : 2;
  for (int level = 0;; ++level) {
    tex.images[0][level] = random_image(rng, w + 2 * border, dims >= 2 ? h + 2 * border : 1,
                                        dims >= 3 ? d + 2 * border : 1, border);
    if (!mips || (w == 1 && h == 1 && d == 1)) break;
    w = std::max(1, w / 2), h = std::max(1, h / 2), d = std::max(1, d / 2);
  }
  return tex;
}

constexpr GLenum kWraps[] = {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER,
                             GL_MIRRORED_REPEAT};
constexpr GLenum kMinFilters[] = {GL_NEAREST,
                                  GL_LINEAR,
                                  GL_NEAREST_MIPMAP_NEAREST,
                                  GL_LINEAR_MIPMAP_NEAREST,
                                  GL_NEAREST_MIPMAP_LINEAR,
                                  GL_LINEAR_MIPMAP_LINEAR};

bool simple_wrap(GLenum w) {
  return w == GL_REPEAT || w == GL_CLAMP_TO_EDGE;
}

// Every filter and wrap on 1D, 2D (power-of-two and not) and 3D textures at random
// coordinates and levels of detail.
TEST(TextureSampler, EveryFilterAndWrapAgainstReference) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<float> coord(-1.7f, 2.3f), lam(-1.5f, 4.5f);
  struct Case {
    GLenum target;
    int w, h, d;
  } cases[] = {{GL_TEXTURE_1D, 16, 1, 1},
               {GL_TEXTURE_2D, 8, 4, 1},
               {GL_TEXTURE_2D, 5, 3, 1},
               {GL_TEXTURE_3D, 4, 4, 4}};
  for (const Case& c : cases) {
    TextureObject tex = make_tex(rng, c.target, c.w, c.h, c.d, true);
    const int dims = c.target == GL_TEXTURE_1D ? 1 : c.target == GL_TEXTURE_3D ? 3 : 2;
    int q = 0;
    while (tex.images[0][q + 1].width != 0)
      ++q;
    for (GLenum wrap : kWraps) {
      for (GLenum minf : kMinFilters) {
        for (GLenum magf : {GL_NEAREST, GL_LINEAR}) {
          tex.params.wrap_s = tex.params.wrap_t = tex.params.wrap_r = wrap;
          tex.params.min_filter = minf;
          tex.params.mag_filter = magf;
          const float bc[4] = {0.25f, 0.5f, 0.75f, 1.0f};
          std::copy(bc, bc + 4, tex.params.border_color);
          SamplerView v;
          ASSERT_TRUE(pineda::make_sampler_view(tex, v));
          // The fixed-point path quantizes coordinates and weights to 1/256 and truncates each
          // linear step: a few 8-bit steps from the exact value.
          const double tol = simple_wrap(wrap) ? 3.5 / 255.0 : 1e-5;
          Ref r{&tex, dims};
          for (int k = 0; k < 200; ++k) {
            const float s = coord(rng), t = coord(rng), rr = coord(rng), l = lam(rng);
            // Keep NEAREST sampling away from texel edges, where a rounding of s picks the
            // neighbour: both are right.
            bool near_edge = false;
            for (int ax = 0; ax < dims; ++ax) {
              const double u = double(ax == 0   ? s
                                      : ax == 1 ? t
                                                : rr) *
                               (ax == 0   ? c.w
                                : ax == 1 ? c.h
                                          : c.d) *
                               64.0;
              near_edge |= std::fabs(u - std::round(u)) < 1e-2;
            }
            if (near_edge) continue;
            const double lf = l - std::floor(l);
            if (std::fabs(lf - 0.5) < 1e-3 || lf < 1e-3) continue; // level choice ties
            const RGBA got = sample1(v, s, t, rr, l);
            const RGBA want = ref_sample(r, s, t, rr, l, 0.0, q);
            for (int ch = 0; ch < 4; ++ch)
              ASSERT_NEAR(got[ch], want[ch], tol)
                  << "target " << c.target << " " << c.w << "x" << c.h << " wrap " << wrap
                  << " min " << minf << " mag " << magf << " s " << s << " t " << t << " r " << rr
                  << " lambda " << l << " ch " << ch;
          }
        }
      }
    }
  }
}

// llvmpipe's 8-bit linear step: v0 + floor(((v1 - v0) * w + 128) / 256), coordinates in 1/256
// texel.
TEST(TextureSampler, FixedPointLinearMatchesLlvmpipe) {
  TextureObject tex;
  tex.target = GL_TEXTURE_2D;
  tex.images[0][0] = solid_image(2, 1, 1, 0, 0, 0, 0);
  tex.images[0][0].rgba = {0, 255, 10, 200, 255, 0, 20, 100};
  tex.params.min_filter = tex.params.mag_filter = GL_LINEAR;
  tex.params.wrap_s = tex.params.wrap_t = GL_CLAMP_TO_EDGE;
  SamplerView v;
  ASSERT_TRUE(pineda::make_sampler_view(tex, v));
  // s = 0.5: u = 0.5 * 2 * 256 - 128 = 128 -> texels 0 and 1, weight 128/256.
  RGBA c = sample1(v, 0.5f, 0.5f, 0, 0);
  EXPECT_EQ(std::lround(c[0] * 255), 128); // 0 + ((255 * 128 + 128) >> 8)
  EXPECT_EQ(std::lround(c[1] * 255), 128); // 255 + ((-255 * 128 + 128) >> 8) = 255 - 127
  EXPECT_EQ(std::lround(c[2] * 255), 15);
  EXPECT_EQ(std::lround(c[3] * 255), 150); // 200 + floor(-49.5)
  // s = 0.3: u = round(153.6) - 128 = 26 -> weight 26/256.
  c = sample1(v, 0.3f, 0.5f, 0, 0);
  EXPECT_EQ(std::lround(c[0] * 255), (255 * 26 + 128) >> 8);
  EXPECT_EQ(std::lround(c[1] * 255), 255 + ((-255 * 26 + 128) >> 8));
}

// NEAREST_MIPMAP_*: level base + round-half-up(lod); LINEAR_MIPMAP: floor and fraction;
// biases, MIN/MAX_LOD, BASE/MAX_LEVEL.
TEST(TextureSampler, MipmapLevelChoice) {
  TextureObject tex;
  tex.target = GL_TEXTURE_2D;
  const uint8_t level_value[5] = {0, 60, 120, 180, 240};
  for (int l = 0, n = 16; l < 5; ++l, n /= 2)
    tex.images[0][l] = solid_image(n, n, 1, level_value[l], 0, 0, 255);
  tex.params.mag_filter = GL_NEAREST;
  tex.params.min_filter = GL_NEAREST_MIPMAP_NEAREST;
  SamplerView v;
  ASSERT_TRUE(pineda::make_sampler_view(tex, v));
  auto level_of = [&](float lambda, float bias = 0) {
    const double r = sample1(v, 0.3f, 0.3f, 0, lambda, bias)[0] * 255.0;
    return int(std::lround(r / 60.0));
  };
  EXPECT_EQ(level_of(-2.0f), 0);
  EXPECT_EQ(level_of(0.49f), 0);
  EXPECT_EQ(level_of(0.5f), 1); // llvmpipe rounds half up (GL 2.1 says level 0)
  EXPECT_EQ(level_of(1.49f), 1);
  EXPECT_EQ(level_of(1.5f), 2);
  EXPECT_EQ(level_of(9.0f), 4);
  EXPECT_EQ(level_of(0.0f, 2.0f), 2);   // unit bias
  EXPECT_EQ(level_of(0.0f, 100.0f), 4); // biases clamp to MAX_TEXTURE_LOD_BIAS
  tex.params.lod_bias = 1.0f;           // object bias adds
  ASSERT_TRUE(pineda::make_sampler_view(tex, v));
  EXPECT_EQ(level_of(1.0f), 2);
  tex.params.lod_bias = 0.0f;
  tex.params.max_lod = 1.2f;
  tex.params.min_lod = 0.7f;
  ASSERT_TRUE(pineda::make_sampler_view(tex, v));
  EXPECT_EQ(level_of(3.0f), 1);
  EXPECT_EQ(level_of(0.1f), 1); // min_lod 0.7 rounds to level 1
  tex.params.max_lod = 1000.0f;
  tex.params.min_lod = -1000.0f;
  tex.params.base_level = 1;
  tex.params.max_level = 2;
  ASSERT_TRUE(pineda::make_sampler_view(tex, v));
  EXPECT_EQ(level_of(-1.0f), 1);
  EXPECT_EQ(level_of(0.7f), 2);
  EXPECT_EQ(level_of(5.0f), 2);
  tex.params.base_level = 0;
  tex.params.max_level = 1000;
  tex.params.min_filter = GL_LINEAR_MIPMAP_LINEAR;
  ASSERT_TRUE(pineda::make_sampler_view(tex, v));
  // lod 1.25: 0.75 * level 1 + 0.25 * level 2 with a truncated 8-bit weight (64/256).
  const double r = sample1(v, 0.3f, 0.3f, 0, 1.25f)[0] * 255.0;
  EXPECT_EQ(std::lround(r), 60 + ((60 * 64 + 128) >> 8));
}

// GL 2.1 §3.8.9: lambda <= 0 magnifies (c = 0 always, as llvmpipe).
TEST(TextureSampler, MagnificationSwitchOver) {
  TextureObject tex;
  tex.target = GL_TEXTURE_2D;
  tex.images[0][0] = solid_image(2, 1, 1, 0, 0, 0, 0);
  tex.images[0][0].rgba = {0, 0, 0, 255, 255, 255, 255, 255};
  tex.images[0][1] = solid_image(1, 1, 1, 9, 9, 9, 9);
  tex.params.mag_filter = GL_LINEAR;
  tex.params.min_filter = GL_NEAREST_MIPMAP_NEAREST;
  tex.params.wrap_s = GL_CLAMP_TO_EDGE;
  SamplerView v;
  ASSERT_TRUE(pineda::make_sampler_view(tex, v));
  EXPECT_NEAR(sample1(v, 0.5f, 0.5f, 0, 0.0f)[0], 128 / 255.0, 1e-6); // LINEAR, level 0
  EXPECT_NEAR(sample1(v, 0.4f, 0.5f, 0, 0.25f)[0], 0.0, 1e-6);        // NEAREST, level 0
  EXPECT_NEAR(sample1(v, 0.4f, 0.5f, 0, 0.75f)[0], 9 / 255.0, 1e-6);  // NEAREST, level 1
}

// Borders: CLAMP + LINEAR blends with the border colour at the edge; CLAMP_TO_BORDER +
// NEAREST reads it outside; a texture with a one-texel border reads its border texels.
TEST(TextureSampler, BorderColourAndBorderTexels) {
  TextureObject tex;
  tex.target = GL_TEXTURE_2D;
  tex.images[0][0] = solid_image(4, 4, 1, 200, 100, 0, 255);
  tex.params.min_filter = tex.params.mag_filter = GL_LINEAR;
  tex.params.wrap_s = tex.params.wrap_t = GL_CLAMP;
  tex.params.border_color[0] = 0.0f, tex.params.border_color[3] = 0.0f;
  SamplerView v;
  ASSERT_TRUE(pineda::make_sampler_view(tex, v));
  RGBA c = sample1(v, 0.0f, 0.5f, 0, 0);
  EXPECT_NEAR(c[0], 100 / 255.0, 1e-5); // half texel, half border
  EXPECT_NEAR(c[3], 0.5, 1e-5);
  tex.params.min_filter = tex.params.mag_filter = GL_NEAREST;
  tex.params.wrap_s = GL_CLAMP_TO_BORDER;
  ASSERT_TRUE(pineda::make_sampler_view(tex, v));
  EXPECT_NEAR(sample1(v, -0.01f, 0.5f, 0, 0)[3], 0.0, 1e-6);
  EXPECT_NEAR(sample1(v, 0.01f, 0.5f, 0, 0)[3], 1.0, 1e-6);
  // A 2x2 texture with a border: the border texels are 4x4's outer ring.
  TextureObject tb;
  tb.target = GL_TEXTURE_2D;
  tb.images[0][0] = solid_image(4, 4, 1, 50, 50, 50, 255);
  tb.images[0][0].border = 1;
  for (int j = 1; j < 3; ++j)
    for (int i = 1; i < 3; ++i)
      tb.images[0][0].rgba[(j * 4 + i) * 4] = 250;
  tb.params.min_filter = tb.params.mag_filter = GL_LINEAR;
  tb.params.wrap_s = tb.params.wrap_t = GL_CLAMP;
  ASSERT_TRUE(pineda::make_sampler_view(tb, v));
  EXPECT_EQ(v.width, 2);
  EXPECT_NEAR(sample1(v, 0.0f, 0.5f, 0, 0)[0], 150 / 255.0, 1e-5);
  EXPECT_NEAR(sample1(v, 0.5f, 0.5f, 0, 0)[0], 250 / 255.0, 1e-5);
}

// Table 3.21: the major axis picks the face; each face's (s, t) orientation.
TEST(TextureSampler, CubeFaceSelection) {
  TextureObject tex;
  tex.target = GL_TEXTURE_CUBE_MAP;
  for (int f = 0; f < 6; ++f) {
    tex.images[f][0] = solid_image(2, 2, 1, uint8_t(40 * f), 0, 0, 255);
    // texel (1, 0) marks the +s half of the bottom row; (0, 1) the +t half of the left column.
    tex.images[f][0].rgba[1 * 4 + 1] = 255;
    tex.images[f][0].rgba[2 * 4 + 2] = 255;
  }
  tex.params.min_filter = tex.params.mag_filter = GL_NEAREST;
  tex.params.wrap_s = tex.params.wrap_t = GL_CLAMP_TO_EDGE;
  SamplerView v;
  ASSERT_TRUE(pineda::make_sampler_view(tex, v));
  struct Dir {
    float x, y, z;
    int face;
  } dirs[] = {{1, 0.1f, 0.2f, 0},  {-1, 0.1f, 0.2f, 1}, {0.1f, 1, 0.2f, 2},
              {0.1f, -1, 0.2f, 3}, {0.1f, 0.2f, 1, 4},  {0.1f, 0.2f, -1, 5}};
  for (const Dir& d : dirs) {
    const RGBA c = sample1(v, d.x, d.y, d.z, 0);
    EXPECT_EQ(std::lround(c[0] * 255), 40 * d.face) << d.face;
    // Table 3.21 (sc, tc) for the direction, then s = (sc/|ma| + 1)/2.
    double sc, tc, ma;
    switch (d.face) {
    case 0:
      sc = -d.z, tc = -d.y, ma = d.x;
      break;
    case 1:
      sc = d.z, tc = -d.y, ma = -d.x;
      break;
    case 2:
      sc = d.x, tc = d.z, ma = d.y;
      break;
    case 3:
      sc = d.x, tc = -d.z, ma = -d.y;
      break;
    case 4:
      sc = d.x, tc = -d.y, ma = d.z;
      break;
    default:
      sc = -d.x, tc = -d.y, ma = -d.z;
      break;
    }
    const bool s_hi = (sc / ma + 1) / 2 >= 0.5, t_hi = (tc / ma + 1) / 2 >= 0.5;
    EXPECT_EQ(c[1] > 0.5, s_hi && !t_hi) << d.face;
    EXPECT_EQ(c[2] > 0.5, !s_hi && t_hi) << d.face;
  }
  // A face of another size makes the cube incomplete (§3.8.10 cube completeness).
  tex.images[3][0] = solid_image(4, 4, 1, 0, 0, 0, 0);
  EXPECT_FALSE(pineda::make_sampler_view(tex, v));
}

// §3.8.14: every comparison function, NEAREST and LINEAR (each texel compared, then
// filtered), and DEPTH_TEXTURE_MODE's expansion.
TEST(TextureSampler, DepthCompare) {
  TextureObject tex;
  tex.target = GL_TEXTURE_2D;
  TexImage& im = tex.images[0][0];
  im.width = 2, im.height = 1, im.depth = 1;
  im.is_depth = true;
  im.internal_format = GL_DEPTH_COMPONENT;
  // Depth texels are stored as a 32-bit depth buffer stores them: 0.25 and 0.75.
  im.depth_size = 32;
  im.z = {1073741824u, 3221225471u};
  tex.params.min_filter = tex.params.mag_filter = GL_NEAREST;
  tex.params.wrap_s = tex.params.wrap_t = GL_CLAMP_TO_EDGE;
  SamplerView v;
  ASSERT_TRUE(pineda::make_sampler_view(tex, v));
  RGBA c = sample1(v, 0.25f, 0.5f, 0.9f, 0);
  EXPECT_EQ(c, (RGBA{0.25, 0.25, 0.25, 1.0})); // no comparison, LUMINANCE
  tex.params.compare_mode = GL_COMPARE_R_TO_TEXTURE;
  const struct {
    GLenum func;
    bool lo, eq, hi; // result for r below, equal to and above the texel's 0.25
  } funcs[] = {{GL_LEQUAL, true, true, false}, {GL_GEQUAL, false, true, true},
               {GL_LESS, true, false, false},  {GL_GREATER, false, false, true},
               {GL_EQUAL, false, true, false}, {GL_NOTEQUAL, true, false, true},
               {GL_ALWAYS, true, true, true},  {GL_NEVER, false, false, false}};
  for (const auto& f : funcs) {
    tex.params.compare_func = f.func;
    ASSERT_TRUE(pineda::make_sampler_view(tex, v));
    EXPECT_EQ(sample1(v, 0.25f, 0.5f, 0.1f, 0)[0], f.lo ? 1.0 : 0.0) << f.func;
    EXPECT_EQ(sample1(v, 0.25f, 0.5f, 0.25f, 0)[0], f.eq ? 1.0 : 0.0) << f.func;
    EXPECT_EQ(sample1(v, 0.25f, 0.5f, 0.6f, 0)[0], f.hi ? 1.0 : 0.0) << f.func;
  }
  // LINEAR: 0.5 between the texels, r = 0.5 passes LEQUAL for the 0.75 texel only.
  tex.params.compare_func = GL_LEQUAL;
  tex.params.min_filter = tex.params.mag_filter = GL_LINEAR;
  tex.params.depth_mode = GL_ALPHA;
  ASSERT_TRUE(pineda::make_sampler_view(tex, v));
  EXPECT_EQ(v.base, TexBase::Alpha);
  c = sample1(v, 0.5f, 0.5f, 0.5f, 0);
  EXPECT_NEAR(c[3], 0.5, 1e-6);
  EXPECT_EQ(c[0], 0.0);
  // r is clamped to [0,1] before comparing.
  tex.params.depth_mode = GL_INTENSITY;
  tex.params.compare_func = GL_GEQUAL;
  ASSERT_TRUE(pineda::make_sampler_view(tex, v));
  c = sample1(v, 0.5f, 0.5f, 7.0f, 0);
  EXPECT_EQ(c, (RGBA{1, 1, 1, 1}));
}

// Table 3.23 expansion of the stored formats, through rgba_to_texels.
TEST(TextureSampler, BaseFormatExpansion) {
  const float in[4] = {0.2f, 0.4f, 0.6f, 0.8f};
  const struct {
    GLenum fmt;
    RGBA want;
  } cases[] = {{GL_ALPHA, {0, 0, 0, 0.8}},
               {GL_LUMINANCE, {0.2, 0.2, 0.2, 1}},
               {GL_LUMINANCE_ALPHA, {0.2, 0.2, 0.2, 0.8}},
               {GL_INTENSITY, {0.2, 0.2, 0.2, 0.2}},
               {GL_RGB, {0.2, 0.4, 0.6, 1}},
               {GL_RGBA, {0.2, 0.4, 0.6, 0.8}}};
  for (const auto& c : cases) {
    pineda::TexFormatInfo f;
    ASSERT_TRUE(pineda::lookup_internal_format(GLint(c.fmt), f));
    TextureObject tex;
    tex.target = GL_TEXTURE_2D;
    tex.images[0][0] = solid_image(1, 1, 1, 0, 0, 0, 0);
    tex.images[0][0].base = f.base;
    pineda::rgba_to_texels(f, in, 1, tex.images[0][0].rgba.data());
    tex.params.min_filter = GL_NEAREST;
    SamplerView v;
    ASSERT_TRUE(pineda::make_sampler_view(tex, v));
    const RGBA got = sample1(v, 0.5f, 0.5f, 0, 0);
    for (int ch = 0; ch < 4; ++ch)
      EXPECT_NEAR(got[ch], c.want[ch], 0.5 / 255.0) << c.fmt;
  }
  // Components kept with fewer bits are rounded to them (RGBA4: 0.2 -> 3/15).
  pineda::TexFormatInfo f;
  ASSERT_TRUE(pineda::lookup_internal_format(GL_RGBA4, f));
  uint8_t t[4];
  pineda::rgba_to_texels(f, in, 1, t);
  EXPECT_EQ(t[0], 3 * 17);
  ASSERT_TRUE(pineda::lookup_internal_format(GL_RGB5_A1, f));
  pineda::rgba_to_texels(f, in, 1, t);
  EXPECT_EQ(t[3], 255);
  EXPECT_EQ(t[1], std::lround(std::lround(0.4 * 31) * 255.0 / 31));
}

// §3.8.10: the levels a mipmap filter needs must exist with halved sizes and one format.
TEST(TextureSampler, Completeness) {
  std::mt19937 rng(7);
  TextureObject tex = make_tex(rng, GL_TEXTURE_2D, 8, 4, 1, true);
  SamplerView v;
  EXPECT_TRUE(pineda::make_sampler_view(tex, v));
  EXPECT_EQ(v.max_level, 3);
  tex.images[0][2] = random_image(rng, 3, 1, 1); // wrong size
  EXPECT_FALSE(pineda::make_sampler_view(tex, v));
  tex.params.min_filter = GL_LINEAR; // only the base level is needed
  EXPECT_TRUE(pineda::make_sampler_view(tex, v));
  tex.params.min_filter = GL_NEAREST_MIPMAP_NEAREST;
  tex.params.max_level = 1; // the broken level is beyond q
  EXPECT_TRUE(pineda::make_sampler_view(tex, v));
  EXPECT_EQ(v.max_level, 1);
  tex.images[0][1].red_size = 4; // another internal format
  EXPECT_FALSE(pineda::make_sampler_view(tex, v));
  tex.params.min_filter = GL_LINEAR;
  tex.params.base_level = 2;
  tex.params.max_level = 1; // base > max
  EXPECT_FALSE(pineda::make_sampler_view(tex, v));
  TextureObject empty;
  empty.target = GL_TEXTURE_2D;
  EXPECT_FALSE(pineda::make_sampler_view(empty, v));
}

// Non-finite coordinates and lambdas give some colour without crashing.
TEST(TextureSampler, NonFiniteInput) {
  std::mt19937 rng(3);
  TextureObject tex = make_tex(rng, GL_TEXTURE_3D, 4, 4, 4, true);
  const float inf = std::numeric_limits<float>::infinity(), nan = std::nanf("");
  for (GLenum wrap : kWraps)
    for (GLenum minf : kMinFilters) {
      tex.params.wrap_s = tex.params.wrap_t = tex.params.wrap_r = wrap;
      tex.params.min_filter = minf;
      SamplerView v;
      ASSERT_TRUE(pineda::make_sampler_view(tex, v));
      for (float x : {inf, -inf, nan, 3e38f, -3e38f})
        for (float l : {inf, -inf, nan, 0.5f, 2.0f}) {
          const RGBA c = sample1(v, x, -x, x, l);
          for (double ch : c)
            EXPECT_TRUE(ch >= 0.0 && ch <= 1.0);
        }
    }
}

} // namespace
