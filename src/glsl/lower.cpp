// Lowering: statements, control flow and function inlining (lower_internal.h has the model).
#include <glslang/MachineIndependent/localintermediate.h>

#include <algorithm>

#include "glsl/lower_internal.h"
#include "shader/io.h"
#include "shader/ir_passes.h"

namespace pineda::glsl {

using namespace glslang;

namespace {

// Calls fn on every child of n.
template <class Fn> void children(TIntermNode* n, Fn&& fn) {
  if (!n) return;
  if (auto* a = n->getAsAggregate()) {
    for (TIntermNode* c : a->getSequence())
      fn(c);
  } else if (auto* b = n->getAsBinaryNode()) {
    fn(b->getLeft());
    fn(b->getRight());
  } else if (auto* u = n->getAsUnaryNode()) {
    fn(u->getOperand());
  } else if (auto* s = n->getAsSelectionNode()) {
    fn(s->getCondition());
    fn(s->getTrueBlock());
    fn(s->getFalseBlock());
  } else if (auto* l = n->getAsLoopNode()) {
    fn(l->getTest());
    fn(l->getBody());
    fn(l->getTerminal());
  } else if (auto* br = n->getAsBranchNode()) {
    fn(br->getExpression());
  }
}

bool contains_kill(TIntermNode* n) {
  if (!n) return false;
  if (auto* b = n->getAsBranchNode(); b && b->getFlowOp() == EOpKill) return true;
  bool found = false;
  children(n, [&](TIntermNode* c) { found = found || contains_kill(c); });
  return found;
}

// The tree's depth, without recursion (the tree may be deeper than the stack allows).
int tree_depth(TIntermNode* root) {
  std::vector<std::pair<TIntermNode*, int>> stack{{root, 1}};
  int deepest = 0;
  while (!stack.empty()) {
    // Plain variables, not a structured binding: clang 14 (the fuzz build's compiler) cannot
    // capture a binding in the lambda below.
    TIntermNode* const n = stack.back().first;
    const int d = stack.back().second;
    stack.pop_back();
    deepest = std::max(deepest, d);
    children(n, [&](TIntermNode* c) {
      if (c) stack.emplace_back(c, d + 1);
    });
  }
  return deepest;
}

// AST nodes, with the bodies of nested loops counted as if unrolled 64 times: the size an
// unrolled loop may grow to.
long node_count(TIntermNode* n) {
  if (!n) return 0;
  long c = 1;
  children(n, [&](TIntermNode* k) { c += node_count(k); });
  if (n->getAsLoopNode()) c *= 64;
  return std::min(c, 1L << 40);
}

bool is_local_storage(TStorageQualifier q) {
  return q == EvqTemporary || q == EvqIn || q == EvqOut || q == EvqInOut || q == EvqConstReadOnly;
}

// Whether `n` assigns to the symbol `id` or passes it to a function (which could write it).
bool writes_symbol(TIntermNode* n, long long id) {
  if (!n) return false;
  const auto root_is = [&](TIntermTyped* t) {
    while (t) {
      if (auto* s = t->getAsSymbolNode()) return s->getId() == id;
      auto* b = t->getAsBinaryNode();
      if (!b) return false;
      t = b->getLeft();
    }
    return false;
  };
  if (auto* op = n->getAsOperator(); op && op->modifiesState()) {
    if (auto* b = n->getAsBinaryNode(); b && root_is(b->getLeft())) return true;
    if (auto* u = n->getAsUnaryNode(); u && root_is(u->getOperand())) return true;
  }
  if (auto* a = n->getAsAggregate(); a && a->getOp() == EOpFunctionCall)
    for (TIntermNode* c : a->getSequence())
      if (auto* t = c->getAsTyped(); t && root_is(t)) return true;
  bool found = false;
  children(n, [&](TIntermNode* c) { found = found || writes_symbol(c, id); });
  return found;
}

} // namespace

Lowerer::Lowerer(const TIntermediate& a, shader::Stage s, const LowerEnv& e, Function& fn,
                 LowerResult& r)
    : ast(a), stage(s), lenv(e), f(fn), result(r) {}

void Lowerer::fail(const std::string& msg) {
  if (result.error.empty()) result.error = msg;
}

// ---- emission ----

ValueId Lowerer::op(Op o, Type t, ValueId a, ValueId b, ValueId c) {
  shader::Inst in;
  in.op = o;
  in.type = t;
  in.arg[0] = a, in.arg[1] = b, in.arg[2] = c;
  uint32_t bits;
  if (shader::fold_constant(f, in, bits)) return f.constant(t, bits);
  return f.emit(*cur, o, t, a, b, c);
}

namespace {
bool is_true(const Function& f, ValueId v) {
  return f.is_const(v) && f.const_bits(v) != 0;
}
bool is_false(const Function& f, ValueId v) {
  return f.is_const(v) && f.const_bits(v) == 0;
}
} // namespace

ValueId Lowerer::and_(ValueId a, ValueId b) {
  if (is_true(f, a)) return b;
  if (is_true(f, b) || a == b) return a;
  if (is_false(f, a) || is_false(f, b)) return f.const_b(false);
  return op(Op::And, Type::Bool, a, b);
}
ValueId Lowerer::or_(ValueId a, ValueId b) {
  if (is_false(f, a)) return b;
  if (is_false(f, b) || a == b) return a;
  if (is_true(f, a) || is_true(f, b)) return f.const_b(true);
  return op(Op::Or, Type::Bool, a, b);
}
ValueId Lowerer::not_(ValueId a) {
  if (f.insts[a].op == Op::Not) return f.insts[a].arg[0];
  return op(Op::Not, Type::Bool, a);
}
ValueId Lowerer::select(ValueId c, ValueId a, ValueId b) {
  if (a == b || is_true(f, c)) return a;
  if (is_false(f, c)) return b;
  return op(Op::Select, f.type(a), c, a, b);
}
ValueId Lowerer::active_value() {
  return active == kNoValue ? f.const_b(true) : active;
}

bool Lowerer::is_uniform(ValueId v) {
  if (v == kNoValue || is_sampler(v)) return true;
  if (uniform_memo.size() < f.insts.size()) uniform_memo.resize(f.insts.size(), 0);
  if (uniform_memo[v]) return uniform_memo[v] == 2;
  const shader::Inst& in = f.insts[v];
  bool u = false;
  if (in.op == Op::Const || in.op == Op::Uniform) {
    u = true;
  } else if (shader::op_is_pure_lanewise(in.op) && !f.is_leaf(v)) {
    u = true;
    for (int k = 0; k < shader::op_arity(in.op); ++k)
      u = u && is_uniform(in.arg[k]);
  }
  uniform_memo[v] = u ? 2 : 1;
  return u;
}

// ---- analysis of the AST ----

bool Lowerer::jumps(TIntermNode* n) {
  if (!n) return false;
  auto it = jump_memo.find(n);
  if (it != jump_memo.end()) return it->second;
  bool j = false;
  if (n->getAsBranchNode()) {
    j = true;
  } else if (auto* a = n->getAsAggregate(); a && a->getOp() == EOpFunctionCall) {
    // Only a discard in the callee concerns the caller's lanes.
    auto fk = fn_kills.find(a->getName().c_str());
    if (fk == fn_kills.end()) {
      auto def = functions.find(a->getName().c_str());
      fn_kills[a->getName().c_str()] = false; // recursion guard
      const bool k = def != functions.end() && contains_kill(def->second);
      fn_kills[a->getName().c_str()] = k;
      j = k;
    } else {
      j = fk->second;
    }
  }
  if (!j) children(n, [&](TIntermNode* c) { j = j || jumps(c); });
  jump_memo[n] = j;
  return j;
}

bool Lowerer::side_effects(TIntermNode* n) {
  if (!n) return false;
  auto it = effect_memo.find(n);
  if (it != effect_memo.end()) return it->second;
  bool e = false;
  if (auto* o = n->getAsOperator(); o && o->modifiesState()) e = true;
  if (auto* a = n->getAsAggregate(); a && a->getOp() == EOpFunctionCall) e = true;
  if (!e) children(n, [&](TIntermNode* c) { e = e || side_effects(c); });
  effect_memo[n] = e;
  return e;
}

// Locals a construct assigns that have no value yet (declared without an initializer before
// it) get one before it, so that they are merged out of it like every other variable.
void Lowerer::prescan_locals(TIntermNode* n) {
  if (!n) return;
  if (auto* s = n->getAsSymbolNode()) {
    if (is_local_storage(s->getQualifier().storage) && s->getBasicType() != EbtVoid) var(s);
    return;
  }
  children(n, [&](TIntermNode* c) { prescan_locals(c); });
}

// ---- statements ----

void Lowerer::recompute_active(ValueId base) {
  ValueId a = base == kNoValue ? f.const_b(true) : base;
  const auto remove = [&](const std::string& key) {
    auto it = env.find(key);
    if (it != env.end()) a = and_(a, not_(it->second[0]));
  };
  if (!fns.empty()) {
    if (loops.size() > fns.back().loop_base) {
      remove(loops.back().brk);
      remove(loops.back().cont);
    }
    remove(fns.back().ret);
  }
  if (has_kill) remove("$kill");
  active = (base == kNoValue && is_true(f, a)) ? kNoValue : a;
}

bool Lowerer::stmt(TIntermNode* n) {
  if (!n || !result.error.empty()) return false;
  if (++lowered_nodes > kMaxLoweredNodes) {
    fail("the program is too large once its functions are inlined");
    return false;
  }
  if (auto* a = n->getAsAggregate()) {
    switch (a->getOp()) {
    case EOpSequence:
    case EOpScope:
      return stmt_list(n);
    case EOpFunction:
    case EOpLinkerObjects:
    case EOpParameters:
      return false;
    default:
      expr(a);
      return false;
    }
  }
  if (auto* s = n->getAsSelectionNode()) {
    if (s->getBasicType() == EbtVoid) return if_stmt(s);
    expr(s);
    return false;
  }
  if (auto* l = n->getAsLoopNode()) {
    loop_stmt(l);
    return false;
  }
  if (auto* b = n->getAsBranchNode()) return branch(b);
  if (n->getAsSwitchNode()) {
    fail("switch statements are not part of GLSL 1.20");
    return false;
  }
  if (auto* t = n->getAsTyped()) expr(t);
  return false;
}

bool Lowerer::stmt_list(TIntermNode* n) {
  auto* a = n ? n->getAsAggregate() : nullptr;
  if (!a || (a->getOp() != EOpSequence && a->getOp() != EOpScope)) return stmt(n);
  const ValueId base = active;
  for (TIntermNode* c : a->getSequence()) {
    if (!result.error.empty()) return false;
    if (stmt(c)) return true;
    if (jumps(c)) {
      recompute_active(base);
      if (active != kNoValue && is_false(f, active)) return true;
    }
  }
  return false;
}

bool Lowerer::region(ValueId cond, bool uniform, ValueId inner_active,
                     const std::function<bool()>& body) {
  if (cond != kNoValue && is_false(f, cond)) return false;
  const auto snapshot = env;
  const uint32_t ri = f.add_region();
  shader::Region& g = f.regions[ri];
  g.cond = cond == kNoValue ? f.const_b(true) : cond;
  g.uniform = uniform;
  Block* saved_cur = cur;
  const ValueId saved_active = active;
  cur = &g.body;
  active = inner_active;
  const bool term = body();
  cur = saved_cur;
  active = saved_active;
  std::vector<std::string> gone;
  for (auto& [key, comps] : env) {
    auto it = snapshot.find(key);
    if (it == snapshot.end()) {
      gone.push_back(key);
      continue;
    }
    for (size_t k = 0; k < comps.size() && k < it->second.size(); ++k) {
      if (comps[k] == it->second[k] || is_sampler(comps[k])) continue;
      const ValueId phi = f.phi(f.type(comps[k]));
      g.outs.push_back({phi, comps[k], it->second[k]});
      comps[k] = phi;
    }
  }
  for (const std::string& k : gone)
    env.erase(k);
  cur->push_back({shader::NodeKind::Region, ri});
  return term;
}

bool Lowerer::if_stmt(TIntermSelection* s) {
  const ValueId c = expr(s->getCondition())[0];
  if (!result.error.empty()) return false;
  // A constant condition: only the branch taken is lowered (the static checks of
  // checks.cpp have seen the other).
  if (f.is_const(c)) return stmt_list(f.const_bits(c) ? s->getTrueBlock() : s->getFalseBlock());
  prescan_locals(s->getTrueBlock());
  prescan_locals(s->getFalseBlock());
  const bool uniform = is_uniform(c);
  const ValueId base = active;
  // A uniform condition selects whole runs: its branches keep the lane mask they have.
  const auto branch_region = [&](ValueId cond_lanes, TIntermNode* body) {
    if (!body) return false;
    const ValueId cond = uniform ? cond_lanes : and_(active_value(), cond_lanes);
    return region(cond, uniform, uniform ? active : cond, [&] { return stmt_list(body); });
  };
  const bool t = branch_region(c, s->getTrueBlock());
  const bool e = s->getFalseBlock() ? branch_region(not_(c), s->getFalseBlock()) : false;
  if (jumps(s)) recompute_active(base);
  return t && e;
}

bool Lowerer::branch(TIntermBranch* b) {
  const auto add = [&](const std::string& key) {
    Comps& m = env[key];
    if (m.empty()) m.push_back(f.const_b(false));
    m[0] = or_(m[0], active_value());
  };
  switch (b->getFlowOp()) {
  case EOpKill:
    if (stage != shader::Stage::Fragment) {
      fail("discard outside a fragment shader");
      return false;
    }
    add("$kill");
    return true;
  case EOpBreak:
    if (loops.empty()) return false;
    add(loops.back().brk);
    return true;
  case EOpContinue:
    if (loops.empty()) return false;
    add(loops.back().cont);
    return true;
  case EOpReturn: {
    // The expression may call functions (which push frames): the frame is looked at after it.
    const Comps v = b->getExpression() ? expr(b->getExpression()) : Comps{};
    const FnCtx fn = fns.back();
    if (b->getExpression()) {
      Comps& rv = env[fn.retval];
      rv.resize(v.size(), kNoValue);
      for (size_t k = 0; k < v.size(); ++k) {
        if (rv[k] == kNoValue || is_sampler(v[k]))
          rv[k] = v[k];
        else
          assign_comp(rv, k, v[k]);
      }
    }
    add(fn.ret);
    return true;
  }
  default:
    fail("unsupported jump");
    return false;
  }
}

// ---- loops ----

void Lowerer::loop_stmt(TIntermLoop* l) {
  if (try_unroll(l)) return;
  prescan_locals(l->getTest());
  prescan_locals(l->getBody());
  prescan_locals(l->getTerminal());
  const ValueId outer_active = active;
  const uint32_t li = f.add_loop();
  shader::Loop& lp = f.loops[li];
  // Every variable is carried by a phi; the passes drop the ones the loop does not change.
  std::vector<std::string> keys;
  for (auto& [key, comps] : env)
    keys.push_back(key);
  std::sort(keys.begin(), keys.end());
  struct Slot {
    std::string key;
    size_t k;
  };
  std::vector<Slot> slots;
  for (const std::string& key : keys) {
    Comps& comps = env[key];
    for (size_t k = 0; k < comps.size(); ++k) {
      if (is_sampler(comps[k]) || comps[k] == kNoValue) continue;
      const ValueId phi = f.phi(f.type(comps[k]));
      lp.phis.push_back({phi, comps[k], kNoValue});
      comps[k] = phi;
      slots.push_back({key, k});
    }
  }
  const ValueId lm = f.phi(Type::Bool);
  lp.phis.push_back({lm, active_value(), kNoValue});
  Block* saved_cur = cur;
  cur = &lp.body;
  const std::string n = std::to_string(serial++);
  loops.push_back({"$brk" + n, "$cont" + n});
  env[loops.back().brk] = {f.const_b(false)};
  env[loops.back().cont] = {f.const_b(false)};
  std::vector<ValueId> exit_values;
  const auto exit_here = [&](ValueId mask) {
    f.emit(*cur, Op::ExitIfNone, Type::Bool, mask);
    for (const Slot& s : slots)
      exit_values.push_back(env[s.key][s.k]);
  };
  // Lanes still iterating after the body: not broken, returned or discarded.
  const auto staying = [&](ValueId from) {
    ValueId a = and_(from, not_(env[loops.back().brk][0]));
    if (!fns.empty()) a = and_(a, not_(env[fns.back().ret][0]));
    if (has_kill) a = and_(a, not_(env["$kill"][0]));
    return a;
  };
  ValueId next_mask;
  if (l->testFirst()) {
    active = lm;
    const ValueId c = l->getTest() ? expr(l->getTest())[0] : f.const_b(true);
    const ValueId lm1 = and_(lm, c);
    exit_here(lm1);
    active = lm1;
    stmt_list(l->getBody());
    active = staying(lm1);
    next_mask = active;
    if (l->getTerminal()) expr(l->getTerminal());
  } else {
    active = lm;
    stmt_list(l->getBody());
    active = staying(lm);
    const ValueId c = l->getTest() ? expr(l->getTest())[0] : f.const_b(true);
    next_mask = and_(active, c);
    exit_here(next_mask);
  }
  for (size_t i = 0; i < slots.size(); ++i)
    lp.phis[i].next = env[slots[i].key][slots[i].k];
  lp.phis.back().next = next_mask;
  env.erase(loops.back().brk);
  env.erase(loops.back().cont);
  loops.pop_back();
  cur = saved_cur;
  // After the loop every variable has the value it had when the loop ended.
  std::unordered_set<std::string> carried;
  for (size_t i = 0; i < slots.size(); ++i) {
    const ValueId out = f.phi(f.type(exit_values[i]));
    lp.exits.push_back({out, exit_values[i]});
    env[slots[i].key][slots[i].k] = out;
    carried.insert(slots[i].key);
  }
  for (auto it = env.begin(); it != env.end();) {
    bool keep = carried.count(it->first) > 0;
    if (!keep) {
      keep = true;
      for (ValueId v : it->second)
        keep = keep && (v == kNoValue || is_sampler(v));
    }
    it = keep ? std::next(it) : env.erase(it);
  }
  cur->push_back({shader::NodeKind::Loop, li});
  recompute_active(outer_active);
}

// for (i = c0; i < c1; i += c2) with a constant start, bound and step, and no other write of
// i: lowered as its iterations one after another, where i is a constant, so that array
// indices (gl_LightSource[i]) become constant and the lanes need no loop mask.
bool Lowerer::try_unroll(TIntermLoop* l) {
  if (!l->testFirst() || !l->getTest() || !l->getTerminal()) return false;
  auto* test = l->getTest()->getAsBinaryNode();
  if (!test) return false;
  TOperator cmp = test->getOp();
  TIntermSymbol* sym = test->getLeft()->getAsSymbolNode();
  TIntermConstantUnion* bound = test->getRight()->getAsConstantUnion();
  if (!sym || !bound) {
    sym = test->getRight()->getAsSymbolNode();
    bound = test->getLeft()->getAsConstantUnion();
    switch (cmp) {
    case EOpLessThan:
      cmp = EOpGreaterThan;
      break;
    case EOpGreaterThan:
      cmp = EOpLessThan;
      break;
    case EOpLessThanEqual:
      cmp = EOpGreaterThanEqual;
      break;
    case EOpGreaterThanEqual:
      cmp = EOpLessThanEqual;
      break;
    default:
      break;
    }
  }
  if (!sym || !bound || !sym->getType().isScalar()) return false;
  if (!is_local_storage(sym->getQualifier().storage)) return false;
  const TBasicType bt = sym->getBasicType();
  if (bt != EbtInt && bt != EbtFloat) return false;
  const std::string key = key_of(sym);
  auto it = env.find(key);
  if (it == env.end() || !f.is_const(it->second[0])) return false;
  // The step.
  uint32_t step = 0;
  bool add = true;
  TIntermNode* term = l->getTerminal();
  const auto same = [&](TIntermTyped* t) {
    auto* s = t ? t->getAsSymbolNode() : nullptr;
    return s && s->getId() == sym->getId();
  };
  const Type t = bt == EbtInt ? Type::Int : Type::Float;
  const uint32_t one = t == Type::Int ? 1u : 0x3f800000u;
  if (auto* u = term->getAsUnaryNode()) {
    if (!same(u->getOperand())) return false;
    switch (u->getOp()) {
    case EOpPostIncrement:
    case EOpPreIncrement:
      step = one;
      break;
    case EOpPostDecrement:
    case EOpPreDecrement:
      step = one, add = false;
      break;
    default:
      return false;
    }
  } else if (auto* b = term->getAsBinaryNode()) {
    auto* c = b->getRight()->getAsConstantUnion();
    if (!same(b->getLeft()) || !c || (b->getOp() != EOpAddAssign && b->getOp() != EOpSubAssign))
      return false;
    step = f.const_bits(constant(c->getConstArray(), c->getType())[0]);
    add = b->getOp() == EOpAddAssign;
  } else {
    return false;
  }
  if (writes_symbol(l->getBody(), sym->getId())) return false;
  shader::LaneOp cmp_op, step_op;
  switch (cmp) {
  case EOpLessThan:
    cmp_op = t == Type::Int ? shader::LaneOp::ILt : shader::LaneOp::FLt;
    break;
  case EOpGreaterThan:
    cmp_op = t == Type::Int ? shader::LaneOp::IGt : shader::LaneOp::FGt;
    break;
  case EOpLessThanEqual:
    cmp_op = t == Type::Int ? shader::LaneOp::ILe : shader::LaneOp::FLe;
    break;
  case EOpGreaterThanEqual:
    cmp_op = t == Type::Int ? shader::LaneOp::IGe : shader::LaneOp::FGe;
    break;
  case EOpNotEqual:
    cmp_op = t == Type::Int ? shader::LaneOp::INe : shader::LaneOp::FNe;
    break;
  default:
    return false;
  }
  step_op = t == Type::Int ? (add ? shader::LaneOp::IAdd : shader::LaneOp::ISub)
                           : (add ? shader::LaneOp::FAdd : shader::LaneOp::FSub);
  const uint32_t limit = f.const_bits(constant(bound->getConstArray(), sym->getType())[0]);
  std::vector<uint32_t> values;
  uint32_t v = f.const_bits(it->second[0]);
  while (shader::eval_lane_op(cmp_op, v, limit, 0) != 0) {
    values.push_back(v);
    if (values.size() > 64) return false;
    v = shader::eval_lane_op(step_op, v, step, 0);
  }
  const long cost = static_cast<long>(values.size()) * node_count(l->getBody());
  if (cost > unroll_budget) return false;
  unroll_budget -= cost;

  prescan_locals(l->getBody());
  const ValueId outer = active;
  const std::string n = std::to_string(serial++);
  loops.push_back({"$brk" + n, "$cont" + n});
  env[loops.back().brk] = {f.const_b(false)};
  const bool jump = jumps(l->getBody());
  for (size_t i = 0; i < values.size(); ++i) {
    env[key][0] = f.constant(t, values[i]);
    env[loops.back().cont] = {f.const_b(false)};
    recompute_active(outer);
    if (active != kNoValue && is_false(f, active)) break;
    if (jump && i > 0) {
      // Later iterations are skipped once every lane has left the loop.
      const ValueId a = active_value();
      region(a, is_uniform(a), active, [&] { return stmt_list(l->getBody()); });
    } else {
      stmt_list(l->getBody());
    }
  }
  env[key][0] = f.constant(t, v);
  env.erase(loops.back().brk);
  env.erase(loops.back().cont);
  loops.pop_back();
  recompute_active(outer);
  return true;
}

// ---- functions ----

Comps Lowerer::call(TIntermAggregate* a) {
  const std::string name = a->getName().c_str();
  auto it = functions.find(name);
  std::vector<Type> rt;
  flat_types(a->getType(), rt);
  Comps zeros;
  for (Type t : rt)
    zeros.push_back(t == kSamplerType ? kNoValue : f.constant(t, 0));
  if (it == functions.end()) {
    fail("function " + name.substr(0, name.find('(')) + " is declared but not defined");
    return zeros;
  }
  // GLSL 1.10 §6.1: recursion is not allowed (glslang does not check it for desktop GLSL).
  if (std::find(call_stack.begin(), call_stack.end(), name) != call_stack.end() ||
      fns.size() > 256) {
    fail("function " + name.substr(0, name.find('(')) + " calls itself (recursion)");
    return zeros;
  }
  TIntermAggregate* def = it->second;
  TIntermSequence& dseq = def->getSequence();
  TIntermAggregate* params = dseq.empty() ? nullptr : dseq[0]->getAsAggregate();
  TIntermNode* body = dseq.size() > 1 ? dseq[1] : nullptr;
  TIntermSequence& args = a->getSequence();
  const size_t np = params ? params->getSequence().size() : 0;
  std::vector<Comps> in(np);
  std::vector<Ref> outs(np);
  std::vector<uint8_t> writes(np, 0);
  for (size_t i = 0; i < np && i < args.size(); ++i) {
    TIntermSymbol* p = params->getSequence()[i]->getAsSymbolNode();
    TIntermTyped* arg = args[i]->getAsTyped();
    const TStorageQualifier q = p ? p->getQualifier().storage : EvqIn;
    if (q == EvqOut || q == EvqInOut) {
      outs[i] = ref(arg);
      writes[i] = 1;
      if (q == EvqInOut) {
        in[i] = load(outs[i]);
      } else {
        std::vector<Type> pt;
        flat_types(p->getType(), pt);
        for (Type t : pt)
          in[i].push_back(f.constant(t, 0));
      }
    } else {
      in[i] = expr(arg);
    }
  }
  FnCtx ctx;
  const std::string n = std::to_string(serial++);
  ctx.ret = "$ret" + n;
  ctx.retval = "$rv" + n;
  ctx.loop_base = loops.size();
  env[ctx.ret] = {f.const_b(false)};
  env[ctx.retval] = zeros;
  for (size_t i = 0; i < np; ++i) {
    TIntermSymbol* p = params->getSequence()[i]->getAsSymbolNode();
    if (!p) continue;
    const std::string key = key_of(p);
    env[key] = in[i];
    ctx.locals.push_back(key);
  }
  fns.push_back(ctx);
  call_stack.push_back(name);
  const ValueId saved_active = active;
  stmt_list(body);
  call_stack.pop_back();
  FnCtx done = fns.back();
  fns.pop_back();
  active = saved_active;
  Comps res = env[done.retval];
  for (size_t i = 0; i < np; ++i) {
    if (!writes[i]) continue;
    TIntermSymbol* p = params->getSequence()[i]->getAsSymbolNode();
    if (p) store(outs[i], env[key_of(p)]);
  }
  for (const std::string& k : done.locals)
    env.erase(k);
  env.erase(done.ret);
  env.erase(done.retval);
  return res;
}

// ---- the stage ----

bool Lowerer::run() {
  TIntermAggregate* root = ast.getTreeRoot() ? ast.getTreeRoot()->getAsAggregate() : nullptr;
  if (!root) {
    fail("no code");
    return false;
  }
  TIntermAggregate* main_fn = nullptr;
  TIntermAggregate* linker_objects = nullptr;
  for (TIntermNode* c : root->getSequence()) {
    auto* a = c->getAsAggregate();
    if (!a) continue;
    if (a->getOp() == EOpFunction) {
      functions[a->getName().c_str()] = a;
      if (std::string(a->getName().c_str()).rfind("main(", 0) == 0) main_fn = a;
    } else if (a->getOp() == EOpLinkerObjects) {
      linker_objects = a;
    }
  }
  if (!main_fn) {
    fail("no main()");
    return false;
  }
  // Every walk of the tree below recurses: a tree deeper than this (a sum of thousands of
  // terms) is refused first.
  if (tree_depth(root) > kMaxExprDepth) {
    fail("an expression is nested more than " + std::to_string(kMaxExprDepth) + " deep");
    return false;
  }
  has_kill = contains_kill(root);
  cur = &f.body;
  FnCtx main_ctx;
  main_ctx.ret = "$ret_main";
  main_ctx.retval = "$rv_main";
  fns.push_back(main_ctx);
  env[main_ctx.ret] = {f.const_b(false)};
  if (has_kill) env["$kill"] = {f.const_b(false)};

  // Globals and outputs start at zero (their value is undefined until written); the
  // built-in outputs are all there so that any of them can be assigned in a branch.
  const auto zero_var = [&](const std::string& name, const TType& t, bool output) {
    std::vector<Type> ts;
    flat_types(t, ts);
    Comps c;
    for (Type x : ts)
      c.push_back(x == kSamplerType ? kNoValue : f.constant(x, 0));
    env[name] = c;
    if (output) outputs.insert(name);
  };
  if (linker_objects) {
    for (TIntermNode* c : linker_objects->getSequence()) {
      auto* s = c->getAsSymbolNode();
      if (!s) continue;
      const TStorageQualifier q = s->getQualifier().storage;
      // A global is an output only for the constant evaluator (const_eval.cpp).
      if (q == EvqGlobal)
        zero_var(s->getName().c_str(), s->getType(), lenv.output(s->getName().c_str(), 0) >= 0);
      if (q == EvqVaryingOut) zero_var(s->getName().c_str(), s->getType(), true);
    }
  }
  const auto builtin_out = [&](const char* name, int comps) {
    if (env.count(name)) {
      outputs.insert(name);
      if (static_cast<int>(env[name].size()) < comps)
        env[name].resize(static_cast<size_t>(comps), f.const_f(0.0f));
      return;
    }
    env[name] = Comps(static_cast<size_t>(comps), f.const_f(0.0f));
    outputs.insert(name);
  };
  if (stage == shader::Stage::Vertex) {
    builtin_out("gl_Position", 4);
    builtin_out("gl_PointSize", 1);
    builtin_out("gl_ClipVertex", 4);
    builtin_out("gl_FrontColor", 4);
    builtin_out("gl_BackColor", 4);
    builtin_out("gl_FrontSecondaryColor", 4);
    builtin_out("gl_BackSecondaryColor", 4);
    builtin_out("gl_TexCoord", 4 * shader::kMaxTextureCoords);
    builtin_out("gl_FogFragCoord", 1);
  } else {
    builtin_out("gl_FragColor", 4);
    builtin_out("gl_FragData", 4 * shader::kMaxDrawBuffers);
    builtin_out("gl_FragDepth", 1);
    // Unless the shader writes it, gl_FragDepth is the fragment's depth (GL 2.1 §3.11.2).
    const int z = lenv.input("gl_FragCoord", 2);
    if (z >= 0) env["gl_FragDepth"][0] = f.input(Type::Float, z);
  }
  // Global initializers, in the order of the source.
  for (TIntermNode* c : root->getSequence()) {
    auto* a = c->getAsAggregate();
    if (a && (a->getOp() == EOpFunction || a->getOp() == EOpLinkerObjects)) continue;
    stmt(c);
  }
  TIntermSequence& mseq = main_fn->getSequence();
  if (mseq.size() > 1) stmt_list(mseq[1]);
  if (!result.error.empty()) return false;

  std::vector<std::string> outs(outputs.begin(), outputs.end());
  std::sort(outs.begin(), outs.end());
  for (const std::string& name : outs) {
    if (!result.written.count(name)) continue;
    const Comps& c = env[name];
    for (size_t k = 0; k < c.size(); ++k) {
      const int id = lenv.output(name, static_cast<int>(k));
      if (id < 0 || c[k] == kNoValue || is_sampler(c[k])) continue;
      f.emit_imm(f.body, Op::StoreOutput, f.type(c[k]), id, 0, 0, c[k]);
    }
  }
  if (has_kill)
    f.emit_imm(f.body, Op::StoreOutput, Type::Bool, shader::kKillOutput, 0, 0, env["$kill"][0]);
  return true;
}

bool lower_stage(const TIntermediate& stage_ast, shader::Stage stage, const LowerEnv& env,
                 Function& out, LowerResult& result) {
  Lowerer l(stage_ast, stage, env, out, result);
  return l.run() && result.error.empty();
}

} // namespace pineda::glsl
