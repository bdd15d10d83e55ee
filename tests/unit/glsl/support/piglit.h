// piglit's GLSL 1.10/1.20 tests as a corpus for the front end and the engine:
// - glslparsertest files (.vert, .frag with a [config] block): compile (and link when
//   check_link says so) and compare with expect_result;
// - shader_runner files (.shader_test): link, expect "link error"/"link success", and run the
//   drawing commands this harness knows (uniforms, draw rect, probes, rgbw textures) on the
//   engine through harness.h, comparing the probes.
// Tests needing what the harness does not have (extensions, other GLSL versions, vertex data,
// most texture commands) are skipped, with the reason.
#pragma once

#include <string>
#include <vector>

namespace pineda::glsl_test {

enum class Outcome { Pass, Fail, Skip };

struct CaseResult {
  Outcome outcome = Outcome::Skip;
  std::string why;
  double compile_link_ms = 0; // glslang and Pineda, for the tests that linked
};

// The corpus under piglit's install folder: GLSL 1.10 and 1.20 tests, sorted.
std::vector<std::string> corpus_files(const std::string& piglit_dir);

CaseResult run_case(const std::string& path);

} // namespace pineda::glsl_test
