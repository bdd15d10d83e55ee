// The shader IR by hand: building, folding, dead code, and running it on the engine.
#include <gtest/gtest.h>

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
