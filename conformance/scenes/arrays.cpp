// Vertex arrays (GL 2.1 §2.8): every primitive mode through glDrawArrays, glArrayElement,
// glDrawElements with each index type, glDrawRangeElements, glMultiDrawArrays/Elements, every
// component type and stride, edge-flag arrays and all fourteen glInterleavedArrays formats.
// Functions newer than GL 1.1 are looked up with proc() (scene.h).
#include "scene_util.h"

#include <cmath>
#include <cstring>
#include <vector>

using namespace scenes;

namespace {

struct Vtx {
  GLfloat x, y;
  GLubyte c[4];
};

Vtx vtx(float x, float y, int colour, float alpha = 1.0f) {
  const float* p = palette(colour);
  return Vtx{x, y, {GLubyte(p[0] * 255.0f + 0.5f), GLubyte(p[1] * 255.0f + 0.5f),
                    GLubyte(p[2] * 255.0f + 0.5f), GLubyte(alpha * 255.0f + 0.5f)}};
}

// Vertices suited to `mode` inside a w x h panel. Quads get one colour per quad and quad strips
// one colour per rung (rungs are vertical), so no result depends on how quads are split.
std::vector<Vtx> shape_for(GLenum mode, float w, float h, std::uint32_t seed) {
  Rng rng(seed);
  std::vector<Vtx> v;
  const float cx = 0.5f * w + 0.2f, cy = 0.5f * h + 0.1f;
  switch (mode) {
  case GL_POINTS:
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 12; ++i)
        v.push_back(vtx(3.25f + i * (w - 6.0f) / 12.0f, 3.75f + j * (h - 6.0f) / 12.0f, i + j));
    break;
  case GL_LINES:
  case GL_LINE_STRIP:
  case GL_LINE_LOOP:
    for (int i = 0; i < 14; ++i) {
      const float a = 2.0f * kPi * static_cast<float>(i * 5 % 14) / 14.0f;
      const float r = (i % 2 ? 0.45f : 0.3f) * w;
      v.push_back(vtx(cx + r * std::cos(a), cy + r * std::sin(a) * h / w, i));
    }
    break;
  case GL_TRIANGLES:
    for (int t = 0; t < 10; ++t) {
      const float tx = rng.range(0.2f * w, 0.8f * w), ty = rng.range(0.2f * h, 0.8f * h);
      for (int k = 0; k < 3; ++k)
        v.push_back(vtx(tx + rng.range(-0.3f, 0.3f) * w, ty + rng.range(-0.3f, 0.3f) * h, t + 3 * k));
    }
    break;
  case GL_TRIANGLE_STRIP:
    for (int i = 0; i < 12; ++i) {
      const float x = 0.05f * w + 0.9f * w * static_cast<float>(i / 2) / 5.0f + (i % 2) * 3.0f;
      v.push_back(vtx(x, (i % 2 ? 0.75f : 0.25f) * h + rng.range(-6.0f, 6.0f), i));
    }
    break;
  case GL_TRIANGLE_FAN:
    v.push_back(vtx(cx, cy, 10));
    for (int i = 0; i <= 9; ++i) {
      const float a = 2.0f * kPi * static_cast<float>(i) / 9.0f;
      v.push_back(vtx(cx + 0.45f * w * std::cos(a), cy + 0.45f * h * std::sin(a), i));
    }
    break;
  case GL_QUADS:
    for (int q = 0; q < 6; ++q) {
      const float x0 = 0.05f * w + (q % 2) * 0.47f * w, y0 = 0.05f * h + (q / 2) * 0.31f * h;
      const float qw = 0.42f * w, qh = 0.27f * h;
      v.push_back(vtx(x0, y0, q));
      v.push_back(vtx(x0 + qw, y0 + 2.0f, q));
      v.push_back(vtx(x0 + qw - 3.0f, y0 + qh, q));
      v.push_back(vtx(x0 + 1.0f, y0 + qh - 2.0f, q));
    }
    break;
  case GL_QUAD_STRIP:
    for (int i = 0; i < 7; ++i) {
      const float x = 0.05f * w + 0.9f * w * static_cast<float>(i) / 6.0f;
      v.push_back(vtx(x, 0.15f * h + rng.range(0.0f, 10.0f), i));
      v.push_back(vtx(x, 0.85f * h - rng.range(0.0f, 10.0f), i));
    }
    break;
  default: // GL_POLYGON: a convex octagon with one colour (polygon colours are split-dependent)
    for (int i = 0; i < 8; ++i) {
      const float a = 2.0f * kPi * static_cast<float>(i) / 8.0f + 0.3f;
      v.push_back(vtx(cx + 0.45f * w * std::cos(a), cy + 0.4f * h * std::sin(a), 6));
    }
    break;
  }
  return v;
}

void set_arrays(const std::vector<Vtx>& v) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, sizeof(Vtx), &v[0].x);
  glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vtx), v[0].c);
}

void unset_arrays() {
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
}

constexpr GLenum kModes[10] = {GL_POINTS,         GL_LINES,          GL_LINE_STRIP, GL_LINE_LOOP,
                               GL_TRIANGLES,      GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS,
                               GL_QUAD_STRIP,     GL_POLYGON};

// An n x n grid of shared vertices with smooth colours, indexed as triangles.
struct Grid {
  std::vector<Vtx> vertices;
  std::vector<GLuint> indices;
};

Grid make_grid(float w, float h, int n, std::uint32_t seed) {
  Grid g;
  Rng rng(seed);
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const float jitter_x = (i > 0 && i < n) ? rng.range(-0.3f, 0.3f) : 0.0f;
      const float jitter_y = (j > 0 && j < n) ? rng.range(-0.3f, 0.3f) : 0.0f;
      // Offsets of 0.3 / 0.2 pixel keep the grid's straight border off pixel boundaries, where a
      // line (in GL_LINE mode) would touch two rows of diamonds at once (GL 2.1 §3.4.1).
      g.vertices.push_back(vtx(4.3f + (w - 8.0f) * (i + jitter_x) / n,
                               4.2f + (h - 8.0f) * (j + jitter_y) / n, rng.below(16)));
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const GLuint a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      // Skip a checkerboard of cells so that missing or misplaced triangles show.
      if ((i * 7 + j * 3) % 5 == 0) continue;
      const GLuint tri[6] = {a, b, d, a, d, c};
      g.indices.insert(g.indices.end(), tri, tri + 6);
    }
  }
  return g;
}

} // namespace

PINEDA_SCENE(arrays_draw_arrays, "glDrawArrays with each of the ten modes, one panel each",
             .allowance = kLineAllowance, .why = kLineWhy) {
  clear_frame(0.0f, 0.0f, 0.0f);
  for (int p = 0; p < 10; ++p) {
    const Panel pn = panel(frame, p, 5, 2);
    // Two dummy vertices in front exercise the `first` argument.
    std::vector<Vtx> v{vtx(-50.0f, -50.0f, 0), vtx(-50.0f, -50.0f, 0)};
    for (const Vtx& x : shape_for(kModes[p], static_cast<float>(pn.w), static_cast<float>(pn.h), 300 + p))
      v.push_back(x);
    set_arrays(v);
    glDrawArrays(kModes[p], 2, static_cast<GLsizei>(v.size() - 2));
    unset_arrays();
  }
}

PINEDA_SCENE(arrays_elements, "glDrawElements ubyte/ushort/uint and glDrawRangeElements on a shared-vertex grid") {
  clear_frame(0.0f, 0.0f, 0.0f);
  const auto draw_range = proc<PFNGLDRAWRANGEELEMENTSPROC>("glDrawRangeElements");
  for (int p = 0; p < 4; ++p) {
    const Panel pn = panel(frame, p, 2, 2);
    const Grid g = make_grid(static_cast<float>(pn.w), static_cast<float>(pn.h), 10, 400 + p);
    set_arrays(g.vertices);
    const GLsizei count = static_cast<GLsizei>(g.indices.size());
    if (p == 0) {
      std::vector<GLubyte> idx(g.indices.begin(), g.indices.end());
      glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_BYTE, idx.data());
    } else if (p == 1) {
      std::vector<GLushort> idx(g.indices.begin(), g.indices.end());
      glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_SHORT, idx.data());
    } else if (p == 2) {
      glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, g.indices.data());
    } else {
      // The range covers exactly the referenced vertices (GL 2.1 §2.8).
      GLuint lo = g.indices[0], hi = g.indices[0];
      for (GLuint i : g.indices) {
        lo = i < lo ? i : lo;
        hi = i > hi ? i : hi;
      }
      std::vector<GLushort> idx(g.indices.begin(), g.indices.end());
      draw_range(GL_TRIANGLES, lo, hi, count, GL_UNSIGNED_SHORT, idx.data());
    }
    unset_arrays();
  }
}

PINEDA_SCENE(arrays_array_element, "glArrayElement inside glBegin/glEnd, mixed with immediate colours") {
  clear_frame(0.0f, 0.0f, 0.0f);
  const Grid g = make_grid(static_cast<float>(frame.width), static_cast<float>(frame.height), 12, 500);
  set_arrays(g.vertices);
  glBegin(GL_TRIANGLES);
  for (std::size_t i = 0; i < g.indices.size() / 2; ++i) glArrayElement(static_cast<GLint>(g.indices[i]));
  glEnd();
  // Second half: colour array off, so glArrayElement uses the current colour, which changes
  // between triangles with immediate glColor calls (GL 2.1 §2.8).
  glDisableClientState(GL_COLOR_ARRAY);
  glBegin(GL_TRIANGLES);
  for (std::size_t i = g.indices.size() / 2; i < g.indices.size(); ++i) {
    if (i % 3 == 0) palette_color(static_cast<int>(i / 3));
    glArrayElement(static_cast<GLint>(g.indices[i]));
  }
  glEnd();
  unset_arrays();
}

PINEDA_SCENE(arrays_types_strides, "Vertex arrays of short/int/float/double x 2/3/4 and colour arrays of all eight types") {
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLenum vertex_types[4] = {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE};
  const GLenum colour_types[8] = {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT,
                                  GL_INT,  GL_UNSIGNED_INT,  GL_FLOAT, GL_DOUBLE};
  for (int p = 0; p < 16; ++p) {
    const Panel pn = panel(frame, p, 4, 4);
    const GLenum vtype = vertex_types[p % 4];
    const GLint vsize = 2 + (p / 4) % 3;
    const GLenum ctype = colour_types[p % 8];
    const GLint csize = 3 + p / 8;
    // One interleaved record per vertex: 4 position slots of 8 bytes, 4 colour slots of 8 bytes
    // and padding, so the stride (72) is never the tightly packed size.
    constexpr int kStride = 72;
    const int n = 6; // a triangle fan of 6 vertices
    std::vector<unsigned char> data(kStride * n, 0);
    const float pts[6][2] = {{0.5f, 0.5f}, {0.05f, 0.1f}, {0.9f, 0.05f},
                             {0.95f, 0.8f}, {0.4f, 0.95f}, {0.06f, 0.7f}};
    for (int i = 0; i < n; ++i) {
      unsigned char* rec = data.data() + i * kStride;
      // Integer types get whole pixels; w = 1 for 4-component positions.
      const double pos[4] = {std::floor(pts[i][0] * pn.w) + (vtype == GL_FLOAT || vtype == GL_DOUBLE ? 0.25 : 0.0),
                             std::floor(pts[i][1] * pn.h) + (vtype == GL_FLOAT || vtype == GL_DOUBLE ? 0.25 : 0.0),
                             0.0, 1.0};
      for (int k = 0; k < vsize; ++k) {
        unsigned char* slot = rec + 8 * k;
        // Components are packed at the type's size, not at the 8-byte slot size.
        switch (vtype) {
        case GL_SHORT: { const GLshort s = GLshort(pos[k]); std::memcpy(rec + 2 * k, &s, 2); break; }
        case GL_INT: { const GLint v = GLint(pos[k]); std::memcpy(rec + 4 * k, &v, 4); break; }
        case GL_FLOAT: { const GLfloat f = GLfloat(pos[k]); std::memcpy(rec + 4 * k, &f, 4); break; }
        default: std::memcpy(slot, &pos[k], 8); break;
        }
      }
      const float* c = palette(i + p);
      const double level[4] = {c[0], c[1], c[2], 0.25 + 0.125 * i};
      unsigned char* col = rec + 32;
      for (int k = 0; k < csize; ++k) {
        const double l = level[k];
        switch (ctype) {
        case GL_BYTE: { const GLbyte v = GLbyte(std::lround(l * 127)); std::memcpy(col + k, &v, 1); break; }
        case GL_UNSIGNED_BYTE: { const GLubyte v = GLubyte(std::lround(l * 255)); std::memcpy(col + k, &v, 1); break; }
        case GL_SHORT: { const GLshort v = GLshort(std::lround(l * 32767)); std::memcpy(col + 2 * k, &v, 2); break; }
        case GL_UNSIGNED_SHORT: { const GLushort v = GLushort(std::lround(l * 65535)); std::memcpy(col + 2 * k, &v, 2); break; }
        case GL_INT: { const GLint v = GLint(std::llround(l * 2147483647.0)); std::memcpy(col + 4 * k, &v, 4); break; }
        case GL_UNSIGNED_INT: { const GLuint v = GLuint(std::llround(l * 4294967295.0)); std::memcpy(col + 4 * k, &v, 4); break; }
        case GL_FLOAT: { const GLfloat v = GLfloat(l); std::memcpy(col + 4 * k, &v, 4); break; }
        default: std::memcpy(col + 8 * k, &l, 8); break;
        }
      }
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(vsize, vtype, kStride, data.data());
    glColorPointer(csize, ctype, kStride, data.data() + 32);
    glDrawArrays(GL_TRIANGLE_FAN, 0, n);
    unset_arrays();
  }
}

PINEDA_SCENE(arrays_multi_draw, "glMultiDrawArrays and glMultiDrawElements with several sub-draws") {
  clear_frame(0.0f, 0.0f, 0.0f);
  const auto multi_arrays = proc<PFNGLMULTIDRAWARRAYSPROC>("glMultiDrawArrays");
  const auto multi_elements = proc<PFNGLMULTIDRAWELEMENTSPROC>("glMultiDrawElements");
  // Left: five triangle fans from one array via glMultiDrawArrays (one with count 0).
  panel(frame, 0, 2, 1);
  std::vector<Vtx> fans;
  GLint firsts[5];
  GLsizei counts[5];
  for (int f = 0; f < 5; ++f) {
    firsts[f] = static_cast<GLint>(fans.size());
    const float cx = 62.3f, cy = 26.1f + 48.0f * f, r = 22.0f + 4.0f * (f % 2);
    fans.push_back(vtx(cx, cy, f + 10));
    for (int i = 0; i <= 7 + f; ++i) {
      const float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(7 + f);
      fans.push_back(vtx(cx + 2.2f * r * std::cos(a), cy + r * std::sin(a), i + f));
    }
    counts[f] = f == 3 ? 0 : static_cast<GLsizei>(fans.size()) - firsts[f];
  }
  set_arrays(fans);
  multi_arrays(GL_TRIANGLE_FAN, firsts, counts, 5);
  unset_arrays();
  // Right: triangle strips of a grid through glMultiDrawElements, one index list per row.
  const Panel pn = panel(frame, 1, 2, 1);
  const int cols = 8, rows = 10;
  std::vector<Vtx> grid;
  Rng rng(600);
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= cols; ++i)
      grid.push_back(vtx(4.0f + (pn.w - 8.0f) * i / cols + rng.range(-2.0f, 2.0f),
                         4.0f + (pn.h - 8.0f) * j / rows + rng.range(-2.0f, 2.0f), rng.below(16)));
  std::vector<std::vector<GLuint>> strips(rows);
  std::vector<const GLvoid*> pointers(rows);
  std::vector<GLsizei> strip_counts(rows);
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i <= cols; ++i) {
      strips[j].push_back(static_cast<GLuint>(j * (cols + 1) + i));
      strips[j].push_back(static_cast<GLuint>((j + 1) * (cols + 1) + i));
    }
    pointers[j] = strips[j].data();
    strip_counts[j] = j % 4 == 2 ? 6 : static_cast<GLsizei>(strips[j].size());
  }
  set_arrays(grid);
  multi_elements(GL_TRIANGLE_STRIP, strip_counts.data(), GL_UNSIGNED_INT, pointers.data(), rows);
  unset_arrays();
}

PINEDA_SCENE(arrays_edge_flags, "glEdgeFlagPointer with polygons in GL_LINE mode",
             .allowance = kLineAllowance, .why = kLineWhy) {
  clear_frame(0.0f, 0.0f, 0.0f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  const Grid g = make_grid(static_cast<float>(frame.width), static_cast<float>(frame.height), 8, 700);
  // The interior diagonal of every cell is hidden: in each triangle (a, b, d) / (a, d, c) the
  // edge starting at d (b->d->a, and a->d is the first edge of the second) is flagged off.
  std::vector<GLboolean> flags(g.vertices.size(), GL_TRUE);
  std::vector<Vtx> expanded;
  std::vector<GLboolean> expanded_flags;
  for (std::size_t i = 0; i < g.indices.size(); ++i) {
    expanded.push_back(g.vertices[g.indices[i]]);
    const std::size_t corner = i % 6;
    expanded_flags.push_back(corner == 1 || corner == 3 ? GL_FALSE : GL_TRUE);
  }
  set_arrays(expanded);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  glEdgeFlagPointer(0, expanded_flags.data());
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(expanded.size()));
  glDisableClientState(GL_EDGE_FLAG_ARRAY);
  unset_arrays();
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

PINEDA_SCENE(arrays_interleaved, "All fourteen glInterleavedArrays formats, one panel each") {
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLenum formats[14] = {GL_V2F,        GL_V3F,          GL_C4UB_V2F,      GL_C4UB_V3F,
                              GL_C3F_V3F,    GL_N3F_V3F,      GL_C4F_N3F_V3F,   GL_T2F_V3F,
                              GL_T4F_V4F,    GL_T2F_C4UB_V3F, GL_T2F_C3F_V3F,   GL_T2F_N3F_V3F,
                              GL_T2F_C4F_N3F_V3F, GL_T4F_C4F_N3F_V4F};
  // Layout of each format (GL 2.1 Table 2.5): texture, colour, normal, vertex components.
  struct Layout { int t, c, n, v; bool ub; };
  const Layout layouts[14] = {{0, 0, 0, 2, false}, {0, 0, 0, 3, false}, {0, 4, 0, 2, true},
                              {0, 4, 0, 3, true},  {0, 3, 0, 3, false}, {0, 0, 3, 3, false},
                              {0, 4, 3, 3, false}, {2, 0, 0, 3, false}, {4, 0, 0, 4, false},
                              {2, 4, 0, 3, true},  {2, 3, 0, 3, false}, {2, 0, 3, 3, false},
                              {2, 4, 3, 3, false}, {4, 4, 3, 4, false}};
  for (int p = 0; p < 14; ++p) {
    const Panel pn = panel(frame, p, 4, 4);
    const Layout& L = layouts[p];
    const int natural = 4 * (L.t + (L.ub ? 1 : L.c) + L.n + L.v);
    // Odd panels use an explicit stride larger than the natural one.
    const int stride = p % 2 ? natural + 12 : natural;
    const std::vector<Vtx> shape = shape_for(GL_TRIANGLE_FAN, static_cast<float>(pn.w),
                                             static_cast<float>(pn.h), 800 + p);
    std::vector<unsigned char> data(static_cast<std::size_t>(stride) * shape.size(), 0);
    for (std::size_t i = 0; i < shape.size(); ++i) {
      float* out = reinterpret_cast<float*>(data.data() + i * static_cast<std::size_t>(stride));
      for (int k = 0; k < L.t; ++k) *out++ = 0.5f * k;
      if (L.ub) {
        std::memcpy(out, shape[i].c, 4);
        ++out;
      } else {
        for (int k = 0; k < L.c; ++k) *out++ = shape[i].c[k] / 255.0f;
      }
      for (int k = 0; k < L.n; ++k) *out++ = k == 2 ? 1.0f : 0.0f;
      // Four-component positions carry w = 2 with x, y doubled.
      const float w = L.v == 4 ? 2.0f : 1.0f;
      *out++ = shape[i].x * w;
      *out++ = shape[i].y * w;
      if (L.v >= 3) *out++ = 0.0f;
      if (L.v == 4) *out++ = w;
    }
    // Formats without colour draw with the current colour (the array is disabled by the call).
    palette_color(p + 3);
    glInterleavedArrays(formats[p], p % 2 ? stride : 0, data.data());
    glDrawArrays(GL_TRIANGLE_FAN, 0, static_cast<GLsizei>(shape.size()));
    for (GLenum a : {GL_VERTEX_ARRAY, GL_COLOR_ARRAY, GL_NORMAL_ARRAY, GL_TEXTURE_COORD_ARRAY})
      glDisableClientState(a);
  }
}
