// The IR's optimization passes (ir_passes.h).
#include "shader/ir_passes.h"

#include <algorithm>
#include <bit>
#include <numeric>
#include <unordered_map>

namespace pineda::shader {

namespace {

// Replacements made by a pass: uses of `from` read `to` instead.
struct Repl {
  std::vector<ValueId> map;
  explicit Repl(size_t n) : map(n) { std::iota(map.begin(), map.end(), ValueId{0}); }
  ValueId operator()(ValueId v) {
    if (v == kNoValue) return v;
    ValueId r = v;
    while (r < map.size() && map[r] != r)
      r = map[r];
    while (v < map.size() && map[v] != r) {
      const ValueId next = map[v];
      map[v] = r;
      v = next;
    }
    return r;
  }
  void set(ValueId from, ValueId to) {
    if (from >= map.size()) {
      const size_t old = map.size();
      map.resize(from + 1);
      std::iota(map.begin() + static_cast<long>(old), map.end(), static_cast<ValueId>(old));
    }
    map[from] = to;
  }
};

// Applies `r` to every operand reference of the function.
void apply(Function& f, Repl& r) {
  const auto walk = [&](auto&& self, Block& b) -> void {
    for (Node& n : b) {
      if (n.kind == NodeKind::Inst) {
        Inst& in = f.insts[n.index];
        for (ValueId& a : in.arg)
          a = r(a);
      } else if (n.kind == NodeKind::Region) {
        Region& g = f.regions[n.index];
        g.cond = r(g.cond);
        self(self, g.body);
        for (RegionOut& o : g.outs)
          o.inner = r(o.inner), o.outer = r(o.outer);
      } else {
        Loop& l = f.loops[n.index];
        for (LoopPhi& p : l.phis)
          p.init = r(p.init);
        self(self, l.body);
        for (LoopPhi& p : l.phis)
          p.next = r(p.next);
        for (LoopExit& e : l.exits)
          e.inner = r(e.inner);
      }
    }
  };
  walk(walk, f.body);
}

bool is_const_f(const Function& f, ValueId v, float x) {
  return f.is_const(v) && f.type(v) == Type::Float && f.const_bits(v) == std::bit_cast<uint32_t>(x);
}
bool is_const_i(const Function& f, ValueId v, int32_t x) {
  return f.is_const(v) && f.type(v) == Type::Int && f.const_bits(v) == static_cast<uint32_t>(x);
}
bool is_true(const Function& f, ValueId v) {
  return f.is_const(v) && f.type(v) == Type::Bool && f.const_bits(v) != 0;
}
bool is_false(const Function& f, ValueId v) {
  return f.is_const(v) && f.type(v) == Type::Bool && f.const_bits(v) == 0;
}

// Marks the values a block defines (instructions, and the phis of its regions and loops).
void mark_defined(const Function& f, const Block& b, std::vector<uint8_t>& out) {
  for (const Node& n : b) {
    if (n.kind == NodeKind::Inst) {
      if (n.index < out.size()) out[n.index] = 1;
    } else if (n.kind == NodeKind::Region) {
      const Region& g = f.regions[n.index];
      mark_defined(f, g.body, out);
      for (const RegionOut& o : g.outs)
        if (o.phi < out.size()) out[o.phi] = 1;
    } else {
      const Loop& l = f.loops[n.index];
      for (const LoopPhi& p : l.phis)
        if (p.phi < out.size()) out[p.phi] = 1;
      mark_defined(f, l.body, out);
      for (const LoopExit& e : l.exits)
        if (e.out < out.size()) out[e.out] = 1;
    }
  }
}

struct Simplifier {
  Function& f;
  Repl r;
  bool changed = false;

  std::vector<uint8_t> uniform;

  explicit Simplifier(Function& fn) : f(fn), r(fn.insts.size()), uniform(uniform_values(fn)) {}

  void replace(ValueId from, ValueId to) {
    r.set(from, to);
    changed = true;
  }

  // The value `in` (already with resolved operands) simplifies to, or kNoValue.
  ValueId simplify_inst(ValueId id) {
    Inst& in = f.insts[id];
    uint32_t bits;
    if (fold_constant(f, in, bits)) return f.constant(in.type, bits);
    const ValueId a = in.arg[0], b = in.arg[1], c = in.arg[2];
    const bool fl = a != kNoValue && f.type(a) == Type::Float;
    switch (in.op) {
    case Op::Add:
      if (fl ? is_const_f(f, b, 0.0f) || is_const_f(f, b, -0.0f) : is_const_i(f, b, 0)) return a;
      if (fl ? is_const_f(f, a, -0.0f) : is_const_i(f, a, 0)) return b;
      break;
    case Op::Sub:
      if (fl ? is_const_f(f, b, 0.0f) : is_const_i(f, b, 0)) return a;
      break;
    case Op::Mul:
      if (fl ? is_const_f(f, b, 1.0f) : is_const_i(f, b, 1)) return a;
      if (fl ? is_const_f(f, a, 1.0f) : is_const_i(f, a, 1)) return b;
      break;
    case Op::Div:
      if (fl ? is_const_f(f, b, 1.0f) : is_const_i(f, b, 1)) return a;
      break;
    case Op::Min:
    case Op::Max:
      if (a == b) return a;
      break;
    case Op::Neg:
      if (f.insts[a].op == Op::Neg) return f.insts[a].arg[0];
      break;
    case Op::Not:
      if (f.insts[a].op == Op::Not) return f.insts[a].arg[0];
      break;
    case Op::And:
      if (is_false(f, a) || is_false(f, b)) return f.const_b(false);
      if (is_true(f, a)) return b;
      if (is_true(f, b) || a == b) return a;
      break;
    case Op::Or:
      if (is_true(f, a) || is_true(f, b)) return f.const_b(true);
      if (is_false(f, a)) return b;
      if (is_false(f, b) || a == b) return a;
      break;
    case Op::Xor:
      if (is_false(f, a)) return b;
      if (is_false(f, b)) return a;
      break;
    case Op::Select:
      if (is_true(f, a)) return b;
      if (is_false(f, a)) return c;
      if (b == c) return b;
      if (in.type == Type::Bool && is_true(f, b) && is_false(f, c)) return a;
      if (in.type == Type::Bool && is_false(f, b) && is_true(f, c)) {
        in.op = Op::Not;
        in.arg[1] = in.arg[2] = kNoValue;
        changed = true;
      }
      break;
    case Op::F2B:
      if (f.insts[a].op == Op::B2F) return f.insts[a].arg[0];
      break;
    case Op::I2B:
      if (f.insts[a].op == Op::B2I) return f.insts[a].arg[0];
      break;
    case Op::Ddx:
    case Op::Ddy:
      // The same value in every lane of a quad has no slope.
      if (a < uniform.size() && uniform[a]) return f.const_f(0.0f);
      break;
    case Op::UniformIndexed:
      if (f.is_const(a)) {
        const int32_t i =
            std::clamp(static_cast<int32_t>(f.const_bits(a)), int32_t{0}, in.imm[2] - 1);
        return f.uniform(in.type, in.imm[0] + i * in.imm[1]);
      }
      break;
    default:
      break;
    }
    return kNoValue;
  }

  Block block(Block& b) {
    Block out;
    out.reserve(b.size());
    for (Node& n : b) {
      if (n.kind == NodeKind::Inst) {
        Inst& in = f.insts[n.index];
        for (ValueId& a : in.arg)
          a = r(a);
        const ValueId s = simplify_inst(n.index);
        if (s != kNoValue && s != n.index) {
          replace(n.index, s);
          continue;
        }
        out.push_back(n);
      } else if (n.kind == NodeKind::Region) {
        region(n.index, out);
      } else {
        loop(n.index, out);
      }
    }
    return out;
  }

  void region(uint32_t ri, Block& out) {
    Region& g = f.regions[ri];
    g.cond = r(g.cond);
    if (is_false(f, g.cond)) {
      for (RegionOut& o : g.outs)
        replace(o.phi, r(o.outer));
      g.dead = true;
      changed = true;
      return;
    }
    Block body = block(g.body);
    g.body = std::move(body);
    std::vector<RegionOut> outs;
    for (RegionOut& o : g.outs) {
      o.inner = r(o.inner);
      o.outer = r(o.outer);
      if (o.inner == o.outer) {
        replace(o.phi, o.inner);
        continue;
      }
      outs.push_back(o);
    }
    g.outs = std::move(outs);
    if (is_true(f, g.cond) || g.body.empty()) {
      // Runs in every lane, or has nothing to skip: its outs are the inner values (merged by
      // the condition for a uniform region, whose updates are not masked by it).
      const bool merge = g.uniform && !is_true(f, g.cond);
      Region moved = std::move(g);
      g.dead = true;
      for (Node& n : moved.body)
        out.push_back(n);
      for (RegionOut& o : moved.outs) {
        if (merge)
          replace(o.phi, f.emit(out, Op::Select, f.type(o.phi), moved.cond, o.inner, o.outer));
        else
          replace(o.phi, o.inner);
      }
      changed = true;
      return;
    }
    out.push_back({NodeKind::Region, ri});
  }

  void loop(uint32_t li, Block& out) {
    Loop& l = f.loops[li];
    for (LoopPhi& p : l.phis)
      p.init = r(p.init);
    Block body = block(l.body);
    l.body = std::move(body);
    std::vector<LoopPhi> phis;
    for (LoopPhi& p : l.phis) {
      p.next = r(p.next);
      if (p.next == p.phi || p.next == p.init) {
        replace(p.phi, p.init);
        continue;
      }
      phis.push_back(p);
    }
    l.phis = std::move(phis);
    // Exits of values the loop does not define are those values.
    std::vector<uint8_t> inside(f.insts.size(), 0);
    for (const LoopPhi& p : l.phis)
      inside[p.phi] = 1;
    mark_defined(f, l.body, inside);
    std::vector<LoopExit> exits;
    for (LoopExit& e : l.exits) {
      e.inner = r(e.inner);
      if (e.inner < inside.size() && !inside[e.inner]) {
        replace(e.out, e.inner);
        continue;
      }
      exits.push_back(e);
    }
    l.exits = std::move(exits);
    // An exit test that never passes: the body up to it runs once.
    size_t exit_at = l.body.size();
    for (size_t k = 0; k < l.body.size(); ++k)
      if (l.body[k].kind == NodeKind::Inst && f.insts[l.body[k].index].op == Op::ExitIfNone)
        exit_at = k;
    if (exit_at < l.body.size() && is_false(f, f.insts[l.body[exit_at].index].arg[0])) {
      for (LoopPhi& p : l.phis)
        replace(p.phi, p.init);
      for (size_t k = 0; k < exit_at; ++k)
        out.push_back(l.body[k]);
      for (LoopExit& e : l.exits)
        replace(e.out, e.inner);
      l.dead = true;
      changed = true;
      return;
    }
    out.push_back({NodeKind::Loop, li});
  }
};

// ---- common subexpressions ----

struct CseKey {
  Op op;
  Type type;
  ValueId arg[4];
  int32_t imm[3];
  bool operator==(const CseKey& o) const {
    return op == o.op && type == o.type && std::equal(arg, arg + 4, o.arg) &&
           std::equal(imm, imm + 3, o.imm);
  }
};
struct CseHash {
  size_t operator()(const CseKey& k) const {
    uint64_t h =
        static_cast<uint64_t>(k.op) * 0x9e3779b97f4a7c15ull + static_cast<uint64_t>(k.type);
    for (ValueId a : k.arg)
      h = (h ^ a) * 0x100000001b3ull;
    for (int32_t i : k.imm)
      h = (h ^ static_cast<uint32_t>(i)) * 0x100000001b3ull;
    return static_cast<size_t>(h ^ (h >> 29));
  }
};

bool commutative(Op op) {
  switch (op) {
  case Op::Add:
  case Op::Mul:
  case Op::Min:
  case Op::Max:
  case Op::And:
  case Op::Or:
  case Op::Xor:
  case Op::Eq:
  case Op::Ne:
    return true;
  default:
    return false;
  }
}

struct Cse {
  Function& f;
  Repl r;
  std::unordered_map<CseKey, ValueId, CseHash> table;
  bool changed = false;

  explicit Cse(Function& fn) : f(fn), r(fn.insts.size()) {}

  void block(Block& b) {
    std::vector<CseKey> added;
    Block out;
    for (Node& n : b) {
      if (n.kind == NodeKind::Inst) {
        Inst& in = f.insts[n.index];
        for (ValueId& a : in.arg)
          a = r(a);
        const bool candidate = op_is_pure_lanewise(in.op) || in.op == Op::Ddx || in.op == Op::Ddy ||
                               in.op == Op::Tex || in.op == Op::TexComp;
        if (candidate) {
          CseKey k{in.op,
                   in.type,
                   {in.arg[0], in.arg[1], in.arg[2], in.arg[3]},
                   {in.imm[0], in.imm[1], in.imm[2]}};
          if (commutative(in.op) && k.arg[0] > k.arg[1]) std::swap(k.arg[0], k.arg[1]);
          auto it = table.find(k);
          if (it != table.end()) {
            r.set(n.index, it->second);
            changed = true;
            continue;
          }
          table.emplace(k, n.index);
          added.push_back(k);
        }
        out.push_back(n);
      } else if (n.kind == NodeKind::Region) {
        Region& g = f.regions[n.index];
        g.cond = r(g.cond);
        block(g.body);
        for (RegionOut& o : g.outs)
          o.inner = r(o.inner), o.outer = r(o.outer);
        out.push_back(n);
      } else {
        Loop& l = f.loops[n.index];
        for (LoopPhi& p : l.phis)
          p.init = r(p.init);
        block(l.body);
        for (LoopPhi& p : l.phis)
          p.next = r(p.next);
        for (LoopExit& e : l.exits)
          e.inner = r(e.inner);
        out.push_back(n);
      }
    }
    b = std::move(out);
    for (const CseKey& k : added)
      table.erase(k);
  }
};

// ---- dead code ----

struct Dce {
  Function& f;
  std::vector<uint8_t> live;
  std::vector<uint8_t> region_live, loop_live;
  // The construct enclosing each instruction or phi: -1 top level, 2r region r, 2l+1 loop l.
  std::vector<int64_t> owner;
  std::vector<int64_t> region_owner, loop_owner;
  std::vector<ValueId> loop_exit_inst;
  std::vector<ValueId> work;

  explicit Dce(Function& fn)
      : f(fn), live(fn.insts.size(), 0), region_live(fn.regions.size(), 0),
        loop_live(fn.loops.size(), 0), owner(fn.insts.size(), -1),
        region_owner(fn.regions.size(), -1), loop_owner(fn.loops.size(), -1),
        loop_exit_inst(fn.loops.size(), kNoValue) {}

  void index(const Block& b, int64_t own) {
    for (const Node& n : b) {
      if (n.kind == NodeKind::Inst) {
        owner[n.index] = own;
        if (f.insts[n.index].op == Op::ExitIfNone && own >= 0 && (own & 1))
          loop_exit_inst[static_cast<size_t>(own >> 1)] = n.index;
      } else if (n.kind == NodeKind::Region) {
        const Region& g = f.regions[n.index];
        region_owner[n.index] = own;
        index(g.body, 2 * int64_t(n.index));
        for (const RegionOut& o : g.outs)
          owner[o.phi] = own;
      } else {
        const Loop& l = f.loops[n.index];
        loop_owner[n.index] = own;
        for (const LoopPhi& p : l.phis)
          owner[p.phi] = 2 * int64_t(n.index) + 1;
        index(l.body, 2 * int64_t(n.index) + 1);
        for (const LoopExit& e : l.exits)
          owner[e.out] = own;
      }
    }
  }

  void mark(ValueId v) {
    if (v == kNoValue || live[v]) return;
    live[v] = 1;
    work.push_back(v);
  }
  void mark_owner(int64_t own) {
    while (own >= 0) {
      if ((own & 1) == 0) {
        const auto ri = static_cast<size_t>(own >> 1);
        if (region_live[ri]) return;
        region_live[ri] = 1;
        mark(f.regions[ri].cond);
        own = region_owner[ri];
      } else {
        const auto li = static_cast<size_t>(own >> 1);
        if (loop_live[li]) return;
        loop_live[li] = 1;
        mark(loop_exit_inst[li]);
        own = loop_owner[li];
      }
    }
  }

  void run() {
    index(f.body, -1);
    // Phi -> what it depends on.
    std::unordered_map<ValueId, std::vector<ValueId>> phi_deps;
    for (size_t ri = 0; ri < f.regions.size(); ++ri) {
      if (f.regions[ri].dead) continue;
      for (const RegionOut& o : f.regions[ri].outs)
        phi_deps[o.phi] = {o.inner, o.outer};
    }
    std::unordered_map<ValueId, int64_t> phi_construct;
    for (size_t ri = 0; ri < f.regions.size(); ++ri)
      for (const RegionOut& o : f.regions[ri].outs)
        phi_construct[o.phi] = 2 * int64_t(ri);
    for (size_t li = 0; li < f.loops.size(); ++li) {
      if (f.loops[li].dead) continue;
      for (const LoopPhi& p : f.loops[li].phis) {
        phi_deps[p.phi] = {p.init, p.next};
        phi_construct[p.phi] = 2 * int64_t(li) + 1;
      }
      for (const LoopExit& e : f.loops[li].exits) {
        phi_deps[e.out] = {e.inner};
        phi_construct[e.out] = 2 * int64_t(li) + 1;
      }
    }
    for (size_t v = 0; v < f.insts.size(); ++v)
      if (f.insts[v].op == Op::StoreOutput && owner[v] != -2) mark(static_cast<ValueId>(v));
    while (!work.empty()) {
      const ValueId v = work.back();
      work.pop_back();
      const Inst& in = f.insts[v];
      if (in.op == Op::Phi) {
        auto it = phi_deps.find(v);
        if (it != phi_deps.end())
          for (ValueId d : it->second)
            mark(d);
        auto ct = phi_construct.find(v);
        if (ct != phi_construct.end()) mark_owner(ct->second);
      } else {
        for (ValueId a : in.arg)
          mark(a);
      }
      mark_owner(owner[v]);
    }
  }

  bool sweep(Block& b) {
    bool changed = false;
    Block out;
    for (Node& n : b) {
      if (n.kind == NodeKind::Inst) {
        if (!live[n.index]) {
          changed = true;
          continue;
        }
      } else if (n.kind == NodeKind::Region) {
        Region& g = f.regions[n.index];
        if (!region_live[n.index]) {
          g.dead = true;
          changed = true;
          continue;
        }
        changed |= sweep(g.body);
        const size_t before = g.outs.size();
        std::erase_if(g.outs, [&](const RegionOut& o) { return !live[o.phi]; });
        changed |= before != g.outs.size();
      } else {
        Loop& l = f.loops[n.index];
        if (!loop_live[n.index]) {
          l.dead = true;
          changed = true;
          continue;
        }
        const size_t before = l.phis.size() + l.exits.size();
        std::erase_if(l.phis, [&](const LoopPhi& p) { return !live[p.phi]; });
        std::erase_if(l.exits, [&](const LoopExit& e) { return !live[e.out]; });
        changed |= before != l.phis.size() + l.exits.size();
        changed |= sweep(l.body);
      }
      out.push_back(n);
    }
    b = std::move(out);
    return changed;
  }
};

int count_block(const Function& f, const Block& b) {
  int n = 0;
  for (const Node& x : b) {
    if (x.kind == NodeKind::Inst)
      ++n;
    else if (x.kind == NodeKind::Region)
      n += count_block(f, f.regions[x.index].body);
    else
      n += count_block(f, f.loops[x.index].body);
  }
  return n;
}

bool contains_loop(const Function& f, const Block& b) {
  for (const Node& x : b) {
    if (x.kind == NodeKind::Loop) return true;
    if (x.kind == NodeKind::Region && contains_loop(f, f.regions[x.index].body)) return true;
  }
  return false;
}

struct Flattener {
  Function& f;
  int max_insts;
  Repl r;
  bool changed = false;

  Flattener(Function& fn, int m) : f(fn), max_insts(m), r(fn.insts.size()) {}

  void block(Block& b) {
    Block out;
    for (Node& n : b) {
      if (n.kind == NodeKind::Region) {
        Region& g = f.regions[n.index];
        block(g.body);
        if (count_block(f, g.body) <= max_insts && !contains_loop(f, g.body)) {
          Region moved = std::move(g);
          g.dead = true;
          for (Node& x : moved.body)
            out.push_back(x);
          for (RegionOut& o : moved.outs) {
            if (moved.uniform)
              r.set(o.phi, f.emit(out, Op::Select, f.type(o.phi), moved.cond, o.inner, o.outer));
            else
              r.set(o.phi, o.inner);
          }
          changed = true;
          continue;
        }
      } else if (n.kind == NodeKind::Loop) {
        block(f.loops[n.index].body);
      }
      out.push_back(n);
    }
    b = std::move(out);
  }
};

} // namespace

bool simplify(Function& f) {
  Simplifier s(f);
  f.body = s.block(f.body);
  apply(f, s.r);
  return s.changed;
}

bool cse(Function& f) {
  Cse c(f);
  c.block(f.body);
  apply(f, c.r);
  return c.changed;
}

bool dce(Function& f) {
  Dce d(f);
  d.run();
  return d.sweep(f.body);
}

bool flatten_small_regions(Function& f, int max_insts) {
  Flattener fl(f, max_insts);
  fl.block(f.body);
  apply(f, fl.r);
  return fl.changed;
}

void optimize(Function& f) {
  for (int iter = 0; iter < 8; ++iter) {
    bool changed = simplify(f);
    changed |= cse(f);
    changed |= dce(f);
    if (iter == 1) changed |= flatten_small_regions(f, 3);
    if (!changed) break;
  }
}

int count_insts(const Function& f) {
  return count_block(f, f.body);
}

std::vector<uint8_t> used_values(const Function& f) {
  std::vector<uint8_t> used(f.insts.size(), 0);
  const auto mark = [&](ValueId v) {
    if (v != kNoValue && v < used.size()) used[v] = 1;
  };
  const auto walk = [&](auto&& self, const Block& b) -> void {
    for (const Node& n : b) {
      if (n.kind == NodeKind::Inst) {
        const Inst& in = f.insts[n.index];
        for (int k = 0; k < op_arity(in.op); ++k)
          mark(in.arg[k]);
      } else if (n.kind == NodeKind::Region) {
        const Region& g = f.regions[n.index];
        mark(g.cond);
        self(self, g.body);
        for (const RegionOut& o : g.outs)
          mark(o.inner), mark(o.outer);
      } else {
        const Loop& l = f.loops[n.index];
        for (const LoopPhi& p : l.phis)
          mark(p.init), mark(p.next);
        self(self, l.body);
        for (const LoopExit& e : l.exits)
          mark(e.inner);
      }
    }
  };
  walk(walk, f.body);
  return used;
}

std::vector<uint8_t> uniform_values(const Function& f) {
  std::vector<uint8_t> u(f.insts.size(), 0);
  for (size_t v = 0; v < f.insts.size(); ++v)
    if (f.insts[v].op == Op::Const || f.insts[v].op == Op::Uniform) u[v] = 1;
  // Instructions in program order; phis of regions with uniform conditions and loops are
  // left varying (their value depends on control flow the engine does not track per lane).
  const auto walk = [&](auto&& self, const Block& b) -> void {
    for (const Node& n : b) {
      if (n.kind == NodeKind::Inst) {
        const Inst& in = f.insts[n.index];
        if (!op_is_pure_lanewise(in.op)) continue;
        bool all = true;
        for (int k = 0; k < op_arity(in.op); ++k)
          all = all && in.arg[k] != kNoValue && u[in.arg[k]];
        u[n.index] = all;
      } else if (n.kind == NodeKind::Region) {
        const Region& g = f.regions[n.index];
        self(self, g.body);
        for (const RegionOut& o : g.outs)
          u[o.phi] = u[g.cond] && u[o.inner] && u[o.outer];
      } else {
        self(self, f.loops[n.index].body);
      }
    }
  };
  walk(walk, f.body);
  return u;
}

} // namespace pineda::shader
