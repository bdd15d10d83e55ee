// The engine's lane-wise operations: every lane of the result depends on the same lane of the
// operands only. What each computes is lane_apply.h.
#pragma once

#include <cstdint>

namespace pineda::shader {

// The lane-wise operations of the engine; the IR's ops map onto them by operand type. Mad is
// (a * b) + c with two roundings, as the unfused pair; Clamp is min(max(a, b), c).
// clang-format off
#define PINEDA_LANE_OPS(X) \
  X(FAdd, 2) \
  X(FSub, 2) \
  X(FMul, 2) \
  X(FDiv, 2) \
  X(FNeg, 1) \
  X(FMin, 2) \
  X(FMax, 2) \
  X(FAbs, 1) \
  X(FSign, 1) \
  X(FFloor, 1) \
  X(FCeil, 1) \
  X(FFract, 1) \
  X(FSqrt, 1) \
  X(FRsq, 1) \
  X(FExp2, 1) \
  X(FLog2, 1) \
  X(FExp, 1) \
  X(FLog, 1) \
  X(FSin, 1) \
  X(FCos, 1) \
  X(FTan, 1) \
  X(FAsin, 1) \
  X(FAcos, 1) \
  X(FAtan, 1) \
  X(FPow, 2) \
  X(FAtan2, 2) \
  X(FLt, 2) \
  X(FLe, 2) \
  X(FGt, 2) \
  X(FGe, 2) \
  X(FEq, 2) \
  X(FNe, 2) \
  X(IAdd, 2) \
  X(ISub, 2) \
  X(IMul, 2) \
  X(IDiv, 2) \
  X(INeg, 1) \
  X(IMin, 2) \
  X(IMax, 2) \
  X(IAbs, 1) \
  X(ISign, 1) \
  X(ILt, 2) \
  X(ILe, 2) \
  X(IGt, 2) \
  X(IGe, 2) \
  X(IEq, 2) \
  X(INe, 2) \
  X(BAnd, 2) \
  X(BOr, 2) \
  X(BXor, 2) \
  X(BNot, 1) \
  X(BEq, 2) \
  X(Select, 3) \
  X(I2F, 1) \
  X(F2I, 1) \
  X(B2F, 1) \
  X(B2I, 1) \
  X(F2B, 1) \
  X(I2B, 1) \
  X(Mov, 1) \
  X(Mad, 3) \
  X(Clamp, 3)
// clang-format on

enum class LaneOp : uint8_t {
#define PINEDA_X(name, n) name,
  PINEDA_LANE_OPS(PINEDA_X)
#undef PINEDA_X
      Count
};

constexpr int lane_op_arity(LaneOp op) {
  switch (op) {
#define PINEDA_X(name, n)                                                                          \
  case LaneOp::name:                                                                               \
    return n;
    PINEDA_LANE_OPS(PINEDA_X)
#undef PINEDA_X
  case LaneOp::Count:
    break;
  }
  return 0;
}

const char* lane_op_name(LaneOp op);

} // namespace pineda::shader
