// GL_FOG_HINT (GL 2.1 §5.6) and where fog is evaluated (§3.10): FASTEST computes the fog
// factor f per vertex and interpolates it, NICEST and DONT_CARE compute f per fragment from the
// interpolated fog coordinate. The pixels are checked against double-precision references of
// both, with perspective-correct interpolation (§3.5.1 eq 3.9). Also the hint's queries and
// errors, display lists, the attribute stack, the raster distance and feedback.
#include <GL/gl.h>
#include <GL/glext.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "api_fixture.h"

namespace {

GLint get_int(GLenum pname) {
  GLint v = -1;
  glGetIntegerv(pname, &v);
  return v;
}

// One vertex of the test triangle: normalized device x, y, clip w and fog coordinate.
struct Vtx {
  double x, y, w, c;
};
const std::array<Vtx, 3> kTri = {
    {{-0.9, -0.9, 1.0, 0.0}, {0.9, -0.8, 2.5, 1.5}, {-0.7, 0.9, 4.0, 4.0}}};

// The fixture's buffer size (GLTest::kW x GLTest::kH).
constexpr int kSize = 32;

// Identity matrices and a full-buffer viewport: clip coordinates go straight to the
// rasterizer, window x = (x_ndc + 1) * 16.
void identity_setup() {
  glViewport(0, 0, kSize, kSize);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
}

// Fog from the fog coordinate, fog colour blue, so that with a white fragment R = G = f.
void fog_setup(GLenum mode, float density) {
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, mode);
  glFogf(GL_FOG_DENSITY, density);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  const GLfloat blue[4] = {0.0f, 0.0f, 1.0f, 1.0f};
  glFogfv(GL_FOG_COLOR, blue);
}

// `scale` enlarges the triangle about the origin in normalized device coordinates; above about
// 1.1 it crosses the clip volume and is clipped (§2.12).
void draw_triangle(double scale = 1.0) {
  glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
  glBegin(GL_TRIANGLES);
  for (const Vtx& v : kTri) {
    glFogCoordf(static_cast<float>(v.c));
    glVertex4f(static_cast<float>(scale * v.x * v.w), static_cast<float>(scale * v.y * v.w), 0.0f,
               static_cast<float>(v.w));
  }
  glEnd();
}

double fog_eq(GLenum mode, double d, double s, double e, double c) {
  double f = 1.0;
  if (mode == GL_EXP) f = std::exp(-d * c);
  if (mode == GL_EXP2) f = std::exp(-(d * c) * (d * c));
  if (mode == GL_LINEAR) f = (e - c) / (e - s);
  return f < 0.0 ? 0.0 : (f > 1.0 ? 1.0 : f);
}

// Screen-space barycentrics of the pixel centre (px + 1/2, py + 1/2); false unless every one
// is at least `margin` (an interior pixel, away from edge ownership questions).
bool barycentric(int px, int py, double margin, double scale, double b[3]) {
  double wx[3], wy[3];
  for (int i = 0; i < 3; ++i) {
    wx[i] = (scale * kTri[i].x + 1.0) * 0.5 * kSize;
    wy[i] = (scale * kTri[i].y + 1.0) * 0.5 * kSize;
  }
  const double x = px + 0.5, y = py + 0.5;
  const double area = (wx[1] - wx[0]) * (wy[2] - wy[0]) - (wx[2] - wx[0]) * (wy[1] - wy[0]);
  b[0] = ((wx[1] - x) * (wy[2] - y) - (wx[2] - x) * (wy[1] - y)) / area;
  b[1] = ((wx[2] - x) * (wy[0] - y) - (wx[0] - x) * (wy[2] - y)) / area;
  b[2] = 1.0 - b[0] - b[1];
  return b[0] >= margin && b[1] >= margin && b[2] >= margin;
}

// Perspective-correct interpolation of per-vertex values (§3.5.1 eq 3.9).
double interp(const double b[3], const double v[3]) {
  double num = 0.0, den = 0.0;
  for (int i = 0; i < 3; ++i) {
    num += b[i] * v[i] / kTri[i].w;
    den += b[i] / kTri[i].w;
  }
  return num / den;
}

struct Refs {
  double per_vertex, per_fragment; // f
};

Refs references(GLenum mode, double d, double s, double e, const double b[3]) {
  double f[3], c[3];
  for (int i = 0; i < 3; ++i) {
    c[i] = kTri[i].c;
    f[i] = fog_eq(mode, d, s, e, c[i]);
  }
  return {interp(b, f), fog_eq(mode, d, s, e, interp(b, c))};
}

// 8-bit tolerance: 1/255 plus a little for float arithmetic.
constexpr double kTol = 1.05;

class FogHintTest : public GLTest {
protected:
  static_assert(kW == kSize && kH == kSize);
  // Checks the interior pixels of the drawn triangle against the per-vertex (FASTEST) or
  // per-fragment reference; returns the number of pixels checked.
  int check_pixels(GLenum mode, double d, double s, double e, bool per_vertex, double scale = 1.0) {
    int checked = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        double b[3];
        if (!barycentric(x, y, 0.02, scale, b)) continue;
        const Refs r = references(mode, d, s, e, b);
        const double want = 255.0 * (per_vertex ? r.per_vertex : r.per_fragment);
        const uint32_t px = pixel(x, y);
        EXPECT_NEAR(static_cast<double>(px & 0xff), want, kTol) << "R at " << x << "," << y;
        EXPECT_NEAR(static_cast<double>((px >> 8) & 0xff), want, kTol) << "G at " << x << "," << y;
        EXPECT_EQ((px >> 16) & 0xff, 255u) << "B at " << x << "," << y;
        ++checked;
      }
    return checked;
  }
};

TEST_F(FogHintTest, QueryRoundTripAndErrors) {
  EXPECT_EQ(get_int(GL_FOG_HINT), GL_DONT_CARE);
  for (GLenum m : {GL_FASTEST, GL_NICEST, GL_DONT_CARE, GL_FASTEST}) {
    glHint(GL_FOG_HINT, m);
    EXPECT_EQ(get_int(GL_FOG_HINT), static_cast<GLint>(m));
    GLfloat f = 0.0f;
    glGetFloatv(GL_FOG_HINT, &f);
    EXPECT_EQ(f, static_cast<GLfloat>(m));
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // §5.6: a mode other than FASTEST, NICEST, DONT_CARE, or an unknown target, is INVALID_ENUM
  // and changes nothing.
  glHint(GL_FOG_HINT, GL_LINEAR);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glHint(GL_FOG, GL_NICEST);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_FOG_HINT), GL_FASTEST);
  // §2.6.3: illegal between Begin and End.
  glBegin(GL_POINTS);
  glHint(GL_FOG_HINT, GL_NICEST);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_FOG_HINT), GL_FASTEST);
}

TEST_F(FogHintTest, AttribStackAndDisplayList) {
  glHint(GL_FOG_HINT, GL_NICEST);
  glPushAttrib(GL_HINT_BIT);
  glHint(GL_FOG_HINT, GL_FASTEST);
  glPopAttrib();
  EXPECT_EQ(get_int(GL_FOG_HINT), GL_NICEST);
  // Other groups leave the hint alone.
  glPushAttrib(GL_FOG_BIT);
  glHint(GL_FOG_HINT, GL_FASTEST);
  glPopAttrib();
  EXPECT_EQ(get_int(GL_FOG_HINT), GL_FASTEST);
  // §5.4: Hint is compiled into display lists, not executed under COMPILE.
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glHint(GL_FOG_HINT, GL_DONT_CARE);
  glEndList();
  EXPECT_EQ(get_int(GL_FOG_HINT), GL_FASTEST);
  glCallList(list);
  EXPECT_EQ(get_int(GL_FOG_HINT), GL_DONT_CARE);
  glDeleteLists(list, 1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// EXP and EXP2 under FASTEST: the interpolation of the per-vertex factors; under NICEST and
// DONT_CARE: the factor of the interpolated coordinate.
TEST_F(FogHintTest, ExpAndExp2FollowTheHint) {
  struct Case {
    GLenum mode;
    float density;
  };
  for (const Case& k : {Case{GL_EXP, 0.8f}, Case{GL_EXP2, 0.6f}})
    for (GLenum hint : {GL_FASTEST, GL_NICEST, GL_DONT_CARE}) {
      SCOPED_TRACE(testing::Message() << "mode " << k.mode << " hint " << hint);
      identity_setup();
      fog_setup(k.mode, k.density);
      glHint(GL_FOG_HINT, hint);
      draw_triangle();
      EXPECT_GT(check_pixels(k.mode, k.density, 0.0, 1.0, hint == GL_FASTEST), 100);
    }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// A clipped triangle (§2.12): the vertices clipping makes carry factors interpolated from the
// original vertices, so the pixels are still the interpolation of the original per-vertex
// factors.
TEST_F(FogHintTest, ClippedTrianglePerVertex) {
  for (GLenum mode : {GL_EXP, GL_EXP2}) {
    SCOPED_TRACE(testing::Message() << "mode " << mode);
    identity_setup();
    fog_setup(mode, 0.5f);
    glHint(GL_FOG_HINT, GL_FASTEST);
    draw_triangle(1.6);
    EXPECT_GT(check_pixels(mode, 0.5, 0.0, 1.0, true, 1.6), 300);
  }
}

// Lines (§3.4.2) and points interpolate the per-vertex factors too: a horizontal line along
// the centres of pixel row 16 with coordinates 0 and 5, then a point with coordinate 3.
TEST_F(FogHintTest, LinesAndPointsPerVertex) {
  identity_setup();
  fog_setup(GL_EXP, 0.6f);
  glHint(GL_FOG_HINT, GL_FASTEST);
  const double x0 = 1.6, x1 = 30.4; // window x of the ends
  glColor3f(1, 1, 1);
  glBegin(GL_LINES);
  glFogCoordf(0.0f);
  glVertex2d(x0 / 16.0 - 1.0, 16.5 / 16.0 - 1.0);
  glFogCoordf(5.0f);
  glVertex2d(x1 / 16.0 - 1.0, 16.5 / 16.0 - 1.0);
  glEnd();
  const double f0 = 1.0, f1 = std::exp(-0.6 * 5.0);
  int checked = 0;
  for (int x = 0; x < kW; ++x) {
    const double t = (x + 0.5 - x0) / (x1 - x0);
    if (t < 0.05 || t > 0.95) continue;
    EXPECT_NEAR(static_cast<double>(pixel(x, 16) & 0xff), 255.0 * (f0 + (f1 - f0) * t), kTol) << x;
    ++checked;
  }
  EXPECT_GT(checked, 20);
  glBegin(GL_POINTS);
  glFogCoordf(3.0f);
  glVertex2d(4.5 / 16.0 - 1.0, 4.5 / 16.0 - 1.0);
  glEnd();
  EXPECT_NEAR(static_cast<double>(pixel(4, 4) & 0xff), 255.0 * std::exp(-0.6 * 3.0), kTol);
}

// With a strongly varying coordinate the two evaluations differ visibly, and switching the
// hint back and forth (directly, through a display list, through the attribute stack) switches
// the result.
TEST_F(FogHintTest, FastestAndNicestDiffer) {
  const auto render = [&](const auto& set_hint) {
    identity_setup();
    fog_setup(GL_EXP2, 0.6f);
    set_hint();
    draw_triangle();
    return buf_;
  };
  const std::vector<uint8_t> nicest = render([] { glHint(GL_FOG_HINT, GL_NICEST); });
  const std::vector<uint8_t> fastest = render([] { glHint(GL_FOG_HINT, GL_FASTEST); });
  int differ = 0;
  for (size_t i = 0; i < nicest.size(); i += 4)
    if (std::abs(int(nicest[i]) - int(fastest[i])) > 10) ++differ;
  EXPECT_GT(differ, 50);

  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glHint(GL_FOG_HINT, GL_FASTEST);
  glEndList();
  glHint(GL_FOG_HINT, GL_NICEST);
  EXPECT_EQ(render([&] { glCallList(list); }), fastest);
  glDeleteLists(list, 1);
  glHint(GL_FOG_HINT, GL_NICEST);
  EXPECT_EQ(render([] {}), nicest);
  // A list holds vertices, not fog factors: the hint in force when it is called decides.
  const GLuint geometry = glGenLists(1);
  glNewList(geometry, GL_COMPILE);
  draw_triangle();
  glEndList();
  for (GLenum hint : {GL_FASTEST, GL_NICEST}) {
    identity_setup();
    fog_setup(GL_EXP2, 0.6f);
    glHint(GL_FOG_HINT, hint);
    glCallList(geometry);
    EXPECT_EQ(buf_, hint == GL_FASTEST ? fastest : nicest);
  }
  glDeleteLists(geometry, 1);
  EXPECT_EQ(render([] {
              glPushAttrib(GL_HINT_BIT);
              glHint(GL_FOG_HINT, GL_FASTEST);
            }),
            fastest);
  glPopAttrib();
  EXPECT_EQ(render([] {}), nicest);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// LINEAR with every vertex coordinate inside [start, end] is linear in the coordinate: both
// hints give the same pixels.
TEST_F(FogHintTest, LinearInsideTheRangeIsTheSame) {
  for (GLenum hint : {GL_FASTEST, GL_NICEST}) {
    identity_setup();
    fog_setup(GL_LINEAR, 1.0f);
    glFogf(GL_FOG_START, -0.5f);
    glFogf(GL_FOG_END, 6.0f);
    glHint(GL_FOG_HINT, hint);
    draw_triangle();
    EXPECT_GT(check_pixels(GL_LINEAR, 1.0, -0.5, 6.0, true), 100);
    EXPECT_GT(check_pixels(GL_LINEAR, 1.0, -0.5, 6.0, false), 100);
  }
}

// FRAGMENT_DEPTH under FASTEST: per vertex from |z_e|, over a quad receding in z under a
// perspective projection, against the per-vertex reference along the quad's centre row.
TEST_F(FogHintTest, FragmentDepthPerVertex) {
  identity_setup();
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 1, 20);
  glMatrixMode(GL_MODELVIEW);
  fog_setup(GL_EXP, 0.3f);
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  glHint(GL_FOG_HINT, GL_FASTEST);
  // A horizontal strip from (x=-1, z=-1.5) to (x=8, z=-12): both vertices of an edge share z.
  glColor3f(1, 1, 1);
  glBegin(GL_QUADS);
  glVertex3f(-1.0f, -1.0f, -1.5f);
  glVertex3f(8.0f, -1.0f, -12.0f);
  glVertex3f(8.0f, 1.0f, -12.0f);
  glVertex3f(-1.0f, 1.0f, -1.5f);
  glEnd();
  // Window x of a point (x, z): (x / -z + 1) * 16. Along the pixel row 16 the eye position is
  // a linear blend t of the two ends; perspective-correct interpolation of f in t.
  const double f0 = std::exp(-0.3 * 1.5), f1 = std::exp(-0.3 * 12.0);
  int checked = 0;
  for (int x = 2; x < 30; ++x) {
    const double xn = (x + 0.5) / 16.0 - 1.0; // x_e / -z_e
    // x_e = -1 + 9t, -z_e = 1.5 + 10.5t: solve (-1 + 9t) = xn (1.5 + 10.5t).
    const double t = (1.0 + 1.5 * xn) / (9.0 - 10.5 * xn);
    if (t < 0.02 || t > 0.98) continue;
    const double want = 255.0 * (f0 * (1.0 - t) + f1 * t);
    EXPECT_NEAR(static_cast<double>(pixel(x, 16) & 0xff), want, kTol) << x;
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

// §2.13: the raster distance is the fog coordinate (FOG_COORD source) or the eye distance,
// under either hint; WindowPos gives the fog coordinate or 0.
TEST_F(FogHintTest, RasterDistance) {
  for (GLenum hint : {GL_FASTEST, GL_NICEST}) {
    glHint(GL_FOG_HINT, hint);
    glEnable(GL_FOG);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glFogCoordf(3.5f);
    GLfloat d = -1.0f;
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glRasterPos3f(0.3f, 0.4f, 0.0f);
    glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
    EXPECT_EQ(d, 3.5f);
    glWindowPos2f(4.0f, 5.0f);
    glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
    EXPECT_EQ(d, 3.5f);
    glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
    glRasterPos3f(0.3f, 0.4f, 0.0f);
    glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
    EXPECT_NEAR(d, 0.5f, 1e-6f);
    glWindowPos2f(4.0f, 5.0f);
    glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
    EXPECT_EQ(d, 0.0f);
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// §5.3: feedback returns the vertex colours before fog, whatever the hint.
TEST_F(FogHintTest, FeedbackIgnoresTheHint) {
  const auto feedback = [&](GLenum hint) {
    identity_setup();
    fog_setup(GL_EXP, 0.8f);
    glHint(GL_FOG_HINT, hint);
    std::vector<GLfloat> buf(64, -1.0f);
    glFeedbackBuffer(static_cast<GLsizei>(buf.size()), GL_3D_COLOR, buf.data());
    glRenderMode(GL_FEEDBACK);
    draw_triangle();
    const GLint n = glRenderMode(GL_RENDER);
    buf.resize(n > 0 ? static_cast<size_t>(n) : 0);
    return buf;
  };
  const std::vector<GLfloat> fast = feedback(GL_FASTEST), nice = feedback(GL_NICEST);
  ASSERT_EQ(fast.size(), 2u + 3u * 7u); // POLYGON_TOKEN, 3, then x y z r g b a per vertex
  EXPECT_EQ(fast, nice);
  for (int v = 0; v < 3; ++v)
    for (int c = 0; c < 4; ++c)
      EXPECT_EQ(fast[2 + 7 * v + 3 + c], 1.0f);
}

} // namespace
