// The per-fragment operations (GL 2.1 §4.1) on blocks of up to 8x8 fragments.
//
// The rasterizers (raster_tri.cpp, raster_line.cpp, raster_point.cpp) hand over an 8x8 block
// at a position aligned to 8 in window space, a 64-bit coverage mask (bit 8*row + column)
// and the primitive's interpolation planes. The block loop that runs is a template instance
// specialized for the StateKey (state_key.h): no per-fragment branches on state and no
// per-fragment indirect calls.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/simd_level.h" // PINEDA_HAVE_AVX2/AVX512: fragment_ops_avx2/avx512.cpp are built
#include "fragment/blend.h"
#include "fragment/per_fragment.h"
#include "fragment/state_key.h"
#include "framebuffer/framebuffer.h"
#include "core/raster_state.h"

namespace pineda {

constexpr int kBlockSize = 8; // blocks are 8x8 and aligned to multiples of 8 in window space

// A linear function of the pixel position, evaluated at pixel centres relative to the origin
// pixel (FragInputs::ox, oy): value at pixel (ox + i, oy + j) is v0 + i*dx + j*dy. Keeping
// the origin near the primitive keeps float products small and exact enough.
struct PlaneF {
  float v0 = 0, dx = 0, dy = 0;
};
struct PlaneD {
  double v0 = 0, dx = 0, dy = 0;
};

// One face's stencil test and update (GL 2.1 §4.1.5) as the block loops read them.
struct StencilSide {
  uint8_t func = 0; // depth_func_bits encoding
  uint8_t ref = 0;  // clamped to [0, 255]
  uint8_t value_mask = 0xff;
  uint8_t write_mask = 0xff;
  StencilOp ops[3] = {}; // stencil fails, depth fails, depth passes
};

struct ShadeInputs; // fragment/shade.h
struct ShadeSetup;  // fragment/shade.h

// Interpolation inputs of one primitive.
struct FragInputs {
  int ox = 0, oy = 0;
  // Window z already multiplied by the depth buffer's maximum value, unclamped; linear in
  // window space (GL 2.1 §3.5.1 eq 3.10). Double, so 24- and 32-bit buffers get exact steps.
  PlaneD z;
  // Perspective-correct colour (GL 2.1 §3.5.1 eq 3.9): c/w and 1/w are linear in window
  // space; the block loop divides per fragment.
  PlaneF inv_w;
  PlaneF color_w[4];
  uint8_t const_color[4] = {0, 0, 0, 0}; // RGBA for ShadePath::Const
  const ShadeInputs* shade = nullptr;    // planes for ShadePath::PerFragment
  // Fragments of a back-facing polygon: the stencil test uses the back face's state (GL 2.1
  // §4.1.5); 0 for every other primitive.
  uint8_t back_facing = 0;
};

struct FragCtx;
using BlockFn = void (*)(const FragCtx& ctx, const FragInputs& in, int bx, int by, uint64_t mask);
// Blends, masks and stores colours colors[c][8 * row + column] (c = R, G, B, A) of the fragments
// of `mask` in the block at (bx, by) into ctx's colour buffer (GL 2.1 §4.1.8-§4.2.2): a further
// draw buffer of a fragment shader's draw (FragCtx::more).
using ColorWriteFn = void (*)(const FragCtx& ctx, int bx, int by, uint64_t mask,
                              const float (*colors)[64]);

// Everything the block loops read that is constant over a draw.
struct FragCtx {
  StateKey key;
  uint8_t* color = nullptr;
  ptrdiff_t color_stride = 0;
  uint32_t* depth = nullptr;
  ptrdiff_t depth_stride = 0;
  double depth_max = 0;     // 2^bits - 1
  uint8_t depth_func = 0;   // StateKey::depth_func, for the generic path
  bool depth_write = false; // for the generic path
  uint32_t color_keep = 0;  // partial colour mask: bits of the stored pixel to keep
  BlendParams blend;
  bool blend_fixed = false; // blend_simd.h blend_params_fixed(blend): the 16-bit generic path
  // Values of the operations StateKey::ext() covers; read only by the extended instances.
  uint8_t alpha_func = 0;     // depth_func_bits encoding (GL 2.1 §4.1.4)
  uint8_t alpha_ref = 0;      // the reference as 8-bit fixed point (§2.14.9)
  uint8_t* stencil = nullptr; // row 0 at the bottom, stride fb_width
  // Front [0] and back [1] stencil state (§4.1.5), indexed by FragInputs::back_facing.
  StencilSide stencil_side[2];
  LogicMasks logic;
  // Fragments outside this rectangle (inclusive) are never produced: the framebuffer,
  // intersected with the scissor box when the scissor test is on (GL 2.1 §4.1.2).
  int clip_x0 = 0, clip_y0 = 0, clip_x1 = -1, clip_y1 = -1;
  // Rows of a block that lie entirely inside the buffer (bx + 8 <= fb_width) are loaded and
  // stored whole, with the coverage applied as a lane select.
  int fb_width = 0;
  int stencil_stride = 0;   // values from one row of the stencil buffer to the next
  bool noop = true;         // nothing can change: no colour, depth or stencil update
  bool needs_color = false; // the colour path or the alpha test reads the primitive's colour
  bool needs_depth = false; // the depth path reads the primitive's z
  BlockFn fn[kShadePathCount] = {}; // indexed by ShadePath
  // Texturing, colour sum and fog per fragment (fragment/shade.h); set when the draw has
  // texturing or fog on and reads colour. Primitives then run ShadePath::PerFragment.
  const ShadeSetup* shade = nullptr;
  // The fragment shader may discard fragments or writes gl_FragDepth: the depth test waits
  // for it (§3.11.2).
  bool late_depth = false;
  // The fragment shader writes gl_FragDepth and the depth test is on: the PerFragment
  // instances test and store the shader's depth, and no block is rejected before shading.
  bool shader_depth = false;
  // The draw buffer this pass writes (Framebuffer::color_output): a shader writing
  // gl_FragData[n] gives buffer n its colour n.
  int color_output = 0;
  // The alpha test of a pass writing gl_FragData[n], n > 0: it tests colour zero's alpha
  // (§4.1.4), so the fragment stage runs it (alpha_func, alpha_ref) and the key has it off.
  bool alpha_test_color0 = false;
  // A fragment shader's draw into several draw buffers (§4.2.1) shades each fragment once: the
  // PerFragment instances store the fragments that pass the tests into these further buffers
  // too, each through its own context's writer (write_color), with colour more[i]->color_output.
  int more_count = 0;
  const FragCtx* more[kMaxDrawBuffers - 1] = {};
  ColorWriteFn write_color = nullptr;
  // Fragments that passed the stencil and depth tests, counted when key.count_samples
  // (occlusion queries, GL 2.1 §4.1.7); draw_primitives hands the sum to the query.
  mutable uint64_t samples_passed = 0;
};

// Fills ctx for one draw: the key, the surfaces and the selected block loops.
void prepare_fragments(const RasterState& rs, const Framebuffer& fb, FragCtx& ctx);

// A copy of `ctx` whose front stencil state is the back face's and which has counted no
// samples yet: for the lines and points outlining a back-facing polygon (GL 2.1 §4.1.5), which
// the rasterizers draw with the front state.
inline FragCtx with_back_stencil(const FragCtx& ctx) {
  FragCtx back = ctx;
  back.stencil_side[0] = back.stencil_side[1];
  back.samples_passed = 0;
  return back;
}

// The colour writer for a key (FragCtx::write_color).
ColorWriteFn select_color_writer(const StateKey& key);

// The block loop for a key and shade path at the current simd_level() (exposed for tests).
BlockFn select_block_fn(const StateKey& key, ShadePath shade);

// The same from the baseline instances and, when PINEDA_HAVE_AVX2, from the AVX2 ones
// (to be called only when the processor has AVX2, BMI1 and BMI2: simd_level.h), and, when
// PINEDA_HAVE_AVX512, from the AVX-512 ones (only at SimdLevel::Avx512).
BlockFn select_block_fn_baseline(const StateKey& key, ShadePath shade);
BlockFn select_block_fn_avx2(const StateKey& key, ShadePath shade);
BlockFn select_block_fn_avx512(const StateKey& key, ShadePath shade);

// Mask of the pixels of the block at (bx, by) inside the inclusive rectangle [x0,x1]x[y0,y1].
inline uint64_t rect_block_mask(int x0, int y0, int x1, int y1, int bx, int by) {
  const int c0 = x0 - bx > 0 ? x0 - bx : 0;
  const int c1 = x1 - bx < 7 ? x1 - bx : 7;
  const int r0 = y0 - by > 0 ? y0 - by : 0;
  const int r1 = y1 - by < 7 ? y1 - by : 7;
  if (c0 > c1 || r0 > r1) return 0;
  const uint64_t row = (0xffu >> (7 - c1)) & (0xffu << c0) & 0xffu;
  const uint64_t rows = (~0ull >> (8 * (7 - r1))) & (~0ull << (8 * r0));
  return (row * 0x0101010101010101ull) & rows;
}

inline uint64_t block_clip_mask(const FragCtx& ctx, int bx, int by) {
  return rect_block_mask(ctx.clip_x0, ctx.clip_y0, ctx.clip_x1, ctx.clip_y1, bx, by);
}

// Fragment colour to unorm8: clamp to [0,1], then round(c * 255) (GL 2.1 §2.14.9).
inline uint8_t color_to_unorm8(float c) {
  c = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;
  return static_cast<uint8_t>(c * 255.0f + 0.5f);
}

} // namespace pineda
