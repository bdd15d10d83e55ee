// The shader IR by hand: building, folding, dead code, and running it on the engine.
#include <gtest/gtest.h>

#include <algorithm>

#include <bit>
#include <cmath>
#include <vector>

#include "shader/engine.h"
#include "shader/ir.h"
#include "shader/ir_passes.h"

namespace pineda::shader {
namespace {

TEST(ShaderIr, FoldsConstants) {
  Function f;
  const ValueId a = f.const_f(2.0f), b = f.const_f(3.0f);
  const ValueId m = f.emit(f.body, Op::Mul, Type::Float, a, b);
  const ValueId s = f.emit(f.body, Op::Sin, Type::Float, m);
  f.emit_imm(f.body, Op::StoreOutput, Type::Float, 0, 0, 0, s);
  optimize(f);
  EXPECT_EQ(verify(f), "");
  ASSERT_EQ(f.body.size(), 1u);
  const Inst& st = f.insts[f.body[0].index];
  ASSERT_TRUE(f.is_const(st.arg[0]));
  EXPECT_NEAR(f.const_float(st.arg[0]), std::sin(6.0), 1e-6);
}

TEST(ShaderIr, RunsOnEngine) {
  Function f;
  const ValueId x = f.input(Type::Float, 0);
  const ValueId u = f.uniform(Type::Float, 0);
  const ValueId m = f.emit(f.body, Op::Mul, Type::Float, x, u);
  const ValueId a = f.emit(f.body, Op::Add, Type::Float, m, f.const_f(1.0f));
  f.emit_imm(f.body, Op::StoreOutput, Type::Float, 0, 0, 0, a);
  optimize(f);
  ASSERT_EQ(verify(f), "");
  std::string err;
  auto exe = Executable::build(f, Stage::Vertex, &err);
  ASSERT_TRUE(exe) << err;
  std::vector<float> in(100), out(100);
  for (int i = 0; i < 100; ++i)
    in[static_cast<size_t>(i)] = static_cast<float>(i);
  const uint32_t uniforms[1] = {std::bit_cast<uint32_t>(0.5f)};
  Prepared p;
  exe->prepare(uniforms, p);
  std::vector<char> scratch(exe->scratch_bytes());
  const float* ins[1] = {in.data()};
  float* outs[1] = {out.data()};
  VertexBatch b;
  b.count = 100;
  b.in = ins;
  b.out = outs;
  exe->run_vertices(p, b, scratch.data());
  for (int i = 0; i < 100; ++i)
    EXPECT_EQ(out[static_cast<size_t>(i)], static_cast<float>(i) * 0.5f + 1.0f);
}

} // namespace
} // namespace pineda::shader

// ---- lowering and passes, through GLSL ----

#include "glsl/glsl.h"
#include "shader/io.h"

namespace pineda::shader {
namespace {

std::unique_ptr<glsl::Program> link_ir(const std::string& vs, const std::string& fs) {
  glsl::Limits l;
  l.keep_ir = true;
  std::vector<std::shared_ptr<const glsl::Shader>> shaders;
  if (!vs.empty()) shaders.push_back(glsl::Shader::compile(glsl::ShaderStage::Vertex, {vs}, l));
  if (!fs.empty()) shaders.push_back(glsl::Shader::compile(glsl::ShaderStage::Fragment, {fs}, l));
  auto p = glsl::Program::link(shaders, {}, l);
  EXPECT_TRUE(p->linked()) << p->info_log();
  return p;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t p = 0; (p = text.find(what, p)) != std::string::npos; p += what.size())
    ++n;
  return n;
}

TEST(ShaderIr, DeadCodeRegionsAndLoopsGo) {
  Function f;
  const ValueId x = f.input(Type::Float, 0);
  // A region and a loop whose results nobody stores.
  const uint32_t ri = f.add_region();
  f.regions[ri].cond = f.emit(f.body, Op::Gt, Type::Bool, x, f.const_f(0.0f));
  const ValueId inner = f.emit(f.regions[ri].body, Op::Sin, Type::Float, x);
  const ValueId phi = f.phi(Type::Float);
  f.regions[ri].outs.push_back({phi, inner, x});
  f.body.push_back({NodeKind::Region, ri});
  const uint32_t li = f.add_loop();
  Loop& l = f.loops[li];
  const ValueId lp = f.phi(Type::Float);
  l.phis.push_back({lp, x, kNoValue});
  const ValueId next = f.emit(l.body, Op::Add, Type::Float, lp, f.const_f(1.0f));
  f.emit(l.body, Op::ExitIfNone, Type::Bool,
         f.emit(l.body, Op::Lt, Type::Bool, next, f.const_f(10.0f)));
  l.phis[0].next = next;
  f.body.push_back({NodeKind::Loop, li});
  f.emit_imm(f.body, Op::StoreOutput, Type::Float, 0, 0, 0, x);
  ASSERT_EQ(verify(f), "");
  optimize(f);
  ASSERT_EQ(verify(f), "");
  EXPECT_EQ(count_insts(f), 1) << print(f);
}

TEST(ShaderIr, CommonSubexpressionsMerge) {
  Function f;
  const ValueId x = f.input(Type::Float, 0), y = f.input(Type::Float, 1);
  const ValueId a = f.emit(f.body, Op::Mul, Type::Float, x, y);
  const ValueId b = f.emit(f.body, Op::Mul, Type::Float, y, x); // commutative
  f.emit_imm(f.body, Op::StoreOutput, Type::Float, 0, 0, 0,
             f.emit(f.body, Op::Add, Type::Float, a, b));
  optimize(f);
  EXPECT_EQ(count_insts(f), 3) << print(f); // one Mul, the Add, the store
}

TEST(ShaderIr, VerifierCatchesUseBeforeDefinition) {
  Function f;
  const ValueId x = f.input(Type::Float, 0);
  Block other;
  const ValueId a = f.emit(other, Op::Neg, Type::Float, x); // never placed in f.body
  f.emit_imm(f.body, Op::StoreOutput, Type::Float, 0, 0, 0, a);
  EXPECT_NE(verify(f), "");
}

TEST(ShaderIr, PrinterShowsStructure) {
  auto p =
      link_ir("", "varying vec4 v0;\nvoid main() {\n"
                  "  vec4 c = v0;\n"
                  "  for (int i = 0; i < int(v0.w); i++) { if (c.x > 1.0) break; c.x += 0.5; }\n"
                  "  gl_FragColor = c;\n}\n");
  const std::string& t = p->ir_text();
  EXPECT_GE(count(t, "loop {"), 1) << t;
  EXPECT_GE(count(t, "ExitIfNone"), 1) << t;
  EXPECT_GE(count(t, "StoreOutput"), 4) << t;
}

TEST(ShaderIr, FunctionsAreInlinedAndConstantsFolded) {
  auto p =
      link_ir("", "float sq(float x) { return x * x; }\n"
                  "float twice(float x) { return sq(x) + sq(x); }\n"
                  "void main() { gl_FragColor = vec4(twice(3.0), sq(2.0) * 0.5, 0.0, 1.0); }\n");
  const std::string& t = p->ir_text();
  // Everything folds to constants: no arithmetic left, the outputs are stored from splats.
  EXPECT_EQ(count(t, "Mul."), 0) << t;
  EXPECT_EQ(count(t, "Add."), 0) << t;
  EXPECT_NE(t.find("const.f 18"), std::string::npos) << t;
}

TEST(ShaderIr, ConstantLoopsUnrollAndIndexUniformsStatically) {
  auto p = link_ir("", "uniform vec4 lights[4];\nvarying vec4 v0;\nvoid main() {\n"
                       "  vec4 s = vec4(0.0);\n"
                       "  for (int i = 0; i < 4; i++) s += lights[i] * v0;\n"
                       "  gl_FragColor = s;\n}\n");
  const std::string& t = p->ir_text();
  EXPECT_EQ(count(t, "loop {"), 0) << t;
  EXPECT_EQ(count(t, "UniformIndexed"), 0) << t;
}

TEST(ShaderIr, DivergentAndUniformBranches) {
  // A varying condition: masked updates (selects); a uniform one: a real branch on a splat.
  auto p = link_ir("", "uniform bool flag;\nvarying vec4 v0;\nvoid main() {\n"
                       "  vec4 c = v0;\n"
                       "  if (v0.x > 0.5) { c = sin(c) * cos(c) + exp(c); c.y += 1.0; }\n"
                       "  if (flag) { c = log(abs(c)) + sqrt(abs(c)) * 3.0; c.z += 2.0; }\n"
                       "  gl_FragColor = c;\n}\n");
  const std::string& t = p->ir_text();
  EXPECT_GE(count(t, "Select."), 4) << t;
  EXPECT_GE(count(t, "JumpIfNoneS"), 1) << t;
  EXPECT_GE(count(t, "JumpIfNone "), 1) << t;
}

TEST(ShaderIr, OnlyWhatIsReadIsComputed) {
  // The fragment shader reads only uv.x: the vertex shader stores only that of its varyings,
  // not `unused`, and no gl_TexCoord; the fragment shader reads one input component; the
  // built-in uniform read only by dead code is not reported.
  auto p = link_ir("attribute vec4 pos;\nvarying vec2 uv;\nvarying vec4 unused;\n"
                   "void main() { uv = pos.xy * 2.0; unused = pos * 3.0;\n"
                   "  gl_TexCoord[0] = pos; gl_Position = gl_ModelViewProjectionMatrix * pos; }\n",
                   "varying vec2 uv;\nvarying vec4 unused;\nvoid main() {\n"
                   "  float f = gl_NormalScale;\n"
                   "  gl_FragColor = vec4(uv.x);\n}\n");
  const auto& outs = p->vertex()->outputs_written();
  EXPECT_EQ(std::count_if(outs.begin(), outs.end(), [](int c) { return c / 4 >= kOutVarying0; }),
            1);
  EXPECT_EQ(std::count_if(outs.begin(), outs.end(), [](int c) { return c / 4 == kOutTexCoord0; }),
            0);
  EXPECT_EQ(p->fragment()->inputs_read().size(), 1u);
  for (const auto& b : p->builtin_uniforms())
    EXPECT_NE(b.name, "gl_NormalScale");
  ASSERT_EQ(p->builtin_uniforms().size(), 1u);
  EXPECT_EQ(p->builtin_uniforms()[0].name, "gl_ModelViewProjectionMatrix");
}

TEST(ShaderIr, FoldedConstantsEqualTheEngine) {
  // eval_lane_op (the folder) and the engine compute the same bits for every lane op.
  Function f;
  const float xs[] = {-3.7f, -1.0f, -0.25f, 0.0f, 0.5f, 1.0f, 2.5f, 100.0f};
  const Op ops[] = {Op::Sin, Op::Cos,  Op::Tan, Op::Atan,  Op::Exp2,  Op::Log2, Op::Exp,
                    Op::Log, Op::Sqrt, Op::Rsq, Op::Floor, Op::Fract, Op::Sign, Op::Abs};
  int out = 0;
  std::vector<uint32_t> folded;
  for (Op op : ops)
    for (float x : xs) {
      Function g;
      const ValueId c = g.const_f(x);
      const ValueId r = g.emit(g.body, op, Type::Float, c);
      uint32_t bits;
      ASSERT_TRUE(fold_constant(g, g.insts[r], bits));
      folded.push_back(bits);
      const ValueId in = f.input(Type::Float, 0);
      const ValueId k = f.emit(f.body, Op::Add, Type::Float, in, f.const_f(x));
      f.emit_imm(f.body, Op::StoreOutput, Type::Float, out++, 0, 0,
                 f.emit(f.body, op, Type::Float, k));
    }
  std::string err;
  auto exe = Executable::build(f, Stage::Vertex, &err);
  ASSERT_TRUE(exe) << err;
  std::vector<float> zero(4, 0.0f), res(static_cast<size_t>(out) * 4);
  std::vector<float*> outs;
  for (int i = 0; i < out; ++i)
    outs.push_back(res.data() + 4 * i);
  const float* ins[1] = {zero.data()};
  Prepared prep;
  exe->prepare(nullptr, prep);
  std::vector<char> scratch(exe->scratch_bytes());
  VertexBatch b;
  b.count = 1;
  b.in = ins;
  b.out = outs.data();
  exe->run_vertices(prep, b, scratch.data());
  for (int i = 0; i < out; ++i)
    EXPECT_EQ(std::bit_cast<uint32_t>(res[static_cast<size_t>(4 * i)]),
              folded[static_cast<size_t>(i)])
        << op_name(ops[i / 8]) << "(" << xs[i % 8] << ")";
}

} // namespace
} // namespace pineda::shader
