// The text framing of a GLSL program that tools/piglit_glsl_pairs.py writes and the GLSL
// fuzzer (glsl_fuzzer.cpp) and the compile-time tool (bench/glsl_compile_time.cpp) read:
//
//   # comment lines before the first section
//   [vertex shader]      each section one shader object of that stage (none: fixed function)
//   ...
//   [fragment shader]
//   ...
//   [uniforms]           optional (the fuzzer): bytes that pick uniform values and draw state
//
// Plain C++ only (no GL headers), so that programs built against Mesa's headers can use it.
#pragma once

#include <cstddef>
#include <string_view>
#include <utility>
#include <vector>

namespace pineda::glsl_framing {

enum class Stage { Vertex, Fragment };

struct Program {
  std::vector<std::pair<Stage, std::string_view>> shaders; // views into the parsed text
  std::string_view uniforms;
};

// A line that is "[name]" (blanks around allowed), and the name.
inline bool section_line(std::string_view line, std::string_view& name) {
  while (!line.empty() &&
         (line.back() == ' ' || line.back() == '\r' || line.back() == '\t' || line.back() == '\n'))
    line.remove_suffix(1);
  while (!line.empty() && (line.front() == ' ' || line.front() == '\t'))
    line.remove_prefix(1);
  if (line.size() < 2 || line.front() != '[' || line.back() != ']') return false;
  name = line.substr(1, line.size() - 2);
  return true;
}

// At most max_shaders shader sections are kept; unknown sections are skipped.
inline Program parse(std::string_view text, size_t max_shaders = 8) {
  Program p;
  enum class Part { None, Vertex, Fragment, Uniforms, Other } part = Part::None;
  size_t body = 0;
  const auto close = [&](size_t end) {
    const std::string_view b = text.substr(body, end - body);
    if ((part == Part::Vertex || part == Part::Fragment) && p.shaders.size() < max_shaders)
      p.shaders.emplace_back(part == Part::Vertex ? Stage::Vertex : Stage::Fragment, b);
    if (part == Part::Uniforms) p.uniforms = b;
  };
  size_t pos = 0;
  while (pos < text.size()) {
    const size_t nl = text.find('\n', pos);
    const size_t next = nl == std::string_view::npos ? text.size() : nl + 1;
    std::string_view name;
    if (section_line(text.substr(pos, next - pos), name)) {
      close(pos);
      part = name == "vertex shader"     ? Part::Vertex
             : name == "fragment shader" ? Part::Fragment
             : name == "uniforms"        ? Part::Uniforms
                                         : Part::Other;
      body = next;
    }
    pos = next;
  }
  close(text.size());
  return p;
}

} // namespace pineda::glsl_framing
