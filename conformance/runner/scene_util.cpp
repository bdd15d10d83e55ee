#include "scene_util.h"

#include <cmath>

namespace scenes {

Panel panel(const Frame& frame, int index, int cols, int rows, int gap) {
  const int w = (frame.width - gap * (cols + 1)) / cols;
  const int h = (frame.height - gap * (rows + 1)) / rows;
  const int col = index % cols;
  const int row_from_top = index / cols;
  const Panel p{gap + col * (w + gap), frame.height - (row_from_top + 1) * (h + gap), w, h};
  glViewport(p.x, p.y, p.w, p.h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, p.w, 0.0, p.h, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  return p;
}

void window_projection(const Frame& frame) {
  glViewport(0, 0, frame.width, frame.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, frame.width, 0.0, frame.height, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

void clear_frame(float r, float g, float b, float a) {
  glClearColor(r, g, b, a);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

namespace {
// Channel values are multiples of 1/16 other than 1/2, so that every implementation converts them
// to the same 8-bit value (c * 255 is never a rounding tie, GL 2.1 §2.14.9).
constexpr float kColors[16][3] = {
    {1.0f, 0.125f, 0.125f}, {0.125f, 1.0f, 0.125f}, {0.25f, 0.375f, 1.0f},
    {1.0f, 1.0f, 0.125f},   {1.0f, 0.125f, 1.0f},   {0.125f, 1.0f, 1.0f},
    {1.0f, 0.625f, 0.125f}, {0.625f, 0.25f, 1.0f},  {0.5625f, 1.0f, 0.625f},
    {1.0f, 0.625f, 0.75f},  {0.75f, 0.75f, 0.75f},  {0.375f, 0.625f, 0.125f},
    {0.125f, 0.5625f, 0.625f}, {0.75f, 0.375f, 0.25f}, {0.875f, 0.875f, 0.5625f},
    {0.375f, 0.125f, 0.625f}};
} // namespace

const float* palette(int index) { return kColors[((index % 16) + 16) % 16]; }

void palette_color(int index, float alpha) {
  const float* c = palette(index);
  glColor4f(c[0], c[1], c[2], alpha);
}

float snap(float v, float steps) { return std::round(v * steps) / steps; }

} // namespace scenes
