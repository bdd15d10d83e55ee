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

// Before glslang sees the source: a #version directive other than 110 and 120 (the first token
// of the concatenated strings, GLSL 1.10 §3.3) appends its error and returns false. glslang
// would otherwise build its built-in symbol tables for that version first (tens of MB and up
// to a quarter of a second, for a shader Pineda refuses anyway).
bool check_version_directive(const std::vector<std::string>& sources, std::string& errors);

// After a successful parse of one shader: appends "ERROR: ..." lines to `errors`.
void check_compiled(const glslang::TIntermediate& ast, ShaderStage stage, const Limits& limits,
                    std::string& errors);

// Before glslang's link, over the parses of one stage's shaders: globals initialized in more
// than one of them must have the same constant initializer (GLSL 1.20 §4.3).
void check_stage_globals(const std::vector<const glslang::TIntermediate*>& shaders,
                         std::string& errors);

} // namespace pineda::glsl
