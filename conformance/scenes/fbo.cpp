// Framebuffer objects (ARB_framebuffer_object / EXT_framebuffer_object): rendering into
// textures and renderbuffers and drawing the results in the window. Render to texture with a
// depth renderbuffer, a packed depth-stencil renderbuffer, cube faces and 3D slices as
// attachments, GenerateMipmap of a rendered texture, several draw buffers, a depth texture
// rendered and then used for depth comparison. Every scene deletes its objects and binds the
// window again.
#include "scene_util.h"

#include <cmath>

using namespace scenes;

namespace {

// The framebuffer object commands, looked up as every command newer than GL 1.1.
struct Fbo {
  PFNGLGENFRAMEBUFFERSPROC gen = proc<PFNGLGENFRAMEBUFFERSPROC>("glGenFramebuffers");
  PFNGLDELETEFRAMEBUFFERSPROC del = proc<PFNGLDELETEFRAMEBUFFERSPROC>("glDeleteFramebuffers");
  PFNGLBINDFRAMEBUFFERPROC bind = proc<PFNGLBINDFRAMEBUFFERPROC>("glBindFramebuffer");
  PFNGLFRAMEBUFFERTEXTURE2DPROC tex2d =
      proc<PFNGLFRAMEBUFFERTEXTURE2DPROC>("glFramebufferTexture2D");
  PFNGLFRAMEBUFFERTEXTURE3DPROC tex3d =
      proc<PFNGLFRAMEBUFFERTEXTURE3DPROC>("glFramebufferTexture3D");
  PFNGLFRAMEBUFFERRENDERBUFFERPROC rb =
      proc<PFNGLFRAMEBUFFERRENDERBUFFERPROC>("glFramebufferRenderbuffer");
  PFNGLGENRENDERBUFFERSPROC gen_rb = proc<PFNGLGENRENDERBUFFERSPROC>("glGenRenderbuffers");
  PFNGLDELETERENDERBUFFERSPROC del_rb = proc<PFNGLDELETERENDERBUFFERSPROC>("glDeleteRenderbuffers");
  PFNGLBINDRENDERBUFFERPROC bind_rb = proc<PFNGLBINDRENDERBUFFERPROC>("glBindRenderbuffer");
  PFNGLRENDERBUFFERSTORAGEPROC storage =
      proc<PFNGLRENDERBUFFERSTORAGEPROC>("glRenderbufferStorage");
  PFNGLCHECKFRAMEBUFFERSTATUSPROC status =
      proc<PFNGLCHECKFRAMEBUFFERSTATUSPROC>("glCheckFramebufferStatus");
  PFNGLGENERATEMIPMAPPROC mipmap = proc<PFNGLGENERATEMIPMAPPROC>("glGenerateMipmap");
  PFNGLDRAWBUFFERSPROC draw_buffers = proc<PFNGLDRAWBUFFERSPROC>("glDrawBuffers");

  GLuint framebuffer() const {
    GLuint f = 0;
    gen(1, &f);
    bind(GL_FRAMEBUFFER, f);
    return f;
  }
  GLuint renderbuffer(GLenum format, int w, int h) const {
    GLuint r = 0;
    gen_rb(1, &r);
    bind_rb(GL_RENDERBUFFER, r);
    storage(GL_RENDERBUFFER, format, w, h);
    return r;
  }
  void check() const {
    if (status(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("framebuffer incomplete");
  }
};

GLuint new_texture(GLenum target, GLenum min, GLenum mag) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(target, t);
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(min));
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(mag));
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  return t;
}

// A small lit, depth-tested scene of overlapping triangles in a w x h target: the content
// rendered into the framebuffer objects.
void inner_scene(int w, int h, int seed) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.6, 0.6, -0.6, 0.6, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -3);
  glEnable(GL_DEPTH_TEST);
  Rng rng(static_cast<std::uint32_t>(seed));
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 24; ++i) {
    const float cx = rng.range(-1.0f, 1.0f), cy = rng.range(-1.0f, 1.0f);
    const float cz = rng.range(-1.0f, 1.0f);
    for (int k = 0; k < 3; ++k) {
      palette_color(i + k * 5);
      glVertex3f(cx + rng.range(-0.6f, 0.6f), cy + rng.range(-0.6f, 0.6f),
                 cz + rng.range(-0.5f, 0.5f));
    }
  }
  glEnd();
  glDisable(GL_DEPTH_TEST);
}

// A quad from (x0,y0) to (x1,y1) in window pixels with coordinates (0,0)-(1,1).
void textured_quad(float x0, float y0, float x1, float y1) {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(x0, y0);
  glTexCoord2f(1, 0);
  glVertex2f(x1, y0);
  glTexCoord2f(1, 1);
  glVertex2f(x1, y1);
  glTexCoord2f(0, 1);
  glVertex2f(x0, y1);
  glEnd();
}

void window_again(const Fbo& fbo, const Frame& frame) {
  fbo.bind(GL_FRAMEBUFFER, 0);
  window_projection(frame);
  glColor4f(1, 1, 1, 1);
}

} // namespace

PINEDA_SCENE(fbo_render_to_texture,
             "A depth-tested scene rendered into an RGBA8 texture with a depth renderbuffer, "
             "then drawn in the window: magnified (LINEAR), 1:1 (NEAREST), halved (LINEAR)") {
  const Fbo fbo;
  clear_frame(0.2f, 0.2f, 0.25f);
  const GLuint tex = new_texture(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 96, 80, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  const GLuint depth = fbo.renderbuffer(GL_DEPTH_COMPONENT24, 96, 80);
  const GLuint f = fbo.framebuffer();
  fbo.tex2d(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  fbo.rb(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  fbo.check();
  glClearColor(0.1f, 0.3f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  inner_scene(96, 80, 7);
  window_again(fbo, frame);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  textured_quad(8, 8, 8 + 192, 8 + 160); // magnified, LINEAR
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  textured_quad(8, 176, 8 + 96, 176 + 80); // 1:1
  // Halved with LINEAR (NEAREST would sample exactly on texel corners, which GL leaves open).
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  textured_quad(120, 176, 120 + 48, 176 + 40);
  glDisable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  fbo.del(1, &f);
  fbo.del_rb(1, &depth);
  glDeleteTextures(1, &tex);
}

PINEDA_SCENE(fbo_packed_depth_stencil,
             "A DEPTH24_STENCIL8 renderbuffer at both attachment points: stencil masks and depth "
             "tests in a framebuffer object, shown through the colour texture",
             .stencil_bits = 8) {
  const Fbo fbo;
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLuint tex = new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 128, 128, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  const GLuint ds = fbo.renderbuffer(GL_DEPTH24_STENCIL8, 128, 128);
  const GLuint f = fbo.framebuffer();
  fbo.tex2d(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  fbo.rb(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ds);
  fbo.rb(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ds);
  fbo.check();
  glClearColor(0.3f, 0.3f, 0.6f, 1.0f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  // Stencil: a ring of value 1 (a disc, then a smaller disc back to 0).
  glViewport(0, 0, 128, 128);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 128, 0, 128, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_STENCIL_TEST);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  for (int pass = 0; pass < 2; ++pass) {
    glStencilFunc(GL_ALWAYS, pass == 0 ? 1 : 0, 0xff);
    const float r = pass == 0 ? 56.0f : 28.0f;
    glBegin(GL_TRIANGLE_FAN);
    glVertex2f(64, 64);
    for (int i = 0; i <= 48; ++i)
      glVertex2f(64 + r * std::cos(i * 2 * kPi / 48), 64 + r * std::sin(i * 2 * kPi / 48));
    glEnd();
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  inner_scene(128, 128, 11);
  glStencilFunc(GL_NOTEQUAL, 1, 0xff);
  inner_scene(128, 128, 12);
  glDisable(GL_STENCIL_TEST);
  window_again(fbo, frame);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  textured_quad(0, 0, 256, 256);
  glDisable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  fbo.del(1, &f);
  fbo.del_rb(1, &ds);
  glDeleteTextures(1, &tex);
}

PINEDA_SCENE(fbo_cube_and_3d_attachments,
             "Each face of a cube map and each slice of a 3D texture rendered as an attachment, "
             "then sampled: the cube through reflection coordinates, the 3D texture across "
             "slices") {
  const Fbo fbo;
  clear_frame(0.1f, 0.1f, 0.1f);
  const GLuint cube = new_texture(GL_TEXTURE_CUBE_MAP, GL_LINEAR, GL_LINEAR);
  for (int face = 0; face < 6; ++face)
    glTexImage2D(static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, GL_RGBA8, 32, 32, 0,
                 GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  const GLuint vol = new_texture(GL_TEXTURE_3D, GL_NEAREST, GL_NEAREST);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 32, 32, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  const GLuint f = fbo.framebuffer();
  for (int face = 0; face < 6; ++face) {
    fbo.tex2d(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
              static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), cube, 0);
    fbo.check();
    const float* c = palette(face * 2 + 1);
    glClearColor(c[0] * 0.5f, c[1] * 0.5f, c[2] * 0.5f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    inner_scene(32, 32, 20 + face);
  }
  for (int slice = 0; slice < 4; ++slice) {
    fbo.tex3d(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, vol, 0, slice);
    fbo.check();
    const float* c = palette(slice * 3);
    glClearColor(c[0], c[1], c[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    inner_scene(32, 32, 40 + slice);
  }
  window_again(fbo, frame);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  // The 3D texture: four quads, one per slice centre, on the left.
  glEnable(GL_TEXTURE_3D);
  for (int slice = 0; slice < 4; ++slice) {
    const float r = (slice + 0.5f) / 4.0f;
    const float y0 = 4.0f + slice * 62.0f;
    glBegin(GL_QUADS);
    glTexCoord3f(0, 0, r);
    glVertex2f(4, y0);
    glTexCoord3f(1, 0, r);
    glVertex2f(64, y0);
    glTexCoord3f(1, 1, r);
    glVertex2f(64, y0 + 60);
    glTexCoord3f(0, 1, r);
    glVertex2f(4, y0 + 60);
    glEnd();
  }
  glDisable(GL_TEXTURE_3D);
  // The cube map: a sphere-like fan of directions, each face's centre region once.
  glEnable(GL_TEXTURE_CUBE_MAP);
  const float dirs[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const float axes[6][2][3] = {{{0, 0, 1}, {0, 1, 0}}, {{0, 0, 1}, {0, 1, 0}},
                               {{1, 0, 0}, {0, 0, 1}}, {{1, 0, 0}, {0, 0, 1}},
                               {{1, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {0, 1, 0}}};
  for (int face = 0; face < 6; ++face) {
    const float x0 = 72.0f + (face % 3) * 60.0f, y0 = 72.0f + (face / 3) * 60.0f;
    const float* d = dirs[face];
    // Two axes perpendicular to the face's direction.
    const float* u = axes[face][0];
    const float* v = axes[face][1];
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; ++k) {
      const float a = (k == 1 || k == 2) ? 0.8f : -0.8f, b = k >= 2 ? 0.8f : -0.8f;
      glTexCoord3f(d[0] + a * u[0] + b * v[0], d[1] + a * u[1] + b * v[1],
                   d[2] + a * u[2] + b * v[2]);
      glVertex2f(x0 + (a > 0 ? 56.0f : 0.0f), y0 + (b > 0 ? 56.0f : 0.0f));
    }
    glEnd();
  }
  glDisable(GL_TEXTURE_CUBE_MAP);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  fbo.del(1, &f);
  glDeleteTextures(1, &cube);
  glDeleteTextures(1, &vol);
}

PINEDA_SCENE(fbo_generate_mipmap,
             "A scene rendered into a 128x128 texture, glGenerateMipmap, then drawn minified "
             "with trilinear filtering on a receding plane") {
  const Fbo fbo;
  clear_frame(0.05f, 0.05f, 0.1f);
  const GLuint tex = new_texture(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 128, 128, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  const GLuint f = fbo.framebuffer();
  fbo.tex2d(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  fbo.check();
  glClearColor(0.9f, 0.9f, 0.8f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  // Depth test without a depth buffer: drawn in order.
  inner_scene(128, 128, 31);
  fbo.bind(GL_FRAMEBUFFER, 0);
  fbo.mipmap(GL_TEXTURE_2D);
  glViewport(0, 0, frame.width, frame.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 60.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex3f(-2.0f, -1.0f, -1.0f);
  glTexCoord2f(4, 0);
  glVertex3f(2.0f, -1.0f, -1.0f);
  glTexCoord2f(4, 12);
  glVertex3f(2.0f, -1.0f, -40.0f);
  glTexCoord2f(0, 12);
  glVertex3f(-2.0f, -1.0f, -40.0f);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  window_projection(frame);
  fbo.del(1, &f);
  glDeleteTextures(1, &tex);
}

PINEDA_SCENE(fbo_draw_buffers,
             "glDrawBuffers into three colour attachments of different formats (RGBA8, RGB8, "
             "LUMINANCE8), blended, each shown in the window") {
  const Fbo fbo;
  clear_frame(0.0f, 0.0f, 0.0f);
  const GLenum formats[3] = {GL_RGBA8, GL_RGB8, GL_LUMINANCE8};
  GLuint tex[3];
  for (int i = 0; i < 3; ++i) {
    tex[i] = new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(formats[i]), 64, 64, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, nullptr);
  }
  const GLuint f = fbo.framebuffer();
  for (int i = 0; i < 3; ++i)
    fbo.tex2d(GL_FRAMEBUFFER, static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i), GL_TEXTURE_2D, tex[i],
              0);
  const GLenum bufs[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  fbo.draw_buffers(3, bufs);
  fbo.check();
  glClearColor(0.2f, 0.4f, 0.6f, 0.5f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glViewport(0, 0, 64, 64);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 64, 0, 64, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  for (int i = 0; i < 8; ++i) {
    palette_color(i, 0.6f);
    glRectf(4.0f + i * 6.0f, 2.0f + i * 3.0f, 24.0f + i * 6.0f, 40.0f + i * 2.0f);
  }
  glDisable(GL_BLEND);
  window_again(fbo, frame);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  for (int i = 0; i < 3; ++i) {
    glBindTexture(GL_TEXTURE_2D, tex[i]);
    textured_quad(4.0f + i * 84.0f, 60, 4.0f + i * 84.0f + 64, 124); // 1:1
  }
  glDisable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  fbo.del(1, &f);
  glDeleteTextures(3, tex);
}

PINEDA_SCENE(fbo_depth_texture_shadow,
             "A depth-only framebuffer object with a DEPTH_COMPONENT24 texture rendered from a "
             "light, then compared against (COMPARE_R_TO_TEXTURE) with eye-linear coordinates") {
  const Fbo fbo;
  const GLuint depth = new_texture(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 128, 128, 0, GL_DEPTH_COMPONENT,
               GL_UNSIGNED_INT, nullptr);
  const GLuint f = fbo.framebuffer();
  fbo.tex2d(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  fbo.check();
  glClear(GL_DEPTH_BUFFER_BIT);
  // The occluders, seen from the light looking down -z (orthographic).
  glViewport(0, 0, 128, 128);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, 0, 4);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLES);
  glVertex3f(-0.7f, -0.6f, -1.0f);
  glVertex3f(0.1f, -0.5f, -1.2f);
  glVertex3f(-0.3f, 0.5f, -0.9f);
  glVertex3f(0.2f, 0.1f, -1.5f);
  glVertex3f(0.8f, 0.2f, -1.5f);
  glVertex3f(0.5f, 0.8f, -1.5f);
  glEnd();
  glBegin(GL_QUADS); // the floor at z = -3
  glVertex3f(-1, -1, -3);
  glVertex3f(1, -1, -3);
  glVertex3f(1, 1, -3);
  glVertex3f(-1, 1, -3);
  glEnd();
  glDisable(GL_DEPTH_TEST);
  window_again(fbo, frame);
  // The floor in the window, shadowed where the depth texture has something nearer: r is the
  // floor's depth from the light ((3 - 0) / 4 = 0.75), s and t its position.
  clear_frame(0.0f, 0.0f, 0.0f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor3f(1.0f, 0.9f, 0.6f);
  glBegin(GL_QUADS);
  const float r = 0.745f;
  glTexCoord3f(0, 0, r);
  glVertex2f(8, 8);
  glTexCoord3f(1, 0, r);
  glVertex2f(248, 8);
  glTexCoord3f(1, 1, r);
  glVertex2f(248, 248);
  glTexCoord3f(0, 1, r);
  glVertex2f(8, 248);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glColor3f(1, 1, 1);
  fbo.del(1, &f);
  glDeleteTextures(1, &depth);
}

PINEDA_SCENE(fbo_blit,
             "glBlitFramebuffer from a rendered framebuffer object into the window: 1:1, "
             "doubled NEAREST and LINEAR, a third NEAREST, mirrored in x and y, scissored, and "
             "depth with stencil") {
  const Fbo fbo;
  auto blit = proc<PFNGLBLITFRAMEBUFFERPROC>("glBlitFramebuffer");
  clear_frame(0.15f, 0.1f, 0.1f);
  const GLuint color = fbo.renderbuffer(GL_RGBA8, 60, 48);
  const GLuint ds = fbo.renderbuffer(GL_DEPTH24_STENCIL8, 60, 48);
  const GLuint f = fbo.framebuffer();
  fbo.rb(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  fbo.rb(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ds);
  fbo.rb(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ds);
  fbo.check();
  glClearColor(0.2f, 0.5f, 0.3f, 1.0f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  inner_scene(60, 48, 51);
  glDisable(GL_STENCIL_TEST);
  fbo.bind(GL_DRAW_FRAMEBUFFER, 0);
  window_projection(frame);
  blit(0, 0, 60, 48, 4, 4, 64, 52, GL_COLOR_BUFFER_BIT, GL_NEAREST);      // 1:1
  blit(0, 0, 60, 48, 70, 4, 190, 100, GL_COLOR_BUFFER_BIT, GL_NEAREST);   // doubled
  blit(0, 0, 60, 48, 4, 104, 124, 200, GL_COLOR_BUFFER_BIT, GL_LINEAR);   // doubled, LINEAR
  blit(0, 0, 60, 48, 200, 4, 220, 20, GL_COLOR_BUFFER_BIT, GL_NEAREST);   // a third
  blit(0, 0, 60, 48, 190, 100, 130, 52, GL_COLOR_BUFFER_BIT, GL_NEAREST); // mirrored
  glEnable(GL_SCISSOR_TEST);
  glScissor(140, 110, 40, 30);
  blit(0, 0, 60, 48, 130, 104, 250, 200, GL_COLOR_BUFFER_BIT, GL_NEAREST); // scissored
  glDisable(GL_SCISSOR_TEST);
  // Depth and stencil into the window's buffers, then shown: a quad where the stencil is 1
  // and the depth test passes against the blitted depths.
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  blit(0, 0, 60, 48, 190, 200, 250, 248, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glColor3f(1.0f, 1.0f, 0.0f);
  glRectf(186, 196, 254, 252); // at depth 0.5
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glColor3f(1, 1, 1);
  fbo.bind(GL_FRAMEBUFFER, 0);
  fbo.del(1, &f);
  fbo.del_rb(1, &color);
  fbo.del_rb(1, &ds);
}
