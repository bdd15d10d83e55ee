// glScissor, glAlphaFunc, glStencilFunc, glStencilOp, glStencilMask, glLogicOp, glDrawBuffer,
// glReadBuffer (GL 2.1 §4.1.2, §4.1.4, §4.1.5, §4.1.10, §4.2.1, §4.2.2, §4.3.2): errors,
// INVALID_OPERATION between Begin and End, state round trips through glGet and glIsEnabled,
// and their effect on drawing and clearing.
#include <functional>
#include <vector>

#include "api_fixture.h"

namespace {

using FragmentState = GLTest;

GLint get_int(GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  return v;
}

void expect_error(GLenum err) { EXPECT_EQ(glGetError(), err); }

TEST_F(FragmentState, InitialState) {
  GLint box[4];
  glGetIntegerv(GL_SCISSOR_BOX, box);
  EXPECT_EQ(box[0], 0);
  EXPECT_EQ(box[1], 0);
  EXPECT_EQ(box[2], kW); // GL 2.1 §4.1.2: the window size
  EXPECT_EQ(box[3], kH);
  for (GLenum cap : {GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_COLOR_LOGIC_OP,
                     GL_INDEX_LOGIC_OP})
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE) << std::hex << cap;
  EXPECT_EQ(get_int(GL_ALPHA_TEST_FUNC), GL_ALWAYS);
  GLfloat ref = -1;
  glGetFloatv(GL_ALPHA_TEST_REF, &ref);
  EXPECT_EQ(ref, 0.0f);
  EXPECT_EQ(get_int(GL_STENCIL_FUNC), GL_ALWAYS);
  EXPECT_EQ(get_int(GL_STENCIL_REF), 0);
  // All ones, which GetIntegerv clamps to the largest integer.
  EXPECT_EQ(get_int(GL_STENCIL_VALUE_MASK), 2147483647);
  EXPECT_EQ(get_int(GL_STENCIL_WRITEMASK), 2147483647);
  EXPECT_EQ(get_int(GL_STENCIL_FAIL), GL_KEEP);
  EXPECT_EQ(get_int(GL_STENCIL_PASS_DEPTH_FAIL), GL_KEEP);
  EXPECT_EQ(get_int(GL_STENCIL_PASS_DEPTH_PASS), GL_KEEP);
  EXPECT_EQ(get_int(GL_LOGIC_OP_MODE), GL_COPY);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(FragmentState, EnablesRoundTrip) {
  for (GLenum cap : {GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_COLOR_LOGIC_OP,
                     GL_INDEX_LOGIC_OP}) {
    glEnable(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_TRUE);
    GLboolean b = GL_FALSE;
    glGetBooleanv(cap, &b);
    EXPECT_EQ(b, GL_TRUE);
    glDisable(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE);
  }
  // GL_LOGIC_OP is GL 1.0's name of INDEX_LOGIC_OP and leaves the colour logic op alone.
  glEnable(GL_LOGIC_OP);
  EXPECT_EQ(glIsEnabled(GL_INDEX_LOGIC_OP), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_COLOR_LOGIC_OP), GL_FALSE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(FragmentState, ScissorRoundTripAndErrors) {
  glScissor(-5, 7, 100000, 3);
  GLint box[4];
  glGetIntegerv(GL_SCISSOR_BOX, box);
  EXPECT_EQ(box[0], -5);
  EXPECT_EQ(box[1], 7);
  EXPECT_EQ(box[2], 100000);
  EXPECT_EQ(box[3], 3);
  glScissor(0, 0, -1, 4);
  expect_error(GL_INVALID_VALUE);
  glScissor(0, 0, 4, -1);
  expect_error(GL_INVALID_VALUE);
  glGetIntegerv(GL_SCISSOR_BOX, box);
  EXPECT_EQ(box[2], 100000); // unchanged by the failed calls
  glScissor(1, 2, 0, 0);     // empty is legal
  expect_error(GL_NO_ERROR);
}

TEST_F(FragmentState, AlphaFuncRoundTripAndErrors) {
  const GLenum funcs[] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                          GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
  for (GLenum f : funcs) {
    glAlphaFunc(f, 0.25f);
    EXPECT_EQ(get_int(GL_ALPHA_TEST_FUNC), static_cast<GLint>(f));
  }
  GLfloat ref = 0;
  glAlphaFunc(GL_LESS, 2.0f); // GL 2.1 §4.1.4: clamped to [0, 1]
  glGetFloatv(GL_ALPHA_TEST_REF, &ref);
  EXPECT_EQ(ref, 1.0f);
  glAlphaFunc(GL_LESS, -3.0f);
  glGetFloatv(GL_ALPHA_TEST_REF, &ref);
  EXPECT_EQ(ref, 0.0f);
  glAlphaFunc(GL_LESS, 0.5f);
  EXPECT_EQ(get_int(GL_ALPHA_TEST_REF), 1073741824); // normalized: 0.5 of the integer range
  glAlphaFunc(GL_ZERO, 0.5f);
  expect_error(GL_INVALID_ENUM);
  glAlphaFunc(GL_NEVER - 1, 0.5f);
  expect_error(GL_INVALID_ENUM);
  glAlphaFunc(GL_ALWAYS + 1, 0.5f);
  expect_error(GL_INVALID_ENUM);
  EXPECT_EQ(get_int(GL_ALPHA_TEST_FUNC), GL_LESS);
}

TEST_F(FragmentState, StencilFuncRoundTripAndErrors) {
  glStencilFunc(GL_GEQUAL, 17, 0xf0u);
  EXPECT_EQ(get_int(GL_STENCIL_FUNC), GL_GEQUAL);
  EXPECT_EQ(get_int(GL_STENCIL_REF), 17);
  EXPECT_EQ(get_int(GL_STENCIL_VALUE_MASK), 0xf0);
  // GL 2.1 §4.1.5: the reference is clamped to [0, 2^s - 1] (s = 8 here).
  glStencilFunc(GL_LESS, 300, 0xff);
  EXPECT_EQ(get_int(GL_STENCIL_REF), 255);
  glStencilFunc(GL_LESS, -4, 0xff);
  EXPECT_EQ(get_int(GL_STENCIL_REF), 0);
  glStencilFunc(GL_KEEP, 1, 1);
  expect_error(GL_INVALID_ENUM);
  EXPECT_EQ(get_int(GL_STENCIL_FUNC), GL_LESS);
}

TEST_F(FragmentState, StencilOpRoundTripAndErrors) {
  const GLenum ops[] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR,
                        GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};
  for (int i = 0; i < 8; ++i) {
    glStencilOp(ops[i], ops[(i + 1) % 8], ops[(i + 2) % 8]);
    EXPECT_EQ(get_int(GL_STENCIL_FAIL), static_cast<GLint>(ops[i]));
    EXPECT_EQ(get_int(GL_STENCIL_PASS_DEPTH_FAIL), static_cast<GLint>(ops[(i + 1) % 8]));
    EXPECT_EQ(get_int(GL_STENCIL_PASS_DEPTH_PASS), static_cast<GLint>(ops[(i + 2) % 8]));
  }
  expect_error(GL_NO_ERROR);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  // One bad enum in any position rejects the whole call.
  glStencilOp(GL_LESS, GL_KEEP, GL_KEEP);
  expect_error(GL_INVALID_ENUM);
  glStencilOp(GL_KEEP, GL_ONE, GL_KEEP);
  expect_error(GL_INVALID_ENUM);
  glStencilOp(GL_ZERO, GL_ZERO, GL_XOR);
  expect_error(GL_INVALID_ENUM);
  EXPECT_EQ(get_int(GL_STENCIL_FAIL), GL_KEEP);
  EXPECT_EQ(get_int(GL_STENCIL_PASS_DEPTH_PASS), GL_KEEP);
}

TEST_F(FragmentState, StencilMaskAndLogicOpRoundTrip) {
  glStencilMask(0x1ffu);
  EXPECT_EQ(get_int(GL_STENCIL_WRITEMASK), 0x1ff);
  for (GLenum op = GL_CLEAR; op <= GL_SET; ++op) {
    glLogicOp(op);
    EXPECT_EQ(get_int(GL_LOGIC_OP_MODE), static_cast<GLint>(op));
  }
  glLogicOp(GL_CLEAR - 1);
  expect_error(GL_INVALID_ENUM);
  glLogicOp(GL_SET + 1);
  expect_error(GL_INVALID_ENUM);
  EXPECT_EQ(get_int(GL_LOGIC_OP_MODE), GL_SET);
}

TEST_F(FragmentState, IllegalBetweenBeginAndEnd) {
  const std::vector<std::function<void()>> calls = {
      [] { glScissor(0, 0, 1, 1); },     [] { glAlphaFunc(GL_LESS, 0.5f); },
      [] { glStencilFunc(GL_LESS, 1, 1); }, [] { glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO); },
      [] { glStencilMask(3); },          [] { glLogicOp(GL_XOR); },
  };
  for (const auto& call : calls) {
    glBegin(GL_POINTS);
    call();
    glEnd();
    expect_error(GL_INVALID_OPERATION);
  }
  // None of them changed anything.
  EXPECT_EQ(get_int(GL_ALPHA_TEST_FUNC), GL_ALWAYS);
  EXPECT_EQ(get_int(GL_STENCIL_FUNC), GL_ALWAYS);
  EXPECT_EQ(get_int(GL_STENCIL_FAIL), GL_KEEP);
  EXPECT_EQ(get_int(GL_STENCIL_WRITEMASK), 2147483647);
  EXPECT_EQ(get_int(GL_LOGIC_OP_MODE), GL_COPY);
  GLint box[4];
  glGetIntegerv(GL_SCISSOR_BOX, box);
  EXPECT_EQ(box[2], kW);
}

// GL 2.1 §4.2.1 / §4.3.2 on a single-buffered, monoscopic context without aux buffers.
TEST_F(FragmentState, DrawAndReadBuffer) {
  EXPECT_EQ(get_int(GL_DRAW_BUFFER), GL_FRONT);
  EXPECT_EQ(get_int(GL_READ_BUFFER), GL_FRONT);
  for (GLenum buf : {GL_FRONT_LEFT, GL_LEFT, GL_FRONT_AND_BACK, GL_NONE, GL_FRONT}) {
    glDrawBuffer(buf);
    expect_error(GL_NO_ERROR);
    EXPECT_EQ(get_int(GL_DRAW_BUFFER), static_cast<GLint>(buf));
  }
  for (GLenum buf : {GL_BACK, GL_BACK_LEFT, GL_BACK_RIGHT, GL_FRONT_RIGHT, GL_RIGHT, GL_AUX0}) {
    glDrawBuffer(buf);
    expect_error(GL_INVALID_OPERATION);
  }
  glDrawBuffer(GL_RGBA);
  expect_error(GL_INVALID_ENUM);
  EXPECT_EQ(get_int(GL_DRAW_BUFFER), GL_FRONT);
  for (GLenum src : {GL_FRONT_LEFT, GL_LEFT, GL_FRONT}) {
    glReadBuffer(src);
    expect_error(GL_NO_ERROR);
    EXPECT_EQ(get_int(GL_READ_BUFFER), static_cast<GLint>(src));
  }
  for (GLenum src : {GL_BACK, GL_BACK_LEFT, GL_BACK_RIGHT, GL_FRONT_RIGHT, GL_RIGHT, GL_AUX3}) {
    glReadBuffer(src);
    expect_error(GL_INVALID_OPERATION);
  }
  // NONE and FRONT_AND_BACK are not GL 2.1 ReadBuffer constants.
  for (GLenum src : {GL_NONE, GL_FRONT_AND_BACK, GL_DEPTH}) {
    glReadBuffer(src);
    expect_error(GL_INVALID_ENUM);
  }
  EXPECT_EQ(get_int(GL_READ_BUFFER), GL_FRONT);
  glBegin(GL_POINTS);
  glDrawBuffer(GL_FRONT);
  glEnd();
  expect_error(GL_INVALID_OPERATION);
  glBegin(GL_POINTS);
  glReadBuffer(GL_FRONT);
  glEnd();
  expect_error(GL_INVALID_OPERATION);
}

// Draw buffer NONE: neither drawing nor glClear touches the colour buffer; depth still does.
TEST_F(FragmentState, DrawBufferNoneDiscardsColour) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kW, 0, kH, -1, 1);
  glClearColor(0, 0, 0, 0);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDrawBuffer(GL_NONE);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glColor4f(1, 0, 0, 1);
  glRecti(0, 0, 16, 16); // z = 0: depth 0.5 written, no colour
  EXPECT_EQ(pixel(4, 4), 0u);
  glDrawBuffer(GL_FRONT);
  glColor4f(0, 1, 0, 1);
  glBegin(GL_QUADS);
  glVertex3f(0, 0, -0.5f); // window depth 0.75: behind what the invisible quad left
  glVertex3f(32, 0, -0.5f);
  glVertex3f(32, 32, -0.5f);
  glVertex3f(0, 32, -0.5f);
  glEnd();
  EXPECT_EQ(pixel(4, 4), 0u);
  EXPECT_EQ(pixel(20, 20), 0xff00ff00u);
  glDisable(GL_DEPTH_TEST);
  expect_error(GL_NO_ERROR);
}

// Drawing through the API: scissored clear and draw, stencil writes read back with
// glReadPixels(GL_STENCIL_INDEX), alpha test and logic op.
TEST_F(FragmentState, EffectsOnDrawingAndClearing) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kW, 0, kH, -1, 1);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(4, 4, 8, 8);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(pixel(4, 4), 0xff0000ffu);
  EXPECT_EQ(pixel(3, 4), 0u);
  EXPECT_EQ(pixel(12, 11), 0u);
  glDisable(GL_SCISSOR_TEST);

  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0x42, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glStencilMask(0x0f);
  glColor4f(0, 1, 0, 1);
  glRecti(0, 0, 16, 32);
  GLubyte s[2] = {0, 0};
  glReadPixels(8, 8, 2, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
  EXPECT_EQ(s[0], 0x02); // write mask 0x0f
  glStencilFunc(GL_EQUAL, 2, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glColor4f(0, 0, 1, 1);
  glRecti(0, 0, 32, 32);
  EXPECT_EQ(pixel(5, 5), 0xffff0000u);  // stencil 2: drawn
  EXPECT_EQ(pixel(20, 5), 0u);          // stencil 0: not drawn
  glDisable(GL_STENCIL_TEST);

  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  glColor4f(1, 1, 1, 0.25f);
  glRecti(16, 0, 32, 32);
  EXPECT_EQ(pixel(20, 5), 0u);
  glColor4f(1, 1, 1, 0.75f);
  glRecti(16, 0, 32, 32);
  EXPECT_EQ(pixel(20, 5), 0xbfffffffu);
  glDisable(GL_ALPHA_TEST);

  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_INVERT);
  glRecti(16, 0, 32, 32);
  EXPECT_EQ(pixel(20, 5), 0x40000000u);
  glDisable(GL_COLOR_LOGIC_OP);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

} // namespace
