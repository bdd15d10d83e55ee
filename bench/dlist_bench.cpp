// Display-list replay against immediate mode (GL 2.1 §5.4): glxgears' three gears, lit and
// depth tested, drawn from lists and with the same calls in immediate mode. "NoContext" issues
// the immediate-mode calls without a current context (every command a no-op), which is the
// application's own cost (the trigonometry of the tessellation) inside the immediate figure.
// A 16x16 viewport makes the geometry stage dominate; 300x300 is glxgears' default window.
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <benchmark/benchmark.h>

#include <vector>

#include "../conformance/common/gear_geometry.h"

namespace {

struct Gears {
  OSMesaContext ctx = nullptr;
  std::vector<unsigned char> buf;
  GLuint lists = 0;
  int size;

  explicit Gears(int s) : size(s) {
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    buf.resize(static_cast<size_t>(s) * s * 4);
    OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, s, s);
    glViewport(0, 0, s, s);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 5, 60);
    glMatrixMode(GL_MODELVIEW);
    const GLfloat pos[4] = {5, 5, 10, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_CULL_FACE);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);
    lists = glGenLists(3);
    for (int i = 0; i < 3; ++i) {
      glNewList(lists + static_cast<GLuint>(i), GL_COMPILE);
      gear(i);
      glEndList();
    }
  }
  ~Gears() {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(ctx);
  }

  static void gear(int i) {
    static const GLfloat colors[3][4] = {
        {0.8f, 0.1f, 0, 1}, {0, 0.8f, 0.2f, 1}, {0.2f, 0.2f, 1, 1}};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, colors[i]);
    if (i == 0) gear_geometry(1.0f, 4.0f, 1.0f, 20, 0.7f);
    if (i == 1) gear_geometry(0.5f, 2.0f, 2.0f, 10, 0.7f);
    if (i == 2) gear_geometry(1.3f, 2.0f, 0.5f, 10, 0.7f);
  }

  // One glxgears frame; `draw(i)` draws gear i.
  template <typename Draw> static void frame(Draw draw) {
    static const float place[3][3] = {{-3, -2, 17}, {3.1f, -2, -43}, {-3.1f, 4.2f, -59}};
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0, 0, -40);
    glRotatef(20, 1, 0, 0);
    glRotatef(30, 0, 1, 0);
    for (int i = 0; i < 3; ++i) {
      glPushMatrix();
      glTranslatef(place[i][0], place[i][1], 0);
      glRotatef(place[i][2], 0, 0, 1);
      draw(i);
      glPopMatrix();
    }
  }
};

void BM_GearsList(benchmark::State& state) {
  Gears g(static_cast<int>(state.range(0)));
  for (auto _ : state)
    Gears::frame([&](int i) { glCallList(g.lists + static_cast<GLuint>(i)); });
  glFinish();
}

void BM_GearsImmediate(benchmark::State& state) {
  Gears g(static_cast<int>(state.range(0)));
  for (auto _ : state)
    Gears::frame(Gears::gear);
  glFinish();
}

void BM_GearsNoContext(benchmark::State& state) {
  Gears g(static_cast<int>(state.range(0)));
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  for (auto _ : state)
    Gears::frame(Gears::gear);
}

BENCHMARK(BM_GearsList)->Arg(16)->Arg(300);
BENCHMARK(BM_GearsImmediate)->Arg(16)->Arg(300);
BENCHMARK(BM_GearsNoContext)->Arg(16);

} // namespace
