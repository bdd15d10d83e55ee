// Pineda's checks where glslang 12 accepts invalid GLSL 1.10/1.20 (checks.h).
#include "glsl/checks.h"

#include <glslang/MachineIndependent/localintermediate.h>

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

std::string where(const TSourceLoc& loc) {
  return std::to_string(loc.string) + ":" + std::to_string(loc.line);
}

} // namespace

void check_compiled(const TIntermediate& ast, ShaderStage stage, std::string& errors) {
  // OpenGL 2.1 has GLSL 1.10 and 1.20 (GL 2.1 §2.15); glslang knows every later version.
  const int v = ast.getVersion();
  if ((v != 110 && v != 120) || ast.getProfile() == EEsProfile) {
    errors += "ERROR: 0:1: '#version' : version " + std::to_string(v) +
              (ast.getProfile() == EEsProfile ? " es" : "") +
              " is not supported (OpenGL 2.1: GLSL 1.10 and 1.20)\n";
    return;
  }
  TIntermNode* root = ast.getTreeRoot();
  if (!root) return;
  Assigned a;
  root->traverse(&a);
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
          init.value += std::to_string(arr[k].getDConst()) + "," +
                        std::to_string(arr[k].getIConst()) + ";";
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
