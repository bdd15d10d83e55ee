// Running a fragment shader over one block of lanes with per-lane varyings, at each SIMD level:
// the execution tests' common tool.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/simd_level.h"
#include "support/harness.h"

namespace pineda::glsl_test {

// The SIMD levels this machine runs (Baseline first).
std::vector<SimdLevel> levels();
const char* level_name(SimdLevel l);

// A fragment shader whose inputs are the varyings v0..v3 (vec4) and whose result is
// gl_FragColor (unclamped), run over 64 lanes.
class LaneShader {
public:
  // `source` is a whole fragment shader; it may declare v0..v3 as varying vec4.
  explicit LaneShader(const std::string& source, const glsl::Limits& limits = {});
  bool ok() const { return program != nullptr; }
  // in[lane][v][comp]; the result per lane. Lanes beyond in.size() are zero; 64 at most.
  std::vector<Vec4> run(const std::vector<std::array<Vec4, 4>>& in, uint64_t* kill = nullptr);

  std::unique_ptr<glsl::Program> program;
  std::unique_ptr<Pipeline> pipe;
  std::string log;
};

// Bits of a float, for comparing runs exactly.
uint32_t bits(float f);

} // namespace pineda::glsl_test
