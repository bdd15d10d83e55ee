// Stress scenes: watertightness, slivers, sub-pixel triangles, huge coordinates, geometry behind
// the eye, an extreme near/far ratio, and heavy scenes for the time ratio.
#include "scene_util.h"

#include <cmath>
#include <vector>

using namespace scenes;

namespace {

void perspective(double half_w, double half_h, double near_plane, double far_plane) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-half_w, half_w, -half_h, half_h, near_plane, far_plane);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

} // namespace

PINEDA_SCENE(stress_watertight, "Shared-edge meshes added at 0.25: any pixel hit twice or missed shows") {
  clear_frame(0.0f, 0.0f, 0.0f, 0.0f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glColor4f(0.25f, 0.25f, 0.25f, 0.25f);
  // A jittered 36 x 36 grid (2592 triangles) with cells split along alternating diagonals. Shared
  // vertices are the very same floats, so a correct fill rule covers every pixel exactly once.
  // The jitter stays below a quarter cell so that no triangle folds over its neighbours.
  Rng rng(1001);
  const int n = 36;
  std::vector<float> xs((n + 1) * (n + 1)), ys((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const bool inner_x = i > 0 && i < n, inner_y = j > 0 && j < n;
      xs[j * (n + 1) + i] = 4.0f + 160.0f * i / n + (inner_x ? rng.range(-1.0f, 1.0f) : 0.0f);
      ys[j * (n + 1) + i] = 4.0f + 248.0f * j / n + (inner_y ? rng.range(-1.6f, 1.6f) : 0.0f);
    }
  }
  glBegin(GL_TRIANGLES);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      const int tris[2][3] = {{a, b, (i + j) % 2 ? c : d}, {(i + j) % 2 ? b : a, d, c}};
      for (const auto& t : tris)
        for (int k : t) glVertex2f(xs[k], ys[k]);
    }
  }
  glEnd();
  // A 300-slice fan around a pixel centre and a 200-slice fan around a pixel corner.
  for (int f = 0; f < 2; ++f) {
    const float cx = 212.5f - 0.5f * f, cy = f ? 70.0f : 190.5f, r = 38.0f;
    const int slices = f ? 200 : 300;
    glBegin(GL_TRIANGLE_FAN);
    glVertex2f(cx, cy);
    for (int i = 0; i <= slices; ++i) {
      const float a = 2.0f * kPi * static_cast<float>(i % slices) / static_cast<float>(slices);
      glVertex2f(cx + r * std::cos(a), cy + r * std::sin(a));
    }
    glEnd();
  }
  // A zig-zag triangle strip of 120 thin triangles between the fans.
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i <= 120; ++i) {
    const float x = 172.3f + 76.0f * static_cast<float>(i / 2) / 60.0f;
    glVertex2f(x + (i % 2 ? 0.7f : 0.0f), i % 2 ? 147.2f : 113.9f);
  }
  glEnd();
  glDisable(GL_BLEND);
}

PINEDA_SCENE(stress_slivers, "Long slivers 0.001-2 px wide at every angle, and sliver pairs added at 0.25") {
  clear_frame(0.0f, 0.0f, 0.0f, 0.0f);
  Rng rng(1101);
  glBegin(GL_TRIANGLES);
  for (int s = 0; s < 160; ++s) {
    const float a = rng.range(0.0f, kPi), len = rng.range(60.0f, 240.0f);
    const float width = 0.001f * std::pow(2000.0f, rng.unit()); // log-uniform 0.001 .. 2
    const float cx = rng.range(40.0f, 216.0f), cy = rng.range(40.0f, 216.0f);
    const float dx = std::cos(a), dy = std::sin(a);
    palette_color(s);
    glVertex2f(cx - 0.5f * len * dx, cy - 0.5f * len * dy);
    glVertex2f(cx + 0.5f * len * dx, cy + 0.5f * len * dy);
    glVertex2f(cx + 0.1f * len * dx - width * dy, cy + 0.1f * len * dy + width * dx);
  }
  glEnd();
  // Thin quads split along their long diagonal, added at 0.25: the shared diagonal must not
  // double any pixel.
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glColor4f(0.25f, 0.25f, 0.25f, 0.25f);
  glBegin(GL_TRIANGLES);
  for (int s = 0; s < 40; ++s) {
    const float x0 = rng.range(10.0f, 60.0f), y0 = rng.range(10.0f, 246.0f);
    const float x1 = rng.range(196.0f, 246.0f), y1 = rng.range(10.0f, 246.0f);
    const float t = rng.range(0.3f, 3.0f);
    glVertex2f(x0, y0);
    glVertex2f(x1, y1);
    glVertex2f(x1, y1 + t);
    glVertex2f(x0, y0);
    glVertex2f(x1, y1 + t);
    glVertex2f(x0, y0 + t);
  }
  glEnd();
  glDisable(GL_BLEND);
}

PINEDA_SCENE(stress_tiny_triangles, "30000 sub-pixel triangles: most cover no pixel centre, some one") {
  clear_frame(0.0f, 0.0f, 0.0f);
  Rng rng(1201);
  glBegin(GL_TRIANGLES);
  for (int t = 0; t < 30000; ++t) {
    const float cx = rng.range(2.0f, 254.0f), cy = rng.range(2.0f, 254.0f);
    palette_color(t);
    for (int k = 0; k < 3; ++k) glVertex2f(cx + rng.range(-0.7f, 0.7f), cy + rng.range(-0.7f, 0.7f));
  }
  glEnd();
}

PINEDA_SCENE(stress_huge_coords, "Perspective geometry with vertices at +-1e7: floor to the horizon, rays") {
  clear_frame(0.0f, 0.0f, 0.125f);
  perspective(0.8, 0.8, 1.0, 1e8);
  const float big = 1e7f;
  // A floor reaching 1e7 in every direction, also behind the eye, as a fan of four triangles.
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(0.375f, 0.25f, 0.125f);
  glVertex3f(0.3f, -1.5f, -6.0f);
  const float floor[5][2] = {{-big, -big}, {big, -big}, {big, big}, {-big, big}, {-big, -big}};
  for (int i = 0; i < 5; ++i) {
    palette_color(i);
    glVertex3f(floor[i][0], -1.5f, floor[i][1]);
  }
  glEnd();
  // Rays: thin triangles from near the eye to 1e7 away, converging on vanishing points.
  glBegin(GL_TRIANGLES);
  for (int r = 0; r < 12; ++r) {
    const float x = -3.0f + 0.55f * r, y = 0.4f + 0.1f * (r % 3);
    palette_color(r + 4);
    glVertex3f(x, y, -2.0f);
    glVertex3f(x + 0.3f, y + 0.05f, -2.0f);
    glColor3f(0.0f, 0.0f, 0.0f);
    glVertex3f(big * (r % 2 ? 0.1f : -0.1f), big * 0.05f, -big);
  }
  // A triangle with all three vertices 1e7 away in different directions, covering the centre.
  glColor3f(0.25f, 0.75f, 0.25f);
  glVertex3f(-big, big, -big);
  palette_color(3);
  glVertex3f(big, 0.2f * big, -big);
  glColor3f(0.75f, 0.25f, 0.75f);
  glVertex3f(0.1f * big, 2.0f * big, -big);
  glEnd();
}

PINEDA_SCENE(stress_behind_eye, "Triangles crossing w = 0 (behind the eye), and glVertex4 with w < 0") {
  clear_frame(0.0f, 0.0f, 0.0f);
  perspective(0.5, 0.5, 0.1, 100.0);
  glEnable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLES);
  // Spanning from 10 units ahead to 10 units behind the eye; without clipping against the near
  // plane the part behind the eye would project inverted.
  for (int t = 0; t < 8; ++t) {
    const float a = 2.0f * kPi * t / 8.0f;
    palette_color(t);
    glVertex3f(4.0f * std::cos(a), 4.0f * std::sin(a), -10.0f);
    palette_color(t + 5);
    glVertex3f(4.0f * std::cos(a + 0.5f), 4.0f * std::sin(a + 0.5f), -10.0f);
    palette_color(t + 10);
    glVertex3f(1.0f * std::cos(a + 2.0f), 1.0f * std::sin(a + 2.0f), 10.0f);
  }
  // One vertex exactly in the eye plane (clip w = 0).
  glColor3f(1.0f, 1.0f, 1.0f);
  glVertex3f(-2.0f, -2.0f, -6.0f);
  glVertex3f(-0.5f, -2.0f, -6.0f);
  glColor3f(1.0f, 0.125f, 0.125f);
  glVertex3f(-0.3f, -0.3f, 0.0f);
  // Entirely behind the eye: nothing.
  glColor3f(1.0f, 1.0f, 0.125f);
  glVertex3f(-1.0f, -1.0f, 2.0f);
  glVertex3f(1.0f, -1.0f, 2.0f);
  glVertex3f(0.0f, 1.0f, 2.0f);
  glEnd();
  // Clip coordinates given directly (identity matrices): a triangle with every w negative lies
  // outside the clip volume -w <= x, y, z <= w altogether (GL 2.1 §2.12); one with mixed signs is
  // clipped where w crosses 0.
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLES);
  glColor3f(0.25f, 1.0f, 1.0f);
  glVertex4f(0.5f, 0.5f, 0.0f, -1.0f);
  glVertex4f(-0.5f, 0.5f, 0.0f, -1.0f);
  glVertex4f(0.0f, -0.5f, 0.0f, -1.0f);
  glColor3f(0.625f, 0.25f, 1.0f);
  glVertex4f(0.6f, -0.95f, 0.0f, 1.0f);
  glVertex4f(0.95f, -0.95f, 0.0f, 1.0f);
  glColor3f(1.0f, 0.625f, 0.125f);
  glVertex4f(0.3f, 0.4f, 0.0f, -0.5f);
  glEnd();
}

PINEDA_SCENE(stress_near_far, "glFrustum near 1e-3, far 1e6 (ratio 1e9): close depth layers at 0.01..300") {
  clear_frame(0.0f, 0.0f, 0.0f);
  perspective(1e-3, 1e-3, 1e-3, 1e6);
  glEnable(GL_DEPTH_TEST);
  // At distance d a pair of quads 12% of d apart; with window depth ~ 1 - near/d the pair is
  // 1e-4/d apart in depth: still 10+ steps of a 24-bit buffer at d = 300. Each pair is scaled
  // with d so it covers the same screen area, and drawn in the wrong order half the time.
  const double distances[6] = {0.01, 0.1, 1.0, 10.0, 100.0, 300.0};
  for (int i = 0; i < 6; ++i) {
    const double d = distances[i];
    const double sx = -0.66 + 0.66 * (i % 3), sy = i < 3 ? 0.45 : -0.45; // screen position
    for (int order = 0; order < 2; ++order) {
      const bool far_first = i % 2 == 0;
      const bool is_far = (order == 0) == far_first;
      const double z = is_far ? d * 1.12 : d;
      const double half = 0.28 * z, shift = (is_far ? 0.07 : -0.07) * z;
      if (is_far) glColor3f(0.375f, 0.375f, 0.375f);
      else palette_color(i);
      glBegin(GL_QUADS);
      glVertex3d(sx * z - half + shift, sy * z - half + shift, -z);
      glVertex3d(sx * z + half + shift, sy * z - half + shift, -z);
      glVertex3d(sx * z + half + shift, sy * z + half + shift, -z);
      glVertex3d(sx * z - half + shift, sy * z + half + shift, -z);
      glEnd();
    }
  }
}

PINEDA_SCENE(stress_huge_triangles, "Triangles with window coordinates up to 1e6 px around a 256 px window") {
  clear_frame(0.0f, 0.0f, 0.0f);
  // Pixel projection: vertices hundreds of thousands of pixels outside the window, edges crossing
  // it at chosen places (GL 2.1 §2.12 clipping; implementations may use a guard band).
  glBegin(GL_TRIANGLES);
  // Enclosing the whole window.
  glColor3f(0.125f, 0.125f, 0.375f);
  glVertex2f(-1e6f, -1e6f);
  glVertex2f(1e6f, -1e6f);
  glVertex2f(100.3f, 1e6f);
  // Long edges through the window: the left edge from (-1e5, -1e5 + 40) to (1e5, 1e5 - 20)
  // crosses it near the diagonal.
  glColor3f(1.0f, 0.25f, 0.25f);
  glVertex2f(-1e5f, -1e5f + 40.0f);
  glColor3f(1.0f, 1.0f, 0.125f);
  glVertex2f(1e5f, 1e5f - 20.0f);
  glColor3f(1.0f, 0.625f, 0.125f);
  glVertex2f(1e5f, -1e5f);
  // A wedge with its apex inside and both far vertices at 5e5.
  glColor3f(0.25f, 1.0f, 0.5625f);
  glVertex2f(60.3f, 190.7f);
  glColor3f(0.125f, 0.5625f, 1.0f);
  glVertex2f(-5e5f, 5e5f);
  glVertex2f(-3e5f, 5e5f);
  // Entirely outside: nothing.
  glVertex2f(-3e5f, -1000.0f);
  glVertex2f(-1e5f, -1000.0f);
  glVertex2f(-2e5f, -5000.0f);
  glEnd();
}

PINEDA_SCENE(stress_many_triangles, "A 65536-triangle torus from glDrawElements, depth-tested and culled") {
  clear_frame(0.0f, 0.0f, 0.0f);
  perspective(0.6, 0.6, 1.0, 20.0);
  glTranslatef(0.0f, 0.0f, -4.2f);
  glRotatef(55.0f, 1.0f, 0.3f, 0.0f);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  const int nu = 256, nv = 128;
  std::vector<GLfloat> pos;
  std::vector<GLubyte> col;
  for (int j = 0; j <= nv; ++j) {
    for (int i = 0; i <= nu; ++i) {
      const float u = 2.0f * kPi * i / nu, v = 2.0f * kPi * j / nv;
      const float r = 1.4f + 0.55f * std::cos(v);
      pos.insert(pos.end(), {r * std::cos(u), r * std::sin(u), 0.55f * std::sin(v)});
      col.insert(col.end(), {GLubyte(128 + 127 * std::cos(3.0f * u)), GLubyte(128 + 127 * std::sin(v)),
                             GLubyte(128 + 127 * std::cos(u + v))});
    }
  }
  std::vector<GLuint> idx;
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const GLuint a = j * (nu + 1) + i, b = a + 1, c = a + nu + 1, d = c + 1;
      idx.insert(idx.end(), {a, b, d, a, d, c});
    }
  }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, pos.data());
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, col.data());
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(idx.size()), GL_UNSIGNED_INT, idx.data());
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
}

PINEDA_SCENE(stress_fillrate, "64 full-window layers: 32 blended back to front, 32 depth-rejected") {
  clear_frame(0.0f, 0.0f, 0.0f);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  // Back to front: every layer passes the depth test and blends. Alpha 1/2 keeps 8-bit rounding
  // differences from accumulating over the layers (each layer halves the earlier error).
  for (int i = 0; i < 32; ++i) {
    const float z = 0.9f - 0.05f * i; // object z; window depth (1 - z) / 2 decreases
    const float* c = palette(i);
    glBegin(GL_TRIANGLES);
    glColor4f(c[0], c[1], c[2], 0.5f);
    glVertex3f(-0.2f, -0.3f, -z);
    glVertex3f(600.0f, -0.3f, -z);
    glColor4f(c[2], c[0], c[1], 0.5f);
    glVertex3f(-0.2f, 600.0f, -z);
    glEnd();
  }
  // Behind everything drawn so far: all rejected by the depth test.
  glDisable(GL_BLEND);
  for (int i = 0; i < 32; ++i) {
    palette_color(i);
    glRectf(-0.5f, -0.5f, 300.0f, 300.0f); // z = 0 is behind the last blended layer
  }
}
