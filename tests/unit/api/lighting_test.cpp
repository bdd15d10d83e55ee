// Fixed-function lighting (GL 2.1 §2.14): errors of every lighting command, state round
// trips (including positions and spot directions transformed by the model-view matrix), and
// the lighting equation against a double-precision reference. Lit colours are read back from
// single points, whose fragment takes the vertex colour unchanged (GL 2.1 §3.3.1).
#include <algorithm>
#include <climits>
#include <cmath>
#include <vector>

#include "api_fixture.h"

namespace {

class Lighting : public GLTest {
protected:
  void SetUp() override {
    GLTest::SetUp();
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, kW, 0, kH, -100, 100);
    glMatrixMode(GL_MODELVIEW);
  }
public:
  // Channel c of pixel (x, y).
  int channel(int x, int y, int c) const { return buf_[(y * kW + x) * 4 + c]; }
};

GLenum err() { return glGetError(); }

// ---- the reference: GL 2.1 §2.14.1 in double precision ----

struct RefLight {
  double amb[4] = {0, 0, 0, 1}, dif[4] = {1, 1, 1, 1}, spec[4] = {1, 1, 1, 1};
  double pos[4] = {0, 0, 1, 0};
  double spot_dir[3] = {0, 0, -1};
  double spot_exp = 0, cutoff = 180;
  double k[3] = {1, 0, 0};
};

struct RefMaterial {
  double amb[4] = {0.2, 0.2, 0.2, 1}, dif[4] = {0.8, 0.8, 0.8, 1}, spec[4] = {0, 0, 0, 1};
  double emi[4] = {0, 0, 0, 1};
  double shin = 0;
};

struct RefModel {
  double amb[4] = {0.2, 0.2, 0.2, 1};
  bool local_viewer = false;
  bool separate = false;
};

double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
void unit(double* v) {
  const double l = std::sqrt(dot(v, v));
  if (l > 0) v[0] /= l, v[1] /= l, v[2] /= l;
}
double clamp01(double v) { return std::min(1.0, std::max(0.0, v)); }

// The colour after the colour sum (§3.9): clamp(clamp(c_pri) + clamp(c_sec)), RGBA.
std::vector<double> reference(const std::vector<RefLight>& lights, const RefMaterial& m,
                              const RefModel& model, const double v[3], const double n_in[3]) {
  double n[3] = {n_in[0], n_in[1], n_in[2]};
  double pri[3], sec[3] = {0, 0, 0};
  for (int c = 0; c < 3; ++c) pri[c] = m.emi[c] + m.amb[c] * model.amb[c];
  for (const RefLight& l : lights) {
    double vp[3], att = 1, spot = 1;
    if (l.pos[3] != 0) {
      for (int c = 0; c < 3; ++c) vp[c] = l.pos[c] / l.pos[3] - v[c];
      const double d = std::sqrt(dot(vp, vp));
      att = 1 / (l.k[0] + l.k[1] * d + l.k[2] * d * d);
      unit(vp);
    } else {
      for (int c = 0; c < 3; ++c) vp[c] = l.pos[c];
      unit(vp);
    }
    if (l.cutoff != 180) {
      double sd[3] = {l.spot_dir[0], l.spot_dir[1], l.spot_dir[2]};
      unit(sd);
      const double pv[3] = {-vp[0], -vp[1], -vp[2]};
      const double s = dot(pv, sd);
      spot = s >= std::cos(l.cutoff * M_PI / 180) ? std::pow(s, l.spot_exp) : 0;
    }
    double h[3];
    if (model.local_viewer) {
      double ve[3] = {-v[0], -v[1], -v[2]};
      unit(ve);
      for (int c = 0; c < 3; ++c) h[c] = vp[c] + ve[c];
    } else {
      h[0] = vp[0], h[1] = vp[1], h[2] = vp[2] + 1;
    }
    unit(h);
    const double ndl = std::max(0.0, dot(n, vp));
    const double f = ndl != 0 ? 1 : 0;
    const double spec = f * std::pow(std::max(0.0, dot(n, h)), m.shin);
    for (int c = 0; c < 3; ++c) {
      pri[c] += att * spot * (m.amb[c] * l.amb[c] + ndl * m.dif[c] * l.dif[c]);
      const double s = att * spot * spec * m.spec[c] * l.spec[c];
      if (model.separate)
        sec[c] += s;
      else
        pri[c] += s;
    }
  }
  std::vector<double> out(4);
  for (int c = 0; c < 3; ++c) out[c] = clamp01(clamp01(pri[c]) + clamp01(sec[c]));
  out[3] = clamp01(m.dif[3]);
  return out;
}

void set_light(int i, const RefLight& l) {
  GLfloat v[4];
  const GLenum id = GL_LIGHT0 + i;
  const auto put = [&](GLenum pname, const double* d, int n) {
    for (int k = 0; k < n; ++k) v[k] = static_cast<GLfloat>(d[k]);
    glLightfv(id, pname, v);
  };
  put(GL_AMBIENT, l.amb, 4);
  put(GL_DIFFUSE, l.dif, 4);
  put(GL_SPECULAR, l.spec, 4);
  put(GL_POSITION, l.pos, 4);
  put(GL_SPOT_DIRECTION, l.spot_dir, 3);
  glLightf(id, GL_SPOT_EXPONENT, static_cast<GLfloat>(l.spot_exp));
  glLightf(id, GL_SPOT_CUTOFF, static_cast<GLfloat>(l.cutoff));
  glLightf(id, GL_CONSTANT_ATTENUATION, static_cast<GLfloat>(l.k[0]));
  glLightf(id, GL_LINEAR_ATTENUATION, static_cast<GLfloat>(l.k[1]));
  glLightf(id, GL_QUADRATIC_ATTENUATION, static_cast<GLfloat>(l.k[2]));
  glEnable(id);
}

void set_material(GLenum face, const RefMaterial& m) {
  GLfloat v[4];
  const auto put = [&](GLenum pname, const double* d) {
    for (int k = 0; k < 4; ++k) v[k] = static_cast<GLfloat>(d[k]);
    glMaterialfv(face, pname, v);
  };
  put(GL_AMBIENT, m.amb);
  put(GL_DIFFUSE, m.dif);
  put(GL_SPECULAR, m.spec);
  put(GL_EMISSION, m.emi);
  glMaterialf(face, GL_SHININESS, static_cast<GLfloat>(m.shin));
}

void set_model(const RefModel& model) {
  const GLfloat a[4] = {GLfloat(model.amb[0]), GLfloat(model.amb[1]), GLfloat(model.amb[2]),
                        GLfloat(model.amb[3])};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, a);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, model.local_viewer ? 1 : 0);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL,
                model.separate ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
}

// ---- errors ----

TEST_F(Lighting, LightErrors) {
  const GLfloat one[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT0 + 8, GL_AMBIENT, one);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glLightfv(GL_LIGHT0, GL_SHININESS, one);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glLightf(GL_LIGHT0, GL_AMBIENT, 1.0f); // multi-valued through the scalar form
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glLighti(GL_LIGHT0, GL_POSITION, 1);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  for (float bad : {-1.0f, 128.5f, NAN}) {
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, bad);
    EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  }
  for (float bad : {-0.5f, 90.5f, 179.0f, 181.0f}) {
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, bad);
    EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  }
  for (GLenum p : {GL_CONSTANT_ATTENUATION, GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION}) {
    glLightf(GL_LIGHT2, p, -0.25f);
    EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  }
  // The boundaries are legal, and a failed call leaves the state alone.
  glLighti(GL_LIGHT1, GL_SPOT_CUTOFF, 90);
  glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 128.0f);
  glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 100.0f);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  GLfloat v = 0;
  glGetLightfv(GL_LIGHT1, GL_SPOT_CUTOFF, &v);
  EXPECT_EQ(v, 90.0f);
  glGetLightfv(GL_LIGHT1, GL_SPOT_EXPONENT, &v);
  EXPECT_EQ(v, 128.0f);
  glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 180.0f);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));

  glGetLightfv(GL_LIGHT0 + 8, GL_AMBIENT, &v);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  GLint iv = 0;
  glGetLightiv(GL_LIGHT0, GL_EMISSION, &iv);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
}

TEST_F(Lighting, MaterialErrors) {
  const GLfloat one[4] = {1, 1, 1, 1};
  glMaterialfv(GL_FRONT_LEFT, GL_AMBIENT, one);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glMaterialfv(GL_FRONT, GL_POSITION, one);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glMaterialf(GL_FRONT, GL_DIFFUSE, 1.0f);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glMaterialf(GL_FRONT, GL_SHININESS, 128.5f);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  glMateriali(GL_BACK, GL_SHININESS, -1);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  GLfloat v[4];
  glGetMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, v);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glGetMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, v);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glGetMaterialfv(GL_FRONT, GL_SPOT_CUTOFF, v);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
}

TEST_F(Lighting, LightModelAndColorMaterialErrors) {
  glLightModelf(GL_LIGHT_MODEL_AMBIENT, 0.5f);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_FRONT);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glLightModeli(GL_SPOT_CUTOFF, 1);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glColorMaterial(GL_FRONT_LEFT, GL_AMBIENT);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glColorMaterial(GL_FRONT, GL_SHININESS);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glEnable(GL_LIGHT0 + 8);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
}

TEST_F(Lighting, BeginEnd) {
  const GLfloat one[4] = {1, 1, 1, 1};
  GLfloat v[4];
  GLint iv[4];
  const auto inside = [&](auto call) {
    glBegin(GL_POINTS);
    call();
    glEnd();
    return err();
  };
  const GLenum op = GL_INVALID_OPERATION;
  EXPECT_EQ(inside([&] { glLightfv(GL_LIGHT0, GL_AMBIENT, one); }), op);
  EXPECT_EQ(inside([&] { glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 1); }), op);
  EXPECT_EQ(inside([&] { glLighti(GL_LIGHT0, GL_SPOT_EXPONENT, 1); }), op);
  EXPECT_EQ(inside([&] { glLightiv(GL_LIGHT0, GL_SPOT_EXPONENT, iv); }), op);
  EXPECT_EQ(inside([&] { glLightModelfv(GL_LIGHT_MODEL_AMBIENT, one); }), op);
  EXPECT_EQ(inside([&] { glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1); }), op);
  EXPECT_EQ(inside([&] { glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 1); }), op);
  EXPECT_EQ(inside([&] { glLightModeliv(GL_LIGHT_MODEL_TWO_SIDE, iv); }), op);
  EXPECT_EQ(inside([&] { glColorMaterial(GL_FRONT, GL_AMBIENT); }), op);
  EXPECT_EQ(inside([&] { glGetLightfv(GL_LIGHT0, GL_AMBIENT, v); }), op);
  EXPECT_EQ(inside([&] { glGetLightiv(GL_LIGHT0, GL_AMBIENT, iv); }), op);
  EXPECT_EQ(inside([&] { glGetMaterialfv(GL_FRONT, GL_AMBIENT, v); }), op);
  EXPECT_EQ(inside([&] { glGetMaterialiv(GL_FRONT, GL_AMBIENT, iv); }), op);
  // GL 2.1 §2.14.2: Material is legal between Begin and End.
  EXPECT_EQ(inside([&] { glMaterialfv(GL_FRONT, GL_AMBIENT, one); }),
            static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(inside([&] { glMateriali(GL_FRONT, GL_SHININESS, 5); }),
            static_cast<GLenum>(GL_NO_ERROR));
  glGetMaterialfv(GL_FRONT, GL_SHININESS, v);
  EXPECT_EQ(v[0], 5.0f);
}

// ---- state ----

TEST_F(Lighting, Defaults) {
  GLfloat v[4];
  glGetLightfv(GL_LIGHT0, GL_DIFFUSE, v);
  EXPECT_EQ(v[0], 1.0f);
  EXPECT_EQ(v[3], 1.0f);
  glGetLightfv(GL_LIGHT3, GL_SPECULAR, v);
  EXPECT_EQ(v[0], 0.0f);
  EXPECT_EQ(v[3], 1.0f);
  glGetLightfv(GL_LIGHT5, GL_POSITION, v);
  EXPECT_EQ(v[2], 1.0f);
  EXPECT_EQ(v[3], 0.0f);
  glGetLightfv(GL_LIGHT5, GL_SPOT_DIRECTION, v);
  EXPECT_EQ(v[2], -1.0f);
  glGetLightfv(GL_LIGHT5, GL_SPOT_CUTOFF, v);
  EXPECT_EQ(v[0], 180.0f);
  glGetLightfv(GL_LIGHT5, GL_CONSTANT_ATTENUATION, v);
  EXPECT_EQ(v[0], 1.0f);
  glGetMaterialfv(GL_BACK, GL_DIFFUSE, v);
  EXPECT_FLOAT_EQ(v[0], 0.8f);
  glGetMaterialfv(GL_FRONT, GL_AMBIENT, v);
  EXPECT_FLOAT_EQ(v[1], 0.2f);
  glGetMaterialfv(GL_FRONT, GL_COLOR_INDEXES, v);
  EXPECT_EQ(v[1], 1.0f);
  glGetFloatv(GL_LIGHT_MODEL_AMBIENT, v);
  EXPECT_FLOAT_EQ(v[2], 0.2f);
  GLint i = -1;
  glGetIntegerv(GL_MAX_LIGHTS, &i);
  EXPECT_GE(i, 8);
  glGetIntegerv(GL_COLOR_MATERIAL_FACE, &i);
  EXPECT_EQ(i, GL_FRONT_AND_BACK);
  glGetIntegerv(GL_COLOR_MATERIAL_PARAMETER, &i);
  EXPECT_EQ(i, GL_AMBIENT_AND_DIFFUSE);
  glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL, &i);
  EXPECT_EQ(i, GL_SINGLE_COLOR);
  GLboolean b = GL_TRUE;
  glGetBooleanv(GL_LIGHT_MODEL_TWO_SIDE, &b);
  EXPECT_EQ(b, GL_FALSE);
  glGetBooleanv(GL_LIGHT_MODEL_LOCAL_VIEWER, &b);
  EXPECT_EQ(b, GL_FALSE);
  for (GLenum cap : {GLenum(GL_LIGHTING), GLenum(GL_LIGHT0), GLenum(GL_LIGHT7),
                     GLenum(GL_COLOR_MATERIAL), GLenum(GL_NORMALIZE), GLenum(GL_RESCALE_NORMAL)})
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Lighting, RoundTrips) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT6);
  EXPECT_EQ(glIsEnabled(GL_LIGHTING), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_LIGHT6), GL_TRUE);
  GLboolean b = GL_FALSE;
  glGetBooleanv(GL_LIGHT6, &b);
  EXPECT_EQ(b, GL_TRUE);

  const GLint half[4] = {INT_MAX / 2, 0, INT_MAX, INT_MIN};
  glLightiv(GL_LIGHT2, GL_AMBIENT, half);
  GLfloat v[4];
  glGetLightfv(GL_LIGHT2, GL_AMBIENT, v);
  EXPECT_NEAR(v[0], 0.5f, 1e-6);
  EXPECT_NEAR(v[2], 1.0f, 1e-6);
  EXPECT_NEAR(v[3], -1.0f, 1e-6);
  GLint iv[4];
  const GLfloat col[4] = {1.0f, 0.0f, -1.0f, 0.5f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, col);
  glGetMaterialiv(GL_BACK, GL_EMISSION, iv);
  EXPECT_EQ(iv[0], INT_MAX);
  EXPECT_EQ(iv[1], 0);
  EXPECT_LE(iv[2], -INT_MAX);
  EXPECT_NEAR(iv[3], INT_MAX / 2, 2);
  glMateriali(GL_FRONT, GL_SHININESS, 17);
  glGetMaterialiv(GL_FRONT, GL_SHININESS, iv);
  EXPECT_EQ(iv[0], 17);
  glGetMaterialfv(GL_BACK, GL_SHININESS, v);
  EXPECT_EQ(v[0], 0.0f);

  const GLfloat ad[4] = {0.25f, 0.5f, 0.75f, 1.0f};
  glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, ad);
  glGetMaterialfv(GL_BACK, GL_AMBIENT, v);
  EXPECT_EQ(v[1], 0.5f);
  glGetMaterialfv(GL_BACK, GL_DIFFUSE, v);
  EXPECT_EQ(v[2], 0.75f);
  glGetMaterialfv(GL_FRONT, GL_DIFFUSE, v);
  EXPECT_FLOAT_EQ(v[2], 0.8f);

  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glLightModelf(GL_LIGHT_MODEL_LOCAL_VIEWER, 1.0f);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  GLint i = 0;
  glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL, &i);
  EXPECT_EQ(i, GL_SEPARATE_SPECULAR_COLOR);
  glGetBooleanv(GL_LIGHT_MODEL_TWO_SIDE, &b);
  EXPECT_EQ(b, GL_TRUE);
  glGetBooleanv(GL_LIGHT_MODEL_LOCAL_VIEWER, &b);
  EXPECT_EQ(b, GL_TRUE);

  glLightf(GL_LIGHT3, GL_QUADRATIC_ATTENUATION, 0.125f);
  glGetLightiv(GL_LIGHT3, GL_QUADRATIC_ATTENUATION, iv);
  EXPECT_EQ(iv[0], 0);
  glGetLightfv(GL_LIGHT3, GL_QUADRATIC_ATTENUATION, v);
  EXPECT_EQ(v[0], 0.125f);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Lighting, PositionAndSpotDirectionUseTheModelview) {
  glTranslatef(1, 2, 3);
  glRotatef(90, 0, 0, 1);
  const GLfloat p[4] = {1, 0, 0, 1};
  glLightfv(GL_LIGHT1, GL_POSITION, p);
  const GLfloat dir[4] = {1, 0, 0, 0};
  glLightfv(GL_LIGHT1, GL_POSITION, dir); // directional: translation has no effect
  GLfloat v[4];
  glGetLightfv(GL_LIGHT1, GL_POSITION, v);
  EXPECT_NEAR(v[0], 0, 1e-6);
  EXPECT_NEAR(v[1], 1, 1e-6);
  EXPECT_NEAR(v[2], 0, 1e-6);
  EXPECT_EQ(v[3], 0.0f);
  glLightfv(GL_LIGHT2, GL_POSITION, p);
  glGetLightfv(GL_LIGHT2, GL_POSITION, v);
  EXPECT_NEAR(v[0], 1, 1e-6);
  EXPECT_NEAR(v[1], 3, 1e-6);
  EXPECT_NEAR(v[2], 3, 1e-6);
  EXPECT_EQ(v[3], 1.0f);
  const GLfloat sd[3] = {2, 0, 0};
  glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, sd);
  glGetLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, v);
  EXPECT_NEAR(v[0], 0, 1e-6);
  EXPECT_NEAR(v[1], 2, 1e-6); // upper 3x3 only, not normalized
  EXPECT_NEAR(v[2], 0, 1e-6);
  // Changing the model-view later does not move the light.
  glLoadIdentity();
  glGetLightfv(GL_LIGHT2, GL_POSITION, v);
  EXPECT_NEAR(v[1], 3, 1e-6);
}

TEST_F(Lighting, ColorMaterialTracksTheCurrentColor) {
  glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
  GLfloat v[4];
  glGetMaterialfv(GL_FRONT, GL_AMBIENT, v);
  EXPECT_FLOAT_EQ(v[0], 0.2f); // not enabled yet
  glEnable(GL_COLOR_MATERIAL);
  EXPECT_EQ(glIsEnabled(GL_COLOR_MATERIAL), GL_TRUE);
  glGetMaterialfv(GL_BACK, GL_DIFFUSE, v);
  EXPECT_FLOAT_EQ(v[0], 0.1f);
  EXPECT_FLOAT_EQ(v[3], 0.4f);
  glColor3f(0.5f, 0.6f, 0.7f);
  glGetMaterialfv(GL_FRONT, GL_AMBIENT, v);
  EXPECT_FLOAT_EQ(v[2], 0.7f);
  // A tracked property ignores Material while COLOR_MATERIAL is on; others take it.
  const GLfloat red[4] = {1, 0, 0, 1};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
  glMaterialfv(GL_FRONT, GL_SPECULAR, red);
  glGetMaterialfv(GL_FRONT, GL_DIFFUSE, v);
  EXPECT_FLOAT_EQ(v[0], 0.5f);
  glGetMaterialfv(GL_FRONT, GL_SPECULAR, v);
  EXPECT_FLOAT_EQ(v[0], 1.0f);
  // Switching the mode copies the current colour into the new property at once.
  glColorMaterial(GL_BACK, GL_EMISSION);
  glGetMaterialfv(GL_BACK, GL_EMISSION, v);
  EXPECT_FLOAT_EQ(v[1], 0.6f);
  glGetMaterialfv(GL_FRONT, GL_EMISSION, v);
  EXPECT_FLOAT_EQ(v[1], 0.0f);
  GLint i = 0;
  glGetIntegerv(GL_COLOR_MATERIAL_PARAMETER, &i);
  EXPECT_EQ(i, GL_EMISSION);
  glGetIntegerv(GL_COLOR_MATERIAL_FACE, &i);
  EXPECT_EQ(i, GL_BACK);
  // Disabled: colours no longer reach the material.
  glDisable(GL_COLOR_MATERIAL);
  glColor3f(0.9f, 0.9f, 0.9f);
  glGetMaterialfv(GL_BACK, GL_EMISSION, v);
  EXPECT_FLOAT_EQ(v[1], 0.6f);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

// ---- the lighting equation ----

// Light one point per (position, normal) and compare with the reference to one step of 8
// bits (the float evaluation may round the other way at a .5 boundary).
void expect_lit(Lighting* t, const std::vector<RefLight>& lights, const RefMaterial& m,
                const RefModel& model, const std::vector<std::vector<double>>& points) {
  glEnable(GL_LIGHTING);
  for (size_t i = 0; i < lights.size(); ++i) set_light(static_cast<int>(i), lights[i]);
  set_material(GL_FRONT_AND_BACK, m);
  set_model(model);
  int px = 0;
  for (const auto& p : points) {
    const double x = px % 16 * 2 + 0.5, y = px / 16 * 2 + 0.5;
    const double v[3] = {x, y, p[0]};
    double n[3] = {p[1], p[2], p[3]};
    glNormal3d(n[0], n[1], n[2]);
    glBegin(GL_POINTS);
    glVertex3dv(v);
    glEnd();
    const std::vector<double> want = reference(lights, m, model, v, n);
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(t->channel(static_cast<int>(x), static_cast<int>(y), c), want[c] * 255.0, 1.0)
          << "point " << px << " channel " << c;
    ++px;
  }
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

// A few positions (z, in eye space) with normals pointing in varied directions.
std::vector<std::vector<double>> sample_points() {
  std::vector<std::vector<double>> pts;
  for (int i = 0; i < 24; ++i) {
    const double a = i * 0.7, b = i * 0.31;
    pts.push_back({-5.0 + i * 0.5, std::sin(a) * std::cos(b), std::cos(a) * std::cos(b),
                   0.3 + std::sin(b)});
  }
  return pts;
}

TEST_F(Lighting, Directional) {
  RefLight l;
  l.pos[0] = 0.3, l.pos[1] = 0.5, l.pos[2] = 1.0;
  l.amb[0] = 0.1, l.amb[1] = 0.05;
  l.dif[2] = 0.6;
  RefMaterial m;
  m.spec[0] = 0.7, m.spec[1] = 0.5, m.spec[2] = 0.3;
  m.shin = 12;
  m.emi[1] = 0.05;
  expect_lit(this, {l}, m, RefModel{}, sample_points());
}

TEST_F(Lighting, PositionalAttenuatedLocalViewer) {
  RefLight l;
  l.pos[0] = 20, l.pos[1] = 10, l.pos[2] = 30, l.pos[3] = 1;
  l.k[0] = 0.5, l.k[1] = 0.02, l.k[2] = 0.001;
  RefMaterial m;
  m.spec[0] = m.spec[1] = m.spec[2] = 0.8;
  m.shin = 30;
  RefModel model;
  model.local_viewer = true;
  expect_lit(this, {l}, m, model, sample_points());
}

TEST_F(Lighting, SpotSeparateSpecular) {
  RefLight l;
  l.pos[0] = 16, l.pos[1] = 4, l.pos[2] = 20, l.pos[3] = 1;
  l.spot_dir[0] = 0, l.spot_dir[1] = 0.2, l.spot_dir[2] = -1;
  l.cutoff = 35, l.spot_exp = 6;
  RefMaterial m;
  m.dif[0] = 0.9, m.dif[1] = 0.4, m.dif[2] = 0.2, m.dif[3] = 0.6;
  m.spec[0] = m.spec[1] = m.spec[2] = 1.0;
  m.shin = 5;
  RefModel model;
  model.separate = true;
  model.amb[0] = 0.05;
  expect_lit(this, {l}, m, model, sample_points());
}

TEST_F(Lighting, EightLights) {
  std::vector<RefLight> lights(8);
  for (int i = 0; i < 8; ++i) {
    RefLight& l = lights[i];
    const double a = i * 0.785;
    l.pos[0] = 16 + 12 * std::cos(a), l.pos[1] = 16 + 12 * std::sin(a), l.pos[2] = 10;
    l.pos[3] = i % 2 == 0 ? 1 : 0;
    for (int c = 0; c < 3; ++c) {
      l.dif[c] = 0.15 + 0.1 * ((i + c) % 3);
      l.spec[c] = 0.1 * ((i * c) % 4);
      l.amb[c] = 0.02 * c;
    }
    l.k[1] = i % 2 == 0 ? 0.01 : 0.0;
  }
  RefMaterial m;
  m.spec[0] = m.spec[1] = m.spec[2] = 0.5;
  m.shin = 20;
  expect_lit(this, lights, m, RefModel{}, sample_points());
}

// GL 2.1 §2.14.1: with two-sided lighting a back-facing polygon takes the colour computed
// with the back material and -n; without it, the front colour.
TEST_F(Lighting, TwoSided) {
  RefLight l;
  l.pos[0] = 0.2, l.pos[1] = -0.3, l.pos[2] = -1; // lights the back of +z normals
  RefMaterial front, back;
  front.dif[0] = 1, front.dif[1] = 0, front.dif[2] = 0;
  back.dif[0] = 0, back.dif[1] = 0.9, back.dif[2] = 0.5;
  back.amb[2] = 0.6;
  back.spec[1] = 0.4, back.shin = 3;
  glEnable(GL_LIGHTING);
  set_light(0, l);
  set_material(GL_FRONT, front);
  set_material(GL_BACK, back);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glNormal3f(0, 0, 1);
  glBegin(GL_TRIANGLES); // clockwise: back facing
  glVertex2f(0, 0);
  glVertex2f(0, 16);
  glVertex2f(16, 0);
  glEnd();
  const double v[3] = {0, 0, 0}, n[3] = {0, 0, -1}, nf[3] = {0, 0, 1};
  const std::vector<double> want = reference({l}, back, RefModel{}, v, n);
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(channel(4, 4, c), want[c] * 255.0, 1.0) << c;
  // Without two-sided lighting the same triangle shows the front colour.
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glVertex2f(0, 16);
  glVertex2f(16, 0);
  glEnd();
  const std::vector<double> want_front = reference({l}, front, RefModel{}, v, nf);
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(channel(4, 4, c), want_front[c] * 255.0, 1.0) << c;
}

// §2.11.3: under a uniformly scaled model-view, RESCALE_NORMAL and NORMALIZE both restore
// unit normals; with neither, the shrunken normal darkens the diffuse term.
TEST_F(Lighting, RescaleAndNormalize) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, std::vector<GLfloat>{0, 0, 0, 1}.data());
  glScalef(4, 4, 4); // normals shrink by 4
  const auto lit_red = [&](int x) {
    glNormal3f(0, 0, 1);
    glBegin(GL_POINTS);
    glVertex2f(x / 4.0f + 0.125f, 0.125f);
    glEnd();
    return channel(x, 0, 0);
  };
  const int plain = lit_red(0);
  glEnable(GL_RESCALE_NORMAL);
  const int rescaled = lit_red(1);
  glDisable(GL_RESCALE_NORMAL);
  glEnable(GL_NORMALIZE);
  const int normalized = lit_red(2);
  EXPECT_EQ(plain, 51);       // 0.8 * 0.25
  EXPECT_EQ(rescaled, 204);   // 0.8
  EXPECT_EQ(normalized, 204);
}

// §2.14.2: Material between Begin and End applies from the next vertex on.
TEST_F(Lighting, MaterialInsideBeginEnd) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, std::vector<GLfloat>{0, 0, 0, 1}.data());
  const GLfloat red[4] = {1, 0, 0, 1}, blue[4] = {0, 0, 1, 1};
  glNormal3f(0, 0, 1);
  glBegin(GL_POINTS);
  glVertex2f(0.5f, 0.5f);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
  glVertex2f(1.5f, 0.5f);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, blue);
  glVertex2f(2.5f, 0.5f);
  glEnd();
  EXPECT_EQ(pixel(0, 0), 0xffccccccu);
  EXPECT_EQ(pixel(1, 0), 0xff0000ffu);
  EXPECT_EQ(pixel(2, 0), 0xffff0000u);
  // The last material stays for later primitives.
  glBegin(GL_POINTS);
  glVertex2f(3.5f, 0.5f);
  glEnd();
  EXPECT_EQ(pixel(3, 0), 0xffff0000u);
}

// §2.14.2 with §2.14.1: per-vertex back materials reach the back colour of a back-facing
// polygon under two-sided lighting.
TEST_F(Lighting, BackMaterialInsideBeginEndTwoSided) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat behind[4] = {0, 0, -1, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, behind); // lights -n of +z normals
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, std::vector<GLfloat>{0, 0, 0, 1}.data());
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  const GLfloat green[4] = {0, 1, 0, 1}, red[4] = {1, 0, 0, 1};
  glNormal3f(0, 0, 1);
  glBegin(GL_TRIANGLES); // clockwise: back facing
  glMaterialfv(GL_BACK, GL_DIFFUSE, green);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
  glVertex2f(0, 0);
  glVertex2f(0, 16);
  glVertex2f(16, 0);
  glEnd();
  EXPECT_EQ(pixel(4, 4), 0xff00ff00u);
  GLfloat v[4];
  glGetMaterialfv(GL_BACK, GL_DIFFUSE, v);
  EXPECT_EQ(v[1], 1.0f);
}

// §2.14.1 eq. 2.5 for a directional light: the spot term uses -VPpli for every vertex.
TEST_F(Lighting, DirectionalSpot) {
  RefLight l;
  l.spot_dir[1] = 0.6;
  l.cutoff = 45, l.spot_exp = 2;
  expect_lit(this, {l}, RefMaterial{}, RefModel{}, sample_points());
}

// §2.14.3: with COLOR_MATERIAL the vertex colour is the tracked material property.
TEST_F(Lighting, ColorMaterialPerVertex) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, std::vector<GLfloat>{0, 0, 0, 1}.data());
  glNormal3f(0, 0, 1);
  glBegin(GL_POINTS);
  glColor4f(0, 1, 0, 0.5f);
  glVertex2f(0.5f, 0.5f);
  glColor4f(1, 0, 1, 1);
  glVertex2f(1.5f, 0.5f);
  glEnd();
  EXPECT_EQ(pixel(0, 0), 0x8000ff00u); // alpha from the diffuse colour
  EXPECT_EQ(pixel(1, 0), 0xffff00ffu);
}

} // namespace

namespace {

// ---- secondary colour and colour sum (GL 1.4; GL 2.1 §2.7, §2.8, §3.9) ----

class ColorSum : public GLTest {
protected:
  void SetUp() override {
    GLTest::SetUp();
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, kW, 0, kH, -1, 1);
    glMatrixMode(GL_MODELVIEW);
  }
};

TEST_F(ColorSum, StateAndErrors) {
  GLfloat v[4];
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, v);
  EXPECT_EQ(v[0], 0.0f);
  EXPECT_EQ(v[3], 1.0f);
  glSecondaryColor3ub(255, 0, 51);
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, v);
  EXPECT_EQ(v[0], 1.0f);
  EXPECT_FLOAT_EQ(v[2], 0.2f);
  EXPECT_EQ(v[3], 1.0f);
  glSecondaryColor3s(32767, -32768, 0); // signed: [-1, 1]
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, v);
  EXPECT_EQ(v[0], 1.0f);
  EXPECT_EQ(v[1], -1.0f);
  // Legal between Begin and End, like every current-attribute command.
  glBegin(GL_POINTS);
  glSecondaryColor3f(0.25f, 0.5f, 0.75f);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, v);
  EXPECT_EQ(v[1], 0.5f);

  EXPECT_EQ(glIsEnabled(GL_COLOR_SUM), GL_FALSE);
  glEnable(GL_COLOR_SUM);
  EXPECT_EQ(glIsEnabled(GL_COLOR_SUM), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_SECONDARY_COLOR_ARRAY), GL_FALSE);

  GLubyte data[3] = {};
  glSecondaryColorPointer(4, GL_UNSIGNED_BYTE, 0, data);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, -1, data);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  glSecondaryColorPointer(3, GL_BOOL, 0, data);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glBegin(GL_POINTS);
  glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 0, data);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glSecondaryColorPointer(3, GL_SHORT, 12, data);
  GLint i = 0;
  glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_TYPE, &i);
  EXPECT_EQ(i, GL_SHORT);
  glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_STRIDE, &i);
  EXPECT_EQ(i, 12);
  glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_SIZE, &i);
  EXPECT_EQ(i, 3);
  void* p = nullptr;
  glGetPointerv(GL_SECONDARY_COLOR_ARRAY_POINTER, &p);
  EXPECT_EQ(p, static_cast<void*>(data));
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  EXPECT_EQ(glIsEnabled(GL_SECONDARY_COLOR_ARRAY), GL_TRUE);
  // §2.8: InterleavedArrays disables the secondary colour array.
  const GLfloat inter[3] = {0, 0, 0};
  glInterleavedArrays(GL_V3F, 0, inter);
  EXPECT_EQ(glIsEnabled(GL_SECONDARY_COLOR_ARRAY), GL_FALSE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// §3.9: the RGB of the secondary colour is added to the primary colour and the sum clamped;
// alpha comes from the primary colour alone.
TEST_F(ColorSum, AddsSecondaryWhenEnabled) {
  glColor4f(0.5f, 0.25f, 0.0f, 0.5f);
  glSecondaryColor3f(0.75f, 0.5f, 0.25f);
  glBegin(GL_POINTS);
  glVertex2f(0.5f, 0.5f);
  glEnd();
  EXPECT_EQ(pixel(0, 0), 0x80004080u); // COLOR_SUM off: primary only
  glEnable(GL_COLOR_SUM);
  glBegin(GL_POINTS);
  glVertex2f(1.5f, 0.5f);
  glEnd();
  EXPECT_EQ(pixel(1, 0), 0x8040bfffu);
  // Smooth shading interpolates both colours; the sum is clamped per fragment.
  glBegin(GL_LINES);
  glSecondaryColor3f(0.0f, 0.0f, 0.0f);
  glVertex2f(2.0f, 4.5f);
  glSecondaryColor3f(1.0f, 1.0f, 1.0f);
  glVertex2f(30.0f, 4.5f);
  glEnd();
  EXPECT_NEAR(buf_[(4 * kW + 2) * 4 + 2], 0, 6); // blue starts at 0
  EXPECT_EQ(buf_[(4 * kW + 28) * 4 + 0], 255); // red saturates
}

TEST_F(ColorSum, FromArrays) {
  const GLfloat pos[6] = {0.5f, 0.5f, 1.5f, 0.5f, 2.5f, 0.5f};
  const GLubyte sec[9] = {255, 0, 0, 0, 255, 0, 0, 0, 255};
  glVertexPointer(2, GL_FLOAT, 0, pos);
  glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 0, sec);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glEnable(GL_COLOR_SUM);
  glColor4f(0, 0, 0, 1);
  glDrawArrays(GL_POINTS, 0, 3);
  EXPECT_EQ(pixel(0, 0), 0xff0000ffu);
  EXPECT_EQ(pixel(1, 0), 0xff00ff00u);
  EXPECT_EQ(pixel(2, 0), 0xffff0000u);
  // ArrayElement also sets the current secondary colour.
  glBegin(GL_POINTS);
  glArrayElement(1);
  glEnd();
  GLfloat v[4];
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, v);
  EXPECT_EQ(v[1], 1.0f);
}

// With lighting on the colour sum applies whatever COLOR_SUM says (§3.9), and the current
// secondary colour is replaced by the lit one (zero with SINGLE_COLOR).
TEST_F(ColorSum, LightingIgnoresCurrentSecondary) {
  glEnable(GL_LIGHTING);
  glEnable(GL_COLOR_SUM);
  glSecondaryColor3f(1, 1, 1);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, std::vector<GLfloat>{0, 0, 0, 1}.data());
  glBegin(GL_POINTS);
  glVertex2f(0.5f, 0.5f);
  glEnd();
  EXPECT_EQ(pixel(0, 0), 0xff000000u);
}

} // namespace
