// Back-end micro-benchmarks: triangle rasterization by size class and fragment path, and the
// whole pipeline through the GL API (immediate mode and vertex arrays). Scene-level timing
// against Mesa lives in the conformance driver (Pineda/llvmpipe ratios per scene).
#include <benchmark/benchmark.h>

#include <GL/gl.h>
#include <GL/osmesa.h>

#include <random>
#include <vector>

#include "framebuffer/framebuffer.h"
#include "raster/raster.h"

namespace {

using namespace pineda;

struct Surface {
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;
  Framebuffer fb;
  Surface(int w, int h) : color(static_cast<size_t>(w) * h * 4), depth(static_cast<size_t>(w) * h) {
    fb.width = w;
    fb.height = h;
    fb.color = color.data();
    fb.color_stride = w * 4;
    fb.depth = depth.data();
    fb.depth_bits = 24;
  }
};

PVertex vertex(float x, float y, float z, float r, float g, float b) {
  PVertex v{};
  v.win[0] = x, v.win[1] = y, v.win[2] = z, v.win[3] = 1.0f;
  v.clip[3] = 1.0f;
  v.attr[kAttrColor + 0] = r, v.attr[kAttrColor + 1] = g, v.attr[kAttrColor + 2] = b;
  v.attr[kAttrColor + 3] = 1.0f;
  return v;
}

// Random triangles of leg length `size` pixels inside a 1024x1024 surface. Arguments: size,
// depth test on/off, smooth/flat.
void BM_RasterTriangle(benchmark::State& st) {
  const float size = static_cast<float>(st.range(0));
  Surface s(1024, 1024);
  RasterState rs;
  rs.depth_test = st.range(1) != 0;
  rs.depth_func = GL_LEQUAL;
  rs.flat = st.range(2) == 0;
  DrawCall dc{&rs, &s.fb};
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> pos(0.0f, 1024.0f - size), u(0.0f, 1.0f);
  std::vector<PVertex> v;
  for (int i = 0; i < 3 * 4096; i += 3) {
    const float x = pos(rng), y = pos(rng), z = u(rng);
    v.push_back(vertex(x, y, z, u(rng), u(rng), u(rng)));
    v.push_back(vertex(x + size, y, z, u(rng), u(rng), u(rng)));
    v.push_back(vertex(x, y + size, z, u(rng), u(rng), u(rng)));
  }
  size_t i = 0;
  for (auto _ : st) {
    raster_triangle(dc, v[i], v[i + 1], v[i + 2], v[i + 2], false);
    i = (i + 3) % v.size();
  }
  st.SetItemsProcessed(st.iterations());
  st.counters["Mpix/s"] = benchmark::Counter(static_cast<double>(st.iterations()) * size * size / 2e6,
                                             benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RasterTriangle)
    ->ArgsProduct({{1, 4, 16, 64, 256}, {0, 1}, {0, 1}})
    ->ArgNames({"size", "depth", "smooth"});

// The whole pipeline: a 100x100 grid of quads through glDrawElements or glBegin/glEnd.
struct GLContext {
  std::vector<uint8_t> buf;
  OSMesaContext ctx;
  GLContext(int w, int h) : buf(static_cast<size_t>(w) * h * 4) {
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, w, h);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, 1, 0, 1, -1, 1);
    glEnable(GL_DEPTH_TEST);
  }
  ~GLContext() { OSMesaDestroyContext(ctx); }
};

void BM_DrawElementsGrid(benchmark::State& st) {
  GLContext gl(512, 512);
  const int n = 100;
  std::vector<float> xy, rgb;
  std::vector<GLuint> idx;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      xy.push_back(static_cast<float>(i) / n);
      xy.push_back(static_cast<float>(j) / n);
      rgb.insert(rgb.end(), {static_cast<float>(i) / n, static_cast<float>(j) / n, 0.5f});
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const GLuint a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      idx.insert(idx.end(), {a, b, d, a, d, c});
    }
  glVertexPointer(2, GL_FLOAT, 0, xy.data());
  glColorPointer(3, GL_FLOAT, 0, rgb.data());
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  for (auto _ : st) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(idx.size()), GL_UNSIGNED_INT, idx.data());
    glFinish();
  }
  st.SetItemsProcessed(st.iterations() * static_cast<int64_t>(idx.size() / 3));
}
BENCHMARK(BM_DrawElementsGrid);

void BM_ImmediateModeTriangles(benchmark::State& st) {
  GLContext gl(512, 512);
  const int n = 100;
  for (auto _ : st) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const float x = static_cast<float>(i) / n, y = static_cast<float>(j) / n, d = 1.0f / n;
        glBegin(GL_TRIANGLES);
        glColor3f(x, y, 0.5f);
        glVertex2f(x, y);
        glVertex2f(x + d, y);
        glVertex2f(x, y + d);
        glEnd();
      }
    glFinish();
  }
  st.SetItemsProcessed(st.iterations() * n * n);
}
BENCHMARK(BM_ImmediateModeTriangles);

} // namespace
