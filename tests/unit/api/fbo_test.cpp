// Framebuffer and renderbuffer objects (ARB_framebuffer_object, EXT_framebuffer_object):
// every command's errors, completeness (§4.4.4), INVALID_FRAMEBUFFER_OPERATION with nothing
// written, rendering into textures of every target and into renderbuffers, deletion of bound
// and attached objects, OUT_OF_MEMORY, draw and read buffers, GenerateMipmap.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdint>
#include <vector>

#include "api_fixture.h"

namespace {

class FboTest : public GLTest {
protected:
  static GLuint texture2d(int w, int h, GLenum internal = GL_RGBA8, int level = 0) {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    const GLenum format = internal == GL_DEPTH_COMPONENT24 || internal == GL_DEPTH_COMPONENT16 ||
                                  internal == GL_DEPTH_COMPONENT
                              ? GL_DEPTH_COMPONENT
                              : GL_RGBA;
    glTexImage2D(GL_TEXTURE_2D, level, GLint(internal), w, h, 0, format, GL_UNSIGNED_BYTE, nullptr);
    return t;
  }
  static GLuint renderbuffer(GLenum format, int w, int h) {
    GLuint r = 0;
    glGenRenderbuffers(1, &r);
    glBindRenderbuffer(GL_RENDERBUFFER, r);
    glRenderbufferStorage(GL_RENDERBUFFER, format, w, h);
    return r;
  }
  static GLuint framebuffer() {
    GLuint f = 0;
    glGenFramebuffers(1, &f);
    glBindFramebuffer(GL_FRAMEBUFFER, f);
    return f;
  }
  static void quad(float x0, float y0, float x1, float y1, float z) {
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
    glEnd();
  }
  static uint32_t read_pixel(int x, int y) {
    uint8_t p[4] = {};
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    return p[0] | (p[1] << 8) | (p[2] << 16) | (uint32_t(p[3]) << 24);
  }
  static std::vector<uint8_t> tex_bytes(GLenum target, int level, int w, int h, int d = 1,
                                        GLenum format = GL_RGBA) {
    const int comps = format == GL_RGBA ? 4 : 1;
    std::vector<uint8_t> out(size_t(w) * h * d * comps);
    glGetTexImage(target, level, format, GL_UNSIGNED_BYTE, out.data());
    return out;
  }
};

#define EXPECT_ERROR(e) EXPECT_EQ(glGetError(), static_cast<GLenum>(e))

TEST_F(FboTest, NamesBindingsAndQueries) {
  GLuint f[2];
  glGenFramebuffers(2, f);
  EXPECT_NE(f[0], f[1]);
  EXPECT_FALSE(glIsFramebuffer(f[0])); // a name becomes an object when bound
  glBindFramebuffer(GL_FRAMEBUFFER, f[0]);
  EXPECT_TRUE(glIsFramebuffer(f[0]));
  GLint v = -1;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &v);
  EXPECT_EQ(v, GLint(f[0]));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, f[1]);
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &v);
  EXPECT_EQ(v, GLint(f[0]));
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &v);
  EXPECT_EQ(v, GLint(f[1]));
  // A name never generated may be bound (compatibility semantics).
  glBindFramebuffer(GL_FRAMEBUFFER, 77);
  EXPECT_ERROR(GL_NO_ERROR);
  EXPECT_TRUE(glIsFramebuffer(77));
  glBindFramebuffer(GL_TEXTURE_2D, 0);
  EXPECT_ERROR(GL_INVALID_ENUM);
  glGenFramebuffers(-1, f);
  EXPECT_ERROR(GL_INVALID_VALUE);
  glDeleteFramebuffers(-1, f);
  EXPECT_ERROR(GL_INVALID_VALUE);
  // Deleting the bound framebuffer reverts both bindings to 0.
  glBindFramebuffer(GL_FRAMEBUFFER, 77);
  GLuint n77 = 77;
  glDeleteFramebuffers(1, &n77);
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &v);
  EXPECT_EQ(v, 0);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &v);
  EXPECT_EQ(v, 0);
  EXPECT_FALSE(glIsFramebuffer(77));
  glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &v);
  EXPECT_EQ(v, 8);
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &v);
  EXPECT_EQ(v, 8);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &v);
  EXPECT_EQ(v, 16384);
  EXPECT_ERROR(GL_NO_ERROR);
  // Between Begin and End.
  glBegin(GL_POINTS);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glEnd();
  EXPECT_ERROR(GL_INVALID_OPERATION);
}

TEST_F(FboTest, RenderbufferErrorsAndQueries) {
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 4, 4);
  EXPECT_ERROR(GL_INVALID_OPERATION); // none bound
  GLuint r = 0;
  glGenRenderbuffers(1, &r);
  EXPECT_FALSE(glIsRenderbuffer(r));
  glBindRenderbuffer(GL_RENDERBUFFER, r);
  EXPECT_TRUE(glIsRenderbuffer(r));
  glBindRenderbuffer(GL_TEXTURE_2D, r);
  EXPECT_ERROR(GL_INVALID_ENUM);
  glRenderbufferStorage(GL_TEXTURE_2D, GL_RGBA8, 4, 4);
  EXPECT_ERROR(GL_INVALID_ENUM);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_COMPRESSED_RGBA, 4, 4);
  EXPECT_ERROR(GL_INVALID_ENUM);
  glRenderbufferStorage(GL_RENDERBUFFER, 4, 4, 4);
  EXPECT_ERROR(GL_INVALID_ENUM);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, -1, 4);
  EXPECT_ERROR(GL_INVALID_VALUE);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 16385, 4);
  EXPECT_ERROR(GL_INVALID_VALUE);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, 4, 4);
  EXPECT_ERROR(GL_INVALID_VALUE); // MAX_SAMPLES is 0
  struct Case {
    GLenum format;
    GLint r, a, d, s;
  } cases[] = {{GL_RGBA8, 8, 8, 0, 0},
               {GL_RGB5, 5, 0, 0, 0},
               {GL_RGBA4, 4, 4, 0, 0},
               {GL_ALPHA8, 0, 8, 0, 0},
               {GL_LUMINANCE8, 8, 0, 0, 0},
               {GL_INTENSITY8, 8, 8, 0, 0},
               {GL_DEPTH_COMPONENT16, 0, 0, 16, 0},
               {GL_DEPTH_COMPONENT24, 0, 0, 24, 0},
               {GL_DEPTH_COMPONENT32, 0, 0, 32, 0},
               {GL_STENCIL_INDEX8, 0, 0, 0, 8},
               {GL_DEPTH24_STENCIL8, 0, 0, 24, 8},
               {GL_DEPTH_STENCIL, 0, 0, 24, 8}};
  for (const Case& c : cases) {
    glRenderbufferStorage(GL_RENDERBUFFER, c.format, 5, 3);
    EXPECT_ERROR(GL_NO_ERROR);
    GLint v = 0;
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &v);
    EXPECT_EQ(v, 5);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_HEIGHT, &v);
    EXPECT_EQ(v, 3);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &v);
    EXPECT_EQ(v, GLint(c.format));
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_RED_SIZE, &v);
    EXPECT_EQ(v, c.r) << c.format;
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_ALPHA_SIZE, &v);
    EXPECT_EQ(v, c.a) << c.format;
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_DEPTH_SIZE, &v);
    EXPECT_EQ(v, c.d) << c.format;
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_STENCIL_SIZE, &v);
    EXPECT_EQ(v, c.s) << c.format;
  }
  GLint v = 0;
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_TEXTURE_WIDTH, &v);
  EXPECT_ERROR(GL_INVALID_ENUM);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &v);
  EXPECT_ERROR(GL_INVALID_OPERATION);
  // Deleting the bound renderbuffer unbinds it.
  glBindRenderbuffer(GL_RENDERBUFFER, r);
  glDeleteRenderbuffers(1, &r);
  glGetIntegerv(GL_RENDERBUFFER_BINDING, &v);
  EXPECT_EQ(v, 0);
  EXPECT_FALSE(glIsRenderbuffer(r));
  EXPECT_ERROR(GL_NO_ERROR);
}

TEST_F(FboTest, OutOfMemoryLeavesTheContextWorking) {
  const GLuint r = renderbuffer(GL_RGBA8, 8, 8);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 16384, 16384);
  EXPECT_ERROR(GL_OUT_OF_MEMORY);
  GLint v = 0;
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &v);
  EXPECT_EQ(v, 8); // unchanged
  const GLuint f = framebuffer();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, r);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(read_pixel(3, 3), 0xff00ff00u);
  EXPECT_ERROR(GL_NO_ERROR);
  glDeleteFramebuffers(1, &f);
}

TEST_F(FboTest, Completeness) {
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(glCheckFramebufferStatus(GL_TEXTURE_2D), 0u);
  EXPECT_ERROR(GL_INVALID_ENUM);
  framebuffer();
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER),
            GLenum(GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT));
  GLuint empty = 0;
  glGenRenderbuffers(1, &empty);
  glBindRenderbuffer(GL_RENDERBUFFER, empty);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, empty);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER),
            GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT)); // no storage
  const GLuint depth = renderbuffer(GL_DEPTH_COMPONENT24, 8, 8);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, depth);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER),
            GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT)); // depth at a colour point
  const GLuint color = renderbuffer(GL_RGBA8, 8, 8);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, color);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER),
            GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT)); // colour at the depth point
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER),
            GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT)); // no stencil in a depth format
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
  glDrawBuffer(GL_COLOR_ATTACHMENT1);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER),
            GLenum(GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER));
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glReadBuffer(GL_COLOR_ATTACHMENT2);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER),
            GLenum(GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER));
  glReadBuffer(GL_NONE);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  // A depth-only framebuffer with no colour buffers is complete.
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, 0);
  glDrawBuffer(GL_NONE);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  // A level of a texture that has no image is incomplete.
  const GLuint t = texture2d(8, 8);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 1);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 0);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  // Respecifying the attached image as a depth image makes it incomplete at a colour point.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 8, 8, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
               nullptr);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT));
  EXPECT_ERROR(GL_NO_ERROR);
}

TEST_F(FboTest, IncompleteFramebufferIsNeitherWrittenNorRead) {
  const GLuint t = texture2d(8, 8);
  std::vector<uint8_t> red(8 * 8 * 4);
  for (size_t i = 0; i < red.size(); i += 4)
    red[i] = 255, red[i + 3] = 255;
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, red.data());
  framebuffer();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 0);
  glDrawBuffer(GL_COLOR_ATTACHMENT1); // names no image: incomplete
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_ERROR(GL_INVALID_FRAMEBUFFER_OPERATION);
  quad(-1, -1, 1, 1, 0);
  EXPECT_ERROR(GL_INVALID_FRAMEBUFFER_OPERATION);
  const float verts[] = {-1, -1, 1, -1, 1, 1};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, verts);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_ERROR(GL_INVALID_FRAMEBUFFER_OPERATION);
  glDisableClientState(GL_VERTEX_ARRAY);
  glRasterPos2i(0, 0);
  const uint8_t px[16] = {};
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_ERROR(GL_INVALID_FRAMEBUFFER_OPERATION);
  const GLubyte bits[2] = {0xff, 0xff};
  glBitmap(8, 2, 0, 0, 0, 0, bits);
  EXPECT_ERROR(GL_INVALID_FRAMEBUFFER_OPERATION);
  glCopyPixels(0, 0, 2, 2, GL_COLOR);
  EXPECT_ERROR(GL_INVALID_FRAMEBUFFER_OPERATION);
  uint8_t out[4] = {};
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_ERROR(GL_INVALID_FRAMEBUFFER_OPERATION);
  GLuint t2 = 0;
  glGenTextures(1, &t2);
  glBindTexture(GL_TEXTURE_2D, t2);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 0, 0, 2, 2, 0);
  EXPECT_ERROR(GL_INVALID_FRAMEBUFFER_OPERATION);
  // Nothing was written.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindTexture(GL_TEXTURE_2D, t);
  EXPECT_EQ(tex_bytes(GL_TEXTURE_2D, 0, 8, 8), red);
  EXPECT_ERROR(GL_NO_ERROR);
}

TEST_F(FboTest, RenderToTextureAndReadBack) {
  const GLuint t = texture2d(16, 8);
  const GLuint depth = renderbuffer(GL_DEPTH_COMPONENT24, 16, 8);
  const GLuint f = framebuffer();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  GLint v = 0;
  glGetIntegerv(GL_DEPTH_BITS, &v);
  EXPECT_EQ(v, 24);
  glGetIntegerv(GL_STENCIL_BITS, &v);
  EXPECT_EQ(v, 0);
  glViewport(0, 0, 16, 8);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glColor3f(0, 1, 0);
  quad(-1, -1, 0, 1, 0.5f); // left half, far
  glColor3f(0, 0, 1);
  quad(-1, -1, 1, 1, 0.9f); // whole, farther: hidden on the left
  glDisable(GL_DEPTH_TEST);
  EXPECT_EQ(read_pixel(2, 2), 0xff00ff00u);
  EXPECT_EQ(read_pixel(12, 2), 0xffff0000u);
  // The window was not touched.
  EXPECT_EQ(pixel(2, 2), 0u);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  const std::vector<uint8_t> img = tex_bytes(GL_TEXTURE_2D, 0, 16, 8);
  EXPECT_EQ(img[(2 * 16 + 2) * 4 + 1], 255);
  EXPECT_EQ(img[(2 * 16 + 12) * 4 + 2], 255);
  // Drawn with the texture in the window.
  glViewport(0, 0, kW, kH);
  glEnable(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glColor3f(1, 1, 1);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(-1, -1);
  glTexCoord2f(1, 0);
  glVertex2f(1, -1);
  glTexCoord2f(1, 1);
  glVertex2f(1, 1);
  glTexCoord2f(0, 1);
  glVertex2f(-1, 1);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  EXPECT_EQ(pixel(4, 16), 0xff00ff00u);
  EXPECT_EQ(pixel(28, 16), 0xffff0000u);
  glDeleteFramebuffers(1, &f);
  EXPECT_ERROR(GL_NO_ERROR);
}

TEST_F(FboTest, DepthTextureStencilRenderbufferAndSeparateReadFramebuffer) {
  const GLuint color = renderbuffer(GL_RGBA8, 8, 8);
  const GLuint stencil = renderbuffer(GL_STENCIL_INDEX8, 8, 8);
  GLuint zt = texture2d(8, 8, GL_DEPTH_COMPONENT24);
  const GLuint f = framebuffer();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, stencil);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, zt, 0);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glViewport(0, 0, 8, 8);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 5, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glEnable(GL_DEPTH_TEST);
  quad(-1, -1, 0, 1, 0.0f); // left half: depth 0.5, stencil 5
  glDisable(GL_DEPTH_TEST);
  glStencilFunc(GL_EQUAL, 5, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glColor3f(1, 1, 0);
  quad(-1, -1, 1, 1, 0.0f);
  glDisable(GL_STENCIL_TEST);
  EXPECT_EQ(read_pixel(1, 1), 0xff00ffffu);
  EXPECT_EQ(read_pixel(6, 1), 0u);
  GLubyte s = 0;
  glReadPixels(1, 1, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
  EXPECT_EQ(s, 5);
  GLfloat z = 0;
  glReadPixels(1, 1, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z);
  EXPECT_NEAR(z, 0.5f, 1e-6f);
  // The depth texture holds what was drawn.
  glBindTexture(GL_TEXTURE_2D, zt);
  std::vector<float> zs(64);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, zs.data());
  EXPECT_NEAR(zs[8 + 1], 0.5f, 1e-6f);
  EXPECT_NEAR(zs[8 + 6], 1.0f, 1e-6f);
  // Reading from the framebuffer object while drawing into the window.
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  EXPECT_EQ(read_pixel(1, 1), 0xff00ffffu);
  glViewport(0, 0, kW, kH);
  glRasterPos2i(-1, -1);
  glCopyPixels(0, 0, 8, 8, GL_COLOR);
  EXPECT_EQ(pixel(1, 1), 0xff00ffffu);
  glDeleteFramebuffers(1, &f);
  EXPECT_ERROR(GL_NO_ERROR);
}

TEST_F(FboTest, CubeFaces3DSlicesAndLevels) {
  GLuint cube = 0, vol = 0;
  glGenTextures(1, &cube);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  for (int face = 0; face < 6; ++face)
    for (int level = 0; level < 3; ++level)
      glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), level, GL_RGBA8, 4 >> level,
                   4 >> level, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGenTextures(1, &vol);
  glBindTexture(GL_TEXTURE_3D, vol);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 4, 4, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  framebuffer();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, cube,
                         1);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  GLint v = 0;
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE, &v);
  EXPECT_EQ(v, GL_TEXTURE_CUBE_MAP_NEGATIVE_Y);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &v);
  EXPECT_EQ(v, 1);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, vol, 0, 2);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER, &v);
  EXPECT_EQ(v, 2);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, vol, 0, 3);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER),
            GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT)); // slice 3 of a depth of 3
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, cube, 0, 0);
  EXPECT_ERROR(GL_INVALID_OPERATION); // not a 3D texture
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  EXPECT_EQ(tex_bytes(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 1, 2, 2)[2], 255);
  EXPECT_EQ(tex_bytes(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 1, 2, 2)[2], 0);
  EXPECT_EQ(tex_bytes(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, 4, 4)[2], 0);
  glBindTexture(GL_TEXTURE_3D, vol);
  const std::vector<uint8_t> slices = tex_bytes(GL_TEXTURE_3D, 0, 4, 4, 3);
  EXPECT_EQ(slices[(2 * 16 + 5) * 4 + 1], 255);
  EXPECT_EQ(slices[(1 * 16 + 5) * 4 + 1], 0);
  EXPECT_ERROR(GL_NO_ERROR);
}

TEST_F(FboTest, AttachmentErrors) {
  const GLuint t = texture2d(4, 4);
  const GLuint r = renderbuffer(GL_RGBA8, 4, 4);
  // The window has no attachment points for these commands.
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 0);
  EXPECT_ERROR(GL_INVALID_OPERATION);
  GLint v = 0;
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  EXPECT_ERROR(GL_INVALID_OPERATION);
  framebuffer();
  glFramebufferTexture2D(GL_TEXTURE_2D, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 0);
  EXPECT_ERROR(GL_INVALID_ENUM);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_BACK, GL_TEXTURE_2D, t, 0);
  EXPECT_ERROR(GL_INVALID_ENUM);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT8, GL_TEXTURE_2D, t, 0);
  EXPECT_ERROR(GL_INVALID_OPERATION);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, t, 0);
  EXPECT_ERROR(GL_INVALID_ENUM);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X, t,
                         0);
  EXPECT_ERROR(GL_INVALID_OPERATION); // a 2D texture is not a cube map
  glFramebufferTexture1D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_1D, t, 0);
  EXPECT_ERROR(GL_INVALID_OPERATION);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 999, 0);
  EXPECT_ERROR(GL_INVALID_OPERATION);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, -1);
  EXPECT_ERROR(GL_INVALID_VALUE);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 12);
  EXPECT_ERROR(GL_INVALID_VALUE);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, r);
  EXPECT_ERROR(GL_INVALID_ENUM);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, 999);
  EXPECT_ERROR(GL_INVALID_OPERATION);
  // Queries of an empty attachment point.
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  EXPECT_EQ(v, GL_NONE);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &v);
  EXPECT_ERROR(GL_INVALID_ENUM);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, r);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  EXPECT_EQ(v, GL_RENDERBUFFER);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &v);
  EXPECT_EQ(v, GLint(r));
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE, &v);
  EXPECT_EQ(v, 8);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &v);
  EXPECT_ERROR(GL_INVALID_ENUM); // a renderbuffer has no level
  // DEPTH_STENCIL_ATTACHMENT attaches both points; its query needs the same image at both.
  const GLuint ds = renderbuffer(GL_DEPTH24_STENCIL8, 4, 4);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ds);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &v);
  EXPECT_EQ(v, GLint(ds));
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT,
                                        GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &v);
  EXPECT_EQ(v, 8);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &v);
  EXPECT_ERROR(GL_INVALID_OPERATION);
  EXPECT_ERROR(GL_NO_ERROR);
}

TEST_F(FboTest, DeletingAttachedObjects) {
  const GLuint t = texture2d(4, 4);
  const GLuint r = renderbuffer(GL_DEPTH_COMPONENT16, 4, 4);
  GLuint f[2];
  glGenFramebuffers(2, f);
  for (GLuint fb : f) {
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, r);
  }
  // f[1] is bound: deleting detaches from it, not from f[0].
  glDeleteTextures(1, &t);
  glDeleteRenderbuffers(1, &r);
  GLint v = -1;
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  EXPECT_EQ(v, GL_NONE);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  EXPECT_EQ(v, GL_NONE);
  glBindFramebuffer(GL_FRAMEBUFFER, f[0]);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  EXPECT_EQ(v, GL_TEXTURE);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  EXPECT_EQ(v, GL_RENDERBUFFER);
  EXPECT_FALSE(glIsTexture(t));
  // The orphaned images are still rendered into.
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glClearColor(1, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  EXPECT_EQ(read_pixel(1, 1), 0xff00ffffu);
  glDeleteFramebuffers(2, f);
  EXPECT_ERROR(GL_NO_ERROR);
}

TEST_F(FboTest, DrawAndReadBuffers) {
  // The window's draw buffer: attachments are not its buffers.
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  EXPECT_ERROR(GL_INVALID_OPERATION);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  EXPECT_ERROR(GL_INVALID_OPERATION);
  const GLenum two_window[] = {GL_FRONT_LEFT, GL_FRONT_LEFT};
  glDrawBuffers(2, two_window);
  EXPECT_ERROR(GL_INVALID_OPERATION); // twice
  const GLenum front[] = {GL_FRONT};
  glDrawBuffers(1, front);
  EXPECT_ERROR(GL_INVALID_ENUM); // names two buffers
  const GLenum back[] = {GL_BACK_LEFT};
  glDrawBuffers(1, back);
  EXPECT_ERROR(GL_INVALID_OPERATION); // not in a single-buffered window
  glDrawBuffers(9, two_window);
  EXPECT_ERROR(GL_INVALID_VALUE);
  const GLuint a = texture2d(4, 4), b = texture2d(4, 4), c = texture2d(4, 4);
  const GLuint f = framebuffer();
  GLint v = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &v);
  EXPECT_EQ(v, GL_COLOR_ATTACHMENT0); // a framebuffer object's initial draw buffer
  glGetIntegerv(GL_READ_BUFFER, &v);
  EXPECT_EQ(v, GL_COLOR_ATTACHMENT0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, a, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, b, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, c, 0);
  glDrawBuffer(GL_BACK);
  EXPECT_ERROR(GL_INVALID_OPERATION);
  glDrawBuffer(GL_COLOR_ATTACHMENT8);
  EXPECT_ERROR(GL_INVALID_OPERATION);
  glDrawBuffer(GL_TEXTURE_2D);
  EXPECT_ERROR(GL_INVALID_ENUM);
  glReadBuffer(GL_FRONT);
  EXPECT_ERROR(GL_INVALID_OPERATION);
  const GLenum dup[] = {GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, dup);
  EXPECT_ERROR(GL_INVALID_OPERATION);
  const GLenum bufs[] = {GL_COLOR_ATTACHMENT2, GL_NONE, GL_COLOR_ATTACHMENT0};
  glDrawBuffers(3, bufs);
  EXPECT_ERROR(GL_NO_ERROR);
  glGetIntegerv(GL_DRAW_BUFFER2, &v);
  EXPECT_EQ(v, GL_COLOR_ATTACHMENT0);
  glGetIntegerv(GL_DRAW_BUFFER1, &v);
  EXPECT_EQ(v, GL_NONE);
  glGetIntegerv(GL_DRAW_BUFFER, &v);
  EXPECT_EQ(v, GL_COLOR_ATTACHMENT2);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glViewport(0, 0, 4, 4);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor4f(1, 0, 1, 1);
  quad(-1, -1, 1, 1, 0);
  // The draw and read buffers belong to the framebuffer object; the window keeps its own.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glGetIntegerv(GL_DRAW_BUFFER, &v);
  EXPECT_EQ(v, GL_FRONT);
  glGetIntegerv(GL_DRAW_BUFFER2, &v);
  EXPECT_EQ(v, GL_NONE);
  glBindFramebuffer(GL_FRAMEBUFFER, f);
  glGetIntegerv(GL_DRAW_BUFFER2, &v);
  EXPECT_EQ(v, GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  for (GLuint t : {a, c}) {
    glBindTexture(GL_TEXTURE_2D, t);
    EXPECT_EQ(tex_bytes(GL_TEXTURE_2D, 0, 4, 4)[0], 255);
  }
  glBindTexture(GL_TEXTURE_2D, b);
  EXPECT_EQ(tex_bytes(GL_TEXTURE_2D, 0, 4, 4)[0], 0);
  // Framebuffer bindings are not attribute state.
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glBindFramebuffer(GL_FRAMEBUFFER, f);
  glPopAttrib();
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &v);
  EXPECT_EQ(v, GLint(f));
  EXPECT_ERROR(GL_NO_ERROR);
}

TEST_F(FboTest, BaseFormatsReadBackExpanded) {
  GLuint lum = 0, rgb = 0;
  glGenTextures(1, &lum);
  glBindTexture(GL_TEXTURE_2D, lum);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE8, 4, 4, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, nullptr);
  glGenTextures(1, &rgb);
  glBindTexture(GL_TEXTURE_2D, rgb);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  framebuffer();
  glClearColor(0.5f, 0.25f, 0.75f, 0.0f);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, lum, 0);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glClear(GL_COLOR_BUFFER_BIT);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, rgb, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  GLint v = 0;
  glGetIntegerv(GL_ALPHA_BITS, &v);
  EXPECT_EQ(v, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindTexture(GL_TEXTURE_2D, lum);
  std::vector<uint8_t> l = tex_bytes(GL_TEXTURE_2D, 0, 4, 4, 1, GL_LUMINANCE);
  EXPECT_EQ(l[5], 128);
  glBindTexture(GL_TEXTURE_2D, rgb);
  std::vector<uint8_t> c = tex_bytes(GL_TEXTURE_2D, 0, 4, 4);
  EXPECT_EQ(c[0], 128);
  EXPECT_EQ(c[1], 64);
  EXPECT_EQ(c[3], 255); // an RGB image has alpha 1
  EXPECT_ERROR(GL_NO_ERROR);
}

TEST_F(FboTest, GenerateMipmap) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  uint8_t texels[4 * 4 * 4] = {};
  for (int i = 0; i < 16; ++i)
    texels[i * 4] = (i % 2) ? 200 : 100, texels[i * 4 + 3] = 255;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glGenerateMipmap(GL_TEXTURE_2D);
  EXPECT_ERROR(GL_NO_ERROR);
  GLint w = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 2, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(w, 1);
  EXPECT_EQ(tex_bytes(GL_TEXTURE_2D, 1, 2, 2)[0], 150);
  glGenerateMipmap(GL_TEXTURE_RECTANGLE_ARB);
  EXPECT_ERROR(GL_INVALID_ENUM);
  GLuint cube = 0;
  glGenTextures(1, &cube);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               texels);
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
  EXPECT_ERROR(GL_INVALID_OPERATION); // not cube complete
  glBegin(GL_POINTS);
  glGenerateMipmap(GL_TEXTURE_2D);
  glEnd();
  EXPECT_ERROR(GL_INVALID_OPERATION);
}

TEST_F(FboTest, DisplayListsExecuteFramebufferCommandsAtOnce) {
  const GLuint t = texture2d(4, 4);
  const GLuint f = framebuffer();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBindFramebuffer(GL_FRAMEBUFFER, f);
  const GLenum bufs[] = {GL_NONE};
  glDrawBuffers(1, bufs); // compiled
  glEndList();
  GLint v = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &v);
  EXPECT_EQ(v, GLint(f));
  glGetIntegerv(GL_DRAW_BUFFER, &v);
  EXPECT_EQ(v, GL_COLOR_ATTACHMENT0);
  glCallList(list);
  glGetIntegerv(GL_DRAW_BUFFER, &v);
  EXPECT_EQ(v, GL_NONE);
  EXPECT_ERROR(GL_NO_ERROR);
}

} // namespace

namespace {

// EXT_packed_depth_stencil: DEPTH_STENCIL textures and pixel transfers, CopyPixels of both.
class PackedDepthStencilTest : public GLTest {};

TEST_F(PackedDepthStencilTest, TexturesPixelTransfersAndAttachments) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  std::vector<GLuint> texels(4 * 4);
  for (int i = 0; i < 16; ++i)
    texels[i] = (GLuint(i * 1000000) << 8) | GLuint(i * 3);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 4, 4, 0, GL_DEPTH_STENCIL,
               GL_UNSIGNED_INT_24_8, texels.data());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLint v = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, &v);
  EXPECT_EQ(v, 8);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &v);
  EXPECT_EQ(v, 24);
  std::vector<GLuint> back(16);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, back.data());
  EXPECT_EQ(back, texels);
  // Errors: the type and format go together, and with the internal format.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 4, 4, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT,
               nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_INT_24_8, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 4, 4, 0, GL_STENCIL_INDEX, GL_INT, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_STENCIL_INDEX, GL_INT, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  // Depth data into a depth-stencil image keeps its stencil; depth-stencil data into a depth
  // image keeps the depth (GL 3.3 §3.8.3).
  const float half = 0.5f;
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 3, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &half);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, back.data());
  EXPECT_EQ(back[12], (0x800000u << 8) | (texels[12] & 0xffu));
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 3, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8,
                  &texels[12]);
  const GLuint patch[4] = {0xffffff01u, 0xffffff02u, 0xffffff03u, 0xffffff04u};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, patch);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, back.data());
  EXPECT_EQ(back[5], 0xffffff01u);
  EXPECT_EQ(back[10], 0xffffff04u);
  EXPECT_EQ(back[0], texels[0]);
  // Attached at both points, drawn into with depth and stencil tests.
  GLuint color = 0, f = 0;
  glGenRenderbuffers(1, &color);
  glBindRenderbuffer(GL_RENDERBUFFER, color);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 4, 4);
  glGenFramebuffers(1, &f);
  glBindFramebuffer(GL_FRAMEBUFFER, f);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, t, 0);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glGetIntegerv(GL_STENCIL_BITS, &v);
  EXPECT_EQ(v, 8);
  glViewport(0, 0, 4, 4);
  glClearDepth(0.25);
  glClearStencil(0x33);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  GLuint ds[16] = {};
  glReadPixels(0, 0, 4, 4, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds);
  EXPECT_EQ(ds[7], (0x400000u << 8) | 0x33u);
  // DrawPixels and CopyPixels of DEPTH_STENCIL.
  glDepthFunc(GL_ALWAYS);
  glEnable(GL_DEPTH_TEST);
  glRasterPos2f(-1, -1);
  const GLuint one = (0x800000u << 8) | 0x5au;
  glDrawPixels(1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &one);
  glRasterPos2f(0, 0); // window (2, 2)
  glCopyPixels(0, 0, 1, 1, GL_DEPTH_STENCIL);
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glReadPixels(0, 0, 4, 4, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds);
  EXPECT_EQ(ds[0], one);
  EXPECT_EQ(ds[2 * 4 + 2], one);
  EXPECT_EQ(ds[1], (0x400000u << 8) | 0x33u);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_FLOAT, ds);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_INT_24_8, ds);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glCopyPixels(0, 0, 1, 1, GL_DEPTH_STENCIL_ATTACHMENT);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &f);
  // The window of this fixture has a depth and a stencil buffer: CopyPixels of both there.
  glViewport(0, 0, kW, kH);
  glClearDepth(0.25);
  glClearStencil(0x33);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glRasterPos2f(0, 0);
  glCopyPixels(0, 0, 2, 2, GL_DEPTH_STENCIL);
  glReadPixels(kW / 2, kH / 2, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds);
  EXPECT_EQ(ds[0], (0x400000u << 8) | 0x33u);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

} // namespace

namespace {

// EXT_framebuffer_blit: errors, NEAREST and LINEAR scaling, mirroring, depth and stencil, the
// scissor test, buffers missing from one side.
class BlitTest : public GLTest {
protected:
  void SetUp() override {
    GLTest::SetUp();
    glGenRenderbuffers(3, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 8, 8);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, 8, 8);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[2]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT16, 8, 8);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
    // A 2x2 checker of four colours, each a 4x4 block.
    const GLubyte colors[4][4] = {
        {255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}};
    std::vector<GLubyte> px(8 * 8 * 4);
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x)
        for (int k = 0; k < 4; ++k)
          px[(y * 8 + x) * 4 + k] = colors[(y / 4) * 2 + x / 4][k];
    glViewport(0, 0, 8, 8);
    glRasterPos2f(-1, -1);
    glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
    glClearDepth(0.75);
    glClearStencil(7);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
  GLuint rb[3] = {}, fbo = 0;
};

TEST_F(BlitTest, Errors) {
  glBlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT | GL_ACCUM_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glBlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_LINEAR_MIPMAP_LINEAR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glBlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, GL_DEPTH_BUFFER_BIT, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, GL_STENCIL_BUFFER_BIT, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  // Depth formats differ (24 bits against 16).
  GLuint other = 0;
  glGenFramebuffers(1, &other);
  glBindFramebuffer(GL_FRAMEBUFFER, other);
  glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[2]);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE); // else incomplete (its read buffer names no image)
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  glBlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  // Incomplete draw framebuffer.
  glDrawBuffer(GL_COLOR_ATTACHMENT3);
  glBlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &other);
  glBegin(GL_POINTS);
  glBlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(BlitTest, ColorScaledMirroredAndScissored) {
  // 1:1.
  glBlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(pixel(1, 1), 0xff0000ffu);
  EXPECT_EQ(pixel(6, 6), 0xffffffffu);
  // Doubled, NEAREST: block edges at 8.
  glBlitFramebuffer(0, 0, 8, 8, 16, 16, 32, 32, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(pixel(23, 16), 0xff0000ffu);
  EXPECT_EQ(pixel(24, 16), 0xff00ff00u);
  EXPECT_EQ(pixel(31, 31), 0xffffffffu);
  // Mirrored in x and y.
  glBlitFramebuffer(0, 0, 8, 8, 8, 8, 0, 0, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(pixel(1, 1), 0xffffffffu);
  EXPECT_EQ(pixel(6, 6), 0xff0000ffu);
  // LINEAR, doubled: at the block edge the colours mix, away from it they do not.
  glBlitFramebuffer(0, 0, 8, 8, 16, 0, 32, 16, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  EXPECT_EQ(pixel(16, 0), 0xff0000ffu);
  const uint32_t mid = pixel(23, 0);
  EXPECT_GT(mid & 0xffu, 100u);
  EXPECT_GT((mid >> 8) & 0xffu, 30u);
  // Scissored: only the box is written.
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(2, 2, 2, 2);
  glBlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glDisable(GL_SCISSOR_TEST);
  EXPECT_EQ(pixel(2, 2), 0xff0000ffu);
  EXPECT_EQ(pixel(1, 1), 0u);
  EXPECT_EQ(pixel(4, 4), 0u);
  // Source pixels outside the read framebuffer write nothing.
  glBlitFramebuffer(-8, 0, 8, 8, 0, 0, 16, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(pixel(0, 0), 0u);
  EXPECT_EQ(pixel(8, 0), 0xff0000ffu);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(BlitTest, DepthAndStencil) {
  // The window of the fixture has 24 depth bits and 8 stencil bits, as the renderbuffer.
  glBlitFramebuffer(0, 0, 8, 8, 4, 4, 12, 12, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
                    GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  GLuint ds = 0;
  glReadPixels(5, 5, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &ds);
  EXPECT_EQ(ds, (0xbfffffu << 8) | 7u); // 0.75 in 24 bits
  glReadPixels(2, 2, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &ds);
  EXPECT_EQ(ds & 0xffu, 0u); // untouched
  // Colour was not in the mask.
  EXPECT_EQ(pixel(5, 5), 0u);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

} // namespace
