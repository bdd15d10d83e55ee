// A glxgears-style toothed wheel in GL 1.0 immediate-mode calls, shared by the display-list
// conformance scene (conformance/scenes/dlist.cpp) and the display-list benchmark
// (bench/dlist_bench.cpp); <GL/gl.h> is Mesa's for the former and Pineda's for the latter.
#pragma once

#include <GL/gl.h>

#include <cmath>

// A toothed wheel in the z = ±width/2 slab: flat front and back faces with teeth, the teeth's
// outer faces with outward normals, and the smooth-shaded bore.
inline void gear_geometry(float bore, float radius, float width, int teeth, float depth) {
  const float r0 = bore, r1 = radius - depth / 2, r2 = radius + depth / 2;
  const float step = 2 * 3.14159265358979323846f / static_cast<float>(teeth), quarter = step / 4;
  const float z = width / 2;
  glShadeModel(GL_FLAT);
  for (int side = 0; side < 2; ++side) {
    const float s = side == 0 ? 1.0f : -1.0f;
    glNormal3f(0, 0, s);
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= teeth; ++i) {
      const float a = static_cast<float>(i) * step;
      glVertex3f(r0 * std::cos(a), r0 * std::sin(a), s * z);
      glVertex3f(r1 * std::cos(a), r1 * std::sin(a), s * z);
      if (i < teeth) {
        glVertex3f(r0 * std::cos(a), r0 * std::sin(a), s * z);
        glVertex3f(r1 * std::cos(a + 3 * quarter), r1 * std::sin(a + 3 * quarter), s * z);
      }
    }
    glEnd();
    glBegin(GL_QUADS);
    for (int i = 0; i < teeth; ++i) {
      const float a = static_cast<float>(i) * step;
      const float c[4] = {a, a + quarter, a + 2 * quarter, a + 3 * quarter};
      const float r[4] = {r1, r2, r2, r1};
      // Front faces counter-clockwise seen from +z, back faces seen from -z.
      for (int k = 0; k < 4; ++k) {
        const int j = side == 0 ? k : 3 - k;
        glVertex3f(r[j] * std::cos(c[j]), r[j] * std::sin(c[j]), s * z);
      }
    }
    glEnd();
  }
  // The outer faces of the teeth, one normal per face.
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i < teeth; ++i) {
    const float a = static_cast<float>(i) * step;
    const float c[4] = {a, a + quarter, a + 2 * quarter, a + 3 * quarter};
    const float r[4] = {r1, r2, r2, r1};
    for (int k = 0; k < 4; ++k) {
      const float x = r[k] * std::cos(c[k]), y = r[k] * std::sin(c[k]);
      const int n = (k + 1) % 4;
      const float dx = r[n] * std::cos(c[n]) - x, dy = r[n] * std::sin(c[n]) - y;
      glNormal3f(dy, -dx, 0);
      glVertex3f(x, y, z);
      glVertex3f(x, y, -z);
    }
  }
  glVertex3f(r1, 0, z);
  glVertex3f(r1, 0, -z);
  glEnd();
  glShadeModel(GL_SMOOTH);
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= teeth; ++i) {
    const float a = static_cast<float>(i) * step;
    glNormal3f(-std::cos(a), -std::sin(a), 0);
    glVertex3f(r0 * std::cos(a), r0 * std::sin(a), -z);
    glVertex3f(r0 * std::cos(a), r0 * std::sin(a), z);
  }
  glEnd();
}
