// Point sprites (GL 2.1 §3.3, ARB_point_sprite): the POINT_SPRITE enable, COORD_REPLACE per
// texture unit through TexEnv, POINT_SPRITE_COORD_ORIGIN through PointParameter; their errors,
// queries, attribute groups and display lists, and what a sprite rasterizes: a square of the
// unrounded size whose texture coordinates run 0..1 across it, with POINT_SMOOTH ignored.
#include <cmath>

#define GL_GLEXT_PROTOTYPES
#include "api_fixture.h"

namespace {

class PointSprite : public GLTest {
protected:
  // Pixels with some colour.
  int count_lit() const {
    int n = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        n += (pixel(x, y) & 0xffffffu) != 0;
    return n;
  }
};

GLint get_int(GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  return v;
}

GLint coord_replace() {
  GLint v = -1;
  glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &v);
  return v;
}

void pixel_ortho() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 32, 0, 32, -1, 1); // the fixture's 32x32 buffer
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

TEST_F(PointSprite, StateQueriesAndErrors) {
  EXPECT_EQ(glIsEnabled(GL_POINT_SPRITE), GL_FALSE);
  EXPECT_EQ(get_int(GL_POINT_SPRITE_COORD_ORIGIN), GL_UPPER_LEFT);
  EXPECT_EQ(coord_replace(), GL_FALSE);
  glEnable(GL_POINT_SPRITE);
  EXPECT_EQ(glIsEnabled(GL_POINT_SPRITE), GL_TRUE);
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
  EXPECT_EQ(get_int(GL_POINT_SPRITE_COORD_ORIGIN), GL_LOWER_LEFT);
  glPointParameterf(GL_POINT_SPRITE_COORD_ORIGIN, static_cast<GLfloat>(GL_UPPER_LEFT));
  EXPECT_EQ(get_int(GL_POINT_SPRITE_COORD_ORIGIN), GL_UPPER_LEFT);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // GL 2.1 §3.3: another origin is INVALID_VALUE and changes nothing.
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_FRONT);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(get_int(GL_POINT_SPRITE_COORD_ORIGIN), GL_UPPER_LEFT);

  // COORD_REPLACE is per texture unit.
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  EXPECT_EQ(coord_replace(), GL_TRUE);
  glActiveTexture(GL_TEXTURE2);
  EXPECT_EQ(coord_replace(), GL_FALSE);
  glTexEnvf(GL_POINT_SPRITE, GL_COORD_REPLACE, 1.0f);
  GLfloat f = -1;
  glGetTexEnvfv(GL_POINT_SPRITE, GL_COORD_REPLACE, &f);
  EXPECT_EQ(f, 1.0f);
  glActiveTexture(GL_TEXTURE1);
  EXPECT_EQ(coord_replace(), GL_FALSE);
  glActiveTexture(GL_TEXTURE0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // A value other than TRUE or FALSE is INVALID_VALUE; another pname INVALID_ENUM.
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, 2);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(coord_replace(), GL_TRUE);
  glTexEnvi(GL_POINT_SPRITE, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  GLint v = 0;
  glGetTexEnviv(GL_POINT_SPRITE, GL_TEXTURE_ENV_MODE, &v);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  // Between Begin and End.
  glBegin(GL_POINTS);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(coord_replace(), GL_TRUE);
}

TEST_F(PointSprite, AttribStackAndLists) {
  glPushAttrib(GL_POINT_BIT);
  glEnable(GL_POINT_SPRITE);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
  glPopAttrib();
  // POINT_BIT saves the enable (point/enable), COORD_REPLACE and the origin (Table 6.12).
  EXPECT_EQ(glIsEnabled(GL_POINT_SPRITE), GL_FALSE);
  EXPECT_EQ(coord_replace(), GL_FALSE);
  EXPECT_EQ(get_int(GL_POINT_SPRITE_COORD_ORIGIN), GL_UPPER_LEFT);
  glPushAttrib(GL_ENABLE_BIT);
  glEnable(GL_POINT_SPRITE);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_POINT_SPRITE), GL_FALSE);

  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glEnable(GL_POINT_SPRITE);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
  glEndList();
  EXPECT_EQ(glIsEnabled(GL_POINT_SPRITE), GL_FALSE);
  EXPECT_EQ(coord_replace(), GL_FALSE);
  glCallList(list);
  EXPECT_EQ(glIsEnabled(GL_POINT_SPRITE), GL_TRUE);
  EXPECT_EQ(coord_replace(), GL_TRUE);
  EXPECT_EQ(get_int(GL_POINT_SPRITE_COORD_ORIGIN), GL_LOWER_LEFT);
  glDeleteLists(list, 1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// §3.3.1: the fragments whose centres lie in the size x size square around the point; the
// size is not rounded (5.5 covers 6 columns here where an aliased point would cover 5) and
// POINT_SMOOTH makes no disc.
TEST_F(PointSprite, SquareOfTheUnroundedSize) {
  pixel_ortho();
  glEnable(GL_POINT_SPRITE);
  glEnable(GL_POINT_SMOOTH);
  glPointSize(6.0f);
  glBegin(GL_POINTS);
  glVertex2f(16.0f, 16.0f); // square [13, 19): centres 13.5 .. 18.5
  glEnd();
  EXPECT_EQ(count_lit(), 36);
  EXPECT_NE(pixel(13, 13), 0u);
  EXPECT_NE(pixel(18, 18), 0u);
  EXPECT_EQ(pixel(19, 16) & 0xffffffu, 0u);
  glClear(GL_COLOR_BUFFER_BIT);
  glPointSize(5.5f);
  glBegin(GL_POINTS);
  glVertex2f(16.2f, 16.2f); // [13.45, 18.95): centres 13.5 .. 18.5
  glEnd();
  EXPECT_EQ(count_lit(), 36);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// The sprite coordinates through a texture whose texel columns and rows have distinct colours:
// s = 1/2 + (x_f + 1/2 - x_w) / size left to right, t bottom to top (LOWER_LEFT) or top to
// bottom (UPPER_LEFT).
TEST_F(PointSprite, CoordinatesFollowTheOrigin) {
  pixel_ortho();
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  // 8x8 texels: red = 32 * column, green = 32 * row.
  GLubyte img[8 * 8 * 4];
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      GLubyte* t = &img[(y * 8 + x) * 4];
      t[0] = static_cast<GLubyte>(32 * x), t[1] = static_cast<GLubyte>(32 * y), t[2] = 0;
      t[3] = 255;
    }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_POINT_SPRITE);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glPointSize(16.0f);
  for (GLenum origin : {GL_UPPER_LEFT, GL_LOWER_LEFT}) {
    glClear(GL_COLOR_BUFFER_BIT);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, static_cast<GLint>(origin));
    glTexCoord2f(0.9f, 0.9f); // replaced
    glBegin(GL_POINTS);
    glVertex2f(16.0f, 16.0f); // pixels 8..23
    glEnd();
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i) {
        const uint32_t p = pixel(8 + i, 8 + j);
        const int row = origin == GL_LOWER_LEFT ? j / 2 : 7 - j / 2;
        ASSERT_EQ(p & 0xffu, 32u * static_cast<uint32_t>(i / 2)) << i << "," << j;
        ASSERT_EQ((p >> 8) & 0xffu, 32u * static_cast<uint32_t>(row)) << i << "," << j;
      }
  }
  // COORD_REPLACE off: every fragment takes the current texture coordinates.
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
  glClear(GL_COLOR_BUFFER_BIT);
  glTexCoord2f(0.9f, 0.1f); // texel (7, 0)
  glBegin(GL_POINTS);
  glVertex2f(16.0f, 16.0f);
  glEnd();
  EXPECT_EQ(pixel(9, 9), 0xff0000e0u);
  EXPECT_EQ(pixel(22, 22), 0xff0000e0u);
  glDeleteTextures(1, &tex);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

} // namespace
