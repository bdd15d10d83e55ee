// The depth buffer (GL 2.1 §4.1.6): the eight depth functions, the depth mask (also on clears,
// §4.2.3), glDepthRange (§2.11.1), glClearDepth, the context's depth precision (16, 24 and 32
// bits, and none) and depth interpolation (§3.5.1).
#include "scene_util.h"

#include <cmath>

using namespace scenes;

namespace {

// Under the default glOrtho(..., -1, 1), window depth is (1 - z) / 2 (GL 2.1 §2.11): the object
// z that lands on window depth `window_z`.
double object_z(double window_z) { return 1.0 - 2.0 * window_z; }

// An axis-aligned quad whose window depth runs linearly from z_left to z_right. Corners move by
// 1/8 pixel so that edges computed from panel sizes (w * 0.3 = 37.5, ...) never pass through
// pixel centres: which side owns such a centre is left to the implementation (GL 2.1 §3.5.1),
// and these scenes are about depth, not about that rule.
void depth_quad(double x0, double y0, double x1, double y1, double z_left, double z_right) {
  x0 += 0.125;
  x1 += 0.125;
  y0 += 0.125;
  y1 += 0.125;
  glBegin(GL_QUADS);
  glVertex3d(x0, y0, object_z(z_left));
  glVertex3d(x1, y0, object_z(z_right));
  glVertex3d(x1, y1, object_z(z_right));
  glVertex3d(x0, y1, object_z(z_left));
  glEnd();
}

// Layers whose window depths fall inside one 16-bit depth step (k / 65535 .. (k + 1) / 65535)
// but more than 50 steps apart at 24 bits: a 16-bit buffer cannot tell them apart, deeper ones
// can. Small k keeps them in the same 16-bit step whether an implementation scales by 65535 or
// 65536 and rounds or truncates. `A` is drawn first with GL_LESS, then `B` slightly farther with
// GL_LEQUAL (wins only where the depths compare equal), then `C` slightly nearer with GL_LESS
// (wins only where nearer is resolvable).
void precision_strips(const Frame& frame) {
  const int strips = 8;
  const double h = (frame.height - 8.0) / strips;
  for (int s = 0; s < strips; ++s) {
    const double k = 400.0 + 300.0 * s;
    const double a = (k + 0.2) / 65535.0, b = (k + 0.45) / 65535.0, c = (k + 0.05) / 65535.0;
    const double y0 = 4.0 + s * h, y1 = y0 + h - 3.0;
    glDepthFunc(GL_LESS);
    palette_color(2 * s);
    depth_quad(4.0, y0, 124.0, y1, a, a);
    glDepthFunc(GL_LEQUAL);
    glColor3f(1.0f, 1.0f, 1.0f);
    depth_quad(24.0, y0 + 4.0, 64.0, y1 - 4.0, b, b);
    glDepthFunc(GL_LESS);
    glColor3f(0.25f, 0.25f, 0.25f);
    depth_quad(80.0, y0 + 4.0, 120.0, y1 - 4.0, c, c);
  }
}

// Geometry every depth precision resolves: a perspective fan of intersecting blades.
void intersecting_blades(const Frame& frame) {
  glViewport(frame.width / 2, 0, frame.width / 2, frame.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -1.0, 1.0, 1.0, 12.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -4.0f);
  glDepthFunc(GL_LESS);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 12; ++i) {
    const float a = 2.0f * kPi * static_cast<float>(i) / 12.0f;
    const float c = std::cos(a), s = std::sin(a);
    palette_color(i);
    glVertex3f(-1.6f * c, -1.6f * s, 1.5f);
    palette_color(i + 4);
    glVertex3f(1.6f * c - 0.5f * s, 1.6f * s + 0.5f * c, -1.5f);
    palette_color(i + 8);
    glVertex3f(1.6f * c + 0.5f * s, 1.6f * s - 0.5f * c, -1.3f);
  }
  glEnd();
}

void depth_precision_scene(const Frame& frame) {
  clear_frame(0.0f, 0.0f, 0.0f);
  glEnable(GL_DEPTH_TEST);
  precision_strips(frame);
  intersecting_blades(frame);
}

} // namespace

PINEDA_SCENE(depth_funcs, "All eight glDepthFunc against tilted, equal and far-plane surfaces") {
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLenum funcs[8] = {GL_NEVER, GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                           GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
  glEnable(GL_DEPTH_TEST);
  for (int p = 0; p < 8; ++p) {
    const Panel pn = panel(frame, p, 4, 2);
    // Even width so that the tilted quad crosses depth 0.5 on a pixel edge, not a pixel centre.
    const double x0 = 2.0, x1 = 2.0 + 2.0 * std::floor((pn.w - 4) / 2.0);
    const double band = (pn.h - 8.0) / 3.0;
    glDepthFunc(GL_LESS);
    glColor3f(0.25f, 0.25f, 0.375f);
    depth_quad(x0, 2.0, x1, 2.0 + band, 0.2, 0.8);
    glColor3f(0.375f, 0.25f, 0.25f);
    depth_quad(x0, 4.0 + band, x1, 4.0 + 2.0 * band, 0.3, 0.7);
    glDepthFunc(funcs[p]);
    // Against a tilted surface: passes on one side of its crossing of depth 0.5.
    glColor3f(1.0f, 0.125f, 0.125f);
    depth_quad(x0 + 2.0, 6.0, x1 - 2.0, band - 2.0, 0.5, 0.5);
    // The very same quad again: identical depths, so only the "equal" functions pass.
    glColor3f(0.125f, 1.0f, 0.125f);
    depth_quad(x0, 4.0 + band, x1, 4.0 + 2.0 * band, 0.3, 0.7);
    // Against the cleared depth 1: at depth exactly 1 (the far plane, still inside the view
    // volume) and at 0.25.
    glColor3f(0.25f, 0.375f, 1.0f);
    depth_quad(x0, 6.0 + 2.0 * band, 0.5 * (x0 + x1), 6.0 + 3.0 * band, 1.0, 1.0);
    glColor3f(1.0f, 1.0f, 0.125f);
    depth_quad(0.5 * (x0 + x1), 6.0 + 2.0 * band, x1, 6.0 + 3.0 * band, 0.25, 0.25);
  }
}

PINEDA_SCENE(depth_mask, "glDepthMask(GL_FALSE) on drawing and on glClear of the depth buffer") {
  clear_frame(0.0f, 0.0f, 0.0f);
  glEnable(GL_DEPTH_TEST);
  // With the mask off, clearing the depth buffer must leave it alone (GL 2.1 §4.2.3): the
  // depth stays 1 from clear_frame and the quads below still pass GL_LESS.
  glDepthMask(GL_FALSE);
  glClearDepth(0.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glClearDepth(1.0);
  for (int p = 0; p < 4; ++p) {
    const Panel pn = panel(frame, p, 2, 2);
    const double w = pn.w, h = pn.h;
    // Near red quad written with the mask as the panel says, then a farther green one.
    glDepthMask(p % 2 ? GL_TRUE : GL_FALSE);
    glColor3f(1.0f, 0.125f, 0.125f);
    depth_quad(10.0, 10.0, w * 0.6, h * 0.6, 0.3, 0.4);
    glDepthMask(GL_TRUE);
    glColor3f(0.125f, 1.0f, 0.125f);
    depth_quad(w * 0.3, h * 0.3, w - 10.0, h - 10.0, 0.5, 0.6);
    // Panels 2 and 3: a blue quad in between, drawn with the mask off; a yellow one afterwards
    // at the blue depth must pass or fail exactly as if blue had never been drawn.
    if (p >= 2) {
      glDepthMask(GL_FALSE);
      glColor3f(0.25f, 0.375f, 1.0f);
      depth_quad(w * 0.15, h * 0.45, w * 0.85, h * 0.55, 0.45, 0.45);
      glDepthMask(GL_TRUE);
      glColor3f(1.0f, 1.0f, 0.125f);
      depth_quad(w * 0.45, h * 0.15, w * 0.55, h * 0.85, 0.45, 0.45);
    }
  }
}

PINEDA_SCENE(depth_range, "glDepthRange (0,1), (0.5,1), (1,0) reversed and (0.25,0.3) per panel") {
  clear_frame(0.0f, 0.0f, 0.0f);
  glEnable(GL_DEPTH_TEST);
  const double ranges[4][2] = {{0.0, 1.0}, {0.5, 1.0}, {1.0, 0.0}, {0.25, 0.3}};
  for (int p = 0; p < 4; ++p) {
    const Panel pn = panel(frame, p, 2, 2);
    const double w = pn.w, h = pn.h;
    glDepthRange(ranges[p][0], ranges[p][1]);
    // Two quads tilted in opposite directions: which one is in front flips with a reversed range.
    glColor3f(1.0f, 0.625f, 0.125f);
    depth_quad(8.0, 8.0, w - 8.0, h * 0.6, 0.1, 0.9);
    glColor3f(0.125f, 0.625f, 1.0f);
    depth_quad(8.0, h * 0.3, w - 8.0, h - 8.0, 0.85, 0.15);
    // A quad nearer in normalized depth but mapped through a farther range: it loses.
    glDepthRange(0.6, 0.9);
    glColor3f(1.0f, 1.0f, 1.0f);
    depth_quad(w * 0.4, 4.0, w * 0.6, h - 4.0, 0.0, 0.0);
  }
  glDepthRange(0.0, 1.0);
}

PINEDA_SCENE(depth_clear_value, "glClearDepth(0.6) with GL_LESS and GL_GREATER staircases") {
  glClearColor(0.0f, 0.0f, 0.125f, 1.0f);
  glClearDepth(0.6);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  for (int half = 0; half < 2; ++half) {
    glDepthFunc(half == 0 ? GL_LESS : GL_GREATER);
    for (int i = 0; i < 12; ++i) {
      // Window depths 0.1 .. 0.98, none within 0.02 of the clear value.
      const double z = 0.1 + 0.08 * i;
      palette_color(i);
      const double x0 = 8.0 + half * 128.0, y0 = 6.0 + i * 20.0;
      depth_quad(x0, y0, x0 + 112.0, y0 + 16.0, z, z);
    }
  }
}

PINEDA_SCENE(depth_bits_16, "16-bit depth: layers within one 16-bit step merge, blades resolve",
             .depth_bits = 16) {
  depth_precision_scene(frame);
}

PINEDA_SCENE(depth_bits_24, "24-bit depth: the same layers resolve", .depth_bits = 24) {
  depth_precision_scene(frame);
}

// Mesa grants 24 bits for a 32-bit request (GL_DEPTH_BITS reads 24), so this scene only uses
// separations that 24 and 32 bits both resolve: it must look like depth_bits_24.
PINEDA_SCENE(depth_bits_32, "32-bit depth request: resolves like 24 bits", .depth_bits = 32) {
  depth_precision_scene(frame);
}

PINEDA_SCENE(depth_none, "No depth buffer: GL_DEPTH_TEST enabled, every fragment passes",
             .depth_bits = 0) {
  // Without a depth buffer the depth test always passes (GL 2.1 §4.1.6): draw order decides.
  depth_precision_scene(frame);
}

PINEDA_SCENE(depth_interpolation, "Interpenetrating perspective surfaces: depth is linear in window space") {
  clear_frame(0.0f, 0.0f, 0.0f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(0.0f, -0.5f, -5.0f);
  glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
  glEnable(GL_DEPTH_TEST);
  // A wavy floor of triangles and steep pyramids piercing it; the intersection curves depend
  // on depth interpolation only. Large slopes keep ties between surfaces improbable.
  const int n = 12;
  auto height = [](int i, int j) {
    return 0.35f * std::sin(0.9f * static_cast<float>(i)) * std::cos(0.7f * static_cast<float>(j));
  };
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const float x0 = (i - n / 2) * 0.5f, x1 = x0 + 0.5f, y0 = (j - n / 2) * 0.5f, y1 = y0 + 0.5f;
      glColor3f(0.25f + 0.5f * i / n, 0.25f, 0.25f + 0.5f * j / n);
      glVertex3f(x0, y0, height(i, j));
      glVertex3f(x1, y0, height(i + 1, j));
      glColor3f(0.25f, 0.75f, 0.25f + 0.5f * j / n);
      glVertex3f(x1, y1, height(i + 1, j + 1));
      glVertex3f(x0, y0, height(i, j));
      glVertex3f(x1, y1, height(i + 1, j + 1));
      glColor3f(0.75f, 0.75f, 0.25f);
      glVertex3f(x0, y1, height(i, j + 1));
    }
  }
  for (int k = 0; k < 7; ++k) {
    const float cx = -2.2f + 0.75f * k, cy = -1.5f + 0.45f * static_cast<float>((k * 3) % 7);
    for (int side = 0; side < 4; ++side) {
      const float a0 = kPi * 0.5f * side + 0.3f * k, a1 = a0 + kPi * 0.5f;
      palette_color(k + side);
      glVertex3f(cx, cy, 1.4f);
      glVertex3f(cx + 0.4f * std::cos(a0), cy + 0.4f * std::sin(a0), -0.8f);
      glVertex3f(cx + 0.4f * std::cos(a1), cy + 0.4f * std::sin(a1), -0.8f);
    }
  }
  glEnd();
}
