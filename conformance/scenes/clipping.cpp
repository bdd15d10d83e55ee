// Clipping against the view volume and user clip planes (GL 2.1 §2.12), with the colours of new
// vertices interpolated in clip space (§2.14.8).
#include "scene_util.h"

#include <cmath>

using namespace scenes;

namespace {

// A big triangle with saturated corner colours.
void color_triangle(const float v[3][3], int colour) {
  for (int k = 0; k < 3; ++k) {
    palette_color(colour + 5 * k);
    glVertex3fv(v[k]);
  }
}

// Frame of a viewport region in window pixels, drawn with the projection reset to the whole
// window so that the outline itself is not clipped by the viewport under test.
void outline(const Frame& frame, int x, int y, int w, int h) {
  window_projection(frame);
  glColor3f(0.25f, 0.25f, 0.375f);
  glRecti(x - 2, y - 2, x + w + 2, y);
  glRecti(x - 2, y + h, x + w + 2, y + h + 2);
  glRecti(x - 2, y, x, y + h);
  glRecti(x + w, y, x + w + 2, y + h);
}

// A grid of small triangles covering [0, w] x [0, h] with smooth colours; used under user clip
// planes so that the cut runs through many primitives.
void triangle_grid(float w, float h, int n) {
  glBegin(GL_TRIANGLES);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const float x0 = w * i / n, x1 = w * (i + 1) / n, y0 = h * j / n, y1 = h * (j + 1) / n;
      glColor3f(static_cast<float>(i) / n, static_cast<float>(j) / n, 0.75f);
      glVertex2f(x0, y0);
      glColor3f(static_cast<float>(i + 1) / n, static_cast<float>(j) / n, 0.25f);
      glVertex2f(x1, y0);
      glColor3f(static_cast<float>(i) / n, static_cast<float>(j + 1) / n, 0.5f);
      glVertex2f(x0, y1);
      glVertex2f(x0, y1);
      glColor3f(static_cast<float>(i + 1) / n, static_cast<float>(j) / n, 0.25f);
      glVertex2f(x1, y0);
      glColor3f(1.0f, static_cast<float>(j + 1) / n, static_cast<float>(i) / n);
      glVertex2f(x1, y1);
    }
  }
  glEnd();
}

} // namespace

PINEDA_SCENE(clip_viewport_edges, "Triangles crossing the left/right/bottom/top planes of an inset viewport") {
  clear_frame(0.0f, 0.0f, 0.0f);
  const int vx = 36, vy = 44, vw = 184, vh = 168;
  outline(frame, vx, vy, vw, vh);
  // The viewport alone bounds the drawing: nothing may appear outside it (GL 2.1 §2.11.1).
  glViewport(vx, vy, vw, vh);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, vw, 0.0, vh, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  Rng rng(101);
  glBegin(GL_TRIANGLES);
  for (int t = 0; t < 16; ++t) {
    // Centres near the edges and corners, vertices reaching well outside.
    const float cx = t % 4 == 0 ? -10.0f : (t % 4 == 1 ? vw + 10.0f : rng.range(0.0f, vw));
    const float cy = t % 4 == 2 ? -10.0f : (t % 4 == 3 ? vh + 10.0f : rng.range(0.0f, vh));
    float v[3][3];
    for (auto& p : v) {
      p[0] = cx + rng.range(-70.0f, 70.0f);
      p[1] = cy + rng.range(-70.0f, 70.0f);
      p[2] = 0.0f;
    }
    color_triangle(v, t);
  }
  glEnd();
}

PINEDA_SCENE(clip_near_far_ortho, "Triangles tilted through the near and far planes of glOrtho") {
  clear_frame(0.0f, 0.0f, 0.0f);
  // glOrtho(..., -1, 1) keeps eye z in [-1, 1]; the triangles span z in [-3, 3], so both planes
  // cut them along lines that depend on the interpolated z only (GL 2.1 §2.12).
  Rng rng(111);
  glBegin(GL_TRIANGLES);
  for (int t = 0; t < 14; ++t) {
    float v[3][3];
    const float cx = rng.range(30.0f, 226.0f), cy = rng.range(30.0f, 226.0f);
    for (auto& p : v) {
      p[0] = cx + rng.range(-80.0f, 80.0f);
      p[1] = cy + rng.range(-80.0f, 80.0f);
      p[2] = rng.range(-3.0f, 3.0f);
    }
    color_triangle(v, t * 3);
  }
  glEnd();
}

PINEDA_SCENE(clip_near_perspective, "Perspective triangles reaching between the eye and the near plane") {
  clear_frame(0.0f, 0.0f, 0.0f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 50.0);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_DEPTH_TEST);
  Rng rng(121);
  glBegin(GL_TRIANGLES);
  for (int t = 0; t < 12; ++t) {
    // One vertex at z = -0.3 (in front of the eye but nearer than the near plane at -1), two
    // farther away: the near plane cuts off a corner whose colour must be interpolated.
    float v[3][3] = {{rng.range(-0.4f, 0.4f), rng.range(-0.4f, 0.4f), -0.3f},
                     {rng.range(-6.0f, 6.0f), rng.range(-6.0f, 6.0f), rng.range(-12.0f, -6.0f)},
                     {rng.range(-6.0f, 6.0f), rng.range(-6.0f, 6.0f), rng.range(-12.0f, -6.0f)}};
    color_triangle(v, t);
  }
  glEnd();
}

PINEDA_SCENE(clip_far_perspective, "Perspective triangles running through the far plane") {
  clear_frame(0.0f, 0.0f, 0.0f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  Rng rng(131);
  glBegin(GL_TRIANGLES);
  for (int t = 0; t < 10; ++t) {
    const float z_near = rng.range(-6.0f, -2.0f), z_far = rng.range(-30.0f, -14.0f);
    float v[3][3] = {{rng.range(-2.0f, 2.0f), rng.range(-2.0f, 2.0f), z_near},
                     {rng.range(-12.0f, 12.0f), rng.range(-12.0f, 12.0f), z_far},
                     {rng.range(-3.0f, 3.0f), rng.range(-3.0f, 3.0f), rng.range(z_far, z_near)}};
    color_triangle(v, 2 * t + 1);
  }
  glEnd();
}

PINEDA_SCENE(clip_inside_box, "Camera inside a box: faces cross all six view-volume planes") {
  clear_frame(0.0f, 0.0f, 0.0f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.6, 0.6, -0.45, 0.5, 0.5, 2.6);
  glMatrixMode(GL_MODELVIEW);
  glRotatef(27.0f, 0.3f, 1.0f, 0.1f);
  glRotatef(-13.0f, 1.0f, 0.0f, 0.0f);
  glEnable(GL_DEPTH_TEST);
  // A 4-unit box around the eye: every face passes behind the eye (near plane) and its corners,
  // about 3.5 units away, lie beyond the far plane at 2.6.
  const float s = 2.0f;
  const float corners[8][3] = {{-s, -s, -s}, {s, -s, -s}, {s, s, -s}, {-s, s, -s},
                               {-s, -s, s},  {s, -s, s},  {s, s, s},  {-s, s, s}};
  const int faces[6][4] = {{0, 1, 2, 3}, {5, 4, 7, 6}, {4, 0, 3, 7},
                           {1, 5, 6, 2}, {4, 5, 1, 0}, {3, 2, 6, 7}};
  glBegin(GL_TRIANGLES);
  for (int f = 0; f < 6; ++f) {
    // Two triangles per face, each with its own corner colours.
    const int tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
    for (const auto& t : tri) {
      for (int k = 0; k < 3; ++k) {
        palette_color(f * 2 + t[k]);
        glVertex3fv(corners[faces[f][t[k]]]);
      }
    }
  }
  glEnd();
}

PINEDA_SCENE(clip_user_planes, "glClipPlane 0-5 in six panels, planes set under rotated modelviews") {
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLdouble planes[6][4] = {{1.0, 0.0, 0.0, -20.0},  {0.0, 1.0, 0.0, -30.0},
                                 {-1.0, -1.0, 0.0, 140.0}, {1.0, -2.0, 0.0, 50.0},
                                 {-0.3, 1.0, 0.0, 10.0},  {0.7, 0.7, 0.0, -40.0}};
  for (int p = 0; p < 6; ++p) {
    const Panel pn = panel(frame, p, 3, 2);
    // Plane equations are transformed by the inverse of the modelview current at glClipPlane
    // time (GL 2.1 §2.12): set them under a rotation about the panel centre, then draw under
    // the identity.
    glPushMatrix();
    glTranslatef(pn.w * 0.5f, pn.h * 0.5f, 0.0f);
    glRotatef(15.0f * static_cast<float>(p), 0.0f, 0.0f, 1.0f);
    glTranslatef(-pn.w * 0.5f, -pn.h * 0.5f, 0.0f);
    for (int k = 0; k <= p; ++k) glClipPlane(GL_CLIP_PLANE0 + k, planes[(k + p) % 6]);
    glPopMatrix();
    for (int k = 0; k <= p; ++k) glEnable(GL_CLIP_PLANE0 + k);
    triangle_grid(static_cast<float>(pn.w), static_cast<float>(pn.h), 9);
    for (int k = 0; k <= p; ++k) glDisable(GL_CLIP_PLANE0 + k);
  }
}

PINEDA_SCENE(clip_user_perspective, "A user clip plane on a perspective scene with depth test") {
  clear_frame(0.0f, 0.0f, 0.0f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -1.0, 1.0, 1.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(0.0f, 0.0f, -6.0f);
  glRotatef(35.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
  glEnable(GL_DEPTH_TEST);
  // A slanted plane through the object: it is specified in object space and must cut the
  // perspective geometry along a straight line in object space.
  const GLdouble plane[4] = {0.4, -1.0, 0.3, 0.6};
  glClipPlane(GL_CLIP_PLANE3, plane);
  glEnable(GL_CLIP_PLANE3);
  Rng rng(141);
  glBegin(GL_QUADS);
  for (int i = -4; i < 4; ++i) {
    for (int j = -4; j < 4; ++j) {
      const float h = rng.range(-0.3f, 0.3f);
      palette_color(i * 8 + j);
      glVertex3f(i * 0.8f, h, j * 0.8f);
      glVertex3f(i * 0.8f, h, (j + 1) * 0.8f);
      glVertex3f((i + 1) * 0.8f, h, (j + 1) * 0.8f);
      glVertex3f((i + 1) * 0.8f, h, j * 0.8f);
    }
  }
  glEnd();
  glBegin(GL_TRIANGLES);
  for (int t = 0; t < 6; ++t) {
    float v[3][3];
    for (auto& p : v) {
      p[0] = rng.range(-3.0f, 3.0f);
      p[1] = rng.range(-1.0f, 2.5f);
      p[2] = rng.range(-3.0f, 3.0f);
    }
    color_triangle(v, t * 2);
  }
  glEnd();
}

PINEDA_SCENE(clip_lines_points, "Lines and points against an inset viewport and a user plane",
             .allowance = kLineAllowance, .why = kLineWhy) {
  clear_frame(0.0f, 0.0f, 0.0f);
  const int vx = 28, vy = 28, vw = 200, vh = 200;
  outline(frame, vx, vy, vw, vh);
  glViewport(vx, vy, vw, vh);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, vw, 0.0, vh, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  const GLdouble plane[4] = {-1.0, 0.35, 0.0, 150.0};
  glClipPlane(GL_CLIP_PLANE0, plane);
  glEnable(GL_CLIP_PLANE0);
  Rng rng(151);
  glBegin(GL_LINES);
  for (int i = 0; i < 40; ++i) {
    palette_color(i);
    glVertex2f(rng.range(-60.0f, vw + 60.0f), rng.range(-60.0f, vh + 60.0f));
    palette_color(i + 7);
    glVertex2f(rng.range(-60.0f, vw + 60.0f), rng.range(-60.0f, vh + 60.0f));
  }
  glEnd();
  // Points either well inside or well outside (a point is kept or dropped whole).
  glBegin(GL_POINTS);
  for (int i = 0; i < 600; ++i) {
    palette_color(i);
    glVertex2f(snap(rng.range(-30.0f, vw + 30.0f), 4.0f) + 0.5f,
               snap(rng.range(-30.0f, vh + 30.0f), 4.0f) + 0.5f);
  }
  glEnd();
}
