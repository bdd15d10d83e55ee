// Rasterization modes (GL 2.1 §3.3 points, §3.4 lines, §3.5 polygons): wide, stippled and smooth
// lines, point sizes, smooth and attenuated points, polygon modes with edge flags, polygon
// offset and polygon stipple. Every scene sets the modes it uses itself (reset_state does not
// know them) and puts them back at the end.
#include "scene_util.h"

#include <cmath>
#include <cstdint>

using namespace scenes;

namespace {

// The GL defaults of everything these scenes touch.
void default_modes() {
  glLineWidth(1.0f);
  glPointSize(1.0f);
  glLineStipple(1, 0xffff);
  for (GLenum cap : {GL_LINE_SMOOTH, GL_LINE_STIPPLE, GL_POINT_SMOOTH, GL_POLYGON_SMOOTH,
                     GL_POLYGON_STIPPLE, GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE,
                     GL_POLYGON_OFFSET_POINT, GL_BLEND, GL_DEPTH_TEST})
    glDisable(cap);
  glPolygonOffset(0.0f, 0.0f);
  glBlendFunc(GL_ONE, GL_ZERO);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

// Segments from the centre of a panel outwards at n angles, both endpoints snapped to the
// 1/16-pixel grid, with per-vertex colours.
void star(const Panel& p, int n, float r0, float r1, float phase, Rng& rng) {
  const float cx = snap(p.w * 0.5f + 0.3f), cy = snap(p.h * 0.5f + 0.2f);
  glBegin(GL_LINES);
  for (int i = 0; i < n; ++i) {
    const float a = phase + 2.0f * kPi * static_cast<float>(i) / static_cast<float>(n);
    palette_color(rng.below(16));
    glVertex2f(snap(cx + r0 * std::cos(a)), snap(cy + r0 * std::sin(a)));
    palette_color(rng.below(16));
    glVertex2f(snap(cx + r1 * std::cos(a)), snap(cy + r1 * std::sin(a)));
  }
  glEnd();
}

} // namespace

PINEDA_SCENE(rm_wide_lines,
             "GL_LINES of widths 1..8 (also fractional), every slope, smooth colours",
             .allowance = kLineAllowance, .why = kLineWhy) {
  default_modes();
  clear_frame(0.0f, 0.0f, 0.0f);
  const float widths[9] = {1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 2.4f, 3.6f, 6.0f, 8.0f};
  Rng rng(101);
  for (int i = 0; i < 9; ++i) {
    const Panel p = panel(frame, i, 3, 3);
    glLineWidth(widths[i]);
    star(p, 14, 6.0f, 36.0f, 0.1f * static_cast<float>(i), rng);
  }
  default_modes();
}

PINEDA_SCENE(rm_wide_line_strips, "Wide GL_LINE_STRIP and GL_LINE_LOOP, flat and smooth",
             .allowance = kLineAllowance, .why = kLineWhy) {
  default_modes();
  clear_frame(0.1f, 0.1f, 0.1f);
  Rng rng(202);
  for (int i = 0; i < 4; ++i) {
    const Panel p = panel(frame, i, 2, 2);
    glLineWidth(static_cast<float>(2 + i));
    glShadeModel(i & 1 ? GL_FLAT : GL_SMOOTH);
    glBegin(i < 2 ? GL_LINE_STRIP : GL_LINE_LOOP);
    for (int k = 0; k < 9; ++k) {
      palette_color(rng.below(16));
      glVertex2f(snap(rng.range(8.0f, p.w - 8.0f)), snap(rng.range(8.0f, p.h - 8.0f)));
    }
    glEnd();
  }
  glShadeModel(GL_SMOOTH);
  default_modes();
}

PINEDA_SCENE(rm_stipple_lines, "Stippled GL_LINES, strips and loops, factors 1..3, widths 1 and 2",
             .allowance = kLineAllowance, .why = kLineWhy) {
  default_modes();
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLushort patterns[3] = {0x0f0f, 0x3c9f, 0xaaaa};
  Rng rng(303);
  glEnable(GL_LINE_STIPPLE);
  for (int i = 0; i < 6; ++i) {
    const Panel p = panel(frame, i, 3, 2);
    glLineStipple(1 + i % 3, patterns[i % 3]);
    glLineWidth(i < 3 ? 1.0f : 2.0f);
    // Independent segments: the pattern restarts with each (GL 2.1 §3.4.2).
    glBegin(GL_LINES);
    for (int k = 0; k < 6; ++k) {
      const float y = snap(6.5f + 6.0f * k);
      palette_color(k);
      glVertex2f(4.5f, y);
      glVertex2f(snap(20.0f + 10.0f * k + 0.25f), snap(y + 2.0f * k - 4.0f));
    }
    // Steep ones.
    for (int k = 0; k < 4; ++k) {
      palette_color(k + 6);
      glVertex2f(snap(p.w - 8.5f - 6.0f * k), 4.5f);
      glVertex2f(snap(p.w - 12.0f - 6.0f * k), snap(p.h * 0.5f));
    }
    glEnd();
    // A strip continues the pattern across its vertices; a loop too, closing segment included.
    glBegin(i & 1 ? GL_LINE_LOOP : GL_LINE_STRIP);
    for (int k = 0; k < 7; ++k) {
      palette_color(rng.below(16));
      glVertex2f(snap(rng.range(6.0f, p.w - 6.0f)), snap(rng.range(p.h * 0.55f, p.h - 6.0f)));
    }
    glEnd();
  }
  default_modes();
}

PINEDA_SCENE(rm_smooth_lines, "GL_LINE_SMOOTH with blending, widths 1, 1.5, 3 and 5",
             .allowance = kLineAllowance, .why = kLineWhy) {
  default_modes();
  clear_frame(0.05f, 0.05f, 0.2f);
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  const float widths[4] = {1.0f, 1.5f, 3.0f, 5.0f};
  Rng rng(404);
  for (int i = 0; i < 4; ++i) {
    const Panel p = panel(frame, i, 2, 2);
    glLineWidth(widths[i]);
    star(p, 12, 8.0f, 56.0f, 0.05f + 0.2f * static_cast<float>(i), rng);
  }
  default_modes();
}

PINEDA_SCENE(rm_point_sizes,
             "GL_POINTS of sizes 1..10 and fractional sizes at fractional positions") {
  default_modes();
  clear_frame(0.0f, 0.0f, 0.0f);
  const float sizes[14] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 1.4f, 2.6f, 3.5f, 4.4f};
  const float offsets[5] = {0.5f, 0.25f, 0.75f, 0.125f, 0.875f};
  Rng rng(505);
  for (int i = 0; i < 14; ++i) {
    glPointSize(sizes[i]);
    glBegin(GL_POINTS);
    for (int k = 0; k < 9; ++k) {
      palette_color(rng.below(16));
      glVertex2f(10.0f + 17.0f * k + offsets[(i + k) % 5], 8.0f + 17.5f * i + offsets[k % 5]);
    }
    glEnd();
  }
  default_modes();
}

PINEDA_SCENE(rm_smooth_points, "GL_POINT_SMOOTH with blending, sizes 1..12") {
  default_modes();
  clear_frame(0.1f, 0.1f, 0.1f);
  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  const float offsets[5] = {0.5f, 0.25f, 0.75f, 0.125f, 0.875f};
  Rng rng(606);
  for (int i = 0; i < 12; ++i) {
    glPointSize(1.0f + static_cast<float>(i) + (i & 1 ? 0.5f : 0.0f));
    glBegin(GL_POINTS);
    for (int k = 0; k < 8; ++k) {
      palette_color(rng.below(16));
      glVertex2f(12.0f + 30.0f * k + offsets[(i + k) % 5], 10.0f + 20.5f * i + offsets[k % 5]);
    }
    glEnd();
  }
  default_modes();
}

PINEDA_SCENE(rm_attenuated_points,
             "GL 1.4 point distance attenuation with size limits, perspective") {
  default_modes();
  clear_frame(0.0f, 0.0f, 0.0f);
  const auto point_fv = proc<PFNGLPOINTPARAMETERFVPROC>("glPointParameterfv");
  const auto point_f = proc<PFNGLPOINTPARAMETERFPROC>("glPointParameterf");
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const GLfloat atten[3] = {0.0f, 0.25f, 0.0f};
  point_fv(GL_POINT_DISTANCE_ATTENUATION, atten);
  point_f(GL_POINT_SIZE_MIN, 2.0f);
  point_f(GL_POINT_SIZE_MAX, 9.0f);
  glPointSize(12.0f);
  Rng rng(707);
  glBegin(GL_POINTS);
  for (int i = 0; i < 120; ++i) {
    const float z = -rng.range(1.5f, 25.0f);
    palette_color(rng.below(16));
    glVertex3f(rng.range(-0.9f, 0.9f) * -z, rng.range(-0.9f, 0.9f) * -z, z);
  }
  glEnd();
  const GLfloat none[3] = {1.0f, 0.0f, 0.0f};
  point_fv(GL_POINT_DISTANCE_ATTENUATION, none);
  point_f(GL_POINT_SIZE_MIN, 0.0f);
  point_f(GL_POINT_SIZE_MAX, 255.0f);
  default_modes();
  window_projection(frame);
}

PINEDA_SCENE(rm_polygon_modes,
             "Polygon modes LINE and POINT per face, edge flags off on inner edges",
             .allowance = kLineAllowance, .why = kLineWhy) {
  default_modes();
  clear_frame(0.0f, 0.0f, 0.0f);
  for (int half = 0; half < 2; ++half) {
    const Panel p = panel(frame, half, 2, 1);
    glPolygonMode(GL_FRONT, half == 0 ? GL_LINE : GL_POINT);
    glPolygonMode(GL_BACK, half == 0 ? GL_POINT : GL_LINE);
    glPointSize(half == 0 ? 3.0f : 2.0f);
    glLineWidth(half == 0 ? 1.0f : 2.0f);
    // A quad drawn as two triangles whose shared diagonal has its edge flag off, front facing.
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.3f, 0.2f);
    glEdgeFlag(GL_TRUE);
    glVertex2f(10.5f, 10.5f);
    glVertex2f(100.5f, 12.5f);
    glEdgeFlag(GL_FALSE);
    glVertex2f(98.5f, 90.5f);
    glEdgeFlag(GL_TRUE);
    glColor3f(0.2f, 1.0f, 0.3f);
    glVertex2f(10.5f, 10.5f);
    glEdgeFlag(GL_FALSE);
    glVertex2f(98.5f, 90.5f);
    glEdgeFlag(GL_TRUE);
    glVertex2f(12.5f, 88.5f);
    glEnd();
    // A back-facing polygon (clockwise) with one inner vertex edge off.
    glBegin(GL_POLYGON);
    glColor3f(0.3f, 0.5f, 1.0f);
    const float cx = p.w * 0.5f, cy = 180.5f;
    for (int k = 0; k < 7; ++k) {
      const float a = -2.0f * kPi * static_cast<float>(k) / 7.0f;
      glEdgeFlag(k == 3 ? GL_FALSE : GL_TRUE);
      glVertex2f(snap(cx + 45.0f * std::cos(a)), snap(cy + 45.0f * std::sin(a)));
    }
    glEnd();
    glEdgeFlag(GL_TRUE);
  }
  default_modes();
}

PINEDA_SCENE(rm_polygon_offset,
             "Hidden-line outline: offset filled faces with coplanar LINE-mode edges",
             .allowance = kLineAllowance, .why = kLineWhy) {
  default_modes();
  clear_frame(0.0f, 0.0f, 0.0f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -1.0, 1.0, 2.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -5.0f);
  glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(40.0f, 0.0f, 1.0f, 0.0f);
  glEnable(GL_DEPTH_TEST);
  // A grid of quads on a sphere-like bump: filled in the background colour with the offset
  // pushing them back, then the same quads as lines without offset.
  const auto surface = [](float u, float v) {
    return 0.35f * std::cos(1.7f * u) * std::cos(1.7f * v);
  };
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 0) {
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(1.0f, 1.0f);
      glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
      glColor3f(0.15f, 0.15f, 0.3f);
    } else {
      glDisable(GL_POLYGON_OFFSET_FILL);
      glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
      glColor3f(1.0f, 1.0f, 0.4f);
    }
    const int n = 10;
    for (int j = 0; j < n; ++j) {
      glBegin(GL_QUAD_STRIP);
      for (int i = 0; i <= n; ++i) {
        const float u = -1.2f + 2.4f * static_cast<float>(i) / n;
        const float v0 = -1.2f + 2.4f * static_cast<float>(j) / n;
        const float v1 = -1.2f + 2.4f * static_cast<float>(j + 1) / n;
        glVertex3f(u, surface(u, v0), v0);
        glVertex3f(u, surface(u, v1), v1);
      }
      glEnd();
    }
  }
  // A second panel-free check: a lined square offset with POLYGON_OFFSET_LINE behind a
  // coplanar filled one.
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -3.0f);
  glRotatef(50.0f, 0.0f, 1.0f, 0.0f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glColor3f(0.6f, 0.1f, 0.1f);
  glRectf(-0.9f, -0.95f, -0.3f, -0.45f);
  glEnable(GL_POLYGON_OFFSET_LINE);
  glPolygonOffset(-1.0f, -2.0f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glColor3f(0.2f, 1.0f, 0.2f);
  glRectf(-0.9f, -0.95f, -0.3f, -0.45f);
  default_modes();
  window_projection(frame);
}

PINEDA_SCENE(rm_polygon_stipple,
             "GL_POLYGON_STIPPLE patterns unpacked with LSB_FIRST, row length, skips, alignment") {
  default_modes();
  clear_frame(0.0f, 0.0f, 0.0f);
  // A pattern that is asymmetric in x and y, so flips and offsets show.
  uint8_t pattern[32 * 4];
  for (int r = 0; r < 32; ++r)
    for (int b = 0; b < 4; ++b)
      pattern[r * 4 + b] = static_cast<uint8_t>((r * 37 + b * 11) ^ (r << b) ^ (b == 0 ? 0x81 : 0));
  // The same pattern inside a larger image: 48-bit rows, 8-byte alignment, skips.
  uint8_t big[40 * 8] = {};
  for (int r = 0; r < 32; ++r)
    for (int c = 0; c < 32; ++c) {
      const bool on = (pattern[r * 4 + c / 8] >> (7 - c % 8)) & 1;
      const int bit = 5 + c; // skip 5 pixels
      if (on) big[(r + 3) * 8 + bit / 8] |= static_cast<uint8_t>(0x80 >> (bit % 8));
    }
  glEnable(GL_POLYGON_STIPPLE);
  for (int i = 0; i < 4; ++i) {
    const Panel p = panel(frame, i, 2, 2);
    if (i == 0) {
      glPolygonStipple(pattern);
    } else if (i == 1) {
      glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
      glPolygonStipple(pattern);
      glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
    } else if (i == 2) {
      glPixelStorei(GL_UNPACK_ROW_LENGTH, 48);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
      glPixelStorei(GL_UNPACK_SKIP_PIXELS, 5);
      glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
      glPolygonStipple(big);
      glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
      glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
      glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    } else {
      const uint8_t checker[4] = {0xcc, 0x33, 0xf0, 0x0f};
      uint8_t c[128];
      for (int k = 0; k < 128; ++k)
        c[k] = checker[(k / 4 + k) % 4];
      glPolygonStipple(c);
    }
    // Smooth-shaded triangles and a quad.
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.2f, 0.2f);
    glVertex2f(3.0f, 3.0f);
    glColor3f(0.2f, 1.0f, 0.2f);
    glVertex2f(p.w - 3.0f, 10.0f);
    glColor3f(0.2f, 0.2f, 1.0f);
    glVertex2f(p.w * 0.4f, p.h - 4.0f);
    glEnd();
    glColor3f(1.0f, 1.0f, 0.3f);
    glRectf(p.w * 0.6f, p.h * 0.5f, p.w - 5.0f, p.h - 5.0f);
  }
  default_modes();
}

PINEDA_SCENE(rm_polygon_smooth,
             "GL_POLYGON_SMOOTH: llvmpipe draws the polygons aliased, so does Pineda") {
  // GL 2.1 §3.5.6 asks for coverage-weighted alpha at polygon edges; llvmpipe (without
  // multisampling) ignores the enable and fills the polygons as if it were off.
  default_modes();
  clear_frame(0.0f, 0.0f, 0.0f);
  glEnable(GL_POLYGON_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE);
  Rng rng(909);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 24; ++i)
    for (int k = 0; k < 3; ++k) {
      palette_color(rng.below(16));
      glVertex2f(snap(rng.range(4.0f, 252.0f)), snap(rng.range(4.0f, 252.0f)));
    }
  glEnd();
  default_modes();
}

PINEDA_SCENE(rm_offset_points,
             "POLYGON_OFFSET_POINT and _LINE on POINT- and LINE-mode polygons over filled ones",
             .allowance = kLineAllowance, .why = kLineWhy) {
  default_modes();
  clear_frame(0.0f, 0.0f, 0.0f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -1.0, 1.0, 2.0, 6.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -4.0f);
  glRotatef(35.0f, 1.0f, 0.3f, 0.0f);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  const auto fan = [] {
    glBegin(GL_TRIANGLE_FAN);
    glVertex3f(0.0f, 0.0f, 0.3f);
    for (int k = 0; k <= 8; ++k) {
      const float a = 2.0f * kPi * static_cast<float>(k) / 8.0f;
      glVertex3f(1.3f * std::cos(a), 1.3f * std::sin(a), 0.0f);
    }
    glEnd();
  };
  glColor3f(0.2f, 0.2f, 0.5f);
  fan();
  // Without offset the coplanar vertices and edges would fight with the fill; pulled forward
  // they all pass LESS.
  glPointSize(4.0f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glEnable(GL_POLYGON_OFFSET_POINT);
  glPolygonOffset(-1.0f, -4.0f);
  glColor3f(1.0f, 0.9f, 0.2f);
  fan();
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glEnable(GL_POLYGON_OFFSET_LINE);
  glPolygonOffset(-1.0f, -2.0f);
  glColor3f(0.2f, 1.0f, 0.9f);
  glTranslatef(0.0f, 0.0f, 0.0f);
  fan();
  default_modes();
  window_projection(frame);
}

PINEDA_SCENE(rm_stipple_outlines,
             "Stippled LINE-mode outlines of every polygon type; stippled smooth lines",
             .allowance = kLineAllowance, .why = kLineWhy) {
  default_modes();
  clear_frame(0.0f, 0.0f, 0.0f);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x1c7f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  const GLenum modes[6] = {GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                           GL_QUADS,     GL_QUAD_STRIP,     GL_POLYGON};
  Rng rng(1111);
  for (int i = 0; i < 6; ++i) {
    const Panel p = panel(frame, i, 3, 3);
    glBegin(modes[i]);
    for (int k = 0; k < 8; ++k) {
      palette_color(rng.below(16));
      // A zig-zag band for strips, a ring for fans and polygons, loose cells otherwise.
      float x, y;
      if (modes[i] == GL_TRIANGLE_FAN || modes[i] == GL_POLYGON) {
        const float a = 2.0f * kPi * static_cast<float>(k) / 8.0f;
        x = p.w * 0.5f + (k == 0 && modes[i] == GL_TRIANGLE_FAN ? 0.0f : 30.0f * std::cos(a));
        y = p.h * 0.5f + (k == 0 && modes[i] == GL_TRIANGLE_FAN ? 0.0f : 30.0f * std::sin(a));
      } else {
        x = 6.0f + 10.0f * static_cast<float>(k) + rng.range(-2.0f, 2.0f);
        y = (k & 1) ? p.h - 8.0f - rng.range(0.0f, 10.0f) : 8.0f + rng.range(0.0f, 10.0f);
      }
      glVertex2f(snap(x), snap(y));
    }
    glEnd();
  }
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  // Stippled smooth lines: each dash is its own smooth segment.
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int i = 6; i < 9; ++i) {
    const Panel p = panel(frame, i, 3, 3);
    glLineStipple(i - 5, 0x33f1);
    glLineWidth(1.0f + static_cast<float>(i - 6));
    glBegin(i == 8 ? GL_LINE_LOOP : GL_LINE_STRIP);
    for (int k = 0; k < 6; ++k) {
      palette_color(rng.below(16));
      glVertex2f(snap(rng.range(6.0f, p.w - 6.0f)), snap(rng.range(6.0f, p.h - 6.0f)));
    }
    glEnd();
  }
  default_modes();
}
