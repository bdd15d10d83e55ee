// Rasterization on worker threads (issue 6, src/raster/workers.h, src/raster/bin.h): a context with
// PINEDA_THREADS=2, 3 or 5, sharing triangles by bands or by bins (PINEDA_RASTER), must
// produce the same colour, depth and stencil buffers, byte for byte, and the same occlusion
// query counts as one with PINEDA_THREADS=1, which draws
// everything on the calling thread. The scenes make the draws large enough to be shared and
// cover every rasterizer path: triangles (smooth, flat, textured, fog, polygon stipple, offset,
// outlined polygons), aliased, wide, stippled and smooth lines, aliased and smooth points,
// blending, depth, stencil, scissored and masked clears. scripts/tsan.sh runs them under
// ThreadSanitizer.
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <dirent.h>
#include <string>
#include <vector>

namespace {

// Large enough for the clears to be shared (at least 512K pixels); odd sizes so the last band
// and the last block column are partial.
constexpr int kW = 931, kH = 601;

using BeginQueryFn = void(GLAPIENTRY*)(GLenum, GLuint);
using EndQueryFn = void(GLAPIENTRY*)(GLenum);
using GetQueryObjectuivFn = void(GLAPIENTRY*)(GLuint, GLenum, GLuint*);

struct Result {
  std::vector<uint8_t> color;
  std::vector<uint8_t> depth; // the depth buffer's bytes
  std::vector<uint8_t> stencil;
  std::vector<GLuint> samples; // occlusion query results
  int threads_started = 0;     // threads the process gained while the context lived
  int threads_left = 0;        // threads still there after the context was destroyed
  GLenum error = GL_NO_ERROR;
};

// Deterministic pseudo-random numbers (the same sequence for every thread count).
struct Rng {
  uint32_t s;
  float unit() {
    s = s * 1664525u + 1013904223u;
    return static_cast<float>(s >> 8) / 16777216.0f;
  }
  float range(float a, float b) { return a + (b - a) * unit(); }
};

int task_count() {
  int n = 0;
  if (DIR* d = opendir("/proc/self/task")) {
    while (dirent* e = readdir(d))
      if (e->d_name[0] != '.') ++n;
    closedir(d);
  }
  return n;
}

void ortho() {
  glViewport(0, 0, kW, kH);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kW, 0, kH, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

void clear_all(float r, float g, float b) {
  glClearColor(r, g, b, 1);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

// Many smooth and flat triangles (one draw of thousands of vertices) and a few large ones
// (one draw each), depth tested, some crossing the window edges and the near plane.
void scene_triangles(Rng& rng) {
  clear_all(0.1f, 0.1f, 0.2f);
  glEnable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 3000; ++i) {
    const float x = rng.range(-20, kW + 20), y = rng.range(-20, kH + 20);
    const float z = rng.range(-1.2f, 1.2f);
    for (int k = 0; k < 3; ++k) {
      glColor4f(rng.unit(), rng.unit(), rng.unit(), 1);
      glVertex3f(x + rng.range(-25, 25), y + rng.range(-25, 25), z + rng.range(-0.1f, 0.1f));
    }
  }
  glEnd();
  // A lit draw of more than 4096 vertices: transformed and lit by every worker, each taking a
  // range of the vertices (draw/draw.cpp).
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  const float pos1[4] = {static_cast<float>(kW), 0, 200, 1};
  glLightfv(GL_LIGHT1, GL_POSITION, pos1);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_NORMALIZE);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 2000; ++i) {
    const float x = rng.range(0, kW), y = rng.range(0, kH);
    for (int k = 0; k < 3; ++k) {
      glColor3f(rng.unit(), rng.unit(), rng.unit());
      glNormal3f(rng.range(-1, 1), rng.range(-1, 1), 1);
      glVertex3f(x + rng.range(-15, 15), y + rng.range(-15, 15), rng.range(-0.9f, 0.9f));
    }
  }
  glEnd();
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  glDisable(GL_NORMALIZE);
  glDisable(GL_COLOR_MATERIAL);
  glDisable(GL_LIGHT1);
  glDisable(GL_LIGHT0);
  glDisable(GL_LIGHTING);
  glShadeModel(GL_FLAT);
  for (int i = 0; i < 6; ++i) {
    glBegin(GL_TRIANGLE_FAN);
    for (int k = 0; k < 5; ++k) {
      glColor3f(rng.unit(), rng.unit(), rng.unit());
      glVertex3f(rng.range(-50, kW + 50), rng.range(-50, kH + 50), rng.range(-1, 1));
    }
    glEnd();
  }
  glShadeModel(GL_SMOOTH);
  glDisable(GL_DEPTH_TEST);
}

// Alpha blending of overlapping quads in one draw, with a scissor box.
void scene_blend(Rng& rng) {
  clear_all(0.2f, 0.2f, 0.2f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_SCISSOR_TEST);
  glScissor(13, 7, kW - 40, kH - 30);
  glBegin(GL_QUADS);
  for (int i = 0; i < 400; ++i) {
    const float x = rng.range(-60, kW), y = rng.range(-60, kH), s = rng.range(10, 160);
    glColor4f(rng.unit(), rng.unit(), rng.unit(), rng.range(0.1f, 0.7f));
    glVertex2f(x, y);
    glVertex2f(x + s, y);
    glColor4f(rng.unit(), rng.unit(), rng.unit(), rng.range(0.1f, 0.7f));
    glVertex2f(x + s, y + s);
    glVertex2f(x, y + s);
  }
  glEnd();
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
}

// Stencil: overlapping quads increment the stencil buffer (with depth-fail and pass
// operations), then a full-window quad draws where the count is 2, and the stencil mask
// limits a clear.
void scene_stencil(Rng& rng) {
  clear_all(0, 0, 0);
  glEnable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_DECR, GL_INCR);
  glBegin(GL_QUADS);
  for (int i = 0; i < 300; ++i) {
    const float x = rng.range(-30, kW), y = rng.range(-30, kH), s = rng.range(20, 120);
    const float z = rng.range(-1, 1);
    glColor3f(rng.unit(), rng.unit(), rng.unit());
    glVertex3f(x, y, z);
    glVertex3f(x + s, y, z);
    glVertex3f(x + s, y + s, z);
    glVertex3f(x, y + s, z);
  }
  glEnd();
  glDisable(GL_DEPTH_TEST);
  glStencilFunc(GL_EQUAL, 2, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
  glColor3f(1, 1, 0);
  glRectf(0, 0, kW, kH);
  glDisable(GL_STENCIL_TEST);
  glStencilMask(0x0f);
  glClearStencil(0x5a);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glClearColor(0.5f, 0.25f, 0.75f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilMask(0xff);
}

// Lines: many 1-pixel segments, stippled strips and loops, wide lines, smooth (blended) lines
// and stippled smooth lines; the stipple counter runs across the segments of each strip.
void scene_lines(Rng& rng) {
  clear_all(0, 0, 0);
  glBegin(GL_LINES);
  for (int i = 0; i < 1200; ++i) {
    glColor3f(rng.unit(), rng.unit(), rng.unit());
    glVertex2f(rng.range(-10, kW + 10), rng.range(-10, kH + 10));
    glColor3f(rng.unit(), rng.unit(), rng.unit());
    glVertex2f(rng.range(-10, kW + 10), rng.range(-10, kH + 10));
  }
  glEnd();
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(3, 0x5f3a);
  for (int w = 1; w <= 7; w += 3) {
    glLineWidth(static_cast<float>(w));
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 40; ++i) {
      glColor3f(rng.unit(), rng.unit(), rng.unit());
      glVertex2f(rng.range(0, kW), rng.range(0, kH));
    }
    glEnd();
    glBegin(GL_LINE_LOOP);
    for (int i = 0; i < 7; ++i)
      glVertex2f(rng.range(0, kW), rng.range(0, kH));
    glEnd();
  }
  glDisable(GL_LINE_STIPPLE);
  glLineWidth(9);
  glBegin(GL_LINES);
  for (int i = 0; i < 20; ++i) {
    glColor3f(rng.unit(), rng.unit(), rng.unit());
    glVertex2f(rng.range(0, kW), rng.range(0, kH));
    glVertex2f(rng.range(0, kW), rng.range(0, kH));
  }
  glEnd();
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      glEnable(GL_LINE_STIPPLE);
      glLineStipple(2, 0x33f1);
    }
    glLineWidth(pass == 0 ? 1.0f : 4.0f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 30; ++i) {
      glColor4f(rng.unit(), rng.unit(), rng.unit(), rng.range(0.5f, 1));
      glVertex2f(rng.range(0, kW), rng.range(0, kH));
    }
    glEnd();
  }
  glDisable(GL_LINE_STIPPLE);
  glDisable(GL_BLEND);
  glDisable(GL_LINE_SMOOTH);
  glLineWidth(1);
}

// Points: thousands of 1-pixel points, then wide aliased and smooth points.
void scene_points(Rng& rng) {
  clear_all(0, 0, 0.1f);
  glBegin(GL_POINTS);
  for (int i = 0; i < 3000; ++i) {
    glColor3f(rng.unit(), rng.unit(), rng.unit());
    glVertex2f(rng.range(-5, kW + 5), rng.range(-5, kH + 5));
  }
  glEnd();
  glPointSize(6);
  glBegin(GL_POINTS);
  for (int i = 0; i < 1500; ++i) {
    glColor3f(rng.unit(), rng.unit(), rng.unit());
    glVertex2f(rng.range(0, kW), rng.range(0, kH));
  }
  glEnd();
  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glPointSize(40);
  glBegin(GL_POINTS);
  for (int i = 0; i < 60; ++i) {
    glColor4f(rng.unit(), rng.unit(), rng.unit(), rng.range(0.3f, 1));
    glVertex2f(rng.range(0, kW), rng.range(0, kH));
  }
  glEnd();
  glDisable(GL_BLEND);
  glDisable(GL_POINT_SMOOTH);
  glPointSize(1);
}

// Polygon stipple, polygon offset, and outlined polygons (LINE mode with a line stipple, POINT
// mode for the back faces).
void scene_polygon_modes(Rng& rng) {
  clear_all(0, 0, 0);
  GLubyte pattern[128];
  for (int i = 0; i < 128; ++i)
    pattern[i] = static_cast<GLubyte>((i * 37) ^ (i >> 2) ^ 0xa5);
  glPolygonStipple(pattern);
  glEnable(GL_POLYGON_STIPPLE);
  glEnable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 12; ++i) {
    glColor3f(rng.unit(), rng.unit(), rng.unit());
    glVertex3f(static_cast<float>(i) * kW / 11.0f, (i & 1) ? kH - 10.0f : 10.0f, 0.2f);
  }
  glEnd();
  glDisable(GL_POLYGON_STIPPLE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 4.0f);
  glBegin(GL_QUADS);
  glColor3f(0.3f, 0.8f, 0.3f);
  glVertex3f(20, 20, -0.5f);
  glVertex3f(kW - 20.0f, 40, 0.7f);
  glVertex3f(kW - 40.0f, kH - 20.0f, 0.1f);
  glVertex3f(30, kH - 50.0f, -0.2f);
  glEnd();
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_DEPTH_TEST);
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_POINT);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(1, 0x0f0f);
  glLineWidth(2);
  glPointSize(3);
  glBegin(GL_QUADS);
  for (int i = 0; i < 300; ++i) {
    const float x = rng.range(0, kW), y = rng.range(0, kH), s = rng.range(10, 90);
    const bool back = i % 3 == 0;
    glColor3f(rng.unit(), rng.unit(), rng.unit());
    glVertex2f(x, y);
    glVertex2f(back ? x : x + s, back ? y + s : y);
    glVertex2f(x + s, y + s);
    glVertex2f(back ? x + s : x, back ? y : y + s);
  }
  glEnd();
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDisable(GL_LINE_STIPPLE);
  glLineWidth(1);
  glPointSize(1);
}

// A mipmapped texture on a perspective ground plane (clipped by the near plane) and on many
// triangles, with fog and the alpha test.
void scene_textured(Rng& rng) {
  clear_all(0.3f, 0.4f, 0.6f);
  std::vector<uint8_t> level;
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  for (int l = 0, size = 64; size >= 1; ++l, size /= 2) {
    level.assign(static_cast<size_t>(size * size * 4), 0);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        uint8_t* p = &level[static_cast<size_t>((y * size + x) * 4)];
        const bool check = ((x * 8 / size) + (y * 8 / size)) % 2 == 0;
        p[0] = static_cast<uint8_t>(check ? 230 : 30 * l);
        p[1] = static_cast<uint8_t>(x * 255 / size);
        p[2] = static_cast<uint8_t>(y * 255 / size);
        p[3] = static_cast<uint8_t>(check ? 255 : 100);
      }
    glTexImage2D(GL_TEXTURE_2D, l, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, level.data());
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 2);
  glFogf(GL_FOG_END, 40);
  const GLfloat fog_color[4] = {0.5f, 0.5f, 0.55f, 1};
  glFogfv(GL_FOG_COLOR, fog_color);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.3f);
  glEnable(GL_DEPTH_TEST);
  glViewport(0, 0, kW, kH);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.6, 0.6, -0.4, 0.4, 0.5, 60);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glColor3f(1, 1, 1);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex3f(-30, -1.5f, -50);
  glTexCoord2f(24, 0);
  glVertex3f(30, -1.5f, -50);
  glTexCoord2f(24, 24);
  glVertex3f(30, -1.5f, 1);
  glTexCoord2f(0, 24);
  glVertex3f(-30, -1.5f, 1);
  glEnd();
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 500; ++i) {
    const float x = rng.range(-4, 4), y = rng.range(-1.5f, 3), z = rng.range(-20, -3);
    for (int k = 0; k < 3; ++k) {
      glColor3f(rng.range(0.5f, 1), rng.range(0.5f, 1), 1);
      glTexCoord2f(rng.range(0, 4), rng.range(0, 4));
      glVertex3f(x + rng.range(-0.5f, 0.5f), y + rng.range(-0.5f, 0.5f), z + rng.range(-1, 1));
    }
  }
  glEnd();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_ALPHA_TEST);
  glDisable(GL_FOG);
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(1, &tex);
  ortho();
}

// Occlusion queries around shared draws: the counts summed over the workers must equal the
// single-threaded ones.
void scene_queries(Rng& rng, std::vector<GLuint>& samples) {
  const auto begin_query = reinterpret_cast<BeginQueryFn>(OSMesaGetProcAddress("glBeginQuery"));
  const auto end_query = reinterpret_cast<EndQueryFn>(OSMesaGetProcAddress("glEndQuery"));
  const auto get_result =
      reinterpret_cast<GetQueryObjectuivFn>(OSMesaGetProcAddress("glGetQueryObjectuiv"));
  if (begin_query == nullptr || end_query == nullptr || get_result == nullptr) return;
  clear_all(0, 0, 0);
  glEnable(GL_DEPTH_TEST);
  for (GLuint q = 1; q <= 4; ++q) {
    begin_query(GL_SAMPLES_PASSED, q);
    switch (q) {
    case 1:
    case 2:
      glBegin(GL_TRIANGLES);
      for (int i = 0; i < 1500; ++i) {
        const float x = rng.range(0, kW), y = rng.range(0, kH), z = rng.range(-1, 1);
        glColor3f(rng.unit(), rng.unit(), rng.unit());
        for (int k = 0; k < 3; ++k)
          glVertex3f(x + rng.range(-30, 30), y + rng.range(-30, 30), z);
      }
      glEnd();
      break;
    case 3:
      glRectf(-10, -10, kW + 10.0f, kH + 10.0f);
      break;
    default:
      glLineWidth(5);
      glBegin(GL_LINE_STRIP);
      for (int i = 0; i < 50; ++i)
        glVertex3f(rng.range(0, kW), rng.range(0, kH), -0.99f);
      glEnd();
      glLineWidth(1);
      break;
    }
    end_query(GL_SAMPLES_PASSED);
  }
  for (GLuint q = 1; q <= 4; ++q) {
    GLuint n = 0;
    get_result(q, GL_QUERY_RESULT, &n);
    samples.push_back(n);
  }
  glDisable(GL_DEPTH_TEST);
}

// Binned draws (src/raster/bin.h) of every triangle mode: vertex arrays drawn with
// DrawArrays and DrawElements as strips, fans, quad strips and polygons spanning many tiles,
// two-sided lighting with front faces culled, and 12000 small triangles in one draw (several
// batches of setup for any thread count up to five).
void scene_triangle_modes(Rng& rng) {
  clear_all(0, 0, 0);
  glEnable(GL_DEPTH_TEST);
  std::vector<float> pos, col;
  const auto vertex = [&](float x, float y, float z) {
    pos.insert(pos.end(), {x, y, z});
    col.insert(col.end(), {rng.unit(), rng.unit(), rng.unit(), 1.0f});
  };
  for (int i = 0; i < 36000; ++i) {
    const float x = rng.range(-10, kW + 10), y = rng.range(-10, kH + 10);
    vertex(x + rng.range(-4, 4), y + rng.range(-4, 4), rng.range(-1, 1));
  }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, pos.data());
  glColorPointer(4, GL_FLOAT, 0, col.data());
  glDrawArrays(GL_TRIANGLES, 0, 36000);
  // A zigzag strip and a quad strip across the window, a fan and a polygon around its centre.
  pos.clear();
  col.clear();
  for (int i = 0; i < 400; ++i)
    vertex(static_cast<float>(i) * kW / 399.0f,
           (i & 1) ? kH - rng.range(0, 100) : rng.range(0, 100), rng.range(-0.9f, 0.9f));
  glVertexPointer(3, GL_FLOAT, 0, pos.data());
  glColorPointer(4, GL_FLOAT, 0, col.data());
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 400);
  std::vector<GLuint> reversed(400);
  for (GLuint i = 0; i < 400; ++i)
    reversed[i] = 399 - i;
  glDrawElements(GL_QUAD_STRIP, 400, GL_UNSIGNED_INT, reversed.data());
  pos.clear();
  col.clear();
  vertex(kW / 2.0f, kH / 2.0f, 0.5f);
  for (int i = 0; i <= 600; ++i) {
    const float a = static_cast<float>(i) * 6.2831853f / 600.0f;
    const float r = rng.range(200, 500);
    vertex(kW / 2.0f + r * std::cos(a), kH / 2.0f + r * std::sin(a), rng.range(-0.5f, 0.9f));
  }
  glVertexPointer(3, GL_FLOAT, 0, pos.data());
  glColorPointer(4, GL_FLOAT, 0, col.data());
  glDrawArrays(GL_TRIANGLE_FAN, 0, 602);
  glDrawArrays(GL_POLYGON, 1, 601);
  glDisableClientState(GL_COLOR_ARRAY);
  // Two-sided lighting, front faces culled: the back faces take the back material.
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  const float front[4] = {1, 0, 0, 1}, back[4] = {0, 0.5f, 1, 1};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, front);
  glMaterialfv(GL_BACK, GL_DIFFUSE, back);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  glNormal3f(0, 0, 1);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 2000; ++i) {
    const float x = rng.range(0, kW), y = rng.range(0, kH), z = rng.range(-0.95f, 0.95f);
    for (int k = 0; k < 3; ++k)
      glVertex3f(x + rng.range(-40, 40), y + rng.range(-40, 40), z);
  }
  glEnd();
  glDisable(GL_CULL_FACE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  glDisable(GL_LIGHT0);
  glDisable(GL_LIGHTING);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisable(GL_DEPTH_TEST);
}

// Renders scene `which` in a new context with PINEDA_THREADS=threads and PINEDA_RASTER=raster.
Result render(int which, int threads, const char* raster = "bands") {
  Result r;
  setenv("PINEDA_THREADS", std::to_string(threads).c_str(), 1);
  setenv("PINEDA_RASTER", raster, 1);
  const int tasks_before = task_count();
  r.color.assign(static_cast<size_t>(kW) * kH * 4, 0);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (ctx == nullptr || !OSMesaMakeCurrent(ctx, r.color.data(), GL_UNSIGNED_BYTE, kW, kH)) {
    r.error = GL_INVALID_OPERATION;
    return r;
  }
  ortho();
  Rng rng{static_cast<uint32_t>(1234 + which)};
  switch (which) {
  case 0:
    scene_triangles(rng);
    break;
  case 1:
    scene_blend(rng);
    break;
  case 2:
    scene_stencil(rng);
    break;
  case 3:
    scene_lines(rng);
    break;
  case 4:
    scene_points(rng);
    break;
  case 5:
    scene_polygon_modes(rng);
    break;
  case 6:
    scene_textured(rng);
    break;
  case 8:
    scene_triangle_modes(rng);
    break;
  default:
    scene_queries(rng, r.samples);
    break;
  }
  glFinish();
  r.error = glGetError();
  r.threads_started = task_count() - tasks_before;
  GLint w = 0, h = 0, bpv = 0;
  void* depth = nullptr;
  if (OSMesaGetDepthBuffer(ctx, &w, &h, &bpv, &depth) && depth != nullptr)
    r.depth.assign(static_cast<const uint8_t*>(depth),
                   static_cast<const uint8_t*>(depth) + static_cast<size_t>(w) * h * bpv);
  r.stencil.assign(static_cast<size_t>(kW) * kH, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, kW, kH, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, r.stencil.data());
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);
  r.threads_left = task_count() - tasks_before;
  unsetenv("PINEDA_THREADS");
  unsetenv("PINEDA_RASTER");
  return r;
}

// Index of the first differing byte, or -1.
long first_difference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  if (a.size() != b.size()) return 0;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) return static_cast<long>(i);
  return -1;
}

constexpr const char* kSceneNames[] = {"triangles", "blend",   "stencil",
                                       "lines",     "points",  "polygon_modes",
                                       "textured",  "queries", "triangle_modes"};

class RasterThreads : public testing::TestWithParam<int> {};

TEST_P(RasterThreads, SameBuffersAndCountsForAnyThreadCount) {
  const int which = GetParam();
  const Result one = render(which, 1);
  ASSERT_EQ(one.error, static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(one.threads_started, 0) << "PINEDA_THREADS=1 starts no thread";
  if (which == 7) {
    EXPECT_EQ(one.samples.size(), 4u);
  }
  for (int threads : {2, 3, 5})
    for (const char* raster : {"bands", "bins"}) {
      SCOPED_TRACE(raster);
      const Result r = render(which, threads, raster);
      ASSERT_EQ(r.error, static_cast<GLenum>(GL_NO_ERROR)) << threads;
      // The context's workers were started (the scene has shared draws) and are joined when it
      // is destroyed.
      EXPECT_EQ(r.threads_started, threads - 1) << threads;
      EXPECT_EQ(r.threads_left, 0) << threads;
      const long c = first_difference(one.color, r.color);
      EXPECT_EQ(c, -1) << "colour differs with " << threads << " threads at pixel " << (c / 4) % kW
                       << "," << (c / 4) / kW;
      EXPECT_EQ(first_difference(one.depth, r.depth), -1) << "depth, " << threads << " threads";
      EXPECT_EQ(first_difference(one.stencil, r.stencil), -1)
          << "stencil, " << threads << " threads";
      EXPECT_EQ(one.samples, r.samples) << threads << " threads";
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, RasterThreads, testing::Range(0, 9),
                         [](const testing::TestParamInfo<int>& param_info) {
                           return std::string(kSceneNames[param_info.param]);
                         });

} // namespace
