// Pineda's shader IR: typed, scalar, structure-of-arrays. Every value is one lane vector (one
// lane per vertex or fragment) of 32-bit floats, ints or bools; a vec4 is four values and a
// matrix its columns' values. Values are in SSA form: each is defined once, by one instruction.
//
// Control flow is structured and explicit about lanes:
// - A Region runs its body only if some lane of its condition (a bool value) is set among the
//   block's entry lanes; its outs merge values: phi = inner if the body ran, outer if not.
//   Lowering masks every assignment inside (select(active, new, old)), so running a body with
//   no active lane changes nothing, and a region can always be flattened into its parent.
//   A region whose condition is uniform (the same in every lane) is a real branch.
// - A Loop repeats its body; its phis carry values from one iteration to the next
//   (phi = init on entry, next after each iteration). Its body's top-level block holds exactly
//   one ExitIfNone: the loop ends there when no entry lane of the mask is set (or the
//   iteration limit is reached), and its exits copy values defined before that point out of
//   the loop. Lanes that break, continue or return leave the mask; their values stay frozen
//   because every update is masked.
// Constants, uniform words and inputs belong to no block: they are available everywhere.
//
// The IR knows nothing of GLSL or GL state: the front end (src/glsl) lowers to it, the passes
// (ir_passes.cpp) optimize it and the engine (engine.h) runs it.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <unordered_map>
#include <vector>

namespace pineda::shader {

using ValueId = uint32_t;
constexpr ValueId kNoValue = ~0u;

enum class Type : uint8_t { Float, Int, Bool };

// The operations. "f" operands are floats, "i" ints, "b" bools (lane masks); the arithmetic and
// comparison ops take float or int operands (both the same type), as the operands' type says.
// clang-format off
#define PINEDA_IR_OPS(X) \
  /* leaves: no block */ \
  X(Const)   /* imm[0]: the 32-bit pattern */ \
  X(Uniform) /* imm[0]: word offset in the uniform buffer (bool: word != 0) */ \
  X(Input)   /* imm[0]: input component (slot * 4 + component) */ \
  X(Phi)     /* defined by a Region out, a Loop phi or a Loop exit */ \
  /* arithmetic: float or int */ \
  X(Add) X(Sub) X(Mul) X(Div) X(Neg) X(Min) X(Max) X(Abs) X(Sign) \
  /* float only */ \
  X(Floor) X(Ceil) X(Fract) X(Sqrt) X(Rsq) X(Exp2) X(Log2) X(Exp) X(Log) \
  X(Sin) X(Cos) X(Tan) X(Asin) X(Acos) X(Atan) X(Pow) X(Atan2) \
  /* comparisons: float or int operands (Eq and Ne also bool), bool result */ \
  X(Lt) X(Le) X(Gt) X(Ge) X(Eq) X(Ne) \
  /* bool */ \
  X(And) X(Or) X(Xor) X(Not) \
  X(Select) /* arg0 ? arg1 : arg2, lane by lane */ \
  /* conversions */ \
  X(I2F) X(F2I) X(B2F) X(B2I) X(F2B) X(I2B) \
  /* fragment derivatives over 2x2 quads */ \
  X(Ddx) X(Ddy) \
  /* uniform array element: imm[0] base word, imm[1] stride, imm[2] count; arg0 index */ \
  X(UniformIndexed) \
  /* texture lookup: args s, t, r, lod-or-bias; imm[0] sampler word, imm[1] TexKind bits */ \
  X(Tex) \
  X(TexComp) /* component imm[0] of the Tex arg0 */ \
  /* side effects and control */ \
  X(StoreOutput) /* imm[0]: output component; arg0 value */ \
  X(ExitIfNone)  /* loop exit test, arg0 mask */
// clang-format on

enum class Op : uint8_t {
#define PINEDA_X(name) name,
  PINEDA_IR_OPS(PINEDA_X)
#undef PINEDA_X
};

const char* op_name(Op op);

// Tex: the sampler target and how the level of detail is found (imm[1]).
enum class TexTarget : uint8_t { Tex1D, Tex2D, Tex3D, Cube };
enum class LodMode : uint8_t {
  Implicit, // from the 2x2 quad's coordinates (fragment shaders)
  Bias,     // implicit plus a per-lane bias (arg3)
  Explicit, // arg3 is the level of detail (vertex shaders; texture*Lod)
};
struct TexKind {
  TexTarget target = TexTarget::Tex2D;
  LodMode lod = LodMode::Implicit;
  bool shadow = false; // r (arg2) is the depth reference (GL 2.1 §3.8.14)
  int32_t pack() const {
    return static_cast<int32_t>(target) | (static_cast<int32_t>(lod) << 4) | (shadow ? 256 : 0);
  }
  static TexKind unpack(int32_t v) {
    TexKind k;
    k.target = static_cast<TexTarget>(v & 15);
    k.lod = static_cast<LodMode>((v >> 4) & 15);
    k.shadow = (v & 256) != 0;
    return k;
  }
};

struct Inst {
  Op op = Op::Const;
  Type type = Type::Float;
  ValueId arg[4] = {kNoValue, kNoValue, kNoValue, kNoValue};
  int32_t imm[3] = {0, 0, 0};
};

enum class NodeKind : uint8_t { Inst, Region, Loop };
struct Node {
  NodeKind kind;
  uint32_t index; // ValueId for Inst, index into Function::regions or ::loops otherwise
};
using Block = std::vector<Node>;

struct RegionOut {
  ValueId phi, inner, outer;
};
struct Region {
  ValueId cond = kNoValue;
  // The condition is uniform: the body runs in every lane or in none, and its assignments
  // are not masked by the condition, so outs merge by the condition when flattened.
  bool uniform = false;
  Block body;
  std::vector<RegionOut> outs;
  bool dead = false; // removed by a pass (its node is gone from every block)
};

struct LoopPhi {
  ValueId phi, init, next;
};
struct LoopExit {
  ValueId out, inner;
};
struct Loop {
  std::vector<LoopPhi> phis;
  Block body;
  std::vector<LoopExit> exits;
  bool dead = false;
};

// Output components at or above this index are not GL outputs: kKillOutput holds the lanes a
// fragment shader discarded.
constexpr int32_t kKillOutput = 1 << 20;

// One shader stage's program.
struct Function {
  std::vector<Inst> insts; // indexed by ValueId
  std::deque<Region> regions;
  std::deque<Loop> loops;
  Block body;

  // Leaves, shared: asking twice for the same constant gives the same value.
  ValueId constant(Type t, uint32_t bits);
  ValueId const_f(float f);
  ValueId const_i(int32_t i);
  ValueId const_b(bool b);
  ValueId uniform(Type t, int32_t word);
  ValueId input(Type t, int32_t component);
  ValueId phi(Type t);

  // Appends an instruction to `b` and returns its value.
  ValueId emit(Block& b, Op op, Type t, ValueId a0 = kNoValue, ValueId a1 = kNoValue,
               ValueId a2 = kNoValue, ValueId a3 = kNoValue);
  ValueId emit_imm(Block& b, Op op, Type t, int32_t i0, int32_t i1 = 0, int32_t i2 = 0,
                   ValueId a0 = kNoValue);

  uint32_t add_region() {
    regions.emplace_back();
    return static_cast<uint32_t>(regions.size() - 1);
  }
  uint32_t add_loop() {
    loops.emplace_back();
    return static_cast<uint32_t>(loops.size() - 1);
  }

  // Renumbers the Input leaves (the link assigns inputs after it has seen what is read).
  template <class Fn> void remap_inputs(Fn&& fn) {
    for (Inst& in : insts)
      if (in.op == Op::Input) in.imm[0] = fn(in.imm[0]);
    rebuild_leaf_index();
  }
  void rebuild_leaf_index();

  bool is_leaf(ValueId v) const {
    const Op op = insts[v].op;
    return op == Op::Const || op == Op::Uniform || op == Op::Input;
  }
  bool is_const(ValueId v) const { return insts[v].op == Op::Const; }
  uint32_t const_bits(ValueId v) const { return static_cast<uint32_t>(insts[v].imm[0]); }
  float const_float(ValueId v) const;
  Type type(ValueId v) const { return insts[v].type; }

private:
  std::unordered_map<uint64_t, ValueId> leaves_;
  ValueId leaf(Op op, Type t, int32_t imm);
};

// Number of value operands `op` reads (arg[0..n-1]); Tex reads up to four, kNoValue when absent.
int op_arity(Op op);
// True for operations without side effects and without lane interaction (no Ddx/Ddy, Tex,
// ExitIfNone, StoreOutput): those a pass may move, merge or drop when unused.
bool op_is_pure_lanewise(Op op);

// The IR in text, one instruction a line (PINEDA_DEBUG=ir prints it).
std::string print(const Function& f);

// Checks the structural rules (definitions before uses, one ExitIfNone at each loop's top
// level, values used only where they are defined); an empty string when the IR is valid.
std::string verify(const Function& f);

} // namespace pineda::shader
