// Runs of every size: the engine runs up to 16 lanes with the small-run kernels and more with
// the whole-block ones (engine_internal.h). Each lane of a run of any size must get the bits it
// gets in a whole block, and the kill bits of lanes past the run stay clear; vertex batches of
// any count are split into blocks and a remainder with the same result.
#include <gtest/gtest.h>

#include <random>

#include "support/lanes.h"

namespace pineda::glsl_test {
namespace {

// Divergent branches, a loop whose trip count differs per lane, integer division by a lane's
// own (possibly zero) value, a uniform-array gather, derivatives and discard.
const char* kShader =
    "varying vec4 v0, v1;\n"
    "uniform float k[4];\n"
    "void main() {\n"
    "  vec4 a = v0 * 0.5 + v1;\n"
    "  float s = 0.0;\n"
    "  for (int i = 0; i < int(abs(v1.x)) + 1; i++) {\n"
    "    if (a.y > float(i)) s += sin(a.x + float(i)); else s -= sqrt(abs(a.z));\n"
    "  }\n"
    "  int d = int(v1.w);\n"
    "  int q = int(v0.x * 7.0) / (d == 0 ? 1 : d);\n"
    "  if (v0.w > 6.0) discard;\n"
    "  gl_FragColor = vec4(s, float(q) + k[int(abs(v0.y)) - 4 * (int(abs(v0.y)) / 4)],\n"
    "                      dFdx(a.x) + dFdy(a.y), exp2(clamp(a.w, -8.0, 8.0)));\n"
    "}\n";

std::vector<std::array<Vec4, 4>> inputs(size_t n) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> d(-8, 8);
  std::vector<std::array<Vec4, 4>> in(n);
  for (auto& lane : in)
    for (auto& v : lane)
      for (float& x : v)
        x = d(rng);
  return in;
}

TEST(EngineRuns, FragmentRunsOfEverySizeMatchTheWholeBlock) {
  LaneShader sh(kShader);
  ASSERT_TRUE(sh.ok()) << sh.log;
  sh.pipe->set_uniform("k", {0.25, -1.5, 3.0, 7.0});
  const auto in = inputs(64);
  for (SimdLevel l : levels()) {
    set_simd_level(l);
    uint64_t block_kill = 0;
    const auto block = sh.run(in, &block_kill);
    for (int quads = 1; quads <= 16; ++quads) {
      const size_t lanes = static_cast<size_t>(quads) * 4;
      const std::vector<std::array<Vec4, 4>> part(in.begin(),
                                                  in.begin() + static_cast<ptrdiff_t>(lanes));
      uint64_t kill = 0;
      const auto out = sh.run(part, &kill);
      ASSERT_EQ(out.size(), lanes);
      const uint64_t mask = lanes == 64 ? ~uint64_t{0} : (uint64_t{1} << lanes) - 1;
      EXPECT_EQ(kill, block_kill & mask) << level_name(l) << ", " << quads << " quads";
      for (size_t lane = 0; lane < lanes; ++lane)
        for (size_t c = 0; c < 4; ++c)
          ASSERT_EQ(bits(out[lane][c]), bits(block[lane][c]))
              << level_name(l) << ", " << quads << " quads, lane " << lane << "." << c;
    }
  }
  set_simd_level(simd_level_supported());
}

TEST(EngineRuns, VertexBatchesOfAnyCount) {
  std::string log;
  auto p = build("attribute vec4 pos;\n"
                 "void main() {\n"
                 "  vec4 p = pos;\n"
                 "  for (int i = 0; i < int(abs(pos.y)); i++) p.x += cos(p.z * float(i));\n"
                 "  gl_Position = p;\n"
                 "  gl_FrontColor = vec4(pos.x > 0.0 ? log2(abs(pos.x) + 1.0) : -pos.x);\n"
                 "}\n",
                 "void main() { gl_FragColor = gl_Color; }\n", &log);
  ASSERT_TRUE(p) << log;
  Pipeline pipe(*p);
  const int attr = shader::kInGeneric0 + p->attrib_location("pos");
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> d(-6, 6);
  std::vector<std::vector<float>> all(200, std::vector<float>(shader::kNumVertexInputs * 4, 0.0f));
  for (auto& v : all)
    for (int c = 0; c < 4; ++c)
      v[static_cast<size_t>(attr * 4 + c)] = d(rng);
  for (SimdLevel l : levels()) {
    set_simd_level(l);
    const auto ref = pipe.run_vertices(all);
    for (size_t n : {1u, 3u, 15u, 16u, 17u, 63u, 64u, 65u, 80u, 128u, 129u, 200u}) {
      const std::vector<std::vector<float>> part(all.begin(),
                                                 all.begin() + static_cast<ptrdiff_t>(n));
      const auto out = pipe.run_vertices(part);
      for (size_t v = 0; v < n; ++v)
        for (int c :
             {shader::kOutPosition * 4, shader::kOutPosition * 4 + 1, shader::kOutFrontColor * 4})
          ASSERT_EQ(bits(out[v][static_cast<size_t>(c)]), bits(ref[v][static_cast<size_t>(c)]))
              << level_name(l) << ", batch of " << n << ", vertex " << v << ", component " << c;
    }
  }
  set_simd_level(simd_level_supported());
}

} // namespace
} // namespace pineda::glsl_test
