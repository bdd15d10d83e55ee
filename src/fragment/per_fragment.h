// Building blocks of the stencil update operations (GL 2.1 §4.1.5) and the logical operation
// (§4.1.10), shared by the block loops (fragment_ops.cpp) and their tests.
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "core/simd.h"

namespace pineda {

// GL 2.1 §4.1.5 (and GL 1.4's INCR_WRAP, DECR_WRAP): what happens to the stored value.
enum class StencilOp : uint8_t { Keep, Zero, Replace, Incr, Decr, Invert, IncrWrap, DecrWrap };

inline StencilOp stencil_op_from_gl(GLenum op) {
  switch (op) {
  case GL_ZERO:
    return StencilOp::Zero;
  case GL_REPLACE:
    return StencilOp::Replace;
  case GL_INCR:
    return StencilOp::Incr;
  case GL_DECR:
    return StencilOp::Decr;
  case GL_INVERT:
    return StencilOp::Invert;
  case GL_INCR_WRAP:
    return StencilOp::IncrWrap;
  case GL_DECR_WRAP:
    return StencilOp::DecrWrap;
  default:
    return StencilOp::Keep; // the front end accepts only the eight enums
  }
}

// The new stencil values before the write mask, for an 8-bit buffer, on lanes holding one
// value each: INCR and DECR saturate at 0 and 255, the _WRAP forms wrap modulo 256, REPLACE
// stores the (clamped) reference. Comparisons give -1 for true, so subtracting or adding a
// comparison is the saturating step.
inline i32x4 stencil_op_lanes(StencilOp op, i32x4 v, i32x4 ref) {
  const i32x4 zero = {}, top = zero + 0xff;
  switch (op) {
  case StencilOp::Keep:
    return v;
  case StencilOp::Zero:
    return zero;
  case StencilOp::Replace:
    return ref;
  case StencilOp::Incr:
    return v - (v < top);
  case StencilOp::Decr:
    return v + (v > zero);
  case StencilOp::Invert:
    return v ^ top;
  case StencilOp::IncrWrap:
    return (v + 1) & top;
  case StencilOp::DecrWrap:
    return (v + 0xff) & top;
  }
  return v;
}

// A logical operation as its truth table (GL 2.1 table 4.3): the result bit for each of the
// four combinations of source bit s and destination bit d. The enums GL_CLEAR..GL_SET carry
// the X window system's codes in their low four bits, whose bit 3 - (2s + d) is the result.
// Spreading each bit over a whole word makes the operation four ANDs and three ORs on any
// packed data, so one code path serves all sixteen operations and every channel at once.
struct LogicMasks {
  uint32_t sd = 0;    // s = 1, d = 1
  uint32_t s_nd = 0;  // s = 1, d = 0
  uint32_t ns_d = 0;  // s = 0, d = 1
  uint32_t ns_nd = 0; // s = 0, d = 0
};

inline LogicMasks logic_masks(GLenum op) {
  const unsigned code = (op - GL_CLEAR) & 0xfu;
  const auto spread = [code](unsigned bit) { return ((code >> bit) & 1u) ? 0xffffffffu : 0u; };
  return LogicMasks{spread(0), spread(1), spread(2), spread(3)};
}

// Works for scalars and for vectors of uint32_t alike.
template <typename T> T apply_logic(const LogicMasks& lm, T s, T d) {
  return (s & d & lm.sd) | (s & ~d & lm.s_nd) | (~s & d & lm.ns_d) | (~s & ~d & lm.ns_nd);
}

} // namespace pineda
