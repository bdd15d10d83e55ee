// Texture objects and images (GL 2.1 §3.8.1-§3.8.12): sized internal formats, sub-images with
// the unpack state, copies from the framebuffer, automatic mipmap generation, level-of-detail
// clamps, borders, non-power-of-two sizes, cube map faces, depth textures with comparison and
// completeness. Every scene deletes its textures and leaves the texture state at the defaults.
#include "scene_util.h"

#include <cmath>
#include <vector>

using namespace scenes;

namespace {

// A w x h RGBA gradient with a coarse checker in blue and an alpha ramp.
std::vector<GLubyte> gradient(int w, int h, int seed) {
  std::vector<GLubyte> p(static_cast<size_t>(w) * h * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      GLubyte* t = &p[(static_cast<size_t>(y) * w + x) * 4];
      t[0] = static_cast<GLubyte>((x * 255) / (w > 1 ? w - 1 : 1));
      t[1] = static_cast<GLubyte>((y * 255) / (h > 1 ? h - 1 : 1));
      t[2] = static_cast<GLubyte>(((x / 2 + y / 2 + seed) % 2) ? 220 : 40);
      t[3] = static_cast<GLubyte>(255 - ((x + y) * 255) / (w + h > 2 ? w + h - 2 : 1));
    }
  return p;
}

void defaults() {
  for (GLenum t : {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP}) {
    glBindTexture(t, 0);
    glDisable(t);
  }
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glColor4f(1, 1, 1, 1);
}

// A textured quad from (x0,y0) to (x1,y1) with coordinates (s0,t0)-(s1,t1).
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

GLuint new_texture(GLenum target) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(target, t);
  return t;
}

void filters(GLenum target, GLenum min, GLenum mag) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(min));
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(mag));
}

// Background stripes so that alpha blending shows.
void stripes(const Frame& frame) {
  window_projection(frame);
  for (int i = 0; i < 16; ++i) {
    palette_color(i);
    glRectf(static_cast<float>(i * frame.width / 16), 0,
            static_cast<float>((i + 1) * frame.width / 16), static_cast<float>(frame.height));
  }
}

// A perspective floor from z = -1 to z = -40 with the texture repeated 16 times.
void floor_quad(const Frame& f, float x0, float x1) {
  glViewport(0, 0, f.width, f.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 60.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glBegin(GL_QUADS);
  glTexCoord2f(x0, 0);
  glVertex3f(x0, -1.0f, -1.0f);
  glTexCoord2f(x1, 0);
  glVertex3f(x1, -1.0f, -1.0f);
  glTexCoord2f(x1, 16);
  glVertex3f(x1, -1.0f, -40.0f);
  glTexCoord2f(x0, 16);
  glVertex3f(x0, -1.0f, -40.0f);
  glEnd();
}

} // namespace

PINEDA_SCENE(texobj_sized_formats,
             "Sized and legacy internal formats (RGBA4, RGB5_A1, R3_G3_B2, RGB10_A2, L4A4 ...)") {
  stripes(frame);
  const GLint formats[16] = {
      GL_RGBA4, GL_RGB5_A1, GL_R3_G3_B2,          GL_RGB10_A2, GL_LUMINANCE4_ALPHA4,  GL_RGB4,
      GL_RGB5,  GL_RGBA2,   GL_INTENSITY4,        GL_ALPHA4,   GL_LUMINANCE12_ALPHA4, GL_RGB16,
      3,        2,          GL_LUMINANCE6_ALPHA2, GL_RGBA12};
  const GLuint tex = new_texture(GL_TEXTURE_2D);
  const std::vector<GLubyte> img = gradient(16, 16, 0);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  for (int i = 0; i < 16; ++i) {
    panel(frame, i, 4, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, formats[i], 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
    // NEAREST on the left half, LINEAR on the right; texel edges off pixel centres.
    filters(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
    quad(2, 2, 30, 60, 0.0031f, 0.0047f, 0.4969f, 0.9953f);
    filters(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR);
    quad(32, 2, 60, 60, 0.5031f, 0.0047f, 0.9969f, 0.9953f);
  }
  glDeleteTextures(1, &tex);
  defaults();
}

PINEDA_SCENE(texobj_subimage_unpack,
             "glTexSubImage2D with row length, skips, alignment, BGRA and packed 5_6_5/4_4_4_4") {
  clear_frame(0.1f, 0.1f, 0.1f);
  const GLuint tex = new_texture(GL_TEXTURE_2D);
  const std::vector<GLubyte> base = gradient(32, 32, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, base.data());
  filters(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  // A 12 x 9 BGR patch taken from the middle of a 20-pixel-wide client image.
  std::vector<GLubyte> client(20 * 12 * 3);
  for (size_t i = 0; i < client.size(); ++i)
    client[i] = static_cast<GLubyte>(i * 7 + 3);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 20);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 3, 12, 9, GL_BGR, GL_UNSIGNED_BYTE, client.data());
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  std::vector<GLushort> packed(10 * 10);
  for (size_t i = 0; i < packed.size(); ++i)
    packed[i] = static_cast<GLushort>(i * 2654435761u);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 18, 4, 10, 10, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, packed.data());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 16, 18, 10, 10, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4,
                  packed.data());
  std::vector<GLfloat> lum(6 * 6);
  for (size_t i = 0; i < lum.size(); ++i)
    lum[i] = static_cast<float>(i) / 35.0f;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 22, 6, 6, GL_LUMINANCE, GL_FLOAT, lum.data());
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  window_projection(frame);
  quad(8, 8, 248, 248, 0.0013f, 0.0017f, 1.0013f, 1.0017f);
  glDeleteTextures(1, &tex);
  defaults();
}

PINEDA_SCENE(texobj_copy_tex_image,
             "glCopyTexImage2D and glCopyTexSubImage2D from drawn content, drawn back") {
  clear_frame(0.0f, 0.0f, 0.2f);
  window_projection(frame);
  // Source content in the bottom-left 64 x 64.
  for (int i = 0; i < 8; ++i) {
    palette_color(i);
    glRectf(static_cast<float>(i * 8), 0, static_cast<float>(i * 8 + 8), 64);
    palette_color(i + 8);
    glRectf(0, static_cast<float>(i * 8), 64, static_cast<float>(i * 8 + 4));
  }
  const GLuint tex = new_texture(GL_TEXTURE_2D);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 64, 64, 0);
  glColor3f(1, 1, 1);
  glRectf(10, 10, 30, 50);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 32, 16, 0, 0, 40, 40);
  filters(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  quad(80, 80, 248, 248, 0.0021f, 0.0023f, 1.0021f, 1.0023f);
  // A luminance copy and a 1D copy of one row.
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 0, 0, 64, 64, 0);
  quad(80, 8, 150, 72, 0.0021f, 0.0023f, 1.0021f, 1.0023f);
  glDisable(GL_TEXTURE_2D);
  const GLuint t1 = new_texture(GL_TEXTURE_1D);
  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 0, 20, 64, 0);
  filters(GL_TEXTURE_1D, GL_NEAREST, GL_NEAREST);
  glEnable(GL_TEXTURE_1D);
  glBegin(GL_QUADS);
  glTexCoord1f(0.0021f);
  glVertex2f(160, 8);
  glTexCoord1f(1.0021f);
  glVertex2f(248, 8);
  glTexCoord1f(1.0021f);
  glVertex2f(248, 72);
  glTexCoord1f(0.0021f);
  glVertex2f(160, 72);
  glEnd();
  glDeleteTextures(1, &tex);
  glDeleteTextures(1, &t1);
  defaults();
}

PINEDA_SCENE(texobj_generate_mipmap,
             "GENERATE_MIPMAP on power-of-two and non-power-of-two textures, trilinear floors") {
  clear_frame(0.0f, 0.0f, 0.0f);
  GLuint tex[2];
  glGenTextures(2, tex);
  const int sizes[2][2] = {{64, 64}, {48, 20}};
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  for (int i = 0; i < 2; ++i) {
    glBindTexture(GL_TEXTURE_2D, tex[i]);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    const std::vector<GLubyte> img = gradient(sizes[i][0], sizes[i][1], i);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, sizes[i][0], sizes[i][1], 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 img.data());
    // A later change of the base level regenerates the levels.
    const GLubyte white[4 * 4 * 4] = {255, 255, 255, 255, 255, 255, 255, 255};
    glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
    filters(GL_TEXTURE_2D, i == 0 ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR);
    floor_quad(frame, -1.9f + 2.0f * static_cast<float>(i), -0.1f + 2.0f * static_cast<float>(i));
  }
  glDeleteTextures(2, tex);
  defaults();
}

PINEDA_SCENE(texobj_lod_clamps, "MIN_LOD, MAX_LOD, BASE_LEVEL and MAX_LEVEL on mipmapped floors") {
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLuint tex = new_texture(GL_TEXTURE_2D);
  for (int l = 0, s = 32; s >= 1; ++l, s /= 2) {
    std::vector<GLubyte> img = gradient(s, s, l);
    const float* c = palette(l);
    for (size_t i = 0; i < img.size(); i += 4) {
      img[i] = static_cast<GLubyte>(img[i] / 4 + c[0] * 190);
      img[i + 1] = static_cast<GLubyte>(img[i + 1] / 4 + c[1] * 190);
      img[i + 2] = static_cast<GLubyte>(c[2] * 255);
    }
    glTexImage2D(GL_TEXTURE_2D, l, GL_RGB, s, s, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  }
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  filters(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  const struct {
    float min_lod, max_lod;
    int base, max;
  } cases[4] = {{0.5f, 1000.0f, 0, 1000},
                {-1000.0f, 2.25f, 0, 1000},
                {-1000.0f, 1000.0f, 1, 3},
                {1.5f, 2.5f, 2, 5}};
  for (int i = 0; i < 4; ++i) {
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, cases[i].min_lod);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, cases[i].max_lod);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, cases[i].base);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, cases[i].max);
    floor_quad(frame, -2.0f + static_cast<float>(i), -1.0f + static_cast<float>(i));
  }
  glDeleteTextures(1, &tex);
  defaults();
}

PINEDA_SCENE(
    texobj_border_colour,
    "CLAMP and CLAMP_TO_BORDER with border colours on RGBA, LUMINANCE and ALPHA textures") {
  stripes(frame);
  const GLuint tex = new_texture(GL_TEXTURE_2D);
  const std::vector<GLubyte> img = gradient(8, 8, 2);
  const GLint formats[3] = {GL_RGBA, GL_LUMINANCE, GL_ALPHA};
  const GLfloat border[4] = {0.9f, 0.3f, 0.6f, 0.4f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor4f(0.8f, 1.0f, 0.9f, 1.0f);
  for (int i = 0; i < 12; ++i) {
    panel(frame, i, 3, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, formats[i % 3], 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
    const GLenum wrap = (i / 3) % 2 == 0 ? GL_CLAMP : GL_CLAMP_TO_BORDER;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
    const GLenum f = i < 6 ? GL_LINEAR : GL_NEAREST;
    filters(GL_TEXTURE_2D, f, f);
    quad(2, 2, 80, 58, -0.3013f, -0.2517f, 1.2987f, 1.2483f);
  }
  glDeleteTextures(1, &tex);
  defaults();
}

PINEDA_SCENE(texobj_npot,
             "Non-power-of-two textures: REPEAT and MIRRORED_REPEAT, LINEAR, rotated") {
  clear_frame(0.05f, 0.05f, 0.05f);
  const GLuint tex = new_texture(GL_TEXTURE_2D);
  const std::vector<GLubyte> img = gradient(13, 7, 3);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 13, 7, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  const GLenum wraps[2] = {GL_REPEAT, GL_MIRRORED_REPEAT};
  for (int i = 0; i < 4; ++i) {
    panel(frame, i, 2, 2);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, static_cast<GLint>(wraps[i % 2]));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, static_cast<GLint>(wraps[i % 2]));
    const GLenum f = i < 2 ? GL_LINEAR : GL_NEAREST;
    filters(GL_TEXTURE_2D, f, f);
    glPushMatrix();
    glTranslatef(63, 63, 0);
    glRotatef(23.0f, 0, 0, 1);
    quad(-80, -80, 80, 80, -1.1234f, -0.8765f, 2.0432f, 1.9876f);
    glPopMatrix();
  }
  glDeleteTextures(1, &tex);
  defaults();
}

PINEDA_SCENE(texobj_cube_faces,
             "Cube map faces from explicit (s,t,r) directions, NEAREST and LINEAR") {
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLuint tex = new_texture(GL_TEXTURE_CUBE_MAP);
  for (int f = 0; f < 6; ++f) {
    std::vector<GLubyte> img = gradient(8, 8, f);
    const float* c = palette(f * 2 + 1);
    for (size_t i = 0; i < img.size(); i += 4)
      img[i + 2] = static_cast<GLubyte>(c[2] * 200);
    glTexImage2D(static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GL_RGB, 8, 8, 0,
                 GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glEnable(GL_TEXTURE_CUBE_MAP);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  // Each panel sweeps directions around one major axis.
  const float axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int i = 0; i < 12; ++i) {
    panel(frame, i, 4, 3);
    const float* a = axes[i % 6];
    const GLenum f = i < 6 ? GL_NEAREST : GL_LINEAR;
    filters(GL_TEXTURE_CUBE_MAP, f, f);
    // u and v: the two axes other than the major one.
    const int m = a[0] != 0 ? 0 : (a[1] != 0 ? 1 : 2);
    const int u = (m + 1) % 3, v = (m + 2) % 3;
    const float corners[4][2] = {{-1.3f, -1.2f}, {1.25f, -1.2f}, {1.25f, 1.3f}, {-1.3f, 1.3f}};
    const float pos[4][2] = {{2, 2}, {60, 2}, {60, 82}, {2, 82}};
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; ++k) {
      float d[3] = {a[0], a[1], a[2]};
      d[u] = corners[k][0] * 0.97f + 0.0123f;
      d[v] = corners[k][1] * 0.97f + 0.0171f;
      glTexCoord3f(d[0], d[1], d[2]);
      glVertex2f(pos[k][0], pos[k][1]);
    }
    glEnd();
  }
  glDeleteTextures(1, &tex);
  defaults();
}

PINEDA_SCENE(texobj_depth_compare,
             "Depth textures: compare functions, NEAREST and LINEAR, LUMINANCE/INTENSITY/ALPHA") {
  stripes(frame);
  const GLuint tex = new_texture(GL_TEXTURE_2D);
  std::vector<GLfloat> z(16 * 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      z[static_cast<size_t>(y) * 16 + x] = 0.5f + 0.4f * std::sin(static_cast<float>(x) * 0.7f) *
                                                      std::cos(static_cast<float>(y) * 0.5f);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 16, 16, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
               z.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  const GLenum funcs[4] = {GL_LEQUAL, GL_GREATER, GL_LESS, GL_GEQUAL};
  const GLenum modes[3] = {GL_LUMINANCE, GL_INTENSITY, GL_ALPHA};
  for (int i = 0; i < 16; ++i) {
    panel(frame, i, 4, 4);
    const bool compare = i < 12;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE,
                    compare ? GL_COMPARE_R_TO_TEXTURE : GL_NONE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, static_cast<GLint>(funcs[i % 4]));
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, static_cast<GLint>(modes[i % 3]));
    const GLenum f = (i / 4) % 2 == 0 ? GL_NEAREST : GL_LINEAR;
    filters(GL_TEXTURE_2D, f, f);
    // r runs from 0.1 to 0.9 across the quad.
    glBegin(GL_QUADS);
    glTexCoord3f(0.0031f, 0.0047f, 0.1f);
    glVertex2f(2, 2);
    glTexCoord3f(0.9969f, 0.0047f, 0.9f);
    glVertex2f(60, 2);
    glTexCoord3f(0.9969f, 0.9953f, 0.9f);
    glVertex2f(60, 60);
    glTexCoord3f(0.0031f, 0.9953f, 0.1f);
    glVertex2f(2, 60);
    glEnd();
  }
  glDeleteTextures(1, &tex);
  defaults();
}

PINEDA_SCENE(texobj_3d_linear, "3D textures: LINEAR and mipmapped LINEAR_MIPMAP_LINEAR slices") {
  const auto tex_image_3d = proc<PFNGLTEXIMAGE3DPROC>("glTexImage3D");
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLuint tex = new_texture(GL_TEXTURE_3D);
  for (int l = 0, s = 8; s >= 1; ++l, s /= 2) {
    std::vector<GLubyte> vol;
    for (int z = 0; z < s; ++z) {
      const std::vector<GLubyte> slice = gradient(s, s, z + l);
      vol.insert(vol.end(), slice.begin(), slice.end());
    }
    tex_image_3d(GL_TEXTURE_3D, l, GL_RGBA, s, s, s, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol.data());
  }
  glEnable(GL_TEXTURE_3D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  for (int i = 0; i < 4; ++i) {
    panel(frame, i, 2, 2);
    filters(GL_TEXTURE_3D, i < 2 ? GL_LINEAR : GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    const float r = 0.2f + 0.25f * static_cast<float>(i);
    const float scale = i < 2 ? 1.0f : 6.0f; // minified in the mipmapped panels
    glBegin(GL_QUADS);
    glTexCoord3f(0.0123f, 0.0171f, r);
    glVertex2f(4, 4);
    glTexCoord3f(scale + 0.0123f, 0.0171f, r + 0.3f);
    glVertex2f(120, 4);
    glTexCoord3f(scale + 0.0123f, scale + 0.0171f, r + 0.1f);
    glVertex2f(120, 120);
    glTexCoord3f(0.0123f, scale + 0.0171f, r);
    glVertex2f(4, 120);
    glEnd();
  }
  glDeleteTextures(1, &tex);
  defaults();
}

PINEDA_SCENE(texobj_incomplete,
             "Incomplete textures disable the unit; deleting a bound texture reverts to 0") {
  clear_frame(0.2f, 0.3f, 0.4f);
  GLuint tex[2];
  glGenTextures(2, tex);
  const std::vector<GLubyte> img = gradient(8, 8, 4);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  window_projection(frame);
  glColor3f(1.0f, 0.5f, 0.0f);
  // Mipmap filter without the levels: incomplete, the fragment colour shows.
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  quad(8, 8, 120, 120, 0, 0, 1, 1);
  // Complete once the filter needs no mipmaps.
  filters(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  quad(136, 8, 248, 120, 0.0031f, 0.0047f, 1.0031f, 1.0047f);
  // BASE_LEVEL beyond the specified levels: incomplete.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2);
  quad(8, 136, 120, 248, 0, 0, 1, 1);
  // The default texture (name 0) after deleting the bound one: never specified, incomplete.
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  filters(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glDeleteTextures(1, &tex[1]);
  quad(136, 136, 248, 248, 0, 0, 1, 1);
  glDeleteTextures(1, &tex[0]);
  defaults();
}
