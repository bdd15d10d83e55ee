// The time-against-error sweep (issue 6, scripts/sweep.sh): families of scenes that draw the same
// geometry under different quality settings an application may choose through GL state
// (minification filter and mipmaps, GL_PERSPECTIVE_CORRECTION_HINT, GL_FOG_HINT, shade model).
// scripts/plot_sweep.py measures each variant's error against llvmpipe's render of the family's
// accurate variant, so the error axis is what the setting really costs in image quality.
//
// Naming convention read by scripts/plot_sweep.py: sweep_<family>_<variant>; the description is
// "<family title>: <variant label>", and the accurate variant's label ends with " (accurate)".
// The scenes are registered into pineda_bench_runner like bench_scenes.cpp; scripts/bench.sh runs
// only the bench_ scenes.
#include "sweep_common.h"

#include "bench_geometry.h"

#include "scene_util.h"

#include <cmath>
#include <vector>

using namespace scenes;
using bench::Mesh;
using bench::perspective_view;
using bench::torus;

namespace {

// --- Textured family ---------------------------------------------------------------------

struct TexVariant {
  GLint min_filter;
  bool mipmaps;       // upload the whole chain (only used by the *_MIPMAP_* filters)
  GLenum perspective; // GL_PERSPECTIVE_CORRECTION_HINT
  GLenum shade_model;
};

// The mipmap chain of bench_textured_mesh: a checkerboard with gradients whose colours also
// change from level to level, so the filter's choice of levels shows in the image.
const std::vector<unsigned char>* texture_levels() {
  static std::vector<unsigned char> levels[9];
  if (levels[0].empty()) {
    for (int l = 0, size = 256; l < 9; ++l, size /= 2) {
      levels[l].resize(static_cast<size_t>(size * size * 4));
      for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
          unsigned char* p = &levels[l][static_cast<size_t>((y * size + x) * 4)];
          const bool check = ((x * 8 / size) + (y * 8 / size)) % 2 == 0;
          p[0] = static_cast<unsigned char>(check ? 230 : 40 + 20 * l);
          p[1] = static_cast<unsigned char>((x * 255) / size);
          p[2] = static_cast<unsigned char>(check ? 60 : (y * 255) / size);
          p[3] = 255;
        }
    }
  }
  return levels;
}

// A ground plane drawn as one large quad (so that a renderer honouring the FASTEST perspective
// hint with affine interpolation would show it) and a smoothly coloured textured torus.
void draw_textured(const Frame& frame, const TexVariant& v) {
  static const Mesh mesh = torus(120, 60, 1.0f, 0.35f);
  const std::vector<unsigned char>* levels = texture_levels();
  clear_frame(0.3f, 0.4f, 0.6f);
  perspective_view(frame, 0.6f, 0.5f, 60.0f);
  glEnable(GL_DEPTH_TEST);
  glHint(GL_PERSPECTIVE_CORRECTION_HINT, v.perspective);
  glShadeModel(v.shade_model);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  for (int l = 0, size = 256; l < (v.mipmaps ? 9 : 1); ++l, size /= 2)
    glTexImage2D(GL_TEXTURE_2D, l, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 levels[l].data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, v.min_filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor3f(1, 1, 1);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex3f(-30, -1.5f, -50);
  glTexCoord2f(24, 0);
  glVertex3f(30, -1.5f, -50);
  glTexCoord2f(24, 24);
  glVertex3f(30, -1.5f, 0);
  glTexCoord2f(0, 24);
  glVertex3f(-30, -1.5f, 0);
  glEnd();
  glTranslatef(0, 0, -5);
  glRotatef(60, 1, 0.3f, 0);
  glBegin(GL_TRIANGLES);
  for (unsigned idx : mesh.indices) {
    const float* p = &mesh.vn[idx * 6];
    glTexCoord2f(p[0] * 2.0f, p[1] * 2.0f + p[2]);
    glColor3f(0.6f + 0.4f * p[3], 0.6f + 0.4f * p[4], 0.8f);
    glVertex3fv(p);
  }
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(1, &tex);
  glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_DONT_CARE);
  glDisable(GL_DEPTH_TEST);
}

template <GLint Min, bool Mip, GLenum Persp, GLenum Shade> void textured(const Frame& frame) {
  draw_textured(frame, TexVariant{Min, Mip, Persp, Shade});
}

} // namespace

void sweep::draw_textured_accurate(const Frame& frame) {
  draw_textured(frame, TexVariant{GL_LINEAR_MIPMAP_LINEAR, true, GL_NICEST, GL_SMOOTH});
}

namespace {

constexpr SceneOptions kTexOptions{.width = 640, .height = 480};

const Registrar tex_variants[] = {
    {"sweep_tex_lml", "Textured mesh: LINEAR_MIPMAP_LINEAR (accurate)", kTexOptions,
     &textured<GL_LINEAR_MIPMAP_LINEAR, true, GL_NICEST, GL_SMOOTH>},
    {"sweep_tex_lmn", "Textured mesh: LINEAR_MIPMAP_NEAREST", kTexOptions,
     &textured<GL_LINEAR_MIPMAP_NEAREST, true, GL_NICEST, GL_SMOOTH>},
    {"sweep_tex_nml", "Textured mesh: NEAREST_MIPMAP_LINEAR", kTexOptions,
     &textured<GL_NEAREST_MIPMAP_LINEAR, true, GL_NICEST, GL_SMOOTH>},
    {"sweep_tex_nmn", "Textured mesh: NEAREST_MIPMAP_NEAREST", kTexOptions,
     &textured<GL_NEAREST_MIPMAP_NEAREST, true, GL_NICEST, GL_SMOOTH>},
    {"sweep_tex_linear", "Textured mesh: LINEAR, no mipmaps", kTexOptions,
     &textured<GL_LINEAR, false, GL_NICEST, GL_SMOOTH>},
    {"sweep_tex_nearest", "Textured mesh: NEAREST, no mipmaps", kTexOptions,
     &textured<GL_NEAREST, false, GL_NICEST, GL_SMOOTH>},
    {"sweep_tex_persp", "Textured mesh: PERSPECTIVE_CORRECTION_HINT FASTEST", kTexOptions,
     &textured<GL_LINEAR_MIPMAP_LINEAR, true, GL_FASTEST, GL_SMOOTH>},
    {"sweep_tex_flat", "Textured mesh: flat shading", kTexOptions,
     &textured<GL_LINEAR_MIPMAP_LINEAR, true, GL_NICEST, GL_FLAT>},
    {"sweep_tex_allfast", "Textured mesh: NEAREST_MIPMAP_NEAREST, FASTEST, flat", kTexOptions,
     &textured<GL_NEAREST_MIPMAP_NEAREST, true, GL_FASTEST, GL_FLAT>},
};

// --- Fog family ----------------------------------------------------------------------------

// A ground grid of large quads receding into EXP2 fog, with rows of lit tori: per-vertex fog
// (FASTEST) interpolates the fog factor across the ground quads, which an exponential does not
// follow, so the hint's error is visible where the quads are large and near.
void draw_fogged(const Frame& frame, GLenum fog_hint) {
  static const Mesh mesh = torus(24, 12, 0.6f, 0.25f);
  clear_frame(0.55f, 0.6f, 0.65f);
  perspective_view(frame, 0.55f, 0.5f, 80.0f);
  glEnable(GL_DEPTH_TEST);
  glHint(GL_FOG_HINT, fog_hint);
  glEnable(GL_FOG);
  const GLfloat fog_color[4] = {0.55f, 0.6f, 0.65f, 1.0f};
  glFogfv(GL_FOG_COLOR, fog_color);
  glFogi(GL_FOG_MODE, GL_EXP2);
  glFogf(GL_FOG_DENSITY, 0.07f);
  glTranslatef(0, -1.5f, 0);
  constexpr int kCells = 16;
  constexpr float kCell = 5.0f;
  glBegin(GL_QUADS);
  for (int i = 0; i < kCells; ++i)
    for (int j = 0; j < kCells; ++j) {
      palette_color((i + j) % 2 ? 3 : 12);
      const float x0 = -40.0f + kCell * static_cast<float>(i), z0 = -kCell * static_cast<float>(j);
      glVertex3f(x0, 0, z0);
      glVertex3f(x0 + kCell, 0, z0);
      glVertex3f(x0 + kCell, 0, z0 - kCell);
      glVertex3f(x0, 0, z0 - kCell);
    }
  glEnd();
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  const GLfloat light[4] = {0.3f, 1.0f, 0.6f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 6 * sizeof(float), mesh.vn.data());
  glNormalPointer(GL_FLOAT, 6 * sizeof(float), mesh.vn.data() + 3);
  for (int row = 0; row < 12; ++row)
    for (int col = -3; col <= 3; ++col) {
      glPushMatrix();
      glTranslatef(3.0f * static_cast<float>(col), 1.0f, -4.0f - 6.0f * static_cast<float>(row));
      glRotatef(static_cast<float>(25 * row + 40 * col), 0.3f, 1, 0.2f);
      palette_color(row * 7 + col + 3);
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.indices.size()), GL_UNSIGNED_INT,
                     mesh.indices.data());
      glPopMatrix();
    }
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisable(GL_COLOR_MATERIAL);
  glDisable(GL_LIGHT0);
  glDisable(GL_LIGHTING);
  glDisable(GL_FOG);
  glHint(GL_FOG_HINT, GL_DONT_CARE);
  glDisable(GL_DEPTH_TEST);
}

template <GLenum Hint> void fogged(const Frame& frame) {
  draw_fogged(frame, Hint);
}

constexpr SceneOptions kFogOptions{.width = 640, .height = 480};

const Registrar fog_variants[] = {
    {"sweep_fog_nicest", "Fogged scene: FOG_HINT NICEST (accurate)", kFogOptions,
     &fogged<GL_NICEST>},
    {"sweep_fog_fastest", "Fogged scene: FOG_HINT FASTEST", kFogOptions, &fogged<GL_FASTEST>},
};

// --- Shading family ------------------------------------------------------------------------

// The lit torus of bench_lit_mesh at 60k triangles: smooth shading interpolates the lit
// colours, flat shading takes each triangle's provoking-vertex colour (GL 2.1 §2.14.7).
template <GLenum Shade> void lit(const Frame& frame) {
  static const Mesh mesh = torus(200, 150, 1.0f, 0.35f);
  clear_frame(0.05f, 0.05f, 0.1f);
  perspective_view(frame, 0.5f, 1.0f, 20.0f);
  glTranslatef(0, 0, -4.5f);
  glRotatef(35, 1, 0.4f, 0);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(Shade);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat pos[4] = {0.5f, 1.0f, 2.0f, 0.0f}, spec[4] = {1, 1, 1, 1};
  const GLfloat amb[4] = {0.2f, 0.15f, 0.1f, 1}, dif[4] = {0.8f, 0.6f, 0.3f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 6 * sizeof(float), mesh.vn.data());
  glNormalPointer(GL_FLOAT, 6 * sizeof(float), mesh.vn.data() + 3);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.indices.size()), GL_UNSIGNED_INT,
                 mesh.indices.data());
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisable(GL_LIGHT0);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
}

constexpr SceneOptions kLitOptions{.width = 640, .height = 480};

const Registrar shade_variants[] = {
    {"sweep_shade_smooth", "Lit mesh: smooth shading (accurate)", kLitOptions, &lit<GL_SMOOTH>},
    {"sweep_shade_flat", "Lit mesh: flat shading", kLitOptions, &lit<GL_FLAT>},
};

} // namespace
