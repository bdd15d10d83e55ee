// Evaluators (GL 2.1 §5.1): a lit bicubic Bézier patch with AUTO_NORMAL drawn by EvalMesh2
// FILL, a colour-mapped patch as EvalMesh2 LINE and POINT grids, Bézier curves drawn by
// EvalMesh1 LINE, by EvalCoord1 in a Begin/End loop and by EvalPoint1, and rational
// (MAP1_VERTEX_4) quarter circles. Every scene saves and restores the evaluator state with
// PushAttrib(EVAL_BIT), so repeated draws start from the defaults.
#include "scene_util.h"

#include <cmath>

using namespace scenes;

namespace {

// A bicubic patch over [-1, 1]^2 with a bump and a dip: 4 x 4 control points (x, y, z).
void wavy_patch(float (&p)[4][4][3]) {
  const float h[4][4] = {{0.0f, 0.3f, -0.2f, 0.1f},
                         {0.2f, 1.2f, -0.6f, 0.0f},
                         {-0.3f, 0.4f, 0.9f, 0.3f},
                         {0.1f, -0.2f, 0.2f, 0.0f}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      p[i][j][0] = -1.0f + 2.0f * static_cast<float>(i) / 3.0f;
      p[i][j][1] = -1.0f + 2.0f * static_cast<float>(j) / 3.0f;
      p[i][j][2] = h[i][j];
    }
}

void light4(GLenum light, GLenum pname, float a, float b, float c, float d) {
  const float v[4] = {a, b, c, d};
  glLightfv(light, pname, v);
}

void material4(GLenum pname, float a, float b, float c, float d) {
  const float v[4] = {a, b, c, d};
  glMaterialfv(GL_FRONT_AND_BACK, pname, v);
}

} // namespace

PINEDA_SCENE(eval_patch_lit,
             "A lit bicubic Bezier patch with AUTO_NORMAL drawn by EvalMesh2 FILL") {
  clear_frame(0.05f, 0.05f, 0.1f);
  glPushAttrib(GL_EVAL_BIT | GL_LIGHTING_BIT | GL_ENABLE_BIT | GL_TRANSFORM_BIT);
  glViewport(0, 0, frame.width, frame.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double aspect = static_cast<double>(frame.width) / frame.height;
  glFrustum(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  // The strips wind clockwise for u = x, v = y, so the visible side is the back face; with
  // one-sided lighting it is lit with the analytic normal as computed (+z towards the eye).
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  light4(GL_LIGHT0, GL_POSITION, -0.8f, 0.5f, 0.35f, 0.0f); // in eye coordinates
  light4(GL_LIGHT0, GL_DIFFUSE, 1.0f, 1.0f, 1.0f, 1.0f);
  light4(GL_LIGHT0, GL_SPECULAR, 0.0f, 0.0f, 0.0f, 1.0f);
  material4(GL_AMBIENT, 0.15f, 0.1f, 0.1f, 1.0f);
  material4(GL_DIFFUSE, 0.9f, 0.6f, 0.2f, 1.0f);
  material4(GL_SPECULAR, 0.0f, 0.0f, 0.0f, 1.0f);
  material4(GL_EMISSION, 0.0f, 0.0f, 0.0f, 1.0f);
  glTranslatef(0.0f, 0.0f, -4.0f);
  glRotatef(-55.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(25.0f, 0.0f, 0.0f, 1.0f);
  float p[4][4][3];
  wavy_patch(p);
  glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 12, 4, 0.0f, 1.0f, 3, 4, &p[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  glMapGrid2f(24, 0.0f, 1.0f, 20, 0.0f, 1.0f);
  glEvalMesh2(GL_FILL, 0, 24, 0, 20);
  glPopAttrib();
}

PINEDA_SCENE(eval_patch_lines,
             "A colour-mapped biquadratic patch as EvalMesh2 LINE and POINT grids, a partial FILL",
             .allowance = kLineAllowance, .why = kLineWhy) {
  clear_frame(0.0f, 0.0f, 0.0f);
  glPushAttrib(GL_EVAL_BIT | GL_POINT_BIT);
  window_projection(frame);
  const float w = static_cast<float>(frame.width), h = static_cast<float>(frame.height);
  // A biquadratic sheet in window coordinates over the domain [2, 5] x [-1, 1].
  float v[3][3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      v[i][j][0] = w * (0.06f + 0.2f * static_cast<float>(i) + (j == 1 ? 0.08f : 0.0f));
      v[i][j][1] = h * (0.1f + 0.38f * static_cast<float>(j) + (i == 1 ? 0.12f : 0.0f));
      v[i][j][2] = 0.0f;
    }
  const float c[2][2][4] = {{{1.0f, 0.2f, 0.1f, 1.0f}, {0.1f, 1.0f, 0.3f, 1.0f}},
                            {{0.2f, 0.3f, 1.0f, 1.0f}, {1.0f, 1.0f, 0.2f, 1.0f}}};
  glMap2f(GL_MAP2_VERTEX_3, 2.0f, 5.0f, 9, 3, -1.0f, 1.0f, 3, 3, &v[0][0][0]);
  glMap2f(GL_MAP2_COLOR_4, 2.0f, 5.0f, 8, 2, -1.0f, 1.0f, 4, 2, &c[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_MAP2_COLOR_4);
  glMapGrid2d(12, 2.0, 5.0, 10, -1.0, 1.0);
  glEvalMesh2(GL_LINE, 0, 12, 0, 10);
  // The same sheet moved right: a POINT grid of size 3 and a FILL sub-rectangle of the grid.
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glTranslatef(w * 0.5f, 0.0f, 0.0f);
  glPointSize(3.0f);
  glEvalMesh2(GL_POINT, 0, 12, 0, 10);
  glEvalMesh2(GL_FILL, 3, 8, 2, 6);
  glPopMatrix();
  glPopAttrib();
}

PINEDA_SCENE(eval_curves,
             "Bezier curves by EvalMesh1 LINE, EvalCoord1 in a Begin/End loop and EvalPoint1",
             .allowance = kLineAllowance, .why = kLineWhy) {
  clear_frame(0.0f, 0.0f, 0.0f);
  glPushAttrib(GL_EVAL_BIT | GL_POINT_BIT | GL_LINE_BIT | GL_CURRENT_BIT);
  window_projection(frame);
  const float w = static_cast<float>(frame.width), h = static_cast<float>(frame.height);
  const float colors[3][4] = {
      {1.0f, 0.1f, 0.1f, 1.0f}, {0.1f, 1.0f, 0.2f, 1.0f}, {0.2f, 0.4f, 1.0f, 1.0f}};
  glMap1f(GL_MAP1_COLOR_4, 0.0f, 1.0f, 4, 3, &colors[0][0]);
  glEnable(GL_MAP1_COLOR_4);
  glEnable(GL_MAP1_VERTEX_3);
  for (int k = 0; k < 4; ++k) {
    // A cubic (order 4) zig-zag in band k.
    const float y0 = h * (0.05f + 0.24f * static_cast<float>(k));
    const float pts[4][3] = {{w * 0.05f, y0, 0.0f},
                             {w * 0.35f, y0 + h * 0.3f, 0.0f},
                             {w * 0.65f, y0 - h * 0.12f, 0.0f},
                             {w * 0.95f, y0 + h * 0.16f, 0.0f}};
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &pts[0][0]);
    glLineWidth(1.0f);
    glPointSize(1.0f);
    switch (k) {
    case 0:
      glMapGrid1f(40, 0.0f, 1.0f);
      glEvalMesh1(GL_LINE, 0, 40);
      break;
    case 1:
      glColor3f(0.5f, 0.5f, 0.5f); // replaced by the colour map, and left as it is
      glBegin(GL_LINE_STRIP);
      for (int i = 0; i <= 50; ++i)
        glEvalCoord1f(static_cast<float>(i) / 50.0f);
      glEnd();
      break;
    case 2:
      glPointSize(4.0f);
      glMapGrid1d(16, 0.0, 1.0);
      glBegin(GL_POINTS);
      for (int i = 0; i <= 16; ++i)
        glEvalPoint1(i);
      glEnd();
      break;
    default:
      // Without the colour map the current colour is used; a reversed grid from 1 to 0.
      glDisable(GL_MAP1_COLOR_4);
      glColor3f(1.0f, 0.8f, 0.2f);
      glLineWidth(2.0f);
      glMapGrid1f(30, 1.0f, 0.0f);
      glEvalMesh1(GL_LINE, 0, 30);
      glEvalMesh1(GL_POINT, 0, 30);
      break;
    }
  }
  glPopAttrib();
}

PINEDA_SCENE(
    eval_rational,
    "MAP1_VERTEX_4 rational quadratics: exact circles from quarter arcs of weight 1/sqrt 2",
    .allowance = kLineAllowance, .why = kLineWhy) {
  clear_frame(0.0f, 0.0f, 0.0f);
  glPushAttrib(GL_EVAL_BIT | GL_CURRENT_BIT);
  window_projection(frame);
  const float w = static_cast<float>(frame.width), h = static_cast<float>(frame.height);
  glEnable(GL_MAP1_VERTEX_4);
  glEnable(GL_MAP1_VERTEX_3); // VERTEX_4 takes precedence
  glMapGrid1f(20, 0.0f, 1.0f);
  const float s = std::sqrt(0.5f);
  for (int c = 0; c < 6; ++c) {
    const float cx = w * (0.18f + 0.32f * static_cast<float>(c % 3));
    const float cy = h * (0.28f + 0.45f * static_cast<float>(c / 3));
    const float r = std::fmin(w, h) * (0.08f + 0.025f * static_cast<float>(c));
    palette_color(c * 3 + 1);
    for (int q = 0; q < 4; ++q) {
      // Quarter q from angle q*90 to (q+1)*90 degrees; the middle point has weight 1/sqrt 2
      // and is given homogeneous (multiplied by its weight).
      const float a0 = static_cast<float>(q) * kPi * 0.5f, a1 = a0 + kPi * 0.5f;
      const float x0 = std::cos(a0), y0 = std::sin(a0), x1 = std::cos(a1), y1 = std::sin(a1);
      const float pts[3][4] = {{cx + r * x0, cy + r * y0, 0.0f, 1.0f},
                               {s * (cx + r * (x0 + x1)), s * (cy + r * (y0 + y1)), 0.0f, s},
                               {cx + r * x1, cy + r * y1, 0.0f, 1.0f}};
      glMap1f(GL_MAP1_VERTEX_4, 0.0f, 1.0f, 4, 3, &pts[0][0]);
      glEvalMesh1(GL_LINE, 0, 20);
    }
  }
  glPopAttrib();
}
