// glEnable/glDisable of the client arrays: GL 2.1 §2.8 names EnableClientState for them, but
// Mesa, the tie-breaker, accepts them in Enable/Disable too and programs rely on it.
#include "api_fixture.h"

namespace {

using EnableCompat = GLTest;

TEST_F(EnableCompat, EnableAndDisableTakeClientArrays) {
  for (GLenum array : {GL_VERTEX_ARRAY, GL_COLOR_ARRAY, GL_NORMAL_ARRAY, GL_TEXTURE_COORD_ARRAY,
                       GL_EDGE_FLAG_ARRAY}) {
    glEnable(array);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << array;
    EXPECT_EQ(glIsEnabled(array), GL_TRUE) << array;
    glDisable(array);
    EXPECT_EQ(glIsEnabled(array), GL_FALSE) << array;
  }
}

TEST_F(EnableCompat, ArraysEnabledWithEnableDraw) {
  static const GLfloat pos[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  static const GLfloat col[4][4] = {{0, 1, 0, 1}, {0, 1, 0, 1}, {0, 1, 0, 1}, {0, 1, 0, 1}};
  glVertexPointer(2, GL_FLOAT, 0, pos);
  glColorPointer(4, GL_FLOAT, 0, col);
  glEnable(GL_VERTEX_ARRAY);
  glEnable(GL_COLOR_ARRAY);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
  EXPECT_EQ(pixel(kW / 2, kH / 2), 0xff00ff00u);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

} // namespace
