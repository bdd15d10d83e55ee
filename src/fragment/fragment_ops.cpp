// The specialized block loops of the per-fragment operations (GL 2.1 §4.1) and the table
// that selects one per StateKey.
//
// One block loop handles up to 8x8 fragments of one primitive, row by row: depth test and
// depth write for the covered fragments of the row (GL 2.1 §4.1.6), then colour
// (perspective-correct or constant), blending (§4.1.8) and the masked store (§4.2.2) for the
// fragments that survived. Every choice that depends on state is a template parameter; what
// is left at run time are values (blend factors, generic depth function, colour keep mask).
// The scissor test (§4.1.2) costs nothing here: it narrows the clip rectangle the
// rasterizers already respect. The alpha test (§4.1.4), the stencil test (§4.1.5) and the
// logical operation (§4.1.10) live in a second set of instances (template parameter X),
// chosen only when one of them is on, with a per-row branch for each.
#include "fragment/fragment_ops.h"

#include "fragment/blend_simd.h"
#include "fragment/shade.h"
#include "fragment/simd.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <utility>

namespace pineda {
namespace {

constexpr int N = kBlockSize;

// Eight packed pixels of one block row, in the 4-byte format's memory order.
struct Row {
  u32x4 v[2];
};

constexpr f32x4 kLaneLo = {0, 1, 2, 3};
constexpr f32x4 kLaneHi = {4, 5, 6, 7};

// Byte offsets of R, G, B, A inside one stored pixel (framebuffer.h ColorFormat).
template <ColorFormat F> struct Layout;
template <> struct Layout<ColorFormat::RGBA8> {
  static constexpr int r = 0, g = 1, b = 2, a = 3, bpp = 4;
};
template <> struct Layout<ColorFormat::BGRA8> {
  static constexpr int r = 2, g = 1, b = 0, a = 3, bpp = 4;
};
template <> struct Layout<ColorFormat::ARGB8> {
  static constexpr int r = 1, g = 2, b = 3, a = 0, bpp = 4;
};
template <> struct Layout<ColorFormat::RGB8> {
  static constexpr int r = 0, g = 1, b = 2, a = -1, bpp = 3;
};

// Shift of the byte at memory offset `off` within a 4-byte pixel read with memcpy.
constexpr int byte_shift(int off) {
  return std::endian::native == std::endian::little ? 8 * off : 8 * (3 - off);
}

template <ColorFormat F> uint32_t pack_pixel(uint32_t r, uint32_t g, uint32_t b, uint32_t a) {
  using L = Layout<F>;
  return r << byte_shift(L::r) | g << byte_shift(L::g) | b << byte_shift(L::b) |
         a << byte_shift(L::a);
}

template <ColorFormat F> u32x4 pack4(i32x4 r, i32x4 g, i32x4 b, i32x4 a) {
  using L = Layout<F>;
  return reinterpret_cast<u32x4>(r) << byte_shift(L::r) |
         reinterpret_cast<u32x4>(g) << byte_shift(L::g) |
         reinterpret_cast<u32x4>(b) << byte_shift(L::b) |
         reinterpret_cast<u32x4>(a) << byte_shift(L::a);
}

// Clamp to [0,1] and round to 8 bits (GL 2.1 §2.14.9); NaN from a degenerate 1/w gives 0.
inline i32x4 to_unorm8(f32x4 v) {
  const f32x4 zero = {}, one = zero + 1.0f;
  v = vmin(vmax(v, zero), one);
  return __builtin_convertvector(v * 255.0f + 0.5f, i32x4);
}

// One block row of the colours shade_block computed (ShadePath::PerFragment).
template <ColorFormat P> void per_fragment_row(const float (*sc)[64], int j, Row& out) {
  for (int h = 0; h < 2; ++h) {
    f32x4 ch[4];
    for (int c = 0; c < 4; ++c)
      std::memcpy(&ch[c], &sc[c][8 * j + 4 * h], sizeof(f32x4));
    out.v[h] = pack4<P>(to_unorm8(ch[0]), to_unorm8(ch[1]), to_unorm8(ch[2]), to_unorm8(ch[3]));
  }
}

// The colour planes of a smoothly shaded primitive with lane k holding the channel stored at
// byte k of a pixel in the packed format P, and each pixel's offset i * dx from its row's start:
// set up once per block, so that a row is computed pixel by pixel with the four channels in
// one vector and packed with two instructions.
template <ColorFormat P> struct SmoothPlanes {
  f32x4 v0 = {}, dx = {}, dy = {};
  f32x4 step[N] = {};
  // 1/w is exactly 1 everywhere (no perspective, w = 1): then every w below is exactly 1 and
  // dividing and multiplying by it change nothing, so both are skipped.
  bool unit_w = true;

  void init(const FragInputs& in) {
    using L = Layout<P>;
    const int offs[4] = {L::r, L::g, L::b, L::a};
    for (int c = 0; c < 4; ++c) {
      v0[offs[c]] = in.color_w[c].v0;
      dx[offs[c]] = in.color_w[c].dx;
      dy[offs[c]] = in.color_w[c].dy;
    }
    for (int i = 0; i < N; ++i)
      step[i] = static_cast<float>(i) * dx;
    unit_w = in.inv_w.v0 == 1.0f && in.inv_w.dx == 0.0f && in.inv_w.dy == 0.0f;
  }
};

// Perspective-correct colour of one block row (GL 2.1 §3.5.1 eq 3.9): c = (c/w) / (1/w), each
// channel of the pixel at (ox + di + i, oy + dj) computed as ((v0 + di dx + dj dy) + i dx) w.
template <ColorFormat P>
[[gnu::always_inline]] inline void shade_row(const SmoothPlanes<P>& sp, const FragInputs& in,
                                             int di, int dj, Row& out) {
  const float fi = static_cast<float>(di), fj = static_cast<float>(dj);
  const f32x4 cr = sp.v0 + fi * sp.dx + fj * sp.dy;
  i32x4 px[N];
  if (sp.unit_w) {
    for (int i = 0; i < N; ++i)
      px[i] = to_unorm8(cr + sp.step[i]);
  } else {
    const PlaneF iw = in.inv_w;
    const float iwr = iw.v0 + fi * iw.dx + fj * iw.dy;
    const f32x4 w[2] = {1.0f / (iwr + kLaneLo * iw.dx), 1.0f / (iwr + kLaneHi * iw.dx)};
    for (int i = 0; i < N; ++i)
      px[i] = to_unorm8((cr + sp.step[i]) * w[i >> 2][i & 3]);
  }
  out.v[0] = pack_pixels(px[0], px[1], px[2], px[3]);
  out.v[1] = pack_pixels(px[4], px[5], px[6], px[7]);
}

// SRC_ALPHA, ONE_MINUS_SRC_ALPHA, FUNC_ADD in exact unorm8 (blend.h blend_over_channel) in
// 16-bit lanes (blend_simd.h).
template <ColorFormat F> inline void blend_over_row(Row& s, const Row& d) {
  for (int h = 0; h < 2; ++h)
    s.v[h] = blend_over4<Layout<F>::a>(s.v[h], d.v[h]);
}

template <ColorFormat F> void unpack_pixel(uint32_t px, bool has_alpha, uint8_t c[4]) {
  using L = Layout<F>;
  c[0] = static_cast<uint8_t>(px >> byte_shift(L::r));
  c[1] = static_cast<uint8_t>(px >> byte_shift(L::g));
  c[2] = static_cast<uint8_t>(px >> byte_shift(L::b));
  // Without alpha bits, destination alpha reads as 1 (GL 2.1 §4.1.8).
  c[3] = has_alpha ? static_cast<uint8_t>(px >> byte_shift(L::a)) : 255;
}

// Any other blend: factors without the constant colour in 16-bit lanes (blend_simd.h, the
// same bytes as blend_pixel), the others one fragment at a time through blend_pixel (float).
template <ColorFormat F>
void blend_generic_row(const FragCtx& ctx, unsigned m, Row& s, const Row& d) {
  if (ctx.blend_fixed) {
    for (int h = 0; h < 2; ++h)
      s.v[h] = blend_fixed4<Layout<F>::a>(ctx.blend, ctx.key.has_alpha, s.v[h], d.v[h]);
    return;
  }
  alignas(16) uint32_t sp[N], dp[N];
  std::memcpy(sp, &s, sizeof(sp));
  std::memcpy(dp, &d, sizeof(dp));
  for (int i = 0; i < N; ++i) {
    if (((m >> i) & 1u) == 0) continue;
    uint8_t sc[4], dc[4], oc[4];
    unpack_pixel<F>(sp[i], true, sc);
    unpack_pixel<F>(dp[i], ctx.key.has_alpha, dc);
    blend_pixel(ctx.blend, sc, dc, oc);
    sp[i] = pack_pixel<F>(oc[0], oc[1], oc[2], oc[3]);
  }
  std::memcpy(&s, sp, sizeof(sp));
}

// Depth test and write of one row of a block (GL 2.1 §4.1.6). Returns the fragments of `m`
// that passed. z is the plane value in depth-buffer units, clamped to [0, 2^bits - 1] (window
// z clamped to [0,1], GL 2.1 §2.11.1) and rounded to the nearest representable value.
template <DepthPath D>
[[gnu::always_inline]] inline unsigned depth_row(const FragCtx& ctx, const FragInputs& in, int bx,
                                                 int y, int di, int dj, unsigned m) {
  uint32_t* const d = ctx.depth + static_cast<ptrdiff_t>(y) * ctx.depth_stride + bx;
  const PlaneD zp = in.z;
  const double zr = zp.v0 + di * zp.dx + dj * zp.dy;
  const f64x2 zero = {}, zmax = zero + ctx.depth_max;
  f64x2 zc[N / 2];
  for (int h = 0; h < N / 2; ++h) {
    const f64x2 lane = {2.0 * h, 2.0 * h + 1.0};
    const f64x2 z = zr + lane * zp.dx;
    zc[h] = vmin(vmax(z, zero), zmax) + 0.5;
  }
  // The values are non-negative, so truncation is the floor. Below 2^31 the conversion is the
  // packed one (two lanes per instruction on SSE2); 32-bit buffers convert lane by lane.
  u32x4 zv[2] = {};
  if (ctx.depth_max < 2147483648.0) {
    for (int k = 0; k < 2; ++k)
      zv[k] = reinterpret_cast<u32x4>(__builtin_convertvector(
          __builtin_shufflevector(zc[2 * k], zc[2 * k + 1], 0, 1, 2, 3), i32x4));
  } else {
    for (int k = 0; k < 2; ++k)
      for (int l = 0; l < 4; ++l)
        zv[k][l] = static_cast<uint32_t>(static_cast<int64_t>(zc[2 * k + l / 2][l & 1]));
  }
  const bool write = D != DepthPath::Generic || ctx.depth_write;
  if (bx + N <= ctx.fb_width) {
    // The whole row lies in the buffer: test all eight lanes and keep the covered ones.
    u32x4 old[2];
    std::memcpy(old, d, sizeof(old));
    i32x4 pass[2];
    bits_to_lanes(m, pass[0], pass[1]);
    for (int h = 0; h < 2; ++h) {
      if constexpr (D == DepthPath::LessWrite) {
        pass[h] &= zv[h] < old[h];
      } else if constexpr (D == DepthPath::LequalWrite) {
        pass[h] &= zv[h] <= old[h];
      } else {
        const i32x4 f = {}, lt = f - static_cast<int32_t>(ctx.depth_func & 1u);
        const i32x4 eq = f - static_cast<int32_t>((ctx.depth_func >> 1) & 1u);
        const i32x4 gt = f - static_cast<int32_t>((ctx.depth_func >> 2) & 1u);
        pass[h] &= ((zv[h] < old[h]) & lt) | ((zv[h] == old[h]) & eq) | ((zv[h] > old[h]) & gt);
      }
    }
    const unsigned bits = lane_bits(pass[0], pass[1]);
    if (write && bits != 0) {
      for (int h = 0; h < 2; ++h)
        old[h] = pass[h] ? zv[h] : old[h];
      std::memcpy(d, old, sizeof(old));
    }
    return bits;
  }
  // The last block of a row whose width is not a multiple of 8: fragment by fragment.
  unsigned bits = 0;
  for (int i = 0; i < N; ++i) {
    if (((m >> i) & 1u) == 0) continue;
    bool pass;
    if constexpr (D == DepthPath::LessWrite) {
      pass = zv[i >> 2][i & 3] < d[i];
    } else if constexpr (D == DepthPath::LequalWrite) {
      pass = zv[i >> 2][i & 3] <= d[i];
    } else {
      const unsigned rel = zv[i >> 2][i & 3] < d[i] ? 1u : (zv[i >> 2][i & 3] == d[i] ? 2u : 4u);
      pass = (ctx.depth_func & rel) != 0;
    }
    if (pass) {
      bits |= 1u << i;
      if (write) d[i] = zv[i >> 2][i & 3];
    }
  }
  return bits;
}

// Alpha test of one row (GL 2.1 §4.1.4): the fragment alpha as the 8-bit value it would be
// stored as, against the reference converted the same way, which is what llvmpipe compares
// (a float comparison gives different results for alphas within half a step of the
// reference). Returns the fragments of `m` that pass.
template <ColorFormat P> unsigned alpha_row(const FragCtx& ctx, const Row& s, unsigned m) {
  const i32x4 f = {}, ref = f + static_cast<int32_t>(ctx.alpha_ref);
  const i32x4 lt = f - static_cast<int32_t>(ctx.alpha_func & 1u);
  const i32x4 eq = f - static_cast<int32_t>((ctx.alpha_func >> 1) & 1u);
  const i32x4 gt = f - static_cast<int32_t>((ctx.alpha_func >> 2) & 1u);
  i32x4 pass[2];
  for (int h = 0; h < 2; ++h) {
    const i32x4 a = reinterpret_cast<i32x4>((s.v[h] >> byte_shift(Layout<P>::a)) & 0xffu);
    pass[h] = ((a < ref) & lt) | ((a == ref) & eq) | ((a > ref) & gt);
  }
  return m & lane_bits(pass[0], pass[1]);
}

// Stencil test of one row (GL 2.1 §4.1.5), the depth test of the survivors (§4.1.6), and the
// stencil update chosen by the outcome of both: sfail where the stencil test failed, dpfail
// where the depth test failed, dppass where both passed (or the depth test is off, which
// counts as passing). Returns the fragments that passed both tests.
template <DepthPath D>
unsigned stencil_depth_row(const FragCtx& ctx, const FragInputs& in, int bx, int y, int di, int dj,
                           unsigned m) {
  uint8_t* const st = ctx.stencil + static_cast<ptrdiff_t>(y) * ctx.fb_width + bx;
  // Whole rows inside the buffer are loaded and stored as eight bytes; the last block of a
  // row whose width is not a multiple of 8 touches only its fragments.
  const bool whole = bx + N <= ctx.fb_width;
  uint8_t old[N] = {};
  if (whole) {
    std::memcpy(old, st, N);
  } else {
    for (int i = 0; i < N; ++i)
      if ((m >> i) & 1u) old[i] = st[i];
  }
  const i32x4 v[2] = {{old[0], old[1], old[2], old[3]}, {old[4], old[5], old[6], old[7]}};
  const i32x4 zero = {}, vm = zero + ctx.stencil_value_mask, ref = zero + ctx.stencil_ref;
  const i32x4 masked_ref = ref & vm;
  const i32x4 lt = zero - static_cast<int32_t>(ctx.stencil_func & 1u);
  const i32x4 eq = zero - static_cast<int32_t>((ctx.stencil_func >> 1) & 1u);
  const i32x4 gt = zero - static_cast<int32_t>((ctx.stencil_func >> 2) & 1u);
  i32x4 pass[2];
  for (int h = 0; h < 2; ++h) {
    const i32x4 sv = v[h] & vm;
    pass[h] = ((masked_ref < sv) & lt) | ((masked_ref == sv) & eq) | ((masked_ref > sv) & gt);
  }
  const unsigned spass = m & lane_bits(pass[0], pass[1]);
  unsigned zpass = spass;
  if constexpr (D != DepthPath::Off)
    zpass = spass != 0 ? depth_row<D>(ctx, in, bx, y, di, dj, spass) : 0;
  if (ctx.stencil_write_mask == 0) return zpass;
  const i32x4 wm = zero + ctx.stencil_write_mask;
  i32x4 sfail[2], dpfail[2], dppass[2];
  bits_to_lanes(m & ~spass, sfail[0], sfail[1]);
  bits_to_lanes(spass & ~zpass, dpfail[0], dpfail[1]);
  bits_to_lanes(zpass, dppass[0], dppass[1]);
  uint8_t out[N];
  for (int h = 0; h < 2; ++h) {
    const i32x4 keep = ~(sfail[h] | dpfail[h] | dppass[h]);
    const i32x4 nv = (stencil_op_lanes(ctx.stencil_ops[0], v[h], ref) & sfail[h]) |
                     (stencil_op_lanes(ctx.stencil_ops[1], v[h], ref) & dpfail[h]) |
                     (stencil_op_lanes(ctx.stencil_ops[2], v[h], ref) & dppass[h]) | (v[h] & keep);
    const i32x4 w = (v[h] & ~wm) | (nv & wm);
    for (int k = 0; k < 4; ++k)
      out[4 * h + k] = static_cast<uint8_t>(w[k]);
  }
  if (whole) {
    std::memcpy(st, out, N);
  } else {
    for (int i = 0; i < N; ++i)
      if ((m >> i) & 1u) st[i] = out[i];
  }
  return zpass;
}

// Blend or logical operation, then colour mask, of source row `s` against destination `dst`
// (GL 2.1 §4.1.8, §4.1.10, §4.2.2); the result is left in `s`.
template <ColorFormat F, ColorPath C, BlendPath B>
[[gnu::always_inline]] inline void combine_row4(const FragCtx& ctx, unsigned m, bool logic, Row& s,
                                                const Row& dst) {
  if constexpr (B == BlendPath::Over)
    blend_over_row<F>(s, dst);
  else if constexpr (B == BlendPath::Generic)
    blend_generic_row<F>(ctx, m, s, dst);
  if (logic)
    for (int h = 0; h < 2; ++h)
      s.v[h] = apply_logic(ctx.logic, s.v[h], dst.v[h]);
  if constexpr (C == ColorPath::Partial) {
    const u32x4 keep = u32x4{} + ctx.color_keep;
    for (int h = 0; h < 2; ++h)
      s.v[h] = (dst.v[h] & keep) | (s.v[h] & ~keep);
  }
}

// Blend, colour mask and store of one row of a 4-byte format (GL 2.1 §4.1.8, §4.2.2). Full
// rows load and store the eight pixels whole; others touch only their fragments.
template <ColorFormat F, ColorPath C, BlendPath B, bool X>
[[gnu::always_inline]] inline void write_row4(const FragCtx& ctx, uint8_t* row, unsigned m,
                                              bool in_buffer, Row& s) {
  constexpr bool kReadsDst = B != BlendPath::Off || C == ColorPath::Partial;
  // GL 2.1 §4.1.10: the logical operation takes blending's place (the key has blend off).
  const bool logic = X && ctx.key.logic_op;
  const bool reads_dst = kReadsDst || logic;
  if (m == 0xffu && !reads_dst) {
    std::memcpy(row, &s, sizeof(s));
    return;
  }
  if (in_buffer) {
    // The whole row lies in the buffer: compute all eight lanes and select the covered ones.
    Row dst;
    std::memcpy(&dst, row, sizeof(dst));
    combine_row4<F, C, B>(ctx, m, logic, s, dst);
    if (m == 0xffu) {
      std::memcpy(row, &s, sizeof(s));
      return;
    }
    i32x4 lanes[2];
    bits_to_lanes(m, lanes[0], lanes[1]);
    for (int h = 0; h < 2; ++h)
      dst.v[h] = lanes[h] ? s.v[h] : dst.v[h];
    std::memcpy(row, &dst, sizeof(dst));
    return;
  }
  // The last block of a row whose width is not a multiple of 8: fragment by fragment.
  Row dst;
  alignas(16) uint32_t tmp[N] = {};
  if (reads_dst) {
    for (int i = 0; i < N; ++i)
      if ((m >> i) & 1u) std::memcpy(&tmp[i], row + 4 * i, 4);
  }
  std::memcpy(&dst, tmp, sizeof(dst));
  combine_row4<F, C, B>(ctx, m, logic, s, dst);
  std::memcpy(tmp, &s, sizeof(tmp));
  for (int i = 0; i < N; ++i)
    if ((m >> i) & 1u) std::memcpy(row + 4 * i, &tmp[i], 4);
}

// The same for 3-byte RGB8 pixels, one fragment at a time; `s` is packed as RGBA8.
template <ColorPath C, BlendPath B, bool X>
void write_row3(const FragCtx& ctx, uint8_t* row, unsigned m, const Row& s) {
  alignas(16) uint32_t sp[N];
  std::memcpy(sp, &s, sizeof(sp));
  uint8_t keep[4];
  std::memcpy(keep, &ctx.color_keep, 4);
  for (int i = 0; i < N; ++i) {
    if (((m >> i) & 1u) == 0) continue;
    uint8_t* p = row + 3 * i;
    uint8_t c[4];
    unpack_pixel<ColorFormat::RGBA8>(sp[i], true, c);
    if constexpr (B != BlendPath::Off) {
      const uint8_t d[4] = {p[0], p[1], p[2], 255}; // no alpha: destination alpha is 1
      if constexpr (B == BlendPath::Over) {
        for (int k = 0; k < 3; ++k)
          c[k] = blend_over_channel(c[k], d[k], c[3]);
      } else {
        uint8_t o[4];
        blend_pixel(ctx.blend, c, d, o);
        std::memcpy(c, o, 4);
      }
    }
    if (X && ctx.key.logic_op) {
      const uint32_t src = c[0] | (c[1] << 8) | (c[2] << 16);
      const uint32_t dst = p[0] | (p[1] << 8) | (p[2] << 16);
      const uint32_t out = apply_logic(ctx.logic, src, dst);
      for (int k = 0; k < 3; ++k)
        c[k] = static_cast<uint8_t>(out >> (8 * k));
    }
    for (int k = 0; k < 3; ++k)
      p[k] = C == ColorPath::Partial ? static_cast<uint8_t>((p[k] & keep[k]) | (c[k] & ~keep[k]))
                                     : c[k];
  }
}

// X selects the extended instances: alpha test (§4.1.4) before the stencil and depth tests
// (§4.1.5, §4.1.6), and the logical operation (§4.1.10) in place of blending, each behind a
// per-row branch on the key. Without X none of that code exists in the instance.
template <DepthPath D, ColorFormat F, ColorPath C, BlendPath B, ShadePath S, bool X>
void block_loop(const FragCtx& ctx, const FragInputs& in, int bx, int by, uint64_t mask) {
  using L = Layout<F>;
  // Pixels travel packed in the format's byte order; RGB8 rows are packed as RGBA8.
  constexpr ColorFormat P = L::bpp == 4 ? F : ColorFormat::RGBA8;
  [[maybe_unused]] Row const_row{};
  [[maybe_unused]] SmoothPlanes<P> smooth;
  if constexpr (S == ShadePath::Smooth) smooth.init(in);
  if constexpr (S == ShadePath::Const) {
    const uint32_t px =
        pack_pixel<P>(in.const_color[0], in.const_color[1], in.const_color[2], in.const_color[3]);
    const_row.v[0] = const_row.v[1] = u32x4{} + px;
  }
  // Texturing and fog: the whole block's colours first (fragment/shade.cpp), which writes every
  // row that holds a fragment of `mask`, the only rows read below.
  [[maybe_unused]] alignas(16) float shaded_block[4][64];
  if constexpr (S == ShadePath::PerFragment) shade_block(ctx, in, bx, by, mask, shaded_block);
  while (mask != 0) {
    const int j = std::countr_zero(mask) >> 3;
    unsigned m = static_cast<unsigned>(mask >> (8 * j)) & 0xffu;
    mask &= ~(0xffull << (8 * j));
    const int y = by + j;
    const int di = bx - in.ox, dj = y - in.oy;
    Row s;
    bool shaded = false;
    if constexpr (X) {
      if (ctx.key.alpha_test) {
        if constexpr (S == ShadePath::Const)
          s = const_row;
        else if constexpr (S == ShadePath::PerFragment)
          per_fragment_row<P>(shaded_block, j, s);
        else
          shade_row<P>(smooth, in, di, dj, s);
        shaded = true;
        m = alpha_row<P>(ctx, s, m);
        if (m == 0) continue;
      }
      if (ctx.key.stencil_test) {
        m = stencil_depth_row<D>(ctx, in, bx, y, di, dj, m);
        if (m == 0) continue;
      } else if constexpr (D != DepthPath::Off) {
        m = depth_row<D>(ctx, in, bx, y, di, dj, m);
        if (m == 0) continue;
      }
    } else if constexpr (D != DepthPath::Off) {
      m = depth_row<D>(ctx, in, bx, y, di, dj, m);
      if (m == 0) continue;
    }
    // §4.1.7: SAMPLES_PASSED counts what survived the stencil and depth tests.
    if constexpr (X)
      if (ctx.key.count_samples) ctx.samples_passed += static_cast<unsigned>(std::popcount(m));
    if constexpr (C != ColorPath::None) {
      uint8_t* const row = ctx.color + static_cast<ptrdiff_t>(y) * ctx.color_stride +
                           static_cast<ptrdiff_t>(bx) * L::bpp;
      if (!shaded) {
        if constexpr (S == ShadePath::Const)
          s = const_row;
        else if constexpr (S == ShadePath::PerFragment)
          per_fragment_row<P>(shaded_block, j, s);
        else
          shade_row<P>(smooth, in, di, dj, s);
      }
      if constexpr (L::bpp == 4)
        write_row4<F, C, B, X>(ctx, row, m, bx + N <= ctx.fb_width, s);
      else
        write_row3<C, B, X>(ctx, row, m, s);
    }
  }
}

void noop_block(const FragCtx&, const FragInputs&, int, int, uint64_t) {}

// Table of colour-writing instances, index
//   (((depth * formats + format) * 2 + (partial ? 1 : 0)) * blends + blend) * shades + shade.
constexpr int kColorInstances =
    kDepthPathCount * kColorFormatCount * 2 * kBlendPathCount * kShadePathCount;

constexpr int color_index(DepthPath d, ColorFormat f, ColorPath c, BlendPath b, ShadePath s) {
  return (((static_cast<int>(d) * kColorFormatCount + static_cast<int>(f)) * 2 +
           (c == ColorPath::Partial ? 1 : 0)) *
              kBlendPathCount +
          static_cast<int>(b)) *
             kShadePathCount +
         static_cast<int>(s);
}

template <int I, bool X> constexpr BlockFn color_entry() {
  constexpr auto s = static_cast<ShadePath>(I % kShadePathCount);
  constexpr auto b = static_cast<BlendPath>((I / kShadePathCount) % kBlendPathCount);
  constexpr int rest = I / (kShadePathCount * kBlendPathCount);
  constexpr auto c = (rest % 2) ? ColorPath::Partial : ColorPath::All;
  constexpr auto f = static_cast<ColorFormat>((rest / 2) % kColorFormatCount);
  constexpr auto d = static_cast<DepthPath>(rest / (2 * kColorFormatCount));
  static_assert(color_index(d, f, c, b, s) == I);
  // The extended instances run every depth function through the generic path, which keeps
  // their number down: all depth rows but Off name the one Generic instance.
  constexpr DepthPath dx = (X && d != DepthPath::Off) ? DepthPath::Generic : d;
  return &block_loop<dx, f, c, b, s, X>;
}

template <bool X, size_t... I>
constexpr std::array<BlockFn, sizeof...(I)> make_color_table(std::index_sequence<I...>) {
  return {color_entry<static_cast<int>(I), X>()...};
}

constexpr std::array<BlockFn, kColorInstances> kColorTable =
    make_color_table<false>(std::make_index_sequence<kColorInstances>{});

constexpr std::array<BlockFn, kColorInstances> kExtColorTable =
    make_color_table<true>(std::make_index_sequence<kColorInstances>{});

// Depth-only instances of the extended loop: the shade path matters for the alpha test.
constexpr std::array<BlockFn, 2 * kShadePathCount> kExtDepthOnlyTable = {
    &block_loop<DepthPath::Off, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Const, true>,
    &block_loop<DepthPath::Off, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Smooth, true>,
    &block_loop<DepthPath::Off, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::PerFragment, true>,
    &block_loop<DepthPath::Generic, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Const, true>,
    &block_loop<DepthPath::Generic, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Smooth, true>,
    &block_loop<DepthPath::Generic, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::PerFragment, true>,
};

// Depth-only instances (colour mask all false or no colour buffer); the other template
// parameters do not matter there.
constexpr std::array<BlockFn, kDepthPathCount> kDepthOnlyTable = {
    &noop_block,
    &block_loop<DepthPath::LessWrite, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Const, false>,
    &block_loop<DepthPath::LequalWrite, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Const, false>,
    &block_loop<DepthPath::Generic, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Const, false>,
};

// Memory-order mask of the bytes a partial colour mask keeps (GL 2.1 §4.2.2).
template <ColorFormat F> uint32_t keep_mask(uint8_t written) {
  using L = Layout<F>;
  uint8_t bytes[4] = {0, 0, 0, 0};
  const int off[4] = {L::r, L::g, L::b, L::a};
  for (int k = 0; k < 4; ++k)
    if (off[k] >= 0 && !(written & (1u << k))) bytes[off[k]] = 0xff;
  if constexpr (L::bpp == 3) bytes[3] = 0xff;
  uint32_t v;
  std::memcpy(&v, bytes, 4);
  return v;
}

// Values of the alpha test, stencil test and logical operation (only when the key has one).
void prepare_ext(const RasterState& rs, const Framebuffer& fb, FragCtx& ctx) {
  const StateKey& k = ctx.key;
  if (k.alpha_test) {
    ctx.alpha_func = depth_func_bits(rs.alpha_func);
    ctx.alpha_ref = color_to_unorm8(rs.alpha_ref);
  }
  if (k.stencil_test) {
    ctx.stencil = fb.stencil;
    ctx.stencil_func = depth_func_bits(rs.stencil_func);
    // GL 2.1 §4.1.5: the reference is clamped to [0, 2^s - 1]; masks use the low s bits.
    ctx.stencil_ref = static_cast<uint8_t>(std::clamp(rs.stencil_ref, 0, 255));
    ctx.stencil_value_mask = static_cast<uint8_t>(rs.stencil_value_mask & 0xffu);
    ctx.stencil_write_mask = static_cast<uint8_t>(rs.stencil_writemask & 0xffu);
    ctx.stencil_ops[0] = stencil_op_from_gl(rs.stencil_fail);
    ctx.stencil_ops[1] = stencil_op_from_gl(rs.stencil_depth_fail);
    ctx.stencil_ops[2] = stencil_op_from_gl(rs.stencil_depth_pass);
  }
  if (k.logic_op) ctx.logic = logic_masks(rs.logic_op_mode);
}

} // namespace

BlockFn select_block_fn(const StateKey& key, ShadePath shade) {
  const ColorPath c = key.color_path();
  if (key.ext()) {
    const DepthPath d = key.depth_test ? DepthPath::Generic : DepthPath::Off;
    if (c == ColorPath::None)
      return kExtDepthOnlyTable[(d == DepthPath::Generic ? kShadePathCount : 0) +
                                static_cast<int>(shade)];
    return kExtColorTable[color_index(d, key.format, c, key.blend_path(), shade)];
  }
  if (c == ColorPath::None) return kDepthOnlyTable[static_cast<int>(key.depth_path())];
  return kColorTable[color_index(key.depth_path(), key.format, c, key.blend_path(), shade)];
}

void prepare_fragments(const RasterState& rs, const Framebuffer& fb, FragCtx& ctx) {
  ctx.key = make_state_key(rs, fb);
  const StateKey& k = ctx.key;
  ctx.color = fb.color;
  ctx.color_stride = fb.color_stride;
  ctx.depth = fb.depth;
  ctx.depth_stride = fb.width;
  ctx.depth_max = fb.depth_bits >= 32 ? 4294967295.0 : static_cast<double>(fb.depth_max());
  ctx.depth_func = k.depth_func;
  ctx.depth_write = k.depth_write;
  switch (k.format) {
  case ColorFormat::RGBA8:
    ctx.color_keep = keep_mask<ColorFormat::RGBA8>(k.color_mask);
    break;
  case ColorFormat::BGRA8:
    ctx.color_keep = keep_mask<ColorFormat::BGRA8>(k.color_mask);
    break;
  case ColorFormat::ARGB8:
    ctx.color_keep = keep_mask<ColorFormat::ARGB8>(k.color_mask);
    break;
  case ColorFormat::RGB8:
    ctx.color_keep = keep_mask<ColorFormat::RGB8>(k.color_mask);
    break;
  }
  if (k.blend) {
    ctx.blend = make_blend_params(rs);
    ctx.blend_fixed = blend_params_fixed(ctx.blend);
  }
  if (k.ext()) prepare_ext(rs, fb, ctx);
  ctx.fb_width = fb.width;
  ctx.clip_x0 = 0;
  ctx.clip_y0 = 0;
  ctx.clip_x1 = fb.width - 1;
  ctx.clip_y1 = fb.height - 1;
  if (rs.scissor_test) {
    // GL 2.1 §4.1.2: x in [left, left + width), y in [bottom, bottom + height); 64-bit ends
    // so that left + width cannot overflow.
    const int64_t x1 = int64_t{rs.scissor[0]} + rs.scissor[2] - 1;
    const int64_t y1 = int64_t{rs.scissor[1]} + rs.scissor[3] - 1;
    ctx.clip_x0 = std::max(ctx.clip_x0, rs.scissor[0]);
    ctx.clip_y0 = std::max(ctx.clip_y0, rs.scissor[1]);
    ctx.clip_x1 = static_cast<int>(std::min<int64_t>(ctx.clip_x1, x1));
    ctx.clip_y1 = static_cast<int>(std::min<int64_t>(ctx.clip_y1, y1));
  }
  ctx.needs_color = k.color_path() != ColorPath::None || k.alpha_test;
  ctx.shade = ctx.needs_color ? rs.shade : nullptr;
  ctx.needs_depth = k.depth_test;
  ctx.noop = (!ctx.needs_color && !ctx.needs_depth && !k.stencil_test && !k.count_samples) ||
             ctx.clip_x0 > ctx.clip_x1 || ctx.clip_y0 > ctx.clip_y1;
  for (int s = 0; s < kShadePathCount; ++s)
    ctx.fn[s] = select_block_fn(k, static_cast<ShadePath>(s));
}

} // namespace pineda
