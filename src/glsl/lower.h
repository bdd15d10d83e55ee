// Lowering of one linked stage's glslang AST to Pineda's IR (shader/ir.h): functions inlined,
// control flow turned into lane masks and structured regions and loops, aggregates scalarized,
// constant-bound loops unrolled, constants folded as they appear.
#pragma once

#include <functional>
#include <set>
#include <string>

#include "shader/engine.h"
#include "shader/ir.h"

namespace glslang {
class TIntermediate;
class TType;
} // namespace glslang

namespace pineda::glsl {

// What the link decided about the stage's variables. Components are flattened: vectors in
// order, matrices column by column, arrays element by element, structs member by member.
struct LowerEnv {
  // Base word of a uniform (user or built-in) in the uniform buffer; allocates it on first use.
  std::function<int(const std::string& name, const glslang::TType& type)> uniform_word;
  // The engine input component of flat component `comp` of an input variable (attribute,
  // varying or built-in input), or -1 when nothing provides it (it reads as 0).
  std::function<int(const std::string& name, int comp)> input;
  // The engine output component of an output variable's flat component, or -1 when nothing
  // reads it (it is not computed).
  std::function<int(const std::string& name, int comp)> output;
};

struct LowerResult {
  std::set<std::string> written; // outputs the stage statically assigns
  std::string error;             // a link error the lowering found (recursion, limits)
};

// Flattened component count of a GLSL type.
int component_count(const glslang::TType& t);

bool lower_stage(const glslang::TIntermediate& stage_ast, shader::Stage stage, const LowerEnv& env,
                 shader::Function& out, LowerResult& result);

} // namespace pineda::glsl
