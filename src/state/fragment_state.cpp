// State of the per-fragment tests and the logical operation (GL 2.1 §4.1.2 scissor, §4.1.4
// alpha test, §4.1.5 stencil test, §4.1.10 logical operation) and the stencil write mask
// (§4.2.2); the area of the per-fragment operations and framebuffer control (Tables 6.20-6.22,
// fragment_state.h): their capabilities, queries and the SCISSOR, COLOR_BUFFER, DEPTH_BUFFER
// and STENCIL_BUFFER groups. raster_state.cpp derives the back end's RasterState from them.
#include "state/api_util.h"
#include "dispatch.h"
#include "state/area.h"

namespace pineda {

namespace {

// NEVER, LESS, EQUAL, LEQUAL, GREATER, NOTEQUAL, GEQUAL, ALWAYS: the comparison functions of
// the alpha and stencil tests (GL 2.1 §4.1.4, §4.1.5).
bool is_compare_func(GLenum func) {
  return func >= GL_NEVER && func <= GL_ALWAYS;
}

// KEEP, ZERO, REPLACE, INCR, DECR, INVERT (GL 2.1 §4.1.5) and INCR_WRAP, DECR_WRAP (GL 1.4).
bool is_stencil_op(GLenum op) {
  switch (op) {
  case GL_KEEP:
  case GL_ZERO:
  case GL_REPLACE:
  case GL_INCR:
  case GL_DECR:
  case GL_INVERT:
  case GL_INCR_WRAP:
  case GL_DECR_WRAP:
    return true;
  default:
    return false;
  }
}

// GL 2.1 §4.1.5: the reference reads back clamped to [0, 2^s - 1].
int clamped_stencil_ref(const Context& ctx, int ref) {
  const int top = ctx.fb.stencil ? (1 << ctx.fb.stencil_bits) - 1 : 0;
  return ref < 0 ? 0 : (ref > top ? top : ref);
}

// The faces FRONT, BACK or FRONT_AND_BACK name (GL 2.1 §4.1.5, §4.2.2); 0 for another enum.
int stencil_faces(Context& ctx, GLenum face, StencilFace* out[2]) {
  switch (face) {
  case GL_FRONT:
    out[0] = &ctx.stencil.front;
    return 1;
  case GL_BACK:
    out[0] = &ctx.stencil.back;
    return 1;
  case GL_FRONT_AND_BACK:
    out[0] = &ctx.stencil.front;
    out[1] = &ctx.stencil.back;
    return 2;
  default:
    return 0;
  }
}

// Tables 6.20-6.22.
bool get_fragment(Context& ctx, GLenum pname, QueryValues& out) {
  const ColorBufferGroup& cb = ctx.color_buffer;
  const BlendState& blend = cb.blend_state;
  const StencilFace& st = ctx.stencil.front;
  switch (pname) {
  case GL_SCISSOR_BOX:
    out.ints({double(ctx.scissor.box[0]), double(ctx.scissor.box[1]), double(ctx.scissor.box[2]),
              double(ctx.scissor.box[3])});
    return true;
  case GL_ALPHA_TEST_FUNC:
    out.ints({double(cb.alpha_func)});
    return true;
  case GL_ALPHA_TEST_REF:
    out.normalized({cb.alpha_ref});
    return true;
  case GL_STENCIL_FUNC:
    out.ints({double(st.func)});
    return true;
  // GL 2.1 §4.1.5: the reference reads back clamped to [0, 2^s - 1].
  case GL_STENCIL_REF:
    out.ints({double(clamped_stencil_ref(ctx, st.ref))});
    return true;
  case GL_STENCIL_VALUE_MASK:
    out.ints({double(st.value_mask)});
    return true;
  case GL_STENCIL_WRITEMASK:
    out.ints({double(st.writemask)});
    return true;
  case GL_STENCIL_FAIL:
    out.ints({double(st.fail)});
    return true;
  case GL_STENCIL_PASS_DEPTH_FAIL:
    out.ints({double(st.depth_fail)});
    return true;
  case GL_STENCIL_PASS_DEPTH_PASS:
    out.ints({double(st.depth_pass)});
    return true;
  // GL 2.1 Table 6.21: the back face's stencil state (GL 2.0 separate stencil).
  case GL_STENCIL_BACK_FUNC:
    out.ints({double(ctx.stencil.back.func)});
    return true;
  case GL_STENCIL_BACK_REF:
    out.ints({double(clamped_stencil_ref(ctx, ctx.stencil.back.ref))});
    return true;
  case GL_STENCIL_BACK_VALUE_MASK:
    out.ints({double(ctx.stencil.back.value_mask)});
    return true;
  case GL_STENCIL_BACK_WRITEMASK:
    out.ints({double(ctx.stencil.back.writemask)});
    return true;
  case GL_STENCIL_BACK_FAIL:
    out.ints({double(ctx.stencil.back.fail)});
    return true;
  case GL_STENCIL_BACK_PASS_DEPTH_FAIL:
    out.ints({double(ctx.stencil.back.depth_fail)});
    return true;
  case GL_STENCIL_BACK_PASS_DEPTH_PASS:
    out.ints({double(ctx.stencil.back.depth_pass)});
    return true;
  case GL_STENCIL_CLEAR_VALUE:
    out.ints({double(ctx.stencil.clear)});
    return true;
  case GL_DEPTH_FUNC:
    out.ints({double(ctx.depth.func)});
    return true;
  case GL_DEPTH_WRITEMASK:
    out.boolean(ctx.depth.mask);
    return true;
  case GL_DEPTH_CLEAR_VALUE:
    out.normalized({ctx.depth.clear});
    return true;
  case GL_BLEND_SRC:
  case GL_BLEND_SRC_RGB:
    out.ints({double(blend.src_rgb)});
    return true;
  case GL_BLEND_DST:
  case GL_BLEND_DST_RGB:
    out.ints({double(blend.dst_rgb)});
    return true;
  case GL_BLEND_SRC_ALPHA:
    out.ints({double(blend.src_a)});
    return true;
  case GL_BLEND_DST_ALPHA:
    out.ints({double(blend.dst_a)});
    return true;
  case GL_BLEND_EQUATION:
    out.ints({double(blend.eq_rgb)});
    return true;
  case GL_BLEND_EQUATION_ALPHA:
    out.ints({double(blend.eq_a)});
    return true;
  case GL_BLEND_COLOR:
    out.normalized(blend.color, 4);
    return true;
  case GL_LOGIC_OP_MODE:
    out.ints({double(cb.logic_op)});
    return true;
  case GL_COLOR_WRITEMASK:
    out.booleans(cb.color_mask, 4);
    return true;
  case GL_COLOR_CLEAR_VALUE:
    out.normalized(cb.clear_color, 4);
    return true;
  // Table 6.21: the mask's 32 bits read as a signed integer (all ones read -1, as in Mesa).
  case GL_INDEX_WRITEMASK:
    out.ints({double(int32_t(cb.index_writemask))});
    return true;
  case GL_INDEX_CLEAR_VALUE:
    out.ints({double(cb.index_clear)});
    return true;
  default:
    return false;
  }
}

constexpr Capability kFragmentCaps[] = {
    // GL 2.1 §4.1.2, §4.1.4, §4.1.5, §4.1.6, §4.1.8, §4.1.10.
    {GL_SCISSOR_TEST, 1, CapabilityKind::kServer, kDirtyFragment,
     [](Context& c, unsigned, unsigned) { return &c.scissor.test; }},
    {GL_ALPHA_TEST, 1, CapabilityKind::kServer, kDirtyFragment,
     [](Context& c, unsigned, unsigned) { return &c.color_buffer.alpha_test; }},
    {GL_STENCIL_TEST, 1, CapabilityKind::kServer, kDirtyFragment,
     [](Context& c, unsigned, unsigned) { return &c.stencil.test; }},
    {GL_DEPTH_TEST, 1, CapabilityKind::kServer, kDirtyFragment,
     [](Context& c, unsigned, unsigned) { return &c.depth.test; }},
    {GL_BLEND, 1, CapabilityKind::kServer, kDirtyFragment,
     [](Context& c, unsigned, unsigned) { return &c.color_buffer.blend; }},
    {GL_COLOR_LOGIC_OP, 1, CapabilityKind::kServer, kDirtyFragment,
     [](Context& c, unsigned, unsigned) { return &c.color_buffer.color_logic_op; }},
    // GL_LOGIC_OP is the same enum. Index logic ops have no effect in RGBA mode, but the
    // enable is state all the same.
    {GL_INDEX_LOGIC_OP, 1, CapabilityKind::kServer, 0,
     [](Context& c, unsigned, unsigned) { return &c.color_buffer.index_logic_op; }},
    // GL 2.1 §4.1.9: dithering may be a no-op; the flag is still state.
    {GL_DITHER, 1, CapabilityKind::kServer, 0,
     [](Context& c, unsigned, unsigned) { return &c.color_buffer.dither; }},
};

constexpr AttribGroup kFragmentGroups[] = {
    member_group<&Context::scissor>(GL_SCISSOR_BIT, kDirtyFragment),
    member_group<&Context::color_buffer>(GL_COLOR_BUFFER_BIT, kDirtyFragment),
    member_group<&Context::depth>(GL_DEPTH_BUFFER_BIT, kDirtyFragment),
    member_group<&Context::stencil>(GL_STENCIL_BUFFER_BIT, kDirtyFragment),
};

} // namespace

const StateArea kFragmentArea = {
    .name = "per-fragment operations and framebuffer control (GL 2.1 §4.1, §4.2, "
            "Tables 6.20-6.22)",
    .capabilities = kFragmentCaps,
    .get = get_fragment,
    .groups = kFragmentGroups,
};

namespace exec {

void GLAPIENTRY Scissor(GLint x, GLint y, GLsizei width, GLsizei height) {
  PINEDA_CTX_OUTSIDE("glScissor");
  // GL 2.1 §4.1.2: a negative width or height is INVALID_VALUE.
  if (width < 0 || height < 0) return record_error(ctx, GL_INVALID_VALUE, "glScissor");
  ctx->scissor.box[0] = x;
  ctx->scissor.box[1] = y;
  ctx->scissor.box[2] = width;
  ctx->scissor.box[3] = height;
  mark_dirty(ctx, kDirtyFragment);
}

void GLAPIENTRY AlphaFunc(GLenum func, GLclampf ref) {
  PINEDA_CTX_OUTSIDE("glAlphaFunc");
  if (!is_compare_func(func)) return record_error(ctx, GL_INVALID_ENUM, "glAlphaFunc", func);
  ctx->color_buffer.alpha_func = func;
  // GL 2.1 §4.1.4: the reference is clamped to [0, 1] when specified.
  ctx->color_buffer.alpha_ref = clampf01(ref);
  mark_dirty(ctx, kDirtyFragment);
}

void GLAPIENTRY StencilFunc(GLenum func, GLint ref, GLuint mask) {
  StencilFuncSeparate(GL_FRONT_AND_BACK, func, ref, mask);
}

// GL 2.1 §4.1.5: StencilFunc sets both faces, StencilFuncSeparate the faces `face` names.
void GLAPIENTRY StencilFuncSeparate(GLenum face, GLenum func, GLint ref, GLuint mask) {
  const char* name = face == GL_FRONT_AND_BACK ? "glStencilFunc" : "glStencilFuncSeparate";
  PINEDA_CTX_OUTSIDE(name);
  StencilFace* faces[2] = {};
  const int n = stencil_faces(*ctx, face, faces);
  if (n == 0) return record_error(ctx, GL_INVALID_ENUM, name, face);
  if (!is_compare_func(func)) return record_error(ctx, GL_INVALID_ENUM, name, func);
  // The reference is kept as given: the clamp to [0, 2^s - 1] depends on the stencil buffer
  // and is applied where the value is used or queried.
  for (int i = 0; i < n; ++i) {
    faces[i]->func = func;
    faces[i]->ref = ref;
    faces[i]->value_mask = mask;
  }
  mark_dirty(ctx, kDirtyFragment);
}

void GLAPIENTRY StencilOp(GLenum sfail, GLenum dpfail, GLenum dppass) {
  StencilOpSeparate(GL_FRONT_AND_BACK, sfail, dpfail, dppass);
}

void GLAPIENTRY StencilOpSeparate(GLenum face, GLenum sfail, GLenum dpfail, GLenum dppass) {
  const char* name = face == GL_FRONT_AND_BACK ? "glStencilOp" : "glStencilOpSeparate";
  PINEDA_CTX_OUTSIDE(name);
  StencilFace* faces[2] = {};
  const int n = stencil_faces(*ctx, face, faces);
  if (n == 0) return record_error(ctx, GL_INVALID_ENUM, name, face);
  for (GLenum op : {sfail, dpfail, dppass})
    if (!is_stencil_op(op)) return record_error(ctx, GL_INVALID_ENUM, name, op);
  for (int i = 0; i < n; ++i) {
    faces[i]->fail = sfail;
    faces[i]->depth_fail = dpfail;
    faces[i]->depth_pass = dppass;
  }
  mark_dirty(ctx, kDirtyFragment);
}

void GLAPIENTRY StencilMask(GLuint mask) {
  StencilMaskSeparate(GL_FRONT_AND_BACK, mask);
}

// GL 2.1 §4.2.2: the low s bits are the mask; the value is kept whole, as given.
void GLAPIENTRY StencilMaskSeparate(GLenum face, GLuint mask) {
  const char* name = face == GL_FRONT_AND_BACK ? "glStencilMask" : "glStencilMaskSeparate";
  PINEDA_CTX_OUTSIDE(name);
  StencilFace* faces[2] = {};
  const int n = stencil_faces(*ctx, face, faces);
  if (n == 0) return record_error(ctx, GL_INVALID_ENUM, name, face);
  for (int i = 0; i < n; ++i)
    faces[i]->writemask = mask;
  mark_dirty(ctx, kDirtyFragment);
}

void GLAPIENTRY LogicOp(GLenum opcode) {
  PINEDA_CTX_OUTSIDE("glLogicOp");
  // GL 2.1 table 4.3: CLEAR..SET are sixteen consecutive enums.
  if (opcode < GL_CLEAR || opcode > GL_SET)
    return record_error(ctx, GL_INVALID_ENUM, "glLogicOp", opcode);
  ctx->color_buffer.logic_op = opcode;
  mark_dirty(ctx, kDirtyFragment);
}

} // namespace exec
} // namespace pineda
