// Per-fragment operations and whole-framebuffer control (GL 2.1 §4.1, §4.2; Tables 6.20-6.22
// "Pixel Operations" and "Framebuffer Control", the "scissor", "color-buffer",
// "depth-buffer", "stencil-buffer" and "accum-buffer" attribute groups). Commands in
// fragment_state.cpp (scissor, alpha, stencil, logic op), blend.cpp, depth.cpp, buffers.cpp
// (clear values, colour mask), color_index.cpp (index mask and clear value), accum.cpp and
// draw_read_buffer.cpp (DrawBuffer). The back end sees them through RasterState
// (core/raster_state.h), which embeds BlendState and StencilFace as they are here.
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "core/raster_state.h"

namespace pineda {

struct StateArea;

// SCISSOR_BIT: Table 6.20 (SCISSOR_TEST is also "enable").
struct ScissorGroup {
  bool test = false;
  GLint box[4] = {0, 0, 0, 0}; // x, y, width, height; the window size once current
};

// COLOR_BUFFER_BIT: Tables 6.20-6.22 (ALPHA_TEST, BLEND, DITHER, INDEX_LOGIC_OP and
// COLOR_LOGIC_OP are also "enable").
struct ColorBufferGroup {
  bool alpha_test = false;
  GLenum alpha_func = GL_ALWAYS;
  float alpha_ref = 0.0f;
  bool blend = false;
  BlendState blend_state; // factors, equations, constant colour (§4.1.8)
  bool dither = true;
  bool color_logic_op = false;
  bool index_logic_op = false; // state only: Pineda has no colour index mode (§4.1.10)
  GLenum logic_op = GL_COPY;
  // §4.2.1, §4.3.2: FRONT when the context has no back buffer, BACK otherwise; a window-system
  // layer that gives the context a back buffer sets it (and PixelGroup::read_buffer) to BACK.
  // DRAW_BUFFERi (GL 2.0 §4.2.1 DrawBuffers) of the bound draw framebuffer; DRAW_BUFFER is
  // [0]. A framebuffer object keeps its own while another is bound (framebuffer_object.h).
  GLenum draw_buffers[kMaxDrawBuffers] = {GL_FRONT};
  GLuint index_writemask = ~0u; // INDEX_WRITEMASK (all ones)
  bool color_mask[4] = {true, true, true, true};
  float clear_color[4] = {0, 0, 0, 0};
  int32_t index_clear = 0; // INDEX_CLEAR_VALUE: the integer part (§4.2.3)
};

// DEPTH_BUFFER_BIT: Tables 6.20-6.22 (DEPTH_TEST is also "enable").
struct DepthGroup {
  bool test = false;
  GLenum func = GL_LESS;
  bool mask = true;
  double clear = 1.0;
};

// STENCIL_BUFFER_BIT: Tables 6.20-6.22 (STENCIL_TEST is also "enable"). The GL 1.5 commands
// set both faces; GL 2.0's StencilFuncSeparate, StencilOpSeparate and StencilMaskSeparate set
// one, and the front face's state is what the GL 1.5 queries read.
struct StencilGroup {
  bool test = false;
  StencilFace front, back;
  GLint clear = 0;
};

// ACCUM_BUFFER_BIT: Table 6.22.
struct AccumGroup {
  float clear[4] = {0, 0, 0, 0}; // ACCUM_CLEAR_VALUE, clamped to [-1, 1]
};

extern const StateArea kFragmentArea; // fragment_state.cpp
extern const StateArea kAccumArea;    // accum.cpp

} // namespace pineda
