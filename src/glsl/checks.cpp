// Pineda's checks where glslang 12 accepts invalid GLSL 1.10/1.20 (checks.h).
#include "glsl/checks.h"

#include <glslang/MachineIndependent/localintermediate.h>

#include <cctype>
#include <map>

namespace pineda::glsl {

using namespace glslang;

namespace {

const TIntermSymbol* root_symbol(TIntermTyped* t) {
  while (t) {
    if (auto* s = t->getAsSymbolNode()) return s;
    auto* b = t->getAsBinaryNode();
    if (!b) return nullptr;
    t = b->getLeft();
  }
  return nullptr;
}

// Records the names of the variables the shader's code assigns (statically: dead code too).
class Assigned : public TIntermTraverser {
public:
  std::map<std::string, TSourceLoc> names;

  bool visitBinary(TVisit, TIntermBinary* n) override {
    if (n->modifiesState()) note(n->getLeft(), n->getLoc());
    return true;
  }
  bool visitUnary(TVisit, TIntermUnary* n) override {
    if (n->modifiesState()) note(n->getOperand(), n->getLoc());
    return true;
  }

private:
  void note(TIntermTyped* t, const TSourceLoc& loc) {
    if (const TIntermSymbol* s = root_symbol(t)) names.emplace(s->getName().c_str(), loc);
  }
};

bool contains_sampler(const TType& t) {
  if (t.getBasicType() == EbtSampler) return true;
  if (t.isStruct())
    for (const TTypeLoc& m : *t.getStruct())
      if (contains_sampler(*m.type)) return true;
  return false;
}

// The largest gl_TexCoord[] the shader declares or implies by its constant indices.
class TexCoordSize : public TIntermTraverser {
public:
  int size = 0;
  TSourceLoc loc{};
  void visitSymbol(TIntermSymbol* s) override {
    if (s->getName() != "gl_TexCoord" || !s->getType().isArray()) return;
    int n = s->getType().getOuterArraySize();
    if (n <= 0 && s->getType().getArraySizes()) n = s->getType().getArraySizes()->getImplicitSize();
    if (n > size) size = n, loc = s->getLoc();
  }
};

std::string where(const TSourceLoc& loc) {
  return std::to_string(loc.string) + ":" + std::to_string(loc.line);
}

std::string version_error(int string, int line, const std::string& version) {
  return "ERROR: " + std::to_string(string) + ":" + std::to_string(line) +
         ": '#version' : version " + version +
         " is not supported (OpenGL 2.1: GLSL 1.10 and 1.20)\n";
}

} // namespace

bool check_version_directive(const std::vector<std::string>& sources, std::string& errors) {
  // The strings read as one text (a comment may span two), with the position of each
  // character as glslang reports it: string index and line within the string.
  size_t si = 0, i = 0;
  int line = 1;
  const auto at_end = [&] {
    while (si < sources.size() && i >= sources[si].size())
      ++si, i = 0, line = 1;
    return si >= sources.size();
  };
  const auto peek = [&](size_t ahead = 0) -> char {
    size_t s = si, k = i + ahead;
    while (s < sources.size() && k >= sources[s].size())
      k -= sources[s].size(), ++s;
    return s < sources.size() ? sources[s][k] : '\0';
  };
  const auto advance = [&] {
    if (sources[si][i] == '\n') ++line;
    ++i;
  };
  // Whitespace and comments; `newlines` false stops at the end of the line (a directive's
  // tokens are on one line).
  const auto skip = [&](bool newlines) {
    while (!at_end()) {
      const char c = peek();
      if (c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || (newlines && c == '\n')) {
        advance();
      } else if (c == '/' && peek(1) == '*') {
        advance(), advance();
        while (!at_end() && !(peek() == '*' && peek(1) == '/'))
          advance();
        if (!at_end()) advance(), advance();
      } else if (c == '/' && peek(1) == '/' && newlines) {
        while (!at_end() && peek() != '\n')
          advance();
      } else {
        return;
      }
    }
  };
  const auto word = [&] {
    std::string w;
    while (!at_end() && (std::isalnum(static_cast<unsigned char>(peek())) || peek() == '_'))
      w += peek(), advance();
    return w;
  };
  skip(true);
  if (at_end() || peek() != '#') return true; // no directive: GLSL 1.10
  const int string = static_cast<int>(si), at = line;
  advance();
  skip(false);
  if (word() != "version") return true;
  skip(false);
  const std::string number = word();
  if (number.empty() || number.find_first_not_of("0123456789") != std::string::npos)
    return true; // malformed: glslang says why
  skip(false);
  const std::string profile = word();
  if ((number == "110" || number == "120") && profile != "es") return true;
  errors += version_error(string, at, profile.empty() ? number : number + " " + profile);
  return false;
}

void check_compiled(const TIntermediate& ast, ShaderStage stage, const Limits& limits,
                    std::string& errors) {
  // OpenGL 2.1 has GLSL 1.10 and 1.20 (GL 2.1 §2.15); glslang knows every later version.
  const int v = ast.getVersion();
  if ((v != 110 && v != 120) || ast.getProfile() == EEsProfile) {
    errors +=
        version_error(0, 1, std::to_string(v) + (ast.getProfile() == EEsProfile ? " es" : ""));
    return;
  }
  TIntermNode* root = ast.getTreeRoot();
  if (!root) return;
  Assigned a;
  root->traverse(&a);
  // GLSL 1.10 §7.6: gl_TexCoord has at most gl_MaxTextureCoords elements (glslang sizes it
  // by the largest index used, without that limit).
  TexCoordSize tc;
  root->traverse(&tc);
  if (tc.size > limits.max_texture_coords)
    errors += "ERROR: " + where(tc.loc) + ": 'gl_TexCoord' : index beyond gl_MaxTextureCoords (" +
              std::to_string(limits.max_texture_coords) + ")\n";
  // GLSL 1.10 §4.1.7: samplers are only uniforms or in-parameters: no out or inout
  // parameter, and no function result, may hold one.
  if (auto* seq = root->getAsAggregate()) {
    for (TIntermNode* c : seq->getSequence()) {
      auto* fn = c->getAsAggregate();
      if (!fn || fn->getOp() != EOpFunction) continue;
      if (contains_sampler(fn->getType()))
        errors += "ERROR: " + where(fn->getLoc()) + ": '" + std::string(fn->getName().c_str()) +
                  "' : a function cannot return a sampler\n";
      auto* params = fn->getSequence().empty() ? nullptr : fn->getSequence()[0]->getAsAggregate();
      if (!params) continue;
      for (TIntermNode* p : params->getSequence()) {
        auto* s = p->getAsSymbolNode();
        if (!s) continue;
        const TStorageQualifier q = s->getQualifier().storage;
        if ((q == EvqOut || q == EvqInOut) && contains_sampler(s->getType()))
          errors += "ERROR: " + where(s->getLoc()) + ": '" + std::string(s->getName().c_str()) +
                    "' : samplers cannot be out or inout parameters\n";
      }
    }
  }
  if (stage == ShaderStage::Fragment) {
    // GLSL 1.10 §7.2: a shader may assign gl_FragColor or gl_FragData, not both; a compile
    // error, before any dead code is removed (glslang only refuses it when linking).
    auto c = a.names.find("gl_FragColor"), d = a.names.find("gl_FragData");
    if (c != a.names.end() && d != a.names.end())
      errors += "ERROR: " + where(d->second) +
                ": 'gl_FragData' : cannot be written in a shader that writes gl_FragColor\n";
  }
}

void check_stage_globals(const std::vector<const TIntermediate*>& shaders, std::string& errors) {
  if (shaders.size() < 2) return;
  // name -> (the initializer's constants, or empty for a non-constant one; shader index)
  struct Init {
    std::string value;
    bool constant;
    size_t shader;
  };
  std::map<std::string, Init> seen;
  for (size_t i = 0; i < shaders.size(); ++i) {
    auto* root = shaders[i]->getTreeRoot() ? shaders[i]->getTreeRoot()->getAsAggregate() : nullptr;
    if (!root) continue;
    const auto visit = [&](auto&& self, TIntermNode* n) -> void {
      auto* agg = n->getAsAggregate();
      if (agg) {
        if (agg->getOp() == EOpSequence)
          for (TIntermNode* c : agg->getSequence())
            self(self, c);
        return;
      }
      auto* b = n->getAsBinaryNode();
      if (!b || b->getOp() != EOpAssign) return;
      auto* s = b->getLeft()->getAsSymbolNode();
      if (!s || s->getQualifier().storage != EvqGlobal) return;
      Init init{"", false, i};
      if (auto* c = b->getRight()->getAsConstantUnion()) {
        init.constant = true;
        const TConstUnionArray& arr = c->getConstArray();
        for (int k = 0; k < arr.size(); ++k)
          init.value +=
              std::to_string(arr[k].getDConst()) + "," + std::to_string(arr[k].getIConst()) + ";";
      }
      const std::string name = s->getName().c_str();
      auto it = seen.find(name);
      if (it == seen.end()) {
        seen.emplace(name, init);
        return;
      }
      if (!it->second.constant || !init.constant)
        errors += "ERROR: Linking: global variable '" + name +
                  "' has non-constant initializers in more than one shader\n";
      else if (it->second.value != init.value)
        errors += "ERROR: Linking: global variable '" + name +
                  "' has different initializers in different shaders\n";
    };
    for (TIntermNode* c : root->getSequence())
      visit(visit, c);
  }
}

} // namespace pineda::glsl
