// The OSMesa colour buffer formats (OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB) and
// OSMesaPixelStore(OSMESA_Y_UP, 0). The runner converts every buffer back to bottom-up RGBA8,
// so each of these scenes must look exactly like format_rgba (alpha reads 255 for OSMESA_RGB).
#include "scene_util.h"

#include <cmath>

using namespace scenes;

namespace {

// An asymmetric picture with every channel distinct and alpha varying, so that swapped
// channels, a mirrored row order or a wrong row stride all show.
void format_pattern(const Frame& frame) {
  glClearColor(0.125f, 0.25f, 0.375f, 0.625f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float w = static_cast<float>(frame.width), h = static_cast<float>(frame.height);
  // Rectangle edges move by 1/8 pixel so that none passes through a pixel centre at any of the
  // window sizes used (which side owns such a centre is the implementation's choice).
  auto rect = [](float x0, float y0, float x1, float y1) {
    glRectf(x0 + 0.125f, y0 + 0.125f, x1 + 0.125f, y1 + 0.125f);
  };
  // Pure channel bars along the bottom, with alpha ramps.
  const float bars[4][4] = {{1, 0, 0, 0.25f}, {0, 1, 0, 0.5625f}, {0, 0, 1, 0.875f}, {1, 1, 1, 0.125f}};
  for (int i = 0; i < 4; ++i) {
    glColor4fv(bars[i]);
    rect(0.05f * w + i * 0.23f * w, 0.04f * h, 0.05f * w + i * 0.23f * w + 0.2f * w, 0.2f * h);
  }
  // A smooth triangle whose corners differ in every channel including alpha.
  glBegin(GL_TRIANGLES);
  glColor4f(1.0f, 0.25f, 0.0f, 1.0f);
  glVertex2f(0.05f * w, 0.26f * h);
  glColor4f(0.0f, 1.0f, 0.375f, 0.0f);
  glVertex2f(0.6f * w, 0.3f * h);
  glColor4f(0.25f, 0.0f, 1.0f, 0.5625f);
  glVertex2f(0.15f * w, 0.95f * h);
  glEnd();
  // An "F" in the top-right corner: its orientation reveals a vertical or horizontal flip.
  glColor4f(1.0f, 0.875f, 0.125f, 0.75f);
  rect(0.68f * w, 0.45f * h, 0.74f * w, 0.95f * h);
  rect(0.74f * w, 0.89f * h, 0.95f * w, 0.95f * h);
  rect(0.74f * w, 0.68f * h, 0.88f * w, 0.74f * h);
  // Single pixels at the four corners, in different colours.
  glBegin(GL_POINTS);
  glColor4f(1, 0, 0, 1);
  glVertex2f(0.5f, 0.5f);
  glColor4f(0, 1, 0, 1);
  glVertex2f(w - 0.5f, 0.5f);
  glColor4f(0, 0, 1, 1);
  glVertex2f(0.5f, h - 0.5f);
  glColor4f(1, 1, 1, 1);
  glVertex2f(w - 0.5f, h - 0.5f);
  glEnd();
}

} // namespace

PINEDA_SCENE(format_rgba, "OSMESA_RGBA reference picture for the format scenes") {
  format_pattern(frame);
}

PINEDA_SCENE(format_bgra, "OSMESA_BGRA colour buffer", .format = OSMESA_BGRA) {
  format_pattern(frame);
}

PINEDA_SCENE(format_argb, "OSMESA_ARGB colour buffer", .format = OSMESA_ARGB) {
  format_pattern(frame);
}

PINEDA_SCENE(format_rgb, "OSMESA_RGB (3 bytes per pixel) at 250x170: rows not 4-byte aligned",
             .width = 250, .height = 170, .format = OSMESA_RGB, .softpipe_oracle = true,
             .why = "llvmpipe (Mesa 22.3) draws striped garbage into OSMESA_RGB buffers (clears are "
                    "right, triangles are not, and repeated frames differ); softpipe draws them "
                    "correctly") {
  format_pattern(frame);
}

PINEDA_SCENE(format_y_down, "OSMesaPixelStore(OSMESA_Y_UP, 0): first row in memory is the top",
             .y_up = false) {
  format_pattern(frame);
}

PINEDA_SCENE(format_bgra_y_down, "OSMESA_BGRA with OSMESA_Y_UP 0 at 200x120", .width = 200,
             .height = 120, .format = OSMESA_BGRA, .y_up = false) {
  format_pattern(frame);
}
