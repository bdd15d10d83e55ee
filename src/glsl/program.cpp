// Program linking (glsl.h Program): glslang's link, Pineda's interface checks, lowering of each
// stage, varying packing, attribute locations, the uniform buffer's layout and reflection.
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>

#include "glsl/checks.h"
#include "glsl/glsl.h"
#include "glsl/glslang_util.h"
#include "glsl/lower.h"
#include "shader/io.h"
#include "shader/ir_passes.h"

namespace pineda::glsl {

using namespace glslang;

struct ProgramImpl {
  std::vector<ActiveUniform> uniforms;
  std::vector<UniformLocation> locations;
  std::vector<ActiveAttrib> attribs;
  std::vector<BuiltinUniform> builtins;
  int uniform_words = 0;
  std::vector<uint32_t> initial;
  std::unique_ptr<shader::Executable> vs, fs;
  bool frag_color = false, frag_depth = false;
  std::string ir;
  std::map<std::pair<std::string, int>, int> packed; // varying component -> packed index
};

namespace {

constexpr int kProvisional = 1 << 24; // inputs before the link assigns them
constexpr int kProvisionalStride = 4096;

// ---- types ----

GLenum gl_type(const TType& t) {
  if (t.getBasicType() == EbtSampler) {
    const TSampler& s = t.getSampler();
    switch (s.dim) {
    case Esd1D:
      return s.shadow ? GL_SAMPLER_1D_SHADOW : GL_SAMPLER_1D;
    case Esd2D:
      return s.shadow ? GL_SAMPLER_2D_SHADOW : GL_SAMPLER_2D;
    case Esd3D:
      return GL_SAMPLER_3D;
    case EsdCube:
      return GL_SAMPLER_CUBE;
    default:
      return GL_SAMPLER_2D;
    }
  }
  if (t.isMatrix()) {
    static const GLenum m[3][3] = {{GL_FLOAT_MAT2, GL_FLOAT_MAT2x3, GL_FLOAT_MAT2x4},
                                   {GL_FLOAT_MAT3x2, GL_FLOAT_MAT3, GL_FLOAT_MAT3x4},
                                   {GL_FLOAT_MAT4x2, GL_FLOAT_MAT4x3, GL_FLOAT_MAT4}};
    return m[t.getMatrixCols() - 2][t.getMatrixRows() - 2];
  }
  const int n = t.getVectorSize();
  switch (t.getBasicType()) {
  case EbtBool: {
    static const GLenum b[] = {GL_BOOL, GL_BOOL_VEC2, GL_BOOL_VEC3, GL_BOOL_VEC4};
    return b[n - 1];
  }
  case EbtInt:
  case EbtUint: {
    static const GLenum i[] = {GL_INT, GL_INT_VEC2, GL_INT_VEC3, GL_INT_VEC4};
    return i[n - 1];
  }
  default: {
    static const GLenum f[] = {GL_FLOAT, GL_FLOAT_VEC2, GL_FLOAT_VEC3, GL_FLOAT_VEC4};
    return f[n - 1];
  }
  }
}

int array_len(const TType& t) {
  if (!t.isArray()) return 1;
  int n = t.getOuterArraySize();
  if (n <= 0 && t.getArraySizes()) n = t.getArraySizes()->getImplicitSize();
  return n > 0 ? n : 1;
}

// Structural equality of two declarations' types (qualifiers aside).
bool same_type(const TType& a, const TType& b) {
  if (a.getBasicType() != b.getBasicType() || a.isArray() != b.isArray()) return false;
  if (a.isArray() && array_len(a) != array_len(b)) return false;
  if (a.getVectorSize() != b.getVectorSize() || a.getMatrixCols() != b.getMatrixCols() ||
      a.getMatrixRows() != b.getMatrixRows())
    return false;
  if (a.getBasicType() == EbtSampler && !(a.getSampler() == b.getSampler())) return false;
  if (a.isStruct()) {
    const TTypeList& x = *a.getStruct();
    const TTypeList& y = *b.getStruct();
    if (x.size() != y.size()) return false;
    for (size_t i = 0; i < x.size(); ++i)
      if (x[i].type->getFieldName() != y[i].type->getFieldName() ||
          !same_type(*x[i].type, *y[i].type))
        return false;
  }
  return true;
}

// ---- the uniform buffer ----

struct Leaf {
  std::string name; // without "[0]"
  GLenum type;
  bool array;
  int count;
  int word;
  int elem_words;
  bool builtin;
};

struct Layout {
  std::map<std::string, int> base;
  int words = 0;
  std::vector<Leaf> leaves;

  void enumerate(const TType& t, const std::string& name, int word, bool builtin) {
    if (t.isStruct() && !t.isArray()) {
      int off = 0;
      for (const TTypeLoc& m : *t.getStruct()) {
        enumerate(*m.type, name + "." + m.type->getFieldName().c_str(), word + off, builtin);
        off += component_count(*m.type);
      }
      return;
    }
    if (t.isArray()) {
      const TType e(t, 0);
      const int n = array_len(t), ew = component_count(e);
      if (e.isStruct()) {
        for (int i = 0; i < n; ++i)
          enumerate(e, name + "[" + std::to_string(i) + "]", word + i * ew, builtin);
        return;
      }
      leaves.push_back({name, gl_type(e), true, n, word, ew, builtin});
      return;
    }
    leaves.push_back({name, gl_type(t), false, 1, word, component_count(t), builtin});
  }

  int word_of(const std::string& name, const TType& t) {
    auto it = base.find(name);
    if (it != base.end()) return it->second;
    const int w = words;
    base.emplace(name, w);
    words += component_count(t);
    enumerate(t, name, w, name.rfind("gl_", 0) == 0);
    return w;
  }
};

// ---- interface of the stages ----

struct Decl {
  std::string name;
  const TType* type;
  TStorageQualifier storage;
  const TIntermSymbol* sym;
};

std::vector<Decl> declarations(const TIntermediate* ast) {
  std::vector<Decl> out;
  if (!ast || !ast->getTreeRoot()) return out;
  auto* root = ast->getTreeRoot()->getAsAggregate();
  if (!root) return out;
  for (TIntermNode* c : root->getSequence()) {
    auto* a = c->getAsAggregate();
    if (!a || a->getOp() != EOpLinkerObjects) continue;
    for (TIntermNode* o : a->getSequence())
      if (auto* s = o->getAsSymbolNode())
        out.push_back({s->getName().c_str(), &s->getType(), s->getQualifier().storage, s});
  }
  return out;
}

int slot_of_multitexcoord(const std::string& name) {
  // gl_MultiTexCoord0..7
  if (name.rfind("gl_MultiTexCoord", 0) != 0 || name.size() != 17) return -1;
  const int i = name[16] - '0';
  return i >= 0 && i < shader::kMaxTextureCoords ? i : -1;
}

// Placed instructions of a function.
template <class Fn> void for_each_placed(const shader::Function& f, Fn&& fn) {
  const auto walk = [&](auto&& self, const shader::Block& b) -> void {
    for (const shader::Node& n : b) {
      if (n.kind == shader::NodeKind::Inst)
        fn(n.index);
      else if (n.kind == shader::NodeKind::Region)
        self(self, f.regions[n.index].body);
      else
        self(self, f.loops[n.index].body);
    }
  };
  walk(walk, f.body);
}

// Uniform words a stage reads.
void words_read(const shader::Function& f, std::vector<uint8_t>& read) {
  const std::vector<uint8_t> used = shader::used_values(f);
  const auto mark = [&](int w) {
    if (w >= 0 && static_cast<size_t>(w) < read.size()) read[static_cast<size_t>(w)] = 1;
  };
  for (size_t v = 0; v < f.insts.size(); ++v)
    if (used[v] && f.insts[v].op == shader::Op::Uniform) mark(f.insts[v].imm[0]);
  for_each_placed(f, [&](shader::ValueId v) {
    const shader::Inst& in = f.insts[v];
    if (in.op == shader::Op::UniformIndexed)
      for (int k = 0; k < in.imm[2]; ++k)
        mark(in.imm[0] + k * in.imm[1]);
    if (in.op == shader::Op::Tex) mark(in.imm[0]);
  });
}

int count_read(const std::vector<uint8_t>& r) {
  return static_cast<int>(std::count(r.begin(), r.end(), 1));
}

bool debug_ir() {
  const char* d = std::getenv("PINEDA_DEBUG");
  return d && std::strstr(d, "ir") != nullptr;
}

bool debug_ir_raw() {
  const char* d = std::getenv("PINEDA_DEBUG");
  return d && std::strstr(d, "ir-raw") != nullptr;
}

} // namespace

Program::~Program() = default;

const std::vector<ActiveUniform>& Program::uniforms() const {
  return impl_->uniforms;
}
const std::vector<UniformLocation>& Program::locations() const {
  return impl_->locations;
}
const std::vector<ActiveAttrib>& Program::attribs() const {
  return impl_->attribs;
}
int Program::uniform_words() const {
  return impl_->uniform_words;
}
const std::vector<uint32_t>& Program::initial_uniforms() const {
  return impl_->initial;
}
const std::vector<BuiltinUniform>& Program::builtin_uniforms() const {
  return impl_->builtins;
}
const shader::Executable* Program::vertex() const {
  return impl_->vs.get();
}
const shader::Executable* Program::fragment() const {
  return impl_->fs.get();
}
bool Program::writes_frag_color() const {
  return impl_->frag_color;
}
bool Program::writes_frag_depth() const {
  return impl_->frag_depth;
}
const std::string& Program::ir_text() const {
  return impl_->ir;
}

int Program::varying_component(const std::string& name, int comp) const {
  auto it = impl_->packed.find({name, comp});
  return it == impl_->packed.end() ? -1 : it->second;
}

size_t Program::max_uniform_name_length() const {
  size_t n = 0;
  for (const ActiveUniform& u : impl_->uniforms)
    n = std::max(n, u.name.size() + 1);
  return n;
}
size_t Program::max_attrib_name_length() const {
  size_t n = 0;
  for (const ActiveAttrib& a : impl_->attribs)
    n = std::max(n, a.name.size() + 1);
  return n;
}

int Program::uniform_location(std::string_view name) const {
  if (!linked_ || name.rfind("gl_", 0) == 0) return -1;
  // "name", "name[i]": GL 2.1 §2.15.3.
  std::string_view base = name;
  int index = 0;
  bool indexed = false;
  if (!name.empty() && name.back() == ']') {
    const size_t open = name.rfind('[');
    if (open == std::string_view::npos || open + 2 > name.size() - 1 + 1) return -1;
    const std::string_view digits = name.substr(open + 1, name.size() - open - 2);
    if (digits.empty() || digits.size() > 9) return -1;
    for (char c : digits)
      if (c < '0' || c > '9') return -1;
    index = std::atoi(std::string(digits).c_str());
    base = name.substr(0, open);
    indexed = true;
  }
  for (const ActiveUniform& u : impl_->uniforms) {
    if (u.location < 0) continue;
    const std::string_view un =
        u.array ? std::string_view(u.name).substr(0, u.name.size() - 3) : std::string_view(u.name);
    if (un != base) continue;
    if (indexed && !u.array) return -1;
    if (index >= u.size) return -1;
    return u.location + index;
  }
  return -1;
}

int Program::attrib_location(std::string_view name) const {
  if (!linked_ || name.rfind("gl_", 0) == 0) return -1;
  for (const ActiveAttrib& a : impl_->attribs)
    if (a.name == name) return a.location;
  return -1;
}

std::unique_ptr<Program> Program::link(const std::vector<std::shared_ptr<const Shader>>& shaders,
                                       const std::vector<AttribBinding>& bindings,
                                       const Limits& limits) {
  std::unique_ptr<Program> p(new Program());
  p->impl_ = std::make_unique<ProgramImpl>();
  ProgramImpl& impl = *p->impl_;
  std::string& log = p->log_;
  const auto fail = [&](const std::string& msg) {
    log += msg;
    if (!msg.empty() && msg.back() != '\n') log += '\n';
    return std::move(p);
  };

  std::vector<Shader::Impl*> stage_shaders[2];
  for (const auto& s : shaders) {
    if (!s) continue;
    if (!s->compiled())
      return fail("ERROR: Linking: a shader attached to the program did not compile");
    stage_shaders[s->stage() == ShaderStage::Vertex ? 0 : 1].push_back(s->impl());
  }
  if (stage_shaders[0].empty() && stage_shaders[1].empty()) {
    // No shaders: both stages stay fixed function (OpenGL 2.1 compatibility).
    p->linked_ = true;
    return p;
  }
  ensure_glslang();
  std::lock_guard<std::mutex> lock(glslang_mutex());

  // ---- glslang's parse and link ----
  std::vector<std::unique_ptr<TShader>> parsed[2];
  for (int st = 0; st < 2; ++st) {
    std::vector<const TIntermediate*> asts;
    for (Shader::Impl* s : stage_shaders[st]) {
      auto t = s->take_or_parse();
      if (!t) return fail("ERROR: Linking: a shader could not be parsed again");
      asts.push_back(t->getIntermediate());
      parsed[st].push_back(std::move(t));
    }
    std::string errors;
    check_stage_globals(asts, errors);
    if (!errors.empty()) return fail(errors);
  }
  // Each stage is linked by glslang on its own: the checks between the stages are Pineda's
  // (glslang's refuse valid programs, e.g. gl_TexCoord sized differently in the two stages).
  TProgram progs[2];
  const TIntermediate* asts[2] = {nullptr, nullptr};
  for (int st = 0; st < 2; ++st) {
    if (parsed[st].empty()) continue;
    for (auto& t : parsed[st])
      progs[st].addShader(t.get());
    if (!progs[st].link(EShMsgDefault)) {
      // A call to a function without a body is an error only if the call can run: the
      // lowering reports it then (glslang reports it even in dead code, which GLSL allows).
      const std::string info = progs[st].getInfoLog();
      bool only_missing_bodies =
          info.find("No function definition (body) found") != std::string::npos;
      for (size_t pos = 0;
           only_missing_bodies && (pos = info.find("ERROR:", pos)) != std::string::npos; ++pos) {
        const size_t eol = info.find('\n', pos);
        only_missing_bodies =
            info.substr(pos, eol - pos).find("No function definition (body) found") !=
            std::string::npos;
      }
      if (!only_missing_bodies ||
          !progs[st].getIntermediate(st == 0 ? EShLangVertex : EShLangFragment))
        return fail(info);
    }
    asts[st] = progs[st].getIntermediate(st == 0 ? EShLangVertex : EShLangFragment);
  }
  const TIntermediate* vs_ast = asts[0];
  const TIntermediate* fs_ast = asts[1];

  // ---- interface checks (GLSL 1.20 §4.3.5, §4.3.6) ----
  const std::vector<Decl> vs_decls = declarations(vs_ast), fs_decls = declarations(fs_ast);
  for (const Decl& f : fs_decls) {
    for (const Decl& v : vs_decls) {
      if (f.name != v.name) continue;
      if (f.storage == EvqUniform && v.storage == EvqUniform && !same_type(*f.type, *v.type))
        return fail("ERROR: Linking: uniform '" + f.name +
                    "' has different types in the vertex and fragment shaders");
      if (f.storage == EvqUniform && v.storage == EvqUniform && f.sym->getConstArray().size() > 0 &&
          v.sym->getConstArray().size() > 0 && !(f.sym->getConstArray() == v.sym->getConstArray()))
        return fail("ERROR: Linking: uniform '" + f.name +
                    "' has different initializers in the vertex and fragment shaders");
      // (gl_TexCoord may have different sizes in the two stages, GLSL 1.10 §7.6.)
      if (f.storage == EvqVaryingIn && v.storage == EvqVaryingOut && f.name.rfind("gl_", 0) != 0 &&
          !same_type(*f.type, *v.type))
        return fail("ERROR: Linking: varying '" + f.name +
                    "' has different types in the vertex and fragment shaders");
    }
  }

  Layout layout;
  std::string ir_log;

  // ---- fragment stage ----
  std::vector<std::string> fs_varyings;
  std::map<std::pair<std::string, int>, int> packed; // (varying, component) -> packed index
  std::vector<uint8_t> fs_reads(static_cast<size_t>(shader::kNumFragmentInputs) * 4, 0);
  std::set<std::string> fs_read_varyings;
  shader::Function fs_ir;
  LowerResult fs_res;
  if (fs_ast) {
    LowerEnv env;
    env.uniform_word = [&](const std::string& n, const TType& t) { return layout.word_of(n, t); };
    env.input = [&](const std::string& n, int c) -> int {
      using namespace shader;
      if (n == "gl_Color") return c < 4 ? kFragColor * 4 + c : -1;
      if (n == "gl_SecondaryColor") return c < 4 ? kFragSecondaryColor * 4 + c : -1;
      if (n == "gl_TexCoord")
        return c < 4 * limits.max_texture_coords && c < 4 * kMaxTextureCoords
                   ? kFragTexCoord0 * 4 + c
                   : -1;
      if (n == "gl_FogFragCoord") return c == 0 ? kFragFogFragCoord * 4 : -1;
      if (n == "gl_FragCoord") return c < 4 ? kFragCoord * 4 + c : -1;
      if (n == "gl_PointCoord") return c < 2 ? kFragPointCoord * 4 + c : -1;
      if (n == "gl_FrontFacing") return c == 0 ? kFragFrontFacing * 4 : -1;
      if (n.rfind("gl_", 0) == 0 || c >= kProvisionalStride) return -1;
      auto it = std::find(fs_varyings.begin(), fs_varyings.end(), n);
      const int vi = static_cast<int>(it - fs_varyings.begin());
      if (it == fs_varyings.end()) fs_varyings.push_back(n);
      return kProvisional + vi * kProvisionalStride + c;
    };
    env.output = [&](const std::string& n, int c) -> int {
      using namespace shader;
      if (n == "gl_FragColor") return c < 4 ? kOutFragData0 * 4 + c : -1;
      if (n == "gl_FragData")
        return c < 4 * limits.max_draw_buffers && c < 4 * kMaxDrawBuffers ? kOutFragData0 * 4 + c
                                                                          : -1;
      if (n == "gl_FragDepth") return c == 0 ? kOutFragDepth * 4 : -1;
      return -1;
    };
    if (!lower_stage(*fs_ast, shader::Stage::Fragment, env, fs_ir, fs_res))
      return fail("ERROR: Linking fragment shader: " + fs_res.error);
    if (debug_ir_raw())
      std::fprintf(stderr, "fragment shader IR before optimization:\n%s",
                   shader::print(fs_ir).c_str());
    shader::optimize(fs_ir);
    // GLSL 1.10 §7.2: a program may assign gl_FragColor or gl_FragData, not both. Each shader
    // is checked when compiled (checks.cpp); two fragment shaders may still split them.
    if (fs_res.written.count("gl_FragColor") > 0 && fs_res.written.count("gl_FragData") > 0)
      return fail("ERROR: Linking: the fragment shaders write both gl_FragColor and gl_FragData");
    impl.frag_color = fs_res.written.count("gl_FragColor") > 0;
    impl.frag_depth = fs_res.written.count("gl_FragDepth") > 0;
    // Pack the varying components the optimized shader reads, in order, four to a slot.
    const std::vector<uint8_t> used = shader::used_values(fs_ir);
    std::vector<std::pair<int, int>> prov;
    for (size_t v = 0; v < fs_ir.insts.size(); ++v) {
      const shader::Inst& in = fs_ir.insts[v];
      if (!used[v] || in.op != shader::Op::Input) continue;
      if (in.imm[0] >= kProvisional) {
        const int id = in.imm[0] - kProvisional;
        prov.emplace_back(id / kProvisionalStride, id % kProvisionalStride);
      } else if (in.imm[0] < static_cast<int>(fs_reads.size())) {
        fs_reads[static_cast<size_t>(in.imm[0])] = 1;
      }
    }
    std::sort(prov.begin(), prov.end());
    int next = 0;
    for (const auto& [vi, c] : prov) {
      packed[{fs_varyings[static_cast<size_t>(vi)], c}] = next++;
      fs_read_varyings.insert(fs_varyings[static_cast<size_t>(vi)]);
    }
    if (next > limits.max_varying_floats || next > 4 * shader::kMaxVaryingSlots)
      return fail("ERROR: Linking: the fragment shader reads " + std::to_string(next) +
                  " varying components; the limit is " + std::to_string(limits.max_varying_floats));
    fs_ir.remap_inputs([&](int32_t id) {
      if (id < kProvisional) return id;
      const int rel = id - kProvisional;
      const std::string& n = fs_varyings[static_cast<size_t>(rel / kProvisionalStride)];
      auto it = packed.find({n, rel % kProvisionalStride});
      // A component nothing reads any more (only dead code used it): any index will do.
      return shader::kFragVarying0 * 4 + (it == packed.end() ? 0 : it->second);
    });
  }

  // ---- vertex stage ----
  shader::Function vs_ir;
  LowerResult vs_res;
  std::vector<std::string> attr_names;
  std::vector<const TType*> attr_types;
  if (vs_ast) {
    for (const Decl& d : vs_decls)
      if (d.storage == EvqVaryingIn && d.name.rfind("gl_", 0) != 0) {
        attr_names.push_back(d.name);
        attr_types.push_back(d.type);
      }
    const bool has_fs = fs_ast != nullptr;
    const auto fs_reads_comp = [&](int comp) {
      return !has_fs || fs_reads[static_cast<size_t>(comp)] != 0;
    };
    LowerEnv env;
    env.uniform_word = [&](const std::string& n, const TType& t) { return layout.word_of(n, t); };
    env.input = [&](const std::string& n, int c) -> int {
      using namespace shader;
      if (n == "gl_Vertex") return c < 4 ? kInVertex * 4 + c : -1;
      if (n == "gl_Normal") return c < 3 ? kInNormal * 4 + c : -1;
      if (n == "gl_Color") return c < 4 ? kInColor * 4 + c : -1;
      if (n == "gl_SecondaryColor") return c < 4 ? kInSecondaryColor * 4 + c : -1;
      if (n == "gl_FogCoord") return c == 0 ? kInFogCoord * 4 : -1;
      if (const int t = slot_of_multitexcoord(n); t >= 0)
        return c < 4 ? (kInMultiTexCoord0 + t) * 4 + c : -1;
      if (n.rfind("gl_", 0) == 0 || c >= kProvisionalStride) return -1;
      auto it = std::find(attr_names.begin(), attr_names.end(), n);
      if (it == attr_names.end()) return -1;
      return kProvisional + static_cast<int>(it - attr_names.begin()) * kProvisionalStride + c;
    };
    env.output = [&](const std::string& n, int c) -> int {
      using namespace shader;
      if (n == "gl_Position") return c < 4 ? kOutPosition * 4 + c : -1;
      if (n == "gl_PointSize") return c == 0 ? kOutPointSize * 4 : -1;
      if (n == "gl_ClipVertex") return c < 4 ? kOutClipVertex * 4 + c : -1;
      if (n == "gl_FrontColor" || n == "gl_BackColor") {
        if (c >= 4 || !fs_reads_comp(kFragColor * 4 + c)) return -1;
        return (n == "gl_FrontColor" ? kOutFrontColor : kOutBackColor) * 4 + c;
      }
      if (n == "gl_FrontSecondaryColor" || n == "gl_BackSecondaryColor") {
        if (c >= 4 || !fs_reads_comp(kFragSecondaryColor * 4 + c)) return -1;
        return (n == "gl_FrontSecondaryColor" ? kOutFrontSecondaryColor : kOutBackSecondaryColor) *
                   4 +
               c;
      }
      if (n == "gl_TexCoord") {
        if (c >= 4 * kMaxTextureCoords || c >= 4 * limits.max_texture_coords ||
            !fs_reads_comp(kFragTexCoord0 * 4 + c))
          return -1;
        return kOutTexCoord0 * 4 + c;
      }
      if (n == "gl_FogFragCoord")
        return c == 0 && fs_reads_comp(kFragFogFragCoord * 4) ? kOutFogFragCoord * 4 : -1;
      auto it = packed.find({n, c});
      return it == packed.end() ? -1 : kOutVarying0 * 4 + it->second;
    };
    if (!lower_stage(*vs_ast, shader::Stage::Vertex, env, vs_ir, vs_res))
      return fail("ERROR: Linking vertex shader: " + vs_res.error);
    if (debug_ir_raw())
      std::fprintf(stderr, "vertex shader IR before optimization:\n%s",
                   shader::print(vs_ir).c_str());
    shader::optimize(vs_ir);
    // GLSL 1.10 §7.1: "The variable gl_Position is available only in the vertex language and
    // is intended for writing the homogeneous vertex position. All executions of a
    // well-formed vertex shader must write a value into this variable." (a link error, as Mesa
    // makes it below GLSL 1.40).
    if (!vs_res.written.count("gl_Position"))
      return fail("ERROR: Linking: the vertex shader does not write gl_Position");
    // GLSL 1.10 §4.3.6 (as Mesa): a varying the fragment shader reads must be written.
    for (const std::string& n : fs_read_varyings)
      if (!vs_res.written.count(n))
        return fail("ERROR: Linking: the fragment shader reads varying '" + n +
                    "', which the vertex shader does not write");

    // Attribute locations: glBindAttribLocation's, then the lowest free ones (not 0 when
    // gl_Vertex, which aliases generic attribute 0, is read).
    const std::vector<uint8_t> used = shader::used_values(vs_ir);
    std::vector<uint8_t> active(attr_names.size(), 0);
    bool reads_vertex = false;
    std::set<int> builtin_slots;
    for (size_t v = 0; v < vs_ir.insts.size(); ++v) {
      const shader::Inst& in = vs_ir.insts[v];
      if (!used[v] || in.op != shader::Op::Input) continue;
      if (in.imm[0] >= kProvisional)
        active[static_cast<size_t>((in.imm[0] - kProvisional) / kProvisionalStride)] = 1;
      else
        builtin_slots.insert(in.imm[0] / 4);
    }
    reads_vertex = builtin_slots.count(shader::kInVertex) > 0;
    std::vector<int> loc(attr_names.size(), -1);
    std::vector<uint8_t> taken(static_cast<size_t>(limits.max_vertex_attribs), 0);
    const auto columns = [&](size_t i) {
      return attr_types[i]->isMatrix() ? attr_types[i]->getMatrixCols() : 1;
    };
    for (size_t i = 0; i < attr_names.size(); ++i) {
      if (!active[i]) continue;
      for (const AttribBinding& b : bindings)
        if (b.name == attr_names[i]) loc[i] = b.location;
      if (loc[i] < 0) continue;
      if (loc[i] + columns(i) > limits.max_vertex_attribs)
        return fail("ERROR: Linking: attribute '" + attr_names[i] +
                    "' is bound beyond the last generic attribute");
      for (int c = 0; c < columns(i); ++c)
        taken[static_cast<size_t>(loc[i] + c)] = 1;
    }
    for (size_t i = 0; i < attr_names.size(); ++i) {
      if (!active[i] || loc[i] >= 0) continue;
      for (int l = reads_vertex ? 1 : 0; l + columns(i) <= limits.max_vertex_attribs; ++l) {
        bool free = true;
        for (int c = 0; c < columns(i); ++c)
          free = free && !taken[static_cast<size_t>(l + c)];
        if (!free) continue;
        loc[i] = l;
        for (int c = 0; c < columns(i); ++c)
          taken[static_cast<size_t>(l + c)] = 1;
        break;
      }
      if (loc[i] < 0) return fail("ERROR: Linking: too many vertex attributes");
    }
    vs_ir.remap_inputs([&](int32_t id) {
      if (id < kProvisional) return id;
      const int rel = id - kProvisional;
      const size_t ai = static_cast<size_t>(rel / kProvisionalStride);
      const int c = rel % kProvisionalStride;
      const int rows = attr_types[ai]->isMatrix() ? attr_types[ai]->getMatrixRows() : 4;
      const int l = std::max(loc[ai], 0) + c / rows;
      return (shader::kInGeneric0 + l) * 4 + c % rows;
    });
    for (size_t i = 0; i < attr_names.size(); ++i)
      if (active[i]) impl.attribs.push_back({attr_names[i], gl_type(*attr_types[i]), 1, loc[i]});
    static const struct {
      int slot;
      const char* name;
      GLenum type;
    } kBuiltinAttribs[] = {{shader::kInVertex, "gl_Vertex", GL_FLOAT_VEC4},
                           {shader::kInNormal, "gl_Normal", GL_FLOAT_VEC3},
                           {shader::kInColor, "gl_Color", GL_FLOAT_VEC4},
                           {shader::kInSecondaryColor, "gl_SecondaryColor", GL_FLOAT_VEC4},
                           {shader::kInFogCoord, "gl_FogCoord", GL_FLOAT}};
    for (const auto& b : kBuiltinAttribs)
      if (builtin_slots.count(b.slot)) impl.attribs.push_back({b.name, b.type, 1, -1});
    for (int t = 0; t < shader::kMaxTextureCoords; ++t)
      if (builtin_slots.count(shader::kInMultiTexCoord0 + t))
        impl.attribs.push_back({"gl_MultiTexCoord" + std::to_string(t), GL_FLOAT_VEC4, 1, -1});
  }

  // ---- limits ----
  std::vector<uint8_t> read_vs(static_cast<size_t>(layout.words), 0), read_fs = read_vs;
  if (vs_ast) words_read(vs_ir, read_vs);
  if (fs_ast) words_read(fs_ir, read_fs);
  if (count_read(read_vs) > limits.max_vertex_uniform_components)
    return fail("ERROR: Linking: the vertex shader reads more uniform components than the limit (" +
                std::to_string(limits.max_vertex_uniform_components) + ")");
  if (count_read(read_fs) > limits.max_fragment_uniform_components)
    return fail(
        "ERROR: Linking: the fragment shader reads more uniform components than the limit (" +
        std::to_string(limits.max_fragment_uniform_components) + ")");

  // ---- executables ----
  std::string err;
  if (fs_ast) {
    impl.fs = shader::Executable::build(fs_ir, shader::Stage::Fragment, &err);
    if (!impl.fs) return fail("ERROR: Linking fragment shader: " + err);
  }
  if (vs_ast) {
    impl.vs = shader::Executable::build(vs_ir, shader::Stage::Vertex, &err);
    if (!impl.vs) return fail("ERROR: Linking vertex shader: " + err);
  }
  // GL 2.1 §2.15.3 "Samplers", §2.15.4 "Texture Access": the active samplers per stage and in
  // all; a sampler both stages use counts once in each.
  const size_t vs_samplers = impl.vs ? impl.vs->sampler_words().size() : 0;
  const size_t fs_samplers = impl.fs ? impl.fs->sampler_words().size() : 0;
  if (static_cast<int>(vs_samplers) > limits.max_vertex_texture_image_units ||
      static_cast<int>(fs_samplers) > limits.max_texture_image_units ||
      static_cast<int>(vs_samplers + fs_samplers) > limits.max_combined_texture_image_units)
    return fail("ERROR: Linking: too many samplers (vertex " + std::to_string(vs_samplers) +
                ", fragment " + std::to_string(fs_samplers) + "; limits " +
                std::to_string(limits.max_vertex_texture_image_units) + ", " +
                std::to_string(limits.max_texture_image_units) + ", " +
                std::to_string(limits.max_combined_texture_image_units) + " combined)");

  // ---- uniforms: initial values (GLSL 1.20 §4.3.5) and reflection ----
  for (const std::vector<Decl>* decls : {&vs_decls, &fs_decls})
    for (const Decl& d : *decls)
      if (d.storage == EvqUniform && d.sym->getConstArray().size() > 0)
        layout.word_of(d.name, *d.type);
  impl.uniform_words = layout.words;
  impl.initial.assign(static_cast<size_t>(layout.words), 0);
  for (const std::vector<Decl>* decls : {&vs_decls, &fs_decls})
    for (const Decl& d : *decls) {
      if (d.storage != EvqUniform || d.sym->getConstArray().size() == 0) continue;
      const int w = layout.word_of(d.name, *d.type);
      const TConstUnionArray& c = d.sym->getConstArray();
      for (int k = 0; k < c.size() && w + k < layout.words; ++k) {
        uint32_t bits = 0;
        switch (c[k].getType()) {
        case EbtFloat:
        case EbtDouble:
          bits = std::bit_cast<uint32_t>(static_cast<float>(c[k].getDConst()));
          break;
        case EbtBool:
          bits = c[k].getBConst() ? 1u : 0u;
          break;
        default:
          bits = static_cast<uint32_t>(c[k].getIConst());
          break;
        }
        impl.initial[static_cast<size_t>(w + k)] = bits;
      }
    }
  read_vs.resize(static_cast<size_t>(layout.words), 0);
  read_fs.resize(static_cast<size_t>(layout.words), 0);
  // A uniform with an initializer is active even when no code reads it, as in Mesa: an
  // application that declares a value for it may set it (piglit's uniform-initializer
  // *-set-by-API tests); GL 2.1 §2.15.3 leaves activity of unread uniforms to the linker.
  for (const std::vector<Decl>* decls : {&vs_decls, &fs_decls})
    for (const Decl& d : *decls) {
      if (d.storage != EvqUniform || d.sym->getConstArray().size() == 0) continue;
      const int w = layout.word_of(d.name, *d.type);
      for (int k = 0; k < component_count(*d.type) && w + k < layout.words; ++k)
        (decls == &vs_decls ? read_vs : read_fs)[static_cast<size_t>(w + k)] = 1;
    }
  for (const Leaf& leaf : layout.leaves) {
    int size = 0;
    for (int e = 0; e < leaf.count; ++e)
      for (int k = 0; k < leaf.elem_words; ++k) {
        const size_t w = static_cast<size_t>(leaf.word + e * leaf.elem_words + k);
        if (read_vs[w] || read_fs[w]) size = e + 1;
      }
    if (size == 0) continue;
    ActiveUniform u;
    u.name = leaf.array ? leaf.name + "[0]" : leaf.name;
    u.type = leaf.type;
    u.size = size;
    u.word = leaf.word;
    u.stride = leaf.elem_words;
    u.array = leaf.array;
    if (leaf.builtin) {
      for (int e = 0; e < size; ++e)
        impl.builtins.push_back({leaf.array ? leaf.name + "[" + std::to_string(e) + "]" : leaf.name,
                                 leaf.type, leaf.word + e * leaf.elem_words});
    } else {
      u.location = static_cast<int>(impl.locations.size());
      for (int e = 0; e < size; ++e)
        impl.locations.push_back(
            {static_cast<int>(impl.uniforms.size()), e, leaf.word + e * leaf.elem_words});
    }
    impl.uniforms.push_back(u);
  }

  if (debug_ir() || limits.keep_ir) {
    if (vs_ast) impl.ir += "vertex shader IR:\n" + shader::print(vs_ir) + impl.vs->disassemble();
    if (fs_ast) impl.ir += "fragment shader IR:\n" + shader::print(fs_ir) + impl.fs->disassemble();
    if (debug_ir()) std::fputs(impl.ir.c_str(), stderr);
  }
  impl.packed = packed;
  p->linked_ = true;
  return p;
}

} // namespace pineda::glsl
