// The engine's machine: instructions, the run state and the kernel tables of each SIMD level.
// Shared by the code generator (codegen.cpp), the runner (engine.cpp) and the kernel files
// (engine_sse2.cpp, engine_avx2.cpp, engine_avx512.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/simd_level.h"
#include "shader/engine.h"
#include "shader/ir.h"
#include "shader/lane_ops.h"

namespace pineda::shader {

struct Instr;
struct Frame;
// A kernel runs one instruction over the frame's lanes and continues with the next one.
using Kernel = const Instr* (*)(const Instr* ip, Frame& f);

// How a kernel continues (PINEDA_NEXT). Threaded: it tail-calls the next kernel, so a program
// runs as one chain of jumps and returns nullptr from End. Otherwise it returns the next
// instruction to the dispatch loop (engine.cpp execute), which calls it. A tail call must be
// guaranteed: an unoptimized call per instruction would grow the stack with every instruction
// a loop runs. Clang guarantees it with musttail; GCC makes sibling calls in optimized builds,
// but not always with AddressSanitizer's instrumentation, so those builds use the loop.
#if defined(__has_cpp_attribute)
#if __has_cpp_attribute(clang::musttail)
#define PINEDA_SHADER_THREADED 1
#define PINEDA_NEXT(next)                                                                          \
  do {                                                                                             \
    const Instr* pineda_next_ = (next);                                                            \
    [[clang::musttail]] return pineda_next_->fn(pineda_next_, f);                                  \
  } while (0)
#endif
#endif
#if !defined(PINEDA_SHADER_THREADED) && defined(__GNUC__) && defined(__OPTIMIZE__) &&              \
    !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__) &&                             \
    !defined(PINEDA_SHADER_LOOP)
#define PINEDA_SHADER_THREADED 1
#define PINEDA_NEXT(next)                                                                          \
  do {                                                                                             \
    const Instr* pineda_next_ = (next);                                                            \
    return pineda_next_->fn(pineda_next_, f);                                                      \
  } while (0)
#endif
#if !defined(PINEDA_SHADER_THREADED)
#define PINEDA_SHADER_THREADED 0
#define PINEDA_NEXT(next) return (next)
#endif

// Register operands and results are byte offsets into the frame's registers; splat operands
// byte offsets into the prepared splats. `aux` is a jump target (instruction index), an input
// or output component, a uniform word, a constant's bits or a texture descriptor's index.
struct Instr {
  Kernel fn;
  uint32_t d, a, b, c;
  uint32_t aux;
};

constexpr uint32_t kRegBytes = kBlockLanes * 4; // one register: 64 lanes
constexpr uint32_t kSplatBytes = 64;            // one splat: 16 lanes
constexpr int kMaxLoopDepth = 16;

// The special (not lane-wise) kernels.
#define PINEDA_SPECIAL_KERNELS(X)                                                                  \
  X(LoadInput)   /* d <- in[aux] (lanes of this run) */                                            \
  X(LoadFacing)  /* d <- front_facing mask */                                                      \
  X(StoreOutput) /* out[aux] <- a */                                                               \
  X(StoreKill)   /* kill bits <- a & entry */                                                      \
  X(Gather)      /* d <- uniforms[aux + clamp(a, 0, c - 1) * b] */                                 \
  X(GatherBool)  /* the same, != 0 as a mask */                                                    \
  X(Tex)         /* texture lookup, descriptor aux */                                              \
  X(Ddx)         /* d <- a's difference along x in each quad */                                    \
  X(Ddy)                                                                                           \
  X(Jump)        /* to aux */                                                                      \
  X(JumpIfNone)  /* to aux when no entry lane of register a is set */                              \
  X(JumpIfNoneS) /* the same for a splat */                                                        \
  X(LoopInit)    /* loop counter aux <- 0 */                                                       \
  X(ExitIfNone)  /* to aux when no entry lane of a is set or counter c is spent */                 \
  X(ExitIfNoneS)                                                                                   \
  X(End)                                                                                           \
  X(LoadConst)       /* d <- aux bits (prologue) */                                                \
  X(LoadUniform)     /* d <- uniforms[aux] (prologue) */                                           \
  X(LoadUniformBool) /* d <- uniforms[aux] != 0 (prologue) */

enum class Special : uint16_t {
#define PINEDA_X(name) name,
  PINEDA_SPECIAL_KERNELS(PINEDA_X)
#undef PINEDA_X
      Count
};

// Kernel ids: lane op `op` with operand kinds `k` (bit i set: operand i is a splat) is
// op * 8 + k; the specials follow.
constexpr int kLaneKernels = static_cast<int>(LaneOp::Count) * 8;
constexpr int kNumKernels = kLaneKernels + static_cast<int>(Special::Count);
constexpr uint16_t lane_kernel(LaneOp op, int kinds) {
  return static_cast<uint16_t>(static_cast<int>(op) * 8 + kinds);
}
constexpr uint16_t special_kernel(Special s) {
  return static_cast<uint16_t>(kLaneKernels + static_cast<int>(s));
}

// An instruction before its kernel is chosen for a SIMD level.
struct PInstr {
  uint16_t kernel;
  uint32_t d = 0, a = 0, b = 0, c = 0;
  uint32_t aux = 0;
};

struct TexDesc {
  uint32_t sampler_word = 0;
  TexKind kind;
  uint32_t coord[3] = {0, 0, 0}; // register or splat offsets
  uint32_t lod = 0;
  uint8_t present = 0; // bit i: coord[i] used; bit 3: lod used
  uint8_t splat = 0;   // bit i: operand i is a splat
  uint32_t dst[4] = {0, 0, 0, 0};
};

// Everything a run reads besides its registers.
struct RunState {
  const float* const* in = nullptr;
  float* const* out = nullptr;
  int base = 0;  // first vertex of this batch in the caller's arrays
  int lanes = 0; // lanes of this run
  const uint32_t* uniforms = nullptr;
  TextureSampler* sampler = nullptr;
  const TexDesc* tex = nullptr;
  bool front_facing = true;
  uint32_t loop_count[kMaxLoopDepth] = {};
  uint32_t budget = kRunIterationBudget;
  uint64_t kill = 0;
  float* tmp = nullptr;    // 4 * kBlockLanes floats for splatted texture operands
  uint32_t caller_csr = 0; // the caller's floating-point environment (fp_env.h)
};

struct Frame {
  char* regs;
  const char* splats;
  const Instr* code;
  RunState* rs;
  int nvec; // vectors per register of this run
};

// A run covers either a whole block (64 lanes) or a small run of 16 lanes (up to four quads; the
// prologue's splats), each with its own kernel table whose lane loops have a fixed trip count
// and are unrolled: a loop over a run-time count cost about as much as a whole block even for
// one quad (glsl_bench). Lanes past a run's own are computed on zeros and never stored.
constexpr int kSmallRunLanes = 16;
struct KernelTable {
  const Kernel* k;
  int width; // lanes per vector: a register is kBlockLanes / width vectors
};
// The table of each level for blocks (`block`) or small runs. Levels the build does not have
// return the level below's table.
KernelTable kernels_baseline(bool block);
KernelTable kernels_avx2(bool block);
KernelTable kernels_avx512(bool block);

// The compiled program, portable across levels.
struct Code {
  std::vector<PInstr> prologue; // runs over the splats: evaluates constants, uniforms and
                                // everything computed from them only
  std::vector<PInstr> main;
  std::vector<TexDesc> tex;
  uint32_t splat_count = 0;
  uint32_t reg_count = 0; // register 0: the entry lanes
  std::vector<int> inputs, outputs, sampler_words;
  bool discards = false;
};

// IR to code (codegen.cpp).
bool generate_code(const Function& ir, Stage stage, Code& out, std::string* error);
std::string disassemble(const Code& c);
const char* kernel_name(uint16_t id);

} // namespace pineda::shader
