// Display lists (GL 2.1 §5.4) holding texture, fog, pixel and multitexture commands: data is
// copied and unpacked with the pixel-store state of compile time, proxy images execute at
// once, and multitexture and fog coordinates are current attributes like TexCoord.
#include "api_fixture.h"

#include <GL/glext.h>

#include <array>

namespace {

using DlistTexPix = GLTest;

void window_ortho() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 32, 0, 32, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

TEST_F(DlistTexPix, DrawPixelsUsesTheDataAndUnpackStateOfCompileTime) {
  window_ortho();
  // A 2x1 image at skip-pixels 1 of a 3-pixel row, alignment 1.
  std::array<GLubyte, 12> img = {0, 0, 0, 0, 255, 0, 0, 255, 0, 0, 255, 255};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glDrawPixels(2, 1, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glEndList();
  EXPECT_EQ(pixel(3, 3), 0u); // COMPILE draws nothing
  img.fill(0x55);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glRasterPos2i(3, 3);
  glCallList(list);
  EXPECT_EQ(pixel(3, 3), 0xff0000ffu);
  EXPECT_EQ(pixel(4, 3), 0xffff0000u);
  GLint skip = -1;
  glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skip);
  EXPECT_EQ(skip, 0); // the list's unpack state was only borrowed
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(DlistTexPix, BitmapKeepsLsbFirstOfCompileTime) {
  window_ortho();
  GLubyte bits[1] = {0x01}; // LSB first: the leftmost pixel
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBitmap(8, 1, 0, 0, 0, 0, bits);
  glEndList();
  bits[0] = 0;
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glColor3f(0, 1, 0);
  glRasterPos2i(10, 10);
  glCallList(list);
  EXPECT_EQ(pixel(10, 10), 0xff00ff00u);
  EXPECT_EQ(pixel(17, 10), 0u);
}

TEST_F(DlistTexPix, TextureFogAndEnvironmentParametersAreCopied) {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  std::array<GLubyte, 4 * 4 * 4> img{};
  std::array<GLfloat, 4> border = {0.25f, 0.5f, 0.75f, 1.0f};
  std::array<GLfloat, 4> fog = {0.1f, 0.2f, 0.3f, 0.4f};
  std::array<GLfloat, 4> env = {0.5f, 0.25f, 0.125f, 1.0f};
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border.data());
  glFogfv(GL_FOG_COLOR, fog.data());
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env.data());
  glEndList();
  GLint width = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
  EXPECT_EQ(width, 0); // not executed yet
  border.fill(0);
  fog.fill(0);
  env.fill(0);
  glCallList(list);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
  EXPECT_EQ(width, 4);
  GLfloat v[4] = {};
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, v);
  EXPECT_FLOAT_EQ(v[2], 0.75f);
  glGetFloatv(GL_FOG_COLOR, v);
  EXPECT_FLOAT_EQ(v[3], 0.4f);
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, v);
  EXPECT_FLOAT_EQ(v[1], 0.25f);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glDeleteTextures(1, &tex);
}

TEST_F(DlistTexPix, ProxyTexImageExecutesImmediately) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glEndList();
  GLint width = -1;
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
  EXPECT_EQ(width, 8);
}

TEST_F(DlistTexPix, MultiTexCoordAndFogCoordAreCompiledAttributes) {
  auto multi_tex_coord_2f =
      reinterpret_cast<PFNGLMULTITEXCOORD2FPROC>(OSMesaGetProcAddress("glMultiTexCoord2f"));
  auto fog_coord_f = reinterpret_cast<PFNGLFOGCOORDFPROC>(OSMesaGetProcAddress("glFogCoordf"));
  auto active_texture =
      reinterpret_cast<PFNGLACTIVETEXTUREPROC>(OSMesaGetProcAddress("glActiveTexture"));
  ASSERT_NE(multi_tex_coord_2f, nullptr);
  ASSERT_NE(fog_coord_f, nullptr);
  ASSERT_NE(active_texture, nullptr);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  multi_tex_coord_2f(GL_TEXTURE1, 0.5f, 0.75f);
  fog_coord_f(3.0f);
  glBegin(GL_POINTS);
  glVertex2f(0, 0);
  glEnd();
  glEndList();
  glCallList(list);
  active_texture(GL_TEXTURE1);
  GLfloat t[4] = {};
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
  EXPECT_FLOAT_EQ(t[0], 0.5f);
  EXPECT_FLOAT_EQ(t[1], 0.75f);
  GLfloat f = 0;
  glGetFloatv(GL_CURRENT_FOG_COORD, &f);
  EXPECT_FLOAT_EQ(f, 3.0f);
  // A target naming no unit is an error when the list executes, not when it is compiled.
  const GLuint bad = glGenLists(1);
  glNewList(bad, GL_COMPILE);
  multi_tex_coord_2f(GL_TEXTURE0 + 31, 1, 1);
  glEndList();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glCallList(bad);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
}

} // namespace
