// Per-fragment shading: texture coordinates and level of detail (GL 2.1 §3.8.8), texture
// lookups (src/texture/sampler.h), the texture environments in unit order (§3.8.13), the colour
// sum (§3.9) and fog (§3.10), for the fragments of one 8x8 block.
//
// Level of detail follows llvmpipe: one lambda per 2x2 quad (quads aligned to even pixel
// positions), from the differences of the coordinates along the quad's upper row (d/dx) and
// left column (d/dy), with rho the longer of the two scaled derivative vectors (§3.8.8).
// The work runs quad by quad, four fragments in a vector, with the same arithmetic lane by
// lane as one fragment at a time.
#include "fragment/shade.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "fragment/fog_equation.h"
#include "core/simd.h"
#include "texture/cpu_dispatch.h"

namespace pineda {

namespace {

inline float clamp01(float v) {
  return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
}

inline float eval(const PlaneF& p, float fi, float fj) {
  return p.v0 + fi * p.dx + fj * p.dy;
}

// eval and clamp01 on the four fragments of a quad (the same operations lane by lane).
inline f32x4 evalv(const PlaneF& p, f32x4 fi, f32x4 fj) {
  return p.v0 + fi * p.dx + fj * p.dy;
}
inline f32x4 clamp01v(f32x4 v) {
  const f32x4 zero = {}, one = zero + 1.0f;
  return v > zero ? vmin(v, one) : zero;
}

// Quad q's four entries of a quad-ordered array.
inline f32x4 load4(const float* a, int q) {
  f32x4 v;
  std::memcpy(&v, a + 4 * q, sizeof(v));
  return v;
}
inline void store4(float* a, int q, f32x4 v) {
  std::memcpy(a + 4 * q, &v, sizeof(v));
}

// One combine argument (§3.8.13 Table 3.26/3.27): the operand applied to the source colour.
inline void operand_rgb(GLenum op, const float* src, float out[3]) {
  switch (op) {
  case GL_SRC_COLOR:
    for (int k = 0; k < 3; ++k)
      out[k] = src[k];
    break;
  case GL_ONE_MINUS_SRC_COLOR:
    for (int k = 0; k < 3; ++k)
      out[k] = 1.0f - src[k];
    break;
  case GL_SRC_ALPHA:
    for (int k = 0; k < 3; ++k)
      out[k] = src[3];
    break;
  default:
    for (int k = 0; k < 3; ++k)
      out[k] = 1.0f - src[3];
    break;
  }
}

inline float operand_alpha(GLenum op, const float* src) {
  return op == GL_SRC_ALPHA ? src[3] : 1.0f - src[3];
}

// The combine function (§3.8.13 Table 3.24/3.25) on one component.
inline float combine(GLenum f, float a0, float a1, float a2) {
  switch (f) {
  case GL_REPLACE:
    return a0;
  case GL_MODULATE:
    return a0 * a1;
  case GL_ADD:
    return a0 + a1;
  case GL_ADD_SIGNED:
    return a0 + a1 - 0.5f;
  case GL_INTERPOLATE:
    return a0 * a2 + a1 * (1.0f - a2);
  case GL_SUBTRACT:
    return a0 - a1;
  default:
    return a0;
  }
}

// The texture environment of one fragment; inlined into shade_block's fragment loop.
inline void tex_env(const ShadeUnit& u, TexBase base, const float cp[4], const float cf[4],
                    const float (*tex)[4], const int* slot_of_unit, const float cs[4],
                    float cv[4]) {
  // The sampler expands the texel by Table 3.23 (ALPHA -> (0,0,0,A), LUMINANCE -> (L,L,L,1),
  // INTENSITY -> (I,I,I,I), RGB -> (R,G,B,1)); which components the base format really has
  // still decides between the rows of Table 3.22.
  const bool has_rgb = base != TexBase::Alpha;
  const bool has_alpha = base == TexBase::Alpha || base == TexBase::LuminanceAlpha ||
                         base == TexBase::Intensity || base == TexBase::RGBA;
  switch (u.mode) {
  case GL_REPLACE:
    for (int k = 0; k < 3; ++k)
      cv[k] = has_rgb ? cs[k] : cp[k];
    cv[3] = has_alpha ? cs[3] : cp[3];
    break;
  case GL_MODULATE:
    for (int k = 0; k < 3; ++k)
      cv[k] = has_rgb ? cp[k] * cs[k] : cp[k];
    cv[3] = has_alpha ? cp[3] * cs[3] : cp[3];
    break;
  case GL_DECAL:
    // Defined for RGB and RGBA (As is 1 for RGB); the other formats get the same formula.
    for (int k = 0; k < 3; ++k)
      cv[k] = cp[k] * (1.0f - cs[3]) + cs[k] * cs[3];
    cv[3] = cp[3];
    break;
  case GL_BLEND:
    for (int k = 0; k < 3; ++k)
      cv[k] = has_rgb ? cp[k] * (1.0f - cs[k]) + u.color[k] * cs[k] : cp[k];
    if (base == TexBase::Intensity)
      cv[3] = cp[3] * (1.0f - cs[3]) + u.color[3] * cs[3];
    else
      cv[3] = has_alpha ? cp[3] * cs[3] : cp[3];
    break;
  case GL_ADD:
    for (int k = 0; k < 3; ++k)
      cv[k] = has_rgb ? cp[k] + cs[k] : cp[k];
    if (base == TexBase::Intensity)
      cv[3] = cp[3] + cs[3];
    else
      cv[3] = has_alpha ? cp[3] * cs[3] : cp[3];
    break;
  case GL_COMBINE: {
    const auto source = [&](uint8_t s) -> const float* {
      if (s < kMaxTexUnits) {
        const int slot = slot_of_unit[s];
        // GL 1.4: a crossbar reference to a disabled unit is undefined; use the previous colour.
        return slot >= 0 ? tex[slot] : cp;
      }
      if (s == 4) return u.color;
      if (s == 5) return cf;
      return cp;
    };
    float arg_rgb[3][3], arg_a[3];
    for (int i = 0; i < 3; ++i) {
      operand_rgb(u.op_rgb[i], source(u.src_rgb[i]), arg_rgb[i]);
      arg_a[i] = operand_alpha(u.op_alpha[i], source(u.src_alpha[i]));
    }
    if (u.combine_rgb == GL_DOT3_RGB || u.combine_rgb == GL_DOT3_RGBA) {
      // 4 ((r0 - 1/2)(r1 - 1/2) + (g0 - 1/2)(g1 - 1/2) + (b0 - 1/2)(b1 - 1/2)) in every channel.
      float d = 0.0f;
      for (int k = 0; k < 3; ++k)
        d += (arg_rgb[0][k] - 0.5f) * (arg_rgb[1][k] - 0.5f);
      d *= 4.0f;
      for (int k = 0; k < 3; ++k)
        cv[k] = clamp01(d * u.rgb_scale);
      // DOT3_RGBA writes the dot product to alpha too, ignoring COMBINE_ALPHA.
      cv[3] = u.combine_rgb == GL_DOT3_RGBA
                  ? clamp01(d * u.rgb_scale)
                  : clamp01(combine(u.combine_alpha, arg_a[0], arg_a[1], arg_a[2]) * u.alpha_scale);
      return;
    }
    for (int k = 0; k < 3; ++k)
      cv[k] = clamp01(combine(u.combine_rgb, arg_rgb[0][k], arg_rgb[1][k], arg_rgb[2][k]) *
                      u.rgb_scale);
    cv[3] = clamp01(combine(u.combine_alpha, arg_a[0], arg_a[1], arg_a[2]) * u.alpha_scale);
    return;
  }
  default:
    for (int k = 0; k < 4; ++k)
      cv[k] = cp[k];
    break;
  }
  for (int k = 0; k < 4; ++k)
    cv[k] = clamp01(cv[k]);
}

} // namespace

void apply_tex_env(const ShadeUnit& u, TexBase base, const float cp[4], const float cf[4],
                   const float (*tex)[4], const int* slot_of_unit, const float cs[4], float cv[4]) {
  tex_env(u, base, cp, cf, tex, slot_of_unit, cs, cv);
}

float fog_factor(const ShadeSetup& ss, float c) {
  return fog_equation(ss.fog_mode, ss.fog_density, ss.fog_start, ss.fog_end, c);
}

namespace {

// shade_block's body, compiled twice like the sampler's quad path (texture/sampler_quad.cpp):
// for the default target and, chosen at run time, for AVX2 (VEX forms of the same instructions,
// no FMA, so the same results).
[[gnu::always_inline]] inline void shade_body(const FragCtx& ctx, const FragInputs& in, int bx,
                                              int by, uint64_t mask, float (*out)[64]) {
  const ShadeSetup& ss = *ctx.shade;
  const ShadeInputs& si = *in.shade;
  const float fi0 = static_cast<float>(bx - in.ox), fj0 = static_cast<float>(by - in.oy);

  // The 2x2 quads holding a fragment. Everything below is kept in quad order: entry 4q + k is
  // lane k of quad q, the pixel (k & 1, k >> 1) of the quad. Every pixel of such a quad feeds
  // the derivatives; quads without a fragment in a row pair with one are written as zeros
  // (the block loop reads whole rows).
  int qpix[16];      // block pixel index of lane 0
  unsigned qcov[16]; // fragments of the quad: bit k for lane k
  int nq = 0;
  for (int qy = 0; qy < 4; ++qy) {
    const unsigned pair = static_cast<unsigned>(mask >> (16 * qy)) & 0xffffu;
    if (pair == 0) continue;
    for (int qx = 0; qx < 4; ++qx) {
      const unsigned m = (pair >> (2 * qx)) & 0x303u;
      const int p = 16 * qy + 2 * qx;
      if (m == 0) {
        for (int c = 0; c < 4; ++c)
          out[c][p] = out[c][p + 1] = out[c][p + 8] = out[c][p + 9] = 0.0f;
        continue;
      }
      qpix[nq] = p;
      qcov[nq] = (m & 3u) | ((m >> 6) & 0xcu);
      ++nq;
    }
  }

  // Window offsets, w (1 / (1/w), §3.5.1 eq 3.9) and the primary (and secondary) colours.
  const i32x4 lane_x = {0, 1, 0, 1}, lane_y = {0, 0, 1, 1};
  alignas(16) float fiq[64], fjq[64], w[64];
  alignas(16) float cf[4][64], c2[3][64];
  for (int q = 0; q < nq; ++q) {
    const int p = qpix[q];
    const f32x4 fi = fi0 + __builtin_convertvector((p & 7) + lane_x, f32x4);
    const f32x4 fj = fj0 + __builtin_convertvector((p >> 3) + lane_y, f32x4);
    const f32x4 wv = 1.0f / evalv(si.inv_w, fi, fj);
    store4(fiq, q, fi);
    store4(fjq, q, fj);
    store4(w, q, wv);
    if (si.const_colors) {
      for (int c = 0; c < 4; ++c)
        store4(cf[c], q, f32x4{} + si.color[c]);
      if (ss.color_sum)
        for (int c = 0; c < 3; ++c)
          store4(c2[c], q, f32x4{} + si.color2[c]);
      continue;
    }
    for (int c = 0; c < 4; ++c)
      store4(cf[c], q, clamp01v(evalv(si.color_w[c], fi, fj) * wv));
    if (ss.color_sum)
      for (int c = 0; c < 3; ++c)
        store4(c2[c], q, clamp01v(evalv(si.color2_w[c], fi, fj) * wv));
  }

  // Texture lookups of every enabled unit, in planes: tex[unit][channel][4q + k].
  alignas(16) float tex[kMaxTexUnits][4][64];
  for (int k = 0; k < ss.unit_count; ++k) {
    const ShadeUnit& su = ss.unit[k];
    const PlaneF* tp = si.tex_w[su.index];
    const bool cube = su.dims == LodDims::Cube;
    // The vector sampler reads s and t only; r also serves depth comparison (§3.8.14).
    const bool need_r = !su.view.quads;
    alignas(16) float s[64], t[64], r[64];
    for (int q = 0; q < nq; ++q) {
      const f32x4 fi = load4(fiq, q), fj = load4(fjq, q), wv = load4(w, q);
      const f32x4 ss_ = evalv(tp[0], fi, fj) * wv;
      const f32x4 tt = evalv(tp[1], fi, fj) * wv;
      if (cube) {
        // §3.8.6: cube map coordinates are a direction; q does not matter.
        store4(s, q, ss_), store4(t, q, tt), store4(r, q, evalv(tp[2], fi, fj) * wv);
      } else {
        // §3.8.8: the coordinates are divided by q.
        const f32x4 inv_q = 1.0f / (evalv(tp[3], fi, fj) * wv);
        store4(s, q, ss_ * inv_q), store4(t, q, tt * inv_q);
        if (need_r) store4(r, q, (evalv(tp[2], fi, fj) * wv) * inv_q);
      }
    }
    // lambda per quad, from lanes 0 (lower left), 2 (upper left) and 3 (upper right).
    alignas(16) float lam[16];
    const float width = static_cast<float>(su.view.width);
    const float height = static_cast<float>(su.view.height);
    const float depth = static_cast<float>(su.view.depth);
    for (int q = 0; q < nq; ++q) {
      const int ll = 4 * q, ul = ll + 2, ur = ll + 3;
      // Scaled derivatives (u, v, w) along x and y (§3.8.8 eq 3.18).
      float dx[3] = {0, 0, 0}, dy[3] = {0, 0, 0};
      if (cube) {
        // Derivatives of the face coordinates along the major axis of the quad's first
        // fragment. Not the upper-left lane's: where a small primitive covers part of a quad
        // (a 3x3 face drawn at an odd position), that lane may be a helper whose extrapolated
        // direction leaves the face, and another face's axis gives a far too large rho.
        const int rep = ll + std::countr_zero(qcov[q]);
        const float ax = std::fabs(s[rep]), ay = std::fabs(t[rep]), az = std::fabs(r[rep]);
        const int major = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
        const auto face = [&](int p, float& u, float& v) {
          const float d[3] = {s[p], t[p], r[p]};
          const float ma = std::fabs(d[major]);
          const float inv = ma > 0.0f ? 0.5f / ma : 0.0f;
          u = d[major == 0 ? 2 : 0] * inv;
          v = d[major == 1 ? 2 : 1] * inv;
        };
        float u0, v0, u1, v1, u2, v2;
        face(ul, u0, v0);
        face(ur, u1, v1);
        face(ll, u2, v2);
        dx[0] = (u1 - u0) * width, dx[1] = (v1 - v0) * width;
        dy[0] = (u0 - u2) * width, dy[1] = (v0 - v2) * width;
      } else {
        dx[0] = (s[ur] - s[ul]) * width, dy[0] = (s[ul] - s[ll]) * width;
        if (su.dims != LodDims::One)
          dx[1] = (t[ur] - t[ul]) * height, dy[1] = (t[ul] - t[ll]) * height;
        if (su.dims == LodDims::Three)
          dx[2] = (r[ur] - r[ul]) * depth, dy[2] = (r[ul] - r[ll]) * depth;
      }
      // §3.8.8 eq 3.19: rho = max of the two derivative vectors' lengths; lambda = log2(rho),
      // taken as half the log of the squared length.
      const float rho2 = std::max(dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2],
                                  dy[0] * dy[0] + dy[1] * dy[1] + dy[2] * dy[2]);
      // log2(0) is -infinity: plain magnification; keep it finite for the sampler.
      lam[q] = rho2 > 0.0f ? std::max(0.5f * lod_log2(rho2), -64.0f) : -64.0f;
    }
    if (su.view.quads) {
      sample_quads(su.view, nq, s, t, lam, su.bias, tex[k]);
      continue;
    }
    // The general sampler on the fragments only; the quads' other lanes read as zeros.
    alignas(16) float gs[64], gt[64], gr[64], gl[64];
    int n = 0;
    for (int q = 0; q < nq; ++q)
      for (int l = 0; l < 4; ++l)
        if (qcov[q] & (1u << l)) {
          gs[n] = s[4 * q + l], gt[n] = t[4 * q + l], gr[n] = r[4 * q + l], gl[n] = lam[q];
          ++n;
        }
    float sampled[64][4];
    sample_texture(su.view, n, gs, gt, gr, gl, su.bias, sampled);
    n = 0;
    for (int q = 0; q < nq; ++q)
      for (int l = 0; l < 4; ++l) {
        const bool covered = (qcov[q] & (1u << l)) != 0;
        for (int c = 0; c < 4; ++c)
          tex[k][c][4 * q + l] = covered ? sampled[n][c] : 0.0f;
        n += covered ? 1 : 0;
      }
  }

  // Environments in unit order (§3.8.13), colour sum (§3.9), fog (§3.10). MODULATE and
  // REPLACE run four fragments at a time; the other environments one fragment at a time.
  bool vector_env = true;
  for (int k = 0; k < ss.unit_count; ++k)
    vector_env = vector_env && (ss.unit[k].mode == GL_MODULATE || ss.unit[k].mode == GL_REPLACE);
  for (int q = 0; q < nq; ++q) {
    const int p = qpix[q];
    f32x4 c[4];
    if (vector_env) {
      for (int ch = 0; ch < 4; ++ch)
        c[ch] = load4(cf[ch], q);
      for (int k = 0; k < ss.unit_count; ++k) {
        const ShadeUnit& su = ss.unit[k];
        const TexBase base = su.view.base;
        // Table 3.22: which components the base format has picks the row.
        const bool has_rgb = base != TexBase::Alpha;
        const bool has_alpha = base == TexBase::Alpha || base == TexBase::LuminanceAlpha ||
                               base == TexBase::Intensity || base == TexBase::RGBA;
        const bool modulate = su.mode == GL_MODULATE;
        for (int ch = 0; ch < 4; ++ch) {
          if (ch < 3 ? has_rgb : has_alpha) {
            const f32x4 cs = load4(tex[k][ch], q);
            c[ch] = modulate ? c[ch] * cs : cs;
          }
          c[ch] = clamp01v(c[ch]);
        }
      }
      // §3.9 clamps the sum; llvmpipe (the tie-breaker) carries it unclamped and clamps only
      // the final colour.
      if (ss.color_sum)
        for (int ch = 0; ch < 3; ++ch)
          c[ch] += load4(c2[ch], q);
      if (ss.fog) {
        const f32x4 coord = evalv(si.fog_w, load4(fiq, q), load4(fjq, q)) * load4(w, q);
        // GL_FOG_HINT = FASTEST: the geometry stage evaluated f per vertex and `coord` is its
        // interpolation (§3.10 "may be computed at each vertex and interpolated").
        f32x4 fog = clamp01v(coord);
        if (!ss.fog_per_vertex)
          for (int l = 0; l < 4; ++l)
            fog[l] = (qcov[q] & (1u << l)) != 0 ? fog_factor(ss, coord[l]) : 0.0f;
        // §3.10: C = f C_r + (1 - f) C_f on R, G and B; alpha is unchanged.
        for (int ch = 0; ch < 3; ++ch)
          c[ch] = fog * c[ch] + (1.0f - fog) * ss.fog_color[ch];
      }
    } else {
      for (int l = 0; l < 4; ++l) {
        const int e = 4 * q + l;
        const float cfl[4] = {cf[0][e], cf[1][e], cf[2][e], cf[3][e]};
        float cl[4] = {cfl[0], cfl[1], cfl[2], cfl[3]};
        if (ss.unit_count != 0) {
          float tf[kMaxTexUnits][4];
          for (int k = 0; k < ss.unit_count; ++k)
            for (int ch = 0; ch < 4; ++ch)
              tf[k][ch] = tex[k][ch][e];
          for (int k = 0; k < ss.unit_count; ++k) {
            float cv[4];
            tex_env(ss.unit[k], ss.unit[k].view.base, cl, cfl, tf, ss.slot_of_unit, tf[k], cv);
            for (int ch = 0; ch < 4; ++ch)
              cl[ch] = cv[ch];
          }
        }
        if (ss.color_sum)
          for (int ch = 0; ch < 3; ++ch)
            cl[ch] += c2[ch][e];
        if (ss.fog && (qcov[q] & (1u << l)) != 0) {
          const float coord = eval(si.fog_w, fiq[e], fjq[e]) * w[e];
          // GL_FOG_HINT = FASTEST: the geometry stage evaluated f per vertex and `coord` is
          // its interpolation (§3.10 "may be computed at each vertex and interpolated").
          const float fog = ss.fog_per_vertex ? clamp01(coord) : fog_factor(ss, coord);
          // §3.10: C = f C_r + (1 - f) C_f on R, G and B; alpha is unchanged.
          for (int ch = 0; ch < 3; ++ch)
            cl[ch] = fog * cl[ch] + (1.0f - fog) * ss.fog_color[ch];
        }
        for (int ch = 0; ch < 4; ++ch)
          c[ch][l] = cl[ch];
      }
    }
    // Lanes 0, 1 are pixels p, p + 1; lanes 2, 3 the row above.
    for (int ch = 0; ch < 4; ++ch) {
#if defined(__SSE2__)
      _mm_storel_pi(reinterpret_cast<__m64*>(&out[ch][p]), c[ch]);
      _mm_storeh_pi(reinterpret_cast<__m64*>(&out[ch][p + 8]), c[ch]);
#else
      const f32x4 hi = __builtin_shufflevector(c[ch], c[ch], 2, 3, 2, 3);
      std::memcpy(&out[ch][p], &c[ch], 2 * sizeof(float));
      std::memcpy(&out[ch][p + 8], &hi, 2 * sizeof(float));
#endif
    }
  }
}

void shade_block_sse2(const FragCtx& ctx, const FragInputs& in, int bx, int by, uint64_t mask,
                      float (*out)[64]) {
  shade_body(ctx, in, bx, by, mask, out);
}

#if defined(__x86_64__)
[[gnu::target("avx2")]] void shade_block_avx2(const FragCtx& ctx, const FragInputs& in, int bx,
                                              int by, uint64_t mask, float (*out)[64]) {
  shade_body(ctx, in, bx, by, mask, out);
}

#endif

} // namespace

uint64_t shade_block(const FragCtx& ctx, const FragInputs& in, int bx, int by, uint64_t mask,
                     float (*out)[64], uint32_t* depth) {
  if (ctx.shade->program != nullptr) return shade_program_block(ctx, in, bx, by, mask, out, depth);
#if defined(__x86_64__)
  if (use_avx2()) {
    shade_block_avx2(ctx, in, bx, by, mask, out);
    return mask;
  }
#endif
  shade_block_sse2(ctx, in, bx, by, mask, out);
  return mask;
}

} // namespace pineda
