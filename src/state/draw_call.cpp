// The state layer's draws handed to the draw home (draw_call.h).
#include "state/draw_call.h"

#include <algorithm>
#include <bit>

#include "draw/draw.h"
#include "shader/engine.h"
#include "state/program_draw.h"
#include "state/validate.h"

namespace pineda {

uint32_t input_tex_units(Context* ctx) {
  check_program_link(ctx);
  validate_state(ctx);
  const TexVertexSetup& tvs = ctx->texpipe.vertex;
  // As the draw home decides which units the geometry stage reads (draw/draw.cpp).
  uint32_t units = ctx->raster.shade != nullptr ? tvs.units : 0;
  // A vertex shader reads the coordinates its gl_MultiTexCoord inputs name.
  if (ctx->program_draw->has_vertex) units = ctx->program_draw->vs_tex_units;
  // Feedback of the COLOR_TEXTURE types reports unit 0's coordinates (GL 2.1 §5.3).
  if (!render_mode_is_render(ctx)) units |= 1u;
  return units;
}

namespace {

// The vertex shader's view of the draw's generic attributes (geometry/vertex_program.h).
const VertexProgram* vertex_program(Context* ctx, GenericVertices generic) {
  refresh_program(ctx);
  ProgramDerived& d = *ctx->program_draw;
  if (!d.has_vertex) return nullptr;
  VertexProgram& vp = d.vertex;
  vp.generic = generic.data;
  vp.generic_stride = 4 * std::popcount(generic.mask);
  int column = 0;
  for (int i = 0; i < kMaxVertexAttribs; ++i) {
    const bool given = generic.data != nullptr && (generic.mask & (1u << i)) != 0;
    vp.generic_column[i] = static_cast<int8_t>(given ? column : -1);
    if (given) column += 4;
    std::copy(ctx->vertex_attrib.value[i], ctx->vertex_attrib.value[i] + 4, vp.generic_current[i]);
  }
  return &vp;
}

} // namespace

void draw_vertices(Context* ctx, GLenum mode, const InputVertex* verts, size_t n,
                   const uint32_t* indices, size_t count, GenericVertices generic) {
  // ARB_framebuffer_object §4.4.4: nothing is drawn into an incomplete framebuffer.
  if (!draw_framebuffer_ready(ctx, "glDraw") || !ctx->fb.present() || n == 0) return;
  check_program_link(ctx);
  validate_state(ctx);
  DrawInput in;
  if (ctx->program_draw->linked != nullptr) in.vertex_program = vertex_program(ctx, generic);
  in.mode = mode;
  in.in = verts;
  in.n = n;
  in.indices = indices;
  in.count = count;
  // GL 2.1 §2.14.1: lighting replaces the current colour. Material calls between Begin and
  // End (§2.14.2) change the material from a given vertex of the primitive on.
  const LightingGroup& lighting = ctx->lighting;
  in.lit = lighting.enabled;
  in.material = lighting.material;
  if (in.lit && !ctx->imm.material_changes.empty()) {
    in.changes = ctx->imm.material_changes.data();
    in.change_count = ctx->imm.material_changes.size();
    in.material = ctx->imm.begin_material;
  }
  // §3.9: with lighting on the colour sum always applies and the secondary colour is zero
  // unless the specular term is separate; otherwise COLOR_SUM adds the current secondary
  // colour. Feedback returns the primary colour alone (GL 2.1 §5.3), so nothing is folded in
  // there.
  const bool render = ctx->render_mode.mode == GL_RENDER;
  in.color_sum = (in.lit ? ctx->light_setup.separate_specular : ctx->fog.color_sum) && render;
  if (render) return draw_vertices(ctx->draw, in);
  // GL 2.1 §5.2, §5.3: in SELECT and FEEDBACK mode the primitives become selection hits or
  // feedback values.
  RenderModeRecords records(ctx->render_mode);
  in.records = &records;
  in.texture0 = &ctx->texture_matrix[0].top();
  VertexProgram feedback_program;
  if (in.vertex_program != nullptr) {
    // GL 2.1 §5.3 with a vertex shader (§2.20.2): feedback reports gl_FrontColor and
    // gl_TexCoord[0], whatever the fragment stage reads; the colour sum is not folded in.
    feedback_program = *in.vertex_program;
    const shader::Executable& exe = *feedback_program.exe;
    bool color = false, tex = false;
    for (int c : exe.outputs_written()) {
      color |= c / 4 == shader::kOutFrontColor;
      tex |= c / 4 == shader::kOutTexCoord0;
    }
    for (int k = 0; k < 4; ++k) {
      feedback_program.out_attr[shader::kOutFrontColor * 4 + k] =
          static_cast<int16_t>(kAttrColor + k);
      feedback_program.out_attr[shader::kOutTexCoord0 * 4 + k] =
          static_cast<int16_t>(kAttrTex0 + k);
    }
    feedback_program.attr_count = std::max(feedback_program.attr_count, kAttrTex0 + 4);
    feedback_program.fold_sum = false;
    in.vertex_program = &feedback_program;
    if (!color) in.feedback_color = ctx->current.color;
    if (!tex) in.feedback_tex = ctx->current.tex[0];
  }
  draw_vertices(ctx->draw, in);
}

} // namespace pineda
