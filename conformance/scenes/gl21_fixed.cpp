// The fixed-function features of GL 2.0 and 2.1 outside the shading language: separate
// stencil (GL 2.1 §4.1.5, §4.2.2), separate blend equations (§4.1.8), point sprites (§3.3),
// pixel buffer objects (§2.9, §3.6.1, §4.3.2) and sRGB textures (§3.8.1, §3.8.15). Mesa draws
// them as a GL 2.1 context (.gl_version). Each scene saves and restores the state it changes
// (glPushAttrib/glPushClientAttrib) and deletes its objects.
#include "scene_util.h"

#include <cmath>
#include <cstring>
#include <vector>

using namespace scenes;

namespace {

using StencilFuncSeparateFn = void(APIENTRY*)(GLenum, GLenum, GLint, GLuint);
using StencilOpSeparateFn = void(APIENTRY*)(GLenum, GLenum, GLenum, GLenum);
using StencilMaskSeparateFn = void(APIENTRY*)(GLenum, GLuint);
using BlendEquationSeparateFn = void(APIENTRY*)(GLenum, GLenum);
using BlendFuncSeparateFn = void(APIENTRY*)(GLenum, GLenum, GLenum, GLenum);
using PointParameterfFn = void(APIENTRY*)(GLenum, GLfloat);
using PointParameterfvFn = void(APIENTRY*)(GLenum, const GLfloat*);
using ActiveTextureFn = void(APIENTRY*)(GLenum);
using MultiTexCoord2fFn = void(APIENTRY*)(GLenum, GLfloat, GLfloat);
using GenBuffersFn = void(APIENTRY*)(GLsizei, GLuint*);
using DeleteBuffersFn = void(APIENTRY*)(GLsizei, const GLuint*);
using BindBufferFn = void(APIENTRY*)(GLenum, GLuint);
using BufferDataFn = void(APIENTRY*)(GLenum, GLsizeiptr, const void*, GLenum);
using BufferSubDataFn = void(APIENTRY*)(GLenum, GLintptr, GLsizeiptr, const void*);
using MapBufferFn = void*(APIENTRY*)(GLenum, GLenum);
using UnmapBufferFn = GLboolean(APIENTRY*)(GLenum);
using WindowPos2iFn = void(APIENTRY*)(GLint, GLint);

// Everything a scene here may change, saved for its end.
void push_all() {
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
}
void pop_all() {
  glPopClientAttrib();
  glPopAttrib();
}

// A quad over [x0, x1] x [y0, y1], counter-clockwise when ccw.
void rect(float x0, float y0, float x1, float y1, bool ccw = true) {
  glBegin(GL_QUADS);
  if (ccw) {
    glVertex2f(x0, y0);
    glVertex2f(x1, y0);
    glVertex2f(x1, y1);
    glVertex2f(x0, y1);
  } else {
    glVertex2f(x0, y0);
    glVertex2f(x0, y1);
    glVertex2f(x1, y1);
    glVertex2f(x1, y0);
  }
  glEnd();
}

// Shows the stencil values of the window as colours: one pass per bit plane, each adding
// (logic op OR) a colour with that bit at a different weight per channel, so every stencil
// value has its own colour and a value off by one changes a channel by at least 8.
void show_stencil(const Frame& frame) {
  window_projection(frame);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_OR);
  for (int b = 0; b < 8; ++b) {
    glStencilFunc(GL_EQUAL, 1 << b, 1u << b);
    glColor4f(static_cast<float>(1 << b) / 255.0f, static_cast<float>(1 << ((b + 3) & 7)) / 255.0f,
              static_cast<float>(1 << ((b + 5) & 7)) / 255.0f, 1.0f);
    glRecti(0, 0, frame.width, frame.height);
  }
  glDisable(GL_COLOR_LOGIC_OP);
  glDisable(GL_STENCIL_TEST);
}

// A w x h RGBA image: red and green ramps, a blue checker and an alpha ramp.
std::vector<GLubyte> gradient(int w, int h) {
  std::vector<GLubyte> p(static_cast<size_t>(w) * h * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      GLubyte* t = &p[(static_cast<size_t>(y) * w + x) * 4];
      t[0] = static_cast<GLubyte>((x * 255) / (w > 1 ? w - 1 : 1));
      t[1] = static_cast<GLubyte>((y * 255) / (h > 1 ? h - 1 : 1));
      t[2] = static_cast<GLubyte>(((x / 2 + y / 2) % 2) ? 230 : 30);
      t[3] = static_cast<GLubyte>(255 - ((x + y) * 200) / (w + h > 2 ? w + h - 2 : 1));
    }
  return p;
}

void textured_quad(float x0, float y0, float x1, float y1, float s0, float t0, float s1, float t1) {
  glBegin(GL_QUADS);
  glTexCoord2f(s0, t0);
  glVertex2f(x0, y0);
  glTexCoord2f(s1, t0);
  glVertex2f(x1, y0);
  glTexCoord2f(s1, t1);
  glVertex2f(x1, y1);
  glTexCoord2f(s0, t1);
  glVertex2f(x0, y1);
  glEnd();
}

} // namespace

// ---- separate stencil -----------------------------------------------------------------------

PINEDA_SCENE(gl2_stencil_separate, "Separate stencil: front- and back-facing triangles with their own function, reference, masks and operations (both windings, FrontFace CW), points and lines using the front state, then a test pass per face; stencil shown bit by bit", .stencil_bits = 8, .gl_version = "2.1") {
  const auto func_sep = proc<StencilFuncSeparateFn>("glStencilFuncSeparate");
  const auto op_sep = proc<StencilOpSeparateFn>("glStencilOpSeparate");
  const auto mask_sep = proc<StencilMaskSeparateFn>("glStencilMaskSeparate");
  push_all();
  glClearColor(0, 0, 0, 1);
  glClearStencil(0x10);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  // Front faces: INCR where drawn; back faces: REPLACE with 0x0b through write mask 0x0f.
  func_sep(GL_FRONT, GL_ALWAYS, 0, 0xff);
  func_sep(GL_BACK, GL_ALWAYS, 0x0b, 0xff);
  op_sep(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR);
  op_sep(GL_BACK, GL_KEEP, GL_KEEP, GL_REPLACE);
  mask_sep(GL_BACK, 0x0f);
  Rng rng(21);
  for (int i = 0; i < 24; ++i) {
    const float cx = rng.range(20, 236), cy = rng.range(100, 236), r = rng.range(12, 40);
    const float a = rng.range(0, 2 * kPi);
    const bool ccw = rng.below(2) == 0;
    glBegin(GL_TRIANGLES);
    for (int k = 0; k < 3; ++k) {
      const float ang = a + (ccw ? 1.0f : -1.0f) * static_cast<float>(k) * 2.0f * kPi / 3.0f;
      glVertex2f(snap(cx + r * std::cos(ang)), snap(cy + r * std::sin(ang)));
    }
    glEnd();
  }
  // With FrontFace(CW) the clockwise quad is the front one.
  glFrontFace(GL_CW);
  rect(8, 8, 40, 40, false);
  rect(48, 8, 80, 40, true);
  glFrontFace(GL_CCW);
  // Points and lines use the front state (§4.1.5): INCR.
  glPointSize(5);
  glBegin(GL_POINTS);
  for (int i = 0; i < 12; ++i)
    glVertex2f(96.5f + 8.0f * static_cast<float>(i), 20.5f);
  glEnd();
  glBegin(GL_LINES);
  glVertex2f(90, 40.5f);
  glVertex2f(250, 48.5f);
  glEnd();
  // The test: front faces pass where stencil > 0x10 (masked 0x1f), back faces where the
  // low bits equal 0x0b; failures zero (back) or invert (front) through their own masks.
  func_sep(GL_FRONT, GL_LESS, 0x10, 0x1f);
  func_sep(GL_BACK, GL_EQUAL, 0x0b, 0x0f);
  op_sep(GL_FRONT, GL_INVERT, GL_KEEP, GL_DECR);
  op_sep(GL_BACK, GL_ZERO, GL_KEEP, GL_INCR_WRAP);
  mask_sep(GL_FRONT, 0xf0);
  mask_sep(GL_BACK, 0xff);
  rect(10, 60, 120, 250, true);
  rect(130, 60, 250, 250, false);
  show_stencil(frame);
  pop_all();
}

// ---- blend equation separate ----------------------------------------------------------------

PINEDA_SCENE(gl2_blend_equation_separate, "glBlendEquationSeparate: every pair of the five equations for RGB and alpha, over a background with varying alpha; a second pass shows the destination alpha as colour", .gl_version = "2.1") {
  const auto eq_sep = proc<BlendEquationSeparateFn>("glBlendEquationSeparate");
  const auto func_sep = proc<BlendFuncSeparateFn>("glBlendFuncSeparate");
  push_all();
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  const GLenum eqs[5] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
  // Background: colour and alpha ramps, left half and right half differ.
  glBegin(GL_QUADS);
  glColor4f(0.2f, 0.7f, 0.4f, 0.1f);
  glVertex2f(0, 0);
  glColor4f(0.9f, 0.3f, 0.5f, 0.9f);
  glVertex2f(256, 0);
  glColor4f(0.5f, 0.2f, 0.9f, 0.6f);
  glVertex2f(256, 256);
  glColor4f(0.1f, 0.8f, 0.2f, 0.3f);
  glVertex2f(0, 256);
  glEnd();
  glEnable(GL_BLEND);
  func_sep(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      eq_sep(eqs[i], eqs[j]);
      const float x = 4.0f + 50.0f * static_cast<float>(i), y = 132.0f + 24.0f * static_cast<float>(j);
      glBegin(GL_QUADS);
      glColor4f(0.8f, 0.2f, 0.6f, 0.25f);
      glVertex2f(x, y);
      glColor4f(0.3f, 0.9f, 0.1f, 0.75f);
      glVertex2f(x + 46, y);
      glColor4f(0.5f, 0.5f, 0.9f, 0.5f);
      glVertex2f(x + 46, y + 20);
      glColor4f(0.1f, 0.4f, 0.3f, 0.9f);
      glVertex2f(x, y + 20);
      glEnd();
    }
  // The same quads again lower down, then their destination alpha copied into green and blue
  // (DST_ALPHA times a white quad, alpha untouched) so that the alpha equations show as
  // colour too.
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      eq_sep(eqs[j], eqs[i]);
      const float x = 4.0f + 50.0f * static_cast<float>(i), y = 4.0f + 24.0f * static_cast<float>(j);
      glColor4f(0.6f, 0.3f, 0.7f, 0.4f + 0.1f * static_cast<float>(j));
      glRectf(x, y, x + 46, y + 20);
    }
  eq_sep(GL_FUNC_ADD, GL_FUNC_ADD);
  glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_FALSE);
  glBlendFunc(GL_DST_ALPHA, GL_ZERO);
  glColor4f(1, 1, 1, 1);
  glRectf(0, 0, 256, 124);
  pop_all();
}

// ---- point sprites --------------------------------------------------------------------------

namespace {

// Point sprites of several sizes, positions and colours with a texture that shows the sprite
// coordinates (unit 0 replaces them, unit 1 keeps the vertex's), under the given origin.
void sprite_scene(GLenum origin) {
  const auto point_f = proc<PointParameterfFn>("glPointParameterf");
  const auto point_fv = proc<PointParameterfvFn>("glPointParameterfv");
  const auto active = proc<ActiveTextureFn>("glActiveTexture");
  const auto mtc = proc<MultiTexCoord2fFn>("glMultiTexCoord2f");
  push_all();
  glClearColor(0.1f, 0.1f, 0.15f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  GLuint tex[2] = {};
  glGenTextures(2, tex);
  // Unit 0: an 8x8 gradient with a checker (which corner is where shows the origin).
  const std::vector<GLubyte> img = gradient(8, 8);
  active(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  // Unit 1: a 2x2 texture sampled at the vertex's own coordinates (no replacement).
  const GLubyte small[16] = {255, 255, 255, 255, 128, 128, 255, 255,
                             255, 128, 128, 255, 128, 255, 128, 255};
  active(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, small);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  active(GL_TEXTURE0);

  glEnable(GL_POINT_SPRITE);
  point_f(GL_POINT_SPRITE_COORD_ORIGIN, static_cast<GLfloat>(origin));
  // Sizes on whole and half pixels, centres placed off pixel-centre ties.
  const float sizes[6] = {4, 7, 10, 16, 23.5f, 32};
  for (int i = 0; i < 6; ++i) {
    glPointSize(sizes[i]);
    glBegin(GL_POINTS);
    for (int j = 0; j < 4; ++j) {
      palette_color(i * 4 + j);
      mtc(GL_TEXTURE1, j % 2 ? 0.75f : 0.25f, j / 2 ? 0.75f : 0.25f);
      glVertex2f(22.0f + 40.0f * static_cast<float>(i) + 0.3f,
                 24.0f + 40.0f * static_cast<float>(j) + 0.2f);
    }
    glEnd();
  }
  // POINT_SMOOTH is ignored for sprites.
  glEnable(GL_POINT_SMOOTH);
  glPointSize(20);
  glColor4f(1, 1, 1, 1);
  glBegin(GL_POINTS);
  glVertex2f(40.3f, 200.4f);
  glEnd();
  glDisable(GL_POINT_SMOOTH);
  // Sizes from distance attenuation, clamped to [2, 40].
  const GLfloat atten[3] = {0.0f, 0.0f, 1.0f};
  point_fv(GL_POINT_DISTANCE_ATTENUATION, atten);
  point_f(GL_POINT_SIZE_MIN, 2.0f);
  point_f(GL_POINT_SIZE_MAX, 40.0f);
  glPointSize(60);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glFrustum(-1, 1, -1, 1, 1, 20);
  glMatrixMode(GL_MODELVIEW);
  glBegin(GL_POINTS);
  for (int k = 0; k < 4; ++k) {
    const float z = -1.5f - 1.1f * static_cast<float>(k);
    glColor4f(1, 1, 1, 1);
    glVertex3f((0.15f + 0.18f * static_cast<float>(k)) * -z, 0.6f * -z, z);
  }
  glEnd();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  // Sprites off again: an ordinary square point.
  glDisable(GL_POINT_SPRITE);
  glPointSize(9);
  glBegin(GL_POINTS);
  glVertex2f(230.5f, 230.5f);
  glEnd();
  pop_all();
  glDeleteTextures(2, tex);
}

} // namespace

PINEDA_SCENE(gl2_point_sprite_upper_left, "Point sprites, POINT_SPRITE_COORD_ORIGIN UPPER_LEFT: textured sprites of whole and fractional sizes with COORD_REPLACE on unit 0 and vertex coordinates on unit 1, smooth ignored, attenuated sizes", .gl_version = "2.1") {
  sprite_scene(GL_UPPER_LEFT);
}

PINEDA_SCENE(gl2_point_sprite_lower_left, "Point sprites, POINT_SPRITE_COORD_ORIGIN LOWER_LEFT: as gl2_point_sprite_upper_left with t running upwards", .gl_version = "2.1") {
  sprite_scene(GL_LOWER_LEFT);
}

PINEDA_SCENE(gl2_point_sprite_mipmap, "Point sprites with a mipmapped texture (LINEAR_MIPMAP_LINEAR): the sprite coordinates' derivatives pick the level", .gl_version = "2.1") {
  push_all();
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  // Each level a different colour tint over the gradient, so the chosen level shows.
  for (int level = 0, size = 64; size >= 1; ++level, size /= 2) {
    std::vector<GLubyte> img = gradient(size, size);
    for (size_t k = 0; k < img.size(); k += 4) {
      img[k + 3] = 255;
      img[k + 2] = static_cast<GLubyte>(40 * level);
    }
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 img.data());
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_POINT_SPRITE);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  const float sizes[5] = {6, 12, 24, 48, 63};
  float x = 6;
  for (float s : sizes) {
    glPointSize(s);
    glBegin(GL_POINTS);
    glVertex2f(x + s / 2 + 0.3f, 128.2f);
    glEnd();
    x += s + 4;
  }
  pop_all();
  glDeleteTextures(1, &tex);
}

// ---- pixel buffer objects -------------------------------------------------------------------

PINEDA_SCENE(gl2_pbo, "Pixel buffer objects: DrawPixels, TexImage2D, TexSubImage2D, Bitmap and PolygonStipple from a PIXEL_UNPACK_BUFFER at offsets, ReadPixels into a PIXEL_PACK_BUFFER (with pack state) drawn back from the same buffer, and a mapped buffer written by the application", .stencil_bits = 8, .gl_version = "2.1") {
  const auto gen = proc<GenBuffersFn>("glGenBuffers");
  const auto del = proc<DeleteBuffersFn>("glDeleteBuffers");
  const auto bind = proc<BindBufferFn>("glBindBuffer");
  const auto data = proc<BufferDataFn>("glBufferData");
  const auto sub = proc<BufferSubDataFn>("glBufferSubData");
  const auto map = proc<MapBufferFn>("glMapBuffer");
  const auto unmap = proc<UnmapBufferFn>("glUnmapBuffer");
  const auto window_pos = proc<WindowPos2iFn>("glWindowPos2i");
  push_all();
  glClearColor(0.05f, 0.05f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  GLuint buf[3] = {};
  gen(3, buf);
  GLuint tex = 0;
  glGenTextures(1, &tex);

  // An unpack buffer: 64 bytes of padding, then a 32x32 RGBA gradient, then 128 bytes of
  // polygon stipple, then a 24x24 bitmap.
  const std::vector<GLubyte> img = gradient(32, 32);
  const size_t img_at = 64, stipple_at = img_at + img.size(), bitmap_at = stipple_at + 128;
  bind(GL_PIXEL_UNPACK_BUFFER, buf[0]);
  data(GL_PIXEL_UNPACK_BUFFER, static_cast<GLsizeiptr>(bitmap_at + 24 * 3), nullptr,
       GL_STATIC_DRAW);
  sub(GL_PIXEL_UNPACK_BUFFER, static_cast<GLintptr>(img_at), static_cast<GLsizeiptr>(img.size()),
      img.data());
  GLubyte stipple[128];
  for (int i = 0; i < 128; ++i)
    stipple[i] = static_cast<GLubyte>((i / 4) % 2 ? 0xcc : 0x33);
  sub(GL_PIXEL_UNPACK_BUFFER, static_cast<GLintptr>(stipple_at), 128, stipple);
  GLubyte bitmap[24 * 3];
  for (int y = 0; y < 24; ++y)
    for (int b = 0; b < 3; ++b)
      bitmap[y * 3 + b] = static_cast<GLubyte>((y + b) % 3 == 0 ? 0xff : (0x81 << (y % 2)) & 0xff);
  sub(GL_PIXEL_UNPACK_BUFFER, static_cast<GLintptr>(bitmap_at), sizeof bitmap, bitmap);
  const auto offset = [](size_t at) { return reinterpret_cast<const void*>(at); };

  // DrawPixels from the buffer, with zoom, and with SKIP_PIXELS/ROW_LENGTH selecting a part.
  window_pos(8, 8);
  glDrawPixels(32, 32, GL_RGBA, GL_UNSIGNED_BYTE, offset(img_at));
  glPixelZoom(2.0f, 1.4f); // no zoomed row edge on a pixel centre (conformance/README.md)
  window_pos(48, 8);
  glDrawPixels(32, 32, GL_RGBA, GL_UNSIGNED_BYTE, offset(img_at));
  glPixelZoom(1, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 32);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 8);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 4);
  window_pos(120, 8);
  glDrawPixels(16, 20, GL_RGBA, GL_UNSIGNED_BYTE, offset(img_at));
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);

  // TexImage2D from the buffer, TexSubImage2D from a part of it, drawn on a quad.
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, offset(img_at));
  glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE,
                  offset(img_at + 4 * (32 * 16 + 16)));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  textured_quad(160, 8, 224, 72, 0, 0, 1, 1);
  glDisable(GL_TEXTURE_2D);

  // PolygonStipple and Bitmap from the buffer.
  glPolygonStipple(static_cast<const GLubyte*>(offset(stipple_at)));
  glEnable(GL_POLYGON_STIPPLE);
  glColor4f(0.9f, 0.6f, 0.1f, 1);
  rect(8, 90, 72, 150);
  glDisable(GL_POLYGON_STIPPLE);
  glColor4f(0.2f, 0.9f, 0.9f, 1);
  glRasterPos2i(80, 90);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1); // rows of 3 bytes, as stored
  for (int i = 0; i < 4; ++i)
    glBitmap(24, 24, 0, 0, 26, 4, static_cast<const GLubyte*>(offset(bitmap_at)));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  bind(GL_PIXEL_UNPACK_BUFFER, 0);

  // ReadPixels into a pack buffer (with pack skip and row length), then the same buffer
  // drawn as an unpack buffer.
  bind(GL_PIXEL_PACK_BUFFER, buf[1]);
  data(GL_PIXEL_PACK_BUFFER, 4 * 80 * 70 + 256, nullptr, GL_STREAM_COPY);
  glPixelStorei(GL_PACK_ROW_LENGTH, 80);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 4);
  glReadPixels(8, 8, 72, 64, GL_RGBA, GL_UNSIGNED_BYTE, reinterpret_cast<void*>(256));
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  bind(GL_PIXEL_PACK_BUFFER, 0);
  bind(GL_PIXEL_UNPACK_BUFFER, buf[1]);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 80);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 4);
  window_pos(8, 170);
  glDrawPixels(72, 64, GL_RGBA, GL_UNSIGNED_BYTE, offset(256));
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  // Luminance read back as floats into the buffer and drawn again from it.
  bind(GL_PIXEL_UNPACK_BUFFER, 0);
  bind(GL_PIXEL_PACK_BUFFER, buf[1]);
  glReadPixels(160, 8, 64, 64, GL_LUMINANCE, GL_FLOAT, nullptr);
  bind(GL_PIXEL_PACK_BUFFER, 0);
  bind(GL_PIXEL_UNPACK_BUFFER, buf[1]);
  window_pos(96, 170);
  glDrawPixels(64, 64, GL_LUMINANCE, GL_FLOAT, nullptr);
  bind(GL_PIXEL_UNPACK_BUFFER, 0);

  // A buffer the application fills through MapBuffer, drawn as stencil indices, then shown.
  bind(GL_PIXEL_UNPACK_BUFFER, buf[2]);
  data(GL_PIXEL_UNPACK_BUFFER, 48 * 48, nullptr, GL_STREAM_DRAW);
  auto* p = static_cast<GLubyte*>(map(GL_PIXEL_UNPACK_BUFFER, GL_WRITE_ONLY));
  if (p != nullptr) {
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 48; ++x)
        p[y * 48 + x] = static_cast<GLubyte>(((x / 6) ^ (y / 6)) & 1 ? 1 : 0);
    unmap(GL_PIXEL_UNPACK_BUFFER);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  window_pos(176, 176);
  glDrawPixels(48, 48, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, nullptr);
  bind(GL_PIXEL_UNPACK_BUFFER, 0);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 1, 1);
  glColor4f(1, 0.3f, 0.6f, 1);
  rect(170, 170, 230, 230);
  glDisable(GL_STENCIL_TEST);
  pop_all();
  del(3, buf);
  glDeleteTextures(1, &tex);
}

// ---- sRGB textures --------------------------------------------------------------------------

PINEDA_SCENE(gl2_srgb_textures, "sRGB textures: SRGB8, SRGB8_ALPHA8, SLUMINANCE8 and SLUMINANCE8_ALPHA8 images magnified with LINEAR and NEAREST, minified with LINEAR_MIPMAP_LINEAR over given levels, beside the same data as linear RGBA8; decoding comes before filtering", .gl_version = "2.1") {
  push_all();
  glClearColor(0.3f, 0.3f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  // A 4x4 image of strong contrasts (so filtering in sRGB or linear space differ) and an alpha
  // ramp.
  GLubyte rgba[4 * 4 * 4];
  GLubyte lum[4 * 4], la[4 * 4 * 2];
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const int i = y * 4 + x;
      const bool on = ((x + y) % 2) == 0;
      rgba[i * 4 + 0] = on ? 255 : 0;
      rgba[i * 4 + 1] = static_cast<GLubyte>(x * 85);
      rgba[i * 4 + 2] = on ? 20 : 200;
      rgba[i * 4 + 3] = static_cast<GLubyte>(60 + y * 60);
      lum[i] = on ? 250 : static_cast<GLubyte>(10 * x);
      la[i * 2] = lum[i];
      la[i * 2 + 1] = static_cast<GLubyte>(255 - 50 * y);
    }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  struct Format {
    GLint internal;
    GLenum format;
    const GLubyte* data;
  };
  const Format formats[5] = {{GL_RGBA8, GL_RGBA, rgba},
                             {GL_SRGB8, GL_RGBA, rgba},
                             {GL_SRGB8_ALPHA8, GL_RGBA, rgba},
                             {GL_SLUMINANCE8, GL_LUMINANCE, lum},
                             {GL_SLUMINANCE8_ALPHA8, GL_LUMINANCE_ALPHA, la}};
  GLuint tex[5] = {};
  glGenTextures(5, tex);
  for (int k = 0; k < 5; ++k) {
    glBindTexture(GL_TEXTURE_2D, tex[k]);
    glTexImage2D(GL_TEXTURE_2D, 0, formats[k].internal, 4, 4, 0, formats[k].format,
                 GL_UNSIGNED_BYTE, formats[k].data);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    const float x = 4.0f + 50.0f * static_cast<float>(k);
    // LINEAR magnification, CLAMP_TO_EDGE and REPEAT, then NEAREST.
    textured_quad(x, 196, x + 46, 252, 0, 0, 1, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    textured_quad(x, 136, x + 46, 192, -0.3f, -0.2f, 1.4f, 1.1f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    textured_quad(x, 96, x + 46, 132, 0, 0, 1, 1);
  }
  // Mipmapped minification: a 32x32 checker with given levels (each level a box filter of
  // the one above in sRGB values, so every format sees the same data), on a receding quad.
  std::vector<GLubyte> level(32 * 32 * 4);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      GLubyte* t = &level[(y * 32 + x) * 4];
      const bool on = ((x / 2 + y / 2) % 2) == 0;
      t[0] = on ? 240 : 16, t[1] = static_cast<GLubyte>(x * 8), t[2] = on ? 30 : 220;
      t[3] = 255;
    }
  GLuint mip[2] = {};
  glGenTextures(2, mip);
  const GLint mip_formats[2] = {GL_RGBA8, GL_SRGB8_ALPHA8};
  for (int k = 0; k < 2; ++k) {
    glBindTexture(GL_TEXTURE_2D, mip[k]);
    std::vector<GLubyte> cur = level;
    for (int l = 0, size = 32; size >= 1; ++l, size /= 2) {
      glTexImage2D(GL_TEXTURE_2D, l, mip_formats[k], size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   cur.data());
      if (size == 1) break;
      const int half = size / 2;
      std::vector<GLubyte> next(static_cast<size_t>(half) * half * 4);
      for (int y = 0; y < half; ++y)
        for (int x = 0; x < half; ++x)
          for (int c = 0; c < 4; ++c) {
            const auto at = [&](int xx, int yy) { return cur[(yy * size + xx) * 4 + c]; };
            next[(y * half + x) * 4 + c] = static_cast<GLubyte>(
                (at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) +
                 at(2 * x + 1, 2 * y + 1) + 2) / 4);
          }
      cur.swap(next);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    const float x0 = 4.0f + 126.0f * static_cast<float>(k);
    glBegin(GL_QUADS);
    glTexCoord4f(0, 0, 0, 1);
    glVertex2f(x0, 4);
    glTexCoord4f(4, 0, 0, 1);
    glVertex2f(x0 + 120, 4);
    glTexCoord4f(0.6f, 1.2f, 0, 0.3f);
    glVertex2f(x0 + 120 * 0.65f, 88);
    glTexCoord4f(0, 1.2f, 0, 0.3f);
    glVertex2f(x0 + 120 * 0.35f, 88);
    glEnd();
  }
  pop_all();
  glDeleteTextures(5, tex);
  glDeleteTextures(2, mip);
}
