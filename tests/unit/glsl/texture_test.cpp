// Texture lookups (GLSL 1.20 §8.7) through the engine's sampler interface, with the test
// sampler: every target, projective division, bias, explicit level, shadow comparison, the
// implicit level of detail from quad neighbours, and the unit read from the sampler uniform.
// The reference is the test sampler's own lookup with the coordinates and level computed in
// C++, so the test checks what the engine hands to the sampler.
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <random>

#include "support/lanes.h"

namespace pineda::glsl_test {
namespace {

using shader::TexTarget;

TestTexture checker(TexTarget t, int size) {
  auto tex =
      TestTexture::make(t, size, t == TexTarget::Tex1D ? 1 : size, t == TexTarget::Tex3D ? size : 1,
                        [&](int face, int x, int y, int z) -> std::array<float, 4> {
                          return {static_cast<float>(x) / static_cast<float>(size),
                                  static_cast<float>(y) / static_cast<float>(size),
                                  static_cast<float>(z + face) / static_cast<float>(size),
                                  ((x + y + z) & 1) ? 1.0f : 0.25f};
                        });
  tex.build_mipmaps();
  return tex;
}

std::vector<std::array<Vec4, 4>> coords(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> d(-1.5f, 1.5f), q(0.5f, 2.0f), s(0.0f, 0.05f);
  std::vector<std::array<Vec4, 4>> in(64);
  // Quads whose coordinates step by a per-quad scale, so that the level of detail varies.
  for (size_t qd = 0; qd < 16; ++qd) {
    const float sx = d(rng), sy = d(rng), sz = d(rng), step = s(rng), qq = q(rng);
    for (size_t k = 0; k < 4; ++k) {
      auto& lane = in[4 * qd + k];
      lane[0] = {sx + step * static_cast<float>(k & 1), sy + step * static_cast<float>(k >> 1),
                 sz + step * 0.5f * static_cast<float>(k), qq};
      lane[1] = {d(rng), std::fabs(d(rng)), 0, 0}; // bias, lod
    }
  }
  return in;
}

void expect_near4(const Vec4& got, const std::array<float, 4>& want, const std::string& what) {
  for (size_t c = 0; c < 4; ++c)
    EXPECT_NEAR(got[c], want[c], 1e-6) << what << " component " << c;
}

// The implicit level of detail the test sampler computes (it mirrors fragment/shade.cpp).
float quad_lambda(const std::array<Vec4, 4>* q, const float* s, const float* t, int w, int h) {
  (void)q;
  const float dx0 = (s[3] - s[2]) * static_cast<float>(w),
              dy0 = (s[2] - s[0]) * static_cast<float>(w);
  const float dx1 = t ? (t[3] - t[2]) * static_cast<float>(h) : 0.0f;
  const float dy1 = t ? (t[2] - t[0]) * static_cast<float>(h) : 0.0f;
  const float rho = std::max(std::sqrt(dx0 * dx0 + dx1 * dx1), std::sqrt(dy0 * dy0 + dy1 * dy1));
  return rho > 0 ? std::log2(rho) : -100.0f;
}

struct TexCase {
  const char* name;
  const char* decl;
  const char* call;
  TexTarget target;
  bool shadow, proj;
  int lod; // 0 implicit, 1 bias, 2 explicit
};
// gtest prints a parameter in the test's listing: the name, not the struct's bytes (which
// hold addresses, and so made ctest's test names differ from one build to the next).
void PrintTo(const TexCase& c, std::ostream* os) {
  *os << c.name;
}

const TexCase kTexCases[] = {
    {"texture1D", "sampler1D", "texture1D(s, v0.x)", TexTarget::Tex1D, false, false, 0},
    {"texture1DProj", "sampler1D", "texture1DProj(s, v0.xw)", TexTarget::Tex1D, false, true, 0},
    {"texture2D", "sampler2D", "texture2D(s, v0.xy)", TexTarget::Tex2D, false, false, 0},
    {"texture2DBias", "sampler2D", "texture2D(s, v0.xy, v1.x)", TexTarget::Tex2D, false, false, 1},
    {"texture2DProj", "sampler2D", "texture2DProj(s, v0.xyw)", TexTarget::Tex2D, false, true, 0},
    {"texture2DProj4", "sampler2D", "texture2DProj(s, vec4(v0.xy, 7.0, v0.w))", TexTarget::Tex2D,
     false, true, 0},
    {"texture3D", "sampler3D", "texture3D(s, v0.xyz)", TexTarget::Tex3D, false, false, 0},
    {"textureCube", "samplerCube", "textureCube(s, v0.xyz)", TexTarget::Cube, false, false, 0},
    {"shadow2D", "sampler2DShadow", "shadow2D(s, vec3(v0.xy, 0.5))", TexTarget::Tex2D, true, false,
     0},
    {"shadow1DProj", "sampler1DShadow", "shadow1DProj(s, vec4(v0.x, 0.0, 0.5, v0.w))",
     TexTarget::Tex1D, true, true, 0},
};

class TextureLookup : public ::testing::TestWithParam<TexCase> {};

TEST_P(TextureLookup, HandsTheSamplerWhatGlslSays) {
  const TexCase& tc = GetParam();
  const std::string src = std::string("varying vec4 v0, v1;\nuniform ") + tc.decl +
                          " s;\nvoid main() { gl_FragColor = " + tc.call + "; }\n";
  LaneShader sh(src);
  ASSERT_TRUE(sh.ok()) << sh.log;
  const int size = tc.target == TexTarget::Tex3D ? 8 : 16;
  sh.pipe->sampler.units.resize(3);
  sh.pipe->sampler.units[2] = checker(tc.target, size);
  if (tc.shadow) {
    // A depth texture: depth in the red channel.
    sh.pipe->sampler.units[2] = TestTexture::make(
        tc.target, size, tc.target == TexTarget::Tex1D ? 1 : size, 1,
        [&](int, int x, int y, int) -> std::array<float, 4> {
          return {static_cast<float>(x + y) / (2.0f * static_cast<float>(size)), 0, 0, 1};
        });
  }
  ASSERT_TRUE(sh.pipe->set_uniform("s", {2}));
  const auto in = coords(17);
  for (SimdLevel l : levels()) {
    set_simd_level(l);
    const auto out = sh.run(in);
    set_simd_level(simd_level_supported());
    for (size_t q = 0; q < 16; ++q) {
      float s[4], t[4], r[4];
      for (size_t k = 0; k < 4; ++k) {
        const Vec4& v = in[4 * q + k][0];
        const float inv = tc.proj ? v[3] : 1.0f;
        s[k] = v[0], t[k] = v[1], r[k] = v[2];
        if (std::string(tc.name) == "texture2DProj4") r[k] = 7.0f;
        if (tc.shadow) r[k] = 0.5f;
        if (tc.proj) s[k] /= inv, t[k] /= inv, r[k] /= inv;
      }
      const bool is1d = tc.target == TexTarget::Tex1D;
      const float lambda = quad_lambda(nullptr, s, is1d ? nullptr : t, size, size);
      for (size_t k = 0; k < 4; ++k) {
        float lam = lambda;
        if (tc.lod == 1) lam += in[4 * q + k][1][0];
        const auto want =
            sh.pipe->sampler.lookup(2, s[k], is1d ? 0.0f : t[k], r[k], lam, tc.shadow);
        expect_near4(out[4 * q + k], want,
                     std::string(tc.name) + " lane " + std::to_string(4 * q + k));
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Glsl120, TextureLookup, ::testing::ValuesIn(kTexCases),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

// Vertex shaders: the Lod forms take the level given; the others level 0 (§8.7).
TEST(TextureLookup, VertexShaderLevels) {
  auto p = build("attribute vec4 pos;\nuniform sampler2D s;\nvarying vec4 c;\n"
                 "void main() { c = texture2DLod(s, pos.xy, pos.z) + texture2D(s, pos.yx) * 10.0;\n"
                 "  gl_Position = pos; }\n",
                 "varying vec4 c;\nvoid main() { gl_FragColor = c; }\n", nullptr);
  ASSERT_TRUE(p);
  Pipeline pipe(*p);
  pipe.sampler.units.push_back(checker(TexTarget::Tex2D, 16));
  ASSERT_TRUE(pipe.set_uniform("s", {0}));
  std::vector<std::vector<float>> in(20, pipe.attrib_defaults);
  const int loc = p->attrib_location("pos");
  ASSERT_GE(loc, 0);
  for (size_t v = 0; v < in.size(); ++v)
    for (int c = 0; c < 4; ++c)
      in[v][static_cast<size_t>((shader::kInGeneric0 + loc) * 4 + c)] =
          c == 2 ? static_cast<float>(v % 5) : 0.05f * static_cast<float>(v) + (c ? 0.3f : 0.0f);
  const int k = p->varying_component("c", 0);
  ASSERT_GE(k, 0);
  for (SimdLevel l : levels()) {
    set_simd_level(l);
    const auto out = pipe.run_vertices(in);
    set_simd_level(simd_level_supported());
    for (size_t v = 0; v < in.size(); ++v) {
      const float* pos = &in[v][static_cast<size_t>((shader::kInGeneric0 + loc) * 4)];
      const auto a = pipe.sampler.lookup(0, pos[0], pos[1], 0, pos[2], false);
      const auto b = pipe.sampler.lookup(0, pos[1], pos[0], 0, 0, false);
      const float want = a[0] + b[0] * 10;
      EXPECT_NEAR(out[v][static_cast<size_t>((shader::kOutVarying0)*4 + k)], want, 1e-5)
          << "vertex " << v;
    }
  }
}

// Two samplers reading different units, through a function taking a sampler parameter.
TEST(TextureLookup, SamplerUniformsSelectUnits) {
  LaneShader sh("varying vec4 v0;\nuniform sampler2D a, b;\n"
                "vec4 look(sampler2D t, vec2 c) { return texture2D(t, c); }\n"
                "void main() { gl_FragColor = look(a, v0.xy) - look(b, v0.xy); }\n");
  ASSERT_TRUE(sh.ok()) << sh.log;
  sh.pipe->sampler.units.resize(4);
  sh.pipe->sampler.units[1] = TestTexture::make(TexTarget::Tex2D, 1, 1, 1, [](int, int, int, int) {
    return std::array<float, 4>{1, 2, 3, 4};
  });
  sh.pipe->sampler.units[3] = TestTexture::make(TexTarget::Tex2D, 1, 1, 1, [](int, int, int, int) {
    return std::array<float, 4>{0.5f, 0.5f, 0.5f, 0.5f};
  });
  ASSERT_TRUE(sh.pipe->set_uniform("a", {1}));
  ASSERT_TRUE(sh.pipe->set_uniform("b", {3}));
  const auto out = sh.run(coords(3));
  for (const Vec4& o : out)
    expect_near4(o, {0.5f, 1.5f, 2.5f, 3.5f}, "a - b");
  EXPECT_EQ(sh.program->fragment()->sampler_words().size(), 2u);
}

} // namespace
} // namespace pineda::glsl_test
