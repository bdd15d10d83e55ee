// Regressions found by piglit's GL 1.x list (conformance/piglit): each test names the piglit
// test that caught the behaviour and the spec section that decides it.
#include <GL/gl.h>
#include <GL/glext.h>

#include <vector>

#include "api_fixture.h"

namespace {

GLenum err() {
  return glGetError();
}

// The colour of pixel (x, y) read back as RGBA bytes.
struct Rgba {
  int r, g, b, a;
};
Rgba read_rgba(int x, int y) {
  GLubyte p[4] = {};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  return {p[0], p[1], p[2], p[3]};
}

void ortho_pixels(int w, int h) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, w, 0, h, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

using PiglitRegressionTest = GLTest;

// piglit gl-1.0-dlist-beginend: a DrawArrays compiled while no vertex array is enabled draws
// nothing, but the list called between Begin and End must still report INVALID_OPERATION
// (GL 2.1 §2.6.3; §5.4: the command is compiled, its error belongs to execution).
TEST_F(PiglitRegressionTest, ArrayDrawWithoutVerticesInListIsIllegalBetweenBeginEnd) {
  const GLuint list = glGenLists(2);
  glNewList(list, GL_COMPILE);
  glDrawArrays(GL_QUADS, 0, 4);
  glEndList();
  GLuint idx[4] = {0, 1, 2, 3};
  glNewList(list + 1, GL_COMPILE);
  glDrawElements(GL_QUADS, 4, GL_UNSIGNED_INT, idx);
  glEndList();
  ASSERT_EQ(err(), GLenum(GL_NO_ERROR));

  for (GLuint l : {list, list + 1}) {
    glBegin(GL_QUADS);
    glCallList(l);
    glEnd();
    EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION)) << "list " << l;
    // Outside Begin/End the empty draw is no error and draws nothing.
    glCallList(l);
    EXPECT_EQ(err(), GLenum(GL_NO_ERROR)) << "list " << l;
  }
  glDeleteLists(list, 2);
}

// The same with the draw compiled inside a Begin/End of the list itself (piglit
// gl-1.0-beginend-coverage, "glNewList(GL_COMPILE) with begin/end inside").
TEST_F(PiglitRegressionTest, ArrayDrawCompiledInsideBeginEndErrsAtExecution) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBegin(GL_POINTS);
  glDrawArrays(GL_POINTS, 0, 1);
  glEnd();
  glEndList();
  ASSERT_EQ(err(), GLenum(GL_NO_ERROR));
  glCallList(list);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glDeleteLists(list, 1);
}

// piglit draw-pixels: a packed type with a format it does not fit is INVALID_OPERATION even
// when the format is unknown to GL 1.5 (GL_RG): both errors apply (§3.6.4, §2.5), and Mesa
// reports the packed-type mismatch.
TEST_F(PiglitRegressionTest, PackedTypeMismatchBeforeUnknownFormat) {
  GLubyte px[64] = {};
  glRasterPos2i(0, 0);
  glDrawPixels(2, 2, 0x8227 /* GL_RG */, GL_UNSIGNED_BYTE_3_3_2, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glDrawPixels(2, 2, 0x1234, GL_UNSIGNED_INT_8_8_8_8, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glReadPixels(0, 0, 2, 2, 0x8227, GL_UNSIGNED_SHORT_5_6_5, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // An unknown format with a plain type, and an unknown type, stay INVALID_ENUM.
  glDrawPixels(2, 2, 0x8227, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glDrawPixels(2, 2, GL_RGB, 0x1234, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  // BITMAP with a colour format: INVALID_ENUM (§3.6.4).
  glDrawPixels(2, 2, GL_RGB, GL_BITMAP, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
}

// piglit copyteximage: an invalid internalformat for CopyTexImage is INVALID_ENUM (GL 2.1
// §3.8.2), including the TexImage-only 1 .. 4.
TEST_F(PiglitRegressionTest, CopyTexImageInvalidInternalFormatIsInvalidEnum) {
  glCopyTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 0, 0, 4, 4, 0);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glCopyTexImage2D(GL_TEXTURE_2D, 0, 4, 0, 0, 4, 4, 0);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGB16F_ARB, 0, 0, 4, 0);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glCopyTexImage1D(GL_TEXTURE_1D, 0, 2, 0, 0, 4, 0);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, 0, 0, 4, 0);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

// piglit gl-1.1-read-pixels-after-display-list: TexImage2D takes COLOR_INDEX images of type
// BITMAP (§3.8.1 excludes only STENCIL_INDEX); each bit is an index that the I_TO_R .. I_TO_A
// maps turn into RGBA (§3.6.5), also when the command is compiled into a list.
TEST_F(PiglitRegressionTest, TexImageFromColorIndexBitmap) {
  const GLfloat r_map[] = {0, 1}, g_map[] = {0, 0}, b_map[] = {1, 0}, a_map[] = {1, 1};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 2, r_map);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 2, g_map);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 2, b_map);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 2, a_map);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  ortho_pixels(kW, kH);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  // Two texels in one byte, MSB first: 1 then 0.
  const GLubyte bits = 0x80;
  for (bool in_list : {false, true}) {
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    const GLuint list = glGenLists(1);
    if (in_list) glNewList(list, GL_COMPILE_AND_EXECUTE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_COLOR_INDEX, GL_BITMAP, &bits);
    EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0), glVertex2f(0, 0);
    glTexCoord2f(1, 0), glVertex2f(2, 0);
    glTexCoord2f(1, 1), glVertex2f(2, 1);
    glTexCoord2f(0, 1), glVertex2f(0, 1);
    glEnd();
    if (in_list) glEndList();
    const Rgba fg = read_rgba(0, 0), bg = read_rgba(1, 0);
    EXPECT_EQ(fg.r, 255) << in_list;
    EXPECT_EQ(fg.b, 0) << in_list;
    EXPECT_EQ(bg.r, 0) << in_list;
    EXPECT_EQ(bg.b, 255) << in_list;
    if (in_list) {
      glClear(GL_COLOR_BUFFER_BIT);
      glCallList(list);
      EXPECT_EQ(read_rgba(0, 0).r, 255);
      EXPECT_EQ(read_rgba(1, 0).b, 255);
    }
    glDeleteLists(list, 1);
  }
  // STENCIL_INDEX stays illegal for texture images, BITMAP with a colour format too.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_STENCIL_INDEX, GL_BITMAP, &bits);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_BITMAP, &bits);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
}

// piglit linestipple ("Factor 2x"): the stipple counter of a line loop advances by each
// segment's length in whole pixels (§3.4.2); a segment between pixel centres 32 pixels apart
// must not count 33 because the transforms left its window length a few ulps above 32.
TEST(PiglitRegressionLines, StippleCounterIgnoresTransformRounding) {
  constexpr int kSize = 160;
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  ASSERT_NE(ctx, nullptr);
  std::vector<uint8_t> buf(kSize * kSize * 4, 0);
  ASSERT_EQ(OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, kSize, kSize), GL_TRUE);
  ortho_pixels(kSize, kSize);
  glTranslatef(10, 10, 0); // 2/160 is inexact: window positions pick up rounding
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_LINE_STIPPLE);
  const GLushort pattern = 0x838f;
  glLineStipple(2, pattern);
  glColor3f(0, 0, 1);
  const int v[4][2] = {{0, 32}, {32, 32}, {32, 33}, {0, 33}};
  glBegin(GL_LINE_LOOP);
  for (const auto& p : v)
    glVertex2f(p[0] + 0.5f, p[1] + 0.5f);
  glEnd();
  glFinish();
  // Fragments counted from the loop's start: 32 on the first segment, 1 on the second, then
  // the third runs leftwards from x = 32.
  for (int i = 0; i < 32; ++i) {
    const int x = 32 - i, counter = 33 + i;
    const bool on = (pattern >> ((counter / 2) % 16)) & 1;
    const uint8_t blue = buf[((10 + 33) * kSize + 10 + x) * 4 + 2];
    EXPECT_EQ(blue != 0, on) << "x " << x;
  }
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);
}

// A 2x2 RGBA float texture whose texel (i, j) is tex2x2[j][i], nearest filtering, MODULATE.
void texture_2x2(const float (*texels)[2][4]) {
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_FLOAT, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

int to_ub(double v) {
  return static_cast<int>(v * 255.0 + 0.5);
}

// piglit draw-pixel-with-texture: DrawPixels fragments take the raster position's texture
// coordinates and are textured (GL 2.1 §3.6.4 "Conversion to Fragments", §3.8.13); the same
// for Bitmap (§3.7) and CopyPixels (§4.3.3: as DrawPixels).
TEST_F(PiglitRegressionTest, PixelRectanglesAreTextured) {
  ortho_pixels(kW, kH);
  const float texels[2][2][4] = {{{1, 0, 0, 1}, {0, 1, 0, 1}}, {{0, 0, 1, 1}, {1, 1, 1, 0.5f}}};
  texture_2x2(texels);
  glEnable(GL_TEXTURE_2D);
  std::vector<float> img(4 * 4 * 4);
  for (size_t i = 0; i < img.size(); i += 4)
    img[i] = 0.2f, img[i + 1] = 0.6f, img[i + 2] = 0.8f, img[i + 3] = 1.0f;
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);

  glTexCoord2f(0.75f, 0.25f); // texel (1, 0): green
  glRasterPos2i(0, 0);
  glDrawPixels(4, 4, GL_RGBA, GL_FLOAT, img.data());
  Rgba p = read_rgba(1, 1);
  EXPECT_EQ(p.r, 0);
  EXPECT_EQ(p.g, to_ub(0.6));
  EXPECT_EQ(p.b, 0);
  EXPECT_EQ(p.a, 255);

  // Bitmap: the raster colour modulated by texel (1, 1) (white, alpha 0.5).
  glColor4f(0.4f, 0.5f, 0.6f, 1.0f);
  glTexCoord2f(0.75f, 0.75f);
  glRasterPos2i(8, 0);
  const GLubyte bits[4] = {0xf0, 0xf0, 0xf0, 0xf0};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBitmap(4, 4, 0, 0, 0, 0, bits);
  p = read_rgba(9, 1);
  EXPECT_EQ(p.r, to_ub(0.4));
  EXPECT_EQ(p.g, to_ub(0.5));
  EXPECT_EQ(p.b, to_ub(0.6));
  EXPECT_EQ(p.a, to_ub(0.5));

  // CopyPixels of the green DrawPixels result, modulated by texel (0, 1) (blue): black.
  glTexCoord2f(0.25f, 0.75f);
  glRasterPos2i(16, 0);
  glCopyPixels(0, 0, 4, 4, GL_COLOR);
  p = read_rgba(17, 1);
  EXPECT_EQ(p.r, 0);
  EXPECT_EQ(p.g, 0);
  EXPECT_EQ(p.b, 0);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));

  // Texturing off again: DrawPixels writes its colours unchanged.
  glDisable(GL_TEXTURE_2D);
  glRasterPos2i(24, 0);
  glDrawPixels(4, 4, GL_RGBA, GL_FLOAT, img.data());
  p = read_rgba(25, 1);
  EXPECT_EQ(p.r, to_ub(0.2));
  EXPECT_EQ(p.g, to_ub(0.6));
  EXPECT_EQ(p.b, to_ub(0.8));
}

// §3.10: fog applies to pixel fragments too, with the raster distance as fog coordinate
// (§2.13). Linear fog from 0 to 8 at distance 4 blends half of the fog colour in.
TEST_F(PiglitRegressionTest, PixelRectanglesAreFogged) {
  ortho_pixels(kW, kH);
  glTranslatef(0, 0, -1); // eye z = -1 for the raster position below
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 8.0f);
  const float fog_color[4] = {0, 1, 0, 1};
  glFogfv(GL_FOG_COLOR, fog_color);
  glRasterPos3f(0, 0, 0);
  GLfloat dist = 0;
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &dist);
  ASSERT_FLOAT_EQ(dist, 1.0f);
  const float img[4] = {1, 0, 0, 1};
  glDrawPixels(1, 1, GL_RGBA, GL_FLOAT, img);
  const double f = (8.0 - 1.0) / 8.0;
  const Rgba p = read_rgba(0, 0);
  EXPECT_NEAR(p.r, to_ub(f), 1);
  EXPECT_NEAR(p.g, to_ub(1.0 - f), 1);
  EXPECT_EQ(p.b, 0);
  glDisable(GL_FOG);
}

} // namespace
