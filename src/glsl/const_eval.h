// Constant expressions glslang 12 cannot fold: it refuses valid GLSL 1.20 whose array sizes or
// const initializers use matrix built-ins (transpose, matrixCompMult) or compare aggregates in
// certain forms ((v == w) == true folds wrongly). Pineda evaluates such an expression with its
// own IR folder (the engine's arithmetic) and puts the value in the source instead.
#pragma once

#include <string>
#include <vector>

namespace pineda::glsl {

// The value of `expr` of type `type` ("int", "mat2", ...), as a GLSL literal or constructor of
// literals; false when it is not a constant Pineda can compute on its own. `prelude` holds
// declarations of constants the expression may use.
bool evaluate_constant(const std::string& type, const std::string& expr, int version,
                       std::string& literal, const std::string& prelude = "");

// After a failed parse with log `log`: replaces, in the lines glslang refused for an array size
// or a const initializer it could not fold, those expressions by their values. True when
// something was replaced (parse again).
bool fold_unfolded_constants(std::vector<std::string>& sources, const std::string& log);

} // namespace pineda::glsl
