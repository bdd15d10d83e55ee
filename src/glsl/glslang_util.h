// The front end's glslang plumbing shared by compiler.cpp and program.cpp.
#pragma once

#include <glslang/Include/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "glsl/glsl.h"

namespace pineda::glsl {

// glslang's process state is initialized once; its calls are serialized (compiling is not a
// hot path, and its pool allocators are per thread).
void ensure_glslang();
std::mutex& glslang_mutex();
TBuiltInResource resources_for(const Limits& l);

struct Shader::Impl {
  ShaderStage stage = ShaderStage::Vertex;
  Limits limits;
  TBuiltInResource resources{};
  std::vector<std::string> sources; // as glslang sees them (compiler.cpp prepares them)
  // The parse of a successful compile, handed to the first link that uses the shader; later
  // links parse the sources again (glslang cannot link one TShader into two programs).
  std::unique_ptr<glslang::TShader> parsed;
  std::unique_ptr<glslang::TShader> take_or_parse();
};

// Parses the shader's sources; null (with the log) when glslang refuses them.
std::unique_ptr<glslang::TShader> parse_shader(const Shader::Impl& impl, std::string& log);

} // namespace pineda::glsl
