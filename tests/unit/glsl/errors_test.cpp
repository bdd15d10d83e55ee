// Bad input: compile errors with line numbers in the log, link errors, unsupported versions,
// and random or mangled source, none of which may crash.
#include <gtest/gtest.h>

#include <random>

#include "support/lanes.h"

namespace pineda::glsl_test {
namespace {

std::shared_ptr<glsl::Shader> fs(const std::string& s) {
  return glsl::Shader::compile(glsl::ShaderStage::Fragment, {s});
}
std::shared_ptr<glsl::Shader> vs(const std::string& s) {
  return glsl::Shader::compile(glsl::ShaderStage::Vertex, {s});
}

TEST(GlslErrors, CompileErrorsNameTheLine) {
  struct Case {
    const char* src;
    const char* where;
  };
  const Case cases[] = {
      {"void main() {\n  gl_FragColor = vec4(1.0)\n}\n", "0:3"},     // missing ;
      {"void main() {\n\n  gl_FragColor = undeclared;\n}\n", "0:3"}, // unknown name
      {"void main() {\n  vec3 v = vec4(1.0);\n  gl_FragColor = vec4(v, 1.0);\n}\n", "0:2"},
      {"void main() {\n  float f = 1.0;\n  f.xyz = vec3(1.0);\n}\n", "0:3"}, // bad swizzle
      {"void main() {\n  break;\n}\n", "0:2"},                               // break outside a loop
  };
  for (const Case& c : cases) {
    auto f = fs(c.src);
    EXPECT_FALSE(f->compiled()) << c.src;
    EXPECT_NE(f->info_log().find(std::string("ERROR: ") + c.where), std::string::npos)
        << c.src << "\n"
        << f->info_log();
  }
  // Several strings: the log names the string (GLSL 1.10 §3.2).
  auto f =
      glsl::Shader::compile(glsl::ShaderStage::Fragment,
                            {"uniform vec4 c;\n", "void main() {\n  gl_FragColor = c +;\n}\n"});
  EXPECT_FALSE(f->compiled());
  EXPECT_NE(f->info_log().find("1:2"), std::string::npos) << f->info_log();
}

TEST(GlslErrors, OnlyGlsl110And120) {
  EXPECT_TRUE(fs("#version 110\nvoid main() { gl_FragColor = vec4(1.0); }\n")->compiled());
  EXPECT_TRUE(fs("#version 120\nvoid main() { gl_FragColor = vec4(1.0); }\n")->compiled());
  for (const char* v :
       {"#version 130\n", "#version 100\n", "#version 300 es\n", "#version 150\n"}) {
    auto f = fs(std::string(v) + "void main() { }\n");
    EXPECT_FALSE(f->compiled()) << v;
    EXPECT_FALSE(f->info_log().empty()) << v;
  }
}

// The directive is found as glslang would: after comments, across strings, with the string
// and line it is on in the log; malformed directives are left to glslang.
TEST(GlslErrors, VersionDirectiveCheckedFirst) {
  const char* body = "void main() { gl_FragColor = vec4(1.0); }\n";
  const auto log_of = [](std::vector<std::string> strings) {
    auto f = glsl::Shader::compile(glsl::ShaderStage::Fragment, strings);
    EXPECT_FALSE(f->compiled()) << strings[0];
    return f->info_log();
  };
  EXPECT_NE(log_of({"#version 130\n", body}).find("ERROR: 0:1: '#version' : version 130"),
            std::string::npos);
  EXPECT_NE(log_of({"// a comment\n/* two\nlines */  # version 330 core\n", body})
                .find("ERROR: 0:3: '#version' : version 330 core"),
            std::string::npos);
  EXPECT_NE(log_of({"/* spans ", "strings */\n\n#version 999\n", body})
                .find("ERROR: 1:3: '#version' : version 999"),
            std::string::npos);
  EXPECT_NE(log_of({"#version 120 es\n", body}).find("version 120 es"), std::string::npos);
  EXPECT_FALSE(log_of({"#version\n", body}).empty());
  EXPECT_FALSE(log_of({"#version 1x0\n", body}).empty());
  EXPECT_TRUE(fs(std::string("/* c */ // c\n  #  version 120\n") + body)->compiled());
  EXPECT_TRUE(fs(std::string("#define X 1\n") + body)->compiled());
}

TEST(GlslErrors, LinkErrors) {
  const auto link = [](std::vector<std::shared_ptr<const glsl::Shader>> s) {
    return glsl::Program::link(s, {});
  };
  // No main.
  EXPECT_FALSE(link({fs("void f() {}\n")})->linked());
  // Varyings of different types; a varying read but never written.
  EXPECT_FALSE(
      link({vs("varying vec3 a;\nvoid main() { a = vec3(1.0); gl_Position = gl_Vertex; }\n"),
            fs("varying vec4 a;\nvoid main() { gl_FragColor = a; }\n")})
          ->linked());
  EXPECT_FALSE(link({vs("varying vec4 a;\nvoid main() { gl_Position = gl_Vertex; }\n"),
                     fs("varying vec4 a;\nvoid main() { gl_FragColor = a; }\n")})
                   ->linked());
  // Uniforms of different types in the two stages.
  EXPECT_FALSE(link({vs("uniform vec3 u;\nvoid main() { gl_Position = vec4(u, 1.0); }\n"),
                     fs("uniform vec4 u;\nvoid main() { gl_FragColor = u; }\n")})
                   ->linked());
  // A shader that did not compile.
  EXPECT_FALSE(link({fs("void main() { oops }\n")})->linked());
  // Two main functions in one stage.
  EXPECT_FALSE(link({fs("void main() { gl_FragColor = vec4(1.0); }\n"),
                     fs("void main() { gl_FragColor = vec4(0.0); }\n")})
                   ->linked());
  // Too many varying components for MAX_VARYING_FLOATS.
  EXPECT_FALSE(
      link({vs("varying float a[70];\nvoid main() { for (int i = 0; i < 70; i++) a[i] = 1.0;"
               " gl_Position = gl_Vertex; }\n"),
            fs("varying float a[70];\nvoid main() { float s = 0.0;"
               " for (int i = 0; i < 70; i++) s += a[i]; gl_FragColor = vec4(s); }\n")})
          ->linked());
  // Every failed link says why.
  auto p = link({fs("void f() {}\n")});
  EXPECT_FALSE(p->info_log().empty());
}

// Expressions glslang parses but that are too deep to lower recursively fail the link instead
// of exhausting the stack; a long but reasonable one links.
TEST(GlslErrors, DeepExpressions) {
  const auto shader = [](int terms) {
    std::string s = "void main() { float x = 1.0; gl_FragColor = vec4(x";
    for (int i = 0; i < terms; ++i)
      s += "+x";
    s += "); }\n";
    return s;
  };
  auto f = fs(shader(20000));
  ASSERT_TRUE(f->compiled()) << f->info_log();
  auto p = glsl::Program::link({f}, {});
  EXPECT_FALSE(p->linked());
  EXPECT_NE(p->info_log().find("nested"), std::string::npos) << p->info_log();
  EXPECT_TRUE(glsl::Program::link({fs(shader(1000))}, {})->linked());
}

TEST(GlslErrors, NoShadersIsFixedFunction) {
  auto p = glsl::Program::link({}, {});
  EXPECT_TRUE(p->linked());
  EXPECT_EQ(p->vertex(), nullptr);
  EXPECT_EQ(p->fragment(), nullptr);
}

// Random bytes, random tokens and mangled valid shaders: compile and link never crash (the
// sanitizer build runs this too).
TEST(GlslErrors, GarbageNeverCrashes) {
  std::mt19937 rng(2024);
  const std::string valid =
      "uniform sampler2D s;\nuniform vec4 c[4];\nvarying vec2 uv;\n"
      "float f(float x) { for (int i = 0; i < 3; i++) x = x * 0.5 + c[i].x; return x; }\n"
      "void main() {\n  vec4 t = texture2D(s, uv);\n  if (t.x > 0.5) discard;\n"
      "  gl_FragColor = t * f(uv.y) + c[int(uv.x)];\n}\n";
  const char* tokens[] = {"void",      "main",  "(",      ")",         "{",     "}",
                          ";",         "float", "vec4",   "=",         "+",     "gl_FragColor",
                          "if",        "for",   "while",  "int",       "i",     "[",
                          "]",         "1.0",   "return", "discard",   ".xyzw", "uniform",
                          "#define",   "\\\n",  "#if",    "struct",    "mat3",  "*",
                          "texture2D", ",",     "0",      "sampler2D", "#endif"};
  int compiled = 0;
  for (int iter = 0; iter < 300; ++iter) {
    std::string src;
    if (iter % 3 == 0) {
      std::uniform_int_distribution<int> byte(1, 255), len(0, 200);
      for (int n = len(rng); n > 0; --n)
        src += static_cast<char>(byte(rng));
    } else if (iter % 3 == 1) {
      std::uniform_int_distribution<size_t> tok(0, std::size(tokens) - 1);
      for (int n = 0; n < 60; ++n)
        src += std::string(tokens[tok(rng)]) + " ";
    } else {
      src = valid;
      std::uniform_int_distribution<size_t> pos(0, src.size() - 1);
      std::uniform_int_distribution<int> what(0, 2);
      for (int m = 0; m < 3; ++m) {
        const size_t p = pos(rng) % src.size();
        if (what(rng) == 0)
          src.erase(p, 1);
        else if (what(rng) == 1)
          src.insert(p, tokens[pos(rng) % std::size(tokens)]);
        else
          src[p] = src[pos(rng) % src.size()];
      }
    }
    auto f = fs(src);
    if (f->compiled()) {
      ++compiled;
      auto p = glsl::Program::link({f}, {});
      if (p->linked()) {
        Pipeline pipe(*p);
        std::vector<std::vector<float>> in(
            4, std::vector<float>(shader::kNumFragmentInputs * 4, 0.5f)),
            out;
        pipe.run_fragments(1, in, out);
      }
    } else {
      EXPECT_FALSE(f->info_log().empty());
    }
  }
  RecordProperty("compiled", compiled);
}

} // namespace
} // namespace pineda::glsl_test
