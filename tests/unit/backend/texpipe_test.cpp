// Texture environment (GL 2.1 §3.8.13 Tables 3.22-3.27), fog factor (§3.10) and texture
// coordinate generation (§2.11.4) against double-precision references written from the spec
// tables.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "fragment/shade.h"
#include "geometry/texcoord.h"

namespace pineda {
namespace {

double clampd(double v) {
  return std::min(1.0, std::max(0.0, v));
}

struct Rng {
  uint32_t s = 12345u;
  double unit() {
    s ^= s << 13;
    s ^= s >> 17;
    s ^= s << 5;
    return static_cast<double>(s >> 8) / 16777216.0;
  }
};

constexpr TexBase kBases[] = {TexBase::Alpha,     TexBase::Luminance, TexBase::LuminanceAlpha,
                              TexBase::Intensity, TexBase::RGB,       TexBase::RGBA};

// Table 3.23: the texel as the sampler hands it over.
void expand(TexBase b, const double raw[4], double out[4]) {
  switch (b) {
  case TexBase::Alpha:
    out[0] = out[1] = out[2] = 0, out[3] = raw[3];
    break;
  case TexBase::Luminance:
    out[0] = out[1] = out[2] = raw[0], out[3] = 1;
    break;
  case TexBase::LuminanceAlpha:
    out[0] = out[1] = out[2] = raw[0], out[3] = raw[3];
    break;
  case TexBase::Intensity:
    out[0] = out[1] = out[2] = out[3] = raw[0];
    break;
  case TexBase::RGB:
    std::copy(raw, raw + 3, out), out[3] = 1;
    break;
  case TexBase::RGBA:
    std::copy(raw, raw + 4, out);
    break;
  }
}

// Table 3.22 row by row (the formats' own components, not the expanded ones).
void reference_env(GLenum mode, TexBase b, const double cp[4], const double raw[4],
                   const double cc[4], double cv[4]) {
  const double L = raw[0], A = raw[3];
  const double rgb[3] = {raw[0], raw[1], raw[2]};
  for (int k = 0; k < 4; ++k)
    cv[k] = cp[k];
  const auto set_rgb = [&](auto f) {
    for (int k = 0; k < 3; ++k)
      cv[k] = f(k);
  };
  const double* cs = (b == TexBase::RGB || b == TexBase::RGBA) ? rgb : nullptr;
  const auto col = [&](int k) { return cs ? cs[k] : L; }; // L for luminance/intensity formats
  switch (mode) {
  case GL_REPLACE:
    if (b != TexBase::Alpha) set_rgb(col);
    if (b == TexBase::Alpha || b == TexBase::LuminanceAlpha || b == TexBase::RGBA) cv[3] = A;
    if (b == TexBase::Intensity) cv[3] = L;
    break;
  case GL_MODULATE:
    if (b != TexBase::Alpha) set_rgb([&](int k) { return cp[k] * col(k); });
    if (b == TexBase::Alpha || b == TexBase::LuminanceAlpha || b == TexBase::RGBA)
      cv[3] = cp[3] * A;
    if (b == TexBase::Intensity) cv[3] = cp[3] * L;
    break;
  case GL_DECAL:
    if (b == TexBase::RGB) set_rgb(col);
    if (b == TexBase::RGBA) set_rgb([&](int k) { return cp[k] * (1 - A) + rgb[k] * A; });
    break;
  case GL_BLEND:
    if (b != TexBase::Alpha) set_rgb([&](int k) { return cp[k] * (1 - col(k)) + cc[k] * col(k); });
    if (b == TexBase::Alpha || b == TexBase::LuminanceAlpha || b == TexBase::RGBA)
      cv[3] = cp[3] * A;
    if (b == TexBase::Intensity) cv[3] = cp[3] * (1 - L) + cc[3] * L;
    break;
  case GL_ADD:
    if (b != TexBase::Alpha) set_rgb([&](int k) { return cp[k] + col(k); });
    if (b == TexBase::Alpha || b == TexBase::LuminanceAlpha || b == TexBase::RGBA)
      cv[3] = cp[3] * A;
    if (b == TexBase::Intensity) cv[3] = cp[3] + L;
    break;
  default:
    break;
  }
  for (int k = 0; k < 4; ++k)
    cv[k] = clampd(cv[k]);
}

TEST(TexEnv, FixedFunctionsMatchTable322) {
  Rng rng;
  const int slot_of_unit[kMaxTexUnits] = {0, -1, -1, -1};
  for (GLenum mode : {GL_REPLACE, GL_MODULATE, GL_DECAL, GL_BLEND, GL_ADD}) {
    for (TexBase b : kBases) {
      // DECAL is defined for RGB and RGBA only.
      if (mode == GL_DECAL && b != TexBase::RGB && b != TexBase::RGBA) continue;
      for (int iter = 0; iter < 200; ++iter) {
        double cp[4], raw[4], cc[4], cs[4] = {}, ref[4];
        for (int k = 0; k < 4; ++k)
          cp[k] = rng.unit(), raw[k] = rng.unit(), cc[k] = rng.unit();
        expand(b, raw, cs);
        reference_env(mode, b, cp, raw, cc, ref);
        ShadeUnit u;
        u.mode = mode;
        float fcp[4], fcs[4], out[4], tex[1][4];
        for (int k = 0; k < 4; ++k) {
          fcp[k] = static_cast<float>(cp[k]);
          fcs[k] = tex[0][k] = static_cast<float>(cs[k]);
          u.color[k] = static_cast<float>(cc[k]);
        }
        apply_tex_env(u, b, fcp, fcp, tex, slot_of_unit, fcs, out);
        for (int k = 0; k < 4; ++k)
          ASSERT_NEAR(out[k], ref[k], 1e-6) << "mode " << mode << " base " << int(b) << " k " << k;
      }
    }
  }
}

// Table 3.24 / 3.25 on arguments already through their operands.
double reference_combine(GLenum f, double a0, double a1, double a2) {
  switch (f) {
  case GL_REPLACE:
    return a0;
  case GL_MODULATE:
    return a0 * a1;
  case GL_ADD:
    return a0 + a1;
  case GL_ADD_SIGNED:
    return a0 + a1 - 0.5;
  case GL_INTERPOLATE:
    return a0 * a2 + a1 * (1 - a2);
  case GL_SUBTRACT:
    return a0 - a1;
  default:
    return 0;
  }
}

TEST(TexEnv, CombineFunctionsSourcesAndOperands) {
  Rng rng;
  const GLenum funcs[] = {GL_REPLACE,     GL_MODULATE, GL_ADD,      GL_ADD_SIGNED,
                          GL_INTERPOLATE, GL_SUBTRACT, GL_DOT3_RGB, GL_DOT3_RGBA};
  const GLenum ops_rgb[] = {GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA,
                            GL_ONE_MINUS_SRC_ALPHA};
  // Sources: 0, 1 texture of units 0 and 1, 4 constant, 5 primary, 6 previous.
  const uint8_t sources[] = {0, 1, 4, 5, 6};
  const int slot_of_unit[kMaxTexUnits] = {0, 1, -1, -1};
  for (int iter = 0; iter < 4000; ++iter) {
    ShadeUnit u;
    u.mode = GL_COMBINE;
    u.combine_rgb = funcs[iter % 8];
    u.combine_alpha = funcs[(iter / 8) % 6];
    for (int i = 0; i < 3; ++i) {
      u.src_rgb[i] = sources[(iter / (3 + i)) % 5];
      u.src_alpha[i] = sources[(iter / (7 + i)) % 5];
      u.op_rgb[i] = ops_rgb[(iter / (11 + i)) % 4];
      u.op_alpha[i] = ops_rgb[2 + (iter / (13 + i)) % 2];
    }
    u.rgb_scale = static_cast<float>(1 << (iter % 3));
    u.alpha_scale = static_cast<float>(1 << ((iter / 3) % 3));
    double v[7][4] = {}; // by source index
    float fv[7][4];
    for (int s : {0, 1, 4, 5, 6})
      for (int k = 0; k < 4; ++k) {
        fv[s][k] = static_cast<float>(rng.unit());
        v[s][k] = fv[s][k];
      }
    for (int k = 0; k < 4; ++k)
      u.color[k] = fv[4][k];
    const float tex[2][4] = {{fv[0][0], fv[0][1], fv[0][2], fv[0][3]},
                             {fv[1][0], fv[1][1], fv[1][2], fv[1][3]}};
    float out[4];
    apply_tex_env(u, TexBase::RGBA, fv[6], fv[5], tex, slot_of_unit, tex[0], out);
    double arg[3][4];
    for (int i = 0; i < 3; ++i) {
      const double* s = v[u.src_rgb[i]];
      for (int k = 0; k < 3; ++k) {
        switch (u.op_rgb[i]) {
        case GL_SRC_COLOR:
          arg[i][k] = s[k];
          break;
        case GL_ONE_MINUS_SRC_COLOR:
          arg[i][k] = 1 - s[k];
          break;
        case GL_SRC_ALPHA:
          arg[i][k] = s[3];
          break;
        default:
          arg[i][k] = 1 - s[3];
          break;
        }
      }
      const double a = v[u.src_alpha[i]][3];
      arg[i][3] = u.op_alpha[i] == GL_SRC_ALPHA ? a : 1 - a;
    }
    double ref[4];
    if (u.combine_rgb == GL_DOT3_RGB || u.combine_rgb == GL_DOT3_RGBA) {
      double d = 0;
      for (int k = 0; k < 3; ++k)
        d += (arg[0][k] - 0.5) * (arg[1][k] - 0.5);
      for (int k = 0; k < 3; ++k)
        ref[k] = clampd(4 * d * u.rgb_scale);
      ref[3] = u.combine_rgb == GL_DOT3_RGBA
                   ? clampd(4 * d * u.rgb_scale)
                   : clampd(reference_combine(u.combine_alpha, arg[0][3], arg[1][3], arg[2][3]) *
                            u.alpha_scale);
    } else {
      for (int k = 0; k < 3; ++k)
        ref[k] =
            clampd(reference_combine(u.combine_rgb, arg[0][k], arg[1][k], arg[2][k]) * u.rgb_scale);
      ref[3] = clampd(reference_combine(u.combine_alpha, arg[0][3], arg[1][3], arg[2][3]) *
                      u.alpha_scale);
    }
    for (int k = 0; k < 4; ++k)
      ASSERT_NEAR(out[k], ref[k], 4e-6) << "iteration " << iter;
  }
}

TEST(Fog, FactorMatchesEquations) {
  ShadeSetup ss;
  ss.fog_density = 0.37f;
  ss.fog_start = 1.5f;
  ss.fog_end = 11.0f;
  for (double c = -2.0; c < 30.0; c += 0.173) {
    const auto fc = static_cast<float>(c);
    ss.fog_mode = GL_LINEAR;
    EXPECT_NEAR(fog_factor(ss, fc), clampd((11.0 - fc) / (11.0 - 1.5)), 1e-6);
    ss.fog_mode = GL_EXP;
    EXPECT_NEAR(fog_factor(ss, fc), clampd(std::exp(-0.37 * fc)), 1e-6);
    ss.fog_mode = GL_EXP2;
    EXPECT_NEAR(fog_factor(ss, fc), clampd(std::exp(-(0.37 * fc) * (0.37 * fc))), 1e-6);
  }
}

// §2.11.4 with the model-view a rotation + translation, in double precision.
TEST(TexGen, EveryModeAndTheTextureMatrix) {
  const double mv[16] = {0.8, 0.6, 0, 0, -0.6, 0.8, 0, 0, 0, 0, 1, 0, 0.5, -0.25, -4.0, 1};
  TexVertexSetup ts;
  for (int i = 0; i < 16; ++i)
    ts.modelview[i] = static_cast<float>(mv[i]);
  // Rotation: the normal matrix is the rotation itself.
  const int idx3[9] = {0, 1, 2, 4, 5, 6, 8, 9, 10};
  for (int i = 0; i < 9; ++i)
    ts.normal_matrix[i] = static_cast<float>(mv[idx3[i]]);
  ts.units = 0xf;
  ts.need_eye = ts.need_normal = true;
  const GLenum modes[4][4] = {
      {GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_OBJECT_LINEAR, GL_EYE_LINEAR},
      {GL_SPHERE_MAP, GL_SPHERE_MAP, GL_OBJECT_LINEAR, GL_OBJECT_LINEAR},
      {GL_REFLECTION_MAP, GL_REFLECTION_MAP, GL_REFLECTION_MAP, GL_EYE_LINEAR},
      {GL_NORMAL_MAP, GL_NORMAL_MAP, GL_NORMAL_MAP, GL_OBJECT_LINEAR}};
  const double plane[4] = {0.25, -0.5, 0.75, 0.125};
  for (int u = 0; u < 4; ++u)
    for (int c = 0; c < 4; ++c) {
      ts.unit[u].gen[c] = true;
      ts.unit[u].mode[c] = modes[u][c];
      for (int k = 0; k < 4; ++k)
        ts.unit[u].plane[c][k] = static_cast<float>(plane[(k + c) % 4]);
    }
  // Unit 3 gets a texture matrix: scale 2 and translate (0.5, 0, 0).
  ts.unit[3].identity = false;
  const float tm[16] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0.5f, 0, 0, 1};
  std::copy(tm, tm + 16, ts.unit[3].matrix);
  ts.fog = true;
  ts.fog_from_depth = true;

  const float pos[4] = {0.3f, -0.7f, 1.1f, 1.0f};
  const float nrm[3] = {0.48f, 0.6f, 0.64f}; // unit length
  const float tex[4][4] = {};
  float attr[kMaxAttr] = {};
  tex_vertex(ts, pos, nrm, tex, 0.0f, attr);

  double eye[4], n[4] = {0, 0, 0, 0};
  for (int r = 0; r < 4; ++r)
    eye[r] = mv[r] * pos[0] + mv[4 + r] * pos[1] + mv[8 + r] * pos[2] + mv[12 + r] * pos[3];
  for (int r = 0; r < 3; ++r)
    n[r] = mv[r] * nrm[0] + mv[4 + r] * nrm[1] + mv[8 + r] * nrm[2];
  const double len = std::sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);
  const double uu[3] = {eye[0] / len, eye[1] / len, eye[2] / len};
  const double nu = n[0] * uu[0] + n[1] * uu[1] + n[2] * uu[2];
  double rf[4] = {0, 0, 0, 0};
  for (int k = 0; k < 3; ++k)
    rf[k] = uu[k] - 2 * n[k] * nu;
  const double m = 2 * std::sqrt(rf[0] * rf[0] + rf[1] * rf[1] + (rf[2] + 1) * (rf[2] + 1));
  for (int u = 0; u < 4; ++u) {
    double g[4];
    for (int c = 0; c < 4; ++c) {
      double p[4];
      for (int k = 0; k < 4; ++k)
        p[k] = plane[(k + c) % 4];
      switch (modes[u][c]) {
      case GL_OBJECT_LINEAR:
        g[c] = p[0] * pos[0] + p[1] * pos[1] + p[2] * pos[2] + p[3] * pos[3];
        break;
      case GL_EYE_LINEAR:
        g[c] = p[0] * eye[0] + p[1] * eye[1] + p[2] * eye[2] + p[3] * eye[3];
        break;
      case GL_SPHERE_MAP:
        g[c] = rf[c] / m + 0.5;
        break;
      case GL_REFLECTION_MAP:
        g[c] = rf[c];
        break;
      default:
        g[c] = n[c];
        break;
      }
    }
    if (u == 3) {
      for (int c = 0; c < 3; ++c)
        g[c] *= 2;
      g[0] += 0.5 * g[3];
    }
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(attr[kAttrTex0 + 4 * u + c], g[c], 2e-6) << "unit " << u << " coord " << c;
  }
  EXPECT_NEAR(attr[kAttrFog], std::fabs(eye[2]), 1e-6);
}

} // namespace
} // namespace pineda
