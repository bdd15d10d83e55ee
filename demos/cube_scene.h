// The spinning colour cube of the headless demos (osmesa_cube through OSMesa, egl_cube through
// EGL): the scene, the animation, the screenshot and the check that the picture shows it.
#pragma once

#include <GL/gl.h>

#include <cstdio>
#include <set>
#include <string>
#include <vector>

namespace cube {

constexpr int kWidth = 320, kHeight = 240;

inline void draw_cube() {
  // Each face gets its own corner colours so smooth shading shows across it.
  static const float v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  static const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                  {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
  glBegin(GL_QUADS);
  for (const auto& f : faces)
    for (int k : f) {
      glColor3f(0.2f + 0.8f * (v[k][0] > 0), 0.2f + 0.8f * (v[k][1] > 0),
                0.2f + 0.8f * (v[k][2] > 0));
      glVertex3fv(v[k]);
    }
  glEnd();
}

// The GL state of the scene, once after the context is made current.
inline void setup() {
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1.0, 1.0, -0.75, 0.75, 1.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
}

// Frame `frame` of the animation.
inline void draw_frame(int frame) {
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -5.0f);
  glRotatef(static_cast<float>(frame) * 3.0f, 1.0f, 0.7f, 0.2f);
  draw_cube();
  glFinish();
}

// Bottom-up RGBA rows as a binary PPM (top-down rows).
inline bool write_ppm(const std::string& path, const std::vector<unsigned char>& rgba) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return false;
  std::fprintf(f, "P6\n%d %d\n255\n", kWidth, kHeight);
  for (int y = kHeight - 1; y >= 0; --y)
    for (int x = 0; x < kWidth; ++x)
      std::fwrite(&rgba[(y * kWidth + x) * 4], 1, 3, f);
  return std::fclose(f) == 0;
}

// Whether the picture shows the cube: several colours over the background, no GL error.
inline bool shows_cube(const std::vector<unsigned char>& rgba) {
  std::set<unsigned> colours;
  for (size_t i = 0; i < rgba.size(); i += 4)
    colours.insert(rgba[i] | rgba[i + 1] << 8 | rgba[i + 2] << 16);
  return colours.size() >= 50 && glGetError() == GL_NO_ERROR;
}

} // namespace cube
