// The vertex transform and lighting on four or eight lanes (src/geometry/vertex_simd.h) give
// the scalar functions' results bit for bit: clip coordinates, clip codes, window coordinates
// and the lit colours, over lighting configurations and awkward positions (w <= 0, NaN,
// infinities, points on the planes). 37 vertices cover eight-lane groups, a four-lane group
// and the scalar tail.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include "api_fixture.h"
#include "core/simd_level.h"
#include "geometry/clip.h"
#include "geometry/light_eval.h"
#include "geometry/vertex_simd.h"
#include "state/lighting.h"
#include "raster/raster.h"

namespace pineda {
namespace {

constexpr size_t kCount = 37;

std::vector<InputVertex> random_vertices(uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  std::vector<InputVertex> v(kCount);
  for (InputVertex& x : v) {
    std::memset(static_cast<void*>(&x), 0, sizeof x);
    for (float& c : x.pos)
      c = u(rng);
    x.pos[3] = 1.0f + 0.25f * u(rng);
    for (float& c : x.normal)
      c = u(rng);
    for (float& c : x.color)
      c = 0.5f + 0.2f * u(rng);
  }
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  v[1].pos[3] = 0.0f;
  v[2].pos[3] = -1.0f;
  v[3].pos[0] = nan;
  v[5].pos[1] = inf;
  v[6].pos[3] = 1e-40f; // denormal w
  v[7].normal[0] = v[7].normal[1] = v[7].normal[2] = 0.0f;
  v[9].pos[0] = v[9].pos[3] = 1.0f; // on the right plane
  v[33].pos[2] = -inf;
  v[35].normal[1] = nan;
  return v;
}

void expect_same_floats(const float* a, const float* b, int n, size_t vertex, const char* what) {
  for (int k = 0; k < n; ++k) {
    uint32_t x, y;
    std::memcpy(&x, &a[k], 4);
    std::memcpy(&y, &b[k], 4);
    // Any NaN matches any NaN; everything else bit for bit.
    if (std::isnan(a[k]) && std::isnan(b[k])) continue;
    EXPECT_EQ(x, y) << what << "[" << k << "] of vertex " << vertex << ": " << a[k] << " vs "
                    << b[k];
  }
}

void check_transform_matches_scalar() {
  const glm::mat4 proj = glm::perspective(0.9f, 1.3f, 0.5f, 20.0f);
  const glm::mat4 mv = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.2f, -0.1f, -4.0f)),
                                   0.7f, glm::vec3(0.3f, 1.0f, 0.2f));
  const glm::mat4 mvp = proj * mv;
  RasterState rs;
  rs.viewport = Viewport{3.0f, 5.0f, 640.0f, 480.0f, 0.1f, 0.9f};
  for (int user = 0; user < 2; ++user) {
    rs.user_clip_mask = user != 0 ? 0x5u : 0u;
    rs.user_planes[0][0] = 1.0f, rs.user_planes[0][3] = 0.5f;
    rs.user_planes[2][1] = -1.0f, rs.user_planes[2][2] = 0.25f, rs.user_planes[2][3] = 0.75f;
    ClipSetup cs;
    init_clip_setup(cs, rs);
    const std::vector<InputVertex> in = random_vertices(7u + static_cast<uint32_t>(user));
    std::vector<PVertex> got(kCount), want(kCount);
    transform_positions(&mvp[0][0], cs, rs.viewport, in.data(), got.data(), kCount);
    const float* m = &mvp[0][0];
    for (size_t i = 0; i < kCount; ++i) {
      PVertex& p = want[i];
      const float* pos = in[i].pos;
      for (int r = 0; r < 4; ++r)
        p.clip[r] = m[r] * pos[0] + m[4 + r] * pos[1] + m[8 + r] * pos[2] + m[12 + r] * pos[3];
      p.clipmask = clip_code(cs, p.clip);
      if (p.clipmask == 0) to_window(p, rs.viewport);
      expect_same_floats(got[i].clip, p.clip, 4, i, "clip");
      EXPECT_EQ(got[i].clipmask, p.clipmask) << "vertex " << i;
      if (p.clipmask == 0) expect_same_floats(got[i].win, p.win, 4, i, "win");
    }
  }
}

// Every instruction-set level (core/simd_level.h): the SSE2 lanes and, where the processor has
// them, the AVX2 and AVX-512 ones.
TEST(VertexSimd, TransformMatchesScalar) {
  const pineda::SimdLevel saved = pineda::simd_level();
  for (const pineda::SimdLevel level :
       {pineda::SimdLevel::Baseline, pineda::SimdLevel::Avx2, pineda::SimdLevel::Avx512}) {
    if (level > pineda::simd_level_supported()) continue;
    pineda::set_simd_level(level);
    SCOPED_TRACE(level == pineda::SimdLevel::Avx512 ? "AVX-512"
                 : level == pineda::SimdLevel::Avx2 ? "AVX2"
                                                    : "baseline");
    check_transform_matches_scalar();
  }
  pineda::set_simd_level(saved);
}

void check_lighting_matches_scalar() {
  const glm::mat4 mv = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.5f, -5.0f)),
                                   0.4f, glm::vec3(1.0f, 0.2f, 0.0f));
  for (int config = 0; config < 16; ++config) {
    LightingGroup ls;
    LightSetup setup;
    ls.enabled = true;
    ls.local_viewer = (config & 1) != 0;
    ls.two_side = (config & 2) != 0;
    ls.color_control = (config & 4) != 0 ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR;
    const bool normalize = (config & 8) != 0;
    Light& l0 = ls.light[0];
    l0.enabled = true;
    l0.position[0] = 0.5f, l0.position[1] = 1.0f, l0.position[2] = 2.0f, l0.position[3] = 0.0f;
    Light& l1 = ls.light[1];
    l1.enabled = true;
    l1.position[0] = -3.0f, l1.position[1] = -1.0f, l1.position[2] = 2.0f, l1.position[3] = 1.0f;
    for (int c = 0; c < 3; ++c)
      l1.diffuse[c] = 0.3f + 0.2f * static_cast<float>(c), l1.specular[c] = 0.9f;
    l1.attenuation[1] = 0.2f, l1.attenuation[2] = 0.05f;
    Light& l2 = ls.light[3];
    l2.enabled = true;
    l2.position[0] = 1.0f, l2.position[1] = 2.0f, l2.position[2] = -1.0f, l2.position[3] = 2.0f;
    l2.spot_direction[0] = -0.2f, l2.spot_direction[1] = -1.0f, l2.spot_direction[2] = -1.5f;
    l2.spot_cutoff = 60.0f, l2.spot_exponent = 3.0f;
    for (int c = 0; c < 3; ++c)
      l2.diffuse[c] = 0.6f, l2.specular[c] = 0.4f, l2.ambient[c] = 0.1f;
    for (Material& m : ls.material) {
      m.shininess = 40.0f;
      for (int c = 0; c < 3; ++c)
        m.specular[c] = 0.7f;
    }
    ls.material[1].diffuse[0] = 0.2f;
    setup_lighting(setup, ls, mv, normalize, false);
    LitFaces faces;
    prepare_lit_faces(setup, ls.material, nullptr, faces);
    const std::vector<InputVertex> in = random_vertices(100u + static_cast<uint32_t>(config));
    std::vector<PVertex> got(kCount), want(kCount);
    light_vertices(setup, faces, in.data(), got.data(), kCount);
    for (size_t i = 0; i < kCount; ++i) {
      light_vertex_faces(setup, faces, in[i].pos, in[i].normal, want[i].attr);
      expect_same_floats(got[i].attr + kAttrColor, want[i].attr + kAttrColor, 8, i, "front");
      if (ls.two_side)
        expect_same_floats(got[i].attr + kAttrBackColor, want[i].attr + kAttrBackColor, 8, i,
                           "back");
    }
  }
}

// Every instruction-set level (core/simd_level.h): the SSE2 lanes and, where the processor has
// them, the AVX2 and AVX-512 ones.
TEST(VertexSimd, LightingMatchesScalar) {
  const pineda::SimdLevel saved = pineda::simd_level();
  for (const pineda::SimdLevel level :
       {pineda::SimdLevel::Baseline, pineda::SimdLevel::Avx2, pineda::SimdLevel::Avx512}) {
    if (level > pineda::simd_level_supported()) continue;
    pineda::set_simd_level(level);
    SCOPED_TRACE(level == pineda::SimdLevel::Avx512 ? "AVX-512"
                 : level == pineda::SimdLevel::Avx2 ? "AVX2"
                                                    : "baseline");
    check_lighting_matches_scalar();
  }
  pineda::set_simd_level(saved);
}

} // namespace
} // namespace pineda

// lit_pow against a double-precision pow: repeated squaring for an integer exponent y stays
// within about y units in the last place (below 1e-5 relative, far below a colour step); other
// exponents are the library's powf.
TEST(VertexSimd, LitPowMatchesDoublePow) {
  for (int yi = 0; yi <= 130; ++yi) {
    const float ys[2] = {static_cast<float>(yi), static_cast<float>(yi) + 0.37f};
    for (const float y : ys) {
      for (int xi = 0; xi <= 1000; ++xi) {
        const float x = static_cast<float>(xi) / 1000.0f;
        const double want = std::pow(static_cast<double>(x), static_cast<double>(y));
        const double got = pineda::lit_pow(x, y);
        // Each squaring doubles the relative error of its operand: about y units in the
        // last place at worst.
        const double ulps = 2.0 * static_cast<double>(y) + 4.0;
        EXPECT_NEAR(got, want, ulps * 0x1p-24 * want + 1e-30) << x << "^" << y;
      }
    }
  }
  EXPECT_EQ(pineda::lit_pow(0.0f, 0.0f), 1.0f); // 0^0 = 1, as pow gives
  EXPECT_EQ(pineda::lit_pow(0.0f, 40.0f), 0.0f);
}

// A DrawArrays of independent triangles longer than one slice (draw/draw.cpp draws such a draw
// a slice of vertices at a time) gives the pixels and the sample count of the same triangles
// drawn by calls short enough to be drawn whole.
class SlicedDrawTest : public GLTest {};

TEST_F(SlicedDrawTest, LongTriangleListMatchesShortDraws) {
  constexpr int kTris = 12000; // 36000 vertices, above one slice
  std::vector<float> pos, col;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < kTris; ++i) {
    const float x = -1.0f + 2.0f * u(rng), y = -1.0f + 2.0f * u(rng);
    const float d[3][2] = {{0.0f, 0.0f}, {0.3f * u(rng), 0.02f}, {0.01f, 0.3f * u(rng)}};
    for (const auto& v : d) {
      pos.insert(pos.end(), {x + v[0], y + v[1], u(rng) * 2.0f - 1.0f});
      col.insert(col.end(), {u(rng), u(rng), u(rng)});
    }
  }
  glEnable(GL_DEPTH_TEST);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, pos.data());
  glColorPointer(3, GL_FLOAT, 0, col.data());
  GLuint q[2];
  glGenQueries(2, q);
  std::vector<uint8_t> image[2];
  for (int pass = 0; pass < 2; ++pass) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBeginQuery(GL_SAMPLES_PASSED, q[pass]);
    if (pass == 0) {
      glDrawArrays(GL_TRIANGLES, 0, 3 * kTris);
    } else {
      constexpr int kPart = 3 * 1000;
      for (int first = 0; first < 3 * kTris; first += kPart)
        glDrawArrays(GL_TRIANGLES, first, kPart);
    }
    glEndQuery(GL_SAMPLES_PASSED);
    glFinish();
    image[pass] = buf_;
  }
  GLuint samples[2];
  glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &samples[0]);
  glGetQueryObjectuiv(q[1], GL_QUERY_RESULT, &samples[1]);
  EXPECT_GT(samples[0], 0u);
  EXPECT_EQ(samples[0], samples[1]);
  EXPECT_EQ(image[0], image[1]);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}
