// GLSL 1.20's built-in functions (§8) executed on the engine at every SIMD level, compared with
// double-precision references. Every level must give the same bits; the tolerances are
// stated per function (absolute + relative to the reference). The same expressions computed
// from uniforms (the prologue path) and from literals (the constant folder) give the same bits
// as from varyings.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ostream>
#include <random>

#include "support/lanes.h"

namespace pineda::glsl_test {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Case {
  const char* name;
  const char* expr; // GLSL of vec4s a, b, c
  int args;
  float lo[3], hi[3];
  double (*ref)(double, double, double);
  double tol_abs, tol_rel;
};
// gtest prints a parameter in the test's listing: the name, not the struct's bytes (which
// hold addresses, and so made ctest's test names differ from one build to the next).
void PrintTo(const Case& c, std::ostream* os) {
  *os << c.name;
}

double glsl_mod(double x, double y) {
  return x - y * std::floor(x / y);
}
double glsl_sign(double x) {
  return x > 0 ? 1 : x < 0 ? -1 : 0;
}
double smooth(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

const Case kCases[] = {
    // §8.1 angle and trigonometry
    {"radians",
     "radians(a)",
     1,
     {-720, 0, 0},
     {720, 0, 0},
     [](double x, double, double) { return x * kPi / 180; },
     0,
     1e-6},
    {"degrees",
     "degrees(a)",
     1,
     {-10, 0, 0},
     {10, 0, 0},
     [](double x, double, double) { return x * 180 / kPi; },
     0,
     1e-6},
    {"sin",
     "sin(a)",
     1,
     {-10, 0, 0},
     {10, 0, 0},
     [](double x, double, double) { return std::sin(x); },
     2e-6,
     0},
    {"cos",
     "cos(a)",
     1,
     {-10, 0, 0},
     {10, 0, 0},
     [](double x, double, double) { return std::cos(x); },
     2e-6,
     0},
    {"tan",
     "tan(a)",
     1,
     {-1.4f, 0, 0},
     {1.4f, 0, 0},
     [](double x, double, double) { return std::tan(x); },
     1e-6,
     2e-6},
    {"asin",
     "asin(a)",
     1,
     {-1, 0, 0},
     {1, 0, 0},
     [](double x, double, double) { return std::asin(x); },
     2e-6,
     0},
    {"acos",
     "acos(a)",
     1,
     {-1, 0, 0},
     {1, 0, 0},
     [](double x, double, double) { return std::acos(x); },
     2e-6,
     0},
    {"atan",
     "atan(a)",
     1,
     {-100, 0, 0},
     {100, 0, 0},
     [](double x, double, double) { return std::atan(x); },
     2e-6,
     0},
    {"atan2",
     "atan(a, b)",
     2,
     {-10, -10, 0},
     {10, 10, 0},
     [](double y, double x, double) { return std::atan2(y, x); },
     4e-6,
     0},
    // §8.2 exponential
    {"pow",
     "pow(a, b)",
     2,
     {0.01f, -3, 0},
     {10, 3, 0},
     [](double x, double y, double) { return std::pow(x, y); },
     0,
     2e-6},
    {"exp",
     "exp(a)",
     1,
     {-20, 0, 0},
     {20, 0, 0},
     [](double x, double, double) { return std::exp(x); },
     0,
     4e-6},
    {"log",
     "log(a)",
     1,
     {1e-3f, 0, 0},
     {1e3f, 0, 0},
     [](double x, double, double) { return std::log(x); },
     1e-6,
     1e-6},
    {"exp2",
     "exp2(a)",
     1,
     {-30, 0, 0},
     {30, 0, 0},
     [](double x, double, double) { return std::exp2(x); },
     0,
     1e-6},
    {"log2",
     "log2(a)",
     1,
     {1e-3f, 0, 0},
     {1e4f, 0, 0},
     [](double x, double, double) { return std::log2(x); },
     1e-6,
     1e-6},
    {"sqrt",
     "sqrt(a)",
     1,
     {0, 0, 0},
     {1e4f, 0, 0},
     [](double x, double, double) { return std::sqrt(x); },
     0,
     1e-7},
    {"inversesqrt",
     "inversesqrt(a)",
     1,
     {1e-3f, 0, 0},
     {1e3f, 0, 0},
     [](double x, double, double) { return 1 / std::sqrt(x); },
     0,
     2e-7},
    // §8.3 common
    {"abs",
     "abs(a)",
     1,
     {-100, 0, 0},
     {100, 0, 0},
     [](double x, double, double) { return std::fabs(x); },
     0,
     0},
    {"sign",
     "sign(a)",
     1,
     {-2, 0, 0},
     {2, 0, 0},
     [](double x, double, double) { return glsl_sign(x); },
     0,
     0},
    {"floor",
     "floor(a)",
     1,
     {-100, 0, 0},
     {100, 0, 0},
     [](double x, double, double) { return std::floor(x); },
     0,
     0},
    {"ceil",
     "ceil(a)",
     1,
     {-100, 0, 0},
     {100, 0, 0},
     [](double x, double, double) { return std::ceil(x); },
     0,
     0},
    {"fract",
     "fract(a)",
     1,
     {-100, 0, 0},
     {100, 0, 0},
     [](double x, double, double) { return x - std::floor(x); },
     0,
     0},
    {"mod",
     "mod(a, b)",
     2,
     {-100, 0.5f, 0},
     {100, 10, 0},
     [](double x, double y, double) { return glsl_mod(x, y); },
     1e-5,
     0},
    {"mod_float", "mod(a, b.x)", 2, {-100, 0.5f, 0}, {100, 10, 0}, nullptr, 1e-5, 0},
    {"min",
     "min(a, b)",
     2,
     {-10, -10, 0},
     {10, 10, 0},
     [](double x, double y, double) { return std::min(x, y); },
     0,
     0},
    {"max",
     "max(a, b)",
     2,
     {-10, -10, 0},
     {10, 10, 0},
     [](double x, double y, double) { return std::max(x, y); },
     0,
     0},
    {"clamp",
     "clamp(a, b, b + abs(c))",
     3,
     {-10, -5, -5},
     {10, 5, 5},
     [](double x, double lo, double w) { return std::min(std::max(x, lo), lo + std::fabs(w)); },
     1e-6,
     0},
    {"mix",
     "mix(a, b, c)",
     3,
     {-10, -10, 0},
     {10, 10, 1},
     [](double x, double y, double t) { return x * (1 - t) + y * t; },
     2e-6,
     0},
    {"step",
     "step(a, b)",
     2,
     {-1, -1, 0},
     {1, 1, 0},
     [](double e, double x, double) { return x < e ? 0.0 : 1.0; },
     0,
     0},
    {"smoothstep",
     "smoothstep(a, a + 0.5 + abs(b), c)",
     3,
     {-1, -1, -2},
     {1, 1, 3},
     [](double e0, double w, double x) { return smooth(e0, e0 + 0.5 + std::fabs(w), x); },
     2e-6,
     0},
    // §8.9 noise (zero, as Mesa)
    {"noise1",
     "vec4(noise1(a))",
     1,
     {-5, 0, 0},
     {5, 0, 0},
     [](double, double, double) { return 0.0; },
     0,
     0},
};

std::vector<std::array<Vec4, 4>> random_inputs(const Case& c, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<std::array<Vec4, 4>> in(64);
  for (auto& lane : in)
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < 4; ++k) {
        std::uniform_real_distribution<float> d(c.lo[a], std::max(c.hi[a], c.lo[a] + 1e-6f));
        lane[static_cast<size_t>(a)][static_cast<size_t>(k)] = d(rng);
      }
  return in;
}

class BuiltinTest : public ::testing::TestWithParam<Case> {};

TEST_P(BuiltinTest, MatchesDoubleReferenceAtEveryLevel) {
  const Case& c = GetParam();
  const std::string src =
      std::string("varying vec4 v0, v1, v2;\nvoid main() {\n  vec4 a = v0, b = v1, c = v2;\n") +
      "  gl_FragColor = " + c.expr + ";\n}\n";
  LaneShader sh(src);
  ASSERT_TRUE(sh.ok()) << sh.log;
  const auto in = random_inputs(c, 1234);
  std::vector<Vec4> first;
  double worst = 0;
  for (SimdLevel l : levels()) {
    set_simd_level(l);
    const auto out = sh.run(in);
    set_simd_level(simd_level_supported());
    if (first.empty()) first = out;
    for (size_t lane = 0; lane < out.size(); ++lane)
      for (size_t k = 0; k < 4; ++k) {
        ASSERT_EQ(bits(out[lane][k]), bits(first[lane][k]))
            << c.name << ": level " << level_name(l) << " differs from baseline, lane " << lane;
        const double x = in[lane][0][k], y = in[lane][1][k], z = in[lane][2][k];
        double want;
        if (c.ref)
          want = c.ref(x, y, z);
        else
          want = glsl_mod(x, in[lane][1][0]); // mod(vec4, float)
        const double err = std::fabs(out[lane][k] - want);
        worst = std::max(worst, err / (c.tol_abs + c.tol_rel * std::fabs(want) + 1e-300));
        EXPECT_LE(err, c.tol_abs + c.tol_rel * std::fabs(want))
            << c.name << "(" << x << ", " << y << ", " << z << ") = " << out[lane][k]
            << ", double: " << want;
      }
  }
  RecordProperty("worst_error_over_tolerance", std::to_string(worst));
}

INSTANTIATE_TEST_SUITE_P(Glsl120, BuiltinTest, ::testing::ValuesIn(kCases),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

// The same expression from varyings (per-lane kernels), uniforms (the prologue) and literals
// (the constant folder) gives the same bits.
TEST(BuiltinPaths, VaryingUniformAndConstantAgree) {
  const char* fns[] = {"sin(T)",
                       "cos(T)",
                       "tan(T * 0.1)",
                       "asin(T * 0.1)",
                       "acos(T * 0.1)",
                       "atan(T)",
                       "atan(T, 0.7)",
                       "pow(abs(T), 1.3)",
                       "exp(T)",
                       "log(abs(T))",
                       "exp2(T)",
                       "log2(abs(T))",
                       "sqrt(abs(T))",
                       "inversesqrt(abs(T))",
                       "fract(T)",
                       "mod(T, 0.7)",
                       "smoothstep(-1.0, 2.0, T)",
                       "sign(T)",
                       "degrees(T)",
                       "floor(T * 3.3)"};
  const float xs[] = {-7.25f, -1.5f, -0.3f, 0.0f, 0.4f, 1.0f, 2.71828f, 9.5f};
  const auto with = [](std::string e, const std::string& by) {
    for (size_t p = 0; (p = e.find('T', p)) != std::string::npos; p += by.size())
      e.replace(p, 1, by);
    return e;
  };
  for (const char* fn : fns) {
    LaneShader vary("varying vec4 v0;\nvoid main() { gl_FragColor = vec4(" + with(fn, "v0.x") +
                    "); }\n");
    LaneShader unif("uniform float u;\nvoid main() { gl_FragColor = vec4(" + with(fn, "u") +
                    "); }\n");
    ASSERT_TRUE(vary.ok() && unif.ok()) << vary.log << unif.log;
    for (float x : xs) {
      char lit[32];
      std::snprintf(lit, sizeof lit, "%.9g", static_cast<double>(x));
      std::string l = lit;
      if (l.find_first_of(".e") == std::string::npos) l += ".0";
      LaneShader cnst("void main() { gl_FragColor = vec4(" + with(fn, "(" + l + ")") + "); }\n");
      ASSERT_TRUE(cnst.ok()) << cnst.log;
      unif.pipe->set_uniform("u", {static_cast<double>(x)});
      std::vector<std::array<Vec4, 4>> in(4);
      for (auto& lane : in)
        lane[0] = {x, 0, 0, 0};
      const float a = vary.run(in)[0][0], b = unif.run(in)[0][0], c = cnst.run(in)[0][0];
      EXPECT_EQ(bits(a), bits(b)) << fn << " at " << x << ": varying " << a << ", uniform " << b;
      // (mod and fract cancel: their error scales with the argument.)
      EXPECT_TRUE(a == c || std::fabs(a - c) <= 4e-7 * (1 + std::fabs(a) + 4 * std::fabs(x)))
          << fn << " at " << x << ": varying " << a << ", constant " << c;
    }
  }
}

// §8.4 geometric functions.
TEST(BuiltinGeometric, MatchDoubleReference) {
  LaneShader sh(
      "varying vec4 v0, v1, v2;\n"
      "uniform int which;\n"
      "void main() {\n"
      "  vec3 a = v0.xyz, b = v1.xyz;\n"
      "  if (which == 0) gl_FragColor = vec4(length(a), distance(a, b), dot(a, b), length(v0));\n"
      "  else if (which == 1) gl_FragColor = vec4(cross(a, b), dot(v0.xy, v1.xy));\n"
      "  else if (which == 2) gl_FragColor = vec4(normalize(a), 0.0);\n"
      "  else if (which == 3) gl_FragColor = vec4(faceforward(a, b, v2.xyz), 0.0);\n"
      "  else if (which == 4) gl_FragColor = vec4(reflect(a, normalize(b)), 0.0);\n"
      "  else gl_FragColor = vec4(refract(normalize(a), normalize(b), v2.w), 0.0);\n"
      "}\n");
  ASSERT_TRUE(sh.ok()) << sh.log;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> d(-4, 4), eta(0.5f, 1.5f);
  std::vector<std::array<Vec4, 4>> in(64);
  for (auto& lane : in) {
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 4; ++k)
        lane[static_cast<size_t>(v)][static_cast<size_t>(k)] = d(rng);
    lane[2][3] = eta(rng);
  }
  using V3 = std::array<double, 3>;
  const auto dot3 = [](V3 a, V3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const auto norm = [&](V3 a) {
    const double l = std::sqrt(dot3(a, a));
    return V3{a[0] / l, a[1] / l, a[2] / l};
  };
  for (int which = 0; which <= 5; ++which) {
    sh.pipe->set_uniform("which", {static_cast<double>(which)});
    for (SimdLevel l : levels()) {
      set_simd_level(l);
      const auto out = sh.run(in);
      set_simd_level(simd_level_supported());
      for (size_t lane = 0; lane < out.size(); ++lane) {
        const auto& x = in[lane];
        const V3 a{x[0][0], x[0][1], x[0][2]}, b{x[1][0], x[1][1], x[1][2]},
            n{x[2][0], x[2][1], x[2][2]};
        double want[4] = {0, 0, 0, 0};
        if (which == 0) {
          const V3 dd{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
          want[0] = std::sqrt(dot3(a, a));
          want[1] = std::sqrt(dot3(dd, dd));
          want[2] = dot3(a, b);
          want[3] = std::sqrt(dot3(a, a) + double(x[0][3]) * x[0][3]);
        } else if (which == 1) {
          want[0] = a[1] * b[2] - a[2] * b[1];
          want[1] = a[2] * b[0] - a[0] * b[2];
          want[2] = a[0] * b[1] - a[1] * b[0];
          want[3] = a[0] * b[0] + a[1] * b[1];
        } else if (which == 2) {
          const V3 r = norm(a);
          want[0] = r[0], want[1] = r[1], want[2] = r[2];
        } else if (which == 3) {
          const double s = dot3(n, b) < 0 ? 1 : -1;
          want[0] = s * a[0], want[1] = s * a[1], want[2] = s * a[2];
        } else if (which == 4) {
          const V3 nb = norm(b);
          const double dd = dot3(nb, a);
          for (int k = 0; k < 3; ++k)
            want[k] = a[static_cast<size_t>(k)] - 2 * dd * nb[static_cast<size_t>(k)];
        } else {
          const V3 i = norm(a), nb = norm(b);
          const double e = x[2][3], dd = dot3(nb, i), k2 = 1 - e * e * (1 - dd * dd);
          for (int k = 0; k < 3; ++k)
            want[k] = k2 < 0 ? 0
                             : e * i[static_cast<size_t>(k)] -
                                   (e * dd + std::sqrt(k2)) * nb[static_cast<size_t>(k)];
        }
        for (size_t k = 0; k < 4; ++k)
          EXPECT_NEAR(out[lane][k], want[k], 2e-5 * (1 + std::fabs(want[k])))
              << "function set " << which << " lane " << lane << " component " << k;
      }
    }
  }
}

// §8.5 matrix functions and the matrix operators, square and not.
TEST(BuiltinMatrix, MatchDoubleReference) {
  LaneShader sh("#version 120\n"
                "varying vec4 v0, v1, v2, v3;\n"
                "uniform int which;\n"
                "void main() {\n"
                "  mat2x3 a = mat2x3(v0.xyz, v1.xyz);\n"      // 2 columns, 3 rows
                "  mat3x2 b = mat3x2(v2.xy, v2.zw, v3.xy);\n" // 3 columns, 2 rows
                "  mat3 p = a * b;\n"                         // 3x3
                "  mat2 q = b * a;\n"                         // 2x2
                "  if (which == 0) gl_FragColor = vec4(p[0][0], p[1][2], p[2][1], q[1][0]);\n"
                "  else if (which == 1) gl_FragColor = vec4(transpose(a)[2], transpose(b)[1].zx);\n"
                "  else if (which == 2) gl_FragColor = vec4(matrixCompMult(a, mat2x3(v2.xyz, "
                "v3.xyz))[1], outerProduct(v0.xy, v1.xyz)[2][1]);\n"
                "  else if (which == 3) gl_FragColor = vec4(a * v3.xy, 0.0);\n"
                "  else gl_FragColor = vec4(v3.xyz * a, 0.0, mat4(v0, v1, v2, v3)[2][3]);\n"
                "}\n");
  ASSERT_TRUE(sh.ok()) << sh.log;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> d(-3, 3);
  std::vector<std::array<Vec4, 4>> in(64);
  for (auto& lane : in)
    for (auto& v : lane)
      for (float& x : v)
        x = d(rng);
  for (int which = 0; which <= 4; ++which) {
    sh.pipe->set_uniform("which", {static_cast<double>(which)});
    for (SimdLevel l : levels()) {
      set_simd_level(l);
      const auto out = sh.run(in);
      set_simd_level(simd_level_supported());
      for (size_t lane = 0; lane < out.size(); ++lane) {
        const auto& x = in[lane];
        // A[c][r]: a has columns v0.xyz, v1.xyz; b columns v2.xy, v2.zw, v3.xy.
        const double A[2][3] = {{x[0][0], x[0][1], x[0][2]}, {x[1][0], x[1][1], x[1][2]}};
        const double B[3][2] = {{x[2][0], x[2][1]}, {x[2][2], x[2][3]}, {x[3][0], x[3][1]}};
        const auto P = [&](int c, int r) { return A[0][r] * B[c][0] + A[1][r] * B[c][1]; };
        const auto Q = [&](int c, int r) {
          return B[0][r] * A[c][0] + B[1][r] * A[c][1] + B[2][r] * A[c][2];
        };
        double want[4] = {0, 0, 0, 0};
        if (which == 0) {
          want[0] = P(0, 0), want[1] = P(1, 2), want[2] = P(2, 1), want[3] = Q(1, 0);
        } else if (which == 1) {
          // transpose(a)[2] = row 2 of a; transpose(b)[1] = row 1 of b, then .zx.
          want[0] = A[0][2], want[1] = A[1][2], want[2] = B[2][1], want[3] = B[0][1];
        } else if (which == 2) {
          // matrixCompMult(a, m)[1] where m's column 1 is v3.xyz; outerProduct(c, r)[j][i] = c[i] *
          // r[j].
          want[0] = A[1][0] * x[3][0], want[1] = A[1][1] * x[3][1], want[2] = A[1][2] * x[3][2];
          want[3] = double(x[0][1]) * x[1][2];
        } else if (which == 3) {
          for (int r = 0; r < 3; ++r)
            want[r] = A[0][r] * x[3][0] + A[1][r] * x[3][1];
        } else {
          for (int c = 0; c < 2; ++c)
            want[c] = A[c][0] * x[3][0] + A[c][1] * x[3][1] + A[c][2] * x[3][2];
          want[2] = 0;
          want[3] = x[2][3];
        }
        for (int k = 0; k < 4; ++k)
          EXPECT_NEAR(out[lane][static_cast<size_t>(k)], want[k], 1e-5 * (1 + std::fabs(want[k])))
              << "matrix set " << which << " lane " << lane << " component " << k;
      }
    }
  }
}

// §8.6 vector relational functions.
TEST(BuiltinRelational, MatchReference) {
  LaneShader sh("varying vec4 v0, v1;\n"
                "uniform int which;\n"
                "void main() {\n"
                "  ivec4 ia = ivec4(v0), ib = ivec4(v1);\n"
                "  if (which == 0) gl_FragColor = vec4(lessThan(v0, v1));\n"
                "  else if (which == 1) gl_FragColor = vec4(lessThanEqual(ia, ib));\n"
                "  else if (which == 2) gl_FragColor = vec4(greaterThan(v0, v1));\n"
                "  else if (which == 3) gl_FragColor = vec4(greaterThanEqual(ia, ib));\n"
                "  else if (which == 4) gl_FragColor = vec4(equal(ia, ib));\n"
                "  else if (which == 5) gl_FragColor = vec4(notEqual(v0, v1));\n"
                "  else gl_FragColor = vec4(any(lessThan(v0, v1)), all(lessThan(v0, v1)),\n"
                "                           any(not(equal(ia, ib))), all(not(equal(ia, ib))));\n"
                "}\n");
  ASSERT_TRUE(sh.ok()) << sh.log;
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> d(-2, 2);
  std::vector<std::array<Vec4, 4>> in(64);
  for (auto& lane : in)
    for (int v = 0; v < 2; ++v)
      for (float& x : lane[static_cast<size_t>(v)])
        x = static_cast<float>(d(rng));
  for (int which = 0; which <= 6; ++which) {
    sh.pipe->set_uniform("which", {static_cast<double>(which)});
    for (SimdLevel l : levels()) {
      set_simd_level(l);
      const auto out = sh.run(in);
      set_simd_level(simd_level_supported());
      for (size_t lane = 0; lane < out.size(); ++lane) {
        const auto& a = in[lane][0];
        const auto& b = in[lane][1];
        float want[4];
        bool any_lt = false, all_lt = true, any_ne = false, all_ne = true;
        for (size_t k = 0; k < 4; ++k) {
          const bool r[6] = {a[k]<b[k], a[k] <= b[k], a[k]> b[k], a[k] >= b[k], a[k] == b[k],
                             a[k] != b[k]};
          if (which < 6) want[k] = r[which] ? 1.0f : 0.0f;
          any_lt = any_lt || r[0], all_lt = all_lt && r[0], any_ne = any_ne || r[5],
          all_ne = all_ne && r[5];
        }
        if (which == 6) want[0] = any_lt, want[1] = all_lt, want[2] = any_ne, want[3] = all_ne;
        for (size_t k = 0; k < 4; ++k)
          EXPECT_EQ(out[lane][k], want[k]) << "relational set " << which << " lane " << lane;
      }
    }
  }
}

// §8.8 derivatives over 2x2 quads: coarse, dFdx from the quad's upper row and dFdy from its
// left column, the same for the four fragments.
TEST(BuiltinDerivatives, FromQuadNeighbours) {
  LaneShader sh(
      "varying vec4 v0;\nvoid main() {\n"
      "  gl_FragColor = vec4(dFdx(v0.x), dFdy(v0.x), fwidth(v0.y), dFdx(v0.z * v0.z));\n}\n");
  ASSERT_TRUE(sh.ok()) << sh.log;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> d(-10, 10);
  std::vector<std::array<Vec4, 4>> in(64);
  for (auto& lane : in)
    for (float& x : lane[0])
      x = d(rng);
  for (SimdLevel l : levels()) {
    set_simd_level(l);
    const auto out = sh.run(in);
    set_simd_level(simd_level_supported());
    for (size_t q = 0; q < 16; ++q) {
      const auto v = [&](size_t k, size_t c) { return in[4 * q + k][0][c]; };
      for (size_t k = 0; k < 4; ++k) {
        const Vec4& o = out[4 * q + k];
        EXPECT_EQ(o[0], v(3, 0) - v(2, 0));
        EXPECT_EQ(o[1], v(2, 0) - v(0, 0));
        EXPECT_EQ(o[2], std::fabs(v(3, 1) - v(2, 1)) + std::fabs(v(2, 1) - v(0, 1)));
        EXPECT_EQ(o[3], v(3, 2) * v(3, 2) - v(2, 2) * v(2, 2));
      }
    }
  }
}

} // namespace
} // namespace pineda::glsl_test
