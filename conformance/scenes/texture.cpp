// Texturing (GL 2.1 §3.8): 2D textures with every filter and wrap mode on screen-aligned and
// rotated quads, a mipmapped perspective floor, the base formats under each texture function,
// 1D and 3D textures, textured lines and points. Every scene deletes its textures and puts the
// texture state it touched back to the defaults at the end.
#include "scene_util.h"

#include <cmath>
#include <vector>

using namespace scenes;

namespace {

// A 2^n texture with smooth gradients, a checker and a few hard edges, so that filtering,
// wrapping and level selection all show.
std::vector<GLubyte> pattern(int w, int h, int seed) {
  std::vector<GLubyte> p(static_cast<size_t>(w) * h * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      GLubyte* t = &p[(static_cast<size_t>(y) * w + x) * 4];
      const bool check = ((x * 8 / w) + (y * 8 / h)) % 2 == 0;
      t[0] = static_cast<GLubyte>((x * 255) / (w > 1 ? w - 1 : 1));
      t[1] = static_cast<GLubyte>((y * 255) / (h > 1 ? h - 1 : 1));
      t[2] = check ? static_cast<GLubyte>(200 - 40 * (seed % 3)) : 30;
      t[3] = static_cast<GLubyte>(check ? 255 : 96 + 16 * (seed % 4));
      if (x == y || x == w - 1 - y) t[0] = t[1] = t[2] = 255;
    }
  return p;
}

// A level filled with one colour per level, so that level selection is visible directly.
std::vector<GLubyte> solid(int w, int h, const float* c) {
  std::vector<GLubyte> p(static_cast<size_t>(w) * h * 4);
  for (size_t i = 0; i < p.size(); i += 4) {
    p[i] = static_cast<GLubyte>(c[0] * 255);
    p[i + 1] = static_cast<GLubyte>(c[1] * 255);
    p[i + 2] = static_cast<GLubyte>(c[2] * 255);
    p[i + 3] = 255;
  }
  return p;
}

GLuint make_texture_2d(int w, int h, int seed, GLenum min_filter, GLenum mag_filter) {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  const std::vector<GLubyte> p = pattern(w, h, seed);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min_filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag_filter);
  return tex;
}

void texture_defaults() {
  glBindTexture(GL_TEXTURE_1D, 0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glDisable(GL_TEXTURE_1D);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_TEXTURE_3D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  const GLfloat zero[4] = {0, 0, 0, 0};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, zero);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
}

// A quad from (x0,y0) to (x1,y1) with texture coordinates (s0,t0) to (s1,t1).
void quad(float x0, float y0, float x1, float y1, float s0, float t0, float s1, float t1) {
  glBegin(GL_QUADS);
  glTexCoord2f(s0, t0);
  glVertex2f(x0, y0);
  glTexCoord2f(s1, t0);
  glVertex2f(x1, y0);
  glTexCoord2f(s1, t1);
  glVertex2f(x1, y1);
  glTexCoord2f(s0, t1);
  glVertex2f(x0, y1);
  glEnd();
}

constexpr GLenum kWraps[] = {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_MIRRORED_REPEAT, GL_CLAMP,
                             GL_CLAMP_TO_BORDER};

// Five wrap modes in rows, magnified and minified quads in columns.
void wrap_grid(const Frame& frame, GLenum filter) {
  clear_frame(0.1f, 0.1f, 0.15f);
  const GLuint tex = make_texture_2d(16, 16, 1, filter, filter);
  const GLfloat border[4] = {0.25f, 0.75f, 0.5f, 1.0f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  for (int i = 0; i < 10; ++i) {
    panel(frame, i, 2, 5);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, kWraps[i / 2]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, kWraps[(i / 2 + 1) % 5]);
    if (i % 2 == 0) {
      quad(2, 2, 124, 46, -1.25f, -0.5f, 2.25f, 1.75f); // magnified, coordinates beyond [0,1]
    } else {
      glPushMatrix();
      glTranslatef(62, 24, 0);
      glRotatef(17.0f, 0, 0, 1);
      quad(-70, -18, 70, 18, -0.3f, -0.2f, 1.3f, 1.2f);
      glPopMatrix();
    }
  }
  glDeleteTextures(1, &tex);
  texture_defaults();
}

void perspective(const Frame& f) {
  glViewport(0, 0, f.width, f.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double aspect = static_cast<double>(f.width) / f.height;
  glFrustum(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, 1.0, 60.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

// A floor from z = -1 to z = -50, its texture repeated 24 times, seen at a grazing angle.
void floor_quad(float x0, float x1) {
  glBegin(GL_QUADS);
  glTexCoord2f(x0 * 2.0f, 0);
  glVertex3f(x0, -1.0f, -1.0f);
  glTexCoord2f(x1 * 2.0f, 0);
  glVertex3f(x1, -1.0f, -1.0f);
  glTexCoord2f(x1 * 2.0f, 24);
  glVertex3f(x1, -1.0f, -50.0f);
  glTexCoord2f(x0 * 2.0f, 24);
  glVertex3f(x0, -1.0f, -50.0f);
  glEnd();
}

const float kLevelColors[7][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0},
                                  {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};

} // namespace

PINEDA_SCENE(tex_nearest_wraps,
             "NEAREST 2D texture, REPLACE, five wrap modes, magnified and rotated") {
  wrap_grid(frame, GL_NEAREST);
}

PINEDA_SCENE(tex_linear_wraps,
             "LINEAR 2D texture, REPLACE, five wrap modes, magnified and rotated") {
  wrap_grid(frame, GL_LINEAR);
}

PINEDA_SCENE(tex_mipmap_floor,
             "Mipmapped perspective floor: the four mipmap filters side by side") {
  clear_frame(0.0f, 0.0f, 0.0f);
  perspective(frame);
  const GLuint tex = make_texture_2d(64, 64, 2, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  // Levels 1.. with one colour each: the selected level shows as a colour band.
  for (int l = 1, s = 32; s >= 1; ++l, s /= 2) {
    const std::vector<GLubyte> p = solid(s, s, kLevelColors[l % 7]);
    glTexImage2D(GL_TEXTURE_2D, l, GL_RGBA, s, s, 0, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  }
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  const GLenum filters[4] = {GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
                             GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR};
  for (int i = 0; i < 4; ++i) {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filters[i]);
    floor_quad(-3.0f + 1.5f * i, -1.5f + 1.5f * i);
  }
  glDeleteTextures(1, &tex);
  texture_defaults();
}

PINEDA_SCENE(tex_lod_bias, "Mipmapped floor with TEXTURE_LOD_BIAS from glTexEnv and the object") {
  clear_frame(0.0f, 0.0f, 0.0f);
  perspective(frame);
  const GLuint tex = make_texture_2d(64, 64, 3, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR);
  for (int l = 1, s = 32; s >= 1; ++l, s /= 2) {
    const std::vector<GLubyte> p = solid(s, s, kLevelColors[l % 7]);
    glTexImage2D(GL_TEXTURE_2D, l, GL_RGBA, s, s, 0, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  }
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  const float biases[4] = {-1.0f, 0.0f, 1.0f, 2.0f};
  for (int i = 0; i < 4; ++i) {
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, biases[i]);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, i == 3 ? -1.0f : 0.0f);
    floor_quad(-3.0f + 1.5f * i, -1.5f + 1.5f * i);
  }
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.0f);
  glDeleteTextures(1, &tex);
  texture_defaults();
}

PINEDA_SCENE(tex_env_modes,
             "REPLACE, MODULATE, DECAL, BLEND, ADD on smooth-shaded quads, RGBA and RGB") {
  clear_frame(0.2f, 0.2f, 0.2f);
  const GLuint tex = make_texture_2d(16, 16, 4, GL_LINEAR, GL_LINEAR);
  glEnable(GL_TEXTURE_2D);
  const GLfloat env[4] = {0.875f, 0.25f, 0.5f, 0.75f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  const GLenum modes[5] = {GL_REPLACE, GL_MODULATE, GL_DECAL, GL_BLEND, GL_ADD};
  for (int i = 0; i < 10; ++i) {
    panel(frame, i, 2, 5);
    if (i % 2 == 1) {
      const std::vector<GLubyte> p = pattern(16, 16, 5);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
    } else {
      const std::vector<GLubyte> p = pattern(16, 16, 4);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
    }
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, modes[i / 2]);
    glBegin(GL_QUADS);
    glColor4f(1.0f, 0.125f, 0.125f, 1.0f);
    glTexCoord2f(0, 0);
    glVertex2f(2, 2);
    glColor4f(0.125f, 1.0f, 0.25f, 0.75f);
    glTexCoord2f(2, 0);
    glVertex2f(124, 2);
    glColor4f(0.25f, 0.375f, 1.0f, 0.5f);
    glTexCoord2f(2, 1);
    glVertex2f(124, 46);
    glColor4f(1.0f, 1.0f, 0.125f, 0.875f);
    glTexCoord2f(0, 1);
    glVertex2f(2, 46);
    glEnd();
  }
  glDeleteTextures(1, &tex);
  texture_defaults();
}

PINEDA_SCENE(tex_base_formats,
             "ALPHA, LUMINANCE, LUMINANCE_ALPHA, INTENSITY under every texture function") {
  clear_frame(0.25f, 0.25f, 0.25f);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  const GLfloat env[4] = {0.125f, 0.625f, 1.0f, 0.375f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  const std::vector<GLubyte> p = pattern(8, 8, 6);
  const GLenum formats[4] = {GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_INTENSITY};
  const GLenum modes[4] = {GL_REPLACE, GL_MODULATE, GL_BLEND, GL_ADD};
  for (int i = 0; i < 16; ++i) {
    panel(frame, i, 4, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, formats[i % 4], 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, modes[i / 4]);
    glColor4f(0.875f, 0.375f, 0.25f, 0.625f);
    quad(2, 2, 58, 58, 0, 0, 1, 1);
  }
  glDeleteTextures(1, &tex);
  texture_defaults();
}

PINEDA_SCENE(tex_1d_3d, "1D texture with a texture matrix and a 3D texture sliced along r") {
  const auto tex_image_3d = proc<PFNGLTEXIMAGE3DPROC>("glTexImage3D");
  clear_frame(0.0f, 0.0f, 0.0f);
  GLuint tex[2] = {0, 0};
  glGenTextures(2, tex);
  glBindTexture(GL_TEXTURE_1D, tex[0]);
  const std::vector<GLubyte> line = pattern(32, 1, 7);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, line.data());
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glEnable(GL_TEXTURE_1D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  panel(frame, 0, 2, 2);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glRotatef(30.0f, 0, 0, 1);
  glScalef(1.5f, 1.5f, 1);
  glMatrixMode(GL_MODELVIEW);
  glColor3f(1, 1, 1);
  quad(4, 4, 120, 120, 0, 0, 1, 1);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glDisable(GL_TEXTURE_1D);

  glBindTexture(GL_TEXTURE_3D, tex[1]);
  std::vector<GLubyte> vol;
  for (int z = 0; z < 8; ++z) {
    const std::vector<GLubyte> slice = pattern(8, 8, z);
    vol.insert(vol.end(), slice.begin(), slice.end());
  }
  tex_image_3d(GL_TEXTURE_3D, 0, GL_RGBA, 8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol.data());
  glEnable(GL_TEXTURE_3D);
  for (int i = 1; i < 4; ++i) {
    panel(frame, i, 2, 2);
    const GLenum filter = i == 1 ? GL_NEAREST : GL_LINEAR;
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, filter);
    const float r = 0.3f * static_cast<float>(i) - 0.0863f; // slice boundaries off pixel centres
    // s and t offsets keep texel boundaries off pixel centres.
    const float s0 = 0.0123f, s1 = 1.0123f, t0 = 0.0171f, t1 = 1.0171f;
    glBegin(GL_QUADS);
    glTexCoord3f(s0, t0, r);
    glVertex2f(4, 4);
    glTexCoord3f(s1, t0, r + 0.2f);
    glVertex2f(120, 4);
    glTexCoord3f(s1, t1, r + 0.4f);
    glVertex2f(120, 120);
    glTexCoord3f(s0, t1, r);
    glVertex2f(4, 120);
    glEnd();
  }
  glBindTexture(GL_TEXTURE_3D, 0);
  glDeleteTextures(2, tex);
  texture_defaults();
}

PINEDA_SCENE(tex_lines_points, "Textured lines and points (MODULATE, NEAREST and LINEAR)",
             .allowance = kLineAllowance, .why = kLineWhy) {
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLuint tex = make_texture_2d(16, 16, 8, GL_NEAREST, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor3f(1, 1, 1);
  glBegin(GL_LINES);
  for (int i = 0; i < 40; ++i) {
    const float a = 2.0f * kPi * static_cast<float>(i) / 40.0f;
    glTexCoord2f(0.5f, 0.5f);
    glVertex2f(128.0f, 128.0f);
    glTexCoord2f(0.5f + std::cos(a), 0.5f + std::sin(a));
    glVertex2f(128.0f + 120.0f * std::cos(a), 128.0f + 120.0f * std::sin(a));
  }
  glEnd();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glBegin(GL_POINTS);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      glTexCoord2f(static_cast<float>(x) / 31.0f, static_cast<float>(y) / 31.0f);
      glVertex2f(4.5f + 2.0f * x, 4.5f + 2.0f * y);
    }
  glEnd();
  glDeleteTextures(1, &tex);
  texture_defaults();
}

PINEDA_SCENE(tex_color_sum, "Colour sum after texturing: SEPARATE_SPECULAR_COLOR on a lit textured "
                            "sphere, COLOR_SUM on quads") {
  const auto secondary = proc<PFNGLSECONDARYCOLOR3FPROC>("glSecondaryColor3f");
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLuint tex = make_texture_2d(32, 32, 9, GL_LINEAR, GL_LINEAR);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  // Left: COLOR_SUM with per-vertex secondary colours, unlit.
  panel(frame, 0, 2, 1);
  glEnable(GL_COLOR_SUM);
  glBegin(GL_QUADS);
  const float xs[4] = {4, 120, 120, 4}, ys[4] = {8, 8, 240, 240};
  for (int v = 0; v < 4; ++v) {
    palette_color(v + 2);
    secondary(0.125f * v, 0.5f - 0.125f * v, 0.25f);
    glTexCoord2f(xs[v] / 61.3f, ys[v] / 97.1f);
    glVertex2f(xs[v], ys[v]);
  }
  glEnd();
  glDisable(GL_COLOR_SUM);
  // Right: lighting with the specular colour added after the texture environment.
  const Panel p = panel(frame, 1, 2, 1);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double aspect = static_cast<double>(p.w) / p.h;
  glFrustum(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat pos[4] = {-0.5f, 0.8f, 1.0f, 0.0f}, white[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  glTranslatef(0, 0, -3.5f);
  glRotatef(20, 1, 0, 0);
  const int slices = 32, stacks = 20;
  for (int i = 0; i < stacks; ++i) {
    const float t0 = kPi * i / stacks, t1 = kPi * (i + 1) / stacks;
    glBegin(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= slices; ++j) {
      const float ph = 2.0f * kPi * j / slices;
      for (float t : {t1, t0}) {
        const float x = std::sin(t) * std::cos(ph), y = std::cos(t), z = std::sin(t) * std::sin(ph);
        glNormal3f(x, y, z);
        glTexCoord2f(2.0f * j / slices + 0.013f, t / kPi + 0.011f);
        glVertex3f(x, y, z);
      }
    }
    glEnd();
  }
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  const GLfloat black[4] = {0, 0, 0, 1};
  glMaterialfv(GL_FRONT, GL_SPECULAR, black);
  glMaterialf(GL_FRONT, GL_SHININESS, 0.0f);
  glDisable(GL_LIGHT0);
  glDisable(GL_LIGHTING);
  glDeleteTextures(1, &tex);
  texture_defaults();
}
