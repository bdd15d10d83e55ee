// The IR's builder, printer and verifier (ir.h).
#include "shader/ir.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstring>
#include <unordered_set>

namespace pineda::shader {

const char* op_name(Op op) {
  switch (op) {
#define PINEDA_X(name)                                                                             \
  case Op::name:                                                                                   \
    return #name;
    PINEDA_IR_OPS(PINEDA_X)
#undef PINEDA_X
  }
  return "?";
}

int op_arity(Op op) {
  switch (op) {
  case Op::Const:
  case Op::Uniform:
  case Op::Input:
  case Op::Phi:
    return 0;
  case Op::Neg:
  case Op::Abs:
  case Op::Sign:
  case Op::Floor:
  case Op::Ceil:
  case Op::Fract:
  case Op::Sqrt:
  case Op::Rsq:
  case Op::Exp2:
  case Op::Log2:
  case Op::Exp:
  case Op::Log:
  case Op::Sin:
  case Op::Cos:
  case Op::Tan:
  case Op::Asin:
  case Op::Acos:
  case Op::Atan:
  case Op::Not:
  case Op::I2F:
  case Op::F2I:
  case Op::B2F:
  case Op::B2I:
  case Op::F2B:
  case Op::I2B:
  case Op::Ddx:
  case Op::Ddy:
  case Op::UniformIndexed:
  case Op::TexComp:
  case Op::StoreOutput:
  case Op::ExitIfNone:
    return 1;
  case Op::Select:
    return 3;
  case Op::Tex:
    return 4;
  default:
    return 2;
  }
}

bool op_is_pure_lanewise(Op op) {
  switch (op) {
  case Op::Ddx:
  case Op::Ddy:
  case Op::Tex:
  case Op::TexComp:
  case Op::StoreOutput:
  case Op::ExitIfNone:
  case Op::Phi:
    return false;
  default:
    return true;
  }
}

ValueId Function::leaf(Op op, Type t, int32_t imm) {
  const uint64_t key = (uint64_t(static_cast<uint8_t>(op)) << 40) |
                       (uint64_t(static_cast<uint8_t>(t)) << 32) | static_cast<uint32_t>(imm);
  auto it = leaves_.find(key);
  if (it != leaves_.end()) return it->second;
  Inst in;
  in.op = op;
  in.type = t;
  in.imm[0] = imm;
  insts.push_back(in);
  const auto id = static_cast<ValueId>(insts.size() - 1);
  leaves_.emplace(key, id);
  return id;
}

void Function::rebuild_leaf_index() {
  leaves_.clear();
  for (size_t v = 0; v < insts.size(); ++v) {
    const Inst& in = insts[v];
    if (in.op != Op::Const && in.op != Op::Uniform && in.op != Op::Input) continue;
    const uint64_t key = (uint64_t(static_cast<uint8_t>(in.op)) << 40) |
                         (uint64_t(static_cast<uint8_t>(in.type)) << 32) |
                         static_cast<uint32_t>(in.imm[0]);
    leaves_.emplace(key, static_cast<ValueId>(v));
  }
}

ValueId Function::constant(Type t, uint32_t bits) {
  return leaf(Op::Const, t, static_cast<int32_t>(bits));
}
ValueId Function::const_f(float f) {
  return constant(Type::Float, std::bit_cast<uint32_t>(f));
}
ValueId Function::const_i(int32_t i) {
  return constant(Type::Int, static_cast<uint32_t>(i));
}
ValueId Function::const_b(bool b) {
  return constant(Type::Bool, b ? ~0u : 0u);
}
ValueId Function::uniform(Type t, int32_t word) {
  return leaf(Op::Uniform, t, word);
}
ValueId Function::input(Type t, int32_t component) {
  return leaf(Op::Input, t, component);
}

ValueId Function::phi(Type t) {
  Inst in;
  in.op = Op::Phi;
  in.type = t;
  insts.push_back(in);
  return static_cast<ValueId>(insts.size() - 1);
}

float Function::const_float(ValueId v) const {
  return std::bit_cast<float>(const_bits(v));
}

ValueId Function::emit(Block& b, Op op, Type t, ValueId a0, ValueId a1, ValueId a2, ValueId a3) {
  Inst in;
  in.op = op;
  in.type = t;
  in.arg[0] = a0;
  in.arg[1] = a1;
  in.arg[2] = a2;
  in.arg[3] = a3;
  insts.push_back(in);
  const auto id = static_cast<ValueId>(insts.size() - 1);
  b.push_back({NodeKind::Inst, id});
  return id;
}

ValueId Function::emit_imm(Block& b, Op op, Type t, int32_t i0, int32_t i1, int32_t i2,
                           ValueId a0) {
  const ValueId id = emit(b, op, t, a0);
  insts[id].imm[0] = i0;
  insts[id].imm[1] = i1;
  insts[id].imm[2] = i2;
  return id;
}

namespace {

// Concatenation by appending (GCC 12 warns falsely about chains of operator+ on strings).
template <class... A> std::string cat(const A&... a) {
  std::string s;
  ((s += a), ...);
  return s;
}

const char* type_suffix(Type t) {
  switch (t) {
  case Type::Float:
    return "f";
  case Type::Int:
    return "i";
  case Type::Bool:
    return "b";
  }
  return "?";
}

struct Printer {
  const Function& f;
  std::string out;

  void line(int depth, const std::string& s) {
    out.append(static_cast<size_t>(depth) * 2, ' ');
    out += s;
    out += '\n';
  }
  static std::string v(ValueId id) {
    return id == kNoValue ? std::string("_") : cat("%", std::to_string(id));
  }
  std::string leaf(ValueId id) const {
    const Inst& in = f.insts[id];
    char buf[96];
    switch (in.op) {
    case Op::Const:
      if (in.type == Type::Float)
        std::snprintf(buf, sizeof buf, "const.f %.9g", f.const_float(id));
      else if (in.type == Type::Int)
        std::snprintf(buf, sizeof buf, "const.i %d", in.imm[0]);
      else
        std::snprintf(buf, sizeof buf, "const.b %s", in.imm[0] ? "true" : "false");
      return buf;
    case Op::Uniform:
      std::snprintf(buf, sizeof buf, "uniform.%s [%d]", type_suffix(in.type), in.imm[0]);
      return buf;
    case Op::Input:
      std::snprintf(buf, sizeof buf, "input.%s %d.%c", type_suffix(in.type), in.imm[0] / 4,
                    "xyzw"[in.imm[0] & 3]);
      return buf;
    default:
      return "?";
    }
  }
  std::string inst(ValueId id) const {
    const Inst& in = f.insts[id];
    std::string s;
    if (in.op != Op::StoreOutput && in.op != Op::ExitIfNone) s = cat(v(id), " = ");
    s += op_name(in.op);
    s += '.';
    s += type_suffix(in.type);
    const int n = op_arity(in.op);
    for (int k = 0; k < n; ++k) {
      if (k == 3 && in.arg[k] == kNoValue) break;
      s += k == 0 ? " " : ", ";
      s += v(in.arg[k]);
    }
    char buf[96];
    switch (in.op) {
    case Op::UniformIndexed:
      std::snprintf(buf, sizeof buf, " [%d + %d * i, %d]", in.imm[0], in.imm[1], in.imm[2]);
      s += buf;
      break;
    case Op::Tex: {
      const TexKind k = TexKind::unpack(in.imm[1]);
      static const char* const targets[] = {"1d", "2d", "3d", "cube"};
      static const char* const lods[] = {"implicit", "bias", "lod"};
      std::snprintf(buf, sizeof buf, " sampler [%d] %s%s %s", in.imm[0],
                    targets[static_cast<int>(k.target)], k.shadow ? " shadow" : "",
                    lods[static_cast<int>(k.lod)]);
      s += buf;
      break;
    }
    case Op::TexComp:
      s += std::string(" .") + "xyzw"[in.imm[0] & 3];
      break;
    case Op::StoreOutput:
      if (in.imm[0] == kKillOutput)
        s += " -> kill";
      else {
        std::snprintf(buf, sizeof buf, " -> %d.%c", in.imm[0] / 4, "xyzw"[in.imm[0] & 3]);
        s += buf;
      }
      break;
    default:
      break;
    }
    return s;
  }
  void block(const Block& b, int depth) {
    for (const Node& n : b) {
      if (n.kind == NodeKind::Inst) {
        line(depth, inst(n.index));
      } else if (n.kind == NodeKind::Region) {
        const Region& r = f.regions[n.index];
        line(depth, cat("region any ", v(r.cond), " {"));
        block(r.body, depth + 1);
        std::string outs = "}";
        for (const RegionOut& o : r.outs)
          outs += cat(" ", v(o.phi), "=", v(o.inner), "|", v(o.outer));
        line(depth, outs);
      } else {
        const Loop& l = f.loops[n.index];
        line(depth, "loop {");
        for (const LoopPhi& p : l.phis)
          line(depth + 1, cat(v(p.phi), " = phi.", type_suffix(f.insts[p.phi].type), " ", v(p.init),
                              ", ", v(p.next)));
        block(l.body, depth + 1);
        std::string exits = "}";
        for (const LoopExit& e : l.exits)
          exits += cat(" ", v(e.out), "=", v(e.inner));
        line(depth, exits);
      }
    }
  }
};

struct Verifier {
  const Function& f;
  std::vector<uint8_t> defined;
  std::string err;

  void fail(const std::string& s) {
    if (err.empty()) err = s;
  }
  bool ok(ValueId v) const { return v < f.insts.size() && (f.is_leaf(v) || defined[v]); }
  void use(ValueId v, ValueId user) {
    if (v == kNoValue) return;
    if (!ok(v))
      fail(
          cat("%", std::to_string(user), " uses %", std::to_string(v), " where it is not defined"));
  }
  // Defines every value of `b`, recursing; returns the values defined at this level so that
  // the caller can undefine them when the scope ends.
  void block(const Block& b, std::vector<ValueId>& scope, int loop_depth, bool loop_top,
             int* exits) {
    for (const Node& n : b) {
      if (n.kind == NodeKind::Inst) {
        const Inst& in = f.insts[n.index];
        if (f.is_leaf(n.index) || in.op == Op::Phi) fail("leaf or phi in a block");
        const int na = op_arity(in.op);
        for (int k = 0; k < na; ++k) {
          if (in.op == Op::Tex && k > 0) {
            use(in.arg[k], n.index);
            continue;
          }
          if (in.arg[k] == kNoValue) fail(cat("missing operand of %", std::to_string(n.index)));
          use(in.arg[k], n.index);
        }
        if (in.op == Op::ExitIfNone) {
          if (!loop_top) fail("ExitIfNone outside a loop's top-level block");
          if (exits) ++*exits;
        }
        if (defined[n.index]) fail(cat("%", std::to_string(n.index), " defined twice"));
        defined[n.index] = 1;
        scope.push_back(n.index);
      } else if (n.kind == NodeKind::Region) {
        const Region& r = f.regions[n.index];
        use(r.cond, kNoValue);
        std::vector<ValueId> inner;
        block(r.body, inner, loop_depth, false, nullptr);
        for (const RegionOut& o : r.outs)
          use(o.inner, o.phi);
        for (ValueId v : inner)
          defined[v] = 0;
        for (const RegionOut& o : r.outs) {
          use(o.outer, o.phi);
          if (f.insts[o.phi].op != Op::Phi) fail("region out is not a phi");
          defined[o.phi] = 1;
          scope.push_back(o.phi);
        }
      } else {
        const Loop& l = f.loops[n.index];
        std::vector<ValueId> inner;
        for (const LoopPhi& p : l.phis) {
          use(p.init, p.phi);
          if (f.insts[p.phi].op != Op::Phi) fail("loop phi is not a phi");
          defined[p.phi] = 1;
          inner.push_back(p.phi);
        }
        int count = 0;
        // Exits may only use values defined before the ExitIfNone: checked by recording the
        // defined set at that point.
        block_with_exit(l, inner, loop_depth + 1, &count);
        if (count != 1) fail("loop without exactly one ExitIfNone");
        for (const LoopPhi& p : l.phis)
          use(p.next, p.phi);
        for (ValueId v : inner)
          defined[v] = 0;
        for (const LoopExit& e : l.exits) {
          if (f.insts[e.out].op != Op::Phi) fail("loop exit is not a phi");
          defined[e.out] = 1;
          scope.push_back(e.out);
        }
      }
    }
  }
  void block_with_exit(const Loop& l, std::vector<ValueId>& scope, int loop_depth, int* exits) {
    // The top-level block, checking the exits' inner values at the ExitIfNone.
    for (const Node& n : l.body) {
      Block one{n};
      block(one, scope, loop_depth, true, exits);
      if (n.kind == NodeKind::Inst && f.insts[n.index].op == Op::ExitIfNone)
        for (const LoopExit& e : l.exits)
          use(e.inner, e.out);
    }
  }
};

} // namespace

std::string print(const Function& f) {
  Printer p{f, {}};
  // The leaves the program reads, then the blocks.
  std::unordered_set<ValueId> seen;
  std::vector<ValueId> leaves;
  auto note = [&](ValueId v) {
    if (v != kNoValue && v < f.insts.size() && f.is_leaf(v) && seen.insert(v).second)
      leaves.push_back(v);
  };
  for (size_t i = 0; i < f.insts.size(); ++i) {
    const Inst& in = f.insts[i];
    for (ValueId a : in.arg)
      note(a);
  }
  for (const Region& r : f.regions) {
    note(r.cond);
    for (const RegionOut& o : r.outs)
      note(o.inner), note(o.outer);
  }
  for (const Loop& l : f.loops) {
    for (const LoopPhi& ph : l.phis)
      note(ph.init), note(ph.next);
    for (const LoopExit& e : l.exits)
      note(e.inner);
  }
  std::sort(leaves.begin(), leaves.end());
  for (ValueId v : leaves)
    p.line(0, cat(Printer::v(v), " = ", p.leaf(v)));
  p.block(f.body, 0);
  return p.out;
}

std::string verify(const Function& f) {
  Verifier v{f, std::vector<uint8_t>(f.insts.size(), 0), {}};
  std::vector<ValueId> scope;
  v.block(f.body, scope, 0, false, nullptr);
  return v.err;
}

} // namespace pineda::shader
