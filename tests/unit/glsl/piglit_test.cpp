// piglit's GLSL 1.10/1.20 tests as a corpus (support/piglit.h): every sixth file, so that the
// test run stays short (the glsl_corpus tool runs them all). A file that fails must be in the
// list below, which gives each one's reason; a listed file that passes is reported so that the
// list stays true.
#include <gtest/gtest.h>

#include <map>

#include "support/piglit.h"

namespace pineda::glsl_test {
namespace {

const std::map<std::string, const char*> kKnownFailures = {
    // glslang accepts what GLSL 1.10/1.20 forbids, in forms Pineda does not check:
    {"tests/spec/glsl-1.10/compiler/preprocessor/stringification.frag",
     "glslang accepts # in macros"},
    {"tests/spec/glsl-1.10/compiler/qualifiers/fn-inout-array-prohibited-cstyle.frag",
     "glslang accepts C-style array parameters"},
    {"tests/spec/glsl-1.10/compiler/qualifiers/fn-inout-array-prohibited-cstyle.vert",
     "glslang accepts C-style array parameters"},
    {"tests/spec/glsl-1.10/compiler/qualifiers/fn-out-array-prohibited-cstyle.frag",
     "glslang accepts C-style array parameters"},
    {"tests/spec/glsl-1.10/compiler/qualifiers/fn-out-array-prohibited-cstyle.vert",
     "glslang accepts C-style array parameters"},
    {"tests/spec/glsl-1.10/compiler/void/void-unary_plus.vert", "glslang accepts unary + on void"},
    {"tests/spec/glsl-1.20/compiler/structure-and-array-operations/array-positive.vert",
     "glslang accepts unary + on arrays"},
    {"tests/spec/glsl-1.20/compiler/structure-and-array-operations/"
     "array-redeclaration-too-small.vert",
     "glslang accepts the smaller redeclaration"},
    {"tests/spec/glsl-1.20/compiler/structure-and-array-operations/"
     "array-resize-after-access-too-small.vert",
     "glslang accepts the smaller redeclaration"},
    {"tests/spec/glsl-1.20/compiler/structure-and-array-operations/array-size-ivec2.vert",
     "glslang accepts an ivec array size"},
    {"tests/spec/glsl-1.20/compiler/structure-and-array-operations/array-size-ivec3.vert",
     "glslang accepts an ivec array size"},
    {"tests/spec/glsl-1.20/compiler/structure-and-array-operations/array-size-ivec4.vert",
     "glslang accepts an ivec array size"},
    // glslang refuses valid GLSL:
    {"tests/spec/glsl-1.10/compiler/version-macro-default.frag",
     "glslang: defined __VERSION__ is false"},
    {"tests/spec/glsl-1.10/compiler/version-macro.frag", "glslang: defined __VERSION__ is false"},
    {"tests/spec/glsl-1.20/compiler/version-macro.frag", "glslang: defined __VERSION__ is false"},
    // glslang computes something else:
    {"tests/spec/glsl-1.20/execution/const-builtin/glsl-const-builtin-degrees.shader_test",
     "glslang folds constants in double precision (int(degrees(pi)) = 179)"},
    {"tests/spec/glsl-1.20/execution/fs-do-while-scope.shader_test",
     "glslang: a do-while test sees the body's declaration"},
    {"tests/spec/glsl-1.20/execution/qualifiers/"
     "vs-out-conversion-int-to-float-vec4-index.shader_test",
     "glslang evaluates a converted out argument's index after the call"},
    // The tests rely on Mesa accepting non-GLSL-1.10 code:
    {"tests/spec/glsl-1.10/execution/vs-loop-variable-iteration-limit-unroll.shader_test",
     "min(int, int) is not GLSL 1.10"},
    {"tests/spec/glsl-1.10/linker/fs-loop-unrolled-divide-by-zero.shader_test",
     "the f suffix is not GLSL 1.10"},
    // Pineda inlines every call: 2^64 calls are refused with a link error.
    {"tests/spec/glsl-1.10/execution/glsl-fs-inline-explosion.shader_test",
     "every call is inlined"},
    {"tests/spec/glsl-1.10/execution/glsl-vs-inline-explosion.shader_test",
     "every call is inlined"},
    // The test harness has no fixed-function vertex colour clamping.
    {"tests/spec/glsl-1.10/execution/glsl-clamp-vertex-color.shader_test",
     "harness: no colour clamping"},
};

TEST(PiglitCorpus, SampleMatchesExpectations) {
  const std::string dir = PINEDA_PIGLIT_DIR;
  if (dir.empty()) GTEST_SKIP() << "piglit is not installed";
  const auto files = corpus_files(dir);
  if (files.empty()) GTEST_SKIP() << "no GLSL tests under " << dir;
  int pass = 0, fail = 0, skip = 0, known = 0;
  for (size_t i = 0; i < files.size(); i += 6) {
    const std::string rel = files[i].substr(dir.size() + 1);
    const CaseResult r = run_case(files[i]);
    const bool listed = kKnownFailures.count(rel) > 0;
    if (r.outcome == Outcome::Skip) {
      ++skip;
    } else if (r.outcome == Outcome::Pass) {
      ++pass;
      EXPECT_FALSE(listed) << rel << " passes now: remove it from the known failures";
    } else {
      ++fail;
      known += listed;
      EXPECT_TRUE(listed) << rel << ": " << r.why;
    }
  }
  RecordProperty("pass", pass);
  RecordProperty("fail", fail);
  RecordProperty("skip", skip);
  std::printf("piglit sample: %d pass, %d fail (%d known), %d skipped: %.1f%%\n", pass, fail, known,
              skip, 100.0 * pass / std::max(1, pass + fail));
}

} // namespace
} // namespace pineda::glsl_test
