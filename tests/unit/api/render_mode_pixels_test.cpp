// Pixel rectangles, bitmaps and raster positions in SELECT and FEEDBACK render modes
// (GL 2.1 §5.2, §5.3): tokens with the raster position, hits from raster positions, and no
// fragments.
#include "api_fixture.h"

#include <array>

namespace {

class RenderModePixels : public GLTest {
protected:
  void SetUp() override {
    GLTest::SetUp();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, kW, 0, kH, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
  }
};

TEST_F(RenderModePixels, FeedbackWritesBitmapDrawAndCopyTokensWithTheRasterPosition) {
  std::array<GLfloat, 64> fb{};
  glFeedbackBuffer(static_cast<GLsizei>(fb.size()), GL_2D, fb.data());
  glRenderMode(GL_FEEDBACK);
  glRasterPos2f(5.0f, 6.0f);
  const GLubyte bits[8] = {0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff};
  glBitmap(8, 8, 0.0f, 0.0f, 3.0f, 1.0f, bits); // moves the raster position to (8, 7)
  const GLubyte rgba[4] = {255, 0, 0, 255};
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glCopyPixels(0, 0, 2, 2, GL_COLOR);
  const GLint values = glRenderMode(GL_RENDER);
  ASSERT_EQ(values, 9);
  EXPECT_EQ(fb[0], static_cast<GLfloat>(GL_BITMAP_TOKEN));
  EXPECT_FLOAT_EQ(fb[1], 5.0f);
  EXPECT_FLOAT_EQ(fb[2], 6.0f);
  EXPECT_EQ(fb[3], static_cast<GLfloat>(GL_DRAW_PIXEL_TOKEN));
  EXPECT_FLOAT_EQ(fb[4], 8.0f);
  EXPECT_FLOAT_EQ(fb[5], 7.0f);
  EXPECT_EQ(fb[6], static_cast<GLfloat>(GL_COPY_PIXEL_TOKEN));
  EXPECT_FLOAT_EQ(fb[7], 8.0f);
  EXPECT_FLOAT_EQ(fb[8], 7.0f);
  // Nothing reached the colour buffer.
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) ASSERT_EQ(pixel(x, y), 0u) << x << "," << y;
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(RenderModePixels, InvalidRasterPositionWritesNoToken) {
  std::array<GLfloat, 16> fb{};
  glFeedbackBuffer(static_cast<GLsizei>(fb.size()), GL_2D, fb.data());
  glRenderMode(GL_FEEDBACK);
  glRasterPos2f(-100.0f, 5.0f); // outside the view volume: invalid (§2.13)
  const GLubyte rgba[4] = {255, 0, 0, 255};
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);
}

TEST_F(RenderModePixels, SelectionCountsAValidRasterPositionAsAHit) {
  std::array<GLuint, 16> sel{};
  glSelectBuffer(static_cast<GLsizei>(sel.size()), sel.data());
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(7);
  glRasterPos3f(4.0f, 4.0f, 0.0f); // window z 0.5
  glLoadName(8);
  glRasterPos2f(-50.0f, 4.0f); // invalid: no hit
  const GLubyte rgba[4] = {255, 255, 255, 255};
  glWindowPos2i(1, 1);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba); // nothing drawn in SELECT mode
  EXPECT_EQ(glRenderMode(GL_RENDER), 2);
  EXPECT_EQ(sel[0], 1u); // one name: 7
  EXPECT_EQ(sel[3], 7u);
  EXPECT_EQ(sel[4], 1u); // the WindowPos hit under name 8
  EXPECT_EQ(sel[7], 8u);
  EXPECT_EQ(pixel(1, 1), 0u);
}

} // namespace
