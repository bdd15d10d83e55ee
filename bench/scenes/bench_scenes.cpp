// The scene benchmark's scenes (issue 6): heavy, deterministic frames that Pineda, llvmpipe and
// softpipe render in the same run (scripts/bench.sh). They are registered with the same
// PINEDA_SCENE macro as the conformance scenes but compiled into their own runner
// (pineda_bench_runner), so they never slow down the conformance tests.
#include "bench_geometry.h"
#include "scene_util.h"
#include "sweep_common.h"

#include <cmath>
#include <vector>

using namespace scenes;
using bench::Mesh;
using bench::perspective_view;
using bench::torus;

namespace {

void light_setup() {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  const GLfloat p0[4] = {0.5f, 1.0f, 2.0f, 0.0f}, p1[4] = {-3.0f, -1.0f, 2.0f, 1.0f};
  const GLfloat d1[4] = {0.4f, 0.4f, 0.8f, 1.0f}, spec[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, p0);
  glLightfv(GL_LIGHT1, GL_POSITION, p1);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, d1);
  glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
  const GLfloat amb[4] = {0.2f, 0.15f, 0.1f, 1}, dif[4] = {0.8f, 0.6f, 0.3f, 1};
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
}

// The classic gear of glxgears: a toothed wheel as quads and quad strips.
void gear(float inner, float outer, float width, int teeth, float tooth_depth) {
  const float r0 = inner, r1 = outer - tooth_depth / 2.0f, r2 = outer + tooth_depth / 2.0f;
  const float da = 2.0f * kPi / static_cast<float>(teeth) / 4.0f;
  glShadeModel(GL_FLAT);
  glNormal3f(0, 0, 1);
  for (int side = 0; side < 2; ++side) {
    const float z = side == 0 ? width * 0.5f : -width * 0.5f;
    if (side == 1) glNormal3f(0, 0, -1);
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= teeth; ++i) {
      const float a = static_cast<float>(i) * 2.0f * kPi / static_cast<float>(teeth);
      glVertex3f(r0 * std::cos(a), r0 * std::sin(a), z);
      glVertex3f(r1 * std::cos(a), r1 * std::sin(a), z);
      if (i < teeth) {
        glVertex3f(r0 * std::cos(a), r0 * std::sin(a), z);
        glVertex3f(r1 * std::cos(a + 3 * da), r1 * std::sin(a + 3 * da), z);
      }
    }
    glEnd();
    glBegin(GL_QUADS);
    for (int i = 0; i < teeth; ++i) {
      const float a = static_cast<float>(i) * 2.0f * kPi / static_cast<float>(teeth);
      glVertex3f(r1 * std::cos(a), r1 * std::sin(a), z);
      glVertex3f(r2 * std::cos(a + da), r2 * std::sin(a + da), z);
      glVertex3f(r2 * std::cos(a + 2 * da), r2 * std::sin(a + 2 * da), z);
      glVertex3f(r1 * std::cos(a + 3 * da), r1 * std::sin(a + 3 * da), z);
    }
    glEnd();
  }
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i < teeth; ++i) {
    const float a = static_cast<float>(i) * 2.0f * kPi / static_cast<float>(teeth);
    const float pts[4][2] = {{r1 * std::cos(a), r1 * std::sin(a)},
                             {r2 * std::cos(a + da), r2 * std::sin(a + da)},
                             {r2 * std::cos(a + 2 * da), r2 * std::sin(a + 2 * da)},
                             {r1 * std::cos(a + 3 * da), r1 * std::sin(a + 3 * da)}};
    for (int k = 0; k < 4; ++k) {
      const float* p = pts[k];
      const float* q = pts[(k + 1) % 4];
      glNormal3f(q[1] - p[1], p[0] - q[0], 0);
      glVertex3f(p[0], p[1], width * 0.5f);
      glVertex3f(p[0], p[1], -width * 0.5f);
    }
  }
  glEnd();
  glShadeModel(GL_SMOOTH);
}

} // namespace

PINEDA_SCENE(bench_tiny_tris, "200k triangles of about one pixel, random colours, no depth",
             .width = 512, .height = 512) {
  clear_frame(0, 0, 0);
  Rng rng(7);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 200000; ++i) {
    const float x = rng.range(1, 511), y = rng.range(1, 511);
    glColor3f(rng.unit(), rng.unit(), rng.unit());
    glVertex2f(x, y);
    glVertex2f(x + rng.range(0.5f, 1.5f), y + rng.range(-0.3f, 0.3f));
    glVertex2f(x + rng.range(-0.3f, 0.3f), y + rng.range(0.5f, 1.5f));
  }
  glEnd();
}

PINEDA_SCENE(bench_overdraw_depth,
             "12 full-screen layers at 1024x768 with depth test, "
             "front to back and back to front",
             .width = 1024, .height = 768) {
  clear_frame(0, 0, 0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  for (int pass = 0; pass < 2; ++pass) {
    for (int i = 0; i < 6; ++i) {
      const int layer = pass == 0 ? i : 5 - i;
      const float z = 0.9f - 0.15f * static_cast<float>(layer) - 0.05f * static_cast<float>(pass);
      palette_color(layer + 6 * pass);
      glBegin(GL_QUADS);
      glVertex3f(0, 0, z);
      glVertex3f(1024, 0, z);
      glColor3f(0.1f * static_cast<float>(layer), 0.5f, 1.0f - 0.1f * static_cast<float>(layer));
      glVertex3f(1024, 768, z);
      glVertex3f(0, 768, z);
      glEnd();
    }
  }
  glDisable(GL_DEPTH_TEST);
}

PINEDA_SCENE(bench_lit_mesh,
             "300k-triangle lit torus knot of tori, vertex arrays, two lights, "
             "depth test, 640x480",
             .width = 640, .height = 480) {
  static const Mesh mesh = torus(500, 300, 1.0f, 0.35f); // 300k triangles
  clear_frame(0.05f, 0.05f, 0.1f);
  perspective_view(frame, 0.5f, 1.0f, 20.0f);
  glTranslatef(0, 0, -4.5f);
  glRotatef(35, 1, 0.4f, 0);
  glEnable(GL_DEPTH_TEST);
  light_setup();
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 6 * sizeof(float), mesh.vn.data());
  glNormalPointer(GL_FLOAT, 6 * sizeof(float), mesh.vn.data() + 3);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.indices.size()), GL_UNSIGNED_INT,
                 mesh.indices.data());
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
}

PINEDA_SCENE(bench_textured_mesh,
             "Mipmapped, trilinear textured ground plane and torus, "
             "perspective, 640x480",
             .width = 640, .height = 480) {
  // The accurate variant of the sweep's textured family (sweep_scenes.cpp) at 640x480.
  sweep::draw_textured_accurate(frame);
}

PINEDA_SCENE(bench_immediate,
             "50k smooth triangles through glBegin/glEnd, one Begin per "
             "triangle, depth test",
             .width = 512, .height = 512) {
  clear_frame(0, 0, 0);
  glEnable(GL_DEPTH_TEST);
  Rng rng(11);
  for (int i = 0; i < 50000; ++i) {
    const float x = rng.range(0, 500), y = rng.range(0, 500), z = rng.range(-0.9f, 0.9f);
    glBegin(GL_TRIANGLES);
    glColor3f(rng.unit(), rng.unit(), rng.unit());
    glVertex3f(x, y, z);
    glColor3f(rng.unit(), rng.unit(), rng.unit());
    glVertex3f(x + rng.range(2, 14), y + rng.range(-3, 3), z);
    glColor3f(rng.unit(), rng.unit(), rng.unit());
    glVertex3f(x + rng.range(-3, 3), y + rng.range(2, 14), z);
    glEnd();
  }
  glDisable(GL_DEPTH_TEST);
}

PINEDA_SCENE(bench_gears_lists,
             "glxgears' three gears compiled into display lists and drawn "
             "from them 20 times, lit, depth test, 640x480",
             .width = 640, .height = 480) {
  clear_frame(0, 0, 0);
  perspective_view(frame, 0.4f, 5.0f, 60.0f);
  glTranslatef(0, 0, -40);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat pos[4] = {5, 5, 10, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  const GLfloat colors[3][4] = {{0.8f, 0.1f, 0.0f, 1}, {0.0f, 0.8f, 0.2f, 1}, {0.2f, 0.2f, 1, 1}};
  const GLuint base = glGenLists(3);
  const float params[3][5] = {
      {1, 4, 1, 20, 0.7f}, {0.5f, 2, 2, 10, 0.7f}, {1.3f, 2, 0.5f, 10, 0.7f}};
  for (int g = 0; g < 3; ++g) {
    glNewList(base + static_cast<GLuint>(g), GL_COMPILE);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, colors[g]);
    gear(params[g][0], params[g][1], params[g][2], static_cast<int>(params[g][3]), params[g][4]);
    glEndList();
  }
  const float offsets[3][3] = {{-3, -2, 0}, {3.1f, -2, 0}, {-3.1f, 4.2f, 0}};
  for (int rep = 0; rep < 20; ++rep) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (int g = 0; g < 3; ++g) {
      glPushMatrix();
      glRotatef(20, 1, 0, 0);
      glRotatef(30, 0, 1, 0);
      glTranslatef(offsets[g][0], offsets[g][1], offsets[g][2]);
      glRotatef(static_cast<float>(rep * 3 + 9 * g), 0, 0, 1);
      glCallList(base + static_cast<GLuint>(g));
      glPopMatrix();
    }
  }
  glDeleteLists(base, 3);
  glDisable(GL_LIGHTING);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
}

PINEDA_SCENE(bench_blend_heavy, "2000 overlapping alpha-blended smooth quads at 800x600",
             .width = 800, .height = 600) {
  clear_frame(0.1f, 0.1f, 0.1f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  Rng rng(5);
  glBegin(GL_QUADS);
  for (int i = 0; i < 2000; ++i) {
    const float x = rng.range(-100, 750), y = rng.range(-100, 550), s = rng.range(40, 220);
    glColor4f(rng.unit(), rng.unit(), rng.unit(), rng.range(0.1f, 0.6f));
    glVertex2f(x, y);
    glVertex2f(x + s, y);
    glColor4f(rng.unit(), rng.unit(), rng.unit(), rng.range(0.1f, 0.6f));
    glVertex2f(x + s, y + s);
    glVertex2f(x, y + s);
  }
  glEnd();
  glDisable(GL_BLEND);
}
