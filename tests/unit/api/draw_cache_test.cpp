// The per-draw setup kept across draws (src/draw/draw_cache.h) must follow every change
// of what it was made from: GL state between draws, another colour buffer of the same size,
// and the texture units a Begin/End copies.
#include <array>

#include "api_fixture.h"

namespace {

void quad(float x0, float y0, float x1, float y1) {
  glBegin(GL_QUADS);
  glVertex2f(x0, y0);
  glVertex2f(x1, y0);
  glVertex2f(x1, y1);
  glVertex2f(x0, y1);
  glEnd();
}

class DrawCacheTest : public GLTest {
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

TEST_F(DrawCacheTest, StateChangesBetweenIdenticalDrawsTakeEffect) {
  glColor3f(1, 0, 0);
  quad(0, 0, 16, 16);
  EXPECT_EQ(pixel(4, 4), 0xff0000ffu);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 8, 32);
  glColor3f(0, 1, 0);
  quad(0, 0, 16, 16);
  EXPECT_EQ(pixel(4, 4), 0xff00ff00u);
  EXPECT_EQ(pixel(12, 4), 0xff0000ffu); // outside the new scissor box
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_TRUE);
  glColor3f(1, 1, 1);
  quad(0, 0, 16, 16);
  EXPECT_EQ(pixel(12, 4), 0xffffffffu); // red kept, green and blue written
}

TEST_F(DrawCacheTest, AnotherBufferOfTheSameSizeReceivesTheNextDraw) {
  std::vector<uint8_t> other(kW * kH * 4, 0);
  glColor3f(1, 0, 0);
  quad(0, 0, 16, 16);
  ASSERT_EQ(OSMesaMakeCurrent(ctx_, other.data(), GL_UNSIGNED_BYTE, kW, kH), GL_TRUE);
  glColor3f(0, 0, 1);
  quad(0, 0, 16, 16);
  EXPECT_EQ(pixel(4, 4), 0xff0000ffu); // the first buffer keeps its red
  const uint8_t* p = &other[(4 * kW + 4) * 4];
  EXPECT_EQ((std::array<uint8_t, 4>{p[0], p[1], p[2], p[3]}),
            (std::array<uint8_t, 4>{0, 0, 255, 255}));
}

TEST_F(DrawCacheTest, BeginEndCopiesTheTextureCoordinatesTexturingReads) {
  // A 2x1 texture: texel 0 red, texel 1 green, nearest filtering. Unit 1 is on, unit 0 off.
  const uint8_t texels[] = {255, 0, 0, 255, 0, 255, 0, 255};
  GLuint tex = 0;
  glGenTextures(1, &tex);
  auto active = reinterpret_cast<void (*)(GLenum)>(OSMesaGetProcAddress("glActiveTexture"));
  auto multi = reinterpret_cast<void (*)(GLenum, GLfloat, GLfloat)>(
      OSMesaGetProcAddress("glMultiTexCoord2f"));
  ASSERT_NE(active, nullptr);
  ASSERT_NE(multi, nullptr);
  active(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  for (int pass = 0; pass < 2; ++pass) {
    // Texel 1 everywhere: s = 0.75 at every vertex.
    glBegin(GL_TRIANGLES);
    multi(GL_TEXTURE1, 0.75f, 0.5f);
    glVertex2f(0, 0);
    glVertex2f(32, 0);
    glVertex2f(0, 32);
    glEnd();
    EXPECT_EQ(pixel(2, 2), 0xff00ff00u) << "pass " << pass;
    // Texturing off: the same unit's coordinates are no longer copied, and drawing works.
    glDisable(GL_TEXTURE_2D);
    glColor3f(0, 0, 1);
    quad(0, 0, 8, 8);
    EXPECT_EQ(pixel(2, 2), 0xffff0000u) << "pass " << pass;
    glEnable(GL_TEXTURE_2D);
    glColor3f(1, 1, 1);
  }
  glDeleteTextures(1, &tex);
}

} // namespace
