// The ARB_shader_objects commands of their own (ARB_shader_objects §2.14 "Generic Objects",
// §6.1.12): handles, GetHandleARB, GetObjectParameter{if}vARB with their errors, GetInfoLogARB,
// GetAttachedObjectsARB, DeleteObjectARB, and their lookup through OSMesaGetProcAddress. The
// other ARB commands are aliases of GL 2.0 ones (shader_api_test.cpp tests those).
#define GL_GLEXT_PROTOTYPES 1
#include "api_fixture.h"

#include <GL/glext.h>

#include <cstring>
#include <string>
#include <vector>

namespace {

class ArbShaderObjectsTest : public GLTest {
protected:
  GLuint shader(GLenum type, const std::string& src) {
    const GLuint s = glCreateShader(type);
    const char* p = src.c_str();
    glShaderSource(s, 1, &p, nullptr);
    glCompileShader(s);
    return s;
  }
  std::string log(GLuint p) {
    char buf[2048] = {};
    glGetProgramInfoLog(p, sizeof buf, nullptr, buf);
    return buf;
  }
  GLenum err() { return glGetError(); }
};

constexpr GLenum kNoError = GL_NO_ERROR;
constexpr GLenum kInvalidEnum = GL_INVALID_ENUM;
constexpr GLenum kInvalidOperation = GL_INVALID_OPERATION;
constexpr GLenum kInvalidValue = GL_INVALID_VALUE;

TEST_F(ArbShaderObjectsTest, HandleQueries) {
  const GLuint vs = shader(GL_VERTEX_SHADER, "void main() { gl_Position = gl_Vertex; }\n");
  const GLuint fs = shader(GL_FRAGMENT_SHADER, "void main() { gl_FragColor = vec4(1.0); }\n");
  const GLuint p = glCreateProgram();
  glAttachShader(p, vs);
  glAttachShader(p, fs);
  glLinkProgram(p);
  EXPECT_EQ(glGetHandleARB(GL_PROGRAM_OBJECT_ARB), 0u);
  glUseProgram(p);
  EXPECT_EQ(glGetHandleARB(GL_PROGRAM_OBJECT_ARB), p);
  EXPECT_EQ(glGetHandleARB(GL_CURRENT_PROGRAM), 0u);
  EXPECT_EQ(err(), kInvalidEnum);

  GLint v = 0;
  glGetObjectParameterivARB(vs, GL_OBJECT_TYPE_ARB, &v);
  EXPECT_EQ(v, GL_SHADER_OBJECT_ARB);
  glGetObjectParameterivARB(vs, GL_OBJECT_SUBTYPE_ARB, &v);
  EXPECT_EQ(v, GL_VERTEX_SHADER_ARB);
  glGetObjectParameterivARB(fs, GL_OBJECT_SUBTYPE_ARB, &v);
  EXPECT_EQ(v, GL_FRAGMENT_SHADER_ARB);
  glGetObjectParameterivARB(vs, GL_OBJECT_COMPILE_STATUS_ARB, &v);
  EXPECT_EQ(v, GL_TRUE);
  glGetObjectParameterivARB(p, GL_OBJECT_TYPE_ARB, &v);
  EXPECT_EQ(v, GL_PROGRAM_OBJECT_ARB);
  glGetObjectParameterivARB(p, GL_OBJECT_LINK_STATUS_ARB, &v);
  EXPECT_EQ(v, GL_TRUE);
  glGetObjectParameterivARB(p, GL_OBJECT_ATTACHED_OBJECTS_ARB, &v);
  EXPECT_EQ(v, 2);
  glGetObjectParameterivARB(p, GL_OBJECT_DELETE_STATUS_ARB, &v);
  EXPECT_EQ(v, GL_FALSE);
  GLfloat f = 0;
  glGetObjectParameterfvARB(p, GL_OBJECT_TYPE_ARB, &f);
  EXPECT_EQ(f, static_cast<GLfloat>(GL_PROGRAM_OBJECT_ARB));
  glGetObjectParameterfvARB(vs, GL_OBJECT_SHADER_SOURCE_LENGTH_ARB, &f);
  EXPECT_EQ(f, static_cast<GLfloat>(std::strlen("void main() { gl_Position = gl_Vertex; }\n") + 1));
  EXPECT_EQ(err(), kNoError);

  // Errors: program state of a shader and shader state of a program are INVALID_OPERATION, an
  // unknown parameter INVALID_ENUM, a handle that is no object (zero too) INVALID_VALUE; none
  // writes the result.
  v = 1234;
  glGetObjectParameterivARB(vs, GL_OBJECT_LINK_STATUS_ARB, &v);
  EXPECT_EQ(err(), kInvalidOperation);
  glGetObjectParameterivARB(p, GL_OBJECT_SUBTYPE_ARB, &v);
  EXPECT_EQ(err(), kInvalidOperation);
  glGetObjectParameterivARB(p, GL_OBJECT_COMPILE_STATUS_ARB, &v);
  EXPECT_EQ(err(), kInvalidOperation);
  glGetObjectParameterivARB(p, GL_TEXTURE_2D, &v);
  EXPECT_EQ(err(), kInvalidEnum);
  glGetObjectParameterivARB(0, GL_OBJECT_TYPE_ARB, &v);
  EXPECT_EQ(err(), kInvalidValue);
  glGetObjectParameterfvARB(4321, GL_OBJECT_TYPE_ARB, &f);
  EXPECT_EQ(err(), kInvalidValue);
  EXPECT_EQ(v, 1234);

  GLhandleARB objs[4] = {};
  GLsizei count = 0;
  glGetAttachedObjectsARB(p, 4, &count, objs);
  ASSERT_EQ(count, 2);
  EXPECT_EQ(objs[0], vs);
  EXPECT_EQ(objs[1], fs);
  glGetAttachedObjectsARB(vs, 4, &count, objs);
  EXPECT_EQ(err(), kInvalidOperation);
  glUseProgram(0);
}

TEST_F(ArbShaderObjectsTest, InfoLog) {
  const GLuint bad = shader(GL_FRAGMENT_SHADER, "void main() { nothing = 1.0; }\n");
  GLint n = 0;
  glGetObjectParameterivARB(bad, GL_OBJECT_INFO_LOG_LENGTH_ARB, &n);
  ASSERT_GT(n, 1);
  std::vector<GLcharARB> text(static_cast<size_t>(n));
  GLsizei len = 0;
  glGetInfoLogARB(bad, n, &len, text.data());
  EXPECT_EQ(len, n - 1);
  EXPECT_NE(std::string(text.data()).find("nothing"), std::string::npos) << text.data();
  const GLuint p = glCreateProgram();
  glAttachShader(p, bad);
  glLinkProgram(p);
  glGetObjectParameterivARB(p, GL_OBJECT_INFO_LOG_LENGTH_ARB, &n);
  ASSERT_GT(n, 1);
  text.assign(static_cast<size_t>(n), 0);
  glGetInfoLogARB(p, n, nullptr, text.data());
  EXPECT_EQ(std::string(text.data()), log(p));
  glGetInfoLogARB(p, -1, nullptr, text.data());
  EXPECT_EQ(err(), kInvalidValue);
  glGetInfoLogARB(0, n, nullptr, text.data());
  EXPECT_EQ(err(), kInvalidValue);
}

TEST_F(ArbShaderObjectsTest, DeleteObject) {
  // ARB_shader_objects §2.14: deleted at once, or flagged while attached or in use.
  const GLuint vs = shader(GL_VERTEX_SHADER, "void main() { gl_Position = gl_Vertex; }\n");
  const GLuint p = glCreateProgram();
  glAttachShader(p, vs);
  glLinkProgram(p);
  glUseProgram(p);
  glDeleteObjectARB(vs);
  glDeleteObjectARB(p);
  EXPECT_EQ(err(), kNoError);
  GLint v = 0;
  glGetObjectParameterivARB(vs, GL_OBJECT_DELETE_STATUS_ARB, &v);
  EXPECT_EQ(v, GL_TRUE);
  glGetObjectParameterivARB(p, GL_OBJECT_DELETE_STATUS_ARB, &v);
  EXPECT_EQ(v, GL_TRUE);
  EXPECT_EQ(glIsProgram(p), GL_TRUE);
  glUseProgram(0);
  EXPECT_EQ(glIsProgram(p), GL_FALSE);
  EXPECT_EQ(glIsShader(vs), GL_FALSE);
  const GLuint lone = shader(GL_FRAGMENT_SHADER, "void main() {}\n");
  glDeleteObjectARB(lone);
  EXPECT_EQ(glIsShader(lone), GL_FALSE);
  glDeleteObjectARB(0); // silently ignored
  EXPECT_EQ(err(), kNoError);
  glDeleteObjectARB(lone);
  EXPECT_EQ(err(), kInvalidValue);
}

TEST_F(ArbShaderObjectsTest, CommandsThroughGetProcAddress) {
  for (const char* name :
       {"glDeleteObjectARB", "glGetHandleARB", "glGetObjectParameterivARB",
        "glGetObjectParameterfvARB", "glGetInfoLogARB", "glGetAttachedObjectsARB"})
    EXPECT_NE(OSMesaGetProcAddress(name), nullptr) << name;
  // The aliases of GL 2.0 commands come with the extension string (src/api/extensions.txt).
  const auto* ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  ASSERT_NE(ext, nullptr);
  if (std::strstr(ext, "GL_ARB_shader_objects ") == nullptr) GTEST_SKIP() << "not advertised";
  for (const char* name : {"glCreateShaderObjectARB", "glShaderSourceARB", "glCompileShaderARB",
                           "glCreateProgramObjectARB", "glAttachObjectARB", "glDetachObjectARB",
                           "glLinkProgramARB", "glUseProgramObjectARB", "glValidateProgramARB",
                           "glUniform4fARB", "glUniformMatrix4fvARB", "glGetUniformLocationARB",
                           "glGetActiveUniformARB", "glGetUniformfvARB", "glGetShaderSourceARB"})
    EXPECT_NE(OSMesaGetProcAddress(name), nullptr) << name;
}

} // namespace
