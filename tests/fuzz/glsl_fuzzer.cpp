// libFuzzer harness of the shading language path: the input is the text of a program in the
// framing of glsl_framing.h, which tools/piglit_glsl_pairs.py writes (the seeds are piglit's
// GLSL 1.10/1.20 programs; a [uniforms] section's bytes pick uniform values and draw state).
// It goes through glShaderSource, glCompileShader, glLinkProgram and the queries (info logs,
// active uniforms and attributes); a linked program gets every active uniform set (values from the
// [uniforms] bytes: special floats, boundary integers, samplers of any unit), textures of every
// target on the units, generic attribute arrays, and draws triangles, lines, points and a pixel
// rectangle into a 16x16 OSMesa buffer. Shader sources are handed over with their lengths in
// exact-size heap blocks, so that AddressSanitizer sees a read past a source's end.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_input.h"
#include "glsl_framing.h"

namespace {

using pineda::fuzz::Input;

constexpr int kSize = 16;            // the drawable's width and height
constexpr int kUnits = 4;            // texture units given textures
constexpr int kMaxUniformElems = 64; // array elements set per uniform

// Textures of every target on the first units: 2x2 (1D: 4, 3D: 2x2x2) RGBA images with
// mipmaps on unit 0, nearest without on unit 1, depth textures with comparison on unit 2.
void make_textures(Input& in) {
  uint8_t texels[4 * 4 * 8];
  for (size_t i = 0; i < sizeof texels; ++i)
    texels[i] = static_cast<uint8_t>(i * 37 + 11);
  float depths[8] = {0.0f, 0.25f, 0.5f, 1.0f, 0.75f, 0.125f, 0.9f, 0.3f};
  for (int unit = 0; unit < kUnits; ++unit) {
    glActiveTexture(GL_TEXTURE0 + unit);
    const bool depth = unit == 2;
    const GLenum ifmt = depth ? GL_DEPTH_COMPONENT : GL_RGBA;
    const GLenum fmt = depth ? GL_DEPTH_COMPONENT : GL_RGBA;
    const GLenum type = depth ? GL_FLOAT : GL_UNSIGNED_BYTE;
    const void* data = depth ? static_cast<const void*>(depths) : texels;
    for (GLenum target : {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP}) {
      if (depth && (target == GL_TEXTURE_3D || target == GL_TEXTURE_CUBE_MAP)) continue;
      GLuint tex = 0;
      glGenTextures(1, &tex);
      glBindTexture(target, tex);
      if (target == GL_TEXTURE_1D) {
        glTexImage1D(target, 0, ifmt, 4, 0, fmt, type, data);
        glTexImage1D(target, 1, ifmt, 2, 0, fmt, type, data);
        glTexImage1D(target, 2, ifmt, 1, 0, fmt, type, data);
      } else if (target == GL_TEXTURE_2D) {
        glTexImage2D(target, 0, ifmt, 2, 2, 0, fmt, type, data);
        glTexImage2D(target, 1, ifmt, 1, 1, 0, fmt, type, data);
      } else if (target == GL_TEXTURE_3D) {
        glTexImage3D(target, 0, ifmt, 2, 2, 2, 0, fmt, type, data);
        glTexImage3D(target, 1, ifmt, 1, 1, 1, 0, fmt, type, data);
      } else {
        for (int face = 0; face < 6; ++face) {
          glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, ifmt, 2, 2, 0, fmt, type, data);
          glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 1, ifmt, 1, 1, 0, fmt, type, data);
        }
      }
      const uint8_t bits = in.u8();
      glTexParameteri(target, GL_TEXTURE_MIN_FILTER,
                      unit == 1  ? GL_NEAREST
                      : bits & 1 ? GL_LINEAR_MIPMAP_LINEAR
                                 : GL_NEAREST_MIPMAP_NEAREST);
      glTexParameteri(target, GL_TEXTURE_MAG_FILTER, bits & 2 ? GL_LINEAR : GL_NEAREST);
      glTexParameteri(target, GL_TEXTURE_WRAP_S, bits & 4 ? GL_REPEAT : GL_CLAMP_TO_EDGE);
      glTexParameteri(target, GL_TEXTURE_WRAP_T, bits & 8 ? GL_MIRRORED_REPEAT : GL_CLAMP);
      glTexParameterf(target, GL_TEXTURE_LOD_BIAS, in.f());
      if (depth) {
        glTexParameteri(target, GL_TEXTURE_COMPARE_MODE,
                        bits & 16 ? GL_COMPARE_R_TO_TEXTURE : GL_NONE);
        glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, bits & 32 ? GL_LEQUAL : GL_GREATER);
      }
    }
  }
  glActiveTexture(GL_TEXTURE0);
}

bool is_sampler(GLenum type) {
  switch (type) {
  case GL_SAMPLER_1D:
  case GL_SAMPLER_2D:
  case GL_SAMPLER_3D:
  case GL_SAMPLER_CUBE:
  case GL_SAMPLER_1D_SHADOW:
  case GL_SAMPLER_2D_SHADOW:
    return true;
  default:
    return false;
  }
}

// Components of a uniform type and whether they are set with glUniform*i (int, bool, sampler).
int components(GLenum type, bool& ints, int& matrix_cols) {
  ints = false;
  matrix_cols = 0;
  switch (type) {
  case GL_FLOAT:
    return 1;
  case GL_FLOAT_VEC2:
    return 2;
  case GL_FLOAT_VEC3:
    return 3;
  case GL_FLOAT_VEC4:
    return 4;
  case GL_FLOAT_MAT2:
    matrix_cols = 2;
    return 4;
  case GL_FLOAT_MAT3:
    matrix_cols = 3;
    return 9;
  case GL_FLOAT_MAT4:
    matrix_cols = 4;
    return 16;
  case GL_FLOAT_MAT2x3:
    matrix_cols = 2;
    return 6;
  case GL_FLOAT_MAT2x4:
    matrix_cols = 2;
    return 8;
  case GL_FLOAT_MAT3x2:
    matrix_cols = 3;
    return 6;
  case GL_FLOAT_MAT3x4:
    matrix_cols = 3;
    return 12;
  case GL_FLOAT_MAT4x2:
    matrix_cols = 4;
    return 8;
  case GL_FLOAT_MAT4x3:
    matrix_cols = 4;
    return 12;
  default:
    break;
  }
  ints = true;
  switch (type) {
  case GL_INT:
  case GL_BOOL:
    return 1;
  case GL_INT_VEC2:
  case GL_BOOL_VEC2:
    return 2;
  case GL_INT_VEC3:
  case GL_BOOL_VEC3:
    return 3;
  case GL_INT_VEC4:
  case GL_BOOL_VEC4:
    return 4;
  default:
    return is_sampler(type) ? 1 : 0;
  }
}

// Sets one uniform location of the given type from the fuzzer's bytes.
void set_uniform(GLuint prog, Input& in, GLint loc, GLenum type) {
  bool ints = false;
  int cols = 0;
  const int n = components(type, ints, cols);
  if (n == 0) return;
  if (ints) {
    GLint v[4] = {};
    for (int i = 0; i < n; ++i)
      // Samplers: mostly a unit 0..kUnits, sometimes any value (out of range: INVALID_VALUE).
      v[i] = !is_sampler(type) ? in.i()
             : in.peek() < 250 ? static_cast<GLint>(in.u8() % (kUnits + 1))
                               : (in.u8(), in.i());
    switch (n) {
    case 1:
      glUniform1i(loc, v[0]);
      break;
    case 2:
      glUniform2iv(loc, 1, v);
      break;
    case 3:
      glUniform3iv(loc, 1, v);
      break;
    default:
      glUniform4iv(loc, 1, v);
      break;
    }
    GLint back[4];
    glGetUniformiv(prog, loc, back);
    return;
  }
  GLfloat v[16] = {};
  for (int i = 0; i < n; ++i)
    v[i] = in.f();
  const GLboolean transpose = (in.peek() & 1) ? GL_TRUE : GL_FALSE;
  switch (type) {
  case GL_FLOAT:
    glUniform1f(loc, v[0]);
    break;
  case GL_FLOAT_VEC2:
    glUniform2fv(loc, 1, v);
    break;
  case GL_FLOAT_VEC3:
    glUniform3fv(loc, 1, v);
    break;
  case GL_FLOAT_VEC4:
    glUniform4fv(loc, 1, v);
    break;
  case GL_FLOAT_MAT2:
    glUniformMatrix2fv(loc, 1, transpose, v);
    break;
  case GL_FLOAT_MAT3:
    glUniformMatrix3fv(loc, 1, transpose, v);
    break;
  case GL_FLOAT_MAT4:
    glUniformMatrix4fv(loc, 1, transpose, v);
    break;
  case GL_FLOAT_MAT2x3:
    glUniformMatrix2x3fv(loc, 1, transpose, v);
    break;
  case GL_FLOAT_MAT2x4:
    glUniformMatrix2x4fv(loc, 1, transpose, v);
    break;
  case GL_FLOAT_MAT3x2:
    glUniformMatrix3x2fv(loc, 1, transpose, v);
    break;
  case GL_FLOAT_MAT3x4:
    glUniformMatrix3x4fv(loc, 1, transpose, v);
    break;
  case GL_FLOAT_MAT4x2:
    glUniformMatrix4x2fv(loc, 1, transpose, v);
    break;
  case GL_FLOAT_MAT4x3:
    glUniformMatrix4x3fv(loc, 1, transpose, v);
    break;
  default:
    break;
  }
}

// Info logs are read into exact-size blocks of the length GL reports.
void read_shader_log(GLuint s) {
  GLint len = 0;
  glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
  if (len <= 0 || len > (1 << 20)) return;
  char* log = static_cast<char*>(std::malloc(static_cast<size_t>(len)));
  GLsizei got = 0;
  glGetShaderInfoLog(s, len, &got, log);
  if (got >= len) std::abort();
  std::free(log);
  glGetShaderiv(s, GL_SHADER_SOURCE_LENGTH, &len);
  if (len <= 0 || len > (1 << 20)) return;
  char* src = static_cast<char*>(std::malloc(static_cast<size_t>(len)));
  glGetShaderSource(s, len, &got, src);
  if (got >= len) std::abort();
  std::free(src);
}

void read_program_log(GLuint p) {
  GLint len = 0;
  glGetProgramiv(p, GL_INFO_LOG_LENGTH, &len);
  if (len <= 0 || len > (1 << 20)) return;
  char* log = static_cast<char*>(std::malloc(static_cast<size_t>(len)));
  GLsizei got = 0;
  glGetProgramInfoLog(p, len, &got, log);
  if (got >= len) std::abort();
  std::free(log);
}

// Sets every active uniform (each element of arrays, by "name[i]") and reads it back.
void set_uniforms(GLuint prog, Input& in) {
  GLint count = 0, max_len = 0;
  glGetProgramiv(prog, GL_ACTIVE_UNIFORMS, &count);
  glGetProgramiv(prog, GL_ACTIVE_UNIFORM_MAX_LENGTH, &max_len);
  if (count <= 0 || max_len <= 0) return;
  std::vector<char> name(static_cast<size_t>(max_len));
  for (GLint u = 0; u < count && u < 256; ++u) {
    GLsizei len = 0;
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(prog, static_cast<GLuint>(u), max_len, &len, &size, &type, name.data());
    if (len <= 0 || len >= max_len) continue;
    std::string base(name.data(), static_cast<size_t>(len));
    if (base.ends_with("[0]")) base.resize(base.size() - 3);
    if (base.starts_with("gl_")) continue;
    for (GLint e = 0; e < size && e < kMaxUniformElems; ++e) {
      const std::string elem = size > 1 ? base + "[" + std::to_string(e) + "]" : base;
      const GLint loc = glGetUniformLocation(prog, elem.c_str());
      if (loc < 0) continue;
      set_uniform(prog, in, loc, type);
      GLfloat back[16];
      glGetUniformfv(prog, loc, back);
    }
  }
}

// Generic arrays for every active attribute (and the conventional ones), four vertices.
void set_attributes(GLuint prog, Input& in, std::vector<GLfloat>& arrays) {
  GLint count = 0, max_len = 0;
  glGetProgramiv(prog, GL_ACTIVE_ATTRIBUTES, &count);
  glGetProgramiv(prog, GL_ACTIVE_ATTRIBUTE_MAX_LENGTH, &max_len);
  if (count <= 0 || max_len <= 0) return;
  std::vector<char> name(static_cast<size_t>(max_len));
  arrays.assign(16 * 4 * 4, 0.0f);
  for (GLint a = 0; a < count && a < 16; ++a) {
    GLsizei len = 0;
    GLint size = 0;
    GLenum type = 0;
    glGetActiveAttrib(prog, static_cast<GLuint>(a), max_len, &len, &size, &type, name.data());
    if (len <= 0 || len >= max_len) continue;
    const GLint loc = glGetAttribLocation(prog, name.data());
    if (loc <= 0 || loc >= 16) continue; // 0 is the vertex array (gl_Vertex or aliased)
    GLfloat* data = &arrays[static_cast<size_t>(loc) * 16];
    for (int i = 0; i < 16; ++i)
      data[i] = in.empty() ? static_cast<GLfloat>((i * 7 + loc) % 5) * 0.25f : in.f();
    if (in.u8() & 1) {
      glVertexAttribPointer(static_cast<GLuint>(loc), 4, GL_FLOAT, GL_FALSE, 0, data);
      glEnableVertexAttribArray(static_cast<GLuint>(loc));
    } else {
      glVertexAttrib4fv(static_cast<GLuint>(loc), data);
    }
  }
}

void draw(Input& in, std::vector<GLfloat>& verts) {
  const uint8_t flags = in.u8();
  if (flags & 1) glEnable(GL_VERTEX_PROGRAM_POINT_SIZE);
  if (flags & 2) glEnable(GL_VERTEX_PROGRAM_TWO_SIDE);
  if (flags & 4) glEnable(GL_DEPTH_TEST);
  if (flags & 8) glEnable(GL_BLEND);
  if (flags & 16) glEnable(GL_ALPHA_TEST);
  if (flags & 32) glEnable(GL_POINT_SPRITE);
  if (flags & 64) glEnable(GL_CLIP_PLANE0);
  if (flags & 128) glEnable(GL_CULL_FACE);
  // A quad over the whole drawable (z and w from the input for some), then lines and points.
  verts = {-1, -1, 0, 1, 1, -1, 0.5f, 1, -1, 1, -0.5f, 1, 1, 1, 0, 1};
  if (in.u8() & 1) verts[3] = in.f(), verts[6] = in.f();
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(4, GL_FLOAT, 0, verts.data());
  static const GLfloat colors[16] = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 0.5f};
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(4, GL_FLOAT, 0, colors);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(4, GL_FLOAT, 0, colors);
  glNormal3f(0, 0, 1);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glDrawArrays(GL_LINE_LOOP, 0, 4);
  glPointSize(3);
  glDrawArrays(GL_POINTS, 0, 4);
  // Immediate mode with a generic attribute, and a pixel rectangle at the raster position.
  glBegin(GL_TRIANGLES);
  glVertexAttrib4f(1, 0.5f, 0.25f, 1, 0);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(0, 1);
  glEnd();
  glRasterPos2f(-0.5f, -0.5f);
  const uint8_t pixels[2 * 2 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 9, 9, 9, 9};
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  glFinish();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // One worker thread: the draws are tiny, and the fuzzer runs beside other work (also under
  // replay_main.cpp, which has no LLVMFuzzerInitialize).
  static const bool one_thread = setenv("PINEDA_THREADS", "1", 0) == 0;
  (void)one_thread;
  namespace framing = pineda::glsl_framing;
  const framing::Program parsed =
      framing::parse(std::string_view(reinterpret_cast<const char*>(data), size));
  Input in(reinterpret_cast<const uint8_t*>(parsed.uniforms.data()), parsed.uniforms.size());

  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (ctx == nullptr) return 0;
  std::vector<uint8_t> color(kSize * kSize * 4);
  if (!OSMesaMakeCurrent(ctx, color.data(), GL_UNSIGNED_BYTE, kSize, kSize)) {
    OSMesaDestroyContext(ctx);
    return 0;
  }

  const GLuint prog = glCreateProgram();
  std::vector<GLuint> shaders;
  for (const auto& [stage, src] : parsed.shaders) {
    const GLuint s =
        glCreateShader(stage == framing::Stage::Vertex ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER);
    // The source in a block of exactly its bytes, with its length (no terminating zero).
    char* copy = static_cast<char*>(std::malloc(src.size() ? src.size() : 1));
    std::memcpy(copy, src.data(), src.size());
    const GLchar* strings[1] = {copy};
    const GLint lengths[1] = {static_cast<GLint>(src.size())};
    glShaderSource(s, 1, strings, lengths);
    std::free(copy);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    read_shader_log(s);
    glAttachShader(prog, s);
    shaders.push_back(s);
  }
  glLinkProgram(prog);
  GLint linked = 0;
  glGetProgramiv(prog, GL_LINK_STATUS, &linked);
  read_program_log(prog);
  std::vector<GLfloat> arrays, verts;
  if (linked) {
    glValidateProgram(prog);
    read_program_log(prog);
    make_textures(in);
    glUseProgram(prog);
    set_uniforms(prog, in);
    set_attributes(prog, in, arrays);
    draw(in, verts);
    // Relinking the program in use, then drawing with what the relink left.
    if (in.u8() & 1) {
      glLinkProgram(prog);
      draw(in, verts);
    }
    glUseProgram(0);
  }
  for (GLuint s : shaders)
    glDeleteShader(s);
  glDeleteProgram(prog);
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);
  return 0;
}
