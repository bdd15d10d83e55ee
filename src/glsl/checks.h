// Pineda's own checks where glslang 12 accepts what GLSL 1.10/1.20 forbids (each has a test in
// tests/unit/glsl/gaps_test.cpp).
#pragma once

#include <string>
#include <vector>

#include "glsl/glsl.h"

namespace glslang {
class TIntermediate;
} // namespace glslang

namespace pineda::glsl {

// After a successful parse of one shader: appends "ERROR: ..." lines to `errors`.
void check_compiled(const glslang::TIntermediate& ast, ShaderStage stage, const Limits& limits,
                    std::string& errors);

// Before glslang's link, over the parses of one stage's shaders: globals initialized in more
// than one of them must have the same constant initializer (GLSL 1.20 §4.3).
void check_stage_globals(const std::vector<const glslang::TIntermediate*>& shaders,
                         std::string& errors);

} // namespace pineda::glsl
