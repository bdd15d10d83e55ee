// The shader execution engine: runs a compiled stage (Executable) over many vertices or over a
// rasterizer block's 2x2 quads at once. Registers are structure-of-arrays: one register holds
// one value for 64 lanes, and every instruction runs over all the lanes of the block before
// the next one starts, so instruction dispatch is paid once per block. The instructions are
// threaded code: a table of kernel functions, each specialized by SIMD level (4, 8 or 16
// lanes per vector, simd_level.h) and by operand kind (a register, or a uniform or constant
// splatted across the vector), each returning the next instruction.
//
// Use: build() an Executable from optimized IR once per linked program; prepare() it once per
// draw (or whenever the uniforms change) to evaluate everything that depends only on uniforms;
// then run_vertices()/run_fragments() from any number of threads, each with its own scratch
// registers (scratch_bytes()). Every SIMD level writes the same bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "shader/ir.h"

namespace pineda::shader {

constexpr int kBlockLanes = 64;                    // lanes per register: a rasterizer block
constexpr uint32_t kLoopIterationLimit = 65535;    // per loop entry, as llvmpipe
constexpr uint32_t kRunIterationBudget = 1u << 20; // all loops of one run together

// ---- texture lookups: a call out of the engine ----

// One texture lookup for the lanes of a block. Inactive lanes (outside the primitive, or in
// branches they did not take) carry arbitrary coordinates, NaN included: the sampler returns
// something for them without faulting.
struct TexRequest {
  int unit = 0; // texture image unit: the sampler uniform's value
  TexTarget target = TexTarget::Tex2D;
  bool shadow = false; // compare r with the depth texel (GL 2.1 §3.8.14)
  LodMode lod = LodMode::Implicit;
  int lanes = 0;                      // lanes to sample; fragment lookups: whole quads
  const float* coord[3] = {};         // s, t, r (r: the depth reference of 1D/2D shadow
                                      // lookups); projective lookups are already divided by q
  const float* lod_or_bias = nullptr; // per lane: the bias (Bias) or the level (Explicit)
  float* rgba[4] = {};                // per lane results
};
// Implicit and Bias lookups come from fragment shaders: lanes 4q..4q+3 are quad q's
// fragments (x, y), (x+1, y), (x, y+1), (x+1, y+1), so the level of detail can be computed
// from the quad's coordinates (§3.8.8). Vertex shaders use Explicit (0 for the non-Lod forms).
class TextureSampler {
public:
  virtual ~TextureSampler() = default;
  virtual void sample(const TexRequest& req) = 0;
};

// ---- runs ----

// The uniform-dependent part of a program, evaluated by prepare(): read-only while the runs
// use it (from any thread).
struct Prepared {
  std::vector<float> splats; // 16 lanes per slot
  const uint32_t* uniforms = nullptr;
};

struct VertexBatch {
  int count = 0;                    // vertices
  const float* const* in = nullptr; // in[component]: count floats (components the
                                    // Executable reads; others may be null)
  float* const* out = nullptr;      // out[component]: count floats (components written)
  TextureSampler* sampler = nullptr;
};

struct FragmentQuads {
  int quads = 0;                    // 1..16 quads: lanes 0 .. 4 * quads - 1
  const float* const* in = nullptr; // in[component]: 4 * quads floats
  bool front_facing = true;         // gl_FrontFacing for every lane
  float* const* out = nullptr;      // out[component]: 4 * quads floats
  TextureSampler* sampler = nullptr;
};

enum class Stage : uint8_t { Vertex, Fragment };

struct ExecutableImpl;

class Executable {
public:
  // Compiles optimized IR. Fails (null, with a reason in *error) only for programs beyond the
  // engine's limits (loop nesting, register count).
  static std::unique_ptr<Executable> build(const Function& ir, Stage stage, std::string* error);
  ~Executable();

  Stage stage() const;
  // Bytes of scratch registers a run needs (aligned to 64 bytes by the caller).
  size_t scratch_bytes() const;
  void prepare(const uint32_t* uniform_words, Prepared& out) const;
  void run_vertices(const Prepared& p, const VertexBatch& batch, void* scratch) const;
  // Returns the lanes the shader discarded (bit l: lane l).
  uint64_t run_fragments(const Prepared& p, const FragmentQuads& quads, void* scratch) const;

  // What the program touches, for the integration to skip the rest: input and output
  // components (sorted), and the uniform words holding the samplers it reads.
  const std::vector<int>& inputs_read() const;
  const std::vector<int>& outputs_written() const;
  const std::vector<int>& sampler_words() const;
  bool discards() const;

  // The instruction count of the per-run program and of the prologue, for tests and tools.
  int instruction_count() const;
  int prologue_count() const;
  // The compiled code as text (PINEDA_DEBUG=ir).
  std::string disassemble() const;

private:
  Executable() = default;
  std::unique_ptr<ExecutableImpl> impl_;
};

} // namespace pineda::shader
