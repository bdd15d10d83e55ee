// GLSL through the GL API (GL 2.1 §2.15, §2.20, §3.11): shader and program objects, their
// errors and deferred deletion, uniforms and their type checks, generic vertex attributes,
// display-list behaviour (§5.4) and small draws with vertex and fragment shaders.
#define GL_GLEXT_PROTOTYPES 1
#include "api_fixture.h"

#include <GL/glext.h>

#include <cstring>
#include <string>
#include <vector>

namespace {

class ShaderTest : public GLTest {
protected:
  GLuint shader(GLenum type, const char* src) {
    const GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    return s;
  }
  // A linked program of the given stages (null: the stage stays fixed function).
  GLuint program(const char* vs, const char* fs) {
    const GLuint p = glCreateProgram();
    if (vs != nullptr) glAttachShader(p, shader(GL_VERTEX_SHADER, vs));
    if (fs != nullptr) glAttachShader(p, shader(GL_FRAGMENT_SHADER, fs));
    glLinkProgram(p);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    EXPECT_EQ(ok, GL_TRUE);
    return p;
  }
  // Full-window quad in clip coordinates.
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

const char* kPassVs = "void main() { gl_Position = gl_Vertex; gl_FrontColor = gl_Color; }\n";
const char* kRedFs = "void main() { gl_FragColor = vec4(1.0, 0.0, 0.0, 1.0); }\n";

TEST_F(ShaderTest, CreateShaderRejectsBadType) {
  EXPECT_EQ(glCreateShader(GL_TEXTURE_2D), 0u);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
}

TEST_F(ShaderTest, CompileStatusAndLog) {
  const GLuint good = shader(GL_FRAGMENT_SHADER, kRedFs);
  GLint v = 0;
  glGetShaderiv(good, GL_COMPILE_STATUS, &v);
  EXPECT_EQ(v, GL_TRUE);
  glGetShaderiv(good, GL_SHADER_TYPE, &v);
  EXPECT_EQ(v, GL_FRAGMENT_SHADER);
  glGetShaderiv(good, GL_SHADER_SOURCE_LENGTH, &v);
  EXPECT_EQ(v, static_cast<GLint>(std::strlen(kRedFs) + 1));
  std::vector<char> src(static_cast<size_t>(v));
  GLsizei len = 0;
  glGetShaderSource(good, v, &len, src.data());
  EXPECT_EQ(std::string(src.data()), kRedFs);
  EXPECT_EQ(len, v - 1);

  const GLuint bad = shader(GL_FRAGMENT_SHADER, "void main() {\n  undeclared = 1.0;\n}\n");
  glGetShaderiv(bad, GL_COMPILE_STATUS, &v);
  EXPECT_EQ(v, GL_FALSE);
  glGetShaderiv(bad, GL_INFO_LOG_LENGTH, &v);
  ASSERT_GT(v, 1);
  std::vector<char> log(static_cast<size_t>(v));
  glGetShaderInfoLog(bad, v, nullptr, log.data());
  EXPECT_NE(std::string(log.data()).find("undeclared"), std::string::npos) << log.data();
  // A short buffer gets a terminated prefix.
  char small[4] = {'x', 'x', 'x', 'x'};
  glGetShaderInfoLog(bad, 3, &len, small);
  EXPECT_EQ(len, 2);
  EXPECT_EQ(small[2], '\0');
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

// gl_FragDepth and gl_PointCoord are drawn (frag_outputs_test.cpp): programs using them link.
TEST_F(ShaderTest, FragDepthAndPointCoordLink) {
  for (const char* fs :
       {"void main() { gl_FragColor = vec4(1.0); gl_FragDepth = 0.5; }\n",
        "#version 120\nvoid main() { gl_FragColor = vec4(gl_PointCoord, 0.0, 1.0); }\n"}) {
    const GLuint p = glCreateProgram();
    glAttachShader(p, shader(GL_FRAGMENT_SHADER, fs));
    glLinkProgram(p);
    GLint ok = GL_FALSE;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    EXPECT_EQ(ok, GL_TRUE) << fs;
    glUseProgram(p);
    EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
    glUseProgram(0);
    glDeleteProgram(p);
  }
}

TEST_F(ShaderTest, ObjectNameErrors) {
  const GLuint s = glCreateShader(GL_VERTEX_SHADER);
  const GLuint p = glCreateProgram();
  EXPECT_NE(s, p);
  EXPECT_TRUE(glIsShader(s));
  EXPECT_FALSE(glIsShader(p));
  EXPECT_TRUE(glIsProgram(p));
  EXPECT_FALSE(glIsProgram(s));
  // §2.15: the other kind of object is INVALID_OPERATION, no object INVALID_VALUE.
  glCompileShader(p);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glCompileShader(12345);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  glLinkProgram(s);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glAttachShader(p, p);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glAttachShader(p, s);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
  glAttachShader(p, s);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  GLint n = 0;
  glGetProgramiv(p, GL_ATTACHED_SHADERS, &n);
  EXPECT_EQ(n, 1);
  GLuint names[2] = {};
  GLsizei count = 0;
  glGetAttachedShaders(p, 2, &count, names);
  EXPECT_EQ(count, 1);
  EXPECT_EQ(names[0], s);
  glDetachShader(p, s);
  glDetachShader(p, s);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glShaderSource(s, -1, nullptr, nullptr);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  glGetProgramiv(p, GL_SHADER_TYPE, &n);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glGetShaderInfoLog(s, -1, nullptr, nullptr);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  // Zero is ignored by the Delete commands.
  glDeleteShader(0);
  glDeleteProgram(0);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
  // Object commands are illegal between Begin and End.
  glBegin(GL_POINTS);
  EXPECT_EQ(glCreateProgram(), 0u);
  glEnd();
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
}

TEST_F(ShaderTest, LinkFailsWithUncompiledShaderAndUseProgramNeedsLink) {
  const GLuint p = glCreateProgram();
  glAttachShader(p, shader(GL_FRAGMENT_SHADER, "void main() { oops }"));
  glLinkProgram(p);
  GLint ok = 1;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  EXPECT_EQ(ok, GL_FALSE);
  GLint len = 0;
  glGetProgramiv(p, GL_INFO_LOG_LENGTH, &len);
  EXPECT_GT(len, 1);
  glUseProgram(p);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glGetUniformLocation(p, "x");
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  GLint cur = -1;
  glGetIntegerv(GL_CURRENT_PROGRAM, &cur);
  EXPECT_EQ(cur, 0);
}

TEST_F(ShaderTest, DeferredDeletion) {
  const GLuint p = program(kPassVs, kRedFs);
  GLuint shaders[2];
  glGetAttachedShaders(p, 2, nullptr, shaders);
  // An attached shader is deleted when it is detached (§2.15.1).
  glDeleteShader(shaders[0]);
  GLint status = 0;
  glGetShaderiv(shaders[0], GL_DELETE_STATUS, &status);
  EXPECT_EQ(status, GL_TRUE);
  EXPECT_TRUE(glIsShader(shaders[0]));
  glUseProgram(p);
  // A program in use is deleted when no context uses it (§2.15.2).
  glDeleteProgram(p);
  EXPECT_TRUE(glIsProgram(p));
  glGetProgramiv(p, GL_DELETE_STATUS, &status);
  EXPECT_EQ(status, GL_TRUE);
  GLint cur = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &cur);
  EXPECT_EQ(static_cast<GLuint>(cur), p);
  glClear(GL_COLOR_BUFFER_BIT);
  quad(); // still draws with it
  EXPECT_EQ(pixel(16, 16), 0xff0000ffu);
  glUseProgram(0);
  EXPECT_FALSE(glIsProgram(p));
  EXPECT_FALSE(glIsShader(shaders[0])); // detached with the program's deletion
  EXPECT_TRUE(glIsShader(shaders[1]));
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(ShaderTest, ActiveUniformsAndAttributes) {
  const GLuint p =
      program("attribute vec4 pos;\nattribute vec2 uv;\nuniform mat4 m;\nvarying vec2 t;\n"
              "void main() { gl_Position = m * pos; t = uv; }\n",
              "uniform vec4 tint[3];\nuniform sampler2D tex;\nvarying vec2 t;\n"
              "void main() { gl_FragColor = tint[2] * texture2D(tex, t); }\n");
  GLint n = 0, maxlen = 0;
  glGetProgramiv(p, GL_ACTIVE_UNIFORMS, &n);
  glGetProgramiv(p, GL_ACTIVE_UNIFORM_MAX_LENGTH, &maxlen);
  EXPECT_EQ(n, 3);
  EXPECT_EQ(maxlen, static_cast<GLint>(std::strlen("tint[0]") + 1));
  bool found_tint = false;
  for (GLint i = 0; i < n; ++i) {
    char name[64];
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(p, static_cast<GLuint>(i), sizeof name, nullptr, &size, &type, name);
    if (std::string(name) == "tint[0]") {
      found_tint = true;
      EXPECT_EQ(size, 3);
      EXPECT_EQ(type, static_cast<GLenum>(GL_FLOAT_VEC4));
    }
  }
  EXPECT_TRUE(found_tint);
  glGetActiveUniform(p, static_cast<GLuint>(n), 0, nullptr, nullptr, nullptr, nullptr);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_GE(glGetUniformLocation(p, "tint[1]"), 0);
  EXPECT_EQ(glGetUniformLocation(p, "nothing"), -1);
  glGetProgramiv(p, GL_ACTIVE_ATTRIBUTES, &n);
  EXPECT_EQ(n, 2);
  const GLint pos = glGetAttribLocation(p, "pos"), uv = glGetAttribLocation(p, "uv");
  EXPECT_GE(pos, 0);
  EXPECT_GE(uv, 0);
  EXPECT_NE(pos, uv);
  // BindAttribLocation takes effect at the next link.
  glBindAttribLocation(p, 7, "uv");
  EXPECT_EQ(glGetAttribLocation(p, "uv"), uv);
  glLinkProgram(p);
  EXPECT_EQ(glGetAttribLocation(p, "uv"), 7);
  glBindAttribLocation(p, 3, "gl_Vertex");
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glBindAttribLocation(p, 16, "uv");
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
}

// A uniform with an initializer is active though unread (as in Mesa), and glUniform sets it;
// an unread uniform without one is not.
TEST_F(ShaderTest, InitializedUniformIsActiveWhenUnread) {
  const GLuint p = program("void main() { gl_Position = gl_Vertex; }\n",
                           "#version 120\nuniform float unread = 2.0;\nuniform vec2 unused;\n"
                           "void main() { gl_FragColor = vec4(1.0); }\n");
  const GLint loc = glGetUniformLocation(p, "unread");
  ASSERT_GE(loc, 0);
  EXPECT_EQ(glGetUniformLocation(p, "unused"), -1);
  GLfloat v = 0.0f;
  glGetUniformfv(p, loc, &v);
  EXPECT_EQ(v, 2.0f);
  glUseProgram(p);
  glUniform1f(loc, -0.5f);
  glGetUniformfv(p, loc, &v);
  EXPECT_EQ(v, -0.5f);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(ShaderTest, UniformTypeChecks) {
  const GLuint p =
      program(nullptr, "uniform vec4 c;\nuniform int i;\nuniform bool b;\nuniform float f;\n"
                       "uniform sampler2D s;\nuniform mat3 m;\nuniform float arr[4];\n"
                       "void main() { gl_FragColor = c * float(i) * (b ? 1.0 : 0.0) * f *\n"
                       "  texture2D(s, vec2(0.0)) * m[1][1] * arr[3]; }\n");
  const GLint c = glGetUniformLocation(p, "c"), i = glGetUniformLocation(p, "i");
  const GLint b = glGetUniformLocation(p, "b"), f = glGetUniformLocation(p, "f");
  const GLint s = glGetUniformLocation(p, "s"), m = glGetUniformLocation(p, "m");
  const GLint arr = glGetUniformLocation(p, "arr");
  // No current program.
  glUniform4f(c, 1, 2, 3, 4);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glUseProgram(p);
  glUniform4f(c, 1, 2, 3, 4);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
  glUniform3f(c, 1, 2, 3); // size mismatch
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glUniform4i(c, 1, 2, 3, 4); // int into float
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glUniform1f(i, 1.0f); // float into int
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glUniform1i(i, 5);
  glUniform1f(b, 2.0f); // bools take either
  glUniform1i(b, 0);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
  glUniform1f(s, 0.0f); // samplers: Uniform1i only
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glUniform1i(s, 99);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  const GLfloat two[2] = {1, 2};
  glUniform1fv(f, 2, two); // count > 1 for a non-array
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glUniform1fv(f, -1, two);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  glUniform1f(-1, 1.0f); // location -1 is ignored
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
  glUniform1f(9999, 1.0f);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glUniform4fv(m, 1, two); // a vector command on a matrix
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  const GLfloat mat[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  glUniformMatrix4fv(m, 1, GL_FALSE, mat);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glUniformMatrix3fv(m, 1, GL_TRUE, mat);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
  GLfloat got[9] = {};
  glGetUniformfv(p, m, got);
  EXPECT_EQ(got[1], 4.0f); // column 0, row 1 of the transposed input
  EXPECT_EQ(got[3], 2.0f);
  // Arrays: elements past the end are ignored.
  const GLfloat five[5] = {10, 11, 12, 13, 14};
  glUniform1fv(glGetUniformLocation(p, "arr[2]"), 5, five);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
  GLfloat e = 0;
  glGetUniformfv(p, glGetUniformLocation(p, "arr[3]"), &e);
  EXPECT_EQ(e, 11.0f);
  glGetUniformfv(p, arr, &e);
  EXPECT_EQ(e, 0.0f);
  GLint iv[4] = {};
  glGetUniformiv(p, i, iv);
  EXPECT_EQ(iv[0], 5);
  GLfloat cv[4] = {};
  glGetUniformfv(p, c, cv);
  EXPECT_EQ(cv[3], 4.0f);
  glGetUniformfv(p, 9999, cv);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
}

TEST_F(ShaderTest, GenericAttributeState) {
  GLint max = 0;
  glGetIntegerv(GL_MAX_VERTEX_ATTRIBS, &max);
  EXPECT_EQ(max, 16);
  glVertexAttrib4f(16, 1, 2, 3, 4);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  glVertexAttrib3f(2, 1, 2, 3);
  GLfloat v[4] = {};
  glGetVertexAttribfv(2, GL_CURRENT_VERTEX_ATTRIB, v);
  EXPECT_EQ(v[2], 3.0f);
  EXPECT_EQ(v[3], 1.0f);
  const GLubyte ub[4] = {255, 0, 51, 255};
  glVertexAttrib4Nubv(3, ub);
  glGetVertexAttribfv(3, GL_CURRENT_VERTEX_ATTRIB, v);
  EXPECT_FLOAT_EQ(v[0], 1.0f);
  EXPECT_FLOAT_EQ(v[2], 0.2f);
  const GLshort sv[4] = {-32768, 0, 0, 0};
  glVertexAttrib4Nsv(4, sv);
  glGetVertexAttribfv(4, GL_CURRENT_VERTEX_ATTRIB, v);
  EXPECT_FLOAT_EQ(v[0], -1.0f); // (2c + 1) / (2^16 - 1)
  glGetVertexAttribfv(0, GL_CURRENT_VERTEX_ATTRIB, v);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glGetVertexAttribfv(1, GL_TEXTURE_2D, v);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));

  const float data[8] = {};
  glVertexAttribPointer(5, 3, GL_SHORT, GL_TRUE, 8, data);
  glEnableVertexAttribArray(5);
  GLint iv = 0;
  glGetVertexAttribiv(5, GL_VERTEX_ATTRIB_ARRAY_SIZE, &iv);
  EXPECT_EQ(iv, 3);
  glGetVertexAttribiv(5, GL_VERTEX_ATTRIB_ARRAY_TYPE, &iv);
  EXPECT_EQ(iv, GL_SHORT);
  glGetVertexAttribiv(5, GL_VERTEX_ATTRIB_ARRAY_NORMALIZED, &iv);
  EXPECT_EQ(iv, GL_TRUE);
  glGetVertexAttribiv(5, GL_VERTEX_ATTRIB_ARRAY_STRIDE, &iv);
  EXPECT_EQ(iv, 8);
  glGetVertexAttribiv(5, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &iv);
  EXPECT_EQ(iv, GL_TRUE);
  void* ptr = nullptr;
  glGetVertexAttribPointerv(5, GL_VERTEX_ATTRIB_ARRAY_POINTER, &ptr);
  EXPECT_EQ(ptr, static_cast<const void*>(data));
  glVertexAttribPointer(5, 5, GL_FLOAT, GL_FALSE, 0, data);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  glVertexAttribPointer(5, 4, GL_BOOL, GL_FALSE, 0, data);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glEnableVertexAttribArray(16);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  // The arrays are client state, the current values current state.
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glDisableVertexAttribArray(5);
  glPopClientAttrib();
  glGetVertexAttribiv(5, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &iv);
  EXPECT_EQ(iv, GL_TRUE);
  glPushAttrib(GL_CURRENT_BIT);
  glVertexAttrib1f(2, 9.0f);
  glPopAttrib();
  glGetVertexAttribfv(2, GL_CURRENT_VERTEX_ATTRIB, v);
  EXPECT_EQ(v[0], 1.0f);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(ShaderTest, FragmentShaderColoursTheQuad) {
  glUseProgram(program(nullptr, kRedFs));
  glClear(GL_COLOR_BUFFER_BIT);
  quad();
  EXPECT_EQ(pixel(0, 0), 0xff0000ffu);
  EXPECT_EQ(pixel(31, 31), 0xff0000ffu);
  glUseProgram(0);
  glColor3f(0, 1, 0);
  quad();
  EXPECT_EQ(pixel(5, 5), 0xff00ff00u);
}

TEST_F(ShaderTest, VertexShaderWithUniformAndVarying) {
  const GLuint p = program("uniform vec2 offset;\nvarying vec4 c;\n"
                           "void main() { gl_Position = gl_Vertex + vec4(offset, 0.0, 0.0);\n"
                           "  c = vec4(0.0, 0.0, 1.0, 1.0); }\n",
                           "varying vec4 c;\nvoid main() { gl_FragColor = c; }\n");
  glUseProgram(p);
  glUniform2f(glGetUniformLocation(p, "offset"), 1.0f, 0.0f); // the right half only
  glClear(GL_COLOR_BUFFER_BIT);
  quad();
  EXPECT_EQ(pixel(4, 16), 0x00000000u);
  EXPECT_EQ(pixel(28, 16), 0xffff0000u);
}

TEST_F(ShaderTest, DiscardKeepsDepth) {
  const GLuint p = program(nullptr, "void main() { if (gl_FragCoord.x < 16.0) discard;\n"
                                    "  gl_FragColor = vec4(1.0); }\n");
  glEnable(GL_DEPTH_TEST);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glUseProgram(p);
  quad(); // z = 0 where not discarded
  glUseProgram(0);
  glColor3f(0, 1, 0);
  glBegin(GL_QUADS); // behind the white half, in front of the cleared depth elsewhere
  glVertex3f(-1, -1, 0.5f);
  glVertex3f(1, -1, 0.5f);
  glVertex3f(1, 1, 0.5f);
  glVertex3f(-1, 1, 0.5f);
  glEnd();
  EXPECT_EQ(pixel(4, 4), 0xff00ff00u);
  EXPECT_EQ(pixel(28, 4), 0xffffffffu);
}

TEST_F(ShaderTest, GenericAttributeArraysAndAttributeZero) {
  const GLuint p = glCreateProgram();
  glAttachShader(p, shader(GL_VERTEX_SHADER, "attribute vec2 pos;\nattribute vec3 col;\n"
                                             "varying vec3 c;\n"
                                             "void main() { gl_Position = vec4(pos, 0.0, 1.0);\n"
                                             "  c = col; }\n"));
  glAttachShader(p, shader(GL_FRAGMENT_SHADER,
                           "varying vec3 c;\nvoid main() { gl_FragColor = vec4(c, 1.0); }\n"));
  glBindAttribLocation(p, 0, "pos");
  glBindAttribLocation(p, 3, "col");
  glLinkProgram(p);
  glUseProgram(p);
  const float pos[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
  const GLubyte col[12] = {255, 0, 255, 255, 0, 255, 255, 0, 255, 255, 0, 255};
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, pos);
  glVertexAttribPointer(3, 3, GL_UNSIGNED_BYTE, GL_TRUE, 0, col);
  glEnableVertexAttribArray(0); // generic array 0 stands for the vertex array (§2.8)
  glEnableVertexAttribArray(3);
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_EQ(pixel(16, 16), 0xffff00ffu);
  // Current generic values in immediate mode, per vertex.
  glDisableVertexAttribArray(0);
  glDisableVertexAttribArray(3);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_QUADS);
  glVertexAttrib3f(3, 0, 1, 0);
  glVertexAttrib2f(0, -1, -1);
  glVertexAttrib2f(0, 1, -1);
  glVertexAttrib2f(0, 1, 1);
  glVertexAttrib2f(0, -1, 1);
  glEnd();
  EXPECT_EQ(pixel(16, 16), 0xff00ff00u);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(ShaderTest, DisplayListsCompileUniformsAndAttributes) {
  const GLuint p = program("attribute float k;\nvarying float v;\n"
                           "void main() { gl_Position = gl_Vertex; v = k; }\n",
                           "uniform vec4 c[2];\nvarying float v;\n"
                           "void main() { gl_FragColor = c[1] * v; }\n");
  glUseProgram(p);
  const GLint k = glGetAttribLocation(p, "k");
  const GLint c = glGetUniformLocation(p, "c");
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  const GLfloat vals[8] = {0, 0, 0, 0, 0, 1, 1, 1};
  glUniform4fv(c, 2, vals);
  glBegin(GL_QUADS);
  glVertexAttrib1f(static_cast<GLuint>(k), 1.0f);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 1);
  glVertex2f(-1, 1);
  glEnd();
  glEndList();
  // Compiling executed nothing.
  GLfloat got[4] = {};
  glGetUniformfv(p, glGetUniformLocation(p, "c[1]"), got);
  EXPECT_EQ(got[1], 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glCallList(list);
  glGetUniformfv(p, glGetUniformLocation(p, "c[1]"), got);
  EXPECT_EQ(got[1], 1.0f);
  EXPECT_EQ(pixel(16, 16), 0xffffff00u);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(ShaderTest, TextureLookupInFragmentShader) {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  const GLubyte texels[4 * 4] = {255, 0, 0,   255, 0,   255, 0,   255,
                                 0,   0, 255, 255, 255, 255, 255, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  const GLuint p = program("void main() { gl_Position = gl_Vertex;\n"
                           "  gl_TexCoord[0] = gl_Vertex * 0.5 + 0.5; }\n",
                           "uniform sampler2D s;\n"
                           "void main() { gl_FragColor = texture2D(s, gl_TexCoord[0].st); }\n");
  glUseProgram(p);
  glUniform1i(glGetUniformLocation(p, "s"), 0);
  glClear(GL_COLOR_BUFFER_BIT);
  quad();
  EXPECT_EQ(pixel(4, 4), 0xff0000ffu);
  EXPECT_EQ(pixel(28, 4), 0xff00ff00u);
  EXPECT_EQ(pixel(4, 28), 0xffff0000u);
  EXPECT_EQ(pixel(28, 28), 0xffffffffu);
  // An incomplete texture samples as (0, 0, 0, 1).
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  quad();
  EXPECT_EQ(pixel(28, 28), 0xff000000u);
}

TEST_F(ShaderTest, BuiltInMatricesAndFixedVertexStage) {
  // Fixed-function vertex stage, fragment shader reading gl_Color.
  glUseProgram(program(nullptr, "void main() { gl_FragColor = gl_Color.bgra; }\n"));
  glColor3f(1, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  quad();
  EXPECT_EQ(pixel(16, 16), 0xffff0000u);
  // gl_ModelViewProjectionMatrix follows the matrix stacks.
  glUseProgram(program("void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n"
                       "  gl_FrontColor = vec4(1.0); }\n",
                       nullptr));
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(1.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  quad();
  EXPECT_EQ(pixel(4, 16), 0x00000000u);
  EXPECT_EQ(pixel(28, 16), 0xffffffffu);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(ShaderTest, RasterPositionThroughTheVertexShader) {
  // §2.13: with a vertex shader the raster position and its data are the shader's outputs.
  glUseProgram(program("void main() { gl_Position = gl_Vertex + vec4(0.5, 0.0, 0.0, 0.0);\n"
                       "  gl_FrontColor = vec4(0.0, 0.0, 1.0, 1.0);\n"
                       "  gl_TexCoord[1] = vec4(0.25);\n"
                       "  gl_FogFragCoord = 3.0; }\n",
                       nullptr));
  glRasterPos2f(-1.0f, -1.0f);
  GLfloat pos[4] = {}, color[4] = {}, tex[4] = {}, dist = 0, valid = 0;
  glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
  glGetFloatv(GL_CURRENT_RASTER_COLOR, color);
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &dist);
  glGetFloatv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  EXPECT_EQ(valid, 1.0f);
  EXPECT_EQ(pos[0], 0.25f * kW);
  EXPECT_EQ(pos[1], 0.0f);
  EXPECT_EQ(color[2], 1.0f);
  EXPECT_EQ(color[0], 0.0f);
  EXPECT_EQ(dist, 3.0f);
  glActiveTexture(GL_TEXTURE1);
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, tex);
  glActiveTexture(GL_TEXTURE0);
  EXPECT_EQ(tex[3], 0.25f);
  glRasterPos2f(0.8f, 0.0f); // outside once moved by the shader
  glGetFloatv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  EXPECT_EQ(valid, 0.0f);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(ShaderTest, LargeDrawSharedAmongWorkerThreads) {
  // Enough vertices that the vertex shader runs on every worker thread (draw/draw.cpp), each
  // with its own scratch registers, and the generic attribute rows follow each thread's range.
  const GLuint p = glCreateProgram();
  glAttachShader(p, shader(GL_VERTEX_SHADER,
                           "attribute vec2 pos;\nattribute float shade;\n"
                           "void main() { gl_Position = vec4(pos, 0.0, 1.0);\n"
                           "  gl_FrontColor = vec4(shade, 1.0 - shade, 0.0, 1.0); }\n"));
  glAttachShader(p, shader(GL_FRAGMENT_SHADER, "void main() { gl_FragColor = gl_Color; }\n"));
  glBindAttribLocation(p, 0, "pos");
  glBindAttribLocation(p, 1, "shade");
  glLinkProgram(p);
  glUseProgram(p);
  // 32 x 32 pixel-sized quads, each drawn as two triangles, repeated 4 times: 24576 vertices.
  std::vector<float> pos, shade;
  for (int rep = 0; rep < 4; ++rep)
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const float x0 = 2.0f * x / kW - 1.0f, x1 = 2.0f * (x + 1) / kW - 1.0f;
        const float y0 = 2.0f * y / kH - 1.0f, y1 = 2.0f * (y + 1) / kH - 1.0f;
        for (float v : {x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1})
          pos.push_back(v);
        for (int k = 0; k < 6; ++k)
          shade.push_back((x + y) % 2 == 0 ? 1.0f : 0.0f);
      }
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, pos.data());
  glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, 0, shade.data());
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(shade.size()));
  int wrong = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      wrong += pixel(x, y) != ((x + y) % 2 == 0 ? 0xff0000ffu : 0xff00ff00u) ? 1 : 0;
  EXPECT_EQ(wrong, 0);
  glDisableVertexAttribArray(0);
  glDisableVertexAttribArray(1);
}

} // namespace
