// The scaling measurements (issue 6, scripts/scaling.sh).
//
// scale_tris_*: a lit, depth-tested height field of 1k to 1M triangles that always covers the
// same 1024x1024 window, so the fill cost stays (nearly) constant while the vertex and
// triangle-setup cost grows with the count. The description states the exact triangle count
// ("<n> triangles"), which scripts/plot_scaling.py reads.
//
// scale_res_*: one fixed scene (the sweep's accurate textured mesh) at 256x256 to 2048x2048 in
// steps of sqrt(2) per side, so the pixel count doubles from one to the next.
#include "sweep_common.h"

#include "scene_util.h"

#include <cmath>
#include <vector>

using namespace scenes;

namespace {

constexpr int kGridWindow = 1024;

struct Grid {
  std::vector<float> vn; // x y z nx ny nz
  std::vector<unsigned> indices;
};

// cells x cells quads over the whole window, two triangles each; z and the normal follow a
// gentle wave so that lighting gives every vertex its own colour.
Grid height_field(int cells) {
  Grid g;
  const float step = static_cast<float>(kGridWindow) / static_cast<float>(cells);
  const float k = 2.0f * kPi * 3.0f / static_cast<float>(kGridWindow); // three waves per side
  for (int i = 0; i <= cells; ++i) {
    for (int j = 0; j <= cells; ++j) {
      const float x = step * static_cast<float>(j), y = step * static_cast<float>(i);
      const float z = 0.4f * std::sin(k * x) * std::cos(k * y);
      // Normal of the surface z(x, y) scaled to look like relief of a few hundred pixels.
      const float dzdx = 0.8f * std::cos(k * x) * std::cos(k * y);
      const float dzdy = -0.8f * std::sin(k * x) * std::sin(k * y);
      const float len = std::sqrt(dzdx * dzdx + dzdy * dzdy + 1.0f);
      g.vn.insert(g.vn.end(), {x, y, z, -dzdx / len, -dzdy / len, 1.0f / len});
    }
  }
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      const unsigned a = static_cast<unsigned>(i * (cells + 1) + j), b = a + 1;
      const unsigned c = a + static_cast<unsigned>(cells + 1), d = c + 1;
      g.indices.insert(g.indices.end(), {a, b, d, a, d, c});
    }
  }
  return g;
}

template <int Cells> void grid_scene(const Frame&) {
  static const Grid grid = height_field(Cells);
  clear_frame(0, 0, 0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  const GLfloat light[4] = {0.4f, 0.5f, 1.0f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glColor3f(0.9f, 0.7f, 0.4f);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 6 * sizeof(float), grid.vn.data());
  glNormalPointer(GL_FLOAT, 6 * sizeof(float), grid.vn.data() + 3);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(grid.indices.size()), GL_UNSIGNED_INT,
                 grid.indices.data());
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisable(GL_COLOR_MATERIAL);
  glDisable(GL_LIGHT0);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
}

constexpr SceneOptions kGridOptions{.width = kGridWindow, .height = kGridWindow};

// cells = round(sqrt(n / 2)) for n = 1k, 4k, ..., 1M (1024 * 4^i) triangles.
const Registrar tri_scenes[] = {
    {"scale_tris_0001k", "Height field, 1058 triangles, 1024x1024", kGridOptions, &grid_scene<23>},
    {"scale_tris_0004k", "Height field, 4050 triangles, 1024x1024", kGridOptions, &grid_scene<45>},
    {"scale_tris_0016k", "Height field, 16562 triangles, 1024x1024", kGridOptions, &grid_scene<91>},
    {"scale_tris_0064k", "Height field, 65522 triangles, 1024x1024", kGridOptions,
     &grid_scene<181>},
    {"scale_tris_0256k", "Height field, 262088 triangles, 1024x1024", kGridOptions,
     &grid_scene<362>},
    {"scale_tris_1024k", "Height field, 1048352 triangles, 1024x1024", kGridOptions,
     &grid_scene<724>},
};

constexpr SceneOptions res(int side) {
  return SceneOptions{.width = side, .height = side};
}

const Registrar res_scenes[] = {
    {"scale_res_0256", "Textured mesh at 256x256", res(256), &sweep::draw_textured_accurate},
    {"scale_res_0362", "Textured mesh at 362x362", res(362), &sweep::draw_textured_accurate},
    {"scale_res_0512", "Textured mesh at 512x512", res(512), &sweep::draw_textured_accurate},
    {"scale_res_0724", "Textured mesh at 724x724", res(724), &sweep::draw_textured_accurate},
    {"scale_res_1024", "Textured mesh at 1024x1024", res(1024), &sweep::draw_textured_accurate},
    {"scale_res_1448", "Textured mesh at 1448x1448", res(1448), &sweep::draw_textured_accurate},
    {"scale_res_2048", "Textured mesh at 2048x2048", res(2048), &sweep::draw_textured_accurate},
};

} // namespace
