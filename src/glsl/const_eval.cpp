// Constant expressions glslang 12 cannot fold (const_eval.h).
#include "glsl/const_eval.h"

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "glsl/lower.h"
#include "shader/ir_passes.h"

namespace pineda::glsl {

namespace {

bool ident_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool ident_char(char c) {
  return ident_start(c) || (c >= '0' && c <= '9');
}
bool digit(char c) {
  return c >= '0' && c <= '9';
}

// Every literal of `e` made to depend on a uniform that is zero, so that glslang folds
// nothing and the whole expression reaches Pineda's IR.
std::string hide_literals(const std::string& e) {
  std::string out;
  size_t i = 0;
  while (i < e.size()) {
    const char c = e[i];
    if (ident_start(c)) {
      size_t j = i;
      while (j < e.size() && ident_char(e[j]))
        ++j;
      const std::string w = e.substr(i, j - i);
      if (w == "true")
        out += "(pineda_zero == 0.0)";
      else if (w == "false")
        out += "(pineda_zero != 0.0)";
      else
        out += w;
      i = j;
    } else if (digit(c) || (c == '.' && i + 1 < e.size() && digit(e[i + 1]))) {
      size_t j = i;
      bool is_float = false;
      if (c == '0' && i + 1 < e.size() && (e[i + 1] == 'x' || e[i + 1] == 'X')) {
        j += 2;
        while (j < e.size() && std::isxdigit(static_cast<unsigned char>(e[j])))
          ++j;
      } else {
        while (j < e.size() &&
               (digit(e[j]) || e[j] == '.' || e[j] == 'e' || e[j] == 'E' ||
                ((e[j] == '+' || e[j] == '-') && (e[j - 1] == 'e' || e[j - 1] == 'E')))) {
          is_float = is_float || e[j] == '.' || e[j] == 'e' || e[j] == 'E';
          ++j;
        }
      }
      const std::string lit = e.substr(i, j - i);
      out += is_float ? "(" + lit + " + pineda_zero)" : "(" + lit + " + int(pineda_zero))";
      i = j;
    } else {
      out += c;
      ++i;
    }
  }
  return out;
}

std::string float_literal(float v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(v));
  std::string s = buf;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

// "const TYPE NAME = EXPR;" on one line: the part up to and with "=" (`head`), TYPE and EXPR.
bool const_decl(const std::string& line, std::string& head, std::string& type, std::string& expr) {
  size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos || line.compare(i, 5, "const") != 0) return false;
  i += 5;
  const auto word = [&](std::string& out) {
    const size_t b = line.find_first_not_of(" \t", i);
    if (b == std::string::npos || b == i || !ident_start(line[b])) return false;
    size_t e = b;
    while (e < line.size() && ident_char(line[e]))
      ++e;
    out = line.substr(b, e - b);
    i = e;
    return true;
  };
  std::string name;
  if (!word(type) || !word(name)) return false;
  const size_t eq = line.find_first_not_of(" \t", i);
  if (eq == std::string::npos || line[eq] != '=') return false;
  const size_t semi = line.find_last_of(';');
  if (semi == std::string::npos || semi < eq ||
      line.find_first_not_of(" \t\r", semi + 1) != std::string::npos)
    return false;
  head = line.substr(0, eq + 1) + " ";
  expr = line.substr(eq + 1, semi - eq - 1);
  return true;
}

} // namespace

bool evaluate_constant(const std::string& type, const std::string& expr, int version,
                       std::string& literal, const std::string& prelude) {
  // The sequence operator is not part of constant expressions (GLSL 1.20 §4.3.3): a comma
  // must be an argument separator.
  std::vector<bool> call;
  for (size_t i = 0; i < expr.size(); ++i) {
    if (expr[i] == '(') {
      size_t j = i;
      while (j > 0 && expr[j - 1] == ' ')
        --j;
      call.push_back(j > 0 && (ident_char(expr[j - 1]) || expr[j - 1] == ']'));
    } else if (expr[i] == ')') {
      if (!call.empty()) call.pop_back();
    } else if (expr[i] == ',' && (call.empty() || !call.back())) {
      return false;
    }
  }
  const std::string src = "#version " + std::to_string(version) + "\nuniform float pineda_zero;\n" +
                          prelude + type + " pineda_value;\n" + "void main() { pineda_value = (" +
                          hide_literals(expr) + "); }\n";
  glslang::TShader sh(EShLangFragment);
  const char* s = src.c_str();
  sh.setStrings(&s, 1);
  if (!sh.parse(GetDefaultResources(), version, ENoProfile, false, false, EShMsgDefault))
    return false;
  glslang::TProgram prog;
  prog.addShader(&sh);
  if (!prog.link(EShMsgDefault)) return false;
  const glslang::TIntermediate* ast = prog.getIntermediate(EShLangFragment);
  if (!ast) return false;
  bool foreign_uniform = false;
  LowerEnv env;
  env.uniform_word = [&](const std::string& n, const glslang::TType&) {
    foreign_uniform = foreign_uniform || n != "pineda_zero";
    return 0;
  };
  env.input = [](const std::string&, int) { return -1; };
  env.output = [](const std::string& n, int c) { return n == "pineda_value" ? c : -1; };
  shader::Function f;
  LowerResult res;
  if (!lower_stage(*ast, shader::Stage::Fragment, env, f, res) || foreign_uniform) return false;
  // pineda_zero is zero after all.
  for (shader::Inst& in : f.insts)
    if (in.op == shader::Op::Uniform) {
      in.op = shader::Op::Const;
      in.imm[0] = in.type == shader::Type::Float ? 0 : 0;
    }
  f.rebuild_leaf_index();
  shader::optimize(f);
  std::vector<std::string> comps;
  std::vector<std::pair<int, shader::ValueId>> stores;
  for (const shader::Node& n : f.body) {
    if (n.kind != shader::NodeKind::Inst) return false;
    const shader::Inst& in = f.insts[n.index];
    if (in.op != shader::Op::StoreOutput || !f.is_const(in.arg[0])) return false;
    stores.emplace_back(in.imm[0], in.arg[0]);
  }
  if (stores.empty()) return false;
  std::sort(stores.begin(), stores.end());
  for (const auto& [k, v] : stores) {
    (void)k;
    switch (f.type(v)) {
    case shader::Type::Float: {
      const float x = f.const_float(v);
      if (!std::isfinite(x)) return false;
      comps.push_back(float_literal(x));
      break;
    }
    case shader::Type::Int:
      comps.push_back(std::to_string(static_cast<int32_t>(f.const_bits(v))));
      break;
    case shader::Type::Bool:
      comps.push_back(f.const_bits(v) ? "true" : "false");
      break;
    }
  }
  if (comps.size() == 1 && (type == "int" || type == "float" || type == "bool")) {
    literal = comps[0];
    return true;
  }
  literal = type + "(";
  for (size_t i = 0; i < comps.size(); ++i)
    literal += (i ? ", " : "") + comps[i];
  literal += ")";
  return true;
}

bool fold_unfolded_constants(std::vector<std::string>& sources, const std::string& log) {
  // The lines glslang refused: "ERROR: <string>:<line>: ..." with one of its folding failures.
  struct Spot {
    int string, line;
    bool array_size;
  };
  std::vector<Spot> spots;
  std::istringstream in(log);
  for (std::string l; std::getline(in, l);) {
    int sidx = 0, line = 0;
    if (std::sscanf(l.c_str(), "ERROR: %d:%d:", &sidx, &line) != 2) continue;
    const bool size = l.find("array size must be") != std::string::npos;
    const bool init = l.find("'non-constant initializer'") != std::string::npos;
    if ((size || init) && sidx >= 0 && sidx < static_cast<int>(sources.size()) && line > 0)
      spots.push_back({sidx, line, size});
  }
  if (spots.empty()) return false;
  bool changed = false;
  // The constants declared before `begin`, which the expressions may use.
  const auto prelude_before = [&](const std::string& src, size_t begin) {
    std::string prelude, h, t, e;
    std::istringstream before(src.substr(0, begin));
    for (std::string line; std::getline(before, line);)
      if (const_decl(line, h, t, e)) prelude += line + "\n";
    return prelude;
  };
  std::string prelude;
  const auto fold_brackets = [&](const std::string& text, int version, std::string& replaced) {
    // Every bracketed expression that is not a plain number: an array size (or an index,
    // which the value replaces just as well).
    bool any = false;
    size_t i = 0;
    while (i < text.size()) {
      if (text[i] != '[') {
        replaced += text[i++];
        continue;
      }
      int depth = 0;
      size_t j = i;
      for (; j < text.size(); ++j) {
        depth += text[j] == '[' ? 1 : text[j] == ']' ? -1 : 0;
        if (depth == 0) break;
      }
      if (j >= text.size()) {
        replaced += text.substr(i);
        break;
      }
      const std::string inner = text.substr(i + 1, j - i - 1);
      std::string lit;
      const bool plain = inner.find_first_not_of("0123456789 ") == std::string::npos;
      if (!plain && inner.find_first_of("(=<>!?") != std::string::npos &&
          evaluate_constant("int", inner, version, lit, prelude)) {
        replaced += "[" + lit + "]";
        any = true;
      } else {
        replaced += text.substr(i, j - i + 1);
      }
      i = j + 1;
    }
    return any;
  };
  for (const Spot& sp : spots) {
    std::string& src = sources[static_cast<size_t>(sp.string)];
    int version = 110;
    if (const size_t v = src.find("#version"); v != std::string::npos)
      version = std::atoi(src.c_str() + v + 8) == 120 ? 120 : 110;
    size_t begin = 0;
    for (int l = 1; l < sp.line && begin != std::string::npos; ++l) {
      begin = src.find('\n', begin);
      if (begin != std::string::npos) ++begin;
    }
    if (begin == std::string::npos) continue;
    prelude = prelude_before(src, begin);
    if (sp.array_size) {
      // glslang stops at its first error: the lines after it likely have the same kind of
      // size, so they are folded too, in one go.
      std::string rest = src.substr(begin), out;
      std::istringstream lines(rest);
      bool any = false;
      for (std::string line; std::getline(lines, line);) {
        std::string r;
        any = fold_brackets(line, version, r) || any;
        out += r + "\n";
      }
      if (!rest.empty() && rest.back() != '\n') out.pop_back();
      if (any) {
        src.replace(begin, std::string::npos, out);
        changed = true;
      }
      continue;
    }
    size_t end = src.find('\n', begin);
    if (end == std::string::npos) end = src.size();
    const std::string text = src.substr(begin, end - begin);
    std::string head, type, expr, lit;
    if (!const_decl(text, head, type, expr)) continue;
    if (!evaluate_constant(type, expr, version, lit, prelude)) continue;
    src.replace(begin, end - begin, head + lit + ";");
    changed = true;
  }
  return changed;
}

} // namespace pineda::glsl
