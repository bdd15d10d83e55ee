// The per-fragment operations' set-up for a draw (prepare_fragments) and the choice of the
// block loop instance for a state key. The block loops themselves are in block_loop_impl.h,
// compiled here for the baseline instruction set, in fragment_ops_avx2.cpp for AVX2 and in
// fragment_ops_avx512.cpp for AVX-512.
#include "fragment/fragment_ops.h"

#include "fragment/blend_simd.h"
#include "fragment/shade.h"
#include "core/simd.h"
#include "core/simd_level.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <utility>

#define PINEDA_BLOCK_AVX2 0
#include "fragment/block_loop_impl.h"

namespace pineda {
namespace {

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
    const StencilFace* faces[2] = {&rs.stencil, &rs.stencil_back};
    for (int i = 0; i < 2; ++i) {
      const StencilFace& f = *faces[i];
      StencilSide& side = ctx.stencil_side[i];
      side.func = depth_func_bits(f.func);
      // GL 2.1 §4.1.5: the reference is clamped to [0, 2^s - 1]; masks use the low s bits.
      side.ref = static_cast<uint8_t>(std::clamp(f.ref, 0, 255));
      side.value_mask = static_cast<uint8_t>(f.value_mask & 0xffu);
      side.write_mask = static_cast<uint8_t>(f.writemask & 0xffu);
      side.ops[0] = stencil_op_from_gl(f.fail);
      side.ops[1] = stencil_op_from_gl(f.depth_fail);
      side.ops[2] = stencil_op_from_gl(f.depth_pass);
    }
  }
  if (k.logic_op) ctx.logic = logic_masks(rs.logic_op_mode);
}

} // namespace

namespace {

// Colour writers of the further draw buffers (FragCtx::more), index
//   ((format * 2 + (partial ? 1 : 0)) * blends + blend) * 2 + (logic op ? 1 : 0).
// Baseline instances only: every instruction set writes the same bytes.
constexpr int kWriterCount = kColorFormatCount * 2 * kBlendPathCount * 2;

template <int I> constexpr ColorWriteFn writer_entry() {
  constexpr bool x = (I % 2) != 0;
  constexpr auto b = static_cast<BlendPath>((I / 2) % kBlendPathCount);
  constexpr auto c = ((I / (2 * kBlendPathCount)) % 2) ? ColorPath::Partial : ColorPath::All;
  constexpr auto f = static_cast<ColorFormat>(I / (4 * kBlendPathCount));
  return &write_colors<f, c, b, x>;
}

template <size_t... I>
constexpr std::array<ColorWriteFn, sizeof...(I)> make_writer_table(std::index_sequence<I...>) {
  return {writer_entry<static_cast<int>(I)>()...};
}

constexpr std::array<ColorWriteFn, kWriterCount> kWriterTable =
    make_writer_table(std::make_index_sequence<kWriterCount>{});

} // namespace

ColorWriteFn select_color_writer(const StateKey& key) {
  const ColorPath c = key.color_path();
  if (c == ColorPath::None) return nullptr;
  const int i =
      ((static_cast<int>(key.format) * 2 + (c == ColorPath::Partial ? 1 : 0)) * kBlendPathCount +
       static_cast<int>(key.blend_path())) *
          2 +
      (key.logic_op ? 1 : 0);
  return kWriterTable[static_cast<size_t>(i)];
}

BlockFn select_block_fn_baseline(const StateKey& key, ShadePath shade) {
  return select_from_tables(key, shade);
}

BlockFn select_block_fn(const StateKey& key, ShadePath shade) {
  const SimdLevel level = simd_level();
#if PINEDA_HAVE_AVX512
  if (level >= SimdLevel::Avx512) return select_block_fn_avx512(key, shade);
#endif
#if PINEDA_HAVE_AVX2
  if (level >= SimdLevel::Avx2) return select_block_fn_avx2(key, shade);
#endif
  static_cast<void>(level);
  return select_from_tables(key, shade);
}

void prepare_fragments(const RasterState& rs, const Framebuffer& fb, FragCtx& ctx) {
  ctx.key = make_state_key(rs, fb);
  const StateKey& k = ctx.key;
  const FragmentProgram* prog = rs.shade != nullptr ? rs.shade->program : nullptr;
  ctx.color_output = fb.color_output;
  ctx.alpha_test_color0 = false;
  ctx.more_count = 0;
  ctx.write_color = nullptr;
  // §4.1.4: with several fragment colours the alpha test takes colour zero's alpha; a pass of
  // another colour has the fragment stage test it (shade_program.cpp).
  if (k.alpha_test && prog != nullptr && prog->frag_data && fb.color_output != 0) {
    ctx.alpha_test_color0 = true;
    ctx.alpha_func = depth_func_bits(rs.alpha_func);
    ctx.alpha_ref = color_to_unorm8(rs.alpha_ref);
    ctx.key.alpha_test = false;
  }
  ctx.color = fb.color;
  ctx.color_stride = fb.color_stride;
  ctx.depth = fb.depth;
  ctx.depth_stride = fb.depth_stride;
  ctx.stencil_stride = fb.stencil_stride;
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
  // A fragment shader that discards decides which fragments reach the depth and stencil
  // tests even when no colour is written (§3.11.2).
  const bool kills = (prog != nullptr && prog->discards) || ctx.alpha_test_color0;
  // §3.11.2: gl_FragDepth replaces the fragment's depth for the depth test and write.
  ctx.shader_depth = prog != nullptr && prog->writes_depth && k.depth_test;
  ctx.shade = ctx.needs_color || kills || ctx.shader_depth ? rs.shade : nullptr;
  ctx.late_depth = kills || ctx.shader_depth;
  ctx.needs_depth = k.depth_test;
  ctx.noop = (!ctx.needs_color && !ctx.needs_depth && !k.stencil_test && !k.count_samples) ||
             ctx.clip_x0 > ctx.clip_x1 || ctx.clip_y0 > ctx.clip_y1;
  // gl_FragCoord.z is the window z: the rasterizers set up the z plane for it.
  if (ctx.shade != nullptr && ctx.shade->program != nullptr && ctx.shade->program->frag_coord) {
    ctx.needs_depth = true;
    if (!(ctx.depth_max > 0.0)) ctx.depth_max = 16777215.0;
  }
  for (int s = 0; s < kShadePathCount; ++s)
    ctx.fn[s] = select_block_fn(k, static_cast<ShadePath>(s));
}

} // namespace pineda
