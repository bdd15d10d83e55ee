// The shader benchmark (the shader-speed issue): GLSL frames that load one part of a programmable
// pipeline each, rendered by Pineda, llvmpipe and softpipe in the same run (scripts/bench.sh):
//
//   bench_glsl_lights    per-pixel lighting, four point lights, four full-screen layers (ALU)
//   bench_glsl_texture   four lookups from two mipmapped textures per fragment (texture units)
//   bench_glsl_vertex    a 300k-triangle mesh through a vertex shader with matrix products and a
//                        sin-based displacement, trivial fragment shader (vertex stage)
//   bench_glsl_game      a game-like frame: 50 objects with their own uniforms, two programs
//                        switched between draws, a textured ground, depth test (many small draws)
//   bench_glsl_branches  loops and branches whose trip counts and paths differ from pixel to
//                        pixel, so every block runs with partial execution masks
//
// and two time-against-error families for scripts/sweep.sh (sweep_glsllight_*: fewer lights, pow
// by squaring; sweep_glsltex_*: the minification filters of both textures).
//
// A real application compiles its programs once, so the programs and textures are made by the
// first frame of the process (the runner's untimed first render) and kept: the timed frames
// measure drawing only, not glslang's or LLVM's compile time. Each runner process draws one
// scene in one context, so the names stay valid.
#include "bench_geometry.h"
#include "glsl_util.h"
#include "scene_util.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

using namespace scenes;
using scenes::glsl::GL2;

namespace {

// The GL 2.0 entry points the conformance scenes' GL2 lacks.
struct Gl : GL2 {
  PFNGLUNIFORM3FVPROC Uniform3fv = proc<PFNGLUNIFORM3FVPROC>("glUniform3fv");
  PFNGLUNIFORMMATRIX4FVPROC UniformMatrix4fv =
      proc<PFNGLUNIFORMMATRIX4FVPROC>("glUniformMatrix4fv");
};

Gl& gl() {
  static Gl g;
  return g;
}

// ---- column-major 4x4 matrices (as glUniformMatrix4fv takes them with transpose FALSE) ----

using Mat4 = std::array<float, 16>;

Mat4 identity() {
  return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
}

Mat4 mul(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row) {
      float s = 0;
      for (int k = 0; k < 4; ++k)
        s += a[static_cast<size_t>(k * 4 + row)] * b[static_cast<size_t>(c * 4 + k)];
      r[static_cast<size_t>(c * 4 + row)] = s;
    }
  return r;
}

Mat4 translate(float x, float y, float z) {
  Mat4 m = identity();
  m[12] = x;
  m[13] = y;
  m[14] = z;
  return m;
}

Mat4 scale(float s) {
  Mat4 m = identity();
  m[0] = m[5] = m[10] = s;
  return m;
}

// Rotation by `deg` degrees about the unit axis (x, y, z), as glRotatef.
Mat4 rotate(float deg, float x, float y, float z) {
  const float len = std::sqrt(x * x + y * y + z * z);
  x /= len;
  y /= len;
  z /= len;
  const float a = deg * kPi / 180.0f, c = std::cos(a), s = std::sin(a), t = 1 - c;
  return {t * x * x + c,
          t * x * y + s * z,
          t * x * z - s * y,
          0,
          t * x * y - s * z,
          t * y * y + c,
          t * y * z + s * x,
          0,
          t * x * z + s * y,
          t * y * z - s * x,
          t * z * z + c,
          0,
          0,
          0,
          0,
          1};
}

// glFrustum with the vertical half-angle tangent `fovy_tan`.
Mat4 frustum(float fovy_tan, float aspect, float n, float f) {
  const float t = fovy_tan * n, r = t * aspect;
  return {n / r, 0, 0, 0, 0, n / t, 0, 0, 0, 0, -(f + n) / (f - n), -1, 0, 0, -2 * f * n / (f - n),
          0};
}

float aspect_of(const Frame& frame) {
  return static_cast<float>(frame.width) / static_cast<float>(frame.height);
}

// ---- textures ----

// A mipmapped RGBA texture from a function of (x, y, level, size); every level is given
// explicitly (no GENERATE_MIPMAP), repeating, LINEAR magnification.
template <typename Texel> GLuint make_texture(int size, Texel texel) {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  std::vector<unsigned char> data;
  for (int level = 0, s = size; s >= 1; ++level, s /= 2) {
    data.assign(static_cast<size_t>(s * s * 4), 0);
    for (int y = 0; y < s; ++y)
      for (int x = 0; x < s; ++x)
        texel(&data[static_cast<size_t>((y * s + x) * 4)], x, y, level, s);
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, s, s, 0, GL_RGBA, GL_UNSIGNED_BYTE, data.data());
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  return tex;
}

// 256x256 checkerboard with gradients; the colours change from level to level, so the choice
// of levels shows in the image (as the sweep's textured family).
GLuint albedo_texture() {
  return make_texture(256, [](unsigned char* p, int x, int y, int level, int s) {
    const bool check = ((x * 8 / s) + (y * 8 / s)) % 2 == 0;
    p[0] = static_cast<unsigned char>(check ? 230 : 40 + 20 * level);
    p[1] = static_cast<unsigned char>((x * 255) / s);
    p[2] = static_cast<unsigned char>(check ? 60 : (y * 255) / s);
    p[3] = 255;
  });
}

// 128x128 stripes and rings: a detail texture with high frequencies.
GLuint detail_texture() {
  return make_texture(128, [](unsigned char* p, int x, int y, int level, int s) {
    const int dx = x - s / 2, dy = y - s / 2;
    const int ring = ((dx * dx + dy * dy) * 16 / (s * s)) % 2;
    p[0] = static_cast<unsigned char>(ring ? 200 : 90);
    p[1] = static_cast<unsigned char>(((x + y) * 4 / s) % 2 ? 180 : 70 + 15 * level);
    p[2] = static_cast<unsigned char>((x * 7 + y * 3) % 256);
    p[3] = 255;
  });
}

// ---- bench_glsl_lights and the sweep_glsllight family ----

// `lights` point lights; pow_squaring: the specular power 32 by five squarings instead of pow().
GLuint lights_program(int lights, bool pow_squaring) {
  const std::string fs =
      "#define LIGHTS " + std::to_string(lights) +
      "\n"
      "uniform vec3 light_pos[4];\n"
      "uniform vec3 light_color[4];\n"
      "uniform vec3 albedo;\n"
      "uniform float layer;\n"
      "varying vec3 pos;\n"
      "void main() {\n"
      "  vec2 p = pos.xy;\n"
      "  vec3 n = normalize(vec3(0.35 * sin(p.x * 9.0 + layer) * cos(p.y * 7.0),\n"
      "                          0.35 * cos(p.x * 5.0 - p.y * 8.0 + layer), 1.0));\n"
      "  vec3 v = normalize(-pos);\n"
      "  vec3 c = albedo * 0.08;\n"
      "  for (int i = 0; i < LIGHTS; ++i) {\n"
      "    vec3 l = light_pos[i] - pos;\n"
      "    float d2 = dot(l, l);\n"
      "    l *= inversesqrt(d2);\n"
      "    float diffuse = max(dot(n, l), 0.0);\n"
      "    vec3 h = normalize(l + v);\n"
      "    float nh = max(dot(n, h), 0.0);\n" +
      (pow_squaring ? "    float s2 = nh * nh; float s4 = s2 * s2; float s8 = s4 * s4;\n"
                      "    float s16 = s8 * s8; float spec = s16 * s16;\n"
                    : "    float spec = pow(nh, 32.0);\n") +
      "    float att = 1.0 / (1.0 + 0.15 * d2);\n"
      "    c += (albedo * diffuse + vec3(spec)) * light_color[i] * att;\n"
      "  }\n"
      "  gl_FragColor = vec4(c, 0.5);\n"
      "}\n";
  // Full-window quads given in clip coordinates; the eye-space position spans the view.
  const GLuint p = gl().program("uniform float aspect;\n"
                                "uniform float layer;\n"
                                "varying vec3 pos;\n"
                                "void main() {\n"
                                "  gl_Position = vec4(gl_Vertex.xy, 0.0, 1.0);\n"
                                "  pos = vec3(gl_Vertex.x * aspect, gl_Vertex.y, -2.0 - 0.25 * "
                                "layer);\n"
                                "}\n",
                                fs.c_str());
  // The lights are brighter when fewer are used, so every variant has about the same exposure.
  const float k = 2.0f / static_cast<float>(lights);
  const float pos[12] = {-1.2f, 0.8f,  -0.8f, 1.1f, 0.7f,  -1.2f,
                         -0.6f, -0.9f, -1.5f, 0.9f, -0.5f, -0.6f};
  const float base[12] = {0.9f, 0.7f, 0.5f, 0.4f, 0.6f, 1.0f, 0.8f, 0.3f, 0.6f, 0.5f, 0.9f, 0.6f};
  float col[12];
  for (int i = 0; i < 12; ++i)
    col[i] = base[i] * k;
  gl().Uniform3fv(gl().loc(p, "light_pos"), 4, pos);
  gl().Uniform3fv(gl().loc(p, "light_color"), 4, col);
  return p;
}

void draw_lights(const Frame& frame, GLuint p) {
  Gl& g = gl();
  clear_frame(0.02f, 0.02f, 0.05f);
  g.UseProgram(p);
  g.Uniform1f(g.loc(p, "aspect"), aspect_of(frame));
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int layer = 0; layer < 4; ++layer) {
    g.Uniform1f(g.loc(p, "layer"), static_cast<float>(layer));
    const float* c = palette(layer * 5 + 2);
    g.Uniform3f(g.loc(p, "albedo"), 0.4f + 0.6f * c[0], 0.4f + 0.6f * c[1], 0.4f + 0.6f * c[2]);
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
  }
  glDisable(GL_BLEND);
  g.UseProgram(0);
}

template <int Lights, bool PowSquaring> void lights_scene(const Frame& frame) {
  static const GLuint p = lights_program(Lights, PowSquaring);
  draw_lights(frame, p);
}

// ---- bench_glsl_texture and the sweep_glsltex family ----

struct TextureScene {
  GLuint albedo, detail, program;
};

TextureScene texture_scene_setup(GLint min_filter) {
  Gl& g = gl();
  TextureScene s{};
  g.ActiveTexture(GL_TEXTURE1);
  s.detail = detail_texture();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min_filter);
  g.ActiveTexture(GL_TEXTURE0);
  s.albedo = albedo_texture();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min_filter);
  // The scale grows with y, so the level of detail changes over the window; the last lookup
  // depends on the first one's result.
  s.program = g.program("varying vec2 uv;\n"
                        "void main() {\n"
                        "  gl_Position = vec4(gl_Vertex.xy, 0.0, 1.0);\n"
                        "  uv = gl_Vertex.xy * 0.5 + 0.5;\n"
                        "}\n",
                        "uniform sampler2D albedo;\n"
                        "uniform sampler2D detail;\n"
                        "uniform vec2 offset;\n"
                        "varying vec2 uv;\n"
                        "void main() {\n"
                        "  vec2 w = uv * (1.0 + 0.6 * uv.y) + offset;\n"
                        "  vec4 a = texture2D(albedo, w * 2.0);\n"
                        "  vec4 b = texture2D(albedo, vec2(w.y, -w.x) * 5.0 + 0.3);\n"
                        "  vec4 c = texture2D(detail, w * 9.0);\n"
                        "  vec4 d = texture2D(detail, (w + a.rg * 0.05) * 3.0);\n"
                        "  gl_FragColor = vec4(mix(a.rgb, b.rgb, 0.4) * (0.5 + c.rgb) * 0.8 +\n"
                        "                      d.rgb * 0.2, 0.5);\n"
                        "}\n");
  g.Uniform1i(g.loc(s.program, "albedo"), 0);
  g.Uniform1i(g.loc(s.program, "detail"), 1);
  return s;
}

void draw_texture_scene(const TextureScene& s) {
  Gl& g = gl();
  clear_frame(0, 0, 0);
  g.ActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, s.detail);
  g.ActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, s.albedo);
  g.UseProgram(s.program);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int layer = 0; layer < 3; ++layer) {
    g.Uniform2f(g.loc(s.program, "offset"), 0.37f * static_cast<float>(layer),
                0.21f * static_cast<float>(layer));
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
  }
  glDisable(GL_BLEND);
  g.UseProgram(0);
  g.ActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, 0);
  g.ActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, 0);
}

template <GLint MinFilter> void texture_scene(const Frame&) {
  static const TextureScene s = texture_scene_setup(MinFilter);
  draw_texture_scene(s);
}

// ---- meshes with positions, normals and texture coordinates (x y z nx ny nz u v) ----

struct UvMesh {
  std::vector<float> vnt;
  std::vector<unsigned> indices;
};

UvMesh uv_torus(int rings, int sides, float major, float minor) {
  const bench::Mesh m = bench::torus(rings, sides, major, minor);
  UvMesh r;
  r.indices = m.indices;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= sides; ++j) {
      const float* p = &m.vn[static_cast<size_t>((i * (sides + 1) + j) * 6)];
      r.vnt.insert(r.vnt.end(), p, p + 6);
      r.vnt.push_back(static_cast<float>(i) / static_cast<float>(rings) * 4.0f);
      r.vnt.push_back(static_cast<float>(j) / static_cast<float>(sides));
    }
  return r;
}

// An n x n grid over [-size, size]^2 in the plane y = 0, normal up, uv in [0, 1]^2.
UvMesh ground_grid(int n, float size) {
  UvMesh r;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(n);
      const float v = static_cast<float>(j) / static_cast<float>(n);
      r.vnt.insert(r.vnt.end(), {size * (2 * u - 1), 0, size * (1 - 2 * v), 0, 1, 0, u, v});
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const unsigned a = static_cast<unsigned>(j * (n + 1) + i), b = a + 1;
      const unsigned c = a + static_cast<unsigned>(n + 1), d = c + 1;
      r.indices.insert(r.indices.end(), {a, b, d, a, d, c});
    }
  return r;
}

// Generic attributes 0 (position), 1 (normal) and 2 (uv) from the mesh's arrays.
void bind_mesh(const UvMesh& m) {
  Gl& g = gl();
  const GLsizei stride = 8 * sizeof(float);
  g.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, m.vnt.data());
  g.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, m.vnt.data() + 3);
  g.VertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride, m.vnt.data() + 6);
}

void draw_mesh(const UvMesh& m) {
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(m.indices.size()), GL_UNSIGNED_INT,
                 m.indices.data());
}

// ---- bench_glsl_vertex ----

struct VertexScene {
  bench::Mesh mesh;
  GLuint program;
};

VertexScene vertex_scene_setup() {
  Gl& g = gl();
  VertexScene s{bench::torus(500, 300, 1.0f, 0.35f), 0}; // 300k triangles
  s.program =
      g.program("uniform mat4 model;\n"
                "uniform mat4 view;\n"
                "uniform mat4 projection;\n"
                "uniform float phase;\n"
                "attribute vec3 position;\n"
                "attribute vec3 normal;\n"
                "varying vec3 color;\n"
                "void main() {\n"
                "  float s = sin(position.x * 6.0 + phase) * sin(position.y * 5.0) *\n"
                "            cos(position.z * 7.0);\n"
                "  vec3 p = position + normal * (0.06 * s);\n"
                "  vec4 world = model * vec4(p, 1.0);\n"
                "  gl_Position = projection * (view * world);\n"
                "  vec3 n = normalize((view * (model * vec4(normal, 0.0))).xyz);\n"
                "  vec3 l = normalize(vec3(0.5, 1.0, 2.0));\n"
                "  float d = max(dot(n, l), 0.0);\n"
                "  float r = pow(max(reflect(-l, n).z, 0.0), 16.0);\n"
                "  color = vec3(0.15, 0.12, 0.1) + vec3(0.8, 0.6, 0.3) * d + vec3(r) + 0.2 * s;\n"
                "}\n",
                "varying vec3 color;\n"
                "void main() { gl_FragColor = vec4(color, 1.0); }\n",
                {{0, "position"}, {1, "normal"}});
  return s;
}

// ---- bench_glsl_game ----

struct GameScene {
  UvMesh ground, ring, bulb;
  GLuint texture, lit, textured;
};

// Two programs sharing the vertex shader: `lit` shades with a uniform colour and a specular
// highlight, `textured` with a texture, a uniform tint and distance fog.
const char* kGameVs = "uniform mat4 view_projection;\n"
                      "uniform mat4 model;\n"
                      "attribute vec3 position;\n"
                      "attribute vec3 normal;\n"
                      "attribute vec2 uv;\n"
                      "varying vec3 world_normal;\n"
                      "varying vec3 world_pos;\n"
                      "varying vec2 tc;\n"
                      "void main() {\n"
                      "  vec4 w = model * vec4(position, 1.0);\n"
                      "  world_pos = w.xyz;\n"
                      "  world_normal = (model * vec4(normal, 0.0)).xyz;\n"
                      "  tc = uv;\n"
                      "  gl_Position = view_projection * w;\n"
                      "}\n";

GameScene game_scene_setup(const Frame& frame) {
  Gl& g = gl();
  GameScene s{ground_grid(16, 20.0f),
              uv_torus(24, 12, 0.6f, 0.22f),
              uv_torus(16, 16, 0.35f, 0.3f),
              albedo_texture(),
              0,
              0};
  const Mat4 view_projection = mul(frustum(0.55f, aspect_of(frame), 0.5f, 60.0f),
                                   mul(rotate(22, 1, 0, 0), translate(0, -3.5f, -6.0f)));
  const float light[3] = {0.36f, 0.8f, 0.48f}; // unit length
  const std::initializer_list<std::pair<GLuint, const char*>> attribs = {
      {0, "position"}, {1, "normal"}, {2, "uv"}};
  s.lit = g.program(kGameVs,
                    "uniform vec4 color;\n"
                    "uniform vec3 light;\n"
                    "uniform vec3 eye;\n"
                    "varying vec3 world_normal;\n"
                    "varying vec3 world_pos;\n"
                    "void main() {\n"
                    "  vec3 n = normalize(world_normal);\n"
                    "  vec3 h = normalize(light + normalize(eye - world_pos));\n"
                    "  float d = max(dot(n, light), 0.0);\n"
                    "  float sp = pow(max(dot(n, h), 0.0), 24.0);\n"
                    "  gl_FragColor = vec4(color.rgb * (0.2 + 0.8 * d) + vec3(0.5 * sp), 1.0);\n"
                    "}\n",
                    attribs);
  g.UniformMatrix4fv(g.loc(s.lit, "view_projection"), 1, GL_FALSE, view_projection.data());
  g.Uniform3fv(g.loc(s.lit, "light"), 1, light);
  g.Uniform3f(g.loc(s.lit, "eye"), 0, 3.5f, 6.0f);
  s.textured = g.program(kGameVs,
                         "uniform sampler2D tex;\n"
                         "uniform vec4 color;\n"
                         "uniform vec3 light;\n"
                         "uniform vec3 eye;\n"
                         "uniform float tiles;\n"
                         "varying vec3 world_normal;\n"
                         "varying vec3 world_pos;\n"
                         "varying vec2 tc;\n"
                         "void main() {\n"
                         "  vec3 n = normalize(world_normal);\n"
                         "  float d = max(dot(n, light), 0.0);\n"
                         "  vec3 t = texture2D(tex, tc * tiles).rgb * color.rgb;\n"
                         "  float fog = exp(-0.04 * distance(eye, world_pos));\n"
                         "  gl_FragColor = vec4(mix(vec3(0.5, 0.6, 0.7), t * (0.3 + 0.7 * d), "
                         "fog), 1.0);\n"
                         "}\n",
                         attribs);
  g.UniformMatrix4fv(g.loc(s.textured, "view_projection"), 1, GL_FALSE, view_projection.data());
  g.Uniform3fv(g.loc(s.textured, "light"), 1, light);
  g.Uniform3f(g.loc(s.textured, "eye"), 0, 3.5f, 6.0f);
  g.Uniform1i(g.loc(s.textured, "tex"), 0);
  return s;
}

void draw_game(const Frame& frame) {
  static const GameScene s = game_scene_setup(frame);
  Gl& g = gl();
  clear_frame(0.5f, 0.6f, 0.7f);
  glEnable(GL_DEPTH_TEST);
  glBindTexture(GL_TEXTURE_2D, s.texture);
  for (GLuint a = 0; a < 3; ++a)
    g.EnableVertexAttribArray(a);
  // The ground.
  g.UseProgram(s.textured);
  g.UniformMatrix4fv(g.loc(s.textured, "model"), 1, GL_FALSE, identity().data());
  g.Uniform4f(g.loc(s.textured, "color"), 1, 1, 1, 1);
  g.Uniform1f(g.loc(s.textured, "tiles"), 12.0f);
  bind_mesh(s.ground);
  draw_mesh(s.ground);
  // 50 objects in five rows, alternating programs and meshes; every draw sets its own uniforms.
  Rng rng(23);
  const GLuint programs[2] = {s.lit, s.textured};
  for (int i = 0; i < 50; ++i) {
    const GLuint p = programs[i % 2];
    const UvMesh& m = (i / 2) % 2 ? s.bulb : s.ring;
    const float x = -9.0f + 2.0f * static_cast<float>(i % 10),
                z = -2.5f * static_cast<float>(i / 10);
    const Mat4 model = mul(translate(x + rng.range(-0.4f, 0.4f), 0.7f, z + rng.range(-0.4f, 0.4f)),
                           mul(rotate(rng.range(0, 360), rng.range(-1, 1), 1, rng.range(-1, 1)),
                               scale(rng.range(0.7f, 1.2f))));
    const float* c = palette(i * 7);
    g.UseProgram(p);
    g.UniformMatrix4fv(g.loc(p, "model"), 1, GL_FALSE, model.data());
    g.Uniform4f(g.loc(p, "color"), c[0], c[1], c[2], 1);
    if (p == s.textured) g.Uniform1f(g.loc(p, "tiles"), 2.0f);
    bind_mesh(m);
    draw_mesh(m);
  }
  for (GLuint a = 0; a < 3; ++a)
    g.DisableVertexAttribArray(a);
  g.UseProgram(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glDisable(GL_DEPTH_TEST);
}

// ---- bench_glsl_branches ----

// Everything that decides a branch or a trip count is exact in binary floating point (integers
// below 2^24, multiples of powers of two), so every implementation takes the same paths: a
// per-pixel trip count, a three-way branch inside the loop with continue and break, and a
// Collatz sequence whose length (0 to 118 steps) changes from pixel to pixel.
GLuint branches_program() {
  return gl().program(
      "void main() { gl_Position = vec4(gl_Vertex.xy, 0.0, 1.0); }\n",
      "void main() {\n"
      "  vec2 f = floor(gl_FragCoord.xy);\n"
      "  float k = floor(fract(f.x * 0.0625 + f.y * 0.140625) * 32.0);\n"
      "  int n = int(k) + 4;\n"
      "  float a = 0.0, b = 0.0;\n"
      "  for (int i = 0; i < 40; ++i) {\n"
      "    if (i >= n) break;\n"
      "    float fi = float(i);\n"
      "    if (fract((fi + f.x) * 0.25) == 0.0) {\n"
      "      a += sin(fi * 0.37 + f.y * 0.01);\n"
      "    } else if (fract(fi * 0.5) == 0.0) {\n"
      "      b += cos(fi * 0.21 + f.x * 0.013);\n"
      "    } else {\n"
      "      a -= 0.1 * b;\n"
      "      continue;\n"
      "    }\n"
      "    b += 0.05;\n"
      "  }\n"
      "  float z = floor(fract(f.x * 0.0078125 + f.y * 0.01953125) * 128.0) + 1.0;\n"
      "  int steps = 0;\n"
      "  while (z != 1.0) {\n"
      "    if (fract(z * 0.5) == 0.0) z *= 0.5;\n"
      "    else z = 3.0 * z + 1.0;\n"
      "    ++steps;\n"
      "  }\n"
      "  gl_FragColor = vec4(0.5 + 0.1 * a, 0.3 + 0.05 * b, float(steps) / 120.0, 1.0);\n"
      "}\n");
}

} // namespace

PINEDA_SCENE(bench_glsl_lights,
             "GLSL per-pixel lighting: four point lights (Blinn-Phong, attenuation, procedural "
             "normals) on four blended full-screen layers, 640x480",
             .width = 640, .height = 480, .gl_version = "2.1") {
  lights_scene<4, false>(frame);
}

PINEDA_SCENE(bench_glsl_texture,
             "GLSL texturing: four trilinear lookups (one dependent) from two mipmapped textures "
             "per fragment, three blended full-screen quads, 640x480",
             .width = 640, .height = 480, .gl_version = "2.1") {
  texture_scene<GL_LINEAR_MIPMAP_LINEAR>(frame);
}

PINEDA_SCENE(bench_glsl_vertex,
             "GLSL vertex stage: 300k-triangle torus from generic attribute arrays, vertex shader "
             "with four matrix products, sin displacement and per-vertex lighting, depth test, "
             "640x480",
             .width = 640, .height = 480, .gl_version = "2.1") {
  static const VertexScene s = vertex_scene_setup();
  Gl& g = gl();
  clear_frame(0.05f, 0.05f, 0.1f);
  glEnable(GL_DEPTH_TEST);
  g.UseProgram(s.program);
  const Mat4 projection = frustum(0.5f, aspect_of(frame), 1.0f, 20.0f);
  const Mat4 view = translate(0, 0, -4.5f);
  const Mat4 model = rotate(35, 1, 0.4f, 0);
  g.UniformMatrix4fv(g.loc(s.program, "projection"), 1, GL_FALSE, projection.data());
  g.UniformMatrix4fv(g.loc(s.program, "view"), 1, GL_FALSE, view.data());
  g.UniformMatrix4fv(g.loc(s.program, "model"), 1, GL_FALSE, model.data());
  g.Uniform1f(g.loc(s.program, "phase"), 0.7f);
  g.EnableVertexAttribArray(0);
  g.EnableVertexAttribArray(1);
  g.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), s.mesh.vn.data());
  g.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), s.mesh.vn.data() + 3);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(s.mesh.indices.size()), GL_UNSIGNED_INT,
                 s.mesh.indices.data());
  g.DisableVertexAttribArray(0);
  g.DisableVertexAttribArray(1);
  g.UseProgram(0);
  glDisable(GL_DEPTH_TEST);
}

PINEDA_SCENE(bench_glsl_game,
             "GLSL game-like frame: textured ground and 50 objects (two meshes), each draw with "
             "its own model matrix and colour, two programs switched between draws, depth test, "
             "640x480",
             .width = 640, .height = 480, .gl_version = "2.1") {
  draw_game(frame);
}

PINEDA_SCENE(bench_glsl_branches,
             "GLSL divergent control flow: per-pixel loop trip counts, a three-way branch with "
             "continue and break, a Collatz while loop of 0 to 118 steps, full screen 640x480",
             .width = 640, .height = 480, .gl_version = "2.1") {
  static const GLuint p = branches_program();
  clear_frame(0, 0, 0);
  gl().UseProgram(p);
  glBegin(GL_QUADS);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 1);
  glVertex2f(-1, 1);
  glEnd();
  gl().UseProgram(0);
}

// ---- time against error (scripts/sweep.sh; naming as in sweep_scenes.cpp) ----

namespace {

constexpr SceneOptions kShaderSweepOptions{.width = 640, .height = 480, .gl_version = "2.1"};

const Registrar shader_sweep_variants[] = {
    {"sweep_glsllight_4", "GLSL per-pixel lights: four lights, pow (accurate)", kShaderSweepOptions,
     &lights_scene<4, false>},
    {"sweep_glsllight_sq", "GLSL per-pixel lights: four lights, pow by squaring",
     kShaderSweepOptions, &lights_scene<4, true>},
    {"sweep_glsllight_2", "GLSL per-pixel lights: two lights", kShaderSweepOptions,
     &lights_scene<2, false>},
    {"sweep_glsllight_1", "GLSL per-pixel lights: one light", kShaderSweepOptions,
     &lights_scene<1, false>},
    {"sweep_glsltex_lml", "GLSL texture lookups: LINEAR_MIPMAP_LINEAR (accurate)",
     kShaderSweepOptions, &texture_scene<GL_LINEAR_MIPMAP_LINEAR>},
    {"sweep_glsltex_lmn", "GLSL texture lookups: LINEAR_MIPMAP_NEAREST", kShaderSweepOptions,
     &texture_scene<GL_LINEAR_MIPMAP_NEAREST>},
    {"sweep_glsltex_nml", "GLSL texture lookups: NEAREST_MIPMAP_LINEAR", kShaderSweepOptions,
     &texture_scene<GL_NEAREST_MIPMAP_LINEAR>},
    {"sweep_glsltex_nmn", "GLSL texture lookups: NEAREST_MIPMAP_NEAREST", kShaderSweepOptions,
     &texture_scene<GL_NEAREST_MIPMAP_NEAREST>},
    {"sweep_glsltex_linear", "GLSL texture lookups: LINEAR, no mipmapping", kShaderSweepOptions,
     &texture_scene<GL_LINEAR>},
    {"sweep_glsltex_nearest", "GLSL texture lookups: NEAREST, no mipmapping", kShaderSweepOptions,
     &texture_scene<GL_NEAREST>},
};

} // namespace
