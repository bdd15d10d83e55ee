// Lowering: variables, references (indexing, members, swizzles), operators and constructors.
#include <glslang/MachineIndependent/localintermediate.h>

#include <bit>

#include "glsl/lower_internal.h"

namespace pineda::glsl {

using namespace glslang;

Type ir_type(TBasicType b) {
  switch (b) {
  case EbtFloat:
  case EbtDouble:
    return Type::Float;
  case EbtBool:
    return Type::Bool;
  case EbtSampler:
    return kSamplerType;
  default:
    return Type::Int;
  }
}

int array_size(const TType& t) {
  if (!t.isArray()) return 1;
  int n = t.getOuterArraySize();
  if (n <= 0 && t.getArraySizes()) n = t.getArraySizes()->getImplicitSize();
  return n > 0 ? n : 1;
}

void flat_types(const TType& t, std::vector<Type>& out) {
  if (t.isArray()) {
    const TType e(t, 0);
    const int n = array_size(t);
    for (int i = 0; i < n; ++i)
      flat_types(e, out);
    return;
  }
  if (t.isStruct()) {
    for (const TTypeLoc& m : *t.getStruct())
      flat_types(*m.type, out);
    return;
  }
  const int n = t.isMatrix() ? t.getMatrixCols() * t.getMatrixRows() : t.getVectorSize();
  const Type it = ir_type(t.getBasicType());
  for (int i = 0; i < n; ++i)
    out.push_back(it);
}

int component_count(const TType& t) {
  std::vector<Type> ts;
  flat_types(t, ts);
  return static_cast<int>(ts.size());
}

namespace {

bool is_input_storage(TStorageQualifier q) {
  return q == EvqVaryingIn || q == EvqFragCoord || q == EvqFace || q == EvqPointCoord ||
         q == EvqVertexId || q == EvqInstanceId;
}

int const_int(Lowerer& L, TIntermTyped* t, bool& ok) {
  ok = false;
  if (auto* c = t->getAsConstantUnion()) {
    ok = true;
    return c->getConstArray()[0].getIConst();
  }
  const ValueId v = L.expr(t)[0];
  if (L.f.is_const(v)) {
    ok = true;
    return static_cast<int32_t>(L.f.const_bits(v));
  }
  return 0;
}

} // namespace

// ---- variables ----

std::string Lowerer::key_of(const TIntermSymbol* s) const {
  const TStorageQualifier q = s->getQualifier().storage;
  if (q == EvqTemporary || q == EvqIn || q == EvqOut || q == EvqInOut || q == EvqConstReadOnly)
    return std::string(1, '#').append(std::to_string(s->getId()));
  return s->getName().c_str();
}

Comps& Lowerer::var(const TIntermSymbol* s) {
  const std::string key = key_of(s);
  auto it = env.find(key);
  if (it != env.end()) return it->second;
  // A variable read before any assignment (its value is undefined): zero.
  std::vector<Type> ts;
  flat_types(s->getType(), ts);
  Comps c;
  for (Type t : ts)
    c.push_back(t == kSamplerType ? kNoValue : f.constant(t, 0));
  if (!fns.empty() && key[0] == '#') fns.back().locals.push_back(key);
  return env[key] = c;
}

Comps Lowerer::constant(const TConstUnionArray& c, const TType& t) {
  std::vector<Type> ts;
  flat_types(t, ts);
  Comps out;
  for (size_t k = 0; k < ts.size(); ++k) {
    if (static_cast<int>(k) >= c.size()) {
      out.push_back(f.constant(ts[k], 0));
      continue;
    }
    const TConstUnion& u = c[static_cast<int>(k)];
    double d = 0;
    int32_t i = 0;
    bool b = false;
    switch (u.getType()) {
    case EbtFloat:
    case EbtDouble:
      // As the engine's F2I (vmath.h f2i): NaN gives 0, out-of-range values saturate (a
      // folded constant such as inversesqrt(0.0) or an overflow must not be a cast's UB).
      d = u.getDConst(), b = d != 0;
      i = d != d               ? 0
          : d <= -2147483648.0 ? INT32_MIN
          : d >= 2147483520.0  ? 2147483520
                               : static_cast<int32_t>(d);
      break;
    case EbtBool:
      b = u.getBConst(), d = b ? 1 : 0, i = b;
      break;
    case EbtUint:
      i = static_cast<int32_t>(u.getUConst()), d = u.getUConst(), b = i != 0;
      break;
    default:
      i = u.getIConst(), d = i, b = i != 0;
      break;
    }
    switch (ts[k]) {
    case Type::Float:
      out.push_back(f.const_f(static_cast<float>(d)));
      break;
    case Type::Bool:
      out.push_back(f.const_b(b));
      break;
    default:
      out.push_back(f.const_i(i));
      break;
    }
  }
  return out;
}

// ---- references ----

Ref Lowerer::ref(TIntermTyped* n) {
  Ref r;
  if (auto* s = n->getAsSymbolNode()) {
    const TType& t = s->getType();
    flat_types(t, r.root_types);
    r.count = static_cast<int>(r.root_types.size());
    const TStorageQualifier q = s->getQualifier().storage;
    const std::string name = s->getName().c_str();
    if (q == EvqUniform) {
      r.uniform = true;
      r.uniform_base = lenv.uniform_word(name, t);
    } else if (q == EvqConst && s->getConstArray().size() > 0) {
      r.root = constant(s->getConstArray(), t);
    } else if (is_input_storage(q)) {
      for (int k = 0; k < r.count; ++k) {
        const int id = lenv.input(name, k);
        const Type ct = r.root_types[static_cast<size_t>(k)];
        r.root.push_back(id >= 0 ? f.input(ct, id) : f.constant(ct, 0));
      }
    } else {
      r.key = key_of(s);
      r.root = var(s);
    }
    return r;
  }
  auto* b = n->getAsBinaryNode();
  const TOperator o = b ? b->getOp() : EOpNull;
  if (!b || (o != EOpIndexDirect && o != EOpIndexIndirect && o != EOpIndexDirectStruct &&
             o != EOpVectorSwizzle)) {
    r.root = expr(n);
    flat_types(n->getType(), r.root_types);
    r.count = static_cast<int>(r.root.size());
    return r;
  }
  r = ref(b->getLeft());
  const TType& lt = b->getLeft()->getType();
  if (o == EOpIndexDirectStruct) {
    const int idx = b->getRight()->getAsConstantUnion()->getConstArray()[0].getIConst();
    int offset = 0;
    const TTypeList& members = *lt.getStruct();
    for (int i = 0; i < idx; ++i)
      offset += component_count(*members[static_cast<size_t>(i)].type);
    r.base += offset;
    r.count = component_count(*members[static_cast<size_t>(idx)].type);
    return r;
  }
  if (o == EOpVectorSwizzle) {
    std::vector<int> sel;
    for (TIntermNode* c : b->getRight()->getAsAggregate()->getSequence())
      sel.push_back(c->getAsConstantUnion()->getConstArray()[0].getIConst());
    if (r.swz.empty()) {
      r.swz = sel;
    } else {
      std::vector<int> composed;
      for (int i : sel)
        composed.push_back(r.swz[static_cast<size_t>(i)]);
      r.swz = composed;
    }
    return r;
  }
  // Array element, matrix column or vector component.
  int esize = 1, n_el = lt.getVectorSize();
  if (lt.isArray()) {
    esize = component_count(TType(lt, 0));
    n_el = array_size(lt);
  } else if (lt.isMatrix()) {
    esize = lt.getMatrixRows();
    n_el = lt.getMatrixCols();
  }
  bool is_const = false;
  const int i = const_int(*this, b->getRight(), is_const);
  if (!r.swz.empty()) {
    // A component of a swizzle: constant, or one of the swizzle's components.
    if (is_const) {
      r.swz = {r.swz[static_cast<size_t>(std::clamp(i, 0, static_cast<int>(r.swz.size()) - 1))]};
      return r;
    }
    if (r.uniform) {
      // Uniforms are read-only: the swizzled values are the root.
      Ref t;
      t.root = load(r);
      t.root_types.assign(t.root.size(), f.type(t.root[0]));
      t.count = static_cast<int>(t.root.size());
      n_el = t.count;
      r = t;
    } else {
      Ref::Dyn d{expr(b->getRight())[0], 0, static_cast<int>(r.swz.size()), r.swz};
      r.swz.clear();
      r.dyn.push_back(d);
      r.count = 1;
      return r;
    }
  }
  if (is_const) {
    r.base += std::clamp(i, 0, n_el - 1) * esize;
  } else {
    r.dyn.push_back({expr(b->getRight())[0], esize, n_el});
  }
  r.count = esize;
  return r;
}

ValueId Lowerer::pick(const Comps& cands, ValueId index) {
  ValueId r = cands[0];
  for (size_t k = 1; k < cands.size(); ++k)
    r = select(op(Op::Eq, Type::Bool, index, f.const_i(static_cast<int32_t>(k))), cands[k], r);
  return r;
}

namespace {

// The combined offset of a reference's dynamic indices as a value, clamped index by index (for
// uniform gathers, whose indices are strides).
ValueId dyn_offset_value(Lowerer& L, const Ref& r, int& extent) {
  ValueId value = kNoValue;
  extent = 1;
  for (const Ref::Dyn& x : r.dyn) {
    ValueId idx = L.op(Op::Max, Type::Int, x.index, L.f.const_i(0));
    idx = L.op(Op::Min, Type::Int, idx, L.f.const_i(x.count - 1));
    const ValueId term = L.op(Op::Mul, Type::Int, idx, L.f.const_i(x.stride));
    value = value == kNoValue ? term : L.op(Op::Add, Type::Int, value, term);
    extent += (x.count - 1) * x.stride;
  }
  return value;
}

// Every combination of a reference's dynamic indices: the condition selecting it and the
// offset it adds. An index out of its array's range selects nothing (GLSL leaves it undefined).
struct DynCase {
  ValueId cond;
  int offset;
};
std::vector<DynCase> dyn_cases(Lowerer& L, const Ref& r) {
  std::vector<DynCase> cases{{L.f.const_b(true), 0}};
  for (const Ref::Dyn& x : r.dyn) {
    std::vector<DynCase> next;
    for (const DynCase& c : cases)
      for (int i = 0; i < x.count; ++i)
        next.push_back({L.and_(c.cond, L.op(Op::Eq, Type::Bool, x.index, L.f.const_i(i))),
                        c.offset + x.offset(i)});
    cases = std::move(next);
  }
  return cases;
}

} // namespace

Comps Lowerer::load(const Ref& r) {
  const int n = r.size();
  Comps out(static_cast<size_t>(n), kNoValue);
  if (r.uniform) {
    for (int k = 0; k < n; ++k) {
      const int off = r.comp(k);
      const Type t = r.root_types[static_cast<size_t>(off)];
      const int word = r.uniform_base + off;
      if (t == kSamplerType) {
        if (!r.dyn.empty()) fail("sampler arrays may only be indexed by constant expressions");
        out[static_cast<size_t>(k)] = kSamplerTag | static_cast<uint32_t>(word);
      } else if (r.dyn.empty()) {
        out[static_cast<size_t>(k)] = f.uniform(t, word);
      } else if (r.dyn.size() == 1) {
        ValueId idx = r.dyn[0].index;
        out[static_cast<size_t>(k)] =
            f.emit_imm(*cur, Op::UniformIndexed, t, word, r.dyn[0].stride, r.dyn[0].count, idx);
      } else {
        int extent = 1;
        const ValueId offset = dyn_offset_value(*this, r, extent);
        out[static_cast<size_t>(k)] =
            f.emit_imm(*cur, Op::UniformIndexed, t, word, 1, extent, offset);
      }
    }
    return out;
  }
  if (r.dyn.empty()) {
    for (int k = 0; k < n; ++k)
      out[static_cast<size_t>(k)] = r.root[static_cast<size_t>(r.comp(k))];
    return out;
  }
  const std::vector<DynCase> cases = dyn_cases(*this, r);
  for (int k = 0; k < n; ++k) {
    const auto cand = [&](size_t j) {
      const size_t at = static_cast<size_t>(r.comp(k) + cases[j].offset);
      return at < r.root.size() ? r.root[at] : r.root.back();
    };
    ValueId v = cand(0);
    for (size_t j = 1; j < cases.size(); ++j)
      v = select(cases[j].cond, cand(j), v);
    out[static_cast<size_t>(k)] = v;
  }
  return out;
}

void Lowerer::assign_comp(Comps& dst, size_t k, ValueId v) {
  if (k >= dst.size()) dst.resize(k + 1, kNoValue);
  if (active == kNoValue || dst[k] == kNoValue || is_sampler(v) || is_sampler(dst[k]))
    dst[k] = v;
  else
    dst[k] = select(active, v, dst[k]);
}

void Lowerer::store(const Ref& r, const Comps& v) {
  if (r.key.empty()) {
    fail("assignment to something that is not a variable");
    return;
  }
  if (outputs.count(r.key)) result.written.insert(r.key);
  Comps& dst = env[r.key];
  const int n = r.size();
  // Values take the destination's type (out parameters convert on the way back, GLSL 1.20
  // §6.1.1).
  Comps cv = v;
  for (int k = 0; k < n && k < static_cast<int>(cv.size()); ++k) {
    const size_t at = static_cast<size_t>(r.comp(k));
    if (at < r.root_types.size() && r.root_types[at] != kSamplerType &&
        !is_sampler(cv[static_cast<size_t>(k)]) && cv[static_cast<size_t>(k)] != kNoValue &&
        f.type(cv[static_cast<size_t>(k)]) != r.root_types[at])
      cv[static_cast<size_t>(k)] = convert(cv[static_cast<size_t>(k)], r.root_types[at]);
  }
  if (r.dyn.empty()) {
    for (int k = 0; k < n && k < static_cast<int>(cv.size()); ++k)
      assign_comp(dst, static_cast<size_t>(r.comp(k)), cv[static_cast<size_t>(k)]);
    return;
  }
  for (const DynCase& c : dyn_cases(*this, r)) {
    const ValueId hit = and_(active_value(), c.cond);
    for (int k = 0; k < n && k < static_cast<int>(cv.size()); ++k) {
      const size_t at = static_cast<size_t>(r.comp(k) + c.offset);
      if (at >= dst.size()) continue;
      dst[at] = select(hit, cv[static_cast<size_t>(k)], dst[at]);
    }
  }
}

// ---- expressions ----

ValueId Lowerer::convert(ValueId v, Type to) {
  const Type from = f.type(v);
  if (from == to) return v;
  if (from == Type::Float) return op(to == Type::Int ? Op::F2I : Op::F2B, to, v);
  if (from == Type::Int) return op(to == Type::Float ? Op::I2F : Op::I2B, to, v);
  return op(to == Type::Float ? Op::B2F : Op::B2I, to, v);
}

Comps Lowerer::componentwise(Op o, Type t, const Comps& a, const Comps& b) {
  const size_t n = std::max(a.size(), b.size());
  Comps out(n);
  for (size_t k = 0; k < n; ++k) {
    const ValueId x = a.size() == 1 ? a[0] : a[k];
    const ValueId y = b.size() == 1 ? b[0] : b[k];
    out[k] = op(o, t, x, y);
  }
  return out;
}

Comps Lowerer::expr(TIntermTyped* n) {
  if (!n) return {};
  // The lowering recurses with the expression's depth: a deeper one (a sum of thousands of
  // terms) is refused before it exhausts the stack.
  struct Depth {
    int& d;
    explicit Depth(int& x) : d(++x) {}
    ~Depth() { --d; }
  } depth_guard(expr_depth);
  if (expr_depth > kMaxExprDepth)
    fail("an expression is nested more than " + std::to_string(kMaxExprDepth) + " deep");
  if (++lowered_nodes > kMaxLoweredNodes)
    fail("the program is too large once its functions are inlined");
  if (!result.error.empty()) {
    std::vector<Type> ts;
    flat_types(n->getType(), ts);
    Comps z;
    for (Type t : ts)
      z.push_back(t == kSamplerType ? kNoValue : f.constant(t, 0));
    return z;
  }
  if (auto* c = n->getAsConstantUnion()) return constant(c->getConstArray(), c->getType());
  if (n->getAsSymbolNode()) return load(ref(n));
  if (auto* b = n->getAsBinaryNode()) return binary(b);
  if (auto* u = n->getAsUnaryNode()) return unary(u);
  if (auto* a = n->getAsAggregate()) return aggregate(a);
  if (auto* s = n->getAsSelectionNode()) {
    const ValueId c = expr(s->getCondition())[0];
    auto* tb = s->getTrueBlock()->getAsTyped();
    auto* fb = s->getFalseBlock()->getAsTyped();
    if (f.is_const(c)) return expr(f.const_bits(c) ? tb : fb);
    Comps t, e;
    if (side_effects(tb) || side_effects(fb)) {
      // Only the selected expression is evaluated (GLSL 1.20 §5.9): the other one's
      // assignments are masked off.
      const ValueId saved = active;
      active = and_(active_value(), c);
      t = expr(tb);
      active = and_(saved == kNoValue ? f.const_b(true) : saved, not_(c));
      e = expr(fb);
      active = saved;
    } else {
      t = expr(tb);
      e = expr(fb);
    }
    Comps out(t.size());
    for (size_t k = 0; k < t.size() && k < e.size(); ++k)
      out[k] = is_sampler(t[k]) ? t[k] : select(c, t[k], e[k]);
    return out;
  }
  fail("unsupported expression");
  return expr(n); // the error path: zeros of n's type
}

Comps Lowerer::binary(TIntermBinary* b) {
  const TOperator o = b->getOp();
  switch (o) {
  case EOpIndexDirect:
  case EOpIndexIndirect:
  case EOpIndexDirectStruct:
  case EOpVectorSwizzle:
    return load(ref(b));
  case EOpAssign:
  case EOpAddAssign:
  case EOpSubAssign:
  case EOpMulAssign:
  case EOpDivAssign:
  case EOpVectorTimesMatrixAssign:
  case EOpVectorTimesScalarAssign:
  case EOpMatrixTimesScalarAssign:
  case EOpMatrixTimesMatrixAssign:
    return assignment(b);
  case EOpComma:
    expr(b->getLeft());
    return expr(b->getRight());
  case EOpLogicalAnd:
  case EOpLogicalOr: {
    const ValueId l = expr(b->getLeft())[0];
    ValueId r;
    if (side_effects(b->getRight())) {
      // Short-circuit: the right side's effects happen only where the left side did not
      // decide (GLSL 1.20 §5.9).
      const ValueId saved = active;
      active = and_(active_value(), o == EOpLogicalAnd ? l : not_(l));
      r = expr(b->getRight())[0];
      active = saved;
    } else {
      r = expr(b->getRight())[0];
    }
    return {o == EOpLogicalAnd ? and_(l, r) : or_(l, r)};
  }
  case EOpLogicalXor:
    return {op(Op::Xor, Type::Bool, expr(b->getLeft())[0], expr(b->getRight())[0])};
  case EOpEqual:
  case EOpNotEqual: {
    const Comps l = expr(b->getLeft()), r = expr(b->getRight());
    ValueId all = f.const_b(true);
    for (size_t k = 0; k < l.size() && k < r.size(); ++k) {
      if (is_sampler(l[k])) continue;
      all = and_(all, op(Op::Eq, Type::Bool, l[k], r[k]));
    }
    return {o == EOpEqual ? all : not_(all)};
  }
  default:
    return arith(o, b->getLeft()->getType(), expr(b->getLeft()), b->getRight()->getType(),
                 expr(b->getRight()), b->getType());
  }
}

Comps Lowerer::arith(TOperator o, const TType& lt, const Comps& l, const TType& rt, const Comps& r,
                     const TType& result_type) {
  const Type et = ir_type(lt.getBasicType());
  switch (o) {
  case EOpAdd:
    return componentwise(Op::Add, et, l, r);
  case EOpSub:
    return componentwise(Op::Sub, et, l, r);
  case EOpMul:
  case EOpVectorTimesScalar:
  case EOpMatrixTimesScalar:
    return componentwise(Op::Mul, et, l, r);
  case EOpDiv:
    return componentwise(Op::Div, et, l, r);
  case EOpLessThan:
    return componentwise(Op::Lt, Type::Bool, l, r);
  case EOpGreaterThan:
    return componentwise(Op::Gt, Type::Bool, l, r);
  case EOpLessThanEqual:
    return componentwise(Op::Le, Type::Bool, l, r);
  case EOpGreaterThanEqual:
    return componentwise(Op::Ge, Type::Bool, l, r);
  case EOpVectorEqual:
    return componentwise(Op::Eq, Type::Bool, l, r);
  case EOpVectorNotEqual:
    return componentwise(Op::Ne, Type::Bool, l, r);
  case EOpMatrixTimesVector: {
    // res[row] = m[0][row] * v[0] + m[1][row] * v[1] + ..., left to right (as the fixed
    // function transform, so that ftransform() matches it).
    const int cols = lt.getMatrixCols(), rows = lt.getMatrixRows();
    Comps out(static_cast<size_t>(rows));
    for (int row = 0; row < rows; ++row) {
      ValueId acc = kNoValue;
      for (int c = 0; c < cols; ++c) {
        const ValueId p = op(Op::Mul, Type::Float, l[static_cast<size_t>(c * rows + row)],
                             r[static_cast<size_t>(c)]);
        acc = acc == kNoValue ? p : op(Op::Add, Type::Float, acc, p);
      }
      out[static_cast<size_t>(row)] = acc;
    }
    return out;
  }
  case EOpVectorTimesMatrix: {
    const int cols = rt.getMatrixCols(), rows = rt.getMatrixRows();
    Comps out(static_cast<size_t>(cols));
    for (int c = 0; c < cols; ++c) {
      ValueId acc = kNoValue;
      for (int row = 0; row < rows; ++row) {
        const ValueId p = op(Op::Mul, Type::Float, l[static_cast<size_t>(row)],
                             r[static_cast<size_t>(c * rows + row)]);
        acc = acc == kNoValue ? p : op(Op::Add, Type::Float, acc, p);
      }
      out[static_cast<size_t>(c)] = acc;
    }
    return out;
  }
  case EOpMatrixTimesMatrix: {
    const int k_n = lt.getMatrixCols(), rows = lt.getMatrixRows(), cols = rt.getMatrixCols();
    Comps out(static_cast<size_t>(cols * rows));
    for (int c = 0; c < cols; ++c)
      for (int row = 0; row < rows; ++row) {
        ValueId acc = kNoValue;
        for (int i = 0; i < k_n; ++i) {
          const ValueId p = op(Op::Mul, Type::Float, l[static_cast<size_t>(i * rows + row)],
                               r[static_cast<size_t>(c * k_n + i)]);
          acc = acc == kNoValue ? p : op(Op::Add, Type::Float, acc, p);
        }
        out[static_cast<size_t>(c * rows + row)] = acc;
      }
    return out;
  }
  default:
    (void)result_type;
    fail(std::string("unsupported operator ") + std::to_string(static_cast<int>(o)));
    return l;
  }
}

Comps Lowerer::assignment(TIntermBinary* b) {
  const Ref r = ref(b->getLeft());
  Comps v;
  const TType& lt = b->getLeft()->getType();
  if (b->getOp() == EOpAssign) {
    v = expr(b->getRight());
  } else {
    const Comps old = load(r);
    const Comps rhs = expr(b->getRight());
    TOperator o = EOpAdd;
    switch (b->getOp()) {
    case EOpSubAssign:
      o = EOpSub;
      break;
    case EOpMulAssign:
      o = EOpMul;
      break;
    case EOpDivAssign:
      o = EOpDiv;
      break;
    case EOpVectorTimesMatrixAssign:
      o = EOpVectorTimesMatrix;
      break;
    case EOpVectorTimesScalarAssign:
      o = EOpVectorTimesScalar;
      break;
    case EOpMatrixTimesScalarAssign:
      o = EOpMatrixTimesScalar;
      break;
    case EOpMatrixTimesMatrixAssign:
      o = EOpMatrixTimesMatrix;
      break;
    default:
      break;
    }
    v = arith(o, lt, old, b->getRight()->getType(), rhs, lt);
  }
  store(r, v);
  return v;
}

Comps Lowerer::unary(TIntermUnary* u) {
  const TOperator o = u->getOp();
  switch (o) {
  case EOpNegative: {
    Comps v = expr(u->getOperand());
    for (ValueId& x : v)
      x = op(Op::Neg, f.type(x), x);
    return v;
  }
  case EOpLogicalNot:
  case EOpVectorLogicalNot: {
    Comps v = expr(u->getOperand());
    for (ValueId& x : v)
      x = not_(x);
    return v;
  }
  case EOpPostIncrement:
  case EOpPostDecrement:
  case EOpPreIncrement:
  case EOpPreDecrement: {
    const Ref r = ref(u->getOperand());
    const Comps old = load(r);
    Comps nv;
    const bool inc = o == EOpPostIncrement || o == EOpPreIncrement;
    for (ValueId x : old) {
      const Type t = f.type(x);
      const ValueId one = t == Type::Float ? f.const_f(1.0f) : f.const_i(1);
      nv.push_back(op(inc ? Op::Add : Op::Sub, t, x, one));
    }
    store(r, nv);
    return (o == EOpPostIncrement || o == EOpPostDecrement) ? old : nv;
  }
  case EOpConvIntToFloat:
  case EOpConvUintToFloat:
  case EOpConvBoolToFloat:
  case EOpConvDoubleToFloat: {
    Comps v = expr(u->getOperand());
    for (ValueId& x : v)
      x = convert(x, Type::Float);
    return v;
  }
  case EOpConvFloatToInt:
  case EOpConvBoolToInt:
  case EOpConvUintToInt:
  case EOpConvFloatToUint:
  case EOpConvIntToUint:
  case EOpConvBoolToUint: {
    Comps v = expr(u->getOperand());
    for (ValueId& x : v)
      x = convert(x, Type::Int);
    return v;
  }
  case EOpConvIntToBool:
  case EOpConvFloatToBool:
  case EOpConvUintToBool: {
    Comps v = expr(u->getOperand());
    for (ValueId& x : v)
      x = convert(x, Type::Bool);
    return v;
  }
  case EOpCopyObject:
    return expr(u->getOperand());
  default:
    return builtin(o, {u->getOperand()}, u->getType());
  }
}

Comps Lowerer::aggregate(TIntermAggregate* a) {
  if (a->getOp() == EOpFunctionCall) return call(a);
  if (a->isConstructor()) return construct(a);
  if (a->getOp() == EOpSequence || a->getOp() == EOpComma) {
    Comps last;
    for (TIntermNode* c : a->getSequence())
      if (auto* t = c->getAsTyped()) last = expr(t);
    return last;
  }
  std::vector<TIntermTyped*> args;
  for (TIntermNode* c : a->getSequence())
    args.push_back(c->getAsTyped());
  return builtin(a->getOp(), args, a->getType());
}

Comps Lowerer::construct(TIntermAggregate* a) {
  const TType& t = a->getType();
  std::vector<Type> ts;
  flat_types(t, ts);
  const size_t n = ts.size();
  std::vector<Comps> args;
  Comps all;
  for (TIntermNode* c : a->getSequence()) {
    args.push_back(expr(c->getAsTyped()));
    all.insert(all.end(), args.back().begin(), args.back().end());
  }
  Comps out(n, kNoValue);
  if (all.empty()) return out;
  const auto conv = [&](ValueId v, size_t k) {
    return ts[k] == kSamplerType || is_sampler(v) ? v : convert(v, ts[k]);
  };
  if (t.isStruct() || t.isArray()) {
    for (size_t k = 0; k < n && k < all.size(); ++k)
      out[k] = conv(all[k], k);
    return out;
  }
  if (t.isMatrix()) {
    const int cols = t.getMatrixCols(), rows = t.getMatrixRows();
    auto* first = a->getSequence()[0]->getAsTyped();
    if (args.size() == 1 && first->getType().isScalar()) {
      // mat(s): s on the diagonal (GLSL 1.20 §5.4.2).
      const ValueId s = convert(all[0], Type::Float), zero = f.const_f(0.0f);
      for (int c = 0; c < cols; ++c)
        for (int r = 0; r < rows; ++r)
          out[static_cast<size_t>(c * rows + r)] = c == r ? s : zero;
      return out;
    }
    if (args.size() == 1 && first->getType().isMatrix()) {
      // mat(m): m's overlap, the identity elsewhere.
      const int sc = first->getType().getMatrixCols(), sr = first->getType().getMatrixRows();
      for (int c = 0; c < cols; ++c)
        for (int r = 0; r < rows; ++r)
          out[static_cast<size_t>(c * rows + r)] = c < sc && r < sr
                                                       ? all[static_cast<size_t>(c * sr + r)]
                                                       : f.const_f(c == r ? 1.0f : 0.0f);
      return out;
    }
  }
  if (all.size() == 1 && n > 1) {
    const ValueId s = conv(all[0], 0);
    for (size_t k = 0; k < n; ++k)
      out[k] = s;
    return out;
  }
  for (size_t k = 0; k < n && k < all.size(); ++k)
    out[k] = conv(all[k], k);
  return out;
}

} // namespace pineda::glsl
