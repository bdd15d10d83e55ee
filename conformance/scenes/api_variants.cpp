// Every immediate-mode entry point variant: glVertex{2,3,4}{s,i,f,d}[v] (GL 2.1 §2.7),
// glColor{3,4}{b,s,i,f,d,ub,us,ui}[v] with the integer-to-float conversions of Table 2.9,
// glRect{s,i,f,d}[v] (§2.10), and glNormal/glTexCoord, which must not change anything while
// lighting and texturing are off.
#include "scene_util.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

using namespace scenes;

namespace {

// One of the 24 glVertex variants. The 4-component forms pass w = 2 with x, y, z doubled, which
// is the same point after the perspective division (GL 2.1 §2.11). The integer forms receive
// integer positions; the float forms a quarter-pixel offset.
void vertex_variant(int variant, int xi, int yi) {
  const int kind = variant % 8;    // s, sv, i, iv, f, fv, d, dv
  const int size = 2 + variant / 8; // 2, 3, 4
  const bool integer = kind < 4;
  const double off = integer ? 0.0 : 0.25;
  const double x = xi + off, y = yi + off, z = 0.25 * (size > 2) * !integer;
  const double w = size == 4 ? 2.0 : 1.0;
  const double X = x * w, Y = y * w, Z = z * w;
  const GLshort s[4] = {static_cast<GLshort>(X), static_cast<GLshort>(Y), static_cast<GLshort>(Z),
                        static_cast<GLshort>(w)};
  const GLint i[4] = {static_cast<GLint>(X), static_cast<GLint>(Y), static_cast<GLint>(Z),
                      static_cast<GLint>(w)};
  const GLfloat f[4] = {static_cast<GLfloat>(X), static_cast<GLfloat>(Y), static_cast<GLfloat>(Z),
                        static_cast<GLfloat>(w)};
  const GLdouble d[4] = {X, Y, Z, w};
  switch (variant) {
  case 0: glVertex2s(s[0], s[1]); break;
  case 1: glVertex2sv(s); break;
  case 2: glVertex2i(i[0], i[1]); break;
  case 3: glVertex2iv(i); break;
  case 4: glVertex2f(f[0], f[1]); break;
  case 5: glVertex2fv(f); break;
  case 6: glVertex2d(d[0], d[1]); break;
  case 7: glVertex2dv(d); break;
  case 8: glVertex3s(s[0], s[1], s[2]); break;
  case 9: glVertex3sv(s); break;
  case 10: glVertex3i(i[0], i[1], i[2]); break;
  case 11: glVertex3iv(i); break;
  case 12: glVertex3f(f[0], f[1], f[2]); break;
  case 13: glVertex3fv(f); break;
  case 14: glVertex3d(d[0], d[1], d[2]); break;
  case 15: glVertex3dv(d); break;
  case 16: glVertex4s(s[0], s[1], s[2], s[3]); break;
  case 17: glVertex4sv(s); break;
  case 18: glVertex4i(i[0], i[1], i[2], i[3]); break;
  case 19: glVertex4iv(i); break;
  case 20: glVertex4f(f[0], f[1], f[2], f[3]); break;
  case 21: glVertex4fv(f); break;
  case 22: glVertex4d(d[0], d[1], d[2], d[3]); break;
  default: glVertex4dv(d); break;
  }
}

// One of the 32 glColor variants with channel levels in [-1, 1.5]. Levels become the type's
// value level * max (clamped to the type's range), so negative levels reach GL as negative
// signed values or floats, and levels above 1 as out-of-range floats; both are clamped to [0, 1]
// before rasterization (GL 2.1 §2.14.6), while unsigned types saturate here already.
template <typename T> T level_to(double level) {
  const double max = static_cast<double>(std::numeric_limits<T>::max());
  const double min = static_cast<double>(std::numeric_limits<T>::min());
  return static_cast<T>(std::clamp(std::round(level * max), min, max));
}

void color_variant(int variant, const double level[4]) {
  const int kind = variant % 16;       // b, bv, s, sv, i, iv, f, fv, d, dv, ub, ubv, us, usv, ui, uiv
  const bool four = variant >= 16;
  GLbyte b[4];
  GLshort s[4];
  GLint i[4];
  GLfloat f[4];
  GLdouble d[4];
  GLubyte ub[4];
  GLushort us[4];
  GLuint ui[4];
  for (int c = 0; c < 4; ++c) {
    b[c] = level_to<GLbyte>(level[c]);
    s[c] = level_to<GLshort>(level[c]);
    i[c] = level_to<GLint>(level[c]);
    f[c] = static_cast<GLfloat>(level[c]);
    d[c] = level[c];
    ub[c] = level_to<GLubyte>(level[c]);
    us[c] = level_to<GLushort>(level[c]);
    ui[c] = level_to<GLuint>(level[c]);
  }
  if (!four) {
    switch (kind) {
    case 0: glColor3b(b[0], b[1], b[2]); break;
    case 1: glColor3bv(b); break;
    case 2: glColor3s(s[0], s[1], s[2]); break;
    case 3: glColor3sv(s); break;
    case 4: glColor3i(i[0], i[1], i[2]); break;
    case 5: glColor3iv(i); break;
    case 6: glColor3f(f[0], f[1], f[2]); break;
    case 7: glColor3fv(f); break;
    case 8: glColor3d(d[0], d[1], d[2]); break;
    case 9: glColor3dv(d); break;
    case 10: glColor3ub(ub[0], ub[1], ub[2]); break;
    case 11: glColor3ubv(ub); break;
    case 12: glColor3us(us[0], us[1], us[2]); break;
    case 13: glColor3usv(us); break;
    case 14: glColor3ui(ui[0], ui[1], ui[2]); break;
    default: glColor3uiv(ui); break;
    }
    return;
  }
  switch (kind) {
  case 0: glColor4b(b[0], b[1], b[2], b[3]); break;
  case 1: glColor4bv(b); break;
  case 2: glColor4s(s[0], s[1], s[2], s[3]); break;
  case 3: glColor4sv(s); break;
  case 4: glColor4i(i[0], i[1], i[2], i[3]); break;
  case 5: glColor4iv(i); break;
  case 6: glColor4f(f[0], f[1], f[2], f[3]); break;
  case 7: glColor4fv(f); break;
  case 8: glColor4d(d[0], d[1], d[2], d[3]); break;
  case 9: glColor4dv(d); break;
  case 10: glColor4ub(ub[0], ub[1], ub[2], ub[3]); break;
  case 11: glColor4ubv(ub); break;
  case 12: glColor4us(us[0], us[1], us[2], us[3]); break;
  case 13: glColor4usv(us); break;
  case 14: glColor4ui(ui[0], ui[1], ui[2], ui[3]); break;
  default: glColor4uiv(ui); break;
  }
}

} // namespace

PINEDA_SCENE(vertex_variants, "glVertex{2,3,4}{s,i,f,d}[v], one cell each; 4D forms use w = 2") {
  clear_frame(0.0f, 0.0f, 0.125f);
  // Cells of 42 x 64 pixels, 6 columns x 4 rows; vertices on integer (or quarter) positions.
  glBegin(GL_TRIANGLES);
  for (int v = 0; v < 24; ++v) {
    const int x0 = 3 + (v % 6) * 42, y0 = 3 + (v / 6) * 64;
    palette_color(v);
    vertex_variant(v, x0, y0);
    palette_color(v + 5);
    vertex_variant(v, x0 + 38, y0 + 6);
    palette_color(v + 9);
    vertex_variant(v, x0 + 12, y0 + 59);
    palette_color(v + 2);
    vertex_variant(v, x0 + 38, y0 + 12);
    palette_color(v + 7);
    vertex_variant(v, x0 + 36, y0 + 58);
    palette_color(v + 11);
    vertex_variant(v, x0 + 18, y0 + 58);
  }
  glEnd();
}

PINEDA_SCENE(color_variants, "glColor{3,4}{b,s,i,f,d,ub,us,ui}[v] incl. negative and >1 values") {
  clear_frame(0.25f, 0.25f, 0.25f, 0.25f);
  // Levels per triangle vertex; alpha is stored in the RGBA buffer, so the 4-component forms are
  // checked on alpha too. Level 0.5 is left out: it is a rounding tie for most types.
  const double levels[6][4] = {{1.0, 0.25, 0.0, 1.0},   {0.0, 1.0, 0.75, 0.625},
                               {0.375, 0.0, 1.0, 0.25}, {-1.0, 0.875, 1.5, 0.0},
                               {1.5, -0.5, 0.125, 1.25}, {0.625, 0.625, -0.25, 0.875}};
  for (int v = 0; v < 32; ++v) {
    const int x0 = 2 + (v % 8) * 32, y0 = 2 + (v / 8) * 64;
    glBegin(GL_TRIANGLES);
    const int corners[6][2] = {{0, 0}, {29, 0}, {0, 40}, {29, 20}, {29, 61}, {4, 61}};
    for (int k = 0; k < 6; ++k) {
      color_variant(v, levels[k]);
      glVertex2f(static_cast<float>(x0 + corners[k][0]), static_cast<float>(y0 + corners[k][1]));
    }
    glEnd();
  }
}

PINEDA_SCENE(rect_variants, "glRect{s,i,f,d}[v] with reversed corners; upper half culls back faces") {
  clear_frame(0.0f, 0.0f, 0.0f);
  // glRect(x1, y1, x2, y2) is the polygon (x1,y1) (x2,y1) (x2,y2) (x1,y2) (GL 2.1 §2.10): it is
  // counter-clockwise only when x1 < x2 and y1 < y2 have the same order, so swapping one pair
  // makes a back face that the culling half must drop.
  for (int half = 0; half < 2; ++half) {
    if (half == 1) glEnable(GL_CULL_FACE);
    for (int v = 0; v < 8; ++v) {
      const double x0 = 4 + (v % 4) * 63, y0 = 4 + half * 128 + (v / 4) * 62;
      for (int k = 0; k < 4; ++k) {
        double r[4] = {x0 + (k % 2) * 28, y0 + (k / 2) * 28, x0 + (k % 2) * 28 + 26,
                       y0 + (k / 2) * 28 + 26};
        if (k == 1) std::swap(r[0], r[2]); // clockwise
        if (k == 2) std::swap(r[1], r[3]); // clockwise
        if (k == 3) { std::swap(r[0], r[2]); std::swap(r[1], r[3]); } // counter-clockwise again
        if (v >= 4) for (double& c : r) c += 0.25; // the float and double forms get fractions
        palette_color(v * 4 + k);
        const GLshort s[4] = {GLshort(r[0]), GLshort(r[1]), GLshort(r[2]), GLshort(r[3])};
        const GLint i[4] = {GLint(r[0]), GLint(r[1]), GLint(r[2]), GLint(r[3])};
        const GLfloat f[4] = {GLfloat(r[0]), GLfloat(r[1]), GLfloat(r[2]), GLfloat(r[3])};
        switch (v) {
        case 0: glRects(s[0], s[1], s[2], s[3]); break;
        case 1: glRectsv(s, s + 2); break;
        case 2: glRecti(i[0], i[1], i[2], i[3]); break;
        case 3: glRectiv(i, i + 2); break;
        case 4: glRectf(f[0], f[1], f[2], f[3]); break;
        case 5: glRectfv(f, f + 2); break;
        case 6: glRectd(r[0], r[1], r[2], r[3]); break;
        default: glRectdv(r, r + 2); break;
        }
      }
    }
  }
}

PINEDA_SCENE(ignored_attributes, "glNormal and glTexCoord between vertices change nothing unlit") {
  clear_frame(0.0f, 0.0f, 0.0f);
  Rng rng(5);
  // Left: plain triangles. Right: the same with normals and texture coordinates of every form
  // interleaved. Without lighting (GL 2.1 §2.14.1) and texturing (§3.8.16) both must match.
  for (int half = 0; half < 2; ++half) {
    panel(frame, half, 2, 1);
    Rng local(17);
    glBegin(GL_TRIANGLES);
    for (int t = 0; t < 36; ++t) {
      const float cx = local.range(15.0f, 110.0f), cy = local.range(15.0f, 235.0f);
      for (int k = 0; k < 3; ++k) {
        const float x = cx + local.range(-25.0f, 25.0f), y = cy + local.range(-25.0f, 25.0f);
        palette_color(t + k * 3);
        if (half == 1) {
          const float n[3] = {rng.range(-1, 1), rng.range(-1, 1), rng.range(-1, 1)};
          switch ((t + k) % 6) {
          case 0: glNormal3f(n[0], n[1], n[2]); glTexCoord2f(n[0], n[1]); break;
          case 1: glNormal3fv(n); glTexCoord4f(n[0], n[1], n[2], 1.0f); break;
          case 2: glNormal3b(12, -100, 7); glTexCoord1f(n[2]); break;
          case 3: glNormal3d(n[0], n[1], n[2]); glTexCoord3f(n[0], n[1], n[2]); break;
          case 4: glNormal3i(1, 0, -1); glTexCoord2fv(n); break;
          default: glNormal3s(-3, 2, 1); glTexCoord2d(n[1], n[2]); break;
          }
        }
        glVertex2f(x, y);
      }
    }
    glEnd();
  }
}

PINEDA_SCENE(edge_flags, "glEdgeFlag hides polygon edges in GL_LINE and GL_POINT polygon modes",
             .allowance = kLineAllowance, .why = kLineWhy) {
  clear_frame(0.0f, 0.0f, 0.0f);
  // In GL_LINE mode only edges whose starting vertex has the edge flag set are drawn; in GL_POINT
  // mode only vertices with the flag set are (GL 2.1 §2.6.2, §3.5.4). Top: lines; bottom: points.
  for (int mode = 0; mode < 2; ++mode) {
    glPolygonMode(GL_FRONT_AND_BACK, mode == 0 ? GL_LINE : GL_POINT);
    const float base_y = mode == 0 ? 136.0f : 8.0f;
    for (int k = 0; k < 3; ++k) {
      const float x0 = 10.0f + k * 82.0f + 0.3f, y0 = base_y + 0.4f;
      const GLenum prim = k == 0 ? GL_POLYGON : (k == 1 ? GL_TRIANGLES : GL_QUADS);
      const int count = k == 0 ? 7 : (k == 1 ? 6 : 8);
      glBegin(prim);
      for (int v = 0; v < count; ++v) {
        // Flags follow a fixed pattern; the v-array form is used for every other vertex.
        const GLboolean flag = (v % 3) != 1 ? GL_TRUE : GL_FALSE;
        if (v % 2) glEdgeFlagv(&flag);
        else glEdgeFlag(flag);
        palette_color(v + 3 * k);
        float x, y;
        if (k == 0) {
          const float a = 2.0f * kPi * static_cast<float>(v) / 7.0f;
          x = x0 + 32.0f + 30.0f * std::cos(a);
          y = y0 + 56.0f + 52.0f * std::sin(a);
        } else {
          const float pts[8][2] = {{0, 0}, {60, 10}, {10, 50}, {20, 112}, {64, 60}, {60, 110},
                                   {4, 112}, {0, 64}};
          const float quad[8][2] = {{0, 0}, {60, 0}, {62, 50}, {2, 54}, {4, 62}, {60, 60},
                                    {64, 112}, {0, 110}};
          x = x0 + (k == 1 ? pts[v][0] : quad[v][0]);
          y = y0 + (k == 1 ? pts[v][1] : quad[v][1]);
        }
        glVertex2f(x, y);
      }
      glEnd();
    }
  }
  glEdgeFlag(GL_TRUE);
}
