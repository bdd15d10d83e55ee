// Fog (GL 2.1 §3.10): LINEAR, EXP and EXP2 from the fragment depth (eye distance) and from
// the fog coordinate (GL 1.4 FogCoord, FOG_COORD_ARRAY), over smooth-shaded perspective
// geometry, with the colour sum, on lines and points. Each scene puts the fog state it touched
// back to the GL defaults at the end.
#include "scene_util.h"

#include <cmath>

using namespace scenes;

namespace {

void fog_defaults() {
  const GLfloat zero[4] = {0, 0, 0, 0};
  glDisable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_EXP);
  glFogf(GL_FOG_DENSITY, 1.0f);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 1.0f);
  glFogfv(GL_FOG_COLOR, zero);
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  glDisable(GL_COLOR_SUM);
  glDisableClientState(GL_FOG_COORD_ARRAY);
  glDisable(GL_DEPTH_TEST);
}

void perspective(const Frame& f) {
  glViewport(0, 0, f.width, f.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double aspect = static_cast<double>(f.width) / f.height;
  glFrustum(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, 1.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
}

// A smooth-shaded floor receding from z = -1.5 to z = -30 with pillars of quads standing on it.
void fog_world() {
  const int n = 24;
  for (int i = 0; i < n; ++i) {
    const float z0 = -1.5f - 28.5f * i / n, z1 = -1.5f - 28.5f * (i + 1) / n;
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= 8; ++j) {
      const float x = -6.0f + 1.5f * j;
      palette_color(i + j);
      glVertex3f(x, -1.0f, z0);
      palette_color(i + j + 3);
      glVertex3f(x, -1.0f, z1);
    }
    glEnd();
  }
  for (int k = 0; k < 10; ++k) {
    const float z = -3.0f - 2.6f * k, x = (k % 2 ? 1.4f : -1.4f);
    glBegin(GL_QUADS);
    palette_color(k + 2);
    glVertex3f(x - 0.4f, -1.0f, z);
    glVertex3f(x + 0.4f, -1.0f, z);
    palette_color(k + 7);
    glVertex3f(x + 0.4f, 1.2f, z);
    glVertex3f(x - 0.4f, 1.2f, z);
    glEnd();
  }
}

void fog_color(float r, float g, float b) {
  const GLfloat c[4] = {r, g, b, 1.0f};
  glFogfv(GL_FOG_COLOR, c);
}

} // namespace

PINEDA_SCENE(fog_linear, "Linear fog from the eye distance over a perspective floor and pillars") {
  fog_defaults();
  clear_frame(0.5625f, 0.625f, 0.75f);
  perspective(frame);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 2.0f);
  glFogf(GL_FOG_END, 24.0f);
  fog_color(0.5625f, 0.625f, 0.75f);
  fog_world();
  fog_defaults();
}

PINEDA_SCENE(fog_exp, "Exponential fog (EXP, density 0.12) from the eye distance") {
  fog_defaults();
  clear_frame(0.75f, 0.75f, 0.75f);
  perspective(frame);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_EXP);
  glFogf(GL_FOG_DENSITY, 0.12f);
  fog_color(0.75f, 0.75f, 0.75f);
  fog_world();
  fog_defaults();
}

PINEDA_SCENE(fog_exp2, "Squared exponential fog (EXP2, density 0.09) from the eye distance") {
  fog_defaults();
  clear_frame(0.25f, 0.125f, 0.375f);
  perspective(frame);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_EXP2);
  glFogf(GL_FOG_DENSITY, 0.09f);
  fog_color(0.25f, 0.125f, 0.375f);
  fog_world();
  fog_defaults();
}

PINEDA_SCENE(fog_coord, "Fog from per-vertex fog coordinates (FogCoord and FOG_COORD_ARRAY)") {
  const auto fog_coordf = proc<PFNGLFOGCOORDFPROC>("glFogCoordf");
  const auto fog_coord_pointer = proc<PFNGLFOGCOORDPOINTERPROC>("glFogCoordPointer");
  fog_defaults();
  clear_frame(0.0f, 0.0f, 0.0f);
  glEnable(GL_FOG);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  fog_color(1.0f, 0.875f, 0.5f);
  // Immediate mode, LINEAR: a fan of quads whose corners carry coordinates 0..10.
  panel(frame, 0, 2, 2);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 1.0f);
  glFogf(GL_FOG_END, 9.0f);
  for (int i = 0; i < 4; ++i) {
    const float y0 = 4.0f + 30.0f * i, y1 = y0 + 26.0f;
    glBegin(GL_QUADS);
    palette_color(i);
    fog_coordf(0.0f);
    glVertex2f(4, y0);
    fog_coordf(2.5f * i + 2.0f);
    glVertex2f(120, y0);
    palette_color(i + 5);
    fog_coordf(10.0f);
    glVertex2f(120, y1);
    fog_coordf(2.5f * i);
    glVertex2f(4, y1);
    glEnd();
  }
  // Arrays, EXP and EXP2: a triangle strip with coordinates from a float array.
  GLfloat verts[20][2], coords[20];
  for (int i = 0; i < 10; ++i) {
    verts[2 * i][0] = verts[2 * i + 1][0] = 6.0f + 12.0f * i;
    verts[2 * i][1] = 8.0f;
    verts[2 * i + 1][1] = 110.0f;
    coords[2 * i] = 0.4f * i;
    coords[2 * i + 1] = 4.0f - 0.3f * i;
  }
  glVertexPointer(2, GL_FLOAT, 0, verts);
  fog_coord_pointer(GL_FLOAT, 0, coords);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_FOG_COORD_ARRAY);
  for (int p = 1; p < 4; ++p) {
    panel(frame, p, 2, 2);
    glFogi(GL_FOG_MODE, p == 1 ? GL_EXP : (p == 2 ? GL_EXP2 : GL_LINEAR));
    glFogf(GL_FOG_DENSITY, 0.6f);
    glFogf(GL_FOG_START, 4.0f);
    glFogf(GL_FOG_END, 0.5f); // reversed range: fog grows towards small coordinates
    palette_color(p + 8);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 20);
  }
  glDisableClientState(GL_VERTEX_ARRAY);
  fog_defaults();
}

PINEDA_SCENE(fog_color_sum, "Fog after the colour sum, on triangles, lines and points") {
  const auto secondary = proc<PFNGLSECONDARYCOLOR3FPROC>("glSecondaryColor3f");
  fog_defaults();
  clear_frame(0.125f, 0.125f, 0.125f);
  perspective(frame);
  glEnable(GL_FOG);
  glEnable(GL_COLOR_SUM);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 1.0f);
  glFogf(GL_FOG_END, 16.0f);
  fog_color(0.125f, 0.125f, 0.125f);
  for (int i = 0; i < 6; ++i) {
    const float z = -2.0f - 2.2f * i;
    glBegin(GL_TRIANGLES);
    palette_color(i);
    secondary(0.25f, 0.0f, 0.125f * i);
    glVertex3f(-1.8f, -0.9f, z);
    secondary(0.0f, 0.375f, 0.0f);
    glVertex3f(-0.4f, -0.9f, z - 1.0f);
    palette_color(i + 4);
    glVertex3f(-1.1f, 0.8f, z);
    glEnd();
  }
  secondary(0.0f, 0.0f, 0.0f);
  glBegin(GL_LINES);
  for (int i = 0; i < 24; ++i) {
    palette_color(i);
    glVertex3f(0.2f, -1.0f + 0.08f * i, -1.5f);
    palette_color(i + 3);
    glVertex3f(2.5f, -1.0f + 0.08f * i, -20.0f);
  }
  glEnd();
  glBegin(GL_POINTS);
  for (int i = 0; i < 200; ++i) {
    palette_color(i);
    const float t = static_cast<float>(i) / 200.0f;
    glVertex3f(-2.0f + 4.0f * t, 1.1f + 0.3f * std::sin(20.0f * t), -1.5f - 25.0f * t);
  }
  glEnd();
  fog_defaults();
}
