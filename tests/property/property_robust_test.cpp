// Robustness through the GL API: NaN and infinity in vertices, colours, normals, texture
// coordinates and matrices; degenerate primitives; 1x1 and 16384x16384 viewports on a small
// buffer; depth ordering under glFrustum with far/near up to 1e9. Nothing may crash, hang or
// write outside the viewport or the colour buffer (guard bytes on both sides).
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "property_gl.h"
#include "raster/raster.h"

namespace pineda {
namespace {

using test::enable_counting;
using test::GuardedContext;

float nasty(std::mt19937& rng) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  const float table[] = {std::numeric_limits<float>::quiet_NaN(), inf, -inf, 1e30f, -1e30f,
                         std::numeric_limits<float>::max(), std::numeric_limits<float>::denorm_min(),
                         0.0f, -0.0f, 1e-30f};
  if (rng() % 3 == 0) return table[rng() % 10];
  std::uniform_real_distribution<float> u(-2.0f, 2.0f);
  return u(rng);
}

// True when no pixel outside [x0,x1)x[y0,y1) was written (the buffer starts all zero).
bool only_inside(const GuardedContext& gc, int x0, int y0, int x1, int y1) {
  for (int y = 0; y < gc.height(); ++y)
    for (int x = 0; x < gc.width(); ++x) {
      if (x >= x0 && x < x1 && y >= y0 && y < y1) continue;
      const uint8_t* p = gc.px(x, y);
      if (p[0] | p[1] | p[2] | p[3]) return false;
    }
  return true;
}

std::string first_outside(const GuardedContext& gc, int x0, int y0, int x1, int y1) {
  for (int y = 0; y < gc.height(); ++y)
    for (int x = 0; x < gc.width(); ++x) {
      if (x >= x0 && x < x1 && y >= y0 && y < y1) continue;
      const uint8_t* p = gc.px(x, y);
      if (p[0] | p[1] | p[2] | p[3]) return std::to_string(x) + "," + std::to_string(y);
    }
  return "none";
}

TEST(PropertyRobust, NonFiniteInputStaysInsideViewportAndBuffer) {
  GuardedContext gc(40, 36);
  ASSERT_TRUE(gc.ok());
  std::mt19937 rng(5150);
  const GLenum modes[] = {GL_POINTS, GL_LINES, GL_LINE_LOOP, GL_TRIANGLES, GL_TRIANGLE_STRIP,
                          GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON};
  for (int iter = 0; iter < 20000; ++iter) {
    gc.clear_pixels();
    const int vx = static_cast<int>(rng() % 30), vy = static_cast<int>(rng() % 30);
    const int vw = 1 + static_cast<int>(rng() % 20), vh = 1 + static_cast<int>(rng() % 20);
    glViewport(vx, vy, vw, vh);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    if (rng() % 4 == 0) {
      GLfloat m[16];
      for (float& v : m) v = (rng() % 3 == 0) ? nasty(rng) : 0.0f;
      m[0] = m[5] = m[10] = m[15] = 1.0f;
      m[rng() % 16] = nasty(rng);
      glLoadMatrixf(m);
    } else if (rng() & 1) {
      glFrustum(-1, 1, -1, 1, std::fabs(nasty(rng)) + 1e-6, 1e9);
    }
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    if (rng() % 4 == 0) glRotatef(nasty(rng), nasty(rng), nasty(rng), nasty(rng));
    if (rng() % 4 == 0) glScalef(nasty(rng), nasty(rng), nasty(rng));
    const bool fill = rng() & 1;
    glPolygonMode(GL_FRONT_AND_BACK, fill ? GL_FILL : GL_LINE);
    glShadeModel((rng() & 1) ? GL_FLAT : GL_SMOOTH);
    if (rng() & 1) glEnable(GL_DEPTH_TEST);
    else glDisable(GL_DEPTH_TEST);
    if (rng() % 3 == 0) {
      const double eq[4] = {nasty(rng), nasty(rng), nasty(rng), nasty(rng)};
      glClipPlane(GL_CLIP_PLANE0, eq);
      glEnable(GL_CLIP_PLANE0);
    } else {
      glDisable(GL_CLIP_PLANE0);
    }
    std::ostringstream trace;
    const GLenum mode = modes[rng() % 9];
    glBegin(mode);
    const int n = 1 + static_cast<int>(rng() % 9);
    for (int i = 0; i < n; ++i) {
      glColor4f(nasty(rng), nasty(rng), nasty(rng), nasty(rng));
      glNormal3f(nasty(rng), nasty(rng), nasty(rng));
      glTexCoord4f(nasty(rng), nasty(rng), nasty(rng), nasty(rng));
      const float vx4[4] = {nasty(rng), nasty(rng), nasty(rng), (rng() & 1) ? 1.0f : nasty(rng)};
      glVertex4fv(vx4);
      trace << " (" << vx4[0] << "," << vx4[1] << "," << vx4[2] << "," << vx4[3] << ")";
    }
    glEnd();
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << "iteration " << iter;
    ASSERT_TRUE(gc.guards_intact()) << "iteration " << iter;
    // Filled polygons stay inside the viewport. A line clipped onto the viewport's edge may
    // leave one pixel beyond it: an end exactly on a diamond's corner, moved by GL 2.1
    // §3.4.1's perturbation, lies inside the outer pixel's diamond and the line exits it.
    const int m = (fill && mode >= GL_TRIANGLES) ? 0 : 1;
    ASSERT_TRUE(only_inside(gc, vx - m, vy - m, vx + vw + m, vy + vh + m))
        << "iteration " << iter << " mode " << mode << " viewport " << vx << "," << vy << " "
        << vw << "x" << vh << " vertices" << trace.str() << " first outside pixel "
        << first_outside(gc, vx - m, vy - m, vx + vw + m, vy + vh + m);
  }
}

TEST(PropertyRobust, DegeneratePrimitivesDrawNothingOrStayBounded) {
  GuardedContext gc(24, 24);
  ASSERT_TRUE(gc.ok());
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> u(-1.2f, 1.2f);
  enable_counting();
  for (int iter = 0; iter < 3000; ++iter) {
    gc.clear_pixels();
    const float x = u(rng), y = u(rng), x2 = u(rng), y2 = u(rng), t = u(rng);
    glBegin(GL_TRIANGLES);
    glVertex2f(x, y); // one point three times
    glVertex2f(x, y);
    glVertex2f(x, y);
    glVertex2f(x, y); // two repeated
    glVertex2f(x2, y2);
    glVertex2f(x2, y2);
    glEnd();
    glBegin(GL_QUADS); // a quad folded onto a line
    glVertex2f(x, y);
    glVertex2f(x2, y2);
    glVertex2f(x, y);
    glVertex2f(x2, y2);
    glEnd();
    // Zero-area polygons produce no fragments (GL 2.1 §3.5.1).
    ASSERT_TRUE(only_inside(gc, 0, 0, 0, 0)) << "iteration " << iter;
    // Collinear in object space but not exactly after rounding to 1/256 pixel: a sliver that
    // may cover a centre or two.
    glBegin(GL_TRIANGLES);
    glVertex2f(x, y);
    glVertex2f(x2, y2);
    glVertex2f(x + t * (x2 - x), y + t * (y2 - y));
    glEnd();
    glBegin(GL_LINES); // zero-length lines and a point-sized loop
    glVertex2f(x, y);
    glVertex2f(x, y);
    glEnd();
    glBegin(GL_LINE_LOOP);
    glVertex2f(x2, y2);
    glVertex2f(x2, y2);
    glVertex2f(x2, y2);
    glEnd();
    glBegin(GL_POINTS);
    glVertex2f(x, y);
    glVertex2f(x, y);
    glEnd();
    ASSERT_TRUE(gc.guards_intact());
    int hits = 0;
    for (int py = 0; py < 24; ++py)
      for (int px = 0; px < 24; ++px) hits += gc.px(px, py)[0];
    // At most the two points (same pixel), a pixel or two for each zero-length line and
    // the sliver's few centres.
    ASSERT_LE(hits, 10) << "iteration " << iter;
  }
  glDisable(GL_BLEND);
}

// A 1x1 viewport anywhere on the buffer touches only its pixel; a 16384x16384 viewport
// (GL_MAX_VIEWPORT_DIMS) placed so the buffer sees part of it maps NDC exactly, and the
// coverage of unclipped triangles equals the exact reference on the buffer.
TEST(PropertyRobust, TinyAndHugeViewports) {
  GuardedContext gc(32, 24);
  ASSERT_TRUE(gc.ok());
  GLint dims[2] = {};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, dims);
  ASSERT_EQ(dims[0], 16384);
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int iter = 0; iter < 2000; ++iter) {
    gc.clear_pixels();
    const int vx = static_cast<int>(rng() % 34) - 1, vy = static_cast<int>(rng() % 26) - 1;
    glViewport(vx, vy, 1, 1);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 6; ++i) glVertex2f(u(rng) * 3.0f, u(rng) * 3.0f);
    glEnd();
    ASSERT_TRUE(only_inside(gc, vx, vy, vx + 1, vy + 1)) << "iteration " << iter;
  }
  // Vertices on the 1/8192 NDC grid land on exact window coordinates in a 16384 viewport.
  const int ox = -8000, oy = -8100;
  for (int iter = 0; iter < 2000; ++iter) {
    gc.clear_pixels();
    glViewport(ox, oy, 100000, 100000); // clamped to 16384 (GL 2.1 §2.11.1)
    float ndc[3][2];
    int64_t fx[3], fy[3];
    for (int i = 0; i < 3; ++i) {
      const int kx = 8000 - 8192 + static_cast<int>(rng() % 48) - 8;
      const int ky = 8100 - 8192 + static_cast<int>(rng() % 40) - 8;
      const int sub = static_cast<int>(rng() % 64);
      ndc[i][0] = (kx + sub / 64.0f) / 8192.0f;
      ndc[i][1] = (ky + (63 - sub) / 64.0f) / 8192.0f;
      fx[i] = to_fixed(ox + (ndc[i][0] + 1.0f) * 8192.0f);
      fy[i] = to_fixed(oy + (ndc[i][1] + 1.0f) * 8192.0f);
    }
    glBegin(GL_TRIANGLES);
    for (auto& p : ndc) glVertex2f(p[0], p[1]);
    glEnd();
    const int64_t area = (fx[1] - fx[0]) * (fy[2] - fy[0]) - (fx[2] - fx[0]) * (fy[1] - fy[0]);
    for (int y = 0; y < gc.height(); ++y)
      for (int x = 0; x < gc.width(); ++x) {
        bool in = area != 0;
        const int64_t cx = 256 * x + 128, cy = 256 * y + 128;
        for (int e = 0; e < 3 && in; ++e) {
          int a = e, b = (e + 1) % 3;
          if (area < 0) std::swap(a, b);
          const int64_t dx = fx[b] - fx[a], dy = fy[b] - fy[a];
          const int64_t side = dx * (cy - fy[a]) - dy * (cx - fx[a]);
          in = side > 0 || (side == 0 && (dy < 0 || (dy == 0 && dx > 0)));
        }
        ASSERT_EQ(gc.px(x, y)[0] != 0, in) << "iteration " << iter << " pixel " << x << "," << y;
      }
  }
  ASSERT_TRUE(gc.guards_intact());
}

// GL 2.1 §2.11.1 with §4.1.6: layers at well-separated eye distances keep their order under
// the depth test with far/near from 10 to 1e9, drawn in random order.
TEST(PropertyDepthOrder, FrustumLayersKeepOrderUpToFarNearRatio1e9) {
  GuardedContext gc(16, 16, 24);
  ASSERT_TRUE(gc.ok());
  std::mt19937 rng(31337);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int iter = 0; iter < 5000; ++iter) {
    const double n = std::pow(10.0, -3.0 + 4.0 * u(rng));
    const double ratio = std::pow(10.0, 1.0 + 8.0 * u(rng));
    const double f = n * ratio;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-n, n, -n, n, n, f);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc((rng() & 1) ? GL_LESS : GL_LEQUAL);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // Layers at n/d spaced by at least 1e-3 of the window depth range: d = n / s, s in (0,1).
    std::vector<double> s;
    for (int i = 0, count = 2 + static_cast<int>(rng() % 4); i < count; ++i)
      s.push_back(0.002 + 0.99 * u(rng));
    std::sort(s.begin(), s.end());
    std::vector<double> sep = {s[0]};
    for (const double v : s)
      if (v - sep.back() > 1e-3) sep.push_back(v);
    s = sep;
    const int layers = static_cast<int>(s.size());
    std::vector<int> order;
    for (int i = 0; i < layers; ++i) order.push_back(i);
    std::shuffle(order.begin(), order.end(), rng);
    for (int k = 0; k < layers; ++k) {
      const int i = order[k];
      const double d = std::min(n / s[i], f * 0.999);
      glColor4ub(static_cast<GLubyte>(10 + i), 0, 0, 255);
      glBegin(GL_QUADS); // covers the whole view at distance d
      glVertex3d(-2 * d, -2 * d, -d);
      glVertex3d(2 * d, -2 * d, -d);
      glVertex3d(2 * d, 2 * d, -d);
      glVertex3d(-2 * d, 2 * d, -d);
      glEnd();
    }
    // The nearest layer has the largest s.
    const int want = 10 + (layers - 1);
    ASSERT_EQ(gc.px(8, 8)[0], want) << "iteration " << iter << " n " << n << " f " << f;
  }
  ASSERT_TRUE(gc.guards_intact());
}

} // namespace
} // namespace pineda

namespace pineda {
namespace {

// Regressions for the fuzzer's findings through the API (each was undefined behaviour that
// UBSan reported; the sanitizer build of these tests is what guards them).
TEST(PropertyRobust, FuzzRegressionPixelStoreNonFiniteAndHuge) {
  GuardedContext gc(4, 4);
  ASSERT_TRUE(gc.ok());
  glPixelStoref(GL_PACK_ROW_LENGTH, std::numeric_limits<float>::quiet_NaN());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  glPixelStoref(GL_PACK_SKIP_ROWS, 1e30f);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  GLint v = 0;
  glGetIntegerv(GL_PACK_SKIP_ROWS, &v);
  EXPECT_EQ(v, 2147483647);
  glPixelStoref(GL_PACK_SKIP_PIXELS, -std::numeric_limits<float>::infinity());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  glPixelStoref(GL_PACK_SKIP_PIXELS, 2.5f); // rounds to nearest (GL 2.1 §3.6.1)
  glGetIntegerv(GL_PACK_SKIP_PIXELS, &v);
  EXPECT_EQ(v, 3);
}

TEST(PropertyRobust, FuzzRegressionInterleavedArraysAtBufferOffsetZero) {
  GuardedContext gc(8, 8);
  ASSERT_TRUE(gc.ok());
  // GL_C4UB_V2F from offset 0 of a buffer: the colour at +0, the position at +4.
  struct Vtx {
    GLubyte c[4];
    GLfloat p[2];
  };
  const Vtx data[3] = {{{255, 0, 0, 255}, {-1, -1}}, {{255, 0, 0, 255}, {3, -1}},
                       {{255, 0, 0, 255}, {-1, 3}}};
  GLuint buf = 0;
  glGenBuffers(1, &buf);
  glBindBuffer(GL_ARRAY_BUFFER, buf);
  glBufferData(GL_ARRAY_BUFFER, sizeof data, data, GL_STATIC_DRAW);
  glInterleavedArrays(GL_C4UB_V2F, 0, nullptr);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  void* p = nullptr;
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(p), uintptr_t{4});
  EXPECT_EQ(gc.px(4, 4)[0], 255);
  glDeleteBuffers(1, &buf);
}

} // namespace
} // namespace pineda

namespace pineda {
namespace {

// Regression (fuzzer, UBSan: NaN converted to an unsigned depth value in the clear): NaN
// clear values and depth ranges clamp to 0 instead of reaching integer conversions.
TEST(PropertyRobust, FuzzRegressionNaNClearDepthAndDepthRange) {
  GuardedContext gc(8, 8, 24);
  ASSERT_TRUE(gc.ok());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  glClearDepth(nan);
  glClearColor(static_cast<float>(nan), 1.0f, static_cast<float>(nan), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  GLdouble v[4] = {-1, -1, -1, -1};
  glGetDoublev(GL_DEPTH_CLEAR_VALUE, v);
  EXPECT_EQ(v[0], 0.0);
  EXPECT_EQ(gc.px(3, 3)[0], 0);
  EXPECT_EQ(gc.px(3, 3)[1], 255);
  glDepthRange(nan, nan);
  glGetDoublev(GL_DEPTH_RANGE, v);
  EXPECT_EQ(v[0], 0.0);
  EXPECT_EQ(v[1], 0.0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glBegin(GL_TRIANGLES);
  glVertex2f(-1, -1);
  glVertex2f(3, -1);
  glVertex2f(-1, 3);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_TRUE(gc.guards_intact());
}

} // namespace
} // namespace pineda
