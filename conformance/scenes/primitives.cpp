// The ten glBegin modes (GL 2.1 §2.6.1), each drawn twice: smooth-shaded in the left panel and
// flat-shaded in the right one, from the same vertices. The right panel checks the provoking
// vertex of every primitive type (GL 2.1 §2.14.7, Table 2.12); the left one colour
// interpolation along lines (§3.4.1) and across polygons (§3.5.1).
#include "scene_util.h"

#include <cmath>

using namespace scenes;

namespace {

// Draws `body` in the left half with GL_SMOOTH and in the right half with GL_FLAT. `body` gets
// the panel size and must be deterministic (it creates its own Rng).
template <typename Body> void smooth_and_flat(const Frame& frame, Body body) {
  clear_frame(0.0f, 0.0f, 0.0f);
  for (int half = 0; half < 2; ++half) {
    const Panel p = panel(frame, half, 2, 1);
    glShadeModel(half == 0 ? GL_SMOOTH : GL_FLAT);
    body(p);
  }
}

// A colour that is an affine function of the window position inside one polygon: every
// triangulation of a planar polygon then interpolates the same colours, which GL does not
// guarantee for polygons of more than three vertices otherwise (GL 2.1 §3.5.1).
struct AffineColor {
  float base[3], dx[3], dy[3];
  float cx, cy;
  void apply(float x, float y) const {
    float c[3];
    for (int i = 0; i < 3; ++i)
      c[i] = std::fmin(1.0f, std::fmax(0.0f, base[i] + dx[i] * (x - cx) + dy[i] * (y - cy)));
    glColor3f(c[0], c[1], c[2]);
  }
};

// Gradients strong enough (up to 0.34 per axis across the polygon, whose vertices lie within
// half_w and half_h of the centre) that picking the wrong provoking vertex changes the flat colour
// by far more than the tolerance, yet small enough that no vertex colour is clamped: a clamped
// vertex would break the affine property.
AffineColor random_affine(Rng& rng, float cx, float cy, float half_w, float half_h) {
  AffineColor a{};
  a.cx = cx;
  a.cy = cy;
  for (int i = 0; i < 3; ++i) {
    a.base[i] = rng.range(0.35f, 0.65f);
    a.dx[i] = rng.range(-0.17f, 0.17f) / half_w;
    a.dy[i] = rng.range(-0.17f, 0.17f) / half_h;
  }
  return a;
}

} // namespace

PINEDA_SCENE(mode_points, "GL_POINTS size 1 at fractional positions; smooth and flat halves") {
  smooth_and_flat(frame, [](const Panel& p) {
    // A point of size 1 produces the fragment at (floor(x) + 1/2, floor(y) + 1/2)
    // (GL 2.1 §3.3.1). Offsets stay clear of integers: the panel's projection is not exact in
    // float, and floor() of a window x computed as k - 1e-6 would flip to the previous pixel.
    const float offsets[5] = {0.5f, 0.25f, 0.75f, 0.125f, 0.875f};
    Rng rng(11);
    glBegin(GL_POINTS);
    int n = 0;
    for (int y = 2; y < p.h - 2; y += 3) {
      for (int x = 2; x < p.w - 2; x += 3, ++n) {
        palette_color(rng.below(16));
        glVertex2f(static_cast<float>(x) + offsets[n % 5], static_cast<float>(y) + offsets[(n / 5) % 5]);
      }
    }
    glEnd();
  });
}

PINEDA_SCENE(mode_lines, "GL_LINES of every slope with per-vertex colours; smooth and flat",
             .allowance = kLineAllowance, .why = kLineWhy) {
  smooth_and_flat(frame, [](const Panel& p) {
    Rng rng(21);
    glBegin(GL_LINES);
    for (int i = 0; i < 48; ++i) {
      const float x0 = rng.range(4.0f, p.w - 4.0f), y0 = rng.range(4.0f, p.h - 4.0f);
      float x1 = rng.range(4.0f, p.w - 4.0f), y1 = rng.range(4.0f, p.h - 4.0f);
      if (i % 8 == 0) y1 = y0 + 0.25f;  // nearly horizontal
      if (i % 8 == 1) x1 = x0 + 0.25f;  // nearly vertical
      palette_color(2 * i);
      glVertex2f(x0, y0);
      palette_color(2 * i + 5);
      glVertex2f(x1, y1);
    }
    glEnd();
  });
}

PINEDA_SCENE(mode_line_strip, "GL_LINE_STRIP spiral; flat segments take their second vertex",
             .allowance = kLineAllowance, .why = kLineWhy) {
  smooth_and_flat(frame, [](const Panel& p) {
    Rng rng(31);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 90; ++i) {
      const float t = static_cast<float>(i) * 0.35f;
      const float r = 4.0f + 1.05f * static_cast<float>(i) * (p.w * 0.5f - 8.0f) / 90.0f;
      palette_color(i);
      glVertex2f(p.w * 0.5f + r * std::cos(t) + rng.range(-0.4f, 0.4f),
                 p.h * 0.5f + r * 1.7f * std::sin(t) + rng.range(-0.4f, 0.4f));
    }
    glEnd();
  });
}

PINEDA_SCENE(mode_line_loop, "GL_LINE_LOOP star polygons; the closing segment uses vertex 1",
             .allowance = kLineAllowance, .why = kLineWhy) {
  smooth_and_flat(frame, [](const Panel& p) {
    const int points[4] = {5, 7, 9, 3};
    const int steps[4] = {2, 3, 4, 1};
    for (int s = 0; s < 4; ++s) {
      const float cx = p.w * 0.5f + 0.3f, cy = p.h * (0.125f + 0.25f * static_cast<float>(s)) + 0.2f;
      const float r = std::fmin(p.w * 0.45f, p.h * 0.12f);
      glBegin(GL_LINE_LOOP);
      for (int i = 0; i < points[s]; ++i) {
        const float a = 2.0f * kPi * static_cast<float>((i * steps[s]) % points[s]) /
                        static_cast<float>(points[s]) + 0.1f;
        palette_color(3 * s + i);
        glVertex2f(cx + r * std::cos(a), cy + r * std::sin(a));
      }
      glEnd();
    }
  });
}

PINEDA_SCENE(mode_triangles, "GL_TRIANGLES of both windings, overlapping; smooth and flat") {
  smooth_and_flat(frame, [](const Panel& p) {
    Rng rng(41);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 30; ++i) {
      const float cx = rng.range(10.0f, p.w - 10.0f), cy = rng.range(10.0f, p.h - 10.0f);
      for (int v = 0; v < 3; ++v) {
        palette_color(rng.below(16));
        glVertex2f(cx + rng.range(-40.0f, 40.0f), cy + rng.range(-40.0f, 40.0f));
      }
    }
    glEnd();
  });
}

PINEDA_SCENE(mode_triangle_strip, "GL_TRIANGLE_STRIP ribbons; flat uses vertex i+2") {
  smooth_and_flat(frame, [](const Panel& p) {
    Rng rng(51);
    for (int s = 0; s < 4; ++s) {
      const float y = p.h * (0.14f + 0.24f * static_cast<float>(s));
      glBegin(GL_TRIANGLE_STRIP);
      for (int i = 0; i < 18; ++i) {
        const float x = 4.0f + static_cast<float>(i) * (p.w - 8.0f) / 17.0f;
        const float wave = 10.0f * std::sin(static_cast<float>(i) * 0.7f + static_cast<float>(s));
        palette_color(rng.below(16));
        glVertex2f(x + rng.range(-2.0f, 2.0f), y + wave + 22.0f);
        palette_color(rng.below(16));
        glVertex2f(x + rng.range(-2.0f, 2.0f), y + wave - 8.0f + rng.range(-4.0f, 4.0f));
      }
      glEnd();
    }
  });
}

PINEDA_SCENE(mode_triangle_fan, "GL_TRIANGLE_FAN discs and a partial fan; flat uses vertex i+2") {
  smooth_and_flat(frame, [](const Panel& p) {
    Rng rng(61);
    const float centres[3][2] = {{0.5f, 0.8f}, {0.5f, 0.47f}, {0.5f, 0.15f}};
    for (int f = 0; f < 3; ++f) {
      const float cx = p.w * centres[f][0] + 0.3f, cy = p.h * centres[f][1] + 0.1f;
      const int slices = 7 + 5 * f;
      const float sweep = f == 1 ? 1.4f * kPi : 2.0f * kPi;
      glBegin(GL_TRIANGLE_FAN);
      glColor3f(1.0f, 1.0f, 1.0f);
      glVertex2f(cx, cy);
      for (int i = 0; i <= slices; ++i) {
        const float a = sweep * static_cast<float>(i) / static_cast<float>(slices);
        const float r = rng.range(30.0f, 40.0f);
        palette_color(i + 3 * f);
        glVertex2f(cx + r * std::cos(a) * 1.4f, cy + r * std::sin(a));
      }
      glEnd();
    }
  });
}

PINEDA_SCENE(mode_quads, "GL_QUADS convex jittered cells with affine colours; flat uses vertex 4i") {
  smooth_and_flat(frame, [](const Panel& p) {
    Rng rng(71);
    const int cols = 4, rows = 8;
    const float cw = (p.w - 8.0f) / cols, ch = (p.h - 8.0f) / rows;
    glBegin(GL_QUADS);
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < cols; ++c) {
        const float x0 = 4.0f + c * cw, y0 = 4.0f + r * ch;
        const float corner[4][2] = {{x0 + rng.range(0, 5), y0 + rng.range(0, 5)},
                                    {x0 + cw - rng.range(0, 5), y0 + rng.range(0, 5)},
                                    {x0 + cw - rng.range(0, 5), y0 + ch - rng.range(0, 5)},
                                    {x0 + rng.range(0, 5), y0 + ch - rng.range(0, 5)}};
        const AffineColor colour = random_affine(rng, x0 + cw * 0.5f, y0 + ch * 0.5f, cw * 0.5f, ch * 0.5f);
        // Alternate windings: the quads' orientation must not matter without culling.
        for (int v = 0; v < 4; ++v) {
          const int k = (r + c) % 2 ? v : 3 - v;
          colour.apply(corner[k][0], corner[k][1]);
          glVertex2f(corner[k][0], corner[k][1]);
        }
      }
    }
    glEnd();
  });
}

PINEDA_SCENE(mode_quad_strip, "GL_QUAD_STRIP bands with affine colours; flat uses vertex 2i+2") {
  smooth_and_flat(frame, [](const Panel& p) {
    Rng rng(81);
    for (int s = 0; s < 3; ++s) {
      const float y = p.h * (0.05f + 0.32f * static_cast<float>(s));
      // One affine colour field per strip, so every quad of it is triangulation-independent.
      const AffineColor colour = random_affine(rng, p.w * 0.5f, y + 38.0f, p.w * 0.5f + 6.0f, 40.0f);
      glBegin(GL_QUAD_STRIP);
      for (int i = 0; i < 10; ++i) {
        const float x = 4.0f + static_cast<float>(i) * (p.w - 8.0f) / 9.0f;
        const float x_top = x + 6.0f * std::sin(static_cast<float>(i + s));
        const float y_top = y + 70.0f + rng.range(-6.0f, 6.0f);
        colour.apply(x, y);
        glVertex2f(x, y);
        colour.apply(x_top, y_top);
        glVertex2f(x_top, y_top);
      }
      glEnd();
    }
  });
}

PINEDA_SCENE(mode_polygon, "GL_POLYGON convex 3..10-gons with affine colours; flat uses vertex 1") {
  smooth_and_flat(frame, [](const Panel& p) {
    Rng rng(91);
    for (int k = 0; k < 8; ++k) {
      const float cx = p.w * (k % 2 ? 0.7f : 0.3f) + 0.2f;
      const float cy = p.h * (0.07f + 0.123f * static_cast<float>(k)) + 0.1f;
      const int sides = 3 + k;
      const float r = 30.0f, turn = rng.range(0.0f, 1.0f);
      const AffineColor colour = random_affine(rng, cx, cy, 1.1f * r, 0.9f * r);
      glBegin(GL_POLYGON);
      for (int i = 0; i < sides; ++i) {
        const float a = turn + 2.0f * kPi * static_cast<float>(i) / static_cast<float>(sides);
        const float x = cx + r * std::cos(a) * 1.1f, y = cy + r * std::sin(a) * 0.9f;
        colour.apply(x, y);
        glVertex2f(x, y);
      }
      glEnd();
    }
  });
}

PINEDA_SCENE(quad_split_colors, "Non-affine colours on quads, quad strips and polygons: llvmpipe "
             "splits each as a fan from its first vertex",
             .why = "GL allows any split (GL 2.1 §3.5.1); llvmpipe is the reference, softpipe splits "
                    "GL_QUADS along the v1-v3 diagonal instead, hence the llvmpipe vs softpipe gap") {
  // GL leaves the interpolation across polygons of more than three vertices open
  // (GL 2.1 §3.5.1: any convex combination). llvmpipe, the reference, triangulates GL_QUADS,
  // GL_QUAD_STRIP (in polygon order 2i, 2i+1, 2i+3, 2i+2) and GL_POLYGON as a fan from the
  // polygon's first vertex; this scene pins that choice because it is visible in ordinary
  // programs. One vertex per quad is "hot" in turn so each split shows as a crease.
  clear_frame(0.0f, 0.0f, 0.0f);
  for (int p = 0; p < 12; ++p) {
    const Panel pn = panel(frame, p, 4, 3);
    const float w = static_cast<float>(pn.w), h = static_cast<float>(pn.h);
    const int hot = p % 4;
    auto colour = [hot](int v) {
      const float* c = palette(3 * hot + 1);
      if (v == hot) glColor3f(c[0], c[1], c[2]);
      else glColor3f(0.125f, 0.125f, 0.25f);
    };
    const float quad[4][2] = {{0.08f * w, 0.1f * h}, {0.9f * w, 0.06f * h},
                              {0.94f * w, 0.88f * h}, {0.12f * w, 0.95f * h}};
    if (p < 4) {
      glBegin(GL_QUADS);
      for (int v = 0; v < 4; ++v) {
        colour(v);
        glVertex2f(quad[v][0], quad[v][1]);
      }
      glEnd();
    } else if (p < 8) {
      // Strip order a0 b0 a1 b1 describes the polygon a0 b0 b1 a1.
      const int order[4] = {0, 3, 1, 2};
      glBegin(GL_QUAD_STRIP);
      for (int v = 0; v < 4; ++v) {
        colour(v);
        glVertex2f(quad[order[v]][0], quad[order[v]][1]);
      }
      glEnd();
    } else {
      glBegin(GL_POLYGON);
      for (int v = 0; v < 6; ++v) {
        const float a = 2.0f * kPi * static_cast<float>(v) / 6.0f + 0.2f;
        colour(v);
        glVertex2f(0.5f * w + 0.45f * w * std::cos(a), 0.5f * h + 0.45f * h * std::sin(a));
      }
      glEnd();
    }
  }
}
