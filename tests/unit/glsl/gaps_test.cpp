// Where glslang 12 differs from GLSL 1.10/1.20, and Pineda's own handling closes the gap (one
// test each; the first half were verified against glslang 12 on its own before being fixed).
#include <gtest/gtest.h>

#include "support/lanes.h"

namespace pineda::glsl_test {
namespace {

std::shared_ptr<glsl::Shader> vs(const std::string& s) {
  return glsl::Shader::compile(glsl::ShaderStage::Vertex, {s});
}
std::shared_ptr<glsl::Shader> fs(const std::string& s) {
  return glsl::Shader::compile(glsl::ShaderStage::Fragment, {s});
}
std::unique_ptr<glsl::Program> link(std::vector<std::shared_ptr<const glsl::Shader>> s) {
  return glsl::Program::link(s, {});
}

// glslang refuses texture*Lod in vertex shaders without GL_ARB_shader_texture_lod, though
// they are core GLSL 1.10 vertex functions.
TEST(GlslangGaps, TextureLodInVertexShaders) {
  auto v = vs("uniform sampler2D s;\nvoid main() { gl_Position = texture2DLod(s, vec2(0.5), 1.0)"
              " + texture2DProjLod(s, vec3(0.5), 0.0) + textureCubeLod(sc, vec3(1.0), 0.0); }\n"
              "uniform samplerCube sc;\n");
  EXPECT_FALSE(v->compiled()); // sc used before its declaration: a real error
  v = vs("uniform sampler2D s;\nuniform samplerCube sc;\n"
         "void main() { gl_Position = texture2DLod(s, vec2(0.5), 1.0)"
         " + texture2DProjLod(s, vec3(0.5), 0.0) + textureCubeLod(sc, vec3(1.0), 0.0); }\n");
  EXPECT_TRUE(v->compiled()) << v->info_log();
  // ... and the fragment shader still has no Lod forms (GLSL 1.20 §8.7).
  EXPECT_FALSE(
      fs("uniform sampler2D s;\nvoid main() { gl_FragColor = texture2DLod(s, vec2(0.5), 1.0); }\n")
          ->compiled());
}

// glslang refuses backslash line continuation below GLSL 1.30 unless all its errors are
// relaxed; Pineda joins the lines itself and keeps the line numbers.
TEST(GlslangGaps, LineContinuation) {
  auto f = fs("#define COLOR(x) \\\n  vec4(x, \\\n  0.0, 0.0, 1.0)\nvoid main() { gl_FragColor = "
              "COLOR(1.0); }\n");
  EXPECT_TRUE(f->compiled()) << f->info_log();
  f = fs("#define A \\\n  1.0\nvoid main() {\n  gl_FragColor = vec4(A)\n}\n");
  EXPECT_FALSE(f->compiled());
  EXPECT_NE(f->info_log().find("0:5"), std::string::npos) << f->info_log();
}

// glslang cannot fold matrix built-ins (and folds (v == w) == b wrongly) in array sizes and
// const initializers; Pineda folds them with its own IR.
TEST(GlslangGaps, MatrixConstantFolding) {
  LaneShader sh("#version 120\n"
                "const mat2 m = mat2(1.0, 2.0, 3.0, 4.0);\n"
                "void main() {\n"
                "  float a[int(transpose(m)[0][1])];\n"                            // 3
                "  float b[int(matrixCompMult(m, m)[1][1]) - 10];\n"               // 6
                "  float c[(vec2(1.0, 2.0) == vec2(1.0, 2.0)) == true ? 2 : 1];\n" // 2
                "  const mat2 t = transpose(m);\n"
                "  gl_FragColor = vec4(a.length(), b.length(), c.length(), t[1][0]);\n" // 2
                "}\n");
  ASSERT_TRUE(sh.ok()) << sh.log;
  const auto out = sh.run(std::vector<std::array<Vec4, 4>>(4));
  EXPECT_EQ(out[0][0], 3.0f);
  EXPECT_EQ(out[0][1], 6.0f);
  EXPECT_EQ(out[0][2], 2.0f);
  EXPECT_EQ(out[0][3], 2.0f);
  // An array size of a non-integer type stays an error.
  EXPECT_FALSE(
      fs("#version 120\nvoid main() { float a[int(1.0) + 0.5]; gl_FragColor = vec4(0.0); }\n")
          ->compiled());
  // So does the sequence operator, which is not a constant expression.
  EXPECT_FALSE(
      fs("#version 120\nvoid main() { float a[(1, 2)]; gl_FragColor = vec4(a.length()); }\n")
          ->compiled());
}

// glslang defines a GL_ARB_*/GL_EXT_* macro for every extension it knows; Pineda supports
// none of them, so they read as undefined and requiring one fails.
TEST(GlslangGaps, ExtensionMacros) {
  for (const char* ext : {"GL_ARB_gpu_shader5", "GL_ARB_texture_rectangle", "GL_EXT_gpu_shader4",
                          "GL_ARB_shader_texture_lod", "GL_ARB_separate_shader_objects"}) {
    auto f = fs(std::string("#ifdef ") + ext +
                "\n#error defined\n#endif\nvoid main() { gl_FragColor = vec4(1.0); }\n");
    EXPECT_TRUE(f->compiled()) << ext << ": " << f->info_log();
    f = fs(std::string("#extension ") + ext +
           " : require\nvoid main() { gl_FragColor = vec4(1.0); }\n");
    EXPECT_FALSE(f->compiled()) << ext;
    EXPECT_NE(f->info_log().find(ext), std::string::npos) << f->info_log();
  }
  // Names that merely start the same way are left alone.
  EXPECT_TRUE(fs("#define GL_ARB_gpu_shader5_x 1\nvoid main() { gl_FragColor = vec4(1.0); }\n")
                  ->compiled() == false); // GL_ names are reserved (GLSL 1.10 §3.3)
}

// Writing both gl_FragColor and gl_FragData is a compile error, dead code included (glslang
// only refuses it when linking, and not in dead code).
TEST(GlslangGaps, FragColorAndFragData) {
  EXPECT_FALSE(
      fs("void main() { gl_FragColor = vec4(1.0); gl_FragData[0] = vec4(1.0); }\n")->compiled());
  EXPECT_FALSE(
      fs("void main() { gl_FragColor = vec4(1.0); if (false) gl_FragData[1] = vec4(1.0); }\n")
          ->compiled());
  EXPECT_TRUE(
      fs("void main() { gl_FragData[0] = vec4(1.0); gl_FragData[1] = vec4(0.5); }\n")->compiled());
}

// glslang accepts any number of samplers; GL 2.1 §2.15.4 limits those a program uses.
TEST(GlslangGaps, TooManySamplers) {
  auto f = fs(
      "uniform sampler2D s[20];\nvoid main() {\n  vec4 c = vec4(0.0);\n"
      "  for (int i = 0; i < 20; i++) c += texture2D(s[i], vec2(0.5));\n  gl_FragColor = c;\n}\n");
  ASSERT_TRUE(f->compiled()) << f->info_log();
  auto p = link({f});
  EXPECT_FALSE(p->linked());
  EXPECT_NE(p->info_log().find("too many samplers"), std::string::npos) << p->info_log();
  // Declared but unused samplers do not count.
  f = fs("uniform sampler2D s[20];\nvoid main() { gl_FragColor = texture2D(s[3], vec2(0.5)); }\n");
  EXPECT_TRUE(link({f})->linked());
}

// glslang links two shaders of a stage that initialize the same global differently.
TEST(GlslangGaps, GlobalInitializersAcrossShaders) {
  auto a = vs("float g = 1.0;\nvoid main() { gl_Position = gl_Vertex * g; }\n");
  auto b = vs("float g = 2.0;\nvoid f() {}\n");
  auto c = vs("float g = 1.0;\nvoid f() {}\n");
  auto d = vs("uniform float u;\nfloat g = u * 2.0;\nvoid f() {}\n");
  auto e =
      vs("uniform float u;\nfloat g = u * 2.0;\nvoid main() { gl_Position = gl_Vertex * g; }\n");
  EXPECT_FALSE(link({a, b})->linked());
  EXPECT_TRUE(link({a, c})->linked());  // the same constant: one variable
  EXPECT_FALSE(link({d, e})->linked()); // non-constant initializers in two shaders
  // Uniform initializers must match between the stages too.
  auto v =
      vs("#version 120\nuniform float u = 1.0;\nvoid main() { gl_Position = gl_Vertex * u; }\n");
  auto f = fs("#version 120\nuniform float u = 2.0;\nvoid main() { gl_FragColor = vec4(u); }\n");
  EXPECT_FALSE(link({v, f})->linked());
}

// Found with piglit: glslang accepts gl_TexCoord beyond gl_MaxTextureCoords and samplers as
// out parameters, refuses gl_TexCoord sized differently in the two stages and calls to
// functions without bodies in dead code; none of that is GLSL 1.10.
TEST(GlslangGaps, FoundWithPiglit) {
  EXPECT_FALSE(
      vs("void main() { gl_Position = gl_Vertex; gl_TexCoord[gl_MaxTextureCoords] = vec4(1.0); }\n")
          ->compiled());
  EXPECT_FALSE(fs("struct S { sampler2D t; };\nvoid f(out S s) {}\nvoid main() { gl_FragColor = "
                  "vec4(1.0); }\n")
                   ->compiled());
  auto v = vs("varying vec4 gl_TexCoord[2];\nvoid main() { gl_TexCoord[0] = vec4(1.0); gl_Position "
              "= gl_Vertex; }\n");
  auto f = fs("varying vec4 gl_TexCoord[3];\nvoid main() { gl_FragColor = gl_TexCoord[0]; }\n");
  EXPECT_TRUE(link({v, f})->linked());
  auto g = fs("void missing();\nvoid main() { gl_FragColor = vec4(1.0); if (false) missing(); }\n");
  EXPECT_TRUE(link({g})->linked());
  auto h = fs("void missing();\nuniform bool b;\nvoid main() { gl_FragColor = vec4(1.0); if (b) "
              "missing(); }\n");
  EXPECT_FALSE(link({h})->linked());
}

// Recursion (GLSL 1.10 §6.1) is refused (glslang detects it; the inliner checks it again), and
// a vertex shader must write gl_Position (glslang does not check it; Mesa refuses it below
// GLSL 1.40).
TEST(GlslangGaps, RecursionAndPosition) {
  auto f = fs("float f(float x) { return x > 0.0 ? f(x - 1.0) : 0.0; }\n"
              "void main() { gl_FragColor = vec4(f(3.0)); }\n");
  ASSERT_TRUE(f->compiled()) << f->info_log();
  auto p = link({f});
  EXPECT_FALSE(p->linked());
  EXPECT_NE(p->info_log().find("ecursion"), std::string::npos) << p->info_log();
  EXPECT_FALSE(link({vs("void main() { gl_FrontColor = vec4(1.0); }\n")})->linked());
}

} // namespace
} // namespace pineda::glsl_test
