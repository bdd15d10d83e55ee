// The fragment shader's outputs and built-ins drawn (GL 2.1 §3.11.2): gl_FragDepth in the
// depth test and write (clamped, no polygon offset, also in depth-only passes), gl_PointCoord
// and COORD_REPLACE on point sprites (§3.3.1), gl_FragData[n] into draw buffer n (§4.2.1) and
// the link error for a program writing both gl_FragColor and gl_FragData, and pixel rectangles
// shaded with the pixel's colour (§3.6.4, §3.11).
#define GL_GLEXT_PROTOTYPES 1
#include "api_fixture.h"

#include <GL/glext.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

class FragOutputsTest : public GLTest {
protected:
  GLuint shader(GLenum type, const char* src) {
    const GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    EXPECT_EQ(ok, GL_TRUE) << src;
    return s;
  }
  // A linked program in use (vs null: fixed-function vertex stage).
  GLuint use(const char* vs, const char* fs) {
    const GLuint p = glCreateProgram();
    if (vs != nullptr) glAttachShader(p, shader(GL_VERTEX_SHADER, vs));
    glAttachShader(p, shader(GL_FRAGMENT_SHADER, fs));
    glLinkProgram(p);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    EXPECT_EQ(ok, GL_TRUE) << fs;
    glUseProgram(p);
    return p;
  }
  // A full-window quad at NDC depth z.
  static void quad(float z) {
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex3f(-1, -1, z);
    glTexCoord2f(1, 0);
    glVertex3f(1, -1, z);
    glTexCoord2f(1, 1);
    glVertex3f(1, 1, z);
    glTexCoord2f(0, 1);
    glVertex3f(-1, 1, z);
    glEnd();
  }
  static float depth_at(int x, int y) {
    float z = -1.0f;
    glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z);
    return z;
  }
};

const char* kVs = "void main() { gl_Position = gl_Vertex; gl_FrontColor = gl_Color;\n"
                  "  gl_TexCoord[0] = gl_MultiTexCoord0; }\n";

// The shader's depth is what the depth test compares and what is stored; polygon offset does
// not apply to it, and it is clamped to [0, 1].
TEST_F(FragOutputsTest, FragDepthReplacesTheDepth) {
  glEnable(GL_DEPTH_TEST);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0.0f, -1000.0f);
  const GLuint p = use(kVs, "void main() { gl_FragDepth = 0.25;\n"
                            "  gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0); }\n");
  quad(0.0f); // interpolated window z 0.5
  glUseProgram(0);
  glDisable(GL_POLYGON_OFFSET_FILL);
  EXPECT_NEAR(depth_at(5, 5), 0.25f, 1e-6f);
  EXPECT_EQ(pixel(5, 5), 0xff00ff00u);
  // Fixed function at window z 0.3: behind the shader's 0.25 under LESS.
  glColor3f(1, 0, 0);
  quad(-0.4f);
  EXPECT_EQ(pixel(5, 5), 0xff00ff00u);
  // Window z 0.2 is in front.
  quad(-0.6f);
  EXPECT_EQ(pixel(5, 5), 0xff0000ffu);
  // Clamping: 1.5 stores 1, -0.5 stores 0.
  glDepthFunc(GL_ALWAYS);
  const GLuint q = use(kVs, "uniform float z; void main() { gl_FragDepth = z;\n"
                            "  gl_FragColor = vec4(1.0); }\n");
  glUniform1f(glGetUniformLocation(q, "z"), 1.5f);
  quad(0.0f);
  EXPECT_EQ(depth_at(3, 3), 1.0f);
  glUniform1f(glGetUniformLocation(q, "z"), -0.5f);
  quad(0.0f);
  EXPECT_EQ(depth_at(3, 3), 0.0f);
  glUseProgram(0);
  glDeleteProgram(p);
  glDeleteProgram(q);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// A per-fragment depth: the left half of the window near, the right half far; a fixed-function
// quad in between shows through on the right only. Fully covered blocks the interpolated depth
// would reject whole are still shaded.
TEST_F(FragOutputsTest, FragDepthPerFragmentAndBlockRejection) {
  glEnable(GL_DEPTH_TEST);
  glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
  glColor3f(1, 0, 0);
  quad(0.0f); // stored 0.5 everywhere
  // Interpolated z 0.9 (every block rejected by the interpolated depth), shader depth 0.1 on
  // the left.
  const GLuint p = use(kVs, "void main() {\n"
                            "  gl_FragDepth = gl_FragCoord.x < 16.0 ? 0.1 : 0.9;\n"
                            "  gl_FragColor = vec4(0.0, 0.0, 1.0, 1.0); }\n");
  quad(0.8f);
  glUseProgram(0);
  EXPECT_EQ(pixel(3, 10), 0xffff0000u);
  EXPECT_EQ(pixel(28, 10), 0xff0000ffu);
  EXPECT_NEAR(depth_at(3, 10), 0.1f, 1e-6f);
  EXPECT_NEAR(depth_at(28, 10), 0.5f, 1e-6f);
  glDeleteProgram(p);
}

// With the colour mask off (a depth pre-pass) the shader still runs: its depth and its
// discards decide what is stored.
TEST_F(FragOutputsTest, FragDepthAndDiscardInADepthOnlyPass) {
  glEnable(GL_DEPTH_TEST);
  glClear(GL_DEPTH_BUFFER_BIT);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  const GLuint p = use(kVs, "void main() {\n"
                            "  if (gl_FragCoord.y < 16.0) discard;\n"
                            "  gl_FragDepth = 0.125;\n"
                            "  gl_FragColor = vec4(1.0); }\n");
  quad(0.5f);
  glUseProgram(0);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  EXPECT_NEAR(depth_at(10, 28), 0.125f, 1e-6f);
  EXPECT_EQ(depth_at(10, 3), 1.0f);
  // The discarding shader alone, without gl_FragDepth: the interpolated depth where it keeps
  // fragments.
  glClear(GL_DEPTH_BUFFER_BIT);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  const GLuint q = use(kVs, "void main() { if (gl_FragCoord.x < 16.0) discard;\n"
                            "  gl_FragColor = vec4(1.0); }\n");
  quad(0.5f);
  glUseProgram(0);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  EXPECT_EQ(depth_at(3, 10), 1.0f);
  EXPECT_NEAR(depth_at(28, 10), 0.75f, 1e-6f);
  glDeleteProgram(p);
  glDeleteProgram(q);
}

// §3.3.1: gl_PointCoord runs from 0 to 1 across the sprite, t downwards with the UPPER_LEFT
// origin and upwards with LOWER_LEFT; gl_TexCoord[0] is replaced under COORD_REPLACE.
TEST_F(FragOutputsTest, PointCoordOnSprites) {
  glEnable(GL_POINT_SPRITE);
  glPointSize(8.0f);
  const GLuint p = use(kVs, "#version 120\nvoid main() {\n"
                            "  gl_FragColor = vec4(gl_PointCoord, 0.0, 1.0); }\n");
  glBegin(GL_POINTS);
  glVertex2f(0.0f, 0.0f); // window (16, 16): pixels 12..19
  glEnd();
  // Pixel 12: s = 1/2 + (12.5 - 16) / 8 = 1/16.
  const auto r = [&](int x, int y) { return pixel(x, y) & 0xffu; };
  const auto g = [&](int x, int y) { return (pixel(x, y) >> 8) & 0xffu; };
  EXPECT_EQ(r(12, 12), 16u); // round(255 / 16)
  EXPECT_EQ(r(19, 12), 239u);
  EXPECT_EQ(g(12, 19), 16u); // UPPER_LEFT: top row t = 1/16
  EXPECT_EQ(g(12, 12), 239u);
  EXPECT_EQ(pixel(11, 12), 0u);
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_POINTS);
  glVertex2f(0.0f, 0.0f);
  glEnd();
  EXPECT_EQ(g(12, 12), 16u);
  EXPECT_EQ(g(12, 19), 239u);
  // COORD_REPLACE on unit 0: gl_TexCoord[0] = (s, t, 0, 1).
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  const GLuint q = use(kVs, "void main() { gl_FragColor = gl_TexCoord[0].stqp; }\n");
  glClear(GL_COLOR_BUFFER_BIT);
  glTexCoord4f(0.5f, 0.5f, 0.5f, 0.5f);
  glBegin(GL_POINTS);
  glVertex2f(0.0f, 0.0f);
  glEnd();
  EXPECT_EQ(pixel(12, 12), 0x00ff1010u); // s 1/16, t 1/16 (LOWER_LEFT), q 1, r 0
  glUseProgram(0);
  glDeleteProgram(p);
  glDeleteProgram(q);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// Aliased points that are not sprites get the sprite coordinates over their square too, with t
// downwards whatever POINT_SPRITE_COORD_ORIGIN says (undefined in GL 2.1; llvmpipe's values).
TEST_F(FragOutputsTest, PointCoordOnAliasedPoints) {
  const GLuint p = use(kVs, "#version 120\nvoid main() {\n"
                            "  gl_FragColor = vec4(gl_PointCoord, 0.0, 1.0); }\n");
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
  glPointSize(8.0f);
  glBegin(GL_POINTS);
  glVertex2f(0.0f, 0.0f); // window (16, 16): pixels 12..19
  glEnd();
  EXPECT_EQ(pixel(12, 19), 0xff001010u); // s = t = 1/16 at the top left
  EXPECT_EQ(pixel(19, 12), 0xff00efefu); // s = t = 15/16 at the bottom right
  glUseProgram(0);
  glDeleteProgram(p);
}

// §4.2.1: gl_FragData[n] goes to draw buffer n (a NONE entry takes its output nowhere);
// gl_FragColor to every draw buffer.
TEST_F(FragOutputsTest, FragDataIntoDrawBuffers) {
  GLint max = 0;
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &max);
  EXPECT_EQ(max, 8);
  GLuint rb[3];
  glGenRenderbuffers(3, rb);
  GLuint f = 0;
  glGenFramebuffers(1, &f);
  glBindFramebuffer(GL_FRAMEBUFFER, f);
  for (int i = 0; i < 3; ++i) {
    glBindRenderbuffer(GL_RENDERBUFFER, rb[i]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 8, 8);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i),
                              GL_RENDERBUFFER, rb[i]);
  }
  const GLenum bufs[4] = {GL_COLOR_ATTACHMENT0, GL_NONE, GL_COLOR_ATTACHMENT2,
                          GL_COLOR_ATTACHMENT1};
  glDrawBuffers(4, bufs);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
  glViewport(0, 0, 8, 8);
  glClear(GL_COLOR_BUFFER_BIT);
  const GLuint p = use(kVs, "void main() {\n"
                            "  gl_FragData[0] = vec4(1.0, 0.0, 0.0, 1.0);\n"
                            "  gl_FragData[1] = vec4(0.0, 1.0, 0.0, 1.0);\n"
                            "  gl_FragData[2] = vec4(0.0, 0.0, 1.0, 1.0);\n"
                            "  gl_FragData[gl_MaxDrawBuffers - 5] = vec4(0.0, 1.0, 1.0, 1.0);\n"
                            "}\n");
  quad(0.0f);
  const auto read = [](GLenum buffer) {
    glReadBuffer(buffer);
    uint32_t v = 0;
    glReadPixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &v);
    return v;
  };
  EXPECT_EQ(read(GL_COLOR_ATTACHMENT0), 0xff0000ffu);
  EXPECT_EQ(read(GL_COLOR_ATTACHMENT2), 0xffff0000u); // draw buffer 2
  EXPECT_EQ(read(GL_COLOR_ATTACHMENT1), 0xffffff00u); // draw buffer 3
  const GLuint q = use(kVs, "void main() { gl_FragColor = vec4(0.0, 0.5, 1.0, 1.0); }\n");
  quad(0.0f);
  for (GLenum b : {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2})
    EXPECT_EQ(read(b), 0xffff8000u) << b;
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &f);
  glDeleteRenderbuffers(3, rb);
  glDeleteProgram(p);
  glDeleteProgram(q);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// One shader run stores into every draw buffer with the buffer's own format (RGB8: no alpha,
// destination alpha 1 in blending), after the depth test, under the shared blend and mask.
TEST_F(FragOutputsTest, FragDataWithDepthBlendAndMask) {
  GLuint rb[3];
  glGenRenderbuffers(3, rb);
  GLuint f = 0;
  glGenFramebuffers(1, &f);
  glBindFramebuffer(GL_FRAMEBUFFER, f);
  const GLenum formats[3] = {GL_RGBA8, GL_RGB8, GL_DEPTH_COMPONENT24};
  const GLenum points[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_DEPTH_ATTACHMENT};
  for (int i = 0; i < 3; ++i) {
    glBindRenderbuffer(GL_RENDERBUFFER, rb[i]);
    glRenderbufferStorage(GL_RENDERBUFFER, formats[i], 8, 8);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, points[i], GL_RENDERBUFFER, rb[i]);
  }
  const GLenum bufs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, bufs);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
  glViewport(0, 0, 8, 8);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  const GLuint p = use(kVs, "uniform vec4 c0, c1;\n"
                            "void main() { gl_FragData[0] = c0; gl_FragData[1] = c1; }\n");
  const GLint c0 = glGetUniformLocation(p, "c0"), c1 = glGetUniformLocation(p, "c1");
  glUniform4f(c0, 0.2f, 0.2f, 0.2f, 0.5f);
  glUniform4f(c1, 0.4f, 0.4f, 0.4f, 0.5f);
  quad(0.0f);
  // Behind: fails the depth test in both buffers.
  glUniform4f(c0, 1.0f, 1.0f, 1.0f, 1.0f);
  glUniform4f(c1, 1.0f, 1.0f, 1.0f, 1.0f);
  quad(0.5f);
  // In front, blended (SRC_ALPHA, ONE) with green masked off.
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glUniform4f(c0, 0.4f, 0.4f, 0.0f, 0.5f);
  glUniform4f(c1, 0.0f, 0.4f, 0.4f, 0.5f);
  quad(-0.5f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glUseProgram(0);
  const auto read = [](GLenum buffer) {
    glReadBuffer(buffer);
    uint8_t v[4] = {};
    glReadPixels(3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, v);
    return std::vector<int>{v[0], v[1], v[2], v[3]};
  };
  // Buffer 0: (0.2 + 0.2, 0.2, 0.2, 0.5 + 0.25) in 8-bit steps = (102, 51, 51, 192).
  EXPECT_EQ(read(GL_COLOR_ATTACHMENT0), (std::vector<int>{102, 51, 51, 192}));
  // Buffer 1 (RGB8): (0.4, 0.4, 0.4 + 0.2) with alpha read as 1.
  EXPECT_EQ(read(GL_COLOR_ATTACHMENT1), (std::vector<int>{102, 102, 153, 255}));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &f);
  glDeleteRenderbuffers(3, rb);
  glDeleteProgram(p);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// §4.1.4: with several fragment colours the alpha test takes colour zero's alpha for every
// draw buffer.
TEST_F(FragOutputsTest, AlphaTestUsesColorZero) {
  GLuint rb[2];
  glGenRenderbuffers(2, rb);
  GLuint f = 0;
  glGenFramebuffers(1, &f);
  glBindFramebuffer(GL_FRAMEBUFFER, f);
  for (int i = 0; i < 2; ++i) {
    glBindRenderbuffer(GL_RENDERBUFFER, rb[i]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 8, 8);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i),
                              GL_RENDERBUFFER, rb[i]);
  }
  const GLenum bufs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, bufs);
  glViewport(0, 0, 8, 8);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  const GLuint p = use(kVs, "void main() {\n"
                            "  float a = gl_FragCoord.x < 4.0 ? 0.0 : 1.0;\n"
                            "  gl_FragData[0] = vec4(1.0, 0.0, 0.0, a);\n"
                            "  gl_FragData[1] = vec4(0.0, 1.0, 0.0, 1.0 - a);\n"
                            "}\n");
  quad(0.0f);
  glUseProgram(0);
  glDisable(GL_ALPHA_TEST);
  const auto read = [](GLenum buffer, int x) {
    glReadBuffer(buffer);
    uint32_t v = 0;
    glReadPixels(x, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &v);
    return v;
  };
  EXPECT_EQ(read(GL_COLOR_ATTACHMENT0, 1), 0u);
  EXPECT_EQ(read(GL_COLOR_ATTACHMENT0, 6), 0xff0000ffu);
  EXPECT_EQ(read(GL_COLOR_ATTACHMENT1, 1), 0u);
  EXPECT_EQ(read(GL_COLOR_ATTACHMENT1, 6), 0x0000ff00u);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &f);
  glDeleteRenderbuffers(2, rb);
  glDeleteProgram(p);
}

// GLSL 1.10 §7.2: writing both gl_FragColor and gl_FragData is an error; when the two fragment
// shaders of a program split them, the link fails with a log.
TEST_F(FragOutputsTest, FragColorAndFragDataInOneProgramFailToLink) {
  const GLuint p = glCreateProgram();
  glAttachShader(p, shader(GL_FRAGMENT_SHADER, "void data() { gl_FragData[0] = vec4(1.0); }\n"));
  glAttachShader(p,
                 shader(GL_FRAGMENT_SHADER, "void data();\n"
                                            "void main() { gl_FragColor = vec4(0.5); data(); }\n"));
  glLinkProgram(p);
  GLint ok = GL_TRUE;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  EXPECT_EQ(ok, GL_FALSE);
  char log[512] = {};
  glGetProgramInfoLog(p, sizeof log, nullptr, log);
  EXPECT_NE(std::string(log).find("gl_FragColor and gl_FragData"), std::string::npos) << log;
  glDeleteProgram(p);
}

// §3.6.4, §3.11: DrawPixels fragments reach the shader with the pixel's colour as gl_Color
// and the raster position's texture coordinates; Bitmap fragments with the raster colour.
TEST_F(FragOutputsTest, PixelRectanglesThroughTheShader) {
  const GLuint p = use(nullptr, "void main() {\n"
                                "  gl_FragColor = vec4(gl_Color.b, gl_Color.g, gl_Color.r,\n"
                                "                      gl_TexCoord[0].s);\n"
                                "}\n");
  glTexCoord2f(0.5f, 0.0f);
  glRasterPos2f(-1.0f, -1.0f);
  const uint8_t px[4 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 10, 20, 30, 255};
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(pixel(0, 0), 0x80ff0000u);
  EXPECT_EQ(pixel(1, 0), 0x8000ff00u);
  EXPECT_EQ(pixel(0, 1), 0x800000ffu);
  EXPECT_EQ(pixel(1, 1), 0x800a141eu);
  const GLubyte bits[1] = {0x80};
  glColor3f(0.2f, 0.4f, 0.6f);
  glRasterPos2f(0.0f, 0.0f); // window (16, 16)
  glBitmap(1, 1, 0, 0, 0, 0, bits);
  EXPECT_EQ(pixel(16, 16), 0x80336699u);
  glUseProgram(0);
  glDeleteProgram(p);
}

} // namespace
