// GL 2.0 separate stencil (GL 2.1 §4.1.5, §4.2.2): glStencilFuncSeparate, glStencilOpSeparate,
// glStencilMaskSeparate; their errors, the STENCIL_BACK_* queries, the attribute stack, display
// lists, and the face each primitive uses: back-facing polygons the back state, points, lines,
// front-facing polygons, bitmaps and pixel rectangles the front state.
#define GL_GLEXT_PROTOTYPES
#include "api_fixture.h"

namespace {

using StencilSeparate = GLTest;

GLint get_int(GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  return v;
}

GLint stencil_at(int x, int y) {
  GLubyte s = 0;
  glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
  return s;
}

// Pixel-unit projection: (x, y) are window coordinates.
void pixel_ortho() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 32, 0, 32, -1, 1); // the fixture's 32x32 buffer
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

// A rectangle over [x0, x1] x [y0, y1], counter-clockwise (front facing) or clockwise.
void rect(float x0, float y0, float x1, float y1, bool ccw) {
  glBegin(GL_QUADS);
  if (ccw) {
    glVertex2f(x0, y0), glVertex2f(x1, y0), glVertex2f(x1, y1), glVertex2f(x0, y1);
  } else {
    glVertex2f(x0, y0), glVertex2f(x0, y1), glVertex2f(x1, y1), glVertex2f(x1, y0);
  }
  glEnd();
}

TEST_F(StencilSeparate, InitialBackState) {
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FUNC), GL_ALWAYS);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_REF), 0);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_VALUE_MASK), 2147483647); // all ones, clamped
  EXPECT_EQ(get_int(GL_STENCIL_BACK_WRITEMASK), 2147483647);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FAIL), GL_KEEP);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_PASS_DEPTH_FAIL), GL_KEEP);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_PASS_DEPTH_PASS), GL_KEEP);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(StencilSeparate, EachFaceSetsItsOwnState) {
  glStencilFuncSeparate(GL_BACK, GL_LESS, 300, 0x0f); // 300 reads back clamped to 255
  glStencilOpSeparate(GL_BACK, GL_ZERO, GL_INCR_WRAP, GL_INVERT);
  glStencilMaskSeparate(GL_BACK, 0x3c);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FUNC), GL_LESS);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_REF), 255);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_VALUE_MASK), 0x0f);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FAIL), GL_ZERO);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_PASS_DEPTH_FAIL), GL_INCR_WRAP);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_PASS_DEPTH_PASS), GL_INVERT);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_WRITEMASK), 0x3c);
  // The front state, which the GL 1.5 queries read, is untouched.
  EXPECT_EQ(get_int(GL_STENCIL_FUNC), GL_ALWAYS);
  EXPECT_EQ(get_int(GL_STENCIL_FAIL), GL_KEEP);
  EXPECT_EQ(get_int(GL_STENCIL_WRITEMASK), 2147483647);

  glStencilFuncSeparate(GL_FRONT, GL_EQUAL, 3, 0xff);
  glStencilOpSeparate(GL_FRONT, GL_REPLACE, GL_DECR, GL_INCR);
  glStencilMaskSeparate(GL_FRONT, 0x0f);
  EXPECT_EQ(get_int(GL_STENCIL_FUNC), GL_EQUAL);
  EXPECT_EQ(get_int(GL_STENCIL_REF), 3);
  EXPECT_EQ(get_int(GL_STENCIL_FAIL), GL_REPLACE);
  EXPECT_EQ(get_int(GL_STENCIL_PASS_DEPTH_PASS), GL_INCR);
  EXPECT_EQ(get_int(GL_STENCIL_WRITEMASK), 0x0f);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FUNC), GL_LESS);

  // FRONT_AND_BACK, and the GL 1.5 commands, set both.
  glStencilFuncSeparate(GL_FRONT_AND_BACK, GL_GEQUAL, 7, 0x70);
  EXPECT_EQ(get_int(GL_STENCIL_FUNC), GL_GEQUAL);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FUNC), GL_GEQUAL);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_VALUE_MASK), 0x70);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_PASS_DEPTH_PASS), GL_REPLACE);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FAIL), GL_KEEP);
  glStencilMask(0x81);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_WRITEMASK), 0x81);
  glStencilFunc(GL_NEVER, 1, 2);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FUNC), GL_NEVER);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_REF), 1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(StencilSeparate, Errors) {
  glStencilFuncSeparate(GL_BACK, GL_LESS, 1, 1);
  // GL 2.1 §4.1.5: a face other than FRONT, BACK, FRONT_AND_BACK, a function or an operation
  // outside the lists are INVALID_ENUM, and nothing changes.
  glStencilFuncSeparate(GL_LEFT, GL_EQUAL, 2, 2);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glStencilFuncSeparate(GL_BACK, GL_KEEP, 2, 2);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FUNC), GL_LESS);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_REF), 1);
  glStencilOpSeparate(GL_FRONT_LEFT, GL_KEEP, GL_KEEP, GL_KEEP);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glStencilOpSeparate(GL_BACK, GL_KEEP, GL_LESS, GL_KEEP);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_STENCIL_BACK_PASS_DEPTH_FAIL), GL_KEEP);
  glStencilMaskSeparate(GL_NONE, 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_STENCIL_BACK_WRITEMASK), 2147483647);
  // Between Begin and End: INVALID_OPERATION.
  glBegin(GL_POINTS);
  glStencilFuncSeparate(GL_BACK, GL_NEVER, 0, 0);
  glStencilOpSeparate(GL_BACK, GL_ZERO, GL_ZERO, GL_ZERO);
  glStencilMaskSeparate(GL_BACK, 0);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FUNC), GL_LESS);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FAIL), GL_KEEP);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_WRITEMASK), 2147483647);
}

TEST_F(StencilSeparate, AttribStackAndDisplayLists) {
  glStencilFuncSeparate(GL_BACK, GL_GREATER, 5, 0x1f);
  glStencilOpSeparate(GL_BACK, GL_INVERT, GL_ZERO, GL_DECR_WRAP);
  glStencilMaskSeparate(GL_BACK, 0x55);
  glPushAttrib(GL_STENCIL_BUFFER_BIT);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMask(0xff);
  glPopAttrib();
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FUNC), GL_GREATER);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_REF), 5);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FAIL), GL_INVERT);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_PASS_DEPTH_PASS), GL_DECR_WRAP);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_WRITEMASK), 0x55);
  EXPECT_EQ(get_int(GL_STENCIL_FUNC), GL_ALWAYS);

  // GL 2.1 §5.4: the separate commands are compiled, not executed, under COMPILE.
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glStencilFuncSeparate(GL_BACK, GL_LEQUAL, 9, 0xf0);
  glStencilOpSeparate(GL_BACK, GL_REPLACE, GL_REPLACE, GL_REPLACE);
  glStencilMaskSeparate(GL_BACK, 0x0f);
  glEndList();
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FUNC), GL_GREATER);
  glCallList(list);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FUNC), GL_LEQUAL);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_REF), 9);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FAIL), GL_REPLACE);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_WRITEMASK), 0x0f);
  glDeleteLists(list, 1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// Front-facing polygons, points, lines and pixel rectangles write with the front state;
// back-facing polygons with the back state.
TEST_F(StencilSeparate, FacesSelectTheirState) {
  pixel_ortho();
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFuncSeparate(GL_FRONT, GL_ALWAYS, 0x11, 0xff);
  glStencilFuncSeparate(GL_BACK, GL_ALWAYS, 0x22, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glStencilMaskSeparate(GL_BACK, 0x0f); // the back face writes only the low bits: 0x02
  rect(0, 0, 8, 8, true);               // front
  rect(8, 0, 16, 8, false);             // back
  glBegin(GL_POINTS);
  glVertex2f(20.5f, 4.5f);
  glEnd();
  glBegin(GL_LINES);
  glVertex2f(24, 4.5f);
  glVertex2f(30, 4.5f);
  glEnd();
  glWindowPos2i(0, 20);
  const GLubyte px[4 * 4 * 4] = {};
  glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(stencil_at(4, 4), 0x11);
  EXPECT_EQ(stencil_at(12, 4), 0x02);
  EXPECT_EQ(stencil_at(20, 4), 0x11);
  EXPECT_EQ(stencil_at(26, 4), 0x11);
  EXPECT_EQ(stencil_at(2, 22), 0x11);
  // With FrontFace(CW) the clockwise rectangle is the front one.
  glFrontFace(GL_CW);
  rect(0, 8, 8, 16, true);
  rect(8, 8, 16, 16, false);
  EXPECT_EQ(stencil_at(4, 12), 0x02);
  EXPECT_EQ(stencil_at(12, 12), 0x11);

  // The test itself: back faces pass only where the stencil is 0x02.
  glFrontFace(GL_CCW);
  glStencilFuncSeparate(GL_BACK, GL_EQUAL, 0x02, 0xff);
  glStencilOpSeparate(GL_BACK, GL_ZERO, GL_KEEP, GL_INCR);
  glStencilMaskSeparate(GL_BACK, 0xff);
  glColor3f(1, 0, 0);
  rect(0, 0, 16, 8, false);
  EXPECT_EQ(stencil_at(4, 4), 0x00); // failed: ZERO
  EXPECT_EQ(stencil_at(12, 4), 0x03);
  EXPECT_EQ(pixel(4, 4), 0xffffffffu); // the white of the first pass, kept
  EXPECT_EQ(pixel(12, 4), 0xff0000ffu);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// GL 2.1 §4.1.5: "a primitive is still considered a polygon even if the polygon is to be
// rasterized as points or lines due to the current polygon mode". (llvmpipe gives outlines the
// front state; the conformance scenes do not draw them.)
TEST_F(StencilSeparate, OutlinesOfBackFacesUseTheBackState) {
  pixel_ortho();
  glClear(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFuncSeparate(GL_FRONT, GL_ALWAYS, 1, 0xff);
  glStencilFuncSeparate(GL_BACK, GL_ALWAYS, 2, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  rect(4.5f, 4.5f, 12.5f, 12.5f, false); // back
  rect(4.5f, 20.5f, 12.5f, 28.5f, true); // front
  EXPECT_EQ(stencil_at(4, 8), 2);
  EXPECT_EQ(stencil_at(8, 4), 2);
  EXPECT_EQ(stencil_at(4, 24), 1);
  EXPECT_EQ(stencil_at(8, 8), 0); // not filled
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glPointSize(3);
  rect(20.5f, 4.5f, 28.5f, 12.5f, false);
  rect(20.5f, 20.5f, 28.5f, 28.5f, true);
  EXPECT_EQ(stencil_at(20, 4), 2);
  EXPECT_EQ(stencil_at(28, 12), 2);
  EXPECT_EQ(stencil_at(20, 20), 1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

} // namespace
