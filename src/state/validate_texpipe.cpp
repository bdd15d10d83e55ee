// Validation of the texturing pipeline and fog: from the texture unit and fog state to the
// geometry stage's per-vertex setup (texcoord.h) and the fragment stage's per-fragment setup
// (fragment/shade.h), and the live attribute count of the back end.
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "state/context.h"
#include "state/texenv.h"
#include "fragment/shade.h"
#include "texture/sampler.h"

namespace pineda {

namespace {

// GL 2.1 §3.8.15: of the enabled targets of a unit, cube map wins over 3D, 3D over 2D, 2D over
// 1D. Zero when none is enabled.
GLenum unit_target(const TexUnit& u) {
  if (u.enable_cube) return GL_TEXTURE_CUBE_MAP;
  if (u.enable_3d) return GL_TEXTURE_3D;
  if (u.enable_2d) return GL_TEXTURE_2D;
  if (u.enable_1d) return GL_TEXTURE_1D;
  return 0;
}

LodDims lod_dims(GLenum target) {
  switch (target) {
  case GL_TEXTURE_1D:
    return LodDims::One;
  case GL_TEXTURE_3D:
    return LodDims::Three;
  case GL_TEXTURE_CUBE_MAP:
    return LodDims::Cube;
  default:
    return LodDims::Two;
  }
}

// Combine source enum to ShadeUnit's index: 0..3 texture of that unit, 4 constant, 5 primary
// colour, 6 previous.
uint8_t source_index(GLenum src, int unit) {
  if (src == GL_TEXTURE) return static_cast<uint8_t>(unit);
  if (src >= GL_TEXTURE0 && src < GL_TEXTURE0 + kMaxTexUnits)
    return static_cast<uint8_t>(src - GL_TEXTURE0);
  if (src == GL_CONSTANT) return 4;
  if (src == GL_PRIMARY_COLOR) return 5;
  return 6;
}

void setup_unit(ShadeUnit& su, const TexEnv& e, float bias, int unit, GLenum target) {
  su.index = unit;
  su.dims = lod_dims(target);
  su.bias = bias;
  su.mode = e.mode;
  for (int k = 0; k < 4; ++k)
    su.color[k] = e.color[k];
  su.combine_rgb = e.combine_rgb;
  su.combine_alpha = e.combine_alpha;
  for (int i = 0; i < 3; ++i) {
    su.src_rgb[i] = source_index(e.src_rgb[i], unit);
    su.src_alpha[i] = source_index(e.src_alpha[i], unit);
    su.op_rgb[i] = e.op_rgb[i];
    su.op_alpha[i] = e.op_alpha[i];
  }
  su.rgb_scale = e.rgb_scale;
  su.alpha_scale = e.alpha_scale;
}

void setup_vertex(const Context* ctx, uint32_t units, bool fog, TexVertexSetup& vs) {
  const TextureGroup& tex = ctx->texture;
  vs.units = units;
  vs.need_eye = vs.need_normal = false;
  for (int u = 0; u < kMaxTexUnits; ++u) {
    if (!(units & (1u << u))) continue;
    const TexUnit& us = tex.unit[u];
    TexVertexUnit& tu = vs.unit[u];
    for (int c = 0; c < 4; ++c) {
      tu.gen[c] = us.gen_enabled[c];
      tu.mode[c] = us.gen[c].mode;
      const float* plane =
          us.gen[c].mode == GL_OBJECT_LINEAR ? us.gen[c].object_plane : us.gen[c].eye_plane;
      for (int k = 0; k < 4; ++k)
        tu.plane[c][k] = plane[k];
      if (!tu.gen[c]) continue;
      if (tu.mode[c] != GL_OBJECT_LINEAR) vs.need_eye = true;
      if (tu.mode[c] == GL_SPHERE_MAP || tu.mode[c] == GL_REFLECTION_MAP ||
          tu.mode[c] == GL_NORMAL_MAP)
        vs.need_normal = true;
    }
    // §2.11.2: the coordinates are multiplied by the unit's texture matrix.
    const glm::mat4& tm = ctx->texture_matrix[u].top();
    tu.identity = tm == glm::mat4(1.0f);
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row)
        tu.matrix[4 * col + row] = tm[col][row];
  }
  vs.need_eye = vs.need_eye || vs.need_normal;
  vs.fog = fog;
  vs.fog_from_depth = fog && ctx->fog.coord_src == GL_FRAGMENT_DEPTH;
  const glm::mat4& mv = ctx->modelview.top();
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row)
      vs.modelview[4 * col + row] = mv[col][row];
  if (vs.need_normal) {
    // §2.11.3: normals transform by the inverse transpose of the upper 3x3.
    const glm::mat3 nm = glm::transpose(glm::inverse(glm::mat3(mv)));
    for (int col = 0; col < 3; ++col)
      for (int row = 0; row < 3; ++row)
        vs.normal_matrix[3 * col + row] = nm[col][row];
    vs.normalize = ctx->transform.normalize;
    vs.rescale = 1.0f;
    if (ctx->transform.rescale_normal && !ctx->transform.normalize) {
      // §2.11.3: f = 1 / sqrt(m31^2 + m32^2 + m33^2) of the inverse model-view.
      const glm::mat3 inv = glm::inverse(glm::mat3(mv));
      const float len =
          std::sqrt(inv[0][2] * inv[0][2] + inv[1][2] * inv[1][2] + inv[2][2] * inv[2][2]);
      vs.rescale = len > 0.0f ? 1.0f / len : 1.0f;
    }
  }
}

} // namespace

void validate_texpipe(Context& context, uint32_t) {
  Context* ctx = &context;
  TexPipeDerived& tp = ctx->texpipe;
  const uint64_t generation = ctx->shared->texture_generation;
  tp.seen_generation = generation;
  tp.any_target_enabled = false;
  if (!tp.shade) tp.shade = std::make_shared<ShadeSetup>();
  ShadeSetup& ss = *tp.shade;
  ss.unit_count = 0;
  uint32_t units = 0;
  for (int u = 0; u < kMaxTexUnits; ++u) {
    ss.slot_of_unit[u] = -1;
    const GLenum target = unit_target(ctx->texture.unit[u]);
    if (target == 0) continue;
    tp.any_target_enabled = true;
    ShadeUnit& su = ss.unit[ss.unit_count];
    // §3.8.15: a unit whose texture is not complete behaves as if texturing were disabled.
    if (!make_sampler_view(*bound_texture(ctx, u, target), su.view)) continue;
    setup_unit(su, ctx->texture.unit[u].env, ctx->texture.lod_bias[u], u, target);
    ss.slot_of_unit[u] = ss.unit_count++;
    units |= 1u << u;
  }
  const FogGroup& fog = ctx->fog;
  ss.fog = fog.enabled;
  ss.fog_mode = fog.mode;
  for (int k = 0; k < 4; ++k)
    ss.fog_color[k] = fog.color[k];
  ss.fog_density = fog.density;
  ss.fog_start = fog.start;
  ss.fog_end = fog.end;
  // GL 2.1 §3.10 lets f be computed per vertex and interpolated; §5.6 leaves the choice to
  // FOG_HINT. FASTEST evaluates per vertex; NICEST and DONT_CARE per fragment, the accurate
  // default. Mesa: classic swrast/tnl computed f per vertex unless the hint was NICEST
  // (_DoVertexFog = hint != NICEST); Gallium (llvmpipe, the oracle) ignores the hint: its
  // fixed-function vertex program (ffvertex_prog.c build_fog) outputs only the coordinate and
  // the fragment shader evaluates f (st_nir_lower_fog). DONT_CARE follows llvmpipe, FASTEST
  // the classic path.
  // A GLSL program gives the fog coordinate, never the factor (§3.10: with a vertex shader c
  // is the interpolated gl_FogFragCoord; a fragment shader reads the coordinate).
  const bool program = active_program(ctx) != nullptr;
  ss.fog_per_vertex = fog.enabled && ctx->hint.fog == GL_FASTEST && !program;
  const LightingGroup& ls = ctx->lighting;
  // §3.9: with lighting the sum applies when the specular colour is separate; otherwise
  // COLOR_SUM decides.
  // With a vertex shader COLOR_SUM alone decides (§3.9).
  const bool vertex_shader = program && active_program(ctx)->has_vertex;
  ss.color_sum =
      ls.enabled && !vertex_shader ? ctx->light_setup.separate_specular : ctx->fog.color_sum;
  tp.shading = ss.unit_count != 0 || ss.fog;
  // A fragment shader after the fixed-function vertex stage reads the coordinates of the units
  // it names (texturing on or not) and the fog coordinate (GL 2.1 §3.11.2).
  bool program_fog = false;
  const uint32_t program_units = fixed_vertex_program_inputs(*ctx, &program_fog);
  setup_vertex(ctx, units | program_units, ss.fog || program_fog, tp.vertex);
  TexVertexSetup& vs = tp.vertex;
  vs.fog_per_vertex = ss.fog_per_vertex;
  vs.fog_mode = fog.mode;
  vs.fog_density = fog.density;
  vs.fog_start = fog.start;
  vs.fog_end = fog.end;
  // Live attributes: the colours (both when the sum happens per fragment), then up to the
  // last live texture unit or the fog coordinate.
  int count = 4;
  if (tp.shading && ss.color_sum) count = kAttrColor2 + 4;
  for (int u = 0; u < kMaxTexUnits; ++u)
    if (units & (1u << u)) count = kAttrTex0 + 4 * (u + 1);
  if (ss.fog) count = kAttrFog + 1;
  tp.attr_count = count;
}

} // namespace pineda
