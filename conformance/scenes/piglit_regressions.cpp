// Scenes for behaviour piglit's GL 1.x list (conformance/piglit) found wrong: pixel rectangles
// textured with the raster position's texture coordinates (GL 2.1 §3.6.4 "Conversion to
// Fragments", §3.7, §3.8; piglit draw-pixel-with-texture). Fog and CopyPixels are left out:
// llvmpipe fogs pixel fragments with fog coordinate 0 instead of the raster distance and does
// not texture CopyPixels, both against §3.10 and §4.3.3 (the unit tests check those).
#include "scene_util.h"

#include <vector>

using namespace scenes;

namespace {

// A 4x4 RGBA texture of distinct texels, nearest filtering, bound to TEXTURE_2D.
void checker_texture() {
  std::vector<GLubyte> t(4 * 4 * 4);
  for (int i = 0; i < 16; ++i) {
    t[i * 4 + 0] = static_cast<GLubyte>((i & 1) ? 255 : 128);
    t[i * 4 + 1] = static_cast<GLubyte>(64 * (i / 4));
    t[i * 4 + 2] = static_cast<GLubyte>(200 - 10 * i);
    t[i * 4 + 3] = static_cast<GLubyte>(150 + 6 * i);
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

} // namespace

PINEDA_SCENE(piglit_drawpixels_textured,
             "glDrawPixels with TEXTURE_2D on: every fragment takes the raster position's "
             "texture coordinates and goes through the texture environment (MODULATE, REPLACE, "
             "DECAL, ADD, BLEND) like a primitive's") {
  clear_frame(0.1f, 0.1f, 0.1f);
  checker_texture();
  const float env_color[4] = {0.3f, 0.9f, 0.2f, 0.5f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env_color);
  const int w = 24, h = 20;
  std::vector<GLubyte> img(static_cast<size_t>(w * h * 4));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      GLubyte* p = &img[static_cast<size_t>((y * w + x) * 4)];
      p[0] = static_cast<GLubyte>(x * 10);
      p[1] = static_cast<GLubyte>(255 - y * 12);
      p[2] = static_cast<GLubyte>(100 + x * 3);
      p[3] = static_cast<GLubyte>(128 + y * 6);
    }
  const GLenum modes[] = {GL_MODULATE, GL_REPLACE, GL_DECAL, GL_ADD, GL_BLEND};
  const float coords[][2] = {{0.1f, 0.1f}, {0.6f, 0.4f}, {0.9f, 0.8f}, {0.4f, 0.9f}};
  glEnable(GL_TEXTURE_2D);
  for (int m = 0; m < 5; ++m) {
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, static_cast<GLint>(modes[m]));
    for (int c = 0; c < 4; ++c) {
      glTexCoord2f(coords[c][0], coords[c][1]);
      glRasterPos2i(8 + c * 40, 8 + m * 30);
      glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
    }
  }
  glDisable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

PINEDA_SCENE(piglit_bitmap_textured,
             "glBitmap with TEXTURE_2D on: the raster colour through the texture environment "
             "at the raster position's texture coordinates (GL 2.1 §3.7)") {
  clear_frame(0.1f, 0.1f, 0.1f);
  checker_texture();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // A 16x16 ring.
  GLubyte ring[16 * 2];
  for (int y = 0; y < 16; ++y) {
    unsigned row = 0;
    for (int x = 0; x < 16; ++x) {
      const int dx = 2 * x - 15, dy = 2 * y - 15;
      const int d2 = dx * dx + dy * dy;
      if (d2 < 15 * 15 && d2 > 7 * 7) row |= 0x8000u >> x;
    }
    ring[y * 2] = static_cast<GLubyte>(row >> 8);
    ring[y * 2 + 1] = static_cast<GLubyte>(row & 0xffu);
  }
  const GLenum modes[] = {GL_MODULATE, GL_REPLACE, GL_DECAL, GL_ADD};
  const float coords[][2] = {{0.1f, 0.1f}, {0.6f, 0.4f}, {0.9f, 0.8f}, {0.4f, 0.9f}};
  glEnable(GL_TEXTURE_2D);
  for (int m = 0; m < 4; ++m) {
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, static_cast<GLint>(modes[m]));
    for (int c = 0; c < 4; ++c) {
      palette_color(m * 4 + c);
      glTexCoord2f(coords[c][0], coords[c][1]);
      glRasterPos2i(10 + c * 30, 10 + m * 30);
      glBitmap(16, 16, 0, 0, 0, 0, ring);
      // Mesa batches bitmaps and draws the batch with the state of whatever call flushes it:
      // without this flush llvmpipe textures each bitmap with the next one's coordinates.
      glFlush();
    }
  }
  glDisable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}
