// The IR's optimization passes. Each keeps the IR valid (ir.h verify) and returns whether it
// changed something.
#pragma once

#include <cstdint>

#include "shader/ir.h"
#include "shader/lane_ops.h"

namespace pineda::shader {

// The engine's lane operation for an IR instruction (false for ops that are not lane-wise:
// leaves, Tex, derivatives, control).
bool lane_op_for(const Function& f, const Inst& in, LaneOp& out);
// One lane of `op` on the given 32-bit patterns, as the engine computes it.
uint32_t eval_lane_op(LaneOp op, uint32_t a, uint32_t b, uint32_t c);
// The constant an instruction with constant operands evaluates to.
bool fold_constant(const Function& f, const Inst& in, uint32_t& out);

// Constant folding, algebraic identities that hold bit for bit (x * 1, select on a constant,
// and/or with constants), trivial phis, regions with a constant or empty body, and loops
// that exit in their first iteration.
bool simplify(Function& f);
// Common subexpressions: an instruction equal to one that dominates it is replaced by it.
bool cse(Function& f);
// Dead code: everything no output depends on, including whole regions and loops.
bool dce(Function& f);
// Regions whose body costs less than testing the condition are merged into their parent
// (masked updates make that always valid; uniform regions get selects for their outs).
bool flatten_small_regions(Function& f, int max_insts);
// The standard pipeline: the passes above until nothing changes.
void optimize(Function& f);

// Values that are the same in every lane: constants, uniforms and what only they compute.
std::vector<uint8_t> uniform_values(const Function& f);

// Values the placed code reads (operands of instructions in blocks, region conditions and
// outs, loop phis and exits), including leaves: used[v] != 0.
std::vector<uint8_t> used_values(const Function& f);

// Number of instructions in blocks (regions and loops included).
int count_insts(const Function& f);

} // namespace pineda::shader
