// IR to engine code (engine_internal.h Code).
//
// - Everything that depends only on constants and uniforms is hoisted into the prologue, which
//   prepare() runs once per draw; its results are splats (a value broadcast across a vector)
//   that the per-run code reads as operands without a register.
// - The structured control flow becomes jumps: a region is skipped when no entry lane of its
//   condition is set, a loop repeats until its exit test finds no lane or its counter runs out.
//   Phis become copies on the edges.
// - Patterns fuse into one kernel where that saves a pass over the registers: (a * b) + c
//   (two roundings, so the same bits as the pair) and min(max(x, lo), hi).
// - Registers are assigned by a linear scan over the linearized code; a value live into a loop
//   stays live to the loop's end.
#include <algorithm>
#include <cstdio>
#include <unordered_map>

#include "shader/engine_internal.h"
#include "shader/ir_passes.h"

namespace pineda::shader {

namespace {

enum class Class : uint8_t { None, Splat, Reg };

struct TexLI {
  ValueId coord[3] = {kNoValue, kNoValue, kNoValue};
  ValueId lod = kNoValue;
  ValueId dst[4] = {kNoValue, kNoValue, kNoValue, kNoValue};
  uint32_t sampler_word = 0;
  TexKind kind;
};

// One instruction of the linear code before registers are assigned.
struct LI {
  bool label = false;
  bool lane = false;
  LaneOp op = LaneOp::Mov;
  Special special = Special::End;
  ValueId dst = kNoValue;
  ValueId src[3] = {kNoValue, kNoValue, kNoValue};
  uint32_t aux = 0;
  uint32_t b_imm = 0, c_imm = 0; // immediates in the b and c fields (Gather, ExitIfNone)
  int target = -1;               // label id
  int tex = -1;
};

struct Gen {
  const Function& f;
  Stage stage;
  Code& code;
  std::string err;

  std::vector<Class> cls;
  std::vector<uint8_t> needed_splat;
  std::vector<int32_t> slot;
  std::vector<int> uses;
  std::vector<uint8_t> fused;     // Mul or Max folded into its single user
  std::vector<const Block*> home; // the block each instruction is in
  std::vector<uint8_t> input_used;
  std::unordered_map<ValueId, std::vector<ValueId>> tex_comps;

  std::vector<LI> lin;
  std::vector<TexLI> texs;
  std::vector<int> label_at; // label id -> LI index
  struct LoopRange {
    int head, end;
  };
  std::vector<LoopRange> loop_ranges;
  int depth = 0;

  Gen(const Function& fn, Stage s, Code& c) : f(fn), stage(s), code(c) {}

  bool is_splat(ValueId v) const { return v != kNoValue && cls[v] == Class::Splat; }

  // ---- classification ----

  void mark_input(ValueId v) {
    if (v != kNoValue && f.insts[v].op == Op::Input) input_used[v] = 1;
  }
  void classify_block(const Block& b) {
    for (const Node& n : b) {
      if (n.kind == NodeKind::Inst) {
        const Inst& in = f.insts[n.index];
        home[n.index] = &b;
        for (int k = 0; k < op_arity(in.op); ++k)
          mark_input(in.arg[k]);
        bool all = op_is_pure_lanewise(in.op);
        for (int k = 0; k < op_arity(in.op) && all; ++k)
          all = in.arg[k] != kNoValue && cls[in.arg[k]] == Class::Splat;
        cls[n.index] = all ? Class::Splat : Class::Reg;
        for (int k = 0; k < op_arity(in.op); ++k)
          if (in.arg[k] != kNoValue) ++uses[in.arg[k]];
        if (in.op == Op::TexComp) tex_comps[in.arg[0]].push_back(n.index);
      } else if (n.kind == NodeKind::Region) {
        const Region& g = f.regions[n.index];
        ++uses[g.cond];
        mark_input(g.cond);
        classify_block(g.body);
        for (const RegionOut& o : g.outs) {
          cls[o.phi] = Class::Reg;
          ++uses[o.inner], ++uses[o.outer];
          mark_input(o.inner), mark_input(o.outer);
        }
      } else {
        const Loop& l = f.loops[n.index];
        for (const LoopPhi& p : l.phis) {
          cls[p.phi] = Class::Reg;
          ++uses[p.init], ++uses[p.next];
          mark_input(p.init), mark_input(p.next);
        }
        classify_block(l.body);
        for (const LoopExit& e : l.exits) {
          cls[e.out] = Class::Reg;
          ++uses[e.inner];
          mark_input(e.inner);
        }
      }
    }
  }

  // Fusion decisions, before linearization (the Mul comes before its Add).
  void fuse_block(const Block& b) {
    for (const Node& n : b) {
      if (n.kind == NodeKind::Inst) {
        const Inst& in = f.insts[n.index];
        if (cls[n.index] != Class::Reg) continue;
        const auto single = [&](ValueId v, Op op) {
          return v != kNoValue && cls[v] == Class::Reg && f.insts[v].op == op &&
                 f.type(v) == Type::Float && uses[v] == 1 && !fused[v] && home[v] == home[n.index];
        };
        if (in.op == Op::Add && in.type == Type::Float) {
          if (single(in.arg[0], Op::Mul))
            fused[in.arg[0]] = 1;
          else if (single(in.arg[1], Op::Mul))
            fused[in.arg[1]] = 1;
        } else if (in.op == Op::Min && in.type == Type::Float && single(in.arg[0], Op::Max)) {
          fused[in.arg[0]] = 1;
        }
      } else if (n.kind == NodeKind::Region) {
        fuse_block(f.regions[n.index].body);
      } else {
        fuse_block(f.loops[n.index].body);
      }
    }
  }

  // ---- the prologue ----

  void need(ValueId v) {
    if (v == kNoValue || cls[v] != Class::Splat || needed_splat[v]) return;
    needed_splat[v] = 1;
    const Inst& in = f.insts[v];
    for (int k = 0; k < op_arity(in.op); ++k)
      need(in.arg[k]);
  }

  void prologue_block(const Block& b, std::vector<ValueId>& order) {
    for (const Node& n : b) {
      if (n.kind == NodeKind::Inst) {
        if (cls[n.index] == Class::Splat && needed_splat[n.index]) order.push_back(n.index);
      } else if (n.kind == NodeKind::Region) {
        prologue_block(f.regions[n.index].body, order);
      } else {
        prologue_block(f.loops[n.index].body, order);
      }
    }
  }

  void emit_prologue() {
    // Leaves first, then the hoisted instructions in program order (operands before uses).
    std::vector<ValueId> order;
    for (size_t v = 0; v < f.insts.size(); ++v)
      if (needed_splat[v] && f.is_leaf(static_cast<ValueId>(v)))
        order.push_back(static_cast<ValueId>(v));
    prologue_block(f.body, order);
    for (ValueId v : order)
      slot[v] = static_cast<int32_t>(code.splat_count++);
    for (ValueId v : order) {
      const Inst& in = f.insts[v];
      PInstr p;
      p.d = static_cast<uint32_t>(slot[v]) * kSplatBytes;
      const auto off = [&](int k) {
        return in.arg[k] == kNoValue ? 0u : static_cast<uint32_t>(slot[in.arg[k]]) * kSplatBytes;
      };
      if (in.op == Op::Const) {
        p.kernel = special_kernel(Special::LoadConst);
        p.aux = static_cast<uint32_t>(in.imm[0]);
      } else if (in.op == Op::Uniform) {
        p.kernel =
            special_kernel(in.type == Type::Bool ? Special::LoadUniformBool : Special::LoadUniform);
        p.aux = static_cast<uint32_t>(in.imm[0]);
      } else if (in.op == Op::UniformIndexed) {
        p.kernel = special_kernel(in.type == Type::Bool ? Special::GatherBool : Special::Gather);
        p.a = off(0);
        p.aux = static_cast<uint32_t>(in.imm[0]);
        p.b = static_cast<uint32_t>(in.imm[1]);
        p.c = static_cast<uint32_t>(in.imm[2]);
      } else {
        LaneOp op;
        if (!lane_op_for(f, in, op)) {
          err = "internal: hoisted instruction without a lane op";
          return;
        }
        p.kernel = lane_kernel(op, 0);
        p.a = off(0), p.b = off(1), p.c = off(2);
      }
      code.prologue.push_back(p);
    }
    code.prologue.push_back({special_kernel(Special::End)});
  }

  // ---- linearization ----

  int new_label() {
    label_at.push_back(-1);
    return static_cast<int>(label_at.size() - 1);
  }
  void place(int label) {
    label_at[static_cast<size_t>(label)] = static_cast<int>(lin.size());
    LI li;
    li.label = true;
    lin.push_back(li);
  }
  void lane(LaneOp op, ValueId dst, ValueId a, ValueId b = kNoValue, ValueId c = kNoValue) {
    LI li;
    li.lane = true;
    li.op = op;
    li.dst = dst;
    li.src[0] = a, li.src[1] = b, li.src[2] = c;
    lin.push_back(li);
  }
  void special(Special s, ValueId dst = kNoValue, ValueId a = kNoValue, uint32_t aux = 0,
               int target = -1) {
    LI li;
    li.special = s;
    li.dst = dst;
    li.src[0] = a;
    li.aux = aux;
    li.target = target;
    lin.push_back(li);
  }
  void copy(ValueId dst, ValueId src) { lane(LaneOp::Mov, dst, src); }

  // Parallel copies dst[i] <- src[i], ordered so that no source is overwritten before it is
  // read; a cycle goes through a fresh temporary value.
  void parallel_copy(std::vector<std::pair<ValueId, ValueId>> moves) {
    std::erase_if(moves, [](const auto& m) { return m.first == m.second; });
    while (!moves.empty()) {
      bool progress = false;
      for (size_t i = 0; i < moves.size(); ++i) {
        const ValueId dst = moves[i].first;
        const bool read_later =
            std::any_of(moves.begin(), moves.end(), [&](const auto& m) { return m.second == dst; });
        if (!read_later) {
          copy(dst, moves[i].second);
          moves.erase(moves.begin() + static_cast<long>(i));
          progress = true;
          break;
        }
      }
      if (!progress) {
        // Every destination is still read: save one in a temporary.
        const ValueId dst = moves[0].first;
        const ValueId tmp = temp_value(f.insts[dst].type);
        copy(tmp, dst);
        for (auto& m : moves)
          if (m.second == dst) m.second = tmp;
      }
    }
  }
  // Values the code generator adds (temporaries of parallel copies) get ids past the IR's.
  std::vector<Type> extra_types;
  ValueId temp_value(Type t) {
    extra_types.push_back(t);
    const auto id = static_cast<ValueId>(f.insts.size() + extra_types.size() - 1);
    cls.push_back(Class::Reg);
    return id;
  }

  void linear_block(const Block& b, int exit_label) {
    for (const Node& n : b) {
      if (n.kind == NodeKind::Inst) {
        linear_inst(n.index, exit_label);
      } else if (n.kind == NodeKind::Region) {
        const Region& g = f.regions[n.index];
        const int skip = new_label(), end = new_label();
        special(is_splat(g.cond) ? Special::JumpIfNoneS : Special::JumpIfNone, kNoValue, g.cond, 0,
                g.outs.empty() ? end : skip);
        linear_block(g.body, -1);
        if (!g.outs.empty()) {
          for (const RegionOut& o : g.outs)
            copy(o.phi, o.inner);
          special(Special::Jump, kNoValue, kNoValue, 0, end);
          place(skip);
          for (const RegionOut& o : g.outs)
            copy(o.phi, o.outer);
        }
        place(end);
      } else {
        const Loop& l = f.loops[n.index];
        if (depth >= kMaxLoopDepth) {
          err = "loops nested more than " + std::to_string(kMaxLoopDepth) + " deep";
          return;
        }
        for (const LoopPhi& p : l.phis)
          copy(p.phi, p.init);
        special(Special::LoopInit, kNoValue, kNoValue, static_cast<uint32_t>(depth));
        const int head = new_label(), exit = new_label();
        place(head);
        const int head_pos = static_cast<int>(lin.size());
        ++depth;
        linear_block(l.body, exit);
        --depth;
        std::vector<std::pair<ValueId, ValueId>> moves;
        for (const LoopPhi& p : l.phis)
          moves.emplace_back(p.phi, p.next);
        parallel_copy(moves);
        special(Special::Jump, kNoValue, kNoValue, 0, head);
        loop_ranges.push_back({head_pos, static_cast<int>(lin.size() - 1)});
        place(exit);
        for (const LoopExit& e : l.exits)
          copy(e.out, e.inner);
      }
    }
  }

  void linear_inst(ValueId v, int exit_label) {
    const Inst& in = f.insts[v];
    if (cls[v] == Class::Splat || fused[v]) return;
    LaneOp op;
    if (lane_op_for(f, in, op)) {
      const auto fused_with = [&](ValueId x, Op o) {
        return x != kNoValue && fused[x] && f.insts[x].op == o;
      };
      if (in.op == Op::Add && fused_with(in.arg[0], Op::Mul)) {
        const Inst& m = f.insts[in.arg[0]];
        lane(LaneOp::Mad, v, m.arg[0], m.arg[1], in.arg[1]);
      } else if (in.op == Op::Add && fused_with(in.arg[1], Op::Mul)) {
        const Inst& m = f.insts[in.arg[1]];
        lane(LaneOp::Mad, v, m.arg[0], m.arg[1], in.arg[0]);
      } else if (in.op == Op::Min && fused_with(in.arg[0], Op::Max)) {
        const Inst& m = f.insts[in.arg[0]];
        lane(LaneOp::Clamp, v, m.arg[0], m.arg[1], in.arg[1]);
      } else {
        lane(op, v, in.arg[0], in.arg[1], in.arg[2]);
      }
      return;
    }
    switch (in.op) {
    case Op::UniformIndexed: {
      LI li;
      li.special = in.type == Type::Bool ? Special::GatherBool : Special::Gather;
      li.dst = v;
      li.src[0] = in.arg[0];
      li.aux = static_cast<uint32_t>(in.imm[0]);
      li.b_imm = static_cast<uint32_t>(in.imm[1]);
      li.c_imm = static_cast<uint32_t>(in.imm[2]);
      lin.push_back(li);
      break;
    }
    case Op::Ddx:
    case Op::Ddy:
      // simplify() folds the derivatives of uniform values to zero.
      if (is_splat(in.arg[0])) err = "internal: derivative of a uniform value";
      special(in.op == Op::Ddx ? Special::Ddx : Special::Ddy, v, in.arg[0]);
      break;
    case Op::Tex: {
      TexLI t;
      for (int k = 0; k < 3; ++k)
        t.coord[k] = in.arg[k];
      t.lod = in.arg[3];
      t.sampler_word = static_cast<uint32_t>(in.imm[0]);
      t.kind = TexKind::unpack(in.imm[1]);
      auto it = tex_comps.find(v);
      if (it != tex_comps.end())
        for (ValueId c : it->second)
          t.dst[f.insts[c].imm[0] & 3] = c;
      texs.push_back(t);
      LI li;
      li.special = Special::Tex;
      li.tex = static_cast<int>(texs.size() - 1);
      lin.push_back(li);
      if (std::find(code.sampler_words.begin(), code.sampler_words.end(),
                    static_cast<int>(t.sampler_word)) == code.sampler_words.end())
        code.sampler_words.push_back(static_cast<int>(t.sampler_word));
      break;
    }
    case Op::TexComp:
      break;
    case Op::StoreOutput: {
      // The stores read registers: a constant or uniform result is copied to one first.
      ValueId src = in.arg[0];
      if (is_splat(src)) {
        const ValueId tmp = temp_value(f.insts[src].type);
        copy(tmp, src);
        src = tmp;
      }
      if (in.imm[0] == kKillOutput) {
        code.discards = true;
        special(Special::StoreKill, kNoValue, src);
      } else {
        special(Special::StoreOutput, kNoValue, src, static_cast<uint32_t>(in.imm[0]));
        code.outputs.push_back(in.imm[0]);
      }
      break;
    }
    case Op::ExitIfNone:
      special(is_splat(in.arg[0]) ? Special::ExitIfNoneS : Special::ExitIfNone, kNoValue, in.arg[0],
              0, exit_label);
      lin.back().c_imm = static_cast<uint32_t>(depth - 1);
      break;
    default:
      err = std::string("internal: cannot generate ") + op_name(in.op);
      break;
    }
  }

  // ---- registers ----

  std::vector<int> reg; // register of each Reg value

  bool allocate() {
    const size_t nv = f.insts.size() + extra_types.size();
    std::vector<int> start(nv, -1), end(nv, -1);
    const auto def = [&](ValueId v, int p) {
      if (v == kNoValue || cls[v] != Class::Reg) return;
      if (start[v] < 0 || p < start[v]) start[v] = p;
      end[v] = std::max(end[v], p);
    };
    const auto use = [&](ValueId v, int p) {
      if (v == kNoValue || cls[v] != Class::Reg) return;
      end[v] = std::max(end[v], p);
      if (start[v] < 0) start[v] = p;
    };
    for (int p = 0; p < static_cast<int>(lin.size()); ++p) {
      const LI& li = lin[static_cast<size_t>(p)];
      if (li.label) continue;
      for (ValueId s : li.src)
        use(s, p);
      if (li.tex >= 0) {
        const TexLI& t = texs[static_cast<size_t>(li.tex)];
        for (ValueId s : t.coord)
          use(s, p);
        use(t.lod, p);
        for (ValueId d : t.dst)
          def(d, p);
      }
      def(li.dst, p);
    }
    for (int pass = 0; pass < 2; ++pass)
      for (const LoopRange& r : loop_ranges)
        for (size_t v = 0; v < nv; ++v)
          if (start[v] >= 0 && start[v] < r.head && end[v] >= r.head && end[v] < r.end)
            end[v] = r.end;
    std::vector<ValueId> order;
    for (size_t v = 0; v < nv; ++v)
      if (start[v] >= 0) order.push_back(static_cast<ValueId>(v));
    std::sort(order.begin(), order.end(),
              [&](ValueId x, ValueId y) { return start[x] < start[y]; });
    reg.assign(nv, -1);
    std::vector<int> free_regs;
    int next_reg = 2; // 0: entry lanes, 1: results nobody reads
    std::vector<ValueId> active;
    for (ValueId v : order) {
      for (size_t k = 0; k < active.size();) {
        if (end[active[k]] < start[v]) {
          free_regs.push_back(reg[active[k]]);
          active[k] = active.back();
          active.pop_back();
        } else {
          ++k;
        }
      }
      if (free_regs.empty()) {
        reg[v] = next_reg++;
      } else {
        // The lowest free register keeps the working set small.
        auto it = std::min_element(free_regs.begin(), free_regs.end());
        reg[v] = *it;
        free_regs.erase(it);
      }
      active.push_back(v);
    }
    code.reg_count = static_cast<uint32_t>(next_reg);
    if (next_reg > 4096) {
      err = "program needs more than 4096 registers";
      return false;
    }
    return true;
  }

  uint32_t operand(ValueId v, int k, uint32_t& kinds) const {
    if (v == kNoValue) return 0;
    if (cls[v] == Class::Splat) {
      kinds |= 1u << k;
      return static_cast<uint32_t>(slot[v]) * kSplatBytes;
    }
    return static_cast<uint32_t>(reg[v]) * kRegBytes;
  }

  void emit_main() {
    std::vector<int> pos_to_pc(lin.size() + 1, 0);
    int pc = 0;
    for (size_t p = 0; p < lin.size(); ++p) {
      pos_to_pc[p] = pc;
      if (!lin[p].label) ++pc;
    }
    pos_to_pc[lin.size()] = pc;
    for (const LI& li : lin) {
      if (li.label) continue;
      PInstr p;
      uint32_t kinds = 0;
      if (li.dst != kNoValue) p.d = static_cast<uint32_t>(reg[li.dst]) * kRegBytes;
      p.a = operand(li.src[0], 0, kinds);
      p.b = operand(li.src[1], 1, kinds);
      p.c = operand(li.src[2], 2, kinds);
      p.aux = li.aux;
      if (li.lane) {
        const int n = lane_op_arity(li.op);
        if (n < 2) p.b = p.a;
        if (n < 3) p.c = p.a;
        p.kernel = lane_kernel(li.op, static_cast<int>(kinds));
      } else {
        Special s = li.special;
        if (kinds & 1) {
          // Splat sources of the specials that read registers.
          if (s == Special::StoreOutput || s == Special::StoreKill || s == Special::Ddx ||
              s == Special::Ddy || s == Special::Gather || s == Special::GatherBool) {
            err = "internal: splat operand of a register kernel";
            return;
          }
        }
        p.kernel = special_kernel(s);
        if (li.target >= 0)
          p.aux = static_cast<uint32_t>(
              pos_to_pc[static_cast<size_t>(label_at[static_cast<size_t>(li.target)])]);
        if (s == Special::Gather || s == Special::GatherBool) p.b = li.b_imm, p.c = li.c_imm;
        if (s == Special::ExitIfNone || s == Special::ExitIfNoneS) p.c = li.c_imm;
        if (s == Special::Tex) {
          const TexLI& t = texs[static_cast<size_t>(li.tex)];
          TexDesc d;
          d.sampler_word = t.sampler_word;
          d.kind = t.kind;
          uint32_t tk = 0;
          for (int k = 0; k < 3; ++k) {
            if (t.coord[k] == kNoValue) continue;
            d.present |= static_cast<uint8_t>(1u << k);
            uint32_t one = 0;
            d.coord[k] = operand(t.coord[k], 0, one);
            if (one) d.splat |= static_cast<uint8_t>(1u << k);
          }
          if (t.lod != kNoValue) {
            d.present |= 8;
            uint32_t one = 0;
            d.lod = operand(t.lod, 0, one);
            if (one) d.splat |= 8;
          }
          (void)tk;
          for (int k = 0; k < 4; ++k)
            d.dst[k] =
                t.dst[k] == kNoValue ? kRegBytes : static_cast<uint32_t>(reg[t.dst[k]]) * kRegBytes;
          code.tex.push_back(d);
          p.aux = static_cast<uint32_t>(code.tex.size() - 1);
        }
      }
      code.main.push_back(p);
    }
    code.main.push_back({special_kernel(Special::End)});
  }

  bool run(std::string* error) {
    const size_t n = f.insts.size();
    cls.assign(n, Class::None);
    uses.assign(n, 0);
    fused.assign(n, 0);
    home.assign(n, nullptr);
    input_used.assign(n, 0);
    for (size_t v = 0; v < n; ++v) {
      const Op op = f.insts[v].op;
      if (op == Op::Const || op == Op::Uniform) cls[v] = Class::Splat;
      if (op == Op::Input) cls[v] = Class::Reg;
    }
    classify_block(f.body);
    fuse_block(f.body);
    // Splats the per-run code reads (and the zero that stands for derivatives of splats).
    needed_splat.assign(n, 0);
    slot.assign(n, -1);
    linear_inputs();
    linear_block(f.body, -1);
    if (!err.empty()) return fail(error);
    cls.resize(f.insts.size() + extra_types.size(), Class::Reg);
    needed_splat.resize(cls.size(), 0);
    for (const LI& li : lin) {
      for (ValueId s : li.src)
        need(s);
      if (li.tex >= 0) {
        for (ValueId s : texs[static_cast<size_t>(li.tex)].coord)
          need(s);
        need(texs[static_cast<size_t>(li.tex)].lod);
      }
    }
    slot.resize(cls.size(), -1);
    emit_prologue();
    if (!err.empty()) return fail(error);
    if (!allocate()) return fail(error);
    emit_main();
    if (!err.empty()) return fail(error);
    std::sort(code.inputs.begin(), code.inputs.end());
    std::sort(code.outputs.begin(), code.outputs.end());
    code.outputs.erase(std::unique(code.outputs.begin(), code.outputs.end()), code.outputs.end());
    std::sort(code.sampler_words.begin(), code.sampler_words.end());
    return true;
  }

  bool fail(std::string* error) {
    if (error) *error = err;
    return false;
  }

  // Every input the per-run code reads is loaded once, at the start.
  void linear_inputs() {
    std::vector<ValueId> ins;
    for (size_t v = 0; v < f.insts.size(); ++v)
      if (input_used[v]) ins.push_back(static_cast<ValueId>(v));
    std::sort(ins.begin(), ins.end(),
              [&](ValueId a, ValueId b) { return f.insts[a].imm[0] < f.insts[b].imm[0]; });
    for (ValueId v : ins) {
      const int comp = f.insts[v].imm[0];
      if (stage == Stage::Fragment && comp / 4 == kFrontFacingSlot) {
        special(Special::LoadFacing, v);
      } else {
        special(Special::LoadInput, v, kNoValue, static_cast<uint32_t>(comp));
        code.inputs.push_back(comp);
      }
    }
  }
  static constexpr int kFrontFacingSlot = 13; // io.h kFragFrontFacing
};

} // namespace

bool generate_code(const Function& ir, Stage stage, Code& out, std::string* error) {
  out = Code{};
  Gen g(ir, stage, out);
  return g.run(error);
}

const char* kernel_name(uint16_t id) {
  if (id < kLaneKernels) return lane_op_name(static_cast<LaneOp>(id / 8));
  switch (static_cast<Special>(id - kLaneKernels)) {
#define PINEDA_X(name)                                                                             \
  case Special::name:                                                                              \
    return #name;
    PINEDA_SPECIAL_KERNELS(PINEDA_X)
#undef PINEDA_X
  case Special::Count:
    break;
  }
  return "?";
}

std::string disassemble(const Code& c) {
  std::string s;
  char buf[160];
  const auto list = [&](const std::vector<PInstr>& v, const char* title) {
    s += title;
    s += '\n';
    for (size_t i = 0; i < v.size(); ++i) {
      const PInstr& p = v[i];
      const char* kinds = "";
      if (p.kernel < kLaneKernels) {
        static const char* const k[] = {"", ".s__", ".rs_", ".ss_", ".__s", ".s_s", ".rss", ".sss"};
        kinds = k[p.kernel % 8];
      }
      std::snprintf(buf, sizeof buf, "%4zu %-12s%-5s d=%u a=%u b=%u c=%u aux=%u\n", i,
                    kernel_name(p.kernel), kinds, p.d, p.a, p.b, p.c, p.aux);
      s += buf;
    }
  };
  list(c.prologue, "prologue:");
  list(c.main, "main:");
  std::snprintf(buf, sizeof buf, "registers %u, splats %u\n", c.reg_count, c.splat_count);
  s += buf;
  return s;
}

} // namespace pineda::shader
