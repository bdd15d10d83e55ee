// Multitexture and the texture environment (GL 2.1 §3.8.13): two and four units with
// MODULATE/ADD/DECAL, every COMBINE function with its sources and operands, DOT3 bump
// lighting, the TEXTUREn crossbar and RGB/ALPHA_SCALE; texture coordinate generation
// (§2.11.4) with OBJECT_LINEAR, EYE_LINEAR and SPHERE_MAP, and a cube map lit by
// REFLECTION_MAP/NORMAL_MAP coordinates. Each scene resets the units it touched.
#include "scene_util.h"

#include <cmath>
#include <vector>

using namespace scenes;

namespace {

struct Gl13 {
  PFNGLACTIVETEXTUREPROC active = proc<PFNGLACTIVETEXTUREPROC>("glActiveTexture");
  PFNGLMULTITEXCOORD2FARBPROC coord2 = proc<PFNGLMULTITEXCOORD2FARBPROC>("glMultiTexCoord2f");
  PFNGLCLIENTACTIVETEXTUREARBPROC client =
      proc<PFNGLCLIENTACTIVETEXTUREARBPROC>("glClientActiveTexture");
};

// A w x h RGBA texture from a function of the texel position in [0,1).
template <typename F> GLuint make_texture(int w, int h, GLenum filter, F f) {
  std::vector<GLubyte> p(static_cast<size_t>(w) * h * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float c[4];
      f((x + 0.5f) / w, (y + 0.5f) / h, c);
      for (int k = 0; k < 4; ++k) {
        const float v = c[k] < 0 ? 0 : (c[k] > 1 ? 1 : c[k]);
        p[(static_cast<size_t>(y) * w + x) * 4 + k] = static_cast<GLubyte>(v * 255.0f + 0.5f);
      }
    }
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  return tex;
}

GLuint checker_texture() {
  return make_texture(16, 16, GL_NEAREST, [](float s, float t, float* c) {
    const bool on = (static_cast<int>(s * 4) + static_cast<int>(t * 4)) % 2 == 0;
    c[0] = on ? 0.875f : 0.25f;
    c[1] = on ? 0.75f : 0.125f;
    c[2] = on ? 0.5f : 0.625f;
    c[3] = on ? 1.0f : 0.5f;
  });
}

GLuint gradient_texture(GLenum filter = GL_LINEAR) {
  return make_texture(32, 32, filter, [](float s, float t, float* c) {
    c[0] = s;
    c[1] = t;
    c[2] = 1.0f - 0.5f * (s + t);
    c[3] = 0.25f + 0.75f * s * t;
  });
}

// Normal map of a bumpy surface, encoded as 0.5 + 0.5 n (the DOT3 convention).
GLuint normal_texture() {
  return make_texture(32, 32, GL_LINEAR, [](float s, float t, float* c) {
    const float dx = 0.6f * std::cos(6.2831853f * 3.0f * s);
    const float dy = 0.6f * std::cos(6.2831853f * 2.0f * t);
    const float len = std::sqrt(dx * dx + dy * dy + 1.0f);
    c[0] = 0.5f + 0.5f * dx / len;
    c[1] = 0.5f + 0.5f * dy / len;
    c[2] = 0.5f + 0.5f / len;
    c[3] = 1.0f;
  });
}

void reset_units(const Gl13& gl) {
  for (int u = 3; u >= 0; --u) {
    gl.active(GL_TEXTURE0 + u);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_TEXTURE_CUBE_MAP);
    for (GLenum g : {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q})
      glDisable(g);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_MODULATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_MODULATE);
    const GLenum src[3] = {GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
    for (int i = 0; i < 3; ++i) {
      glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB + i, src[i]);
      glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_ALPHA + i, src[i]);
      glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + i, i == 2 ? GL_SRC_ALPHA : GL_SRC_COLOR);
      glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + i, GL_SRC_ALPHA);
    }
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 1.0f);
    glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 1.0f);
    const GLfloat zero[4] = {0, 0, 0, 0};
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, zero);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
  }
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
}

// A quad with unit 0..n-1 coordinates scaled per unit, smooth colours. The small offsets keep
// texel boundaries of NEAREST textures off pixel centres (no ties for rounding to decide).
void multi_quad(const Gl13& gl, int units, float x0, float y0, float x1, float y1) {
  const float xs[4] = {x0, x1, x1, x0}, ys[4] = {y0, y0, y1, y1};
  const float ss[4] = {0, 1, 1, 0}, ts[4] = {0, 0, 1, 1};
  glBegin(GL_QUADS);
  for (int v = 0; v < 4; ++v) {
    palette_color(v * 3 + 1, 0.25f + 0.25f * v);
    for (int u = 0; u < units; ++u)
      gl.coord2(GL_TEXTURE0 + u, ss[v] * (1.0f + u) + 0.1f * u + 0.0137f,
                ts[v] * (1.0f + 0.5f * u) + 0.0113f);
    glVertex2f(xs[v], ys[v]);
  }
  glEnd();
}

void combine(GLenum rgb, GLenum alpha) {
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, rgb);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, alpha);
}

void source(int i, GLenum rgb, GLenum op_rgb, GLenum alpha, GLenum op_alpha) {
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB + i, rgb);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + i, op_rgb);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_ALPHA + i, alpha);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + i, op_alpha);
}

void perspective(const Frame& f) {
  glViewport(0, 0, f.width, f.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double aspect = static_cast<double>(f.width) / f.height;
  glFrustum(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
}

void sphere(float r, int slices, int stacks) {
  for (int i = 0; i < stacks; ++i) {
    const float t0 = kPi * i / stacks, t1 = kPi * (i + 1) / stacks;
    glBegin(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= slices; ++j) {
      const float p = 2.0f * kPi * j / slices;
      for (float t : {t1, t0}) {
        const float x = std::sin(t) * std::cos(p), y = std::cos(t), z = std::sin(t) * std::sin(p);
        glNormal3f(x, y, z);
        glVertex3f(r * x, r * y, r * z);
      }
    }
    glEnd();
  }
}

} // namespace

PINEDA_SCENE(texenv_multitexture,
             "Two and four units: MODULATE x MODULATE, MODULATE + ADD, DECAL over REPLACE") {
  const Gl13 gl;
  clear_frame(0.125f, 0.125f, 0.125f);
  const GLuint t0 = checker_texture(), t1 = gradient_texture(), t2 = normal_texture();
  const GLuint tex[4] = {t0, t1, t2, t1};
  const GLenum modes[4][4] = {{GL_MODULATE, GL_MODULATE, 0, 0},
                              {GL_MODULATE, GL_ADD, 0, 0},
                              {GL_REPLACE, GL_DECAL, 0, 0},
                              {GL_MODULATE, GL_MODULATE, GL_ADD, GL_MODULATE}};
  for (int p = 0; p < 4; ++p) {
    panel(frame, p, 2, 2);
    const int units = p == 3 ? 4 : 2;
    for (int u = 0; u < units; ++u) {
      gl.active(GL_TEXTURE0 + u);
      glBindTexture(GL_TEXTURE_2D, tex[u]);
      glEnable(GL_TEXTURE_2D);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, modes[p][u]);
    }
    multi_quad(gl, units, 4, 4, 120, 120);
    reset_units(gl);
  }
  const GLuint all[3] = {t0, t1, t2};
  glDeleteTextures(3, all);
}

PINEDA_SCENE(texenv_combine, "COMBINE: REPLACE, MODULATE, ADD, ADD_SIGNED, INTERPOLATE, SUBTRACT "
                             "with sources and operands") {
  const Gl13 gl;
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLuint t0 = gradient_texture(), t1 = checker_texture();
  const GLfloat env[4] = {0.25f, 0.625f, 0.875f, 0.375f};
  const GLenum funcs[6] = {GL_REPLACE,    GL_MODULATE,    GL_ADD,
                           GL_ADD_SIGNED, GL_INTERPOLATE, GL_SUBTRACT};
  const GLenum ops[4] = {GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA,
                         GL_ONE_MINUS_SRC_ALPHA};
  const GLenum srcs[4] = {GL_TEXTURE, GL_PRIMARY_COLOR, GL_CONSTANT, GL_PREVIOUS};
  for (int p = 0; p < 12; ++p) {
    panel(frame, p, 3, 4);
    gl.active(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, t1);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    gl.active(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, t0);
    glEnable(GL_TEXTURE_2D);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
    combine(funcs[p % 6], funcs[(p + 2) % 6]);
    for (int i = 0; i < 3; ++i)
      source(i, srcs[(p + i) % 4], ops[(p / 2 + i) % 4], srcs[(p + 2 * i + 1) % 4],
             ops[2 + (p + i) % 2]);
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, p >= 6 ? 2.0f : 1.0f);
    glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, p % 3 == 2 ? 4.0f : 1.0f);
    multi_quad(gl, 2, 2, 2, 80, 58);
    reset_units(gl);
  }
  const GLuint all[2] = {t0, t1};
  glDeleteTextures(2, all);
}

PINEDA_SCENE(texenv_dot3,
             "DOT3_RGB and DOT3_RGBA bump lighting with a normal map and the crossbar") {
  const Gl13 gl;
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLuint normals = normal_texture(), base = checker_texture();
  for (int p = 0; p < 4; ++p) {
    panel(frame, p, 2, 2);
    // Unit 0: DOT3 of the normal map with the light direction in the primary colour.
    gl.active(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, normals);
    glEnable(GL_TEXTURE_2D);
    combine(p % 2 ? GL_DOT3_RGBA : GL_DOT3_RGB, GL_REPLACE);
    source(0, GL_TEXTURE, GL_SRC_COLOR, GL_TEXTURE, GL_SRC_ALPHA);
    source(1, GL_PRIMARY_COLOR, GL_SRC_COLOR, GL_PRIMARY_COLOR, GL_SRC_ALPHA);
    // Unit 1: modulate by the base texture, or (p >= 2) by unit 0's texture via TEXTURE0.
    gl.active(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, base);
    glEnable(GL_TEXTURE_2D);
    combine(GL_MODULATE, GL_MODULATE);
    source(0, p >= 2 ? GL_TEXTURE0 : GL_TEXTURE, GL_SRC_COLOR, GL_TEXTURE, GL_SRC_ALPHA);
    source(1, GL_PREVIOUS, GL_SRC_COLOR, GL_PREVIOUS, GL_SRC_ALPHA);
    glBegin(GL_QUADS);
    const float xs[4] = {4, 120, 120, 4}, ys[4] = {4, 4, 120, 120};
    for (int v = 0; v < 4; ++v) {
      // Light direction (0.3, 0.4, 0.866) and variations, encoded as 0.5 + 0.5 l.
      const float lx = 0.3f * (v % 2 ? 1.0f : -1.0f), ly = 0.4f * (v / 2 ? 1.0f : -1.0f);
      glColor4f(0.5f + 0.5f * lx, 0.5f + 0.5f * ly, 0.5f + 0.5f * 0.866f, 0.75f);
      gl.coord2(GL_TEXTURE0, xs[v] / 115.3f, ys[v] / 115.3f);
      gl.coord2(GL_TEXTURE1, xs[v] / 57.3f + 0.01f, ys[v] / 57.3f + 0.01f);
      glVertex2f(xs[v], ys[v]);
    }
    glEnd();
    reset_units(gl);
  }
  const GLuint all[2] = {normals, base};
  glDeleteTextures(2, all);
}

PINEDA_SCENE(texgen_linear,
             "OBJECT_LINEAR and EYE_LINEAR texture generation on rotating geometry") {
  const Gl13 gl;
  clear_frame(0.0f, 0.0f, 0.125f);
  perspective(frame);
  const GLuint tex = checker_texture();
  glBindTexture(GL_TEXTURE_2D, tex);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  const GLfloat sp[4] = {0.5f, 0.0f, 0.25f, 0.5f}, tp[4] = {0.0f, 0.5f, 0.125f, 0.25f};
  for (int k = 0; k < 2; ++k) {
    const GLenum mode = k == 0 ? GL_OBJECT_LINEAR : GL_EYE_LINEAR;
    const GLenum plane = k == 0 ? GL_OBJECT_PLANE : GL_EYE_PLANE;
    glLoadIdentity();
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, mode);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, mode);
    glTexGenfv(GL_S, plane, sp); // eye planes are taken under the identity model-view
    glTexGenfv(GL_T, plane, tp);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glTranslatef(k == 0 ? -0.9f : 0.9f, 0.0f, -4.0f);
    glRotatef(35.0f, 1.0f, 1.0f, 0.0f);
    glColor3f(1, 1, 1);
    sphere(0.8f, 24, 16);
  }
  glDeleteTextures(1, &tex);
  reset_units(gl);
}

PINEDA_SCENE(texgen_sphere_map,
             "SPHERE_MAP environment mapping on a sphere and a torus-like ring") {
  const Gl13 gl;
  clear_frame(0.0f, 0.0f, 0.0f);
  perspective(frame);
  const GLuint tex = gradient_texture();
  glBindTexture(GL_TEXTURE_2D, tex);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glTranslatef(-0.8f, 0.0f, -4.0f);
  sphere(0.9f, 32, 20);
  glLoadIdentity();
  glTranslatef(0.9f, 0.0f, -5.0f);
  glRotatef(50.0f, 1.0f, 0.2f, 0.0f);
  glScalef(1.0f, 1.0f, 0.4f);
  glEnable(GL_NORMALIZE);
  sphere(1.0f, 32, 20);
  glDisable(GL_NORMALIZE);
  glDeleteTextures(1, &tex);
  reset_units(gl);
}

PINEDA_SCENE(texgen_cube_map, "Cube map with REFLECTION_MAP and NORMAL_MAP coordinates") {
  const Gl13 gl;
  clear_frame(0.0f, 0.0f, 0.0f);
  perspective(frame);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
  const float face_colors[6][3] = {{1, 0.25f, 0.25f}, {0.25f, 1, 0.25f}, {0.25f, 0.25f, 1},
                                   {1, 1, 0.25f},     {1, 0.25f, 1},     {0.25f, 1, 1}};
  for (int f = 0; f < 6; ++f) {
    std::vector<GLubyte> p(16 * 16 * 4);
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        const bool on = ((x / 4) + (y / 4)) % 2 == 0;
        for (int k = 0; k < 3; ++k)
          p[(y * 16 + x) * 4 + k] =
              static_cast<GLubyte>(face_colors[f][k] * (on ? 255.0f : 128.0f));
        p[(y * 16 + x) * 4 + 3] = 255;
      }
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA, 16, 16, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, p.data());
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_CUBE_MAP);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  for (int k = 0; k < 2; ++k) {
    const GLenum mode = k == 0 ? GL_REFLECTION_MAP : GL_NORMAL_MAP;
    for (GLenum c : {GL_S, GL_T, GL_R})
      glTexGeni(c, GL_TEXTURE_GEN_MODE, mode);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_GEN_R);
    glLoadIdentity();
    glTranslatef(k == 0 ? -0.85f : 0.85f, 0.0f, -4.0f);
    glRotatef(30.0f, 0.3f, 1.0f, 0.0f);
    sphere(0.8f, 32, 20);
  }
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glDeleteTextures(1, &tex);
  reset_units(gl);
}
