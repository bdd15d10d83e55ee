// Control flow on the engine: divergent and uniform branches, loops with break, continue and
// return, discard, functions with early returns, dynamically indexed arrays, and the iteration
// limit, each compared lane by lane with the same logic written in C++, at every SIMD level.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "support/lanes.h"

namespace pineda::glsl_test {
namespace {

using Ref = std::function<Vec4(const std::array<Vec4, 4>&)>;

std::vector<std::array<Vec4, 4>> inputs(unsigned seed, float lo, float hi) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> d(lo, hi);
  std::vector<std::array<Vec4, 4>> in(64);
  for (auto& lane : in)
    for (auto& v : lane)
      for (float& x : v)
        x = std::round(d(rng) * 4) / 4; // quarters: exact in float, ties included
  return in;
}

void check(const std::string& src, const Ref& ref, unsigned seed = 1, float lo = -8, float hi = 8,
           const std::function<void(LaneShader&)>& setup = {}, uint64_t* kill_out = nullptr) {
  LaneShader sh(src);
  ASSERT_TRUE(sh.ok()) << sh.log;
  if (setup) setup(sh);
  const auto in = inputs(seed, lo, hi);
  for (SimdLevel l : levels()) {
    set_simd_level(l);
    uint64_t kill = 0;
    const auto out = sh.run(in, &kill);
    set_simd_level(simd_level_supported());
    if (kill_out) *kill_out = kill;
    for (size_t lane = 0; lane < out.size(); ++lane) {
      if ((kill >> lane) & 1) continue;
      const Vec4 want = ref(in[lane]);
      for (size_t k = 0; k < 4; ++k)
        ASSERT_EQ(out[lane][k], want[k])
            << "level " << level_name(l) << ", lane " << lane << ", component " << k << "\n"
            << src;
    }
  }
}

TEST(ControlFlow, DivergentIfElseNested) {
  check("varying vec4 v0, v1;\n"
        "void main() {\n"
        "  vec4 r = vec4(0.0);\n"
        "  if (v0.x > 0.0) {\n"
        "    r.x = 1.0;\n"
        "    if (v0.y > v0.x) r.y = v0.y - v0.x; else r.y = -1.0;\n"
        "  } else if (v0.z > 0.0) {\n"
        "    r.x = 2.0;\n"
        "    r.z = v0.z * 2.0;\n"
        "  } else {\n"
        "    r = v1;\n"
        "  }\n"
        "  gl_FragColor = r;\n"
        "}\n",
        [](const std::array<Vec4, 4>& in) {
          const Vec4& v0 = in[0];
          Vec4 r{0, 0, 0, 0};
          if (v0[0] > 0) {
            r[0] = 1;
            r[1] = v0[1] > v0[0] ? v0[1] - v0[0] : -1;
          } else if (v0[2] > 0) {
            r[0] = 2;
            r[2] = v0[2] * 2;
          } else {
            r = in[1];
          }
          return r;
        });
}

TEST(ControlFlow, LoopWithVaryingBoundBreakContinue) {
  check("varying vec4 v0;\n"
        "void main() {\n"
        "  float sum = 0.0, count = 0.0;\n"
        "  int n = int(abs(v0.x)) + 1;\n"
        "  for (int i = 0; i < n; i++) {\n"
        "    if (float(i) == abs(v0.y)) continue;\n"
        "    sum += float(i) * v0.z;\n"
        "    if (sum > 20.0) break;\n"
        "    count += 1.0;\n"
        "  }\n"
        "  gl_FragColor = vec4(sum, count, float(n), 0.0);\n"
        "}\n",
        [](const std::array<Vec4, 4>& in) {
          const Vec4& v0 = in[0];
          float sum = 0, count = 0;
          const int n = static_cast<int>(std::fabs(v0[0])) + 1;
          for (int i = 0; i < n; i++) {
            if (static_cast<float>(i) == std::fabs(v0[1])) continue;
            sum += static_cast<float>(i) * v0[2];
            if (sum > 20.0f) break;
            count += 1.0f;
          }
          return Vec4{sum, count, static_cast<float>(n), 0};
        });
}

TEST(ControlFlow, WhileAndDoWhile) {
  check("varying vec4 v0;\n"
        "void main() {\n"
        "  float x = abs(v0.x) + 1.0, steps = 0.0;\n"
        "  while (x < 100.0) { x = x * 2.0 + v0.y * v0.y; steps += 1.0; }\n"
        "  float y = v0.z;\n"
        "  int k = 0;\n"
        "  do { y -= 1.5; k++; } while (y > 0.0 && k < 10);\n"
        "  gl_FragColor = vec4(x, steps, y, float(k));\n"
        "}\n",
        [](const std::array<Vec4, 4>& in) {
          const Vec4& v0 = in[0];
          float x = std::fabs(v0[0]) + 1, steps = 0;
          while (x < 100) {
            x = x * 2 + v0[1] * v0[1];
            steps += 1;
          }
          float y = v0[2];
          int k = 0;
          do {
            y -= 1.5f;
            k++;
          } while (y > 0 && k < 10);
          return Vec4{x, steps, y, static_cast<float>(k)};
        });
}

TEST(ControlFlow, EarlyReturnsFromFunctionsAndMain) {
  check("varying vec4 v0;\n"
        "float f(float a, float b) {\n"
        "  if (a < 0.0) return -a;\n"
        "  for (int i = 0; i < 8; i++) {\n"
        "    a -= b;\n"
        "    if (a < 1.0) return a * 10.0;\n"
        "  }\n"
        "  return a;\n"
        "}\n"
        "void main() {\n"
        "  gl_FragColor = vec4(f(v0.x, abs(v0.y) + 0.25), 0.0, 0.0, 1.0);\n"
        "  if (v0.z > 2.0) return;\n"
        "  gl_FragColor.y = 5.0;\n"
        "  if (v0.w < 0.0) { gl_FragColor.z = 3.0; return; }\n"
        "  gl_FragColor.w = 7.0;\n"
        "}\n",
        [](const std::array<Vec4, 4>& in) {
          const Vec4& v0 = in[0];
          const auto f = [](float a, float b) {
            if (a < 0) return -a;
            for (int i = 0; i < 8; i++) {
              a -= b;
              if (a < 1) return a * 10;
            }
            return a;
          };
          Vec4 r{f(v0[0], std::fabs(v0[1]) + 0.25f), 0, 0, 1};
          if (v0[2] > 2) return r;
          r[1] = 5;
          if (v0[3] < 0) {
            r[2] = 3;
            return r;
          }
          r[3] = 7;
          return r;
        });
}

TEST(ControlFlow, DiscardSetsTheKillMask) {
  uint64_t kill = 0;
  check(
      "varying vec4 v0;\n"
      "void main() {\n"
      "  gl_FragColor = v0;\n"
      "  for (int i = 0; i < 4; i++)\n"
      "    if (v0[i] < -6.0) discard;\n"
      "  gl_FragColor.x = 1.0;\n"
      "}\n",
      [](const std::array<Vec4, 4>& in) {
        Vec4 r = in[0];
        r[0] = 1;
        return r;
      },
      3, -8, 8, {}, &kill);
  const auto in = inputs(3, -8, 8);
  for (size_t lane = 0; lane < 64; ++lane) {
    bool k = false;
    for (size_t c = 0; c < 4; ++c)
      k = k || in[lane][0][c] < -6;
    EXPECT_EQ((kill >> lane) & 1, k ? 1u : 0u) << "lane " << lane;
  }
}

TEST(ControlFlow, UniformBranchesAndLoops) {
  for (int mode = 0; mode < 3; ++mode) {
    check(
        "varying vec4 v0;\n"
        "uniform int mode;\n"
        "uniform int n;\n"
        "void main() {\n"
        "  vec4 r = vec4(0.0);\n"
        "  if (mode == 0) r = v0 * 2.0;\n"
        "  else if (mode == 1) r = -v0;\n"
        "  else for (int i = 0; i < n; i++) r += v0;\n"
        "  gl_FragColor = r;\n"
        "}\n",
        [mode](const std::array<Vec4, 4>& in) {
          Vec4 r{0, 0, 0, 0};
          for (size_t k = 0; k < 4; ++k) {
            if (mode == 0)
              r[k] = in[0][k] * 2;
            else if (mode == 1)
              r[k] = -in[0][k];
            else
              for (int i = 0; i < 5; i++)
                r[k] += in[0][k];
          }
          return r;
        },
        4, -8, 8,
        [mode](LaneShader& sh) {
          sh.pipe->set_uniform("mode", {static_cast<double>(mode)});
          sh.pipe->set_uniform("n", {5});
        });
  }
}

TEST(ControlFlow, DynamicallyIndexedLocalArrays) {
  check("varying vec4 v0;\n"
        "void main() {\n"
        "  float a[6];\n"
        "  for (int i = 0; i < 6; i++) a[i] = float(i) * v0.x;\n"
        "  int j = int(abs(v0.y)) - (int(abs(v0.y)) / 6) * 6;\n"
        "  a[j] = 100.0;\n"
        "  vec3 m[2];\n"
        "  m[0] = v0.xyz; m[1] = v0.wzy;\n"
        "  int k = v0.z > 0.0 ? 1 : 0;\n"
        "  gl_FragColor = vec4(a[j], a[5 - j], m[k][j - (j / 3) * 3], m[1 - k].x);\n"
        "}\n",
        [](const std::array<Vec4, 4>& in) {
          const Vec4& v0 = in[0];
          float a[6];
          for (int i = 0; i < 6; i++)
            a[i] = static_cast<float>(i) * v0[0];
          const int y = static_cast<int>(std::fabs(v0[1]));
          const int j = y - (y / 6) * 6;
          a[j] = 100;
          const float m[2][3] = {{v0[0], v0[1], v0[2]}, {v0[3], v0[2], v0[1]}};
          const int k = v0[2] > 0 ? 1 : 0;
          return Vec4{a[j], a[5 - j], m[k][j % 3], m[1 - k][0]};
        });
}

// A loop that never ends by itself stops after 65535 iterations (as llvmpipe's), and nested
// runaway loops stop once the run's budget of iterations is spent: the run returns.
TEST(ControlFlow, IterationLimitStopsRunawayLoops) {
  check("varying vec4 v0;\n"
        "void main() {\n"
        "  float x = 0.0;\n"
        "  while (v0.x < 100.0) { x += 1.0; }\n"
        "  gl_FragColor = vec4(x);\n"
        "}\n",
        [](const std::array<Vec4, 4>&) {
          return Vec4{65535, 65535, 65535, 65535};
        });
  LaneShader sh("varying vec4 v0;\n"
                "void main() {\n"
                "  float x = 0.0;\n"
                "  for (;;) { for (;;) { x += 1.0; if (v0.x > 1000.0) break; } }\n"
                "  gl_FragColor = vec4(x);\n"
                "}\n");
  ASSERT_TRUE(sh.ok()) << sh.log;
  const auto out = sh.run(inputs(9, -8, 8));
  EXPECT_GT(out[0][0], 65534.0f);
  EXPECT_LE(out[0][0], 1048576.0f);
}

TEST(ControlFlow, TernaryAndShortCircuitSideEffects) {
  check("varying vec4 v0;\n"
        "float counter = 0.0;\n"
        "bool bump(float x) { counter += 1.0; return x > 0.0; }\n"
        "void main() {\n"
        "  bool a = v0.x > 0.0 && bump(v0.y);\n"
        "  bool b = v0.z > 0.0 || bump(v0.w);\n"
        "  float t = v0.x > v0.y ? (counter += 10.0) : (counter -= 100.0);\n"
        "  gl_FragColor = vec4(float(a), float(b), counter, t);\n"
        "}\n",
        [](const std::array<Vec4, 4>& in) {
          const Vec4& v0 = in[0];
          float counter = 0;
          const auto bump = [&](float x) {
            counter += 1;
            return x > 0;
          };
          const bool a = v0[0] > 0 && bump(v0[1]);
          const bool b = v0[2] > 0 || bump(v0[3]);
          const float t = v0[0] > v0[1] ? (counter += 10) : (counter -= 100);
          return Vec4{a ? 1.0f : 0.0f, b ? 1.0f : 0.0f, counter, t};
        });
}

} // namespace
} // namespace pineda::glsl_test
