// What each lane-wise operation (lane_ops.h) computes, once for every lane width: the engine's
// kernels (engine_kernels.h) and the IR's constant folder (ir_fold.cpp) both apply these
// templates, so a folded constant has the bits the engine would have computed.
//
// Lanes are 32-bit patterns carried in float vectors; int and bool operations reinterpret
// them. Bools are lane masks: all ones (true) or zero (false).
//
// Like vmath.h, this defines its templates in the namespace PINEDA_SIMD_NS, so that a file
// compiled for another instruction set (engine_avx2.cpp) gets its own copies.
#pragma once

#include <cstdint>

#include "shader/lane_ops.h"
#include "shader/vmath.h"

namespace pineda::shader::PINEDA_SIMD_NS {

// The operation on one vector of lanes. F is a float vector type; the int vector of the same
// width is vm::IOf<F>. D is a double vector of the same lane count (integer division).
template <LaneOp op, class F, class D>
[[gnu::always_inline]] inline F apply_lane_op(F a, F b, F c) {
  using I = IOf<F>;
  using U = UOf<F>;
  // No lambdas here: GCC does not give them the target of the file's pragma.
#define PINEDA_IA (as_int(a))
#define PINEDA_IB (as_int(b))
  const F one = splat<F>(1.0f);
  (void)c;
  (void)one;
  if constexpr (op == LaneOp::FAdd)
    return a + b;
  else if constexpr (op == LaneOp::FSub)
    return a - b;
  else if constexpr (op == LaneOp::FMul)
    return a * b;
  else if constexpr (op == LaneOp::FDiv)
    return a / b;
  else if constexpr (op == LaneOp::FNeg)
    return -a;
  else if constexpr (op == LaneOp::FMin)
    return vmin(a, b);
  else if constexpr (op == LaneOp::FMax)
    return vmax(a, b);
  else if constexpr (op == LaneOp::FAbs)
    return vabs(a);
  else if constexpr (op == LaneOp::FSign)
    return sel(a > F{}, one, sel(a < F{}, -one, sel(a != a, a, F{})));
  else if constexpr (op == LaneOp::FFloor)
    return vfloor(a);
  else if constexpr (op == LaneOp::FCeil)
    return vceil(a);
  else if constexpr (op == LaneOp::FFract)
    return vfract(a);
  else if constexpr (op == LaneOp::FSqrt)
    return vsqrt(a);
  else if constexpr (op == LaneOp::FRsq)
    return one / vsqrt(a);
  else if constexpr (op == LaneOp::FExp2)
    return vexp2(a);
  else if constexpr (op == LaneOp::FLog2)
    return vlog2(a);
  else if constexpr (op == LaneOp::FExp)
    return vexp(a);
  else if constexpr (op == LaneOp::FLog)
    return vlog(a);
  else if constexpr (op == LaneOp::FSin)
    return vsin(a);
  else if constexpr (op == LaneOp::FCos)
    return vcos(a);
  else if constexpr (op == LaneOp::FTan)
    return vtan(a);
  else if constexpr (op == LaneOp::FAsin)
    return vasin(a);
  else if constexpr (op == LaneOp::FAcos)
    return vacos(a);
  else if constexpr (op == LaneOp::FAtan)
    return vatan(a);
  else if constexpr (op == LaneOp::FPow)
    return vpow(a, b);
  else if constexpr (op == LaneOp::FAtan2)
    return vatan2(a, b);
  else if constexpr (op == LaneOp::FLt)
    return as_float<F>(a < b);
  else if constexpr (op == LaneOp::FLe)
    return as_float<F>(a <= b);
  else if constexpr (op == LaneOp::FGt)
    return as_float<F>(a > b);
  else if constexpr (op == LaneOp::FGe)
    return as_float<F>(a >= b);
  else if constexpr (op == LaneOp::FEq)
    return as_float<F>(a == b);
  else if constexpr (op == LaneOp::FNe)
    return as_float<F>(a != b);
  // Integer arithmetic wraps (through unsigned lanes: no signed overflow).
  else if constexpr (op == LaneOp::IAdd)
    return as_float<F>(I(U(PINEDA_IA) + U(PINEDA_IB)));
  else if constexpr (op == LaneOp::ISub)
    return as_float<F>(I(U(PINEDA_IA) - U(PINEDA_IB)));
  else if constexpr (op == LaneOp::IMul)
    return as_float<F>(I(U(PINEDA_IA) * U(PINEDA_IB)));
  else if constexpr (op == LaneOp::IDiv)
    return as_float<F>(idiv<I, D>(PINEDA_IA, PINEDA_IB));
  else if constexpr (op == LaneOp::INeg)
    return as_float<F>(I(U{} - U(PINEDA_IA)));
  else if constexpr (op == LaneOp::IMin)
    return as_float<F>(seli(PINEDA_IA < PINEDA_IB, PINEDA_IA, PINEDA_IB));
  else if constexpr (op == LaneOp::IMax)
    return as_float<F>(seli(PINEDA_IA > PINEDA_IB, PINEDA_IA, PINEDA_IB));
  else if constexpr (op == LaneOp::IAbs)
    return as_float<F>(seli(PINEDA_IA < 0, I(U{} - U(PINEDA_IA)), PINEDA_IA));
  else if constexpr (op == LaneOp::ISign)
    return as_float<F>((PINEDA_IA < 0) - (PINEDA_IA > 0));
  else if constexpr (op == LaneOp::ILt)
    return as_float<F>(PINEDA_IA < PINEDA_IB);
  else if constexpr (op == LaneOp::ILe)
    return as_float<F>(PINEDA_IA <= PINEDA_IB);
  else if constexpr (op == LaneOp::IGt)
    return as_float<F>(PINEDA_IA > PINEDA_IB);
  else if constexpr (op == LaneOp::IGe)
    return as_float<F>(PINEDA_IA >= PINEDA_IB);
  else if constexpr (op == LaneOp::IEq)
    return as_float<F>(PINEDA_IA == PINEDA_IB);
  else if constexpr (op == LaneOp::INe)
    return as_float<F>(PINEDA_IA != PINEDA_IB);
  else if constexpr (op == LaneOp::BAnd)
    return as_float<F>(PINEDA_IA & PINEDA_IB);
  else if constexpr (op == LaneOp::BOr)
    return as_float<F>(PINEDA_IA | PINEDA_IB);
  else if constexpr (op == LaneOp::BXor)
    return as_float<F>(PINEDA_IA ^ PINEDA_IB);
  else if constexpr (op == LaneOp::BNot)
    return as_float<F>(~PINEDA_IA);
  else if constexpr (op == LaneOp::BEq)
    return as_float<F>(~(PINEDA_IA ^ PINEDA_IB));
  else if constexpr (op == LaneOp::Select)
    return sel(PINEDA_IA, b, c);
  else if constexpr (op == LaneOp::I2F)
    return i2f<F>(PINEDA_IA);
  else if constexpr (op == LaneOp::F2I)
    return as_float<F>(f2i(a));
  else if constexpr (op == LaneOp::B2F)
    return as_float<F>(PINEDA_IA & as_int(one));
  else if constexpr (op == LaneOp::B2I)
    return as_float<F>(PINEDA_IA & 1);
  else if constexpr (op == LaneOp::F2B)
    return as_float<F>(a != F{});
  else if constexpr (op == LaneOp::I2B)
    return as_float<F>(PINEDA_IA != 0);
  else if constexpr (op == LaneOp::Mov)
    return a;
  else if constexpr (op == LaneOp::Mad)
    return a * b + c;
  else if constexpr (op == LaneOp::Clamp)
    return vmin(vmax(a, b), c);
  else
    return a;
#undef PINEDA_IA
#undef PINEDA_IB
}

} // namespace pineda::shader::PINEDA_SIMD_NS
