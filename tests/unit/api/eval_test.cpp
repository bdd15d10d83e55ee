// Evaluators (GL 2.1 §5.1): errors, queries, evaluated values checked against a double-
// precision Bernstein reference through feedback, AUTO_NORMAL through lighting, EvalMesh
// primitives, PushAttrib(EVAL_BIT) and display lists that copy the control points.
//
// Every test draws with identity matrices on the 32x32 window: window x = 16 (x + 1),
// y = 16 (y + 1), z = (z + 1) / 2.
#include <cmath>
#include <functional>
#include <vector>

#include "api_fixture.h"

namespace {

using Eval = GLTest;

GLenum err() {
  return glGetError();
}

// Bernstein polynomial B_i^n(t) in double precision.
double bern(int n, int i, double t) {
  double c = 1.0;
  for (int j = 1; j <= i; ++j)
    c = c * (n - i + j) / j;
  return c * std::pow(t, i) * std::pow(1.0 - t, n - i);
}

// Component c of a one-dimensional map with `order` packed points of k values at t in [0,1].
double ref1(const float* pts, int order, int k, int c, double t) {
  double s = 0.0;
  for (int i = 0; i < order; ++i)
    s += bern(order - 1, i, t) * pts[i * k + c];
  return s;
}

struct Fb {
  std::vector<GLfloat> v;
  GLint n = 0;
};

Fb feedback(GLenum type, const std::function<void()>& draw) {
  Fb r;
  r.v.assign(4096, -999.0f);
  glFeedbackBuffer(4096, type, r.v.data());
  glRenderMode(GL_FEEDBACK);
  draw();
  r.n = glRenderMode(GL_RENDER);
  return r;
}

float win(double ndc) {
  return static_cast<float>(16.0 * (ndc + 1.0));
}

// A cubic curve in x, y, z and a colour map on the same domain [2, 4].
const float kCurve[4][3] = {
    {-0.8f, -0.5f, 0.0f}, {-0.3f, 0.9f, 0.2f}, {0.4f, -0.7f, -0.4f}, {0.8f, 0.6f, 0.5f}};
const float kColors[3][4] = {
    {1.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f, 0.5f}, {0.0f, 0.0f, 1.0f, 0.0f}};

void set_curve() {
  glMap1f(GL_MAP1_VERTEX_3, 2.0f, 4.0f, 3, 4, &kCurve[0][0]);
  glMap1f(GL_MAP1_COLOR_4, 2.0f, 4.0f, 4, 3, &kColors[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glEnable(GL_MAP1_COLOR_4);
}

TEST_F(Eval, Map1Errors) {
  const float p[64] = {};
  glMap1f(GL_MAP1_VERTEX_3, 0, 0, 3, 2, p);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE)); // u1 == u2
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 0, p);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE)); // order < 1
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 31, p);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE)); // order > MAX_EVAL_ORDER
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 2, 2, p);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE)); // stride < k
  glMap1d(GL_MAP1_VERTEX_4, 0, 1, 3, 2, nullptr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glMap1f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, p);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glMap1f(GL_TEXTURE_2D, 0, 1, 3, 2, p);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glBegin(GL_POINTS);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, p);
  glEnd();
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // §5.1: Map with ACTIVE_TEXTURE other than TEXTURE0 is INVALID_OPERATION.
  auto active =
      reinterpret_cast<void(GLAPIENTRY*)(GLenum)>(OSMesaGetProcAddress("glActiveTexture"));
  ASSERT_NE(active, nullptr);
  active(GL_TEXTURE1);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, p);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  active(GL_TEXTURE0);
  // The failed calls changed nothing.
  GLint order = 0;
  glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
  EXPECT_EQ(order, 1);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

TEST_F(Eval, Map2AndGridErrors) {
  const double p[256] = {};
  glMap2d(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 1, 1, 6, 2, p);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE)); // v1 == v2
  glMap2d(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 31, p);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glMap2d(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 2, 2, p);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE)); // vstride < k
  glMap2d(GL_MAP2_NORMAL, 0, 1, 2, 2, 0, 1, 6, 2, p);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE)); // ustride < k
  glMap2d(GL_MAP1_NORMAL, 0, 1, 3, 2, 0, 1, 6, 2, p);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glMapGrid1f(0, 0, 1);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glMapGrid2d(1, 0, 1, -1, 0, 1);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glEvalMesh1(GL_FILL, 0, 1);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glEvalMesh2(GL_POLYGON, 0, 1, 0, 1);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glBegin(GL_POINTS);
  glEvalMesh2(GL_FILL, 0, 1, 0, 1);
  glEnd();
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);
  glMapGrid1d(2, 0, 1);
  glEnd();
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  GLfloat f[4];
  glGetMapfv(GL_TEXTURE_1D, GL_ORDER, f);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glGetMapfv(GL_MAP1_INDEX, GL_TEXTURE_1D, f);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glBegin(GL_POINTS);
  glGetMapfv(GL_MAP1_INDEX, GL_ORDER, f);
  glEnd();
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // EvalCoord and EvalPoint are legal between Begin and End.
  glBegin(GL_POINTS);
  glEvalCoord1f(0.5f);
  glEvalCoord2d(0.5, 0.5);
  glEvalPoint1(0);
  glEvalPoint2(0, 0);
  glEnd();
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

TEST_F(Eval, InitialStateAndQueries) {
  GLint i = 0;
  glGetIntegerv(GL_MAX_EVAL_ORDER, &i);
  EXPECT_EQ(i, 30);
  GLfloat f[4] = {};
  glGetFloatv(GL_MAP1_GRID_DOMAIN, f);
  EXPECT_EQ(f[0], 0.0f);
  EXPECT_EQ(f[1], 1.0f);
  glGetIntegerv(GL_MAP1_GRID_SEGMENTS, &i);
  EXPECT_EQ(i, 1);
  GLint seg[2] = {};
  glGetIntegerv(GL_MAP2_GRID_SEGMENTS, seg);
  EXPECT_EQ(seg[0], 1);
  EXPECT_EQ(seg[1], 1);
  const GLenum caps[] = {GL_MAP1_COLOR_4,         GL_MAP1_INDEX,           GL_MAP1_NORMAL,
                         GL_MAP1_TEXTURE_COORD_1, GL_MAP1_TEXTURE_COORD_2, GL_MAP1_TEXTURE_COORD_3,
                         GL_MAP1_TEXTURE_COORD_4, GL_MAP1_VERTEX_3,        GL_MAP1_VERTEX_4,
                         GL_MAP2_COLOR_4,         GL_MAP2_INDEX,           GL_MAP2_NORMAL,
                         GL_MAP2_TEXTURE_COORD_1, GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3,
                         GL_MAP2_TEXTURE_COORD_4, GL_MAP2_VERTEX_3,        GL_MAP2_VERTEX_4,
                         GL_AUTO_NORMAL};
  for (GLenum cap : caps) {
    EXPECT_FALSE(glIsEnabled(cap)) << cap;
    glEnable(cap);
    EXPECT_TRUE(glIsEnabled(cap)) << cap;
    GLboolean b = GL_FALSE;
    glGetBooleanv(cap, &b);
    EXPECT_TRUE(b) << cap;
    glDisable(cap);
    EXPECT_FALSE(glIsEnabled(cap)) << cap;
  }
  // §5.1 initial maps: order 1, domain [0, 1], the constant points of each kind.
  struct Init {
    GLenum target;
    int k;
    float v[4];
  };
  const Init inits[] = {{GL_MAP1_COLOR_4, 4, {1, 1, 1, 1}},
                        {GL_MAP2_INDEX, 1, {1}},
                        {GL_MAP1_NORMAL, 3, {0, 0, 1}},
                        {GL_MAP2_TEXTURE_COORD_2, 2, {0, 0}},
                        {GL_MAP1_TEXTURE_COORD_4, 4, {0, 0, 0, 1}},
                        {GL_MAP2_VERTEX_3, 3, {0, 0, 0}},
                        {GL_MAP1_VERTEX_4, 4, {0, 0, 0, 1}}};
  for (const Init& in : inits) {
    GLfloat c[4] = {-1, -1, -1, -1};
    glGetMapfv(in.target, GL_COEFF, c);
    for (int j = 0; j < in.k; ++j)
      EXPECT_EQ(c[j], in.v[j]) << in.target << " " << j;
    GLint order[2] = {};
    glGetMapiv(in.target, GL_ORDER, order);
    EXPECT_EQ(order[0], 1);
    GLdouble dom[4] = {};
    glGetMapdv(in.target, GL_DOMAIN, dom);
    EXPECT_EQ(dom[0], 0.0);
    EXPECT_EQ(dom[1], 1.0);
  }
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

TEST_F(Eval, MapStoresPackedPointsAndGrids) {
  // Stride 5 with 3 values per point: the extra values are skipped.
  const float p1[] = {1, 2, 3, 9, 9, 4, 5, 6, 9, 9, 7, 8, 9, 9, 9};
  glMap1f(GL_MAP1_NORMAL, -1.0f, 3.5f, 5, 3, p1);
  GLfloat c[9] = {};
  glGetMapfv(GL_MAP1_NORMAL, GL_COEFF, c);
  const float want1[] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  for (int i = 0; i < 9; ++i)
    EXPECT_EQ(c[i], want1[i]);
  GLint dom[2] = {};
  glGetMapiv(GL_MAP1_NORMAL, GL_DOMAIN, dom);
  EXPECT_EQ(dom[0], -1);
  EXPECT_EQ(dom[1], 4); // 3.5 rounds to 4
  // Map2 with ustride 2 (u varies fastest) and vstride 6: R_ij at 2i + 6j.
  double p2[18];
  for (int i = 0; i < 18; ++i)
    p2[i] = i;
  glMap2d(GL_MAP2_TEXTURE_COORD_2, 0, 1, 2, 3, 5, 7, 6, 3, p2);
  GLdouble d[18] = {};
  glGetMapdv(GL_MAP2_TEXTURE_COORD_2, GL_COEFF, d);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 2; ++k)
        EXPECT_EQ(d[(i * 3 + j) * 2 + k], p2[2 * i + 6 * j + k]) << i << j << k;
  GLint order[2] = {};
  glGetMapiv(GL_MAP2_TEXTURE_COORD_2, GL_ORDER, order);
  EXPECT_EQ(order[0], 3);
  EXPECT_EQ(order[1], 3);
  GLfloat fd[4] = {};
  glGetMapfv(GL_MAP2_TEXTURE_COORD_2, GL_DOMAIN, fd);
  EXPECT_EQ(fd[2], 5.0f);
  EXPECT_EQ(fd[3], 7.0f);
  glMapGrid1d(7, 0.25, -2.0);
  GLfloat g[4] = {};
  glGetFloatv(GL_MAP1_GRID_DOMAIN, g);
  EXPECT_EQ(g[0], 0.25f);
  EXPECT_EQ(g[1], -2.0f);
  GLint n = 0;
  glGetIntegerv(GL_MAP1_GRID_SEGMENTS, &n);
  EXPECT_EQ(n, 7);
  glMapGrid2f(3, 1, 2, 4, 5, 6);
  glGetFloatv(GL_MAP2_GRID_DOMAIN, g);
  EXPECT_EQ(g[0], 1.0f);
  EXPECT_EQ(g[1], 2.0f);
  EXPECT_EQ(g[2], 5.0f);
  EXPECT_EQ(g[3], 6.0f);
  GLint seg[2] = {};
  glGetIntegerv(GL_MAP2_GRID_SEGMENTS, seg);
  EXPECT_EQ(seg[0], 3);
  EXPECT_EQ(seg[1], 4);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

// EvalCoord1 values against the Bernstein reference; the current colour is not changed.
TEST_F(Eval, EvalCoord1MatchesBernstein) {
  set_curve();
  glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
  const double us[] = {2.0, 2.3, 3.0, 3.71, 4.0};
  const Fb r = feedback(GL_3D_COLOR, [&] {
    glBegin(GL_POINTS);
    for (double u : us)
      glEvalCoord1d(u);
    glEnd();
  });
  ASSERT_EQ(r.n, 5 * 8);
  for (int i = 0; i < 5; ++i) {
    const double t = (us[i] - 2.0) / 2.0;
    const float* v = &r.v[size_t(i) * 8];
    EXPECT_EQ(v[0], float(GL_POINT_TOKEN));
    EXPECT_NEAR(v[1], win(ref1(&kCurve[0][0], 4, 3, 0, t)), 1e-4);
    EXPECT_NEAR(v[2], win(ref1(&kCurve[0][0], 4, 3, 1, t)), 1e-4);
    EXPECT_NEAR(v[3], (ref1(&kCurve[0][0], 4, 3, 2, t) + 1.0) / 2.0, 1e-5);
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(v[4 + c], ref1(&kColors[0][0], 3, 4, c, t), 1e-5) << i << " " << c;
  }
  GLfloat cur[4];
  glGetFloatv(GL_CURRENT_COLOR, cur);
  EXPECT_EQ(cur[0], 0.25f);
  EXPECT_EQ(cur[1], 0.5f);
  EXPECT_EQ(cur[2], 0.75f);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

// Without a vertex map EvalCoord issues nothing; MAP1_VERTEX_4 takes precedence over VERTEX_3.
TEST_F(Eval, VertexMapSelection) {
  set_curve();
  glDisable(GL_MAP1_VERTEX_3);
  Fb r = feedback(GL_3D, [] {
    glBegin(GL_POINTS);
    glEvalCoord1f(3.0f);
    glEvalPoint1(0);
    glEnd();
    glEvalMesh1(GL_POINT, 0, 1);
  });
  EXPECT_EQ(r.n, 0);
  // A rational quadratic (w = 1, 2, 1 weights applied to x, y): a quarter circle.
  const float p4[] = {0.8f, 0.0f, 0.0f, 1.0f, 0.8f, 0.8f, 0.0f, 1.0f, 0.0f, 0.8f, 0.0f, 2.0f};
  glMap1f(GL_MAP1_VERTEX_4, 0.0f, 1.0f, 4, 3, p4);
  glEnable(GL_MAP1_VERTEX_3);
  glEnable(GL_MAP1_VERTEX_4);
  r = feedback(GL_3D, [] {
    glBegin(GL_POINTS);
    glEvalCoord1f(0.3f);
    glEnd();
  });
  ASSERT_EQ(r.n, 4);
  double h[4];
  for (int c = 0; c < 4; ++c)
    h[c] = ref1(p4, 3, 4, c, 0.3);
  EXPECT_NEAR(r.v[1], win(h[0] / h[3]), 1e-4);
  EXPECT_NEAR(r.v[2], win(h[1] / h[3]), 1e-4);
}

// Texture-coordinate maps: only the one with the most coordinates is used (§5.1).
TEST_F(Eval, TextureMapPrecedence) {
  const float v[] = {0, 0, 0, 0.5f, 0.5f, 0};
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, v);
  const float t1[] = {0.1f, 0.9f};
  const float t2[] = {0.2f, 0.3f, 0.6f, 0.7f};
  glMap1f(GL_MAP1_TEXTURE_COORD_1, 0, 1, 1, 2, t1);
  glMap1f(GL_MAP1_TEXTURE_COORD_2, 0, 1, 2, 2, t2);
  glEnable(GL_MAP1_VERTEX_3);
  glEnable(GL_MAP1_TEXTURE_COORD_1);
  glTexCoord4f(5, 6, 7, 8);
  Fb r = feedback(GL_3D_COLOR_TEXTURE, [] {
    glBegin(GL_POINTS);
    glEvalCoord1f(0.5f);
    glEnd();
  });
  ASSERT_EQ(r.n, 12);
  EXPECT_NEAR(r.v[8], 0.5f, 1e-6);
  EXPECT_EQ(r.v[9], 0.0f);
  EXPECT_EQ(r.v[10], 0.0f);
  EXPECT_EQ(r.v[11], 1.0f);
  glEnable(GL_MAP1_TEXTURE_COORD_2);
  r = feedback(GL_3D_COLOR_TEXTURE, [] {
    glBegin(GL_POINTS);
    glEvalCoord1f(0.5f);
    glEnd();
  });
  ASSERT_EQ(r.n, 12);
  EXPECT_NEAR(r.v[8], 0.4f, 1e-6);
  EXPECT_NEAR(r.v[9], 0.5f, 1e-6);
  GLfloat cur[4];
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, cur);
  EXPECT_EQ(cur[0], 5.0f);
  EXPECT_EQ(cur[3], 8.0f);
}

// EvalMesh1 and EvalPoint1 use the grid; i = n gives u2 exactly (§5.1).
TEST_F(Eval, EvalMesh1Grid) {
  const float v[] = {-1, -1, 0, 1, 1, 0};
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, v);
  glEnable(GL_MAP1_VERTEX_3);
  glMapGrid1f(3, 0.1f, 0.7f);
  Fb r = feedback(GL_2D, [] { glEvalMesh1(GL_LINE, 0, 3); });
  // A 4-vertex line strip: LINE_RESET_TOKEN, then two LINE_TOKENs, 5 values each.
  ASSERT_EQ(r.n, 15);
  EXPECT_EQ(r.v[0], float(GL_LINE_RESET_TOKEN));
  const double x0 = -1.0 + 2.0 * 0.1f, x3 = -1.0 + 2.0 * 0.7f;
  EXPECT_NEAR(r.v[1], win(x0), 1e-4);
  EXPECT_NEAR(r.v[13], win(x3), 1e-4);
  r = feedback(GL_2D, [] { glEvalMesh1(GL_POINT, 1, 2); });
  ASSERT_EQ(r.n, 6);
  EXPECT_NEAR(r.v[1], win(-1.0 + 2.0 * (0.1 + 0.2)), 1e-4);
  r = feedback(GL_2D, [] {
    glBegin(GL_POINTS);
    glEvalPoint1(3);
    glEnd();
  });
  ASSERT_EQ(r.n, 3);
  EXPECT_NEAR(r.v[1], win(x3), 1e-4);
}

// A bilinear patch: EvalMesh2 primitives and values, and AUTO_NORMAL seen through lighting.
TEST_F(Eval, EvalMesh2AndAutoNormal) {
  // Plane z = 0.5 x (tilted about y): normal (-0.5, 0, 1) / |.| for the orientation u = x,
  // v = y.
  const float p[] = {-0.5f, -0.5f, -0.25f, 0.5f, -0.5f, 0.25f,
                     -0.5f, 0.5f,  -0.25f, 0.5f, 0.5f,  0.25f};
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, p);
  glEnable(GL_MAP2_VERTEX_3);
  glMapGrid2f(2, 0, 1, 3, 0, 1);
  Fb r = feedback(GL_2D, [] { glEvalMesh2(GL_POINT, 0, 2, 0, 3); });
  EXPECT_EQ(r.n, 12 * 3);
  r = feedback(GL_2D, [] { glEvalMesh2(GL_LINE, 0, 2, 0, 3); });
  // 4 strips of 3 vertices (2 segments) and 3 strips of 4 vertices (3 segments): 17 lines.
  EXPECT_EQ(r.n, 17 * 5);
  r = feedback(GL_2D, [] { glEvalMesh2(GL_FILL, 0, 2, 0, 3); });
  // 3 rows of 2 quads: 12 triangles of 1 + 1 + 3 * 2 values.
  EXPECT_EQ(r.n, 12 * 8);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const float zero[] = {0, 0, 0, 1}, one[] = {1, 1, 1, 1}, dir[] = {0, 0, 1, 0};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, zero);
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, zero);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, one);
  glNormal3f(0, 0, -1); // the current normal would light nothing
  glEnable(GL_AUTO_NORMAL);
  r = feedback(GL_3D_COLOR, [] {
    glBegin(GL_POINTS);
    glEvalCoord2f(0.3f, 0.6f);
    glEnd();
  });
  ASSERT_EQ(r.n, 8);
  EXPECT_NEAR(r.v[4], 1.0 / std::sqrt(1.25), 1e-5);
  GLfloat cur[3];
  glGetFloatv(GL_CURRENT_NORMAL, cur);
  EXPECT_EQ(cur[2], -1.0f);
  // AUTO_NORMAL takes precedence over a normal map; without it the normal map is used.
  const float n[] = {0, 0.6f, 0.8f};
  glMap2f(GL_MAP2_NORMAL, 0, 1, 3, 1, 0, 1, 3, 1, n);
  glEnable(GL_MAP2_NORMAL);
  r = feedback(GL_3D_COLOR, [] {
    glBegin(GL_POINTS);
    glEvalCoord2f(0.3f, 0.6f);
    glEnd();
    glDisable(GL_AUTO_NORMAL);
    glBegin(GL_POINTS);
    glEvalCoord2f(0.3f, 0.6f);
    glEnd();
  });
  ASSERT_EQ(r.n, 16);
  EXPECT_NEAR(r.v[4], 1.0 / std::sqrt(1.25), 1e-5);
  EXPECT_NEAR(r.v[12], 0.8, 1e-5);
}

// AUTO_NORMAL of a MAP2_VERTEX_4 plane uses the projected q = (x/w, y/w, z/w).
TEST_F(Eval, AutoNormalRational) {
  // The plane z = 0 with weights: every q lies in z = 0, so the normal is (0, 0, +-1).
  const float p[] = {-1, -1, 0, 1, 2, -2, 0, 2, -1, 1, 0, 1, 1, 1, 0, 1};
  glMap2f(GL_MAP2_VERTEX_4, 0, 1, 4, 2, 0, 1, 8, 2, p);
  glEnable(GL_MAP2_VERTEX_4);
  glEnable(GL_AUTO_NORMAL);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const float zero[] = {0, 0, 0, 1}, one[] = {1, 1, 1, 1}, dir[] = {0, 0, 1, 0};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, zero);
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, zero);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, one);
  const Fb r = feedback(GL_3D_COLOR, [] {
    glBegin(GL_POINTS);
    glEvalCoord2f(0.4f, 0.7f);
    glEnd();
  });
  ASSERT_EQ(r.n, 8);
  EXPECT_NEAR(r.v[4], 1.0, 1e-5);
}

TEST_F(Eval, PushPopEvalBit) {
  const float a[] = {1, 2, 3, 4, 5, 6};
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, a);
  glMapGrid1f(4, 0, 2);
  glEnable(GL_MAP1_VERTEX_3);
  glPushAttrib(GL_EVAL_BIT);
  const float b[] = {9, 9, 9};
  glMap1f(GL_MAP1_VERTEX_3, 5, 6, 3, 1, b);
  glMapGrid1f(8, 1, 3);
  glDisable(GL_MAP1_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  glPopAttrib();
  EXPECT_TRUE(glIsEnabled(GL_MAP1_VERTEX_3));
  EXPECT_FALSE(glIsEnabled(GL_AUTO_NORMAL));
  GLfloat c[6] = {};
  glGetMapfv(GL_MAP1_VERTEX_3, GL_COEFF, c);
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ(c[i], a[i]);
  GLint n = 0;
  glGetIntegerv(GL_MAP1_GRID_SEGMENTS, &n);
  EXPECT_EQ(n, 4);
  // ENABLE_BIT restores the enables but not the maps.
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_MAP1_VERTEX_3);
  glEnable(GL_MAP2_COLOR_4);
  glMap1f(GL_MAP1_VERTEX_3, 5, 6, 3, 1, b);
  glPopAttrib();
  EXPECT_TRUE(glIsEnabled(GL_MAP1_VERTEX_3));
  EXPECT_FALSE(glIsEnabled(GL_MAP2_COLOR_4));
  GLint order = 0;
  glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
  EXPECT_EQ(order, 1);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

// §5.4: Map compiles a copy of the points; EvalCoord inside a compiled Begin/End evaluates
// the maps of execution time.
TEST_F(Eval, DisplayListCopiesPoints) {
  float pts[] = {-0.5f, 0.0f, 0.0f, 9.0f, 0.5f, 0.0f, 0.0f, 9.0f};
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 4, 2, pts);
  glMap1f(GL_MAP1_VERTEX_3, 0, 0, 4, 2, pts); // u1 == u2: an error when executed
  glEnable(GL_MAP1_VERTEX_3);
  glBegin(GL_POINTS);
  glEvalCoord1f(0.25f);
  glEnd();
  glEndList();
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  GLint order = 0;
  glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
  EXPECT_EQ(order, 1); // compiled, not executed
  pts[0] = 100.0f;
  const Fb r = feedback(GL_2D, [&] { glCallList(list); });
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  ASSERT_EQ(r.n, 3);
  EXPECT_NEAR(r.v[1], win(-0.25), 1e-4);
  GLfloat c[6] = {};
  glGetMapfv(GL_MAP1_VERTEX_3, GL_COEFF, c);
  EXPECT_EQ(c[0], -0.5f);
  EXPECT_EQ(c[3], 0.5f);
  glDeleteLists(list, 1);
}

// MapGrid and EvalMesh compile as calls; GetMap executes at once (§5.4).
TEST_F(Eval, DisplayListMeshAndGetMap) {
  const float pts[] = {-0.5f, 0.0f, 0.0f, 0.5f, 0.0f, 0.0f};
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, pts);
  glEnable(GL_MAP1_VERTEX_3);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMapGrid1f(2, 0.0f, 1.0f);
  glEvalMesh1(GL_POINT, 0, 2);
  GLint order = 0;
  glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
  EXPECT_EQ(order, 2);
  glEndList();
  GLint n = 0;
  glGetIntegerv(GL_MAP1_GRID_SEGMENTS, &n);
  EXPECT_EQ(n, 1);
  const Fb r = feedback(GL_2D, [&] { glCallList(list); });
  ASSERT_EQ(r.n, 9);
  EXPECT_NEAR(r.v[4], win(0.0), 1e-4);
  EXPECT_NEAR(r.v[7], win(0.5), 1e-4);
  glDeleteLists(list, 1);
  // Integer queries of huge coefficients clamp.
  const float big[] = {1e20f, -1e20f, 2.5f};
  glMap1f(GL_MAP1_NORMAL, 0, 1, 3, 1, big);
  GLint c[3] = {};
  glGetMapiv(GL_MAP1_NORMAL, GL_COEFF, c);
  EXPECT_EQ(c[0], 2147483647);
  EXPECT_EQ(c[1], -2147483647 - 1);
  EXPECT_EQ(c[2], 3);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

} // namespace
