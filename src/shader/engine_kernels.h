// The engine's kernels for one vector width W (4, 8 or 16 float lanes), included once by each
// level's file (engine_sse2.cpp, engine_avx2.cpp, engine_avx512.cpp) after its target pragma
// and with its own PINEDA_SIMD_NS, so that the math compiles for that instruction set. Each
// kernel loops over the frame's vectors: a 64-lane register is 16, 8 or 4 vectors.
//
// Defines make_kernel_table<W>() in an unnamed namespace.
#include <cstring>
#include <utility>

#include "shader/engine_internal.h"
#include "shader/fp_env.h"
#include "shader/lane_apply.h"

namespace pineda::shader {
namespace {

template <int W> struct Vec {
  typedef float F __attribute__((vector_size(W * 4), may_alias));
  typedef int32_t I __attribute__((vector_size(W * 4), may_alias));
  typedef double D __attribute__((vector_size(W * 8)));
};

template <int W> inline typename Vec<W>::F* vreg(Frame& f, uint32_t off) {
  return reinterpret_cast<typename Vec<W>::F*>(f.regs + off);
}
template <int W> inline const typename Vec<W>::F* vsrc(const Frame& f, uint32_t off, bool splat) {
  return reinterpret_cast<const typename Vec<W>::F*>((splat ? f.splats : f.regs) + off);
}

// ---- lane-wise operations ----

// The long polynomial operations: unrolling them would only grow the code.
constexpr bool heavy(LaneOp op) {
  switch (op) {
  case LaneOp::FExp2:
  case LaneOp::FLog2:
  case LaneOp::FExp:
  case LaneOp::FLog:
  case LaneOp::FSin:
  case LaneOp::FCos:
  case LaneOp::FTan:
  case LaneOp::FAsin:
  case LaneOp::FAcos:
  case LaneOp::FAtan:
  case LaneOp::FPow:
  case LaneOp::FAtan2:
  case LaneOp::IDiv:
    return true;
  default:
    return false;
  }
}

template <int W, LaneOp op, int K, class F, class D>
[[gnu::always_inline]] inline void lane_loop(F* __restrict d, const F* a, const F* b, const F* c,
                                             int nv) {
  constexpr int n = lane_op_arity(op);
  if constexpr (n == 1 && (K & 1)) {
    const F r = PINEDA_SIMD_NS::apply_lane_op<op, F, D>(a[0], a[0], a[0]);
    for (int i = 0; i < nv; ++i)
      d[i] = r;
  } else {
    const F as = a[0], bs = b[0], cs = c[0];
    const auto one = [&](int i) {
      return PINEDA_SIMD_NS::apply_lane_op<op, F, D>((K & 1) ? as : a[i],
                                                     n >= 2 ? ((K & 2) ? bs : b[i]) : F{},
                                                     n >= 3 ? ((K & 4) ? cs : c[i]) : F{});
    };
    if constexpr (heavy(op)) {
      for (int i = 0; i < nv; ++i)
        d[i] = one(i);
    } else {
#pragma GCC unroll 16
      for (int i = 0; i < nv; ++i)
        d[i] = one(i);
    }
  }
}

// NV: the vectors of the run (f.nvec), fixed at compile time so that the loop is unrolled.
template <int W, LaneOp op, int K, int NV> const Instr* k_lane(const Instr* ip, Frame& f) {
  using F = typename Vec<W>::F;
  using D = typename Vec<W>::D;
  F* __restrict d = vreg<W>(f, ip->d);
  const F* a = vsrc<W>(f, ip->a, K & 1);
  const F* b = vsrc<W>(f, ip->b, (K & 2) != 0);
  const F* c = vsrc<W>(f, ip->c, (K & 4) != 0);
  lane_loop<W, op, K, F, D>(d, a, b, c, NV);
  PINEDA_NEXT(ip + 1);
}

// ---- inputs and outputs ----

template <int W> const Instr* k_load_input(const Instr* ip, Frame& f) {
  float* d = reinterpret_cast<float*>(f.regs + ip->d);
  const RunState& rs = *f.rs;
  const int total = f.nvec * W;
  const float* src = rs.in ? rs.in[ip->aux] : nullptr;
  int n = 0;
  if (src) {
    n = rs.lanes;
    std::memcpy(d, src + rs.base, static_cast<size_t>(n) * 4);
  }
  std::memset(d + n, 0, static_cast<size_t>(total - n) * 4);
  PINEDA_NEXT(ip + 1);
}

template <int W> const Instr* k_load_facing(const Instr* ip, Frame& f) {
  using I = typename Vec<W>::I;
  I* d = reinterpret_cast<I*>(f.regs + ip->d);
  const I v = I{} + (f.rs->front_facing ? -1 : 0);
  for (int i = 0; i < f.nvec; ++i)
    d[i] = v;
  PINEDA_NEXT(ip + 1);
}

template <int W> const Instr* k_store_output(const Instr* ip, Frame& f) {
  const RunState& rs = *f.rs;
  float* dst = rs.out ? rs.out[ip->aux] : nullptr;
  if (dst) std::memcpy(dst + rs.base, f.regs + ip->a, static_cast<size_t>(rs.lanes) * 4);
  PINEDA_NEXT(ip + 1);
}

template <int W> const Instr* k_store_kill(const Instr* ip, Frame& f) {
  const int32_t* m = reinterpret_cast<const int32_t*>(f.regs + ip->a);
  const int32_t* e = reinterpret_cast<const int32_t*>(f.regs);
  uint64_t bits = 0;
  for (int l = 0; l < f.rs->lanes; ++l)
    bits |= static_cast<uint64_t>((m[l] & e[l]) != 0) << l;
  f.rs->kill = bits;
  PINEDA_NEXT(ip + 1);
}

// ---- uniform arrays indexed per lane ----

template <int W, bool Bool> const Instr* k_gather(const Instr* ip, Frame& f) {
  int32_t* d = reinterpret_cast<int32_t*>(f.regs + ip->d);
  const float* idx = reinterpret_cast<const float*>(f.regs + ip->a);
  const uint32_t* u = f.rs->uniforms;
  const int total = f.nvec * W;
  const int32_t count = static_cast<int32_t>(ip->c);
  for (int l = 0; l < total; ++l) {
    int32_t i;
    std::memcpy(&i, idx + l, 4);
    // Out-of-range indices are undefined in GLSL; they read an element of the array.
    i = i < 0 ? 0 : i >= count ? count - 1 : i;
    const uint32_t w = u[ip->aux + static_cast<uint32_t>(i) * ip->b];
    d[l] = Bool ? (w != 0 ? -1 : 0) : static_cast<int32_t>(w);
  }
  PINEDA_NEXT(ip + 1);
}

// ---- derivatives: coarse, one value per 2x2 quad ----
// Lanes 4q+0..3 are (x, y), (x+1, y), (x, y+1), (x+1, y+1); like the fixed-function level of
// detail (fragment/shade.cpp), x differences come from the upper row and y differences from
// the left column.

template <int W, bool X> const Instr* k_deriv(const Instr* ip, Frame& f) {
  float* d = reinterpret_cast<float*>(f.regs + ip->d);
  const float* a = reinterpret_cast<const float*>(f.regs + ip->a);
  const int total = f.nvec * W;
  for (int q = 0; q < total; q += 4) {
    const float v = X ? a[q + 3] - a[q + 2] : a[q + 2] - a[q];
    d[q] = d[q + 1] = d[q + 2] = d[q + 3] = v;
  }
  PINEDA_NEXT(ip + 1);
}

// ---- texture lookups ----

template <int W> const Instr* k_tex(const Instr* ip, Frame& f) {
  RunState& rs = *f.rs;
  const TexDesc& t = rs.tex[ip->aux];
  const int total = f.nvec * W;
  TexRequest req;
  req.unit = static_cast<int>(rs.uniforms[t.sampler_word]);
  req.target = t.kind.target;
  req.shadow = t.kind.shadow;
  req.lod = t.kind.lod;
  // Fragment lookups cover whole quads.
  req.lanes = (rs.lanes + 3) & ~3;
  const auto operand = [&](uint32_t off, int k) -> const float* {
    if (!(t.splat & (1u << k))) return reinterpret_cast<const float*>(f.regs + off);
    float* tmp = rs.tmp + k * kBlockLanes;
    const float v = *reinterpret_cast<const float*>(f.splats + off);
    for (int l = 0; l < total; ++l)
      tmp[l] = v;
    return tmp;
  };
  for (int k = 0; k < 3; ++k)
    req.coord[k] = (t.present & (1u << k)) ? operand(t.coord[k], k) : nullptr;
  req.lod_or_bias = (t.present & 8) ? operand(t.lod, 3) : nullptr;
  for (int k = 0; k < 4; ++k)
    req.rgba[k] = reinterpret_cast<float*>(f.regs + t.dst[k]);
  if (rs.sampler) {
    with_fp_env(rs.caller_csr, [&] { rs.sampler->sample(req); });
  } else {
    // No sampler: what an incomplete texture gives (GL 2.1 §3.8.10), (0, 0, 0, 1).
    for (int k = 0; k < 4; ++k)
      for (int l = 0; l < total; ++l)
        req.rgba[k][l] = k == 3 ? 1.0f : 0.0f;
  }
  // Back to the dispatch loop: a tail call is not possible past `req`, whose address the
  // sampler received.
  return ip + 1;
}

// ---- control ----

template <int W> inline bool any_entry(const Frame& f, uint32_t off) {
  using I = typename Vec<W>::I;
  const I* m = reinterpret_cast<const I*>(f.regs + off);
  const I* e = reinterpret_cast<const I*>(f.regs);
  I acc = I{};
  for (int i = 0; i < f.nvec; ++i)
    acc |= m[i] & e[i];
  int32_t r = 0;
  for (int l = 0; l < W; ++l)
    r |= acc[l];
  return r != 0;
}

template <int W> const Instr* k_jump(const Instr* ip, Frame& f) {
  PINEDA_NEXT(f.code + ip->aux);
}
template <int W> const Instr* k_jump_if_none(const Instr* ip, Frame& f) {
  PINEDA_NEXT(any_entry<W>(f, ip->a) ? ip + 1 : f.code + ip->aux);
}
template <int W> const Instr* k_jump_if_none_s(const Instr* ip, Frame& f) {
  int32_t m;
  std::memcpy(&m, f.splats + ip->a, 4);
  PINEDA_NEXT(m != 0 ? ip + 1 : f.code + ip->aux);
}
template <int W> const Instr* k_loop_init(const Instr* ip, Frame& f) {
  f.rs->loop_count[ip->aux] = 0;
  PINEDA_NEXT(ip + 1);
}
// The loop's exit test. A loop ends after kLoopIterationLimit iterations, and every loop of
// the run once the run's budget is spent, so that no shader hangs the process.
inline bool loop_continues(Frame& f, uint32_t counter) {
  RunState& rs = *f.rs;
  if (++rs.loop_count[counter] > kLoopIterationLimit || rs.budget == 0) return false;
  --rs.budget;
  return true;
}
template <int W> const Instr* k_exit_if_none(const Instr* ip, Frame& f) {
  PINEDA_NEXT(any_entry<W>(f, ip->a) && loop_continues(f, ip->c) ? ip + 1 : f.code + ip->aux);
}
template <int W> const Instr* k_exit_if_none_s(const Instr* ip, Frame& f) {
  int32_t m;
  std::memcpy(&m, f.splats + ip->a, 4);
  PINEDA_NEXT(m != 0 && loop_continues(f, ip->c) ? ip + 1 : f.code + ip->aux);
}
template <int W> const Instr* k_end(const Instr*, Frame&) {
  return nullptr;
}

// ---- the prologue's leaves ----

template <int W> inline void fill_bits(Frame& f, uint32_t off, uint32_t bits) {
  using I = typename Vec<W>::I;
  I* d = reinterpret_cast<I*>(f.regs + off);
  const I v = I{} + static_cast<int32_t>(bits);
  for (int i = 0; i < f.nvec; ++i)
    d[i] = v;
}
template <int W> const Instr* k_load_const(const Instr* ip, Frame& f) {
  fill_bits<W>(f, ip->d, ip->aux);
  PINEDA_NEXT(ip + 1);
}
template <int W> const Instr* k_load_uniform(const Instr* ip, Frame& f) {
  fill_bits<W>(f, ip->d, f.rs->uniforms[ip->aux]);
  PINEDA_NEXT(ip + 1);
}
template <int W> const Instr* k_load_uniform_bool(const Instr* ip, Frame& f) {
  fill_bits<W>(f, ip->d, f.rs->uniforms[ip->aux] != 0 ? ~0u : 0u);
  PINEDA_NEXT(ip + 1);
}

// ---- the table ----

template <int W, int NV, LaneOp op, int... K>
void fill_lane(Kernel* t, std::integer_sequence<int, K...>) {
  constexpr int m = (1 << lane_op_arity(op)) - 1;
  ((t[static_cast<int>(op) * 8 + K] = &k_lane<W, op, (K & m), NV>), ...);
}

// The table for whole blocks (Block) or small runs (engine_internal.h).
template <int W, bool Block> KernelTable make_kernel_table() {
  // static: the lambda below uses it without a capture, which clang 14 allows only then.
  static constexpr int NV = (Block ? kBlockLanes : kSmallRunLanes) / W;
  static const auto table = [] {
    struct T {
      Kernel k[kNumKernels];
    } t{};
#define PINEDA_X(name, n) fill_lane<W, NV, LaneOp::name>(t.k, std::make_integer_sequence<int, 8>{});
    PINEDA_LANE_OPS(PINEDA_X)
#undef PINEDA_X
    const auto set = [&](Special s, Kernel k) { t.k[special_kernel(s)] = k; };
    set(Special::LoadInput, &k_load_input<W>);
    set(Special::LoadFacing, &k_load_facing<W>);
    set(Special::StoreOutput, &k_store_output<W>);
    set(Special::StoreKill, &k_store_kill<W>);
    set(Special::Gather, &k_gather<W, false>);
    set(Special::GatherBool, &k_gather<W, true>);
    set(Special::Tex, &k_tex<W>);
    set(Special::Ddx, &k_deriv<W, true>);
    set(Special::Ddy, &k_deriv<W, false>);
    set(Special::Jump, &k_jump<W>);
    set(Special::JumpIfNone, &k_jump_if_none<W>);
    set(Special::JumpIfNoneS, &k_jump_if_none_s<W>);
    set(Special::LoopInit, &k_loop_init<W>);
    set(Special::ExitIfNone, &k_exit_if_none<W>);
    set(Special::ExitIfNoneS, &k_exit_if_none_s<W>);
    set(Special::End, &k_end<W>);
    set(Special::LoadConst, &k_load_const<W>);
    set(Special::LoadUniform, &k_load_uniform<W>);
    set(Special::LoadUniformBool, &k_load_uniform_bool<W>);
    return t;
  }();
  return {table.k, W};
}

} // namespace
} // namespace pineda::shader
