// Watertightness through the GL API (GL 2.1 §3.5.1 with §2.12 clipping): random planar meshes
// (jittered grids as triangles, strips, quads and fans) whose outer vertices lie far beyond
// every frustum plane, under random orthographic and perspective projections, with the near
// plane crossing the mesh and random user clip planes. Every fragment adds one to red.
//
// The covered region is convex (a plane intersected with half-spaces), so a pixel whose left
// and right (or lower and upper) neighbours are covered must be covered itself; a pixel hit
// twice or a hole between covered pixels is a crack between a clipped and an unclipped
// neighbour, or between two clipped ones.
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "property_gl.h"

namespace pineda {
namespace {

using test::enable_counting;
using test::GuardedContext;

struct P3 {
  double x, y, z;
};

// Grid coordinates along one axis: a dense middle part, then a few steps out to `far`.
std::vector<double> axis_ticks(std::mt19937& rng, double far) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> t = {-far, far};
  const int inner = 3 + static_cast<int>(rng() % 6);
  for (int i = 0; i < inner; ++i) t.push_back((u(rng) * 2.0 - 1.0) * 3.0);
  t.push_back(-20.0 - 100.0 * u(rng));
  t.push_back(20.0 + 100.0 * u(rng));
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

void vertex(const P3& p) { glVertex3d(p.x, p.y, p.z); }

// One random mesh case; returns the number of covered pixels.
int run_case(GuardedContext& gc, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  gc.clear_pixels();
  glDisable(GL_CLIP_PLANE0);
  glDisable(GL_CLIP_PLANE1);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const bool perspective = rng() & 1;
  if (perspective) {
    const double n = std::pow(10.0, -3.0 + 3.0 * u(rng));
    glFrustum(-n * (0.5 + u(rng)), n * (0.5 + u(rng)), -n * (0.5 + u(rng)), n * (0.5 + u(rng)),
              n, n * std::pow(10.0, 1.0 + 8.0 * u(rng)));
  } else {
    glOrtho(-1.5, 1.5, -1.5, 1.5, -2.0 - 3.0 * u(rng), 2.0 + 3.0 * u(rng));
  }
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  // The mesh plane: tilted so that the near and far planes cross it, in front of the eye
  // for perspective.
  if (perspective) glTranslated(0.0, 0.0, -0.5 - 4.0 * u(rng));
  glRotated(-80.0 + 160.0 * u(rng), u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);

  // Up to two user clip planes in eye space through points near the view axis.
  const int planes = static_cast<int>(rng() % 3);
  for (int i = 0; i < planes; ++i) {
    const double a = u(rng) * 6.283;
    const double eq[4] = {std::cos(a), std::sin(a), u(rng) - 0.5, (u(rng) - 0.5) * 0.5};
    glClipPlane(GL_CLIP_PLANE0 + i, eq);
    glEnable(GL_CLIP_PLANE0 + i);
  }

  const double far = std::pow(10.0, 2.0 + 18.0 * u(rng)); // up to 1e20 in object space
  const std::vector<double> xs = axis_ticks(rng, far), ys = axis_ticks(rng, far);
  const size_t nx = xs.size(), ny = ys.size();
  // Interior vertices jitter within the plane z = 0 (the mesh stays planar and convex).
  std::vector<P3> g(nx * ny);
  for (size_t j = 0; j < ny; ++j)
    for (size_t i = 0; i < nx; ++i) {
      double x = xs[i], y = ys[j];
      if (i > 0 && i + 1 < nx && j > 0 && j + 1 < ny && std::fabs(x) < 10 && std::fabs(y) < 10) {
        x += (u(rng) - 0.5) * 0.2 * std::min(xs[i + 1] - xs[i], xs[i] - xs[i - 1]);
        y += (u(rng) - 0.5) * 0.2 * std::min(ys[j + 1] - ys[j], ys[j] - ys[j - 1]);
      }
      g[j * nx + i] = {x, y, 0.0};
    }
  auto at = [&](size_t i, size_t j) -> const P3& { return g[j * nx + i]; };

  enable_counting();
  switch (rng() % 4) {
  case 0: // independent triangles, random diagonal and winding per cell
    glBegin(GL_TRIANGLES);
    for (size_t j = 0; j + 1 < ny; ++j)
      for (size_t i = 0; i + 1 < nx; ++i) {
        const P3 &a = at(i, j), &b = at(i + 1, j), &c = at(i + 1, j + 1), &d = at(i, j + 1);
        const bool diag = rng() & 1, flip = rng() & 1;
        const P3* t1[3] = {&a, &b, diag ? &c : &d};
        const P3* t2[3] = {diag ? &a : &b, &c, &d};
        for (const P3* const* t : {t1, t2}) {
          vertex(*t[0]);
          vertex(*t[flip ? 2 : 1]);
          vertex(*t[flip ? 1 : 2]);
        }
      }
    glEnd();
    break;
  case 1: // one triangle strip per row
    for (size_t j = 0; j + 1 < ny; ++j) {
      glBegin(GL_TRIANGLE_STRIP);
      for (size_t i = 0; i < nx; ++i) {
        vertex(at(i, j));
        vertex(at(i, j + 1));
      }
      glEnd();
    }
    break;
  case 2: // quads (split by Pineda along q0-q2) and quad strips, alternating rows
    for (size_t j = 0; j + 1 < ny; ++j) {
      if (j & 1) {
        glBegin(GL_QUAD_STRIP);
        for (size_t i = 0; i < nx; ++i) {
          vertex(at(i, j));
          vertex(at(i, j + 1));
        }
      } else {
        glBegin(GL_QUADS);
        for (size_t i = 0; i + 1 < nx; ++i) {
          vertex(at(i, j));
          vertex(at(i + 1, j));
          vertex(at(i + 1, j + 1));
          vertex(at(i, j + 1));
        }
      }
      glEnd();
    }
    break;
  default: { // a fan around an interior point over the grid's boundary ring
    const P3 centre = {(u(rng) - 0.5) * 2.0, (u(rng) - 0.5) * 2.0, 0.0};
    std::vector<P3> ring;
    for (size_t i = 0; i + 1 < nx; ++i) ring.push_back(at(i, 0));
    for (size_t j = 0; j + 1 < ny; ++j) ring.push_back(at(nx - 1, j));
    for (size_t i = nx - 1; i > 0; --i) ring.push_back(at(i, ny - 1));
    for (size_t j = ny - 1; j > 0; --j) ring.push_back(at(0, j));
    glBegin(GL_TRIANGLE_FAN);
    vertex(centre);
    for (const P3& p : ring) vertex(p);
    vertex(ring.front());
    glEnd();
    break;
  }
  }
  glDisable(GL_BLEND);

  EXPECT_TRUE(gc.guards_intact()) << "seed " << seed;
  const int w = gc.width(), h = gc.height();
  auto count = [&](int x, int y) { return static_cast<int>(gc.px(x, y)[0]); };
  int covered = 0, bad = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int c = count(x, y);
      covered += c > 0;
      if (c > 1 && ++bad <= 3) ADD_FAILURE() << "seed " << seed << " pixel " << x << "," << y
                                            << " hit " << c << " times";
      if (c != 0) continue;
      const bool lr = x > 0 && x + 1 < w && count(x - 1, y) && count(x + 1, y);
      const bool ud = y > 0 && y + 1 < h && count(x, y - 1) && count(x, y + 1);
      if ((lr || ud) && ++bad <= 3)
        ADD_FAILURE() << "seed " << seed << " hole at " << x << "," << y;
    }
  return covered;
}

TEST(PropertyWatertight, ClippedMeshesCoverEachPixelOnce) {
  GuardedContext gc(61, 47);
  ASSERT_TRUE(gc.ok());
  int nonempty = 0;
  constexpr int kCases = 5000;
  for (uint32_t seed = 1; seed <= kCases; ++seed) nonempty += run_case(gc, seed) > 0;
  // Most random cases leave something on screen (the tests are not vacuous).
  EXPECT_GT(nonempty, kCases / 3);
}

} // namespace
} // namespace pineda
