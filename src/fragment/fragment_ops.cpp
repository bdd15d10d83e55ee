// The specialized block loops of the per-fragment operations (GL 2.1 §4.1) and the table
// that selects one per StateKey.
//
// One block loop handles up to 8x8 fragments of one primitive, row by row: depth test and
// depth write for the covered fragments of the row (GL 2.1 §4.1.6), then colour
// (perspective-correct or constant), blending (§4.1.8) and the masked store (§4.2.2) for the
// fragments that survived. Every choice that depends on state is a template parameter; what
// is left at run time are values (blend factors, generic depth function, colour keep mask).
#include "fragment/fragment_ops.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <utility>

namespace pineda {
namespace {

constexpr int N = kBlockSize;

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

// One block row of colours, channel-major so that loops over lanes vectorize.
struct Lanes {
  alignas(32) int32_t c[4][N];
};

// round(x / 255) for the blend numerators below (x <= 255*255 + 127): exact division by 255
// as shifts and adds, valid for x < 65535.
inline int32_t div255(int32_t x) { return (x + 1 + (x >> 8)) >> 8; }

// Perspective-correct colour of one block row (GL 2.1 §3.5.1 eq 3.9): c = (c/w) / (1/w),
// clamped to [0,1] and rounded to 8 bits (GL 2.1 §2.14.9). NaN (a degenerate 1/w) clamps to 0.
inline void shade_lanes(const FragInputs& in, int di, int dj, Lanes& out) {
  const PlaneF iw = in.inv_w;
  float w[N];
  const float iwr = iw.v0 + static_cast<float>(di) * iw.dx + static_cast<float>(dj) * iw.dy;
  for (int i = 0; i < N; ++i) w[i] = 1.0f / (iwr + static_cast<float>(i) * iw.dx);
  for (int k = 0; k < 4; ++k) {
    const PlaneF p = in.color_w[k];
    const float cr = p.v0 + static_cast<float>(di) * p.dx + static_cast<float>(dj) * p.dy;
    for (int i = 0; i < N; ++i) {
      float v = (cr + static_cast<float>(i) * p.dx) * w[i];
      v = std::min(std::max(0.0f, v), 1.0f);
      out.c[k][i] = static_cast<int32_t>(v * 255.0f + 0.5f);
    }
  }
}

inline void const_lanes(const uint8_t c[4], Lanes& out) {
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < N; ++i) out.c[k][i] = c[k];
}

template <ColorFormat F> inline uint32_t pack_pixel(uint32_t r, uint32_t g, uint32_t b, uint32_t a) {
  using L = Layout<F>;
  return r << byte_shift(L::r) | g << byte_shift(L::g) | b << byte_shift(L::b) |
         a << byte_shift(L::a);
}

template <ColorFormat F> inline void pack_lanes(const Lanes& l, uint32_t px[N]) {
  for (int i = 0; i < N; ++i)
    px[i] = pack_pixel<F>(static_cast<uint32_t>(l.c[0][i]), static_cast<uint32_t>(l.c[1][i]),
                          static_cast<uint32_t>(l.c[2][i]), static_cast<uint32_t>(l.c[3][i]));
}

// Stored pixels to lanes; without alpha bits destination alpha reads as 255 (GL 2.1 §4.1.8).
template <ColorFormat F> inline void unpack_lanes(const uint32_t px[N], bool has_alpha, Lanes& l) {
  using L = Layout<F>;
  const uint32_t amask = has_alpha ? 0u : 0xffu;
  for (int i = 0; i < N; ++i) {
    l.c[0][i] = static_cast<int32_t>((px[i] >> byte_shift(L::r)) & 0xffu);
    l.c[1][i] = static_cast<int32_t>((px[i] >> byte_shift(L::g)) & 0xffu);
    l.c[2][i] = static_cast<int32_t>((px[i] >> byte_shift(L::b)) & 0xffu);
    l.c[3][i] = static_cast<int32_t>(((px[i] >> byte_shift(L::a)) & 0xffu) | amask);
  }
}

// SRC_ALPHA, ONE_MINUS_SRC_ALPHA, FUNC_ADD in exact unorm8 (blend.h blend_over_channel).
inline void blend_over_lanes(Lanes& s, const Lanes& d) {
  int32_t a[N];
  for (int i = 0; i < N; ++i) a[i] = s.c[3][i];
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < N; ++i)
      s.c[k][i] = div255(s.c[k][i] * a[i] + d.c[k][i] * (255 - a[i]) + 127);
}

inline void blend_generic_lanes(const BlendParams& bp, unsigned m, Lanes& s, const Lanes& d) {
  for (int i = 0; i < N; ++i) {
    if (((m >> i) & 1u) == 0) continue;
    uint8_t sp[4], dp[4], op[4];
    for (int k = 0; k < 4; ++k) {
      sp[k] = static_cast<uint8_t>(s.c[k][i]);
      dp[k] = static_cast<uint8_t>(d.c[k][i]);
    }
    blend_pixel(bp, sp, dp, op);
    for (int k = 0; k < 4; ++k) s.c[k][i] = op[k];
  }
}

// Depth test and write of one row of a block (GL 2.1 §4.1.6). Returns the fragments of `m`
// that passed. z is the plane value in depth-buffer units, clamped to [0, 2^bits - 1] (window
// z clamped to [0,1], GL 2.1 §2.11.1) and rounded to the nearest representable value.
template <DepthPath D> inline bool depth_pass(const FragCtx& ctx, uint32_t z, uint32_t old) {
  if constexpr (D == DepthPath::LessWrite) {
    return z < old;
  } else if constexpr (D == DepthPath::LequalWrite) {
    return z <= old;
  } else {
    const unsigned rel = z < old ? 1u : (z == old ? 2u : 4u);
    return (ctx.depth_func & rel) != 0;
  }
}

template <DepthPath D>
inline unsigned depth_row(const FragCtx& ctx, const FragInputs& in, int bx, int y, int di,
                          int dj, unsigned m) {
  uint32_t* const d = ctx.depth + static_cast<ptrdiff_t>(y) * ctx.depth_stride + bx;
  const PlaneD zp = in.z;
  const double zr = zp.v0 + di * zp.dx + dj * zp.dy;
  const double zmax = ctx.depth_max;
  const bool write = D != DepthPath::Generic || ctx.depth_write;
  uint32_t zq[N];
  for (int i = 0; i < N; ++i) {
    const double z = std::min(std::max(0.0, zr + i * zp.dx), zmax);
    zq[i] = static_cast<uint32_t>(static_cast<int64_t>(z + 0.5));
  }
  unsigned pass = 0;
  if (m == 0xffu) {
    uint32_t old[N];
    std::memcpy(old, d, sizeof(old));
    for (int i = 0; i < N; ++i) pass |= static_cast<unsigned>(depth_pass<D>(ctx, zq[i], old[i])) << i;
    if (write && pass != 0) {
      for (int i = 0; i < N; ++i) old[i] = ((pass >> i) & 1u) ? zq[i] : old[i];
      std::memcpy(d, old, sizeof(old));
    }
    return pass;
  }
  for (int i = 0; i < N; ++i) {
    if (((m >> i) & 1u) == 0) continue;
    if (depth_pass<D>(ctx, zq[i], d[i])) {
      pass |= 1u << i;
      if (write) d[i] = zq[i];
    }
  }
  return pass;
}

// Blend, colour mask and store of one row of a 4-byte format (GL 2.1 §4.1.8, §4.2.2).
// Full rows (all eight fragments) load and store the row whole.
template <ColorFormat F, ColorPath C, BlendPath B>
inline void write_row4(const FragCtx& ctx, uint8_t* row, unsigned m, Lanes& s) {
  const bool full = m == 0xffu;
  uint32_t px[N];
  if constexpr (B != BlendPath::Off || C == ColorPath::Partial) {
    uint32_t dst[N];
    if (full) {
      std::memcpy(dst, row, sizeof(dst));
    } else {
      for (int i = 0; i < N; ++i) {
        dst[i] = 0;
        if ((m >> i) & 1u) std::memcpy(&dst[i], row + 4 * i, 4);
      }
    }
    if constexpr (B != BlendPath::Off) {
      Lanes d;
      unpack_lanes<F>(dst, ctx.key.has_alpha, d);
      if constexpr (B == BlendPath::Over)
        blend_over_lanes(s, d);
      else
        blend_generic_lanes(ctx.blend, m, s, d);
    }
    pack_lanes<F>(s, px);
    if constexpr (C == ColorPath::Partial) {
      const uint32_t keep = ctx.color_keep;
      for (int i = 0; i < N; ++i) px[i] = (dst[i] & keep) | (px[i] & ~keep);
    }
  } else {
    pack_lanes<F>(s, px);
  }
  if (full) {
    std::memcpy(row, px, sizeof(px));
  } else {
    for (int i = 0; i < N; ++i)
      if ((m >> i) & 1u) std::memcpy(row + 4 * i, &px[i], 4);
  }
}

// The same for 3-byte RGB8 pixels, one fragment at a time.
template <ColorPath C, BlendPath B>
inline void write_row3(const FragCtx& ctx, uint8_t* row, unsigned m, Lanes& s) {
  if constexpr (B != BlendPath::Off) {
    Lanes d;
    for (int i = 0; i < N; ++i) {
      const uint8_t* p = row + 3 * i;
      const bool on = (m >> i) & 1u;
      for (int k = 0; k < 3; ++k) d.c[k][i] = on ? p[k] : 0;
      d.c[3][i] = 255;
    }
    if constexpr (B == BlendPath::Over)
      blend_over_lanes(s, d);
    else
      blend_generic_lanes(ctx.blend, m, s, d);
  }
  uint8_t keep[4];
  std::memcpy(keep, &ctx.color_keep, 4);
  for (int i = 0; i < N; ++i) {
    if (((m >> i) & 1u) == 0) continue;
    uint8_t* p = row + 3 * i;
    for (int k = 0; k < 3; ++k) {
      const auto v = static_cast<uint8_t>(s.c[k][i]);
      p[k] = C == ColorPath::Partial ? static_cast<uint8_t>((p[k] & keep[k]) | (v & ~keep[k])) : v;
    }
  }
}

template <DepthPath D, ColorFormat F, ColorPath C, BlendPath B, ShadePath S>
void block_loop(const FragCtx& ctx, const FragInputs& in, int bx, int by, uint64_t mask) {
  using L = Layout<F>;
  // A constant colour with a plain store is one packed value for the whole block.
  [[maybe_unused]] uint32_t const_px = 0;
  if constexpr (S == ShadePath::Const && L::bpp == 4)
    const_px = pack_pixel<F>(in.const_color[0], in.const_color[1], in.const_color[2],
                             in.const_color[3]);
  while (mask != 0) {
    const int j = std::countr_zero(mask) >> 3;
    unsigned m = static_cast<unsigned>(mask >> (8 * j)) & 0xffu;
    mask &= ~(0xffull << (8 * j));
    const int y = by + j;
    const int di = bx - in.ox, dj = y - in.oy;
    if constexpr (D != DepthPath::Off) {
      m = depth_row<D>(ctx, in, bx, y, di, dj, m);
      if (m == 0) continue;
    }
    if constexpr (C != ColorPath::None) {
      uint8_t* const row = ctx.color + static_cast<ptrdiff_t>(y) * ctx.color_stride +
                           static_cast<ptrdiff_t>(bx) * L::bpp;
      if constexpr (S == ShadePath::Const && L::bpp == 4 && B == BlendPath::Off &&
                    C == ColorPath::All) {
        if (m == 0xffu) {
          uint32_t px[N];
          for (int i = 0; i < N; ++i) px[i] = const_px;
          std::memcpy(row, px, sizeof(px));
        } else {
          for (int i = 0; i < N; ++i)
            if ((m >> i) & 1u) std::memcpy(row + 4 * i, &const_px, 4);
        }
      } else {
        Lanes s;
        if constexpr (S == ShadePath::Const)
          const_lanes(in.const_color, s);
        else
          shade_lanes(in, di, dj, s);
        if constexpr (L::bpp == 4)
          write_row4<F, C, B>(ctx, row, m, s);
        else
          write_row3<C, B>(ctx, row, m, s);
      }
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
           (c == ColorPath::Partial ? 1 : 0)) * kBlendPathCount + static_cast<int>(b)) *
             kShadePathCount + static_cast<int>(s);
}

template <int I> constexpr BlockFn color_entry() {
  constexpr auto s = static_cast<ShadePath>(I % kShadePathCount);
  constexpr auto b = static_cast<BlendPath>((I / kShadePathCount) % kBlendPathCount);
  constexpr int rest = I / (kShadePathCount * kBlendPathCount);
  constexpr auto c = (rest % 2) ? ColorPath::Partial : ColorPath::All;
  constexpr auto f = static_cast<ColorFormat>((rest / 2) % kColorFormatCount);
  constexpr auto d = static_cast<DepthPath>(rest / (2 * kColorFormatCount));
  static_assert(color_index(d, f, c, b, s) == I);
  return &block_loop<d, f, c, b, s>;
}

template <size_t... I>
constexpr std::array<BlockFn, sizeof...(I)> make_color_table(std::index_sequence<I...>) {
  return {color_entry<static_cast<int>(I)>()...};
}

constexpr std::array<BlockFn, kColorInstances> kColorTable =
    make_color_table(std::make_index_sequence<kColorInstances>{});

// Depth-only instances (colour mask all false or no colour buffer); the other template
// parameters do not matter there.
constexpr std::array<BlockFn, kDepthPathCount> kDepthOnlyTable = {
    &noop_block,
    &block_loop<DepthPath::LessWrite, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Const>,
    &block_loop<DepthPath::LequalWrite, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Const>,
    &block_loop<DepthPath::Generic, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Const>,
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

} // namespace

BlockFn select_block_fn(const StateKey& key, ShadePath shade) {
  const ColorPath c = key.color_path();
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
  case ColorFormat::RGBA8: ctx.color_keep = keep_mask<ColorFormat::RGBA8>(k.color_mask); break;
  case ColorFormat::BGRA8: ctx.color_keep = keep_mask<ColorFormat::BGRA8>(k.color_mask); break;
  case ColorFormat::ARGB8: ctx.color_keep = keep_mask<ColorFormat::ARGB8>(k.color_mask); break;
  case ColorFormat::RGB8: ctx.color_keep = keep_mask<ColorFormat::RGB8>(k.color_mask); break;
  }
  if (k.blend) ctx.blend = make_blend_params(rs);
  ctx.clip_x0 = 0;
  ctx.clip_y0 = 0;
  ctx.clip_x1 = fb.width - 1;
  ctx.clip_y1 = fb.height - 1;
  ctx.needs_color = k.color_path() != ColorPath::None;
  ctx.needs_depth = k.depth_test;
  ctx.noop = (!ctx.needs_color && !ctx.needs_depth) || fb.width <= 0 || fb.height <= 0;
  for (int s = 0; s < kShadePathCount; ++s)
    ctx.fn[s] = select_block_fn(k, static_cast<ShadePath>(s));
}

} // namespace pineda
