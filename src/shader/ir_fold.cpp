// Constant folding: an instruction whose operands are constants becomes the constant the
// engine would compute (the same lane_ops.h templates, four lanes wide), and the map from IR
// operations to the engine's lane operations.
#include "shader/ir_passes.h"

#include "shader/fp_env.h"
#include "shader/lane_apply.h"

namespace pineda::shader {

const char* lane_op_name(LaneOp op) {
  switch (op) {
#define PINEDA_X(name, n)                                                                          \
  case LaneOp::name:                                                                               \
    return #name;
    PINEDA_LANE_OPS(PINEDA_X)
#undef PINEDA_X
  case LaneOp::Count:
    break;
  }
  return "?";
}

bool lane_op_for(const Function& f, const Inst& in, LaneOp& out) {
  const auto t = [&](int k) { return f.insts[in.arg[k]].type; };
  const bool fl = op_arity(in.op) > 0 && in.arg[0] != kNoValue && t(0) == Type::Float;
  const bool bo = op_arity(in.op) > 0 && in.arg[0] != kNoValue && t(0) == Type::Bool;
  switch (in.op) {
  case Op::Add:
    out = fl ? LaneOp::FAdd : LaneOp::IAdd;
    return true;
  case Op::Sub:
    out = fl ? LaneOp::FSub : LaneOp::ISub;
    return true;
  case Op::Mul:
    out = fl ? LaneOp::FMul : LaneOp::IMul;
    return true;
  case Op::Div:
    out = fl ? LaneOp::FDiv : LaneOp::IDiv;
    return true;
  case Op::Neg:
    out = fl ? LaneOp::FNeg : LaneOp::INeg;
    return true;
  case Op::Min:
    out = fl ? LaneOp::FMin : LaneOp::IMin;
    return true;
  case Op::Max:
    out = fl ? LaneOp::FMax : LaneOp::IMax;
    return true;
  case Op::Abs:
    out = fl ? LaneOp::FAbs : LaneOp::IAbs;
    return true;
  case Op::Sign:
    out = fl ? LaneOp::FSign : LaneOp::ISign;
    return true;
  case Op::Floor:
    out = LaneOp::FFloor;
    return true;
  case Op::Ceil:
    out = LaneOp::FCeil;
    return true;
  case Op::Fract:
    out = LaneOp::FFract;
    return true;
  case Op::Sqrt:
    out = LaneOp::FSqrt;
    return true;
  case Op::Rsq:
    out = LaneOp::FRsq;
    return true;
  case Op::Exp2:
    out = LaneOp::FExp2;
    return true;
  case Op::Log2:
    out = LaneOp::FLog2;
    return true;
  case Op::Exp:
    out = LaneOp::FExp;
    return true;
  case Op::Log:
    out = LaneOp::FLog;
    return true;
  case Op::Sin:
    out = LaneOp::FSin;
    return true;
  case Op::Cos:
    out = LaneOp::FCos;
    return true;
  case Op::Tan:
    out = LaneOp::FTan;
    return true;
  case Op::Asin:
    out = LaneOp::FAsin;
    return true;
  case Op::Acos:
    out = LaneOp::FAcos;
    return true;
  case Op::Atan:
    out = LaneOp::FAtan;
    return true;
  case Op::Pow:
    out = LaneOp::FPow;
    return true;
  case Op::Atan2:
    out = LaneOp::FAtan2;
    return true;
  case Op::Lt:
    out = fl ? LaneOp::FLt : LaneOp::ILt;
    return true;
  case Op::Le:
    out = fl ? LaneOp::FLe : LaneOp::ILe;
    return true;
  case Op::Gt:
    out = fl ? LaneOp::FGt : LaneOp::IGt;
    return true;
  case Op::Ge:
    out = fl ? LaneOp::FGe : LaneOp::IGe;
    return true;
  case Op::Eq:
    out = fl ? LaneOp::FEq : bo ? LaneOp::BEq : LaneOp::IEq;
    return true;
  case Op::Ne:
    out = fl ? LaneOp::FNe : bo ? LaneOp::BXor : LaneOp::INe;
    return true;
  case Op::And:
    out = LaneOp::BAnd;
    return true;
  case Op::Or:
    out = LaneOp::BOr;
    return true;
  case Op::Xor:
    out = LaneOp::BXor;
    return true;
  case Op::Not:
    out = LaneOp::BNot;
    return true;
  case Op::Select:
    out = LaneOp::Select;
    return true;
  case Op::I2F:
    out = LaneOp::I2F;
    return true;
  case Op::F2I:
    out = LaneOp::F2I;
    return true;
  case Op::B2F:
    out = LaneOp::B2F;
    return true;
  case Op::B2I:
    out = LaneOp::B2I;
    return true;
  case Op::F2B:
    out = LaneOp::F2B;
    return true;
  case Op::I2B:
    out = LaneOp::I2B;
    return true;
  default:
    return false;
  }
}

namespace {

using F4 = float __attribute__((vector_size(16)));
using D4 = double __attribute__((vector_size(32)));
using FoldFn = F4 (*)(F4, F4, F4);

template <LaneOp op> F4 fold_one(F4 a, F4 b, F4 c) {
  return vm::apply_lane_op<op, F4, D4>(a, b, c);
}

constexpr FoldFn kFold[] = {
#define PINEDA_X(name, n) &fold_one<LaneOp::name>,
    PINEDA_LANE_OPS(PINEDA_X)
#undef PINEDA_X
};

} // namespace

uint32_t eval_lane_op(LaneOp op, uint32_t a, uint32_t b, uint32_t c) {
  // Lanes by value, not by address: clang does not take the address of a vector element.
  const auto bits = [](uint32_t v) {
    float f;
    __builtin_memcpy(&f, &v, 4);
    F4 r;
    r[0] = r[1] = r[2] = r[3] = f;
    return r;
  };
  ShaderFpEnv env;
  const F4 r = kFold[static_cast<int>(op)](bits(a), bits(b), bits(c));
  uint32_t out;
  const float lane0 = r[0];
  __builtin_memcpy(&out, &lane0, 4);
  return out;
}

bool fold_constant(const Function& f, const Inst& in, uint32_t& out) {
  LaneOp op;
  if (!lane_op_for(f, in, op)) return false;
  const int n = lane_op_arity(op);
  uint32_t v[3] = {0, 0, 0};
  for (int k = 0; k < n; ++k) {
    if (in.arg[k] == kNoValue || !f.is_const(in.arg[k])) return false;
    v[k] = f.const_bits(in.arg[k]);
  }
  out = eval_lane_op(op, v[0], v[1], v[2]);
  if (in.type == Type::Bool) out = out ? ~0u : 0u;
  return true;
}

} // namespace pineda::shader
