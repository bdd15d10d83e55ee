// The per-fragment state that changes generated code, reduced from RasterState and the
// Framebuffer to a few small fields. The fragment stage picks one specialized instance of its
// block loop per key (fragment_ops.cpp), the way softpipe's choose_depth_test or SwiftShader's
// routine cache pick code from state: everything that only changes a value (blend factors,
// the blend colour, the depth function of the generic path) stays runtime data in FragCtx.
#pragma once

#include <cstdint>

#include "framebuffer/framebuffer.h"
#include "core/raster_state.h"

namespace pineda {

// Depth handling of the block loop. GL_LESS and GL_LEQUAL with writes on are what scenes
// use almost always, so they get their own code; every other function and GL_LESS/GL_LEQUAL
// with glDepthMask(GL_FALSE) go through the generic path, whose compare is a table lookup.
enum class DepthPath : uint8_t { Off, LessWrite, LequalWrite, Generic };
constexpr int kDepthPathCount = 4;

// How much of the colour buffer a fragment writes: nothing (glColorMask all false, or no
// colour buffer), every channel the format has, or some of them (read-modify-write).
enum class ColorPath : uint8_t { None, All, Partial };

// Blending (GL 2.1 §4.1.8): off (or an equivalent ONE, ZERO, ADD), the common
// SRC_ALPHA / ONE_MINUS_SRC_ALPHA with ADD in exact unorm8 arithmetic, or any other
// combination of factors and equations in float.
enum class BlendPath : uint8_t { Off, Over, Generic };
constexpr int kBlendPathCount = 3;

// Where a primitive's colour comes from: one value for the whole primitive (flat shading,
// points, or three equal vertex colours), perspective-correct interpolation, or per-fragment
// shading (texturing, colour sum and fog, fragment/shade.h) while texturing or fog is on.
// Chosen per primitive, not per draw.
enum class ShadePath : uint8_t { Const, Smooth, PerFragment };
constexpr int kShadePathCount = 3;

constexpr int kColorFormatCount = 4;

struct StateKey {
  // Depth test active: GL_DEPTH_TEST on and a depth buffer present. With the test off the
  // depth buffer is neither read nor written (GL 2.1 §4.1.6); without a depth buffer the test
  // always passes (GL 2.1 §4.1.6, last paragraph).
  bool depth_test = false;
  // glDepthFunc as a set of outcomes: bit 0 passes "less", bit 1 "equal", bit 2 "greater".
  // GL_NEVER..GL_ALWAYS are 0x200..0x207 in exactly this encoding.
  uint8_t depth_func = 0;
  bool depth_write = false;
  ColorFormat format = ColorFormat::RGBA8;
  // Channels written, bit i for R, G, B, A; the alpha bit is dropped for formats without
  // alpha, so "all" means all channels the format stores.
  uint8_t color_mask = 0;
  bool has_alpha = true;   // the format stores alpha; otherwise destination alpha reads as 1
  bool blend = false;      // blending on and not equivalent to a plain store
  bool blend_over = false; // the blend is SRC_ALPHA, ONE_MINUS_SRC_ALPHA, FUNC_ADD for both
  // The rarer operations each take a per-row branch inside one extra set of instances, so
  // that with all three off the block loops are exactly the ones without them.
  bool alpha_test = false;   // GL 2.1 §4.1.4, on and not ALWAYS
  bool stencil_test = false; // §4.1.5, on, a stencil buffer present, and able to change anything
  bool logic_op = false;     // §4.1.10 on colour, and not COPY (which is a plain store)
  // An occlusion query is active (§4.1.7): the extended instances count the fragments that
  // pass the stencil and depth tests, so instances without a query carry no counting code.
  bool count_samples = false;

  bool ext() const { return alpha_test || stencil_test || logic_op || count_samples; }

  DepthPath depth_path() const;
  ColorPath color_path() const;
  BlendPath blend_path() const;
  uint8_t all_channels() const { return has_alpha ? 0xf : 0x7; }
};

StateKey make_state_key(const RasterState& rs, const Framebuffer& fb);

// GL depth function enum (GL_NEVER..GL_ALWAYS) to the outcome set above.
inline uint8_t depth_func_bits(GLenum func) {
  return (func >= GL_NEVER && func <= GL_ALWAYS) ? static_cast<uint8_t>(func - GL_NEVER) : 0;
}

} // namespace pineda
