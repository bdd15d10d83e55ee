// GLSL 1.10/1.20 programs (GL 2.1 §2.15, §2.20, §3.11), part one: the built-in function groups,
// control flow and discard, derivatives, and texturing from both stages (every sampler type,
// projective, bias, explicit level, shadow). Each scene deletes its objects and puts back the
// state it touched. Part two, built-in state and the pipeline around the shaders: glsl_state.cpp.
#include "glsl_util.h"

using namespace scenes;
using namespace scenes::glsl;

PINEDA_SCENE(glsl_builtin_trig,
             "angle and trigonometry functions: radians, sin, cos, tan, asin, acos, atan") {
  function_scene(
      "  c = vec4(sin(p.x * 3.0) * 0.5 + 0.5, cos(p.y * 2.0 + p.x) * 0.5 + 0.5,\n"
      "    atan(p.y, p.x) / 6.2831853 + 0.5, 1.0);\n"
      "  c.r = c.r * 0.5 + 0.25 * (asin(clamp(p.x * 0.3, -1.0, 1.0)) + 1.5708) / 3.1416;\n"
      "  c.g = c.g * 0.5 + 0.5 * (acos(clamp(p.y * 0.3, -1.0, 1.0)) / 3.1416);\n"
      "  c.b = c.b * 0.7 + 0.3 * clamp(tan(radians(degrees(p.x * 0.2))) + 0.5, 0.0, 1.0);\n",
      -3.0f, 3.0f);
}

PINEDA_SCENE(glsl_builtin_exponential,
             "exponential functions: pow, exp, log, exp2, log2, sqrt, inversesqrt") {
  function_scene("  vec2 q = p + 0.05;\n"
                 "  c = vec4(pow(q.x, 1.7) / 6.0, exp(-q.y) , log(q.x + q.y + 1.0) / 2.5, 1.0);\n"
                 "  c.r += exp2(-q.y * 2.0) * 0.3;\n"
                 "  c.g = c.g * 0.6 + log2(q.x + 1.0) * 0.15;\n"
                 "  c.b = c.b * 0.5 + sqrt(q.y) * 0.1 + inversesqrt(q.x + 0.5) * 0.2;\n",
                 0.0f, 4.0f);
}

PINEDA_SCENE(glsl_builtin_common, "common functions: abs, sign, floor, ceil, fract, mod, min, max, "
                                  "clamp, mix, step, smoothstep") {
  function_scene(
      "  c.r = fract(p.x) * 0.5 + abs(sign(p.y)) * 0.25 + step(0.5, fract(p.y)) * 0.25;\n"
      "  c.g = mod(floor(p.x) + ceil(p.y), 3.0) / 3.0 * 0.5 + smoothstep(-2.0, 2.0, p.x) * 0.5;\n"
      "  c.b = clamp(max(p.x, p.y) * 0.2, 0.0, 1.0) * mix(0.3, 1.0, fract(min(p.x, p.y)));\n"
      "  c.a = 1.0;\n",
      -4.0f, 4.0f);
}

PINEDA_SCENE(glsl_builtin_geometric,
             "geometric and vector relational functions: length, distance, dot, cross, normalize, "
             "faceforward, reflect, refract, lessThan, any, all") {
  function_scene("  vec3 v = vec3(p, 1.0 - length(p));\n"
                 "  vec3 n = normalize(v);\n"
                 "  vec3 r = reflect(vec3(0.0, 0.0, -1.0), n);\n"
                 "  vec3 t = refract(vec3(0.0, 0.0, -1.0), n, 0.7);\n"
                 "  vec3 x = cross(n, vec3(0.0, 1.0, 0.0));\n"
                 "  vec3 f = faceforward(n, vec3(p, -0.5), vec3(0.0, 0.0, 1.0));\n"
                 "  c = vec4(r * 0.5 + 0.5, 1.0) * 0.5 + vec4(t * 0.25 + 0.25, 0.0);\n"
                 "  c.b = c.b * 0.5 + dot(x, x) * 0.25 + distance(p, vec2(0.3)) * 0.1;\n"
                 "  if (all(lessThan(abs(p), vec2(0.2)))) c.g = 1.0;\n"
                 "  if (any(greaterThan(f.xy, vec2(0.9)))) c.r = 0.0;\n"
                 "  c.a = 1.0;\n",
                 -1.2f, 1.2f);
}

PINEDA_SCENE(glsl_builtin_matrix_functions,
             "matrix uniforms and functions: mat2/mat3/mat4 products, matrixCompMult, 1.20 "
             "non-square matrices and outerProduct, transpose") {
  GL2 gl;
  clear_frame(0, 0, 0);
  const GLuint p =
      gl.program("#version 120\nvoid main() { gl_Position = ftransform(); gl_TexCoord[0] = "
                 "gl_MultiTexCoord0; }\n",
                 "#version 120\nuniform mat3 rot;\n"
                 "void main() {\n"
                 "  vec2 q = gl_TexCoord[0].st * 2.0 - 1.0;\n"
                 "  mat2 m2 = mat2(0.8, -0.6, 0.6, 0.8);\n"
                 "  mat2x3 a = mat2x3(1.0, 0.5, 0.0, 0.0, 0.5, 1.0);\n"
                 "  mat3x2 at = transpose(a);\n"
                 "  vec3 v = rot * (a * (m2 * q));\n"
                 "  mat3 o = outerProduct(vec3(q, 1.0), vec3(0.2, 0.3, 0.4));\n"
                 "  mat3 cm = matrixCompMult(o, mat3(2.0));\n"
                 "  gl_FragColor = vec4(fract(v * 2.0), 1.0) * 0.6 + vec4(cm[2] * 0.4, 0.0) +\n"
                 "    vec4(at[0] * 0.1, 0.0, 0.0);\n}\n");
  const float c = std::cos(0.5f), s = std::sin(0.5f);
  const float rot[9] = {c, s, 0, -s, c, 0, 0, 0, 1};
  gl.UniformMatrix3fv(gl.loc(p, "rot"), 1, GL_FALSE, rot);
  clip_quad();
  gl.done(p);
}

PINEDA_SCENE(glsl_control_flow, "loops with break and continue, nested ifs, while and do-while") {
  function_scene("  int n = 0;\n"
                 "  vec2 z = vec2(0.0);\n"
                 "  for (int i = 0; i < 48; ++i) {\n"
                 "    z = vec2(z.x * z.x - z.y * z.y, 2.0 * z.x * z.y) + p;\n"
                 "    if (dot(z, z) > 4.0) break;\n"
                 "    if (i == 3) continue;\n"
                 "    n++;\n"
                 "  }\n"
                 "  float k = 0.0;\n"
                 "  int j = 0;\n"
                 "  while (j < 5) { k += p.x > float(j) * 0.2 - 1.0 ? 0.1 : 0.0; j++; }\n"
                 "  do { k += 0.05; } while (k < 0.2);\n"
                 "  if (n > 40) c = vec4(0.0, 0.0, 0.2, 1.0);\n"
                 "  else if (n > 20) c = vec4(float(n) / 48.0, 0.3, k, 1.0);\n"
                 "  else c = vec4(0.2, float(n) / 20.0, 1.0 - k, 1.0);\n",
                 -2.0f, 1.0f);
}

PINEDA_SCENE(glsl_discard, "discard by a pattern, with the depth test after it") {
  GL2 gl;
  clear_frame(0, 0, 0.3f);
  glEnable(GL_DEPTH_TEST);
  const GLuint p = gl.program(nullptr, "void main() {\n"
                                       "  vec2 c = mod(floor(gl_FragCoord.xy / 12.0), 2.0);\n"
                                       "  if (c.x == c.y) discard;\n"
                                       "  gl_FragColor = vec4(gl_Color.rgb, 1.0);\n}\n");
  glColor3f(1.0f, 0.8f, 0.2f);
  glBegin(GL_QUADS);
  glVertex3f(16, 16, -0.5f);
  glVertex3f(240, 16, -0.5f);
  glVertex3f(240, 240, -0.5f);
  glVertex3f(16, 240, -0.5f);
  glEnd();
  gl.UseProgram(0);
  // Behind the quad: visible only where it discarded.
  glColor3f(0.2f, 0.6f, 1.0f);
  glBegin(GL_TRIANGLES);
  glVertex3f(0, 0, 0.0f);
  glVertex3f(256, 60, 0.0f);
  glVertex3f(80, 256, 0.0f);
  glEnd();
  gl.done(p);
}

PINEDA_SCENE(glsl_texture2d, "texture2D, texture2DProj and a bias, mipmapped, in perspective") {
  GL2 gl;
  clear_frame(0, 0, 0);
  perspective(frame);
  const GLuint tex = checker_texture();
  const GLuint p = gl.program(
      "void main() { gl_Position = ftransform(); gl_TexCoord[0] = gl_MultiTexCoord0 * 4.0; }\n",
      "uniform sampler2D tex;\n"
      "void main() {\n"
      "  vec4 a = texture2D(tex, gl_TexCoord[0].st);\n"
      "  vec4 b = texture2DProj(tex, vec3(gl_TexCoord[0].st * 2.0, 2.0));\n"
      "  vec4 c = texture2D(tex, gl_TexCoord[0].st, 1.5);\n"
      "  gl_FragColor = gl_FragCoord.x < 85.0 ? a : (gl_FragCoord.x < 170.0 ? b : c);\n}\n");
  gl.Uniform1i(gl.loc(p, "tex"), 0);
  glRotatef(-65.0f, 1, 0, 0);
  glScalef(2.0f, 5.0f, 1.0f);
  grid(4, 4);
  gl.done(p);
  glDeleteTextures(1, &tex);
}

PINEDA_SCENE(glsl_texture_units,
             "1D and 2D samplers on two units, a texture matrix in the vertex shader") {
  GL2 gl;
  clear_frame(0, 0, 0);
  const GLuint tex2d = checker_texture();
  gl.ActiveTexture(GL_TEXTURE1);
  GLuint tex1d = 0;
  glGenTextures(1, &tex1d);
  glBindTexture(GL_TEXTURE_1D, tex1d);
  unsigned char ramp[16 * 4];
  for (int i = 0; i < 16; ++i) {
    ramp[4 * i] = static_cast<unsigned char>(i * 16);
    ramp[4 * i + 1] = static_cast<unsigned char>(255 - i * 16);
    ramp[4 * i + 2] = static_cast<unsigned char>((i % 4) * 80);
    ramp[4 * i + 3] = 255;
  }
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, ramp);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glRotatef(20.0f, 0, 0, 1);
  glScalef(2.0f, 2.0f, 1.0f);
  glMatrixMode(GL_MODELVIEW);
  gl.ActiveTexture(GL_TEXTURE0);
  const GLuint p =
      gl.program("void main() { gl_Position = ftransform();\n"
                 "  gl_TexCoord[0] = gl_MultiTexCoord0;\n"
                 "  gl_TexCoord[1] = gl_TextureMatrix[1] * gl_MultiTexCoord0; }\n",
                 "uniform sampler2D a;\nuniform sampler1D b;\n"
                 "void main() { gl_FragColor = texture2D(a, gl_TexCoord[1].st) * 0.6 +\n"
                 "  texture1D(b, gl_TexCoord[0].s) * 0.4; }\n");
  gl.Uniform1i(gl.loc(p, "a"), 0);
  gl.Uniform1i(gl.loc(p, "b"), 1);
  clip_quad();
  gl.done(p);
  gl.ActiveTexture(GL_TEXTURE1);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glDeleteTextures(1, &tex1d);
  gl.ActiveTexture(GL_TEXTURE0);
  glDeleteTextures(1, &tex2d);
}

PINEDA_SCENE(glsl_texture_cube, "textureCube reflection lookup on a sphere") {
  GL2 gl;
  clear_frame(0, 0, 0);
  glEnable(GL_DEPTH_TEST);
  perspective(frame);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
  for (int face = 0; face < 6; ++face) {
    unsigned char texels[16 * 16 * 4];
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        unsigned char* t = &texels[(y * 16 + x) * 4];
        const float* c = palette(face * 2 + ((x / 4 + y / 4) % 2));
        for (int k = 0; k < 3; ++k)
          t[k] = static_cast<unsigned char>(c[k] * 255.0f);
        t[3] = 255;
      }
    glTexImage2D(static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, GL_RGBA, 16, 16, 0,
                 GL_RGBA, GL_UNSIGNED_BYTE, texels);
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // llvmpipe clamps cube faces to their edges whatever the wrap mode (softpipe and Pineda
  // wrap REPEAT within the face, GL 2.1 §3.8.6): the scene uses CLAMP_TO_EDGE, where all agree.
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  const GLuint p = gl.program("varying vec3 r;\n"
                              "void main() { gl_Position = ftransform();\n"
                              "  vec3 e = normalize((gl_ModelViewMatrix * gl_Vertex).xyz);\n"
                              "  r = reflect(e, normalize(gl_NormalMatrix * gl_Normal)); }\n",
                              "uniform samplerCube env;\nvarying vec3 r;\n"
                              "void main() { gl_FragColor = textureCube(env, r); }\n");
  gl.Uniform1i(gl.loc(p, "env"), 0);
  sphere(1.2f, 32, 24);
  gl.done(p);
  glDeleteTextures(1, &tex);
}

PINEDA_SCENE(glsl_vertex_texture, "vertex texture fetch: texture2DLod displaces a grid") {
  GL2 gl;
  clear_frame(0, 0, 0);
  glEnable(GL_DEPTH_TEST);
  perspective(frame);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  unsigned char height[16 * 16 * 4];
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      for (int k = 0; k < 4; ++k)
        height[(y * 16 + x) * 4 + k] =
            static_cast<unsigned char>(127.5f + 127.0f * std::sin(static_cast<float>(x) * 0.7f) *
                                                    std::cos(static_cast<float>(y) * 0.5f));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, height);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  const GLuint p = gl.program(
      "uniform sampler2D h;\n"
      "void main() { float d = texture2DLod(h, gl_MultiTexCoord0.st, 0.0).r;\n"
      "  gl_Position = gl_ModelViewProjectionMatrix * (gl_Vertex + vec4(0.0, 0.0, d * 0.4, 0.0));\n"
      "  gl_FrontColor = vec4(d, 0.5, 1.0 - d, 1.0); }\n",
      nullptr);
  gl.Uniform1i(gl.loc(p, "h"), 0);
  glRotatef(-55.0f, 1, 0, 0);
  glScalef(1.3f, 1.3f, 1.0f);
  grid(24, 24);
  gl.done(p);
  glDeleteTextures(1, &tex);
}

PINEDA_SCENE(glsl_derivatives, "dFdx, dFdy and fwidth for antialiased stripes") {
  GL2 gl;
  clear_frame(0, 0, 0);
  perspective(frame);
  const GLuint p = gl.program("varying vec2 uv;\nvoid main() { gl_Position = ftransform(); uv = "
                              "gl_MultiTexCoord0.st * 8.0; }\n",
                              "varying vec2 uv;\n"
                              "void main() {\n"
                              "  vec2 w = fwidth(uv);\n"
                              "  vec2 s = smoothstep(0.5 - w, 0.5 + w, fract(uv));\n"
                              "  gl_FragColor = vec4(s, clamp(abs(dFdx(uv.x)) * 4.0 + "
                              "abs(dFdy(uv.y)) * 4.0, 0.0, 1.0), 1.0);\n"
                              "}\n");
  glRotatef(-60.0f, 1, 0, 0);
  glRotatef(20.0f, 0, 0, 1);
  glScalef(2.0f, 4.0f, 1.0f);
  grid(2, 2);
  gl.done(p);
}

PINEDA_SCENE(glsl_functions_arrays,
             "user functions with in, out and inout, local arrays indexed dynamically") {
  function_scene("  c = vec4(0.0, 0.0, 0.0, 1.0);\n"
                 "  float w[5];\n"
                 "  for (int i = 0; i < 5; ++i) w[i] = fract(float(i) * 0.37 + p.x);\n"
                 "  int k = int(clamp(floor(p.y * 5.0), 0.0, 4.0));\n"
                 "  c.r = w[k];\n"
                 "  vec2 a = p; float b;\n"
                 "  split(a, b);\n"
                 "  c.g = b; c.b = a.x * a.y;\n",
                 0.0f, 1.0f);
}

PINEDA_SCENE(glsl_shadow2d, "shadow2D and shadow2DProj against a depth texture with compare mode") {
  GL2 gl;
  clear_frame(0, 0, 0);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  std::vector<float> depth(32 * 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      depth[static_cast<size_t>(y * 32 + x)] = 0.5f + 0.4f *
                                                          std::sin(static_cast<float>(x) * 0.3f) *
                                                          std::cos(static_cast<float>(y) * 0.2f);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 32, 32, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
               depth.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
  const GLuint p =
      gl.program(kTransformVs, "uniform sampler2DShadow s;\n"
                               "void main() {\n"
                               "  vec3 c = vec3(gl_TexCoord[0].st, gl_TexCoord[0].s * 0.8 + 0.1);\n"
                               "  float a = shadow2D(s, c).r;\n"
                               "  float b = shadow2DProj(s, vec4(c * 2.0, 2.0)).r;\n"
                               "  gl_FragColor = vec4(a, b, 0.5 * (a + b), 1.0);\n}\n");
  gl.Uniform1i(gl.loc(p, "s"), 0);
  clip_quad();
  gl.done(p);
  glDeleteTextures(1, &tex);
}

PINEDA_SCENE(glsl_texture3d, "texture3D through a volume, trilinear within the slices") {
  GL2 gl;
  clear_frame(0, 0, 0);
  const auto tex_image_3d = proc<PFNGLTEXIMAGE3DPROC>("glTexImage3D");
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_3D, tex);
  std::vector<unsigned char> vol(8 * 8 * 8 * 4);
  for (int z = 0; z < 8; ++z)
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) {
        unsigned char* t = &vol[static_cast<size_t>(((z * 8 + y) * 8 + x) * 4)];
        t[0] = static_cast<unsigned char>(x * 36);
        t[1] = static_cast<unsigned char>(y * 36);
        t[2] = static_cast<unsigned char>(z * 36);
        t[3] = 255;
      }
  tex_image_3d(GL_TEXTURE_3D, 0, GL_RGBA, 8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol.data());
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  const GLuint p =
      gl.program(kTransformVs, "uniform sampler3D v;\n"
                               "void main() {\n"
                               "  vec2 q = gl_TexCoord[0].st;\n"
                               "  gl_FragColor = texture3D(v, vec3(q, fract(q.x + q.y)));\n}\n");
  gl.Uniform1i(gl.loc(p, "v"), 0);
  clip_quad();
  gl.done(p);
  glDeleteTextures(1, &tex);
}
