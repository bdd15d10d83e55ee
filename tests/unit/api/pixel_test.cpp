// The pixel commands (GL 2.1 §2.13, §3.6.3, §3.6.4, §3.7, §4.3): errors, INVALID_OPERATION
// between Begin and End, state queries, and what DrawPixels, Bitmap, CopyPixels and ReadPixels
// with pixel transfer put in the framebuffer or client memory.
#include <cmath>
#include <cstring>
#include <functional>
#include <vector>

#include "api_fixture.h"

namespace {

using Pixel = GLTest;

GLint get_int(GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  return v;
}
GLfloat get_float(GLenum pname) {
  GLfloat v = -12345;
  glGetFloatv(pname, &v);
  return v;
}
void expect_error(GLenum err) {
  EXPECT_EQ(glGetError(), err);
}

// A pixel-exact 2D setup: window coordinates = object coordinates.
void ortho_window() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 32, 0, 32, -1, 1); // the fixture's 32 x 32 buffer
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

TEST_F(Pixel, InitialState) {
  EXPECT_EQ(get_int(GL_MAP_COLOR), 0);
  EXPECT_EQ(get_int(GL_MAP_STENCIL), 0);
  EXPECT_EQ(get_int(GL_INDEX_SHIFT), 0);
  EXPECT_EQ(get_int(GL_INDEX_OFFSET), 0);
  for (GLenum p : {GL_RED_SCALE, GL_GREEN_SCALE, GL_BLUE_SCALE, GL_ALPHA_SCALE, GL_DEPTH_SCALE,
                   GL_ZOOM_X, GL_ZOOM_Y})
    EXPECT_EQ(get_float(p), 1.0f) << std::hex << p;
  for (GLenum p : {GL_RED_BIAS, GL_GREEN_BIAS, GL_BLUE_BIAS, GL_ALPHA_BIAS, GL_DEPTH_BIAS})
    EXPECT_EQ(get_float(p), 0.0f) << std::hex << p;
  for (GLenum p = GL_PIXEL_MAP_I_TO_I_SIZE; p <= GL_PIXEL_MAP_A_TO_A_SIZE; ++p)
    EXPECT_EQ(get_int(p), 1);
  EXPECT_GE(get_int(GL_MAX_PIXEL_MAP_TABLE), 32);
  GLfloat pos[4];
  glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
  EXPECT_EQ(pos[0], 0.0f);
  EXPECT_EQ(pos[3], 1.0f);
  EXPECT_EQ(get_int(GL_CURRENT_RASTER_POSITION_VALID), 1);
  GLfloat c[4];
  glGetFloatv(GL_CURRENT_RASTER_COLOR, c);
  EXPECT_EQ(c[0], 1.0f);
  glGetFloatv(GL_CURRENT_RASTER_SECONDARY_COLOR, c);
  EXPECT_EQ(c[0], 0.0f);
  EXPECT_EQ(c[3], 1.0f);
  EXPECT_EQ(get_float(GL_CURRENT_RASTER_INDEX), 1.0f);
  EXPECT_EQ(get_float(GL_CURRENT_RASTER_DISTANCE), 0.0f);
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, c);
  EXPECT_EQ(c[3], 1.0f);
  expect_error(GL_NO_ERROR);
}

TEST_F(Pixel, TransferAndZoomRoundTrip) {
  glPixelTransferi(GL_MAP_COLOR, 1);
  glPixelTransferf(GL_INDEX_SHIFT, -2.6f);
  glPixelTransferi(GL_INDEX_OFFSET, 7);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferi(GL_DEPTH_BIAS, 2);
  glPixelZoom(-2.0f, 0.5f);
  EXPECT_EQ(get_int(GL_MAP_COLOR), 1);
  EXPECT_EQ(get_int(GL_INDEX_SHIFT), -3);
  EXPECT_EQ(get_int(GL_INDEX_OFFSET), 7);
  EXPECT_EQ(get_float(GL_RED_SCALE), 0.5f);
  EXPECT_EQ(get_float(GL_DEPTH_BIAS), 2.0f);
  EXPECT_EQ(get_float(GL_ZOOM_X), -2.0f);
  EXPECT_EQ(get_float(GL_ZOOM_Y), 0.5f);
  glPixelTransferf(GL_TEXTURE_2D, 1.0f);
  expect_error(GL_INVALID_ENUM);
}

TEST_F(Pixel, PixelMapsAndErrors) {
  const GLfloat f[4] = {0.0f, 0.25f, 0.5f, 2.0f};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 3, f); // colour maps may have any size
  expect_error(GL_NO_ERROR);
  EXPECT_EQ(get_int(GL_PIXEL_MAP_R_TO_R_SIZE), 3);
  GLfloat back[4] = {};
  glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, back);
  EXPECT_EQ(back[1], 0.25f);
  GLuint ui[4] = {};
  glGetPixelMapuiv(GL_PIXEL_MAP_R_TO_R, ui);
  EXPECT_EQ(ui[2], 2147483648u); // 0.5 (2^32 - 1), rounded
  GLushort us[4] = {};
  glGetPixelMapusv(GL_PIXEL_MAP_R_TO_R, us);
  EXPECT_EQ(us[1], 16384);
  // Index maps need a power of two; stencil entries given as floats are rounded.
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 3, f);
  expect_error(GL_INVALID_VALUE);
  const GLfloat s[2] = {2.6f, 7.2f};
  glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 2, s);
  glGetPixelMapuiv(GL_PIXEL_MAP_S_TO_S, ui);
  EXPECT_EQ(ui[0], 3u);
  EXPECT_EQ(ui[1], 7u);
  const GLushort u16[2] = {65535, 0};
  glPixelMapusv(GL_PIXEL_MAP_A_TO_A, 2, u16);
  glGetPixelMapfv(GL_PIXEL_MAP_A_TO_A, back);
  EXPECT_EQ(back[0], 1.0f);
  const GLuint u32[2] = {5, 9};
  glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 2, u32);
  glGetPixelMapfv(GL_PIXEL_MAP_I_TO_I, back);
  EXPECT_EQ(back[1], 9.0f);
  expect_error(GL_NO_ERROR);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, f);
  expect_error(GL_INVALID_VALUE);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, get_int(GL_MAX_PIXEL_MAP_TABLE) + 1, f);
  expect_error(GL_INVALID_VALUE);
  glPixelMapfv(GL_COLOR, 1, f);
  expect_error(GL_INVALID_ENUM);
  glGetPixelMapfv(GL_COLOR, back);
  expect_error(GL_INVALID_ENUM);
  EXPECT_EQ(get_int(GL_PIXEL_MAP_R_TO_R_SIZE), 3); // the failed calls changed nothing
}

TEST_F(Pixel, IllegalBetweenBeginEnd) {
  const GLfloat f[1] = {0};
  GLfloat g[1];
  const GLubyte b[1] = {0};
  const std::vector<std::function<void()>> calls = {
      [] { glPixelTransferf(GL_RED_SCALE, 1); },
      [] { glPixelTransferi(GL_MAP_COLOR, 0); },
      [&] { glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 1, f); },
      [&] { glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, g); },
      [] { glPixelZoom(1, 1); },
      [] { glRasterPos2f(0, 0); },
      [] { glWindowPos2i(0, 0); },
      [&] { glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, b); },
      [&] { glBitmap(1, 1, 0, 0, 0, 0, b); },
      [] { glCopyPixels(0, 0, 1, 1, GL_COLOR); },
  };
  for (size_t i = 0; i < calls.size(); ++i) {
    glBegin(GL_POINTS);
    calls[i]();
    glEnd();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION)) << "call " << i;
  }
}

TEST_F(Pixel, DrawPixelsErrors) {
  const GLubyte data[64] = {};
  glDrawPixels(-1, 1, GL_RGBA, GL_UNSIGNED_BYTE, data);
  expect_error(GL_INVALID_VALUE);
  glDrawPixels(1, 1, GL_RGBA, GL_DOUBLE, data);
  expect_error(GL_INVALID_ENUM);
  glDrawPixels(1, 1, GL_INTENSITY, GL_UNSIGNED_BYTE, data);
  expect_error(GL_INVALID_ENUM);
  glDrawPixels(1, 1, GL_RGBA, GL_BITMAP, data);
  expect_error(GL_INVALID_ENUM);
  glDrawPixels(1, 1, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, data);
  expect_error(GL_INVALID_OPERATION);
  glCopyPixels(0, 0, 1, 1, GL_RGBA);
  expect_error(GL_INVALID_ENUM);
  glCopyPixels(0, 0, -1, 1, GL_COLOR);
  expect_error(GL_INVALID_VALUE);
  glBitmap(-1, 1, 0, 0, 0, 0, data);
  expect_error(GL_INVALID_VALUE);
}

TEST_F(Pixel, NoStencilOrDepthBuffer) {
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
  std::vector<uint8_t> buf(16 * 16 * 4);
  ASSERT_EQ(OSMesaMakeCurrent(c, buf.data(), GL_UNSIGNED_BYTE, 16, 16), GL_TRUE);
  const GLubyte data[4] = {};
  glDrawPixels(1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, data);
  expect_error(GL_INVALID_OPERATION);
  glDrawPixels(1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, data);
  expect_error(GL_INVALID_OPERATION);
  glCopyPixels(0, 0, 1, 1, GL_DEPTH);
  expect_error(GL_INVALID_OPERATION);
  glCopyPixels(0, 0, 1, 1, GL_STENCIL);
  expect_error(GL_INVALID_OPERATION);
  OSMesaMakeCurrent(ctx_, buf_.data(), GL_UNSIGNED_BYTE, kW, kH);
  OSMesaDestroyContext(c);
}

TEST_F(Pixel, RasterPosTransformsAndClips) {
  ortho_window();
  glColor4f(0.25f, 0.5f, 2.0f, 1.0f);
  glRasterPos3f(3.0f, 4.0f, 0.5f);
  GLfloat pos[4];
  glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
  EXPECT_FLOAT_EQ(pos[0], 3.0f);
  EXPECT_FLOAT_EQ(pos[1], 4.0f);
  EXPECT_FLOAT_EQ(pos[2], 0.25f); // z_ndc = -0.5 with this ortho: (1 - 0.5) / 2
  EXPECT_FLOAT_EQ(pos[3], 1.0f);
  EXPECT_FLOAT_EQ(get_float(GL_CURRENT_RASTER_DISTANCE), 5.0f * std::sqrt(1.01f));
  GLfloat c[4];
  glGetFloatv(GL_CURRENT_RASTER_COLOR, c);
  EXPECT_EQ(c[2], 1.0f); // clamped
  EXPECT_EQ(get_int(GL_CURRENT_RASTER_POSITION_VALID), 1);
  glRasterPos2f(-1.0f, 4.0f);
  EXPECT_EQ(get_int(GL_CURRENT_RASTER_POSITION_VALID), 0);
  // A user clip plane invalidates a point inside the view volume.
  const GLdouble plane[4] = {-1, 0, 0, 10};
  glClipPlane(GL_CLIP_PLANE0, plane);
  glEnable(GL_CLIP_PLANE0);
  glRasterPos2f(11.0f, 4.0f);
  EXPECT_EQ(get_int(GL_CURRENT_RASTER_POSITION_VALID), 0);
  glRasterPos2f(9.0f, 4.0f);
  EXPECT_EQ(get_int(GL_CURRENT_RASTER_POSITION_VALID), 1);
}

TEST_F(Pixel, WindowPosSetsWindowCoordinates) {
  glDepthRange(0.5, 1.0);
  glColor4f(-1.0f, 0.5f, 0.5f, 1.0f);
  glWindowPos3f(100.5f, -7.0f, 0.5f); // outside the window, still valid
  GLfloat pos[4];
  glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
  EXPECT_EQ(pos[0], 100.5f);
  EXPECT_EQ(pos[1], -7.0f);
  EXPECT_EQ(pos[2], 0.75f);
  EXPECT_EQ(get_int(GL_CURRENT_RASTER_POSITION_VALID), 1);
  GLfloat c[4];
  glGetFloatv(GL_CURRENT_RASTER_COLOR, c);
  EXPECT_EQ(c[0], 0.0f);
  glWindowPos2i(1, 2);
  glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
  EXPECT_EQ(pos[2], 0.5f);
}

TEST_F(Pixel, DrawPixelsZoomAndInvalidPosition) {
  glWindowPos2i(2, 3);
  const GLubyte rgba[8] = {255, 0, 0, 255, 0, 255, 0, 255};
  glPixelZoom(2.0f, 3.0f);
  glDrawPixels(2, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  EXPECT_EQ(pixel(2, 3), 0xff0000ffu);
  EXPECT_EQ(pixel(3, 5), 0xff0000ffu);
  EXPECT_EQ(pixel(4, 3), 0xff00ff00u);
  EXPECT_EQ(pixel(5, 5), 0xff00ff00u);
  EXPECT_EQ(pixel(6, 3), 0u);
  EXPECT_EQ(pixel(2, 6), 0u);
  // Negative zoom mirrors to the left of the raster position.
  glPixelZoom(-1.0f, 1.0f);
  glWindowPos2i(20, 10);
  glDrawPixels(2, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  EXPECT_EQ(pixel(19, 10), 0xff0000ffu);
  EXPECT_EQ(pixel(18, 10), 0xff00ff00u);
  EXPECT_EQ(pixel(20, 10), 0u);
  // Nothing at all with an invalid raster position.
  glPixelZoom(1.0f, 1.0f);
  glRasterPos2f(-5.0f, 0.0f); // outside the view volume
  ASSERT_EQ(get_int(GL_CURRENT_RASTER_POSITION_VALID), 0);
  const std::vector<uint8_t> before = buf_;
  glDrawPixels(2, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glBitmap(2, 1, 0, 0, 5, 5, rgba);
  EXPECT_EQ(buf_, before);
  expect_error(GL_NO_ERROR);
}

TEST_F(Pixel, BitmapDrawsAndMoves) {
  glColor3f(0.0f, 0.0f, 1.0f);
  glWindowPos2f(4.0f, 4.0f);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const GLubyte bits[2] = {0xA0, 0x40}; // row 0: x . x ; row 1: . x .
  glColor3f(1.0f, 0.0f, 0.0f);          // after WindowPos: the raster colour stays blue
  glBitmap(3, 2, 1.0f, 0.0f, 10.0f, 1.0f, bits);
  EXPECT_EQ(pixel(3, 4), 0xffff0000u);
  EXPECT_EQ(pixel(4, 4), 0u);
  EXPECT_EQ(pixel(5, 4), 0xffff0000u);
  EXPECT_EQ(pixel(4, 5), 0xffff0000u);
  EXPECT_EQ(pixel(3, 5), 0u);
  GLfloat pos[4];
  glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
  EXPECT_EQ(pos[0], 14.0f);
  EXPECT_EQ(pos[1], 5.0f);
  // A null bitmap only moves the position.
  glBitmap(0, 0, 0, 0, 1.0f, 0.0f, nullptr);
  glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
  EXPECT_EQ(pos[0], 15.0f);
}

TEST_F(Pixel, CopyPixelsOverlapping) {
  // A 4-pixel ramp on row 0, copied one pixel to the right onto itself.
  const GLubyte ramp[16] = {10, 0, 0, 255, 20, 0, 0, 255, 30, 0, 0, 255, 40, 0, 0, 255};
  glWindowPos2i(0, 0);
  glDrawPixels(4, 1, GL_RGBA, GL_UNSIGNED_BYTE, ramp);
  glWindowPos2i(1, 0);
  glCopyPixels(0, 0, 4, 1, GL_COLOR);
  EXPECT_EQ(pixel(0, 0) & 0xff, 10u);
  EXPECT_EQ(pixel(1, 0) & 0xff, 10u);
  EXPECT_EQ(pixel(2, 0) & 0xff, 20u);
  EXPECT_EQ(pixel(4, 0) & 0xff, 40u);
}

TEST_F(Pixel, DepthAndStencilDrawPixels) {
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glColor3f(0.0f, 1.0f, 0.0f);
  glWindowPos2i(0, 0);
  const GLfloat z[2] = {0.25f, 0.75f};
  glDrawPixels(2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, z);
  GLfloat back[2] = {};
  glReadPixels(0, 0, 2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, back);
  EXPECT_NEAR(back[0], 0.25f, 1e-6);
  EXPECT_NEAR(back[1], 0.75f, 1e-6);
  EXPECT_EQ(pixel(0, 0), 0xff00ff00u); // raster colour
  // Depth scale/bias on the way in.
  glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
  glDepthFunc(GL_ALWAYS);
  glDrawPixels(2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, z);
  glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
  glReadPixels(0, 0, 2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, back);
  EXPECT_NEAR(back[1], 0.375f, 1e-6);

  // Stencil: only scissor and write mask apply.
  glStencilMask(0x0f);
  const GLubyte s[3] = {0xff, 0x12, 0x34};
  glDrawPixels(3, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
  GLubyte sb[3] = {};
  glReadPixels(0, 0, 3, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sb);
  EXPECT_EQ(sb[0], 0x0f);
  EXPECT_EQ(sb[1], 0x02);
  EXPECT_EQ(sb[2], 0x04);
  // Copying stencil with an offset, then reading it back through INDEX_OFFSET.
  glStencilMask(0xff);
  glWindowPos2i(0, 1);
  glCopyPixels(0, 0, 3, 1, GL_STENCIL);
  glPixelTransferi(GL_INDEX_OFFSET, 1);
  glReadPixels(0, 1, 3, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sb);
  EXPECT_EQ(sb[0], 0x10);
  EXPECT_EQ(sb[2], 0x05);
}

TEST_F(Pixel, ReadPixelsThroughScaleBiasAndMaps) {
  glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glPixelTransferf(GL_RED_SCALE, 2.0f);
  glPixelTransferf(GL_BLUE_BIAS, -0.5f);
  GLubyte out[8] = {};
  glReadPixels(0, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(out[0], 102);
  EXPECT_EQ(out[1], 102);
  EXPECT_NEAR(out[2], 25.5, 0.5); // 153/255 - 0.5 = 0.1 -> 25.5
  glPixelTransferi(GL_MAP_COLOR, 1);
  const GLfloat map[2] = {1.0f, 0.0f};
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, map);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(out[1], 255); // 0.4 rounds to entry 0
  expect_error(GL_NO_ERROR);
}

TEST_F(Pixel, AttribStackSavesPixelModeAndRasterPosition) {
  glWindowPos2i(5, 6);
  glPushAttrib(GL_PIXEL_MODE_BIT | GL_CURRENT_BIT);
  glPixelZoom(3.0f, 3.0f);
  glPixelTransferf(GL_RED_SCALE, 4.0f);
  glPixelTransferi(GL_MAP_STENCIL, 1);
  glWindowPos2i(9, 9);
  glPopAttrib();
  EXPECT_EQ(get_float(GL_ZOOM_X), 1.0f);
  EXPECT_EQ(get_float(GL_RED_SCALE), 1.0f);
  EXPECT_EQ(get_int(GL_MAP_STENCIL), 0);
  GLfloat pos[4];
  glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
  EXPECT_EQ(pos[0], 5.0f);
  EXPECT_EQ(pos[1], 6.0f);
}

TEST_F(Pixel, ColorIndexAndStencilTransferOnDraw) {
  // GL 2.1 §3.6.5: shift/offset, then the I_TO_x maps (2^n entries, index masked).
  const GLfloat r[4] = {0.0f, 1.0f, 0.0f, 0.0f};
  const GLfloat g[4] = {0.0f, 0.0f, 1.0f, 0.0f};
  const GLfloat one[1] = {1.0f};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, r);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 4, g);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 1, one);
  glPixelTransferi(GL_INDEX_SHIFT, 1);
  glPixelTransferi(GL_INDEX_OFFSET, -1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const GLubyte idx[2] = {1, 3}; // (1 << 1) - 1 = 1: red; (3 << 1) - 1 = 5 & 3 = 1: red
  const GLushort idx2[1] = {2};  // 3 & 3 = 3: black
  glWindowPos2i(0, 0);
  glDrawPixels(2, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx);
  glWindowPos2i(2, 0);
  glDrawPixels(1, 1, GL_COLOR_INDEX, GL_UNSIGNED_SHORT, idx2);
  EXPECT_EQ(pixel(0, 0), 0xff0000ffu);
  EXPECT_EQ(pixel(1, 0), 0xff0000ffu);
  EXPECT_EQ(pixel(2, 0), 0xff000000u);
  // MAP_STENCIL on DrawPixels of stencil indices.
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  const GLuint smap[2] = {7, 9};
  glPixelMapuiv(GL_PIXEL_MAP_S_TO_S, 2, smap);
  glPixelTransferi(GL_MAP_STENCIL, 1);
  const GLubyte s[2] = {0, 3};
  glWindowPos2i(0, 4);
  glDrawPixels(2, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
  glPixelTransferi(GL_MAP_STENCIL, 0);
  GLubyte sb[2] = {};
  glReadPixels(0, 4, 2, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sb);
  EXPECT_EQ(sb[0], 7);
  EXPECT_EQ(sb[1], 9);
}

TEST_F(Pixel, RasterPositionIsRoundedForImagesNotBitmaps) {
  const GLubyte red[4] = {255, 0, 0, 255};
  glWindowPos2f(3.5f, 2.49f); // rounds to (4, 2), as SGI's implementation and Mesa place it
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
  EXPECT_EQ(pixel(4, 2), 0xff0000ffu);
  EXPECT_EQ(pixel(3, 2), 0u);
  // Bitmaps use floor(x_rp - x_bo) (§3.7).
  const GLubyte bit[1] = {0x80};
  glColor3f(0.0f, 1.0f, 0.0f);
  glWindowPos2f(6.9f, 2.0f);
  glBitmap(1, 1, 0.0f, 0.0f, 0.0f, 0.0f, bit);
  EXPECT_EQ(pixel(6, 2), 0xff00ff00u);
}

TEST_F(Pixel, CopyPixelsDepthAndClippedSource) {
  glClearDepth(0.5);
  glClear(GL_DEPTH_BUFFER_BIT);
  glWindowPos2i(0, 0);
  const GLfloat z[2] = {0.125f, 0.875f};
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glDrawPixels(2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, z);
  glWindowPos2i(10, 10);
  glPixelTransferf(GL_DEPTH_BIAS, 0.0625f);
  glCopyPixels(0, 0, 2, 1, GL_DEPTH);
  glPixelTransferf(GL_DEPTH_BIAS, 0.0f);
  GLfloat back[2] = {};
  glReadPixels(10, 10, 2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, back);
  EXPECT_NEAR(back[0], 0.1875f, 1e-6);
  EXPECT_NEAR(back[1], 0.9375f, 1e-6);
  // A source half outside the window lands at its place in the rectangle.
  const GLubyte blue[4] = {0, 0, 255, 255};
  glDisable(GL_DEPTH_TEST);
  glWindowPos2i(0, 20);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, blue);
  glWindowPos2i(20, 20);
  glCopyPixels(-3, 20, 5, 1, GL_COLOR);
  EXPECT_EQ(pixel(23, 20), 0xffff0000u);
  expect_error(GL_NO_ERROR);
}

TEST_F(Pixel, BitmapTakesTheColourSum) {
  glEnable(GL_COLOR_SUM);
  glColor3f(0.0f, 0.5f, 0.0f);
  glSecondaryColor3f(0.5f, 0.0f, 0.25f);
  glWindowPos2i(1, 1);
  GLfloat c2[4];
  glGetFloatv(GL_CURRENT_RASTER_SECONDARY_COLOR, c2);
  EXPECT_EQ(c2[0], 0.5f);
  const GLubyte bit[1] = {0x80};
  glBitmap(1, 1, 0, 0, 0, 0, bit);
  EXPECT_EQ(pixel(1, 1), 0xff408080u);
}

TEST_F(Pixel, NonFiniteWindowPositionsDrawNothing) {
  const GLubyte red[16] = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
  const std::vector<uint8_t> before = buf_;
  for (float v : {std::nanf(""), INFINITY, -INFINITY, 1e30f}) {
    glWindowPos2f(v, 1.0f);
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, red);
    glBitmap(2, 2, 0, 0, v, v, red);
    glCopyPixels(0, 0, 4, 4, GL_COLOR);
  }
  EXPECT_EQ(buf_, before);
  expect_error(GL_NO_ERROR);
}

} // namespace
