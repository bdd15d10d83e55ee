// Compiling and linking through the front end: status, logs, reflection.
#include <gtest/gtest.h>

#include "glsl/glsl.h"

namespace pineda::glsl {
namespace {

std::shared_ptr<Shader> vs(const std::string& src) {
  return Shader::compile(ShaderStage::Vertex, {src});
}
std::shared_ptr<Shader> fs(const std::string& src) {
  return Shader::compile(ShaderStage::Fragment, {src});
}

TEST(GlslCompile, SimpleProgramLinks) {
  auto v = vs("uniform mat4 mvp; attribute vec4 pos; varying vec2 uv;\n"
              "void main() { uv = pos.xy; gl_Position = mvp * pos; }\n");
  auto f = fs("uniform vec4 tint; varying vec2 uv;\n"
              "void main() { gl_FragColor = tint * uv.x; }\n");
  ASSERT_TRUE(v->compiled()) << v->info_log();
  ASSERT_TRUE(f->compiled()) << f->info_log();
  Limits l;
  l.keep_ir = true;
  auto p = Program::link({v, f}, {}, l);
  ASSERT_TRUE(p->linked()) << p->info_log();
  EXPECT_GE(p->uniform_location("mvp"), 0);
  EXPECT_GE(p->uniform_location("tint"), 0);
  EXPECT_EQ(p->uniform_location("nope"), -1);
  EXPECT_EQ(p->attrib_location("pos"), 0);
  ASSERT_NE(p->vertex(), nullptr);
  ASSERT_NE(p->fragment(), nullptr);
  std::printf("%s", p->ir_text().c_str());
}

TEST(GlslCompile, ErrorHasLineNumber) {
  auto f = fs("void main() {\n  gl_FragColor = vec4(1.0)\n}\n");
  EXPECT_FALSE(f->compiled());
  EXPECT_NE(f->info_log().find("0:3"), std::string::npos) << f->info_log();
}

} // namespace
} // namespace pineda::glsl
