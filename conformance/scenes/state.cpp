// Per-primitive and per-fragment state: face culling and glFrontFace (GL 2.1 §3.5.1), polygon
// modes (§3.5.4), the colour mask on drawing and on clears (§4.2.2, §4.2.3) and blending with
// (ONE, ONE) and (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) (§4.1.8).
#include "scene_util.h"

#include <cmath>

using namespace scenes;

namespace {

// Geometry of both windings: a counter-clockwise and a clockwise triangle, quads of alternating
// winding, and a fan that folds over itself.
void mixed_facing_geometry(float w, float h) {
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 0.25f, 0.25f);
  glVertex2f(0.08f * w, 0.62f * h);
  glVertex2f(0.46f * w, 0.64f * h);
  glColor3f(1.0f, 0.75f, 0.25f);
  glVertex2f(0.24f * w, 0.94f * h); // counter-clockwise
  glColor3f(0.25f, 0.5625f, 1.0f);
  glVertex2f(0.54f * w, 0.62f * h);
  glVertex2f(0.76f * w, 0.95f * h);
  glColor3f(0.25f, 1.0f, 1.0f);
  glVertex2f(0.93f * w, 0.66f * h); // clockwise
  glEnd();
  // Convex quads of alternating winding (a self-intersecting quad would be undefined,
  // GL 2.1 §2.6.1).
  glBegin(GL_QUADS);
  for (int i = 0; i < 6; ++i) {
    const float x = 0.06f * w + 0.15f * w * static_cast<float>(i);
    const float corners[4][2] = {{x, 0.36f * h}, {x + 0.12f * w, 0.38f * h},
                                 {x + 0.14f * w, 0.56f * h}, {x + 0.02f * w, 0.55f * h}};
    // One colour per quad: smooth colours that are not affine would depend on how the quad is
    // split into triangles, which is not what this geometry tests.
    palette_color(i);
    for (int k = 0; k < 4; ++k) {
      const int v = i % 2 ? 3 - k : k; // odd quads clockwise
      glVertex2f(corners[v][0], corners[v][1]);
    }
  }
  glEnd();
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1.0f, 1.0f, 1.0f);
  glVertex2f(0.5f * w + 0.2f, 0.17f * h + 0.1f);
  const float angles[7] = {0.0f, 1.0f, 2.2f, 1.6f, 3.3f, 4.4f, 3.9f};
  for (int i = 0; i < 7; ++i) {
    palette_color(i + 8);
    glVertex2f(0.5f * w + 0.42f * w * std::cos(angles[i]), 0.17f * h + 0.14f * h * std::sin(angles[i]));
  }
  glEnd();
}

} // namespace

PINEDA_SCENE(cull_modes, "glCullFace BACK/FRONT/FRONT_AND_BACK x glFrontFace CCW/CW, plus a mirror") {
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLenum modes[4] = {0, GL_BACK, GL_FRONT, GL_FRONT_AND_BACK};
  for (int p = 0; p < 8; ++p) {
    const Panel pn = panel(frame, p, 4, 2);
    const float w = static_cast<float>(pn.w), h = static_cast<float>(pn.h);
    glFrontFace(p < 4 ? GL_CCW : GL_CW);
    if (modes[p % 4]) {
      glEnable(GL_CULL_FACE);
      glCullFace(modes[p % 4]);
    } else {
      glDisable(GL_CULL_FACE);
    }
    // Upper half as is; lower half mirrored by a negative scale, which reverses every winding in
    // window coordinates where facing is decided.
    glPushMatrix();
    glTranslatef(0.0f, 0.5f * h, 0.0f);
    glScalef(1.0f, 0.5f, 1.0f);
    mixed_facing_geometry(w, h);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(w, 0.0f, 0.0f);
    glScalef(-1.0f, 0.5f, 1.0f);
    mixed_facing_geometry(w, h);
    glPopMatrix();
    // Points are never culled (culling applies to polygons only).
    glBegin(GL_POINTS);
    glColor3f(1.0f, 1.0f, 1.0f);
    for (int i = 0; i < 8; ++i) glVertex2f(4.5f + 6.0f * i, std::floor(0.5f * h) + 0.25f);
    glEnd();
  }
  glDisable(GL_CULL_FACE);
  glFrontFace(GL_CCW);
}

PINEDA_SCENE(polygon_modes, "glPolygonMode point/line/fill for front and back, with culling",
             .allowance = kLineAllowance, .why = kLineWhy) {
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLenum settings[6][2] = {{GL_LINE, GL_LINE},  {GL_POINT, GL_POINT}, {GL_LINE, GL_FILL},
                                 {GL_POINT, GL_LINE}, {GL_FILL, GL_POINT},  {GL_LINE, GL_LINE}};
  for (int p = 0; p < 6; ++p) {
    const Panel pn = panel(frame, p, 3, 2);
    glPolygonMode(GL_FRONT, settings[p][0]);
    glPolygonMode(GL_BACK, settings[p][1]);
    // The last panel culls back faces first: culling happens before the polygon mode applies.
    if (p == 5) glEnable(GL_CULL_FACE);
    mixed_facing_geometry(static_cast<float>(pn.w), static_cast<float>(pn.h));
    glDisable(GL_CULL_FACE);
  }
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

PINEDA_SCENE(color_mask, "glColorMask per channel on drawing and on glClear (alpha included)") {
  // Clear everything, then clear again with only red and blue enabled: green and alpha keep the
  // first clear's values (GL 2.1 §4.2.3).
  glClearColor(0.25f, 0.75f, 0.125f, 0.875f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glClearColor(0.625f, 0.0f, 0.375f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  const GLboolean masks[9][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1},
                                 {1, 1, 0, 0}, {0, 1, 1, 1}, {1, 0, 1, 0}, {0, 0, 0, 0},
                                 {1, 1, 1, 1}};
  for (int p = 0; p < 9; ++p) {
    const Panel pn = panel(frame, p, 3, 3, 6);
    glColorMask(masks[p][0], masks[p][1], masks[p][2], masks[p][3]);
    const float w = static_cast<float>(pn.w), h = static_cast<float>(pn.h);
    glBegin(GL_TRIANGLES);
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    glVertex2f(0.05f * w, 0.05f * h);
    glColor4f(1.0f, 0.125f, 0.875f, 0.25f);
    glVertex2f(0.95f * w, 0.1f * h);
    glColor4f(0.0f, 0.75f, 0.25f, 0.625f);
    glVertex2f(0.4f * w, 0.95f * h);
    glEnd();
    glColor4f(0.0f, 0.0f, 0.0f, 0.0f);
    glRectf(0.6f * w, 0.55f * h, 0.92f * w, 0.9f * h);
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

PINEDA_SCENE(blend_additive, "glBlendFunc(GL_ONE, GL_ONE): overlapping discs saturate at 1") {
  clear_frame(0.0f, 0.0f, 0.0f, 0.0f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  // Three primary discs of 0.625 overlap: pairs and the triple exceed 1 and must clamp.
  const float centres[3][2] = {{100.3f, 150.2f}, {156.1f, 150.4f}, {128.2f, 102.3f}};
  for (int d = 0; d < 3; ++d) {
    glBegin(GL_TRIANGLE_FAN);
    glColor4f(d == 0 ? 0.625f : 0.0f, d == 1 ? 0.625f : 0.0f, d == 2 ? 0.625f : 0.0f, 0.375f);
    glVertex2f(centres[d][0], centres[d][1]);
    for (int i = 0; i <= 40; ++i) {
      const float a = 2.0f * kPi * static_cast<float>(i) / 40.0f;
      glColor4f(d == 0 ? 0.25f : 0.0f, d == 1 ? 0.25f : 0.0f, d == 2 ? 0.25f : 0.0f, 0.125f);
      glVertex2f(centres[d][0] + 62.0f * std::cos(a), centres[d][1] + 62.0f * std::sin(a));
    }
    glEnd();
  }
  // A stack of dim translucent bars: sums of eight 1/16 steps are exact in 8 bits.
  for (int i = 0; i < 8; ++i) {
    glColor4f(0.0625f, 0.0625f, 0.0625f, 0.0625f);
    glRectf(8.25f + 12.0f * i, 8.25f, 240.25f, 40.25f);
  }
}

PINEDA_SCENE(blend_alpha, "glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) layers over a checkerboard") {
  clear_frame(0.0f, 0.0f, 0.0f, 1.0f);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      const float v = (x + y) % 2 ? 0.875f : 0.125f;
      glColor4f(v, v, v, 1.0f);
      glRecti(x * 32, y * 32, x * 32 + 32, y * 32 + 32);
    }
  }
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  // At most three layers overlap anywhere, so 8-bit rounding differences cannot pile up beyond
  // the tolerance.
  Rng rng(201);
  glBegin(GL_TRIANGLES);
  for (int t = 0; t < 9; ++t) {
    const float cx = 40.0f + 88.0f * (t % 3) + rng.range(-8.0f, 8.0f);
    const float cy = 40.0f + 88.0f * (t / 3) + rng.range(-8.0f, 8.0f);
    for (int k = 0; k < 3; ++k) {
      const float* c = palette(t + 4 * k);
      glColor4f(c[0], c[1], c[2], 0.125f + 0.25f * k + 0.0625f * (t % 3));
      const float a = 2.0f * kPi * k / 3.0f + 0.4f * t;
      glVertex2f(cx + 56.0f * std::cos(a), cy + 56.0f * std::sin(a));
    }
  }
  glEnd();
  glBegin(GL_QUADS);
  glColor4f(1.0f, 1.0f, 1.0f, 0.375f);
  glVertex2f(20.3f, 118.2f);
  glVertex2f(236.1f, 118.2f);
  glColor4f(0.0f, 0.0f, 1.0f, 0.75f);
  glVertex2f(236.1f, 138.4f);
  glVertex2f(20.3f, 138.4f);
  glEnd();
  glDisable(GL_BLEND);
}
