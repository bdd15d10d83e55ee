// glBlendEquationSeparate (GL 2.1 §4.1.8, EXT_blend_equation_separate): its errors, the
// BLEND_EQUATION_RGB (= BLEND_EQUATION) and BLEND_EQUATION_ALPHA queries, the colour-buffer
// attribute group, display lists, and RGB and alpha blended with their own equations.
#define GL_GLEXT_PROTOTYPES
#include "api_fixture.h"

namespace {

using BlendEquationSeparate = GLTest;

GLint get_int(GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  return v;
}

TEST_F(BlendEquationSeparate, QueriesErrorsStackAndLists) {
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_RGB), GL_FUNC_ADD);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_ALPHA), GL_FUNC_ADD);
  glBlendEquationSeparate(GL_FUNC_SUBTRACT, GL_MAX);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_RGB), GL_FUNC_SUBTRACT);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION), GL_FUNC_SUBTRACT); // the same enum
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_ALPHA), GL_MAX);
  // GL 2.1 §4.1.8: either equation outside the five is INVALID_ENUM; nothing changes.
  glBlendEquationSeparate(GL_FUNC_ADD, GL_ONE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glBlendEquationSeparate(GL_LOGIC_OP, GL_FUNC_ADD);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_RGB), GL_FUNC_SUBTRACT);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_ALPHA), GL_MAX);
  glBegin(GL_TRIANGLES);
  glBlendEquationSeparate(GL_MIN, GL_MIN);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_RGB), GL_FUNC_SUBTRACT);
  // BlendEquation sets both.
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_ALPHA), GL_FUNC_REVERSE_SUBTRACT);
  glPopAttrib();
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_RGB), GL_FUNC_SUBTRACT);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_ALPHA), GL_MAX);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBlendEquationSeparate(GL_MIN, GL_FUNC_REVERSE_SUBTRACT);
  glEndList();
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_RGB), GL_FUNC_SUBTRACT);
  glCallList(list);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_RGB), GL_MIN);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_ALPHA), GL_FUNC_REVERSE_SUBTRACT);
  glDeleteLists(list, 1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// Destination (0.5, 0.5, 0.5, 0.5), source (1, 0.25, 0, 0.75), factors ONE, ONE: RGB and
// alpha each take their own equation.
TEST_F(BlendEquationSeparate, EachPartHasItsEquation) {
  struct Case {
    GLenum rgb, alpha;
    uint32_t expect; // 0xAABBGGRR
  };
  const Case cases[] = {
      {GL_FUNC_ADD, GL_FUNC_SUBTRACT, 0x3f80c0ffu},    // a = 0.75 - 0.5
      {GL_FUNC_SUBTRACT, GL_FUNC_ADD, 0xff00007fu},    // rgb = src - dst clamped
      {GL_FUNC_REVERSE_SUBTRACT, GL_MIN, 0x80804000u}, // rgb = dst - src, a = min
      {GL_MIN, GL_MAX, 0xbf004080u},                   // rgb = min, a = max
      {GL_MAX, GL_FUNC_REVERSE_SUBTRACT, 0x008080ffu}, // a = 0.5 - 0.75 clamped
  };
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  for (const Case& c : cases) {
    glDisable(GL_BLEND);
    glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendEquationSeparate(c.rgb, c.alpha);
    glColor4f(1.0f, 0.25f, 0.0f, 0.75f);
    glRectf(-1, -1, 1, 1);
    const uint32_t p = pixel(3, 3);
    for (int k = 0; k < 4; ++k) {
      const int got = static_cast<int>((p >> (8 * k)) & 0xff);
      const int want = static_cast<int>((c.expect >> (8 * k)) & 0xff);
      EXPECT_NEAR(got, want, 1) << std::hex << c.rgb << " " << c.alpha << " channel " << k;
    }
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

} // namespace
