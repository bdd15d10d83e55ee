// Per-fragment shading for texturing and fog (GL 2.1 §3.8.8 level of detail, §3.8.13 texture
// environments, §3.9 colour sum, §3.10 fog): the colour of each fragment of a block, which the
// block loop's ShadePath::PerFragment instances consume. Used only while texturing or fog is
// on; everything else keeps the Const and Smooth paths.
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "fragment/fragment_ops.h"
#include "texture/sampler.h"

// The engine's types by name only (fragment/shade_program.cpp includes shader/engine.h): this
// header reaches files that include Xlib, whose macros collide with the engine's IR names.
namespace pineda::shader {
class Executable;
class TextureSampler;
struct Prepared;
} // namespace pineda::shader

namespace pineda {

// How a unit derives rho (§3.8.8) from the coordinate derivatives.
enum class LodDims : uint8_t { One, Two, Three, Cube };

// One texture unit as the fragment stage runs it (§3.8.13 Table 3.22/3.23, §3.8.13 combine).
struct ShadeUnit {
  int index = 0; // texture unit number (coordinate slot kAttrTex0 + 4 * index)
  SamplerView view;
  LodDims dims = LodDims::Two;
  float bias = 0.0f; // the unit's TEXTURE_LOD_BIAS
  GLenum mode = GL_MODULATE;
  float color[4] = {0, 0, 0, 0};
  GLenum combine_rgb = GL_MODULATE, combine_alpha = GL_MODULATE;
  // Combine sources as indices: 0..3 texture of unit n, 4 constant, 5 primary, 6 previous.
  uint8_t src_rgb[3] = {0, 6, 4}, src_alpha[3] = {0, 6, 4};
  GLenum op_rgb[3] = {GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA};
  GLenum op_alpha[3] = {GL_SRC_ALPHA, GL_SRC_ALPHA, GL_SRC_ALPHA};
  float rgb_scale = 1.0f, alpha_scale = 1.0f;
};

// The fragment stage of a GLSL program (GL 2.1 §3.11): the fragment shader runs in place of
// texturing, colour sum and fog over the 2x2 quads of a block (shader/engine.h). Plain data
// made by the state layer (state/program_draw.cpp).
struct FragmentProgram {
  const shader::Executable* exe = nullptr;
  const shader::Prepared* prepared = nullptr;
  shader::TextureSampler* sampler = nullptr;
  // The interpolated inputs: input component input_comp[i] (shader/io.h FragmentInput) comes
  // from PVertex::attr[input_attr[i]] (colour slots below kAttrTex0 take the back colours of
  // back-facing polygons under two-sided colouring, and the provoking vertex's under flat
  // shading, §2.14.7).
  int input_count = 0;
  int16_t input_comp[kMaxAttr] = {};
  int16_t input_attr[kMaxAttr] = {};
  bool frag_coord = false;  // reads gl_FragCoord
  bool point_coord = false; // reads gl_PointCoord
  bool discards = false;    // may discard: the depth test waits for the shader
  // Writes gl_FragDepth (§3.11.2): the shader's depth replaces the interpolated one in the
  // depth test and write, so the depth test waits for the shader too.
  bool writes_depth = false;
  // Writes gl_FragData[n] (to draw buffer n) rather than gl_FragColor (to every draw buffer,
  // §3.11.2, §4.2.1).
  bool frag_data = false;
};

// Everything the per-fragment shading reads that is constant over a draw.
struct ShadeSetup {
  int unit_count = 0; // enabled, complete units, in unit order
  ShadeUnit unit[kMaxTexUnits];
  int slot_of_unit[kMaxTexUnits] = {-1, -1, -1, -1}; // unit number -> position in unit[], or -1
  bool color_sum = false; // §3.9: add the secondary colour after texturing
  bool fog = false;
  GLenum fog_mode = GL_EXP;
  float fog_color[4] = {0, 0, 0, 0};
  float fog_density = 1.0f, fog_start = 0.0f, fog_end = 1.0f;
  // GL_FOG_HINT = FASTEST (§5.6): the kAttrFog slot holds the factor f computed per vertex
  // (geometry/texcoord.cpp), not the fog coordinate; only read when `fog` is set.
  bool fog_per_vertex = false;
  // A fragment shader replaces everything above (the fields above are then unused).
  const FragmentProgram* program = nullptr;
};

// Interpolation inputs of one primitive for the per-fragment path: perspective-correct planes
// (value/w, and 1/w) for the colours, the live units' coordinates and the fog coordinate.
// Trivially constructible: rasterizers declare one on the stack at no cost and fill it only
// when the draw shades per fragment.
struct ShadeInputs {
  // User-provided, so that value-initialization (the binning's emplace_back()) does not zero the
  // fragment shader planes first: every path writes what its draw reads.
  ShadeInputs() {} // NOLINT(modernize-use-equals-default)
  PlaneF inv_w;
  PlaneF color_w[4];
  PlaneF color2_w[3];
  PlaneF tex_w[kMaxTexUnits][4];
  PlaneF fog_w;
  // Flat shading, points, or equal vertex colours: the colours are these constants.
  bool const_colors;
  float color[4], color2[3];
  // A fragment shader's inputs (FragmentProgram::input_comp order), value/w planes, and
  // whether the primitive is front-facing (gl_FrontFacing, §3.11.2).
  // (Planes without member initializers: a primitive that does not use them pays nothing.)
  bool front_facing;
  struct Plane {
    float v0, dx, dy;
  } prog_w[kMaxAttr];
  // gl_PointCoord (s, t) as linear planes, set when the program reads it: the sprite
  // coordinates of a point sprite (§3.3.1 eqs. 3.3, 3.4), zero for other primitives.
  PlaneF point_coord[2];
};

// Colours of the fragments of `mask` in the block at (bx, by): out[c][8 * row + column] for
// c = R, G, B, A, unclamped-safe floats (the block loop clamps and rounds). Every entry of a
// row holding a fragment of `mask` is written (entries of no fragment with some defined value); the
// other rows are left as they are. Returns the fragments of `mask` that remain: a fragment
// shader may discard some (§3.11.2). When ctx.shader_depth is set, `depth` (64 entries, same
// order and rows) receives the depth the fragment shader wrote, in depth-buffer units.
uint64_t shade_block(const FragCtx& ctx, const FragInputs& in, int bx, int by, uint64_t mask,
                     float (*out)[64], uint32_t* depth = nullptr);

// The same through the draw's fragment shader (ctx.shade->program; shade_program.cpp): the
// colour is gl_FragColor, or gl_FragData[ctx.color_output] for a shader that writes gl_FragData.
uint64_t shade_program_block(const FragCtx& ctx, const FragInputs& in, int bx, int by,
                             uint64_t mask, float (*out)[64], uint32_t* depth);

// After shade_program_block on this thread: the colours the shader gave draw buffer `output`
// (gl_FragData[output], or gl_FragColor), in the layout shade_block writes (every entry of the
// rows it wrote defined).
void shade_program_colors(const FragCtx& ctx, int output, float (*out)[64]);

// Texture environment of one fragment (exposed for tests): previous colour `cp`, primary colour
// `cf`, every unit's texture colour `tex` (indexed by position in ShadeSetup::unit), the result
// in `cv`. All values in [0,1].
void apply_tex_env(const ShadeUnit& u, TexBase base, const float cp[4], const float cf[4],
                   const float (*tex)[4], const int* slot_of_unit, const float cs[4], float cv[4]);

// Fog blend factor f (§3.10 eq 3.25-3.27) for coordinate c, clamped to [0,1].
float fog_factor(const ShadeSetup& ss, float c);

} // namespace pineda
