// The execution tests' lane runner (lanes.h).
#include "support/lanes.h"

#include <bit>

#include "shader/io.h"

namespace pineda::glsl_test {

std::vector<SimdLevel> levels() {
  std::vector<SimdLevel> out{SimdLevel::Baseline};
  const SimdLevel top = simd_level_supported();
  if (static_cast<int>(top) >= static_cast<int>(SimdLevel::Avx2)) out.push_back(SimdLevel::Avx2);
  if (top == SimdLevel::Avx512) out.push_back(SimdLevel::Avx512);
  return out;
}

const char* level_name(SimdLevel l) {
  return l == SimdLevel::Avx512 ? "avx512" : l == SimdLevel::Avx2 ? "avx2" : "baseline";
}

uint32_t bits(float f) {
  return std::bit_cast<uint32_t>(f);
}

LaneShader::LaneShader(const std::string& source, const glsl::Limits& limits) {
  program = build("", source, &log, limits);
  if (program) pipe = std::make_unique<Pipeline>(*program);
}

std::vector<Vec4> LaneShader::run(const std::vector<std::array<Vec4, 4>>& in, uint64_t* kill) {
  const int lanes = static_cast<int>(std::min<size_t>(in.size(), 64));
  const int quads = std::max(1, (lanes + 3) / 4);
  std::vector<std::vector<float>> fin(static_cast<size_t>(quads * 4),
                                      std::vector<float>(shader::kNumFragmentInputs * 4, 0.0f));
  static const char* const names[4] = {"v0", "v1", "v2", "v3"};
  for (int l = 0; l < lanes; ++l)
    for (int v = 0; v < 4; ++v)
      for (int c = 0; c < 4; ++c) {
        const int k = program->varying_component(names[v], c);
        if (k >= 0)
          fin[static_cast<size_t>(l)][static_cast<size_t>(shader::kFragVarying0 * 4 + k)] =
              in[static_cast<size_t>(l)][static_cast<size_t>(v)][static_cast<size_t>(c)];
      }
  std::vector<std::vector<float>> out;
  const uint64_t k = pipe->run_fragments(quads, fin, out);
  if (kill) *kill = k;
  std::vector<Vec4> r(static_cast<size_t>(lanes));
  for (int l = 0; l < lanes; ++l)
    for (int c = 0; c < 4; ++c)
      r[static_cast<size_t>(l)][static_cast<size_t>(c)] =
          out[static_cast<size_t>(l)][static_cast<size_t>(c)];
  return r;
}

} // namespace pineda::glsl_test
