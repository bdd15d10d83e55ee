// A vertex shader's outputs in place of the fixed-function vertex (GL 2.1 §2.20.2) where the
// pipeline reports vertices rather than drawing them: feedback (§5.3: window coordinates from
// gl_Position, gl_FrontColor, gl_TexCoord[0]), selection (§5.2), the raster position (§2.13);
// and the user clip planes against gl_ClipVertex (§2.12, §2.20.3) in draws and for the
// raster position. The feedback values are worked out by hand from the shaders.
#define GL_GLEXT_PROTOTYPES 1
#include "api_fixture.h"

#include <GL/glext.h>

#include <string>
#include <vector>

namespace {

class RenderModeShaderTest : public GLTest {
protected:
  GLuint program(const char* vs) {
    const GLuint s = glCreateShader(GL_VERTEX_SHADER);
    glShaderSource(s, 1, &vs, nullptr);
    glCompileShader(s);
    const GLuint p = glCreateProgram();
    glAttachShader(p, s);
    glLinkProgram(p);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    EXPECT_EQ(ok, GL_TRUE);
    glUseProgram(p);
    return p;
  }
  void triangle() {
    glBegin(GL_TRIANGLES);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(0, 1);
    glEnd();
  }
  void quad() {
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
  }
  GLenum err() { return glGetError(); }
};

TEST_F(RenderModeShaderTest, FeedbackReportsTheShaderOutputs) {
  program("void main() {\n"
          "  gl_Position = gl_Vertex * vec4(0.5, 0.5, 1.0, 1.0) + vec4(0.25, 0.0, 0.0, 0.0);\n"
          "  gl_FrontColor = vec4(0.25, 0.5, 0.75, 1.0);\n"
          "  gl_TexCoord[0] = vec4(gl_Vertex.xy, 0.5, 1.0);\n"
          "}\n");
  std::vector<GLfloat> buf(64, -1.0f);
  glFeedbackBuffer(static_cast<GLsizei>(buf.size()), GL_4D_COLOR_TEXTURE, buf.data());
  glRenderMode(GL_FEEDBACK);
  triangle();
  ASSERT_EQ(glRenderMode(GL_RENDER), 2 + 3 * 12);
  EXPECT_EQ(buf[0], static_cast<GLfloat>(GL_POLYGON_TOKEN));
  EXPECT_EQ(buf[1], 3.0f);
  // Clip x = 0.5 x + 0.25, y = 0.5 y, z = 0, w = 1; window (x + 1) * 16, (y + 1) * 16, 0.5.
  const float win[3][2] = {{12, 8}, {28, 8}, {20, 24}};
  const float obj[3][2] = {{-1, -1}, {1, -1}, {0, 1}};
  for (int v = 0; v < 3; ++v) {
    const GLfloat* f = &buf[static_cast<size_t>(2 + 12 * v)];
    EXPECT_FLOAT_EQ(f[0], win[v][0]) << v;
    EXPECT_FLOAT_EQ(f[1], win[v][1]) << v;
    EXPECT_FLOAT_EQ(f[2], 0.5f) << v;
    EXPECT_FLOAT_EQ(f[3], 1.0f) << v;
    EXPECT_FLOAT_EQ(f[4], 0.25f);
    EXPECT_FLOAT_EQ(f[5], 0.5f);
    EXPECT_FLOAT_EQ(f[6], 0.75f);
    EXPECT_FLOAT_EQ(f[7], 1.0f);
    EXPECT_FLOAT_EQ(f[8], obj[v][0]) << v;
    EXPECT_FLOAT_EQ(f[9], obj[v][1]) << v;
    EXPECT_FLOAT_EQ(f[10], 0.5f);
    EXPECT_FLOAT_EQ(f[11], 1.0f);
  }
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(RenderModeShaderTest, FeedbackClipsTheShaderOutputs) {
  // The shader moves the triangle half out of the window: feedback reports the clipped
  // polygon with interpolated gl_FrontColor and gl_TexCoord[0] (§2.12, §2.14.8).
  program("void main() {\n"
          "  gl_Position = gl_Vertex + vec4(1.0, 0.0, 0.0, 0.0);\n"
          "  gl_FrontColor = vec4(gl_Vertex.x * 0.5 + 0.5, 0.0, 0.0, 1.0);\n"
          "  gl_TexCoord[0] = vec4(gl_Vertex.x, 0.0, 0.0, 1.0);\n"
          "}\n");
  std::vector<GLfloat> buf(128, -1.0f);
  glFeedbackBuffer(static_cast<GLsizei>(buf.size()), GL_3D_COLOR_TEXTURE, buf.data());
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_LINES);
  glVertex2f(-1, 0); // clip x 0: window 16
  glVertex2f(1, 0);  // clip x 2: cut at x = 1 (window 32), the object x there is 0
  glEnd();
  ASSERT_EQ(glRenderMode(GL_RENDER), 1 + 2 * 11);
  EXPECT_EQ(buf[0], static_cast<GLfloat>(GL_LINE_RESET_TOKEN));
  EXPECT_FLOAT_EQ(buf[1], 16.0f);
  EXPECT_FLOAT_EQ(buf[1 + 3], 0.0f);        // red of x = -1
  EXPECT_FLOAT_EQ(buf[1 + 7], -1.0f);       // s of x = -1
  EXPECT_FLOAT_EQ(buf[1 + 11], 32.0f);      // the cut end
  EXPECT_FLOAT_EQ(buf[1 + 11 + 3], 0.5f);   // red of x = 0
  EXPECT_NEAR(buf[1 + 11 + 7], 0.0f, 1e-6); // s of x = 0
}

TEST_F(RenderModeShaderTest, FeedbackOfUnwrittenOutputsIsTheCurrentState) {
  // GL leaves outputs a shader does not write undefined; feedback reports the current colour
  // and texture coordinates there, as Mesa does.
  program("void main() { gl_Position = gl_Vertex; }\n");
  glColor4f(0.125f, 0.25f, 0.375f, 0.5f);
  glTexCoord4f(1, 2, 3, 4);
  std::vector<GLfloat> buf(16, -1.0f);
  glFeedbackBuffer(static_cast<GLsizei>(buf.size()), GL_3D_COLOR_TEXTURE, buf.data());
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_POINTS);
  glVertex2f(0, 0);
  glEnd();
  ASSERT_EQ(glRenderMode(GL_RENDER), 1 + 11);
  const float expect[11] = {16, 16, 0.5f, 0.125f, 0.25f, 0.375f, 0.5f, 1, 2, 3, 4};
  for (int i = 0; i < 11; ++i)
    EXPECT_FLOAT_EQ(buf[static_cast<size_t>(1 + i)], expect[i]) << i;
}

TEST_F(RenderModeShaderTest, SelectionUsesTheShaderPosition) {
  // §5.2: a hit for each primitive that survives clipping, with the window z of the shader's
  // positions; the shader moves the second triangle out of the view volume.
  program("uniform float dx;\n"
          "void main() { gl_Position = vec4(gl_Vertex.x + dx, gl_Vertex.y, 0.5, 1.0); }\n");
  const GLint dx = glGetUniformLocation(glGetHandleARB(GL_PROGRAM_OBJECT_ARB), "dx");
  GLuint buf[32] = {};
  glSelectBuffer(32, buf);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(7);
  glUniform1f(dx, 0.0f);
  triangle();
  glLoadName(8);
  glUniform1f(dx, 3.0f);
  triangle();
  ASSERT_EQ(glRenderMode(GL_RENDER), 1);
  EXPECT_EQ(buf[0], 1u);
  // Window z 0.75 as an unsigned integer scaled by 2^32 - 1.
  EXPECT_NEAR(static_cast<double>(buf[1]), 0.75 * 4294967295.0, 512.0);
  EXPECT_NEAR(static_cast<double>(buf[2]), 0.75 * 4294967295.0, 512.0);
  EXPECT_EQ(buf[3], 7u);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(RenderModeShaderTest, ClipVertexClipsDrawsAndRasterPositions) {
  // §2.12, §2.20.3: the plane (stored in eye space) against gl_ClipVertex: here the vertex
  // mirrored in x, so the left half of the window stays.
  program("void main() { gl_Position = gl_Vertex;\n"
          "  gl_ClipVertex = vec4(-gl_Vertex.x, gl_Vertex.yzw);\n"
          "  gl_FrontColor = vec4(1.0); }\n");
  const GLdouble plane[4] = {1, 0, 0, 0};
  glClipPlane(GL_CLIP_PLANE0, plane);
  glEnable(GL_CLIP_PLANE0);
  glClear(GL_COLOR_BUFFER_BIT);
  quad();
  EXPECT_EQ(pixel(4, 16), 0xffffffffu);
  EXPECT_EQ(pixel(28, 16), 0x00000000u);
  // The raster position is clipped as a point against the same plane (§2.13).
  GLfloat valid = 0;
  glRasterPos2f(0.5f, 0.0f);
  glGetFloatv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  EXPECT_EQ(valid, 0.0f);
  glRasterPos2f(-0.5f, 0.0f);
  glGetFloatv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  EXPECT_EQ(valid, 1.0f);
  // A point drawn where the clip vertex is outside is clipped.
  glClear(GL_COLOR_BUFFER_BIT);
  glPointSize(4);
  glBegin(GL_POINTS);
  glVertex2f(0.5f, 0.0f);
  glVertex2f(-0.5f, 0.0f);
  glEnd();
  EXPECT_EQ(pixel(24, 16), 0x00000000u);
  EXPECT_EQ(pixel(8, 16), 0xffffffffu);
  glDisable(GL_CLIP_PLANE0);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(RenderModeShaderTest, WithoutClipVertexThePlanesTestThePosition) {
  // A shader that does not write gl_ClipVertex: Mesa tests the eye-space plane on
  // gl_Position, whatever the projection (here a mirror, which would swap the halves if the
  // plane went through the projection as in fixed function).
  program("void main() { gl_Position = gl_Vertex; gl_FrontColor = vec4(1.0); }\n");
  glMatrixMode(GL_PROJECTION);
  glScalef(-1, 1, 1);
  glMatrixMode(GL_MODELVIEW);
  const GLdouble plane[4] = {1, 0, 0, 0};
  glClipPlane(GL_CLIP_PLANE0, plane);
  glEnable(GL_CLIP_PLANE0);
  glClear(GL_COLOR_BUFFER_BIT);
  quad();
  EXPECT_EQ(pixel(4, 16), 0x00000000u);
  EXPECT_EQ(pixel(28, 16), 0xffffffffu);
  // Fixed function after the program: the plane through the projection again.
  glUseProgram(0);
  glColor4f(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  quad();
  EXPECT_EQ(pixel(4, 16), 0xffffffffu);
  EXPECT_EQ(pixel(28, 16), 0x00000000u);
  glDisable(GL_CLIP_PLANE0);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

} // namespace
