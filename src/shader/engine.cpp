// The engine's runner (engine.h): builds the threaded code of each SIMD level from the portable
// code and runs it over batches of vertices and blocks of quads.
#include "shader/engine.h"

#include <algorithm>
#include <cstring>

#include "shader/engine_internal.h"
#include "shader/fp_env.h"

namespace pineda::shader {

struct ExecutableImpl {
  Stage stage = Stage::Vertex;
  Code code;
  // Threaded code per level: [level][instruction]; main_block for whole 64-lane blocks,
  // main_small for runs of up to 16 lanes (engine_internal.h), and the lanes per vector of
  // each level's tables.
  std::vector<Instr> prologue[3], main_small[3], main_block[3];
  int width[3] = {4, 4, 4};
};

namespace {

KernelTable table_for(SimdLevel l, bool block) {
  switch (l) {
  case SimdLevel::Avx512:
    return kernels_avx512(block);
  case SimdLevel::Avx2:
    return kernels_avx2(block);
  default:
    return kernels_baseline(block);
  }
}

std::vector<Instr> thread(const std::vector<PInstr>& code, const Kernel* table) {
  std::vector<Instr> out;
  out.reserve(code.size());
  for (const PInstr& p : code)
    out.push_back({table[p.kernel], p.d, p.a, p.b, p.c, p.aux});
  return out;
}

// The dispatch loop: each kernel returns the next instruction.
inline void execute(const Instr* code, Frame& f) {
  const Instr* ip = code;
  while (ip)
    ip = ip->fn(ip, f);
}

char* align64(void* p) {
  const auto v = reinterpret_cast<uintptr_t>(p);
  return reinterpret_cast<char*>((v + 63) & ~uintptr_t{63});
}
const char* splat_base(const Prepared& p) {
  return align64(const_cast<float*>(p.splats.data()));
}

int level_index(SimdLevel l) {
  return static_cast<int>(l);
}

// Register 0 holds the entry lanes: the first `lanes` of the run.
void set_entry(char* regs, int lanes) {
  auto* e = reinterpret_cast<int32_t*>(regs);
  for (int l = 0; l < kBlockLanes; ++l)
    e[l] = l < lanes ? -1 : 0;
}

// One run of `lanes` lanes: a small run or a whole block, whichever covers them.
void run(const ExecutableImpl& e, int level, int lanes, char* regs, const char* splats,
         RunState& rs) {
  const bool block = lanes > kSmallRunLanes;
  const Instr* code = (block ? e.main_block : e.main_small)[level].data();
  Frame f{regs, splats, code, &rs, (block ? kBlockLanes : kSmallRunLanes) / e.width[level]};
  execute(code, f);
}

} // namespace

std::unique_ptr<Executable> Executable::build(const Function& ir, Stage stage, std::string* error) {
  auto impl = std::make_unique<ExecutableImpl>();
  impl->stage = stage;
  if (!generate_code(ir, stage, impl->code, error)) return nullptr;
  const SimdLevel top = simd_level_supported();
  for (int l = 0; l <= level_index(top); ++l) {
    const KernelTable small = table_for(static_cast<SimdLevel>(l), false);
    // The prologue runs over the splats: 16 lanes, a small run.
    static_assert(kSplatBytes / 4 == kSmallRunLanes);
    impl->prologue[l] = thread(impl->code.prologue, small.k);
    impl->main_small[l] = thread(impl->code.main, small.k);
    impl->main_block[l] = thread(impl->code.main, table_for(static_cast<SimdLevel>(l), true).k);
    impl->width[l] = small.width;
  }
  std::unique_ptr<Executable> e(new Executable());
  e->impl_ = std::move(impl);
  return e;
}

Executable::~Executable() = default;

Stage Executable::stage() const {
  return impl_->stage;
}

size_t Executable::scratch_bytes() const {
  return size_t{impl_->code.reg_count} * kRegBytes + 4 * kBlockLanes * sizeof(float) + 64;
}

void Executable::prepare(const uint32_t* uniform_words, Prepared& out) const {
  const size_t floats = size_t{impl_->code.splat_count} * (kSplatBytes / 4) + 16;
  out.splats.assign(floats, 0.0f);
  out.uniforms = uniform_words;
  const int l = level_index(simd_level());
  ShaderFpEnv env;
  RunState rs;
  rs.caller_csr = env.saved();
  rs.uniforms = uniform_words;
  char* base = align64(out.splats.data());
  Frame f{base, base, impl_->prologue[l].data(), &rs, kSmallRunLanes / impl_->width[l]};
  execute(f.code, f);
}

void Executable::run_vertices(const Prepared& p, const VertexBatch& batch, void* scratch) const {
  const int l = level_index(simd_level());
  char* regs = align64(scratch);
  ShaderFpEnv env;
  RunState rs;
  rs.caller_csr = env.saved();
  rs.in = batch.in;
  rs.out = batch.out;
  rs.uniforms = p.uniforms;
  rs.sampler = batch.sampler;
  rs.tex = impl_->code.tex.data();
  rs.tmp = reinterpret_cast<float*>(regs + size_t{impl_->code.reg_count} * kRegBytes);
  for (int base = 0; base < batch.count; base += kBlockLanes) {
    const int lanes = std::min(kBlockLanes, batch.count - base);
    rs.base = base;
    rs.lanes = lanes;
    rs.budget = kRunIterationBudget;
    set_entry(regs, lanes);
    run(*impl_, l, lanes, regs, splat_base(p), rs);
  }
}

uint64_t Executable::run_fragments(const Prepared& p, const FragmentQuads& q, void* scratch) const {
  const int l = level_index(simd_level());
  char* regs = align64(scratch);
  ShaderFpEnv env;
  RunState rs;
  rs.caller_csr = env.saved();
  rs.in = q.in;
  rs.out = q.out;
  rs.uniforms = p.uniforms;
  rs.sampler = q.sampler;
  rs.front_facing = q.front_facing;
  rs.tex = impl_->code.tex.data();
  rs.tmp = reinterpret_cast<float*>(regs + size_t{impl_->code.reg_count} * kRegBytes);
  const int lanes = std::clamp(q.quads, 0, kBlockLanes / 4) * 4;
  if (lanes == 0) return 0;
  rs.lanes = lanes;
  set_entry(regs, lanes);
  run(*impl_, l, lanes, regs, splat_base(p), rs);
  return rs.kill;
}

const std::vector<int>& Executable::inputs_read() const {
  return impl_->code.inputs;
}
const std::vector<int>& Executable::outputs_written() const {
  return impl_->code.outputs;
}
const std::vector<int>& Executable::sampler_words() const {
  return impl_->code.sampler_words;
}
bool Executable::discards() const {
  return impl_->code.discards;
}
int Executable::instruction_count() const {
  return static_cast<int>(impl_->code.main.size());
}
int Executable::prologue_count() const {
  return static_cast<int>(impl_->code.prologue.size());
}
std::string Executable::disassemble() const {
  return shader::disassemble(impl_->code);
}

} // namespace pineda::shader
