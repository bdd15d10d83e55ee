// Helpers of the GLSL scenes (glsl.cpp, glsl_state.cpp): the GL 2.0 entry points looked up at
// run time, programs, and the geometry the scenes draw.
#pragma once

#include "scene_util.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace scenes::glsl {

// The GL 2.0 entry points, looked up at run time (scene.h proc()).
struct GL2 {
  PFNGLCREATESHADERPROC CreateShader = proc<PFNGLCREATESHADERPROC>("glCreateShader");
  PFNGLSHADERSOURCEPROC ShaderSource = proc<PFNGLSHADERSOURCEPROC>("glShaderSource");
  PFNGLCOMPILESHADERPROC CompileShader = proc<PFNGLCOMPILESHADERPROC>("glCompileShader");
  PFNGLGETSHADERIVPROC GetShaderiv = proc<PFNGLGETSHADERIVPROC>("glGetShaderiv");
  PFNGLGETSHADERINFOLOGPROC GetShaderInfoLog =
      proc<PFNGLGETSHADERINFOLOGPROC>("glGetShaderInfoLog");
  PFNGLCREATEPROGRAMPROC CreateProgram = proc<PFNGLCREATEPROGRAMPROC>("glCreateProgram");
  PFNGLATTACHSHADERPROC AttachShader = proc<PFNGLATTACHSHADERPROC>("glAttachShader");
  PFNGLLINKPROGRAMPROC LinkProgram = proc<PFNGLLINKPROGRAMPROC>("glLinkProgram");
  PFNGLGETPROGRAMIVPROC GetProgramiv = proc<PFNGLGETPROGRAMIVPROC>("glGetProgramiv");
  PFNGLGETPROGRAMINFOLOGPROC GetProgramInfoLog =
      proc<PFNGLGETPROGRAMINFOLOGPROC>("glGetProgramInfoLog");
  PFNGLUSEPROGRAMPROC UseProgram = proc<PFNGLUSEPROGRAMPROC>("glUseProgram");
  PFNGLDELETEPROGRAMPROC DeleteProgram = proc<PFNGLDELETEPROGRAMPROC>("glDeleteProgram");
  PFNGLDELETESHADERPROC DeleteShader = proc<PFNGLDELETESHADERPROC>("glDeleteShader");
  PFNGLGETUNIFORMLOCATIONPROC GetUniformLocation =
      proc<PFNGLGETUNIFORMLOCATIONPROC>("glGetUniformLocation");
  PFNGLGETATTRIBLOCATIONPROC GetAttribLocation =
      proc<PFNGLGETATTRIBLOCATIONPROC>("glGetAttribLocation");
  PFNGLBINDATTRIBLOCATIONPROC BindAttribLocation =
      proc<PFNGLBINDATTRIBLOCATIONPROC>("glBindAttribLocation");
  PFNGLUNIFORM1FPROC Uniform1f = proc<PFNGLUNIFORM1FPROC>("glUniform1f");
  PFNGLUNIFORM2FPROC Uniform2f = proc<PFNGLUNIFORM2FPROC>("glUniform2f");
  PFNGLUNIFORM3FPROC Uniform3f = proc<PFNGLUNIFORM3FPROC>("glUniform3f");
  PFNGLUNIFORM4FPROC Uniform4f = proc<PFNGLUNIFORM4FPROC>("glUniform4f");
  PFNGLUNIFORM1IPROC Uniform1i = proc<PFNGLUNIFORM1IPROC>("glUniform1i");
  PFNGLUNIFORM4FVPROC Uniform4fv = proc<PFNGLUNIFORM4FVPROC>("glUniform4fv");
  PFNGLUNIFORM1FVPROC Uniform1fv = proc<PFNGLUNIFORM1FVPROC>("glUniform1fv");
  PFNGLUNIFORMMATRIX3FVPROC UniformMatrix3fv =
      proc<PFNGLUNIFORMMATRIX3FVPROC>("glUniformMatrix3fv");
  PFNGLVERTEXATTRIB4FPROC VertexAttrib4f = proc<PFNGLVERTEXATTRIB4FPROC>("glVertexAttrib4f");
  PFNGLVERTEXATTRIB2FPROC VertexAttrib2f = proc<PFNGLVERTEXATTRIB2FPROC>("glVertexAttrib2f");
  PFNGLVERTEXATTRIBPOINTERPROC VertexAttribPointer =
      proc<PFNGLVERTEXATTRIBPOINTERPROC>("glVertexAttribPointer");
  PFNGLENABLEVERTEXATTRIBARRAYPROC EnableVertexAttribArray =
      proc<PFNGLENABLEVERTEXATTRIBARRAYPROC>("glEnableVertexAttribArray");
  PFNGLDISABLEVERTEXATTRIBARRAYPROC DisableVertexAttribArray =
      proc<PFNGLDISABLEVERTEXATTRIBARRAYPROC>("glDisableVertexAttribArray");
  PFNGLACTIVETEXTUREPROC ActiveTexture = proc<PFNGLACTIVETEXTUREPROC>("glActiveTexture");

  GLuint shader(GLenum type, const char* src) {
    const GLuint s = CreateShader(type);
    ShaderSource(s, 1, &src, nullptr);
    CompileShader(s);
    GLint ok = 0;
    GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      char log[2048];
      GetShaderInfoLog(s, sizeof log, nullptr, log);
      throw std::runtime_error(std::string("shader does not compile: ") + log);
    }
    return s;
  }
  // A linked program of the given stages (null: that stage stays fixed function), in use.
  GLuint program(const char* vs, const char* fs,
                 std::initializer_list<std::pair<GLuint, const char*>> bindings = {}) {
    const GLuint p = CreateProgram();
    GLuint v = 0, f = 0;
    if (vs != nullptr) AttachShader(p, v = shader(GL_VERTEX_SHADER, vs));
    if (fs != nullptr) AttachShader(p, f = shader(GL_FRAGMENT_SHADER, fs));
    for (const auto& [index, name] : bindings)
      BindAttribLocation(p, index, name);
    LinkProgram(p);
    GLint ok = 0;
    GetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
      char log[2048];
      GetProgramInfoLog(p, sizeof log, nullptr, log);
      throw std::runtime_error(std::string("program does not link: ") + log);
    }
    // Flagged for deletion: they go with the program.
    if (v != 0) DeleteShader(v);
    if (f != 0) DeleteShader(f);
    UseProgram(p);
    return p;
  }
  void done(GLuint p) {
    UseProgram(0);
    DeleteProgram(p);
  }
  GLint loc(GLuint p, const char* name) { return GetUniformLocation(p, name); }
};

// A perspective view of the unit cube's surroundings: frustum, camera at z = 3.
inline void perspective(const Frame& f) {
  glViewport(0, 0, f.width, f.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double aspect = static_cast<double>(f.width) / f.height;
  glFrustum(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -3.0f);
}

// A sphere of radius r as quad strips with normals and texture coordinates.
inline void sphere(float r, int slices, int stacks) {
  for (int i = 0; i < stacks; ++i) {
    const float a0 = kPi * (static_cast<float>(i) / stacks - 0.5f);
    const float a1 = kPi * (static_cast<float>(i + 1) / stacks - 0.5f);
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= slices; ++j) {
      const float b = 2.0f * kPi * static_cast<float>(j) / slices;
      for (float a : {a1, a0}) {
        const float x = std::cos(a) * std::cos(b), y = std::sin(a), z = std::cos(a) * std::sin(b);
        glNormal3f(x, y, z);
        glTexCoord2f(static_cast<float>(j) / slices, a / kPi + 0.5f);
        glVertex3f(r * x, r * y, r * z);
      }
    }
    glEnd();
  }
}

// A w x h grid of quads over [-1, 1]^2 at z = 0, texture coordinates [0, 1]^2, colours from
// the palette.
inline void grid(int w, int h) {
  for (int j = 0; j < h; ++j) {
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= w; ++i) {
      for (int dj : {1, 0}) {
        const float u = static_cast<float>(i) / w, v = static_cast<float>(j + dj) / h;
        palette_color(i + 3 * (j + dj));
        glTexCoord2f(u, v);
        glVertex3f(2.0f * u - 1.0f, 2.0f * v - 1.0f, 0.0f);
      }
    }
    glEnd();
  }
}

// The whole window in clip coordinates (identity matrices), texture coordinates [0, 1]^2.
inline void clip_quad() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
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
}

// A 64x64 RGBA checker with a gradient, mipmapped by GENERATE_MIPMAP, trilinear, repeating.
inline GLuint checker_texture() {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  std::vector<unsigned char> texels(64 * 64 * 4);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      unsigned char* t = &texels[static_cast<size_t>((y * 64 + x) * 4)];
      const bool on = ((x / 8) + (y / 8)) % 2 == 0;
      t[0] = static_cast<unsigned char>(on ? 255 : 4 * x);
      t[1] = static_cast<unsigned char>(on ? 255 : 4 * y);
      t[2] = static_cast<unsigned char>(on ? 64 : 200);
      t[3] = 255;
    }
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return tex;
}

inline const char* kTransformVs = "void main() {\n"
                                  "  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n"
                                  "  gl_FrontColor = gl_Color;\n"
                                  "  gl_TexCoord[0] = gl_MultiTexCoord0;\n"
                                  "}\n";

// A fragment shader over a full-window quad mapping gl_TexCoord[0] to a value range: `body`
// computes vec4 c from vec2 p in [lo, hi]^2.
inline void function_scene(const char* body, float lo, float hi) {
  GL2 gl;
  const std::string fs = std::string("uniform vec2 range;\n"
                                     "void split(inout vec2 v, out float f) {\n"
                                     "  f = fract(v.x * 3.0 + v.y);\n"
                                     "  if (f > 0.5) return;\n"
                                     "  v = v.yx * 0.5;\n}\n"
                                     "void main() {\n"
                                     "  vec2 p = mix(vec2(range.x), vec2(range.y), "
                                     "gl_TexCoord[0].st);\n  vec4 c;\n") +
                         body + "  gl_FragColor = c;\n}\n";
  const GLuint p = gl.program(kTransformVs, fs.c_str());
  gl.Uniform2f(gl.loc(p, "range"), lo, hi);
  clear_frame(0, 0, 0);
  clip_quad();
  gl.done(p);
}

} // namespace scenes::glsl
