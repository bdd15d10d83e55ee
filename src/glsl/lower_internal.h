// The lowering's state, shared by lower.cpp (statements, control flow, functions),
// lower_expr.cpp (expressions, variables, operators) and lower_builtin.cpp (built-in functions).
//
// Model: every GLSL variable is an entry of `env`, its flattened components' current SSA
// values. An assignment under a lane mask `active` stores select(active, new, old); statements
// that jump (break, continue, return, discard) add the active lanes to a mask variable, and
// the statements after them run with those lanes removed. If-statements become IR regions
// (skipped when no lane takes them), loops IR loops whose phis carry every variable.
#pragma once

#include <glslang/Include/intermediate.h>

#include <functional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "glsl/lower.h"
#include "shader/ir.h"

namespace pineda::glsl {

using ::TIntermNode;
using shader::Block;
using shader::Function;
using shader::kNoValue;
using shader::Op;
using shader::Type;
using shader::ValueId;
using Comps = std::vector<ValueId>;

// Sampler values are not IR values: a component holding kSamplerTag | word names the uniform
// word that holds the sampler's texture unit.
constexpr uint32_t kSamplerTag = 0x40000000u;
inline bool is_sampler(ValueId v) {
  return v != kNoValue && (v & 0xC0000000u) == kSamplerTag;
}

// Flattened component types of a GLSL type; samplers are kSamplerType (never an IR type).
constexpr Type kSamplerType = static_cast<Type>(3);
void flat_types(const glslang::TType& t, std::vector<Type>& out);
int array_size(const glslang::TType& t);
Type ir_type(glslang::TBasicType b);

// A reference to (part of) a variable: the components base + sum(index * stride) + k (or
// + swizzle[k]) of a root, which is either a uniform in the buffer or a list of values
// (a variable of env, an input, a constant or a temporary).
struct Ref {
  bool uniform = false;
  int uniform_base = 0;
  std::string key; // env key when the root is a writable variable
  Comps root;      // the root's values (not uniform)
  std::vector<Type> root_types;
  int base = 0;
  struct Dyn {
    ValueId index;
    int stride, count;
    std::vector<int> table; // offsets of the elements when not i * stride (a swizzle's)
    int offset(int i) const { return table.empty() ? i * stride : table[static_cast<size_t>(i)]; }
  };
  std::vector<Dyn> dyn;
  std::vector<int> swz;
  int count = 0; // components of the referenced object before the swizzle
  int size() const { return swz.empty() ? count : static_cast<int>(swz.size()); }
  int comp(int k) const { return base + (swz.empty() ? k : swz[static_cast<size_t>(k)]); }
};

class Lowerer {
public:
  Lowerer(const glslang::TIntermediate& ast, shader::Stage stage, const LowerEnv& env, Function& f,
          LowerResult& result);
  bool run();

  // ---- emission (lower.cpp) ----
  ValueId op(Op o, Type t, ValueId a, ValueId b = kNoValue, ValueId c = kNoValue);
  ValueId and_(ValueId a, ValueId b);
  ValueId or_(ValueId a, ValueId b);
  ValueId not_(ValueId a);
  ValueId select(ValueId c, ValueId a, ValueId b);
  ValueId active_value(); // the active lanes as a value (true when all)
  bool is_uniform(ValueId v);
  void fail(const std::string& msg);

  // ---- statements (lower.cpp) ----
  bool stmt(TIntermNode* n);
  bool stmt_list(TIntermNode* n);
  bool if_stmt(glslang::TIntermSelection* s);
  void loop_stmt(glslang::TIntermLoop* l);
  bool try_unroll(glslang::TIntermLoop* l);
  bool branch(glslang::TIntermBranch* b);
  bool region(ValueId cond, bool uniform, ValueId inner_active, const std::function<bool()>& body);
  void recompute_active(ValueId base);
  bool jumps(TIntermNode* n);
  bool side_effects(TIntermNode* n);
  void prescan_locals(TIntermNode* n);
  Comps call(glslang::TIntermAggregate* a);

  // ---- variables and expressions (lower_expr.cpp) ----
  std::string key_of(const glslang::TIntermSymbol* s) const;
  Comps& var(const glslang::TIntermSymbol* s);
  Ref ref(glslang::TIntermTyped* n);
  Comps load(const Ref& r);
  void store(const Ref& r, const Comps& v);
  void assign_comp(Comps& dst, size_t k, ValueId v);
  Comps expr(glslang::TIntermTyped* n);
  Comps constant(const glslang::TConstUnionArray& c, const glslang::TType& t);
  Comps binary(glslang::TIntermBinary* b);
  Comps unary(glslang::TIntermUnary* u);
  Comps aggregate(glslang::TIntermAggregate* a);
  Comps construct(glslang::TIntermAggregate* a);
  Comps assignment(glslang::TIntermBinary* b);
  Comps arith(glslang::TOperator o, const glslang::TType& lt, const Comps& l,
              const glslang::TType& rt, const Comps& r, const glslang::TType& result);
  Comps componentwise(Op o, Type t, const Comps& a, const Comps& b);
  ValueId convert(ValueId v, Type to);
  ValueId pick(const Comps& cands, ValueId index);

  // ---- built-in functions (lower_builtin.cpp) ----
  Comps builtin(glslang::TOperator o, const std::vector<glslang::TIntermTyped*>& args,
                const glslang::TType& result);
  Comps texture(glslang::TOperator o, const std::vector<glslang::TIntermTyped*>& args);
  ValueId dot(const Comps& a, const Comps& b);

  const glslang::TIntermediate& ast;
  shader::Stage stage;
  const LowerEnv& lenv;
  Function& f;
  LowerResult& result;

  std::unordered_map<std::string, Comps> env;
  std::unordered_set<std::string> outputs; // env keys that are stage outputs
  Block* cur = nullptr;
  ValueId active = kNoValue; // kNoValue: every lane

  struct LoopCtx {
    std::string brk, cont;
  };
  std::vector<LoopCtx> loops;
  struct FnCtx {
    std::string ret, retval;
    size_t loop_base = 0;
    std::vector<std::string> locals;
  };
  std::vector<FnCtx> fns;
  bool has_kill = false;
  int serial = 0;
  // Every call is inlined: a program whose calls multiply beyond this many lowered nodes
  // fails to link instead of taking the process's memory and time.
  static constexpr long kMaxLoweredNodes = 400000;
  long lowered_nodes = 0;
  static constexpr int kMaxExprDepth = 2000;
  int expr_depth = 0;
  std::vector<std::string> call_stack;
  long unroll_budget = 20000;

  std::unordered_map<std::string, glslang::TIntermAggregate*> functions;
  std::unordered_map<const TIntermNode*, bool> jump_memo, effect_memo;
  std::unordered_map<std::string, bool> fn_kills;
  std::vector<uint8_t> uniform_memo; // 0 unknown, 1 varying, 2 uniform
};

} // namespace pineda::glsl
