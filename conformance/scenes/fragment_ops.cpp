// Per-fragment operations (GL 2.1 §4.1): the scissor test (also on clears, §4.2.3), the alpha
// test, the stencil test with every stencil operation and the depth test's outcomes, the
// logical operation in place of blending, and the stencil write mask (§4.2.2).
//
// Stencil values are made visible by a second pass per bit plane: the pass for bit b draws
// only where that bit is set (glStencilFunc(GL_EQUAL, 1 << b, 1 << b)) and adds a colour in
// which bit b has a different weight in each channel (combined with GL_OR), so the image
// shows every stencil value exactly and a value off by one changes some channel by at least 8.
#include "scene_util.h"

#include <cmath>

using namespace scenes;

namespace {

// The state of this file's operations at its GL defaults: reset_state() does not know them,
// and every repetition of a scene must start from the same state.
void fragment_defaults() {
  for (GLenum cap : {GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_COLOR_LOGIC_OP})
    glDisable(cap);
  glAlphaFunc(GL_ALWAYS, 0.0f);
  glStencilFunc(GL_ALWAYS, 0, 0xffffffffu);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMask(0xffffffffu);
  glClearStencil(0);
  glLogicOp(GL_COPY);
}

// Draws the stencil values of the whole window as colours (see the file comment) over a
// black colour buffer; the depth, alpha and scissor tests and the logic op are off afterwards.
void show_stencil(const Frame& frame) {
  window_projection(frame);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_ALPHA_TEST);
  glDisable(GL_COLOR_LOGIC_OP);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  // Each pass sets bits no other pass sets, so OR adds the passes' colours exactly.
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_OR);
  for (int b = 0; b < 8; ++b) {
    glStencilFunc(GL_EQUAL, 1 << b, 1u << b);
    glColor4f(static_cast<float>(1 << b) / 255.0f, static_cast<float>(1 << ((b + 3) & 7)) / 255.0f,
              static_cast<float>(1 << ((b + 5) & 7)) / 255.0f, 1.0f);
    glRecti(0, 0, frame.width, frame.height);
  }
  glDisable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_COPY);
  glDisable(GL_STENCIL_TEST);
}

void clear_all(float r, float g, float b, int stencil) {
  glClearColor(r, g, b, 1.0f);
  glClearDepth(1.0);
  glClearStencil(stencil);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

// A quad at window depth z (under glOrtho(..., -1, 1), window z = (1 - object z) / 2).
void depth_rect(float x0, float y0, float x1, float y1, float z) {
  const float oz = 1.0f - 2.0f * z;
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, oz);
  glVertex3f(x1, y0, oz);
  glVertex3f(x1, y1, oz);
  glVertex3f(x0, y1, oz);
  glEnd();
}

const GLenum kFuncs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                          GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};

} // namespace

PINEDA_SCENE(frag_scissor_clear, "Scissored clears: nested boxes, boxes partly outside the window, an empty box, masks", .stencil_bits = 8) {
  fragment_defaults();
  clear_all(0.125f, 0.125f, 0.125f, 0);
  glEnable(GL_SCISSOR_TEST);
  for (int i = 0; i < 6; ++i) {
    glScissor(8 + 7 * i, 120 + 6 * i, 112 - 14 * i, 120 - 12 * i);
    const float* c = palette(i);
    glClearColor(c[0], c[1], c[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  // Boxes reaching past every window edge, and one far outside.
  const int boxes[5][4] = {{-30, -30, 60, 50},  {220, -10, 1000, 40}, {-5, 230, 40, 1000},
                           {200, 200, 100, 100}, {5000, 5000, 10, 10}};
  for (int i = 0; i < 5; ++i) {
    glScissor(boxes[i][0], boxes[i][1], boxes[i][2], boxes[i][3]);
    const float* c = palette(i + 6);
    glClearColor(c[0], c[1], c[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  // An empty box clears nothing.
  glScissor(0, 0, 0, 256);
  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glScissor(0, 0, 256, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  // Scissored clears with a colour mask, and of the depth buffer: the depth clear to 0 in a
  // box keeps a later depth-tested quad out of it.
  glScissor(140, 60, 100, 50);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glClearColor(1.0f, 1.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glScissor(150, 130, 40, 40);
  glClearDepth(0.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_DEPTH_TEST);
  glColor3f(0.25f, 1.0f, 0.75f);
  depth_rect(130.0f, 120.0f, 250.0f, 180.0f, 0.5f);
  glDisable(GL_DEPTH_TEST);
  // Scissored stencil clears, shown through the stencil planes in the lower left.
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 120, 110);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  const int stencil_boxes[4][5] = {
      {4, 4, 100, 90, 0x5a}, {20, 10, 40, 70, 0xff}, {70, 30, 40, 60, 0x01}, {10, 60, 90, 20, 0x80}};
  for (const auto& b : stencil_boxes) {
    glScissor(b[0], b[1], b[2], b[3]);
    glClearStencil(b[4]);
    glClear(GL_STENCIL_BUFFER_BIT);
  }
  glDisable(GL_SCISSOR_TEST);
  show_stencil(frame);
}

PINEDA_SCENE(frag_scissor_draw, "Scissor boxes clipping triangles, lines and points, and a box per panel", .stencil_bits = 8) {
  fragment_defaults();
  clear_all(0.0f, 0.0f, 0.0f, 0);
  glEnable(GL_SCISSOR_TEST);
  // Smooth triangles over the whole window, cut by a box.
  glScissor(10, 140, 110, 100);
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 0.125f, 0.125f);
  glVertex2f(-20.0f, 130.0f);
  glColor3f(0.125f, 1.0f, 0.125f);
  glVertex2f(200.0f, 150.0f);
  glColor3f(0.25f, 0.375f, 1.0f);
  glVertex2f(60.0f, 300.0f);
  glEnd();
  // Lines in every direction, cut by another box.
  glScissor(136, 136, 100, 100);
  glBegin(GL_LINES);
  for (int i = 0; i < 24; ++i) {
    const float a = 2.0f * kPi * static_cast<float>(i) / 24.0f + 0.05f;
    palette_color(i);
    glVertex2f(186.3f, 186.2f);
    glVertex2f(186.3f + 90.0f * std::cos(a), 186.2f + 90.0f * std::sin(a));
  }
  for (int i = 0; i < 10; ++i) {
    palette_color(i + 3);
    glVertex2f(120.3f, 140.6f + 10.0f * i);
    glVertex2f(255.3f, 140.6f + 10.0f * i);
  }
  glEnd();
  // A grid of points, cut by a third box.
  glScissor(20, 20, 83, 77);
  glBegin(GL_POINTS);
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 60; ++x) {
      palette_color(x + y);
      glVertex2f(2.5f + 2.0f * x, 2.5f + 2.0f * y);
    }
  glEnd();
  // Panels drawn with one full-window quad each under a box inside the panel.
  for (int p = 0; p < 4; ++p) {
    const int x = 132 + 30 * p, y = 10 + 8 * p;
    glScissor(x, y, 26 - 4 * p, 100 - 16 * p);
    palette_color(p + 8);
    glRecti(0, 0, 256, 256);
  }
  glDisable(GL_SCISSOR_TEST);
}

PINEDA_SCENE(frag_alpha_test, "glAlphaFunc: the eight functions on steps of alpha and on a smooth alpha ramp", .stencil_bits = 8) {
  fragment_defaults();
  clear_all(0.0f, 0.0f, 0.25f, 0);
  glEnable(GL_ALPHA_TEST);
  // Alphas k/16 and references (2k+1)/32 never convert on a rounding tie (GL 2.1 §2.14.9).
  for (int f = 0; f < 8; ++f) {
    const Panel pn = panel(frame, f, 2, 4);
    glAlphaFunc(kFuncs[f], 7.0f / 16.0f);
    for (int k = 0; k <= 16; ++k) {
      const float* c = palette(k);
      glColor4f(c[0], c[1], c[2], static_cast<float>(k) / 16.0f);
      const float x = static_cast<float>(pn.w) * static_cast<float>(k) / 17.0f;
      glRectf(x, static_cast<float>(pn.h) * 0.55f, x + static_cast<float>(pn.w) / 17.0f,
              static_cast<float>(pn.h));
    }
    // A smooth ramp of alpha against a reference between steps (the top edge kept 1/8 pixel
    // off the pixel centres, whose owner is the implementation's choice, GL 2.1 §3.5.1).
    glAlphaFunc(kFuncs[f], 21.0f / 32.0f);
    const float top = std::floor(static_cast<float>(pn.h) * 0.5f) + 0.125f;
    glBegin(GL_QUADS);
    glColor4f(1.0f, 1.0f, 1.0f, 0.0f);
    glVertex2f(0.0f, 2.0f);
    glColor4f(1.0f, 0.5f, 0.0f, 1.0f);
    glVertex2f(static_cast<float>(pn.w), 2.0f);
    glVertex2f(static_cast<float>(pn.w), top);
    glColor4f(1.0f, 1.0f, 1.0f, 0.0f);
    glVertex2f(0.0f, top);
    glEnd();
  }
  glDisable(GL_ALPHA_TEST);
}

PINEDA_SCENE(frag_alpha_depth, "Alpha test before the depth test: discarded fragments write no depth, clamped references", .stencil_bits = 8) {
  fragment_defaults();
  clear_all(0.0f, 0.0f, 0.0f, 0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_ALPHA_TEST);
  // Near alpha-tested bars with a smooth alpha across them, then a far quad: the far quad
  // shows where the near fragments failed the alpha test, because they wrote no depth.
  const float refs[4] = {-1.0f, 0.25f, 0.75f, 2.0f}; // clamped to 0 and 1 by glAlphaFunc
  for (int i = 0; i < 4; ++i) {
    glAlphaFunc(GL_GREATER, refs[i]);
    const float y0 = 8.0f + 62.0f * i;
    glBegin(GL_QUADS);
    glColor4f(1.0f, 0.125f, 0.125f, 0.0f);
    glVertex3f(8.0f, y0, 0.5f);
    glColor4f(1.0f, 0.875f, 0.125f, 1.0f);
    glVertex3f(248.0f, y0, 0.5f);
    glVertex3f(248.0f, y0 + 54.0f, 0.5f);
    glColor4f(1.0f, 0.125f, 0.125f, 0.0f);
    glVertex3f(8.0f, y0 + 54.0f, 0.5f);
    glEnd();
  }
  glAlphaFunc(GL_ALWAYS, 0.0f);
  glColor4f(0.25f, 0.375f, 1.0f, 1.0f);
  depth_rect(0.0f, 0.0f, 256.0f, 256.0f, 0.6f);
  glDisable(GL_ALPHA_TEST);
  glDisable(GL_DEPTH_TEST);
}

PINEDA_SCENE(frag_stencil_overdraw, "Stencil counting overdraw with INCR, shown per bit plane", .stencil_bits = 8) {
  fragment_defaults();
  clear_all(0.0f, 0.0f, 0.0f, 0);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_INCR, GL_INCR, GL_INCR);
  // Overlapping triangle fans: each pixel counts how many triangles covered it.
  Rng rng(77);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 120; ++i) {
    const float cx = rng.range(20.0f, 236.0f), cy = rng.range(20.0f, 236.0f);
    for (int k = 0; k < 3; ++k) {
      const float a = rng.range(0.0f, 2.0f * kPi);
      const float r = rng.range(10.0f, 70.0f);
      glVertex2f(snap(cx + r * std::cos(a)), snap(cy + r * std::sin(a)));
    }
  }
  glEnd();
  // 300 layers over one strip saturate at 255 with INCR.
  glBegin(GL_QUADS);
  for (int i = 0; i < 300; ++i) {
    glVertex2f(4.0f, 4.0f);
    glVertex2f(252.0f, 4.0f);
    glVertex2f(252.0f, 14.0f);
    glVertex2f(4.0f, 14.0f);
  }
  glEnd();
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  show_stencil(frame);
}

PINEDA_SCENE(frag_stencil_ops, "The eight stencil operations from three start values, one, two and three layers deep", .stencil_bits = 8) {
  fragment_defaults();
  clear_all(0.0f, 0.0f, 0.0f, 0);
  const GLenum ops[8] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR,
                         GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};
  const int starts[3] = {0, 254, 0x5a};
  glEnable(GL_SCISSOR_TEST);
  glEnable(GL_STENCIL_TEST);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  for (int op = 0; op < 8; ++op) {
    for (int s = 0; s < 3; ++s) {
      const int x = 4 + 31 * op, y = 4 + 84 * s;
      glScissor(x, y, 28, 80);
      glClearStencil(starts[s]);
      glClear(GL_STENCIL_BUFFER_BIT);
      glStencilFunc(GL_ALWAYS, 0x33, 0xff);
      glStencilOp(ops[op], ops[op], ops[op]);
      // Three overlapping layers: bottom rows see one, middle two, top three.
      for (int layer = 0; layer < 3; ++layer)
        glRecti(x, y + 20 * layer, x + 28, y + 80);
    }
  }
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  show_stencil(frame);
}

PINEDA_SCENE(frag_stencil_depth, "sfail, dpfail and dppass: z-fail shadow-volume counting with INCR_WRAP / DECR_WRAP", .stencil_bits = 8) {
  fragment_defaults();
  clear_all(0.0f, 0.0f, 0.0f, 0);
  glEnable(GL_DEPTH_TEST);
  // Depth-only receivers: a floor of steps at different depths.
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  for (int i = 0; i < 4; ++i) depth_rect(0.0f, 64.0f * i, 256.0f, 64.0f * (i + 1), 0.3f + 0.12f * i);
  // "Volumes": back faces increment on depth fail, front faces decrement on depth fail
  // (Carmack's reverse), each volume a box from depth 0.2 to 0.5 drawn as a front and a back
  // quad with culling.
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glDepthMask(GL_FALSE);
  glEnable(GL_CULL_FACE);
  const float boxes[5][4] = {{20, 20, 120, 230}, {60, 40, 200, 120}, {150, 10, 240, 250},
                             {90, 150, 230, 210}, {30, 100, 60, 180}};
  const float zfar[5] = {0.5f, 0.65f, 0.8f, 0.35f, 0.95f};
  for (int pass = 0; pass < 2; ++pass) {
    glCullFace(pass == 0 ? GL_FRONT : GL_BACK);
    glStencilOp(GL_KEEP, pass == 0 ? GL_INCR_WRAP : GL_DECR_WRAP, GL_KEEP);
    for (int b = 0; b < 5; ++b) {
      const float* r = boxes[b];
      const float zn = 1.0f - 2.0f * 0.2f, zf = 1.0f - 2.0f * zfar[b];
      glBegin(GL_QUADS);
      // Front face (counter-clockwise) near, back face (clockwise) far.
      glVertex3f(r[0], r[1], zn);
      glVertex3f(r[2], r[1], zn);
      glVertex3f(r[2], r[3], zn);
      glVertex3f(r[0], r[3], zn);
      glVertex3f(r[0], r[1], zf);
      glVertex3f(r[0], r[3], zf);
      glVertex3f(r[2], r[3], zf);
      glVertex3f(r[2], r[1], zf);
      glEnd();
    }
  }
  glDisable(GL_CULL_FACE);
  glDepthMask(GL_TRUE);
  // Distinct sfail / dpfail / dppass on one more layer: a stencil test that fails where the
  // count is 2, then REPLACE where the depth test fails and INVERT where it passes.
  glStencilFunc(GL_NOTEQUAL, 2, 0xff);
  glStencilOp(GL_ZERO, GL_REPLACE, GL_INVERT);
  glDepthFunc(GL_LESS);
  depth_rect(100.0f, 30.0f, 250.0f, 90.0f, 0.36f);
  glDepthFunc(GL_LESS);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  show_stencil(frame);
}

PINEDA_SCENE(frag_stencil_decal, "Stencil decals: REPLACE a mask, then draw only where EQUAL; value masks and write masks", .stencil_bits = 8) {
  fragment_defaults();
  clear_all(0.0f, 0.0f, 0.0f, 0);
  glEnable(GL_STENCIL_TEST);
  // Base shapes write their id into the low nibble (write mask 0x0f).
  glStencilMask(0x0f);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  for (int i = 0; i < 6; ++i) {
    glStencilFunc(GL_ALWAYS, 0xf0 | (i + 1), 0xff);
    palette_color(i);
    glBegin(GL_TRIANGLE_FAN);
    const float cx = 44.0f + 84.0f * (i % 3), cy = 70.0f + 110.0f * (i / 3);
    glVertex2f(cx, cy);
    for (int k = 0; k <= 7; ++k) {
      const float a = 2.0f * kPi * static_cast<float>(k % 7) / 7.0f + 0.1f * i;
      glVertex2f(cx + 40.0f * std::cos(a), cy + 46.0f * std::sin(a));
    }
    glEnd();
  }
  glStencilMask(0xffffffffu);
  // Decals: stripes across everything, kept where the stored id matches; the value mask
  // 0x0f makes the high nibble of the reference irrelevant.
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  for (int i = 0; i < 6; ++i) {
    glStencilFunc(GL_EQUAL, 0xa0 | (i + 1), 0x0f);
    glColor3f(1.0f, 1.0f, 1.0f);
    for (int s = 0; s < 20; ++s) {
      const float y = 13.0f * s + 2.0f * i;
      glBegin(GL_QUADS);
      glVertex2f(0.0f, y);
      glVertex2f(256.0f, y + 30.0f);
      glVertex2f(256.0f, y + 34.0f);
      glVertex2f(0.0f, y + 4.0f);
      glEnd();
    }
  }
  // LESS / GREATER on the masked values: ref 3 < stored id, ref 3 > stored id.
  glStencilFunc(GL_LESS, 3, 0x0f);
  glColor3f(0.125f, 0.125f, 0.125f);
  glRecti(0, 150, 256, 170);
  glStencilFunc(GL_GREATER, 3, 0x0f);
  glColor3f(0.0f, 1.0f, 1.0f);
  glRecti(0, 40, 256, 60);
  glDisable(GL_STENCIL_TEST);
}

PINEDA_SCENE(frag_logic_ops, "The sixteen glLogicOp operations over a colour pattern, with blending on (ignored)", .stencil_bits = 8) {
  fragment_defaults();
  clear_all(0.0f, 0.0f, 0.0f, 0);
  // Blending is on throughout: with COLOR_LOGIC_OP enabled it must have no effect
  // (GL 2.1 §4.1.10).
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int op = 0; op < 16; ++op) {
    const Panel pn = panel(frame, op, 4, 4);
    // Destination: vertical stripes of palette colours, drawn without the logic op.
    glDisable(GL_COLOR_LOGIC_OP);
    glDisable(GL_BLEND);
    // Edges are moved by 1/8 pixel off the pixel centres a division can land on (61 / 2),
    // whose owner is the implementation's choice (GL 2.1 §3.5.1).
    for (int s = 0; s < 6; ++s) {
      palette_color(s + op);
      glRectf(static_cast<float>(pn.w) * s / 6.0f + 0.125f, 0.0f,
              static_cast<float>(pn.w) * (s + 1) / 6.0f + 0.125f, static_cast<float>(pn.h));
    }
    glEnable(GL_BLEND);
    // Source: horizontal stripes with alpha 3/8, combined by the operation.
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(static_cast<GLenum>(GL_CLEAR + op));
    for (int s = 0; s < 5; ++s) {
      palette_color(3 * s + 1, 0.375f);
      glRectf(0.0f, static_cast<float>(pn.h) * s / 5.0f + 1.125f, static_cast<float>(pn.w),
              static_cast<float>(pn.h) * (s + 1) / 5.0f + 0.125f);
    }
  }
  glDisable(GL_COLOR_LOGIC_OP);
  glDisable(GL_BLEND);
  glLogicOp(GL_COPY);
}

PINEDA_SCENE(frag_write_masks, "Stencil write masks on drawing and clears, with colour and depth masks", .stencil_bits = 8) {
  fragment_defaults();
  clear_all(0.0f, 0.0f, 0.0f, 0xff);
  glEnable(GL_STENCIL_TEST);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  // Column c: INVERT under write mask c-dependent; row r: INCR_WRAP r times under the mask.
  const GLuint masks[8] = {0x00, 0x01, 0x0f, 0xf0, 0x55, 0xaa, 0x80, 0xff};
  for (int c = 0; c < 8; ++c) {
    glStencilMask(masks[c]);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_INVERT, GL_INVERT, GL_INVERT);
    glRecti(32 * c, 0, 32 * c + 30, 128);
    glStencilOp(GL_INCR_WRAP, GL_INCR_WRAP, GL_INCR_WRAP);
    for (int r = 0; r < 4; ++r) glRecti(32 * c, 32 * r, 32 * c + 30, 128);
    // Masked stencil clears in the upper half.
    glEnable(GL_SCISSOR_TEST);
    glScissor(32 * c, 130, 30, 60);
    glClearStencil(0x3c);
    glClear(GL_STENCIL_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
  }
  glStencilMask(0xffffffffu);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  show_stencil(frame);
  // Top strip: a depth-masked stencil-tested layer and colour-masked layers.
  glEnable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);
  glStencilFunc(GL_EQUAL, 0xff, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_FALSE);
  glColor3f(1.0f, 1.0f, 0.25f);
  depth_rect(0.0f, 196.0f, 256.0f, 226.0f, 0.5f);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glColor3f(0.25f, 1.0f, 0.25f);
  depth_rect(0.0f, 210.0f, 256.0f, 256.0f, 0.7f);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
}

PINEDA_SCENE(frag_combined, "Scissor, alpha, stencil and depth tests with blending and a logic op, in BGRA", .format = OSMESA_BGRA, .stencil_bits = 8) {
  fragment_defaults();
  clear_all(0.125f, 0.0f, 0.25f, 0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  // A ring of stencil 1 from a fan, drawn with colour.
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glBegin(GL_TRIANGLE_FAN);
  glColor4f(0.25f, 0.25f, 0.5f, 1.0f);
  glVertex3f(128.0f, 128.0f, 0.0f);
  for (int k = 0; k <= 40; ++k) {
    const float a = 2.0f * kPi * static_cast<float>(k % 40) / 40.0f;
    glColor4f(0.5f + 0.5f * std::cos(a), 0.5f, 0.5f + 0.5f * std::sin(a), 1.0f);
    glVertex3f(128.0f + 110.0f * std::cos(a), 128.0f + 110.0f * std::sin(a), 0.6f);
  }
  glEnd();
  // Alpha-tested, blended, scissored triangles where the stencil is 1, counting with INCR.
  glEnable(GL_SCISSOR_TEST);
  glScissor(30, 20, 200, 190);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GEQUAL, 0.3f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glStencilFunc(GL_EQUAL, 1, 0x01);
  glStencilOp(GL_KEEP, GL_DECR, GL_INCR);
  Rng rng(4242);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 40; ++i) {
    const float cx = rng.range(20.0f, 236.0f), cy = rng.range(20.0f, 236.0f);
    for (int k = 0; k < 3; ++k) {
      const float* c = palette(i + k);
      glColor4f(c[0], c[1], c[2], rng.range(0.0f, 1.0f));
      glVertex3f(snap(cx + rng.range(-30.0f, 30.0f)), snap(cy + rng.range(-30.0f, 30.0f)),
                 rng.range(-0.9f, 0.9f));
    }
  }
  glEnd();
  glDisable(GL_BLEND);
  glDisable(GL_ALPHA_TEST);
  // INVERT over odd stencil values only. (Operations that mix source and destination bits
  // would turn a one-step difference in a smooth destination into a large one.)
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_INVERT);
  glStencilFunc(GL_EQUAL, 1, 0x01);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glColor3f(0.75f, 0.375f, 0.0f);
  glRecti(0, 100, 256, 160);
  glDisable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_COPY);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_STENCIL_TEST);
}
