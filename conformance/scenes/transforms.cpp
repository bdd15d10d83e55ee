// Coordinate transformations (GL 2.1 §2.11): matrix stacks, every way of loading and
// multiplying matrices, glFrustum/glOrtho variants, viewports that are non-square, partly
// outside the window or larger than it, and perspective-correct colour interpolation (§3.5.1).
#include "scene_util.h"

#include <cmath>

using namespace scenes;

namespace {

// A unit cube with one colour per face (so no face depends on how its quad is split).
void cube() {
  const float c[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                         {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 4, 7, 3},
                           {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 7, 6, 2}};
  glBegin(GL_QUADS);
  for (int f = 0; f < 6; ++f) {
    palette_color(f * 2 + 1);
    for (int k = 0; k < 4; ++k) glVertex3fv(c[faces[f][k]]);
  }
  glEnd();
}

void branch(int depth) {
  palette_color(depth * 3);
  glBegin(GL_QUADS);
  glVertex2f(-0.08f, 0.0f);
  glVertex2f(0.08f, 0.0f);
  glVertex2f(0.06f, 1.0f);
  glVertex2f(-0.06f, 1.0f);
  glEnd();
  if (depth == 0) return;
  glPushMatrix();
  glTranslatef(0.0f, 1.0f, 0.0f);
  glRotatef(28.0f, 0.0f, 0.0f, 1.0f);
  glScalef(0.74f, 0.74f, 1.0f);
  branch(depth - 1);
  glPopMatrix();
  glPushMatrix();
  glTranslated(0.0, 0.95, 0.0);
  glRotated(-33.0, 0.0, 0.0, 1.0);
  glScaled(0.68, 0.7, 1.0);
  branch(depth - 1);
  glPopMatrix();
}

// A sheared, rotated, translated matrix with a projective bottom row, column-major as GL wants.
void reference_matrix(GLdouble m[16], float w, float h) {
  const double a = 0.4, s = std::sin(a), c = std::cos(a);
  const double cols[16] = {0.9 * c, 0.9 * s, 0.0, 0.004, -0.7 * s + 0.2, 0.7 * c, 0.0, 0.002,
                           0.0,     0.0,     1.0, 0.0,   0.5 * w,       0.45 * h, 0.0, 1.0};
  for (int i = 0; i < 16; ++i) m[i] = cols[i];
}

void transpose(const GLdouble in[16], GLdouble out[16]) {
  for (int r = 0; r < 4; ++r)
    for (int col = 0; col < 4; ++col) out[r * 4 + col] = in[col * 4 + r];
}

} // namespace

PINEDA_SCENE(matrix_stack, "Nested glPush/PopMatrix tree on the modelview stack; projection stack switch") {
  clear_frame(0.0f, 0.0f, 0.0f);
  glPushMatrix();
  glTranslatef(80.2f, 6.3f, 0.0f);
  glScalef(42.0f, 42.0f, 1.0f);
  branch(7);
  glPopMatrix();
  // Switch to a perspective projection for a cube, then pop back to the pixel projection.
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -1.0, 1.0, 2.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  glTranslatef(1.9f, 1.7f, -5.0f);
  glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
  glScalef(0.6f, 0.6f, 0.6f);
  glEnable(GL_DEPTH_TEST);
  cube();
  glDisable(GL_DEPTH_TEST);
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  // Back in pixel units: this bar must land at the bottom-right corner.
  glColor3f(1.0f, 1.0f, 1.0f);
  glRectf(190.25f, 8.25f, 248.25f, 20.25f);
}

PINEDA_SCENE(matrix_load_mult, "The same projective matrix by glLoad/Mult[Transpose]Matrix{f,d} and glRotate/Translate/Scale") {
  clear_frame(0.0f, 0.0f, 0.0f);
  // Mesa's gl.h declares the GL 1.3 prototypes itself, so glext.h has no PFN types for them.
  using MatrixF = void(APIENTRY*)(const GLfloat*);
  using MatrixD = void(APIENTRY*)(const GLdouble*);
  const auto load_tf = proc<MatrixF>("glLoadTransposeMatrixf");
  const auto load_td = proc<MatrixD>("glLoadTransposeMatrixd");
  const auto mult_tf = proc<MatrixF>("glMultTransposeMatrixf");
  const auto mult_td = proc<MatrixD>("glMultTransposeMatrixd");
  for (int p = 0; p < 9; ++p) {
    const Panel pn = panel(frame, p, 3, 3);
    const float w = static_cast<float>(pn.w), h = static_cast<float>(pn.h);
    GLdouble md[16], mt[16];
    reference_matrix(md, w, h);
    transpose(md, mt);
    GLfloat mf[16], mtf[16];
    for (int i = 0; i < 16; ++i) {
      mf[i] = static_cast<GLfloat>(md[i]);
      mtf[i] = static_cast<GLfloat>(mt[i]);
    }
    // Every panel ends with modelview = reference matrix (panel 8: without the projective row).
    switch (p) {
    case 0: glLoadMatrixf(mf); break;
    case 1: glLoadMatrixd(md); break;
    case 2: glLoadIdentity(); glMultMatrixf(mf); break;
    case 3: glTranslatef(5.0f, 0.0f, 0.0f); glTranslatef(-5.0f, 0.0f, 0.0f); glMultMatrixd(md); break;
    case 4: load_tf(mtf); break;
    case 5: load_td(mt); break;
    case 6: glScalef(2.0f, 2.0f, 1.0f); glScalef(0.5f, 0.5f, 1.0f); mult_tf(mtf); break;
    case 7: glLoadIdentity(); mult_td(mt); break;
    default:
      glTranslatef(0.5f * w, 0.45f * h, 0.0f);
      glRotatef(0.4f * 180.0f / kPi, 0.0f, 0.0f, 1.0f);
      glScalef(0.9f, 0.7f, 1.0f);
      break;
    }
    glBegin(GL_TRIANGLES);
    for (int t = 0; t < 6; ++t) {
      const float a = 2.0f * kPi * t / 6.0f;
      glColor3f(1.0f, 1.0f, 1.0f);
      glVertex2f(0.0f, 0.0f);
      palette_color(t);
      glVertex2f(0.42f * w * std::cos(a), 0.42f * h * std::sin(a));
      palette_color(t + 1);
      glVertex2f(0.42f * w * std::cos(a + 0.8f), 0.42f * h * std::sin(a + 0.8f));
    }
    glEnd();
  }
}

PINEDA_SCENE(projection_variants, "Off-centre glFrustum, mirrored and anisotropic glOrtho, wide frustum") {
  clear_frame(0.0f, 0.0f, 0.0f);
  glEnable(GL_DEPTH_TEST);
  for (int p = 0; p < 4; ++p) {
    panel(frame, p, 2, 2);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    switch (p) {
    case 0: glFrustum(-0.2, 1.0, -0.7, 0.4, 1.0, 10.0); break;   // off-centre
    case 1: glOrtho(3.0, -3.0, -3.0, 3.0, -10.0, 10.0); break;   // left > right: mirrored
    case 2: glOrtho(-5.0, 5.0, -2.0, 2.0, -10.0, 10.0); break;   // squashed
    default: glFrustum(-3.0, 3.0, -3.0, 3.0, 0.5, 100.0); break; // very wide angle
    }
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    if (p == 0) glTranslatef(0.0f, 0.0f, -4.0f);
    if (p == 3) glTranslatef(0.0f, 0.0f, -2.2f);
    glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(35.0f + 10.0f * p, 0.0f, 1.0f, 0.0f);
    glScalef(1.2f, 1.2f, 1.2f);
    cube();
  }
}

PINEDA_SCENE(viewport_nonsquare, "A 320x200 window with non-square viewports stretching the same NDC picture",
             .width = 320, .height = 200) {
  clear_frame(0.125f, 0.125f, 0.125f);
  const int vps[3][4] = {{8, 70, 200, 122}, {214, 8, 98, 184}, {8, 8, 200, 56}};
  for (const auto& vp : vps) {
    glViewport(vp[0], vp[1], vp[2], vp[3]);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    // In normalized device coordinates: a fan filling the viewport's inscribed ellipse and a
    // rectangle frame along its border.
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex2f(0.0f, 0.0f);
    for (int i = 0; i <= 24; ++i) {
      const float a = 2.0f * kPi * i / 24.0f;
      palette_color(i);
      glVertex2f(0.95f * std::cos(a), 0.95f * std::sin(a));
    }
    glEnd();
    glColor3f(1.0f, 0.625f, 0.125f);
    glRectf(-1.0f, -1.0f, 1.0f, -0.9f);
    glRectf(-1.0f, 0.9f, 1.0f, 1.0f);
    glRectf(-1.0f, -0.9f, -0.92f, 0.9f);
    glRectf(0.92f, -0.9f, 1.0f, 0.9f);
  }
}

PINEDA_SCENE(viewport_oversized, "Viewports larger than the window and partly outside it") {
  clear_frame(0.0f, 0.0f, 0.0f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  // First a viewport that contains the whole window and more, then one hanging over the
  // top-right corner. Fragments outside the window simply do not exist (GL 2.1 §4.1.1).
  const int vps[2][4] = {{-100, -60, 480, 400}, {170, 150, 200, 200}};
  for (int v = 0; v < 2; ++v) {
    glViewport(vps[v][0], vps[v][1], vps[v][2], vps[v][3]);
    const int n = v == 0 ? 10 : 6;
    glBegin(GL_TRIANGLES);
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        if ((i + j) % 2) continue;
        const float x0 = -1.0f + 2.0f * i / n, y0 = -1.0f + 2.0f * j / n, s = 2.0f / n;
        palette_color(i + j * 3 + v * 5);
        glVertex2f(x0 + 0.05f * s, y0 + 0.05f * s);
        glVertex2f(x0 + 0.95f * s, y0 + 0.1f * s);
        palette_color(i * 2 + j + v);
        glVertex2f(x0 + 0.5f * s, y0 + 0.95f * s);
      }
    }
    glEnd();
  }
}

PINEDA_SCENE(viewport_tiles, "64 viewports of 32x32 pixels, each with its own rotation") {
  clear_frame(0.0f, 0.0f, 0.0f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  for (int t = 0; t < 64; ++t) {
    glViewport((t % 8) * 32, (t / 8) * 32, 32, 32);
    glLoadIdentity();
    glRotatef(5.625f * t, 0.0f, 0.0f, 1.0f);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex2f(0.013f, 0.021f);
    for (int i = 0; i < 4; ++i) {
      const float a = kPi * 0.5f * i;
      palette_color(t + i);
      glVertex2f(0.9f * std::cos(a), 0.9f * std::sin(a) * (i % 2 ? 0.5f : 1.0f));
    }
    glEnd();
  }
}

PINEDA_SCENE(perspective_color, "Perspective-correct colour on a big receding quad and a striped floor") {
  clear_frame(0.0f, 0.0f, 0.25f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 200.0);
  glMatrixMode(GL_MODELVIEW);
  // Colours depend only on depth along the floor, so every split of a quad interpolates them the
  // same way; with perspective correction (GL 2.1 §3.5.1, eq. 3.8) the colour boundary sits far
  // from where affine screen-space interpolation would put it.
  glBegin(GL_QUADS);
  glColor3f(1.0f, 0.125f, 0.125f);
  glVertex3f(-3.0f, -1.5f, -1.5f);
  glVertex3f(3.0f, -1.5f, -1.5f);
  glColor3f(0.125f, 0.25f, 1.0f);
  glVertex3f(3.0f, -1.5f, -14.0f);
  glVertex3f(-3.0f, -1.5f, -14.0f);
  glEnd();
  // A wall on the right with colour stripes along its length.
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i <= 16; ++i) {
    const float z = -1.2f - 1.5f * static_cast<float>(i);
    palette_color(i);
    glVertex3f(1.6f, -1.5f, z);
    glVertex3f(1.6f, 3.0f, z);
  }
  glEnd();
  // A ceiling with a single smooth ramp between near and far.
  glBegin(GL_TRIANGLES);
  glColor3f(0.125f, 1.0f, 0.25f);
  glVertex3f(-4.0f, 1.2f, -1.1f);
  glVertex3f(1.5f, 1.2f, -1.1f);
  glColor3f(1.0f, 1.0f, 0.125f);
  glVertex3f(-1.0f, 1.2f, -20.0f);
  glEnd();
}
