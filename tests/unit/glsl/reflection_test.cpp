// Reflection for glGetActiveUniform/Attrib and glGetUniformLocation (GL 2.1 §2.15.3): names
// ("[0]" for arrays, struct members expanded), GL types, sizes (highest element used plus
// one), locations per array element, built-in uniform state, attribute locations with
// glBindAttribLocation's bindings, and uniform initializers.
#include <gtest/gtest.h>

#include <bit>
#include <map>

#include "support/lanes.h"

namespace pineda::glsl_test {
namespace {

std::unique_ptr<glsl::Program> link(const std::string& v, const std::string& f,
                                    const std::vector<glsl::AttribBinding>& bindings = {}) {
  std::vector<std::shared_ptr<const glsl::Shader>> s;
  if (!v.empty()) s.push_back(glsl::Shader::compile(glsl::ShaderStage::Vertex, {v}));
  if (!f.empty()) s.push_back(glsl::Shader::compile(glsl::ShaderStage::Fragment, {f}));
  auto p = glsl::Program::link(s, bindings);
  EXPECT_TRUE(p->linked()) << p->info_log();
  return p;
}

std::map<std::string, glsl::ActiveUniform> by_name(const glsl::Program& p) {
  std::map<std::string, glsl::ActiveUniform> m;
  for (const auto& u : p.uniforms())
    m[u.name] = u;
  return m;
}

TEST(GlslReflection, UniformsNamesTypesSizes) {
  auto p = link("", "#version 120\n"
                    "struct Light { vec3 color; float power[3]; };\n"
                    "uniform Light lights[2];\n"
                    "uniform mat2x3 m;\n"
                    "uniform bvec3 flags;\n"
                    "uniform float weights[8];\n"
                    "uniform sampler2DShadow sh;\n"
                    "uniform vec4 unused;\n"
                    "void main() {\n"
                    "  float w = weights[0] + weights[5];\n"
                    "  vec3 c = lights[1].color * lights[0].power[2] + m[1] * w;\n"
                    "  if (flags.y) c += vec3(shadow2D(sh, c).x);\n"
                    "  gl_FragColor = vec4(c, 1.0);\n"
                    "}\n");
  const auto u = by_name(*p);
  ASSERT_TRUE(u.count("weights[0]"));
  EXPECT_EQ(u.at("weights[0]").type, static_cast<GLenum>(GL_FLOAT));
  EXPECT_EQ(u.at("weights[0]").size, 6); // elements 0..5 used
  ASSERT_TRUE(u.count("lights[1].color"));
  EXPECT_EQ(u.at("lights[1].color").type, static_cast<GLenum>(GL_FLOAT_VEC3));
  ASSERT_TRUE(u.count("lights[0].power[0]"));
  EXPECT_EQ(u.at("lights[0].power[0]").size, 3);
  EXPECT_FALSE(u.count("lights[0].color")); // never read
  ASSERT_TRUE(u.count("m"));
  EXPECT_EQ(u.at("m").type, static_cast<GLenum>(GL_FLOAT_MAT2x3));
  ASSERT_TRUE(u.count("flags"));
  EXPECT_EQ(u.at("flags").type, static_cast<GLenum>(GL_BOOL_VEC3));
  ASSERT_TRUE(u.count("sh"));
  EXPECT_EQ(u.at("sh").type, static_cast<GLenum>(GL_SAMPLER_2D_SHADOW));
  EXPECT_FALSE(u.count("unused"));
  // Locations: one per array element; "name" and "name[0]" are the first.
  const int w0 = p->uniform_location("weights[0]");
  EXPECT_GE(w0, 0);
  EXPECT_EQ(p->uniform_location("weights"), w0);
  EXPECT_EQ(p->uniform_location("weights[5]"), w0 + 5);
  EXPECT_EQ(p->uniform_location("weights[6]"), -1); // beyond the active size
  EXPECT_EQ(p->uniform_location("m[0]"), -1);       // not an array
  EXPECT_EQ(p->uniform_location("lights[0].power[2]"), p->uniform_location("lights[0].power") + 2);
  EXPECT_EQ(p->uniform_location("lights[1]"), -1); // a struct is not a valid name
  EXPECT_EQ(p->uniform_location("gl_ModelViewMatrix"), -1);
  // Each location writes its element's words.
  const auto& loc = p->locations()[static_cast<size_t>(p->uniform_location("weights[5]"))];
  EXPECT_EQ(loc.word, u.at("weights[0]").word + 5);
  EXPECT_EQ(p->max_uniform_name_length(), std::string("lights[0].power[0]").size() + 1);
}

TEST(GlslReflection, BuiltinUniformState) {
  auto p = link("void main() { gl_Position = ftransform();\n"
                "  gl_FrontColor = gl_LightSource[1].diffuse * gl_FrontMaterial.diffuse; }\n",
                "void main() { gl_FragColor = gl_Color + gl_Fog.color; }\n");
  std::map<std::string, glsl::BuiltinUniform> b;
  for (const auto& x : p->builtin_uniforms())
    b[x.name] = x;
  EXPECT_TRUE(b.count("gl_ModelViewProjectionMatrix"));
  EXPECT_TRUE(b.count("gl_LightSource[1].diffuse"));
  EXPECT_FALSE(b.count("gl_LightSource[0].diffuse"));
  EXPECT_TRUE(b.count("gl_FrontMaterial.diffuse"));
  EXPECT_TRUE(b.count("gl_Fog.color"));
  EXPECT_EQ(b.size(), 4u);
  EXPECT_EQ(b["gl_ModelViewProjectionMatrix"].type, static_cast<GLenum>(GL_FLOAT_MAT4));
  // They are active uniforms too (GL 2.1 §2.15.3), without a location.
  for (const auto& u : p->uniforms())
    EXPECT_EQ(u.location, -1) << u.name;
}

TEST(GlslReflection, AttributeLocations) {
  const std::string v = "attribute vec4 pos;\nattribute mat3 basis;\nattribute vec2 uv;\n"
                        "attribute float unused;\nvarying vec4 c;\n"
                        "void main() { c = vec4(basis * pos.xyz, uv.x) + gl_Color;\n"
                        "  gl_Position = gl_Vertex + pos; }\n";
  const std::string f = "varying vec4 c;\nvoid main() { gl_FragColor = c; }\n";
  auto p = link(v, f, {{"uv", 3}});
  EXPECT_EQ(p->attrib_location("uv"), 3);
  // gl_Vertex aliases generic attribute 0, so the automatic locations start at 1; the mat3
  // takes three consecutive ones.
  const int pos = p->attrib_location("pos"), basis = p->attrib_location("basis");
  EXPECT_GE(pos, 1);
  EXPECT_GE(basis, 1);
  EXPECT_TRUE(basis + 3 <= 3 || basis >= 4);
  EXPECT_NE(pos, 3);
  EXPECT_EQ(p->attrib_location("unused"), -1);
  EXPECT_EQ(p->attrib_location("gl_Vertex"), -1);
  std::map<std::string, glsl::ActiveAttrib> a;
  for (const auto& x : p->attribs())
    a[x.name] = x;
  EXPECT_EQ(a.at("basis").type, static_cast<GLenum>(GL_FLOAT_MAT3));
  EXPECT_TRUE(a.count("gl_Vertex"));
  EXPECT_TRUE(a.count("gl_Color"));
  EXPECT_FALSE(a.count("unused"));
  // The engine reads the columns of basis from consecutive generic slots.
  const auto& in = p->vertex()->inputs_read();
  for (int col = 0; col < 3; ++col)
    EXPECT_TRUE(std::find(in.begin(), in.end(), (shader::kInGeneric0 + basis + col) * 4) !=
                in.end());
  // A binding that leaves no room for a matrix is a link error.
  std::vector<std::shared_ptr<const glsl::Shader>> s{
      glsl::Shader::compile(glsl::ShaderStage::Vertex, {v}),
      glsl::Shader::compile(glsl::ShaderStage::Fragment, {f})};
  EXPECT_FALSE(glsl::Program::link(s, {{"basis", 14}})->linked());
}

TEST(GlslReflection, UniformInitializers) {
  auto p =
      link("", "#version 120\nuniform float f = 2.5;\nuniform ivec2 i = ivec2(3, -4);\n"
               "uniform bool b = true;\nvoid main() { gl_FragColor = vec4(f, i, float(b)); }\n");
  const auto u = by_name(*p);
  const auto& init = p->initial_uniforms();
  EXPECT_EQ(std::bit_cast<float>(init[static_cast<size_t>(u.at("f").word)]), 2.5f);
  EXPECT_EQ(static_cast<int32_t>(init[static_cast<size_t>(u.at("i").word + 1)]), -4);
  EXPECT_EQ(init[static_cast<size_t>(u.at("b").word)], 1u);
  // And the program computes with them before any glUniform.
  LaneShader sh("#version 120\nuniform float f = 2.5;\nuniform ivec2 i = ivec2(3, -4);\n"
                "uniform bool b = true;\nvoid main() { gl_FragColor = vec4(f, i, float(b)); }\n");
  ASSERT_TRUE(sh.ok()) << sh.log;
  const auto out = sh.run(std::vector<std::array<Vec4, 4>>(4));
  EXPECT_EQ(out[0][0], 2.5f);
  EXPECT_EQ(out[0][1], 3.0f);
  EXPECT_EQ(out[0][2], -4.0f);
  EXPECT_EQ(out[0][3], 1.0f);
}

} // namespace
} // namespace pineda::glsl_test
