// Texture objects (GL 2.1 §3.8.12): names, binding, deletion, priorities and residency; texture
// parameters (§3.8.4, §3.8.14) and their queries (§6.1.3); the bindings part of
// glPushAttrib(TEXTURE_BIT); the glGet values of the texture objects (Tables 6.17, 6.36).
#include "state/texture_object.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "state/api_util.h"
#include "dispatch.h"
#include "state/area.h"
#include "state/texture_internal.h"

namespace pineda {

namespace {

constexpr GLenum kTargets[kTexTargetCount] = {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D,
                                              GL_TEXTURE_CUBE_MAP};

TextureObject* lookup(Context* ctx, GLuint name) {
  auto it = ctx->shared->textures.find(name);
  return it == ctx->shared->textures.end() ? nullptr : it->second.get();
}

// A value of a parameter, from any of the command variants (§3.8.4): floats keep their value,
// integers are kept as integers for enums and levels and converted per Table 2.9 for the border
// colour.
struct ParamValue {
  double v[4] = {0, 0, 0, 0};
  bool from_int = false;
};

bool to_enum(double d, GLenum* e) {
  if (!(d >= 0.0 && d <= 4294967295.0)) return false;
  *e = static_cast<GLenum>(std::llround(d));
  return true;
}

bool valid_wrap(GLenum e) {
  return e == GL_REPEAT || e == GL_CLAMP || e == GL_CLAMP_TO_EDGE || e == GL_CLAMP_TO_BORDER ||
         e == GL_MIRRORED_REPEAT;
}

bool valid_min_filter(GLenum e) {
  return e == GL_NEAREST || e == GL_LINEAR || e == GL_NEAREST_MIPMAP_NEAREST ||
         e == GL_LINEAR_MIPMAP_NEAREST || e == GL_NEAREST_MIPMAP_LINEAR ||
         e == GL_LINEAR_MIPMAP_LINEAR;
}

bool valid_compare_func(GLenum e) {
  return e >= GL_NEVER && e <= GL_ALWAYS;
}

bool same_params(const TexParams& a, const TexParams& b) {
  return a.min_filter == b.min_filter && a.mag_filter == b.mag_filter && a.wrap_s == b.wrap_s &&
         a.wrap_t == b.wrap_t && a.wrap_r == b.wrap_r &&
         std::equal(a.border_color, a.border_color + 4, b.border_color) && a.min_lod == b.min_lod &&
         a.max_lod == b.max_lod && a.base_level == b.base_level && a.max_level == b.max_level &&
         a.lod_bias == b.lod_bias && a.priority == b.priority &&
         a.generate_mipmap == b.generate_mipmap && a.depth_mode == b.depth_mode &&
         a.compare_mode == b.compare_mode && a.compare_func == b.compare_func;
}

// Sets one parameter after validation (§3.8.4: INVALID_ENUM for an unknown pname or a bad enum
// value, INVALID_VALUE for a negative level). `vector` is false for the scalar commands, which
// cannot set BORDER_COLOR.
void set_param(Context* ctx, TextureObject* tex, GLenum pname, const ParamValue& pv, bool vector,
               const char* func) {
  TexParams p = tex->params;
  GLenum e = 0;
  const double x = pv.v[0];
  auto bad_enum = [&]() { record_error(ctx, GL_INVALID_ENUM, func, pname); };
  switch (pname) {
  case GL_TEXTURE_MIN_FILTER:
    if (!to_enum(x, &e) || !valid_min_filter(e)) return bad_enum();
    p.min_filter = e;
    break;
  case GL_TEXTURE_MAG_FILTER:
    if (!to_enum(x, &e) || (e != GL_NEAREST && e != GL_LINEAR)) return bad_enum();
    p.mag_filter = e;
    break;
  case GL_TEXTURE_WRAP_S:
  case GL_TEXTURE_WRAP_T:
  case GL_TEXTURE_WRAP_R:
    if (!to_enum(x, &e) || !valid_wrap(e)) return bad_enum();
    (pname == GL_TEXTURE_WRAP_S ? p.wrap_s : pname == GL_TEXTURE_WRAP_T ? p.wrap_t : p.wrap_r) = e;
    break;
  case GL_TEXTURE_BORDER_COLOR:
    if (!vector) return bad_enum();
    // GL 2.1 §3.8.4: the border colour is clamped to [0,1] when specified.
    for (int i = 0; i < 4; ++i) {
      double c = pv.v[i];
      if (pv.from_int) c = (2.0 * c + 1.0) / 4294967295.0;
      p.border_color[i] = clampf01(static_cast<float>(c));
    }
    break;
  case GL_TEXTURE_MIN_LOD:
    p.min_lod = static_cast<float>(x);
    break;
  case GL_TEXTURE_MAX_LOD:
    p.max_lod = static_cast<float>(x);
    break;
  case GL_TEXTURE_BASE_LEVEL:
  case GL_TEXTURE_MAX_LEVEL: {
    if (!(x == x)) return record_error(ctx, GL_INVALID_VALUE, func);
    const double r = std::nearbyint(std::clamp(x, -2147483648.0, 2147483647.0));
    if (r < 0) return record_error(ctx, GL_INVALID_VALUE, func);
    (pname == GL_TEXTURE_BASE_LEVEL ? p.base_level : p.max_level) = static_cast<GLint>(r);
    break;
  }
  case GL_TEXTURE_LOD_BIAS:
    p.lod_bias = static_cast<float>(x);
    break;
  case GL_TEXTURE_PRIORITY:
    p.priority = clampf01(static_cast<float>(x));
    break;
  case GL_GENERATE_MIPMAP:
    if (!to_enum(x, &e) || (e != GL_TRUE && e != GL_FALSE)) return bad_enum();
    p.generate_mipmap = e == GL_TRUE;
    break;
  case GL_DEPTH_TEXTURE_MODE:
    if (!to_enum(x, &e) || (e != GL_LUMINANCE && e != GL_INTENSITY && e != GL_ALPHA))
      return bad_enum();
    p.depth_mode = e;
    break;
  case GL_TEXTURE_COMPARE_MODE:
    if (!to_enum(x, &e) || (e != GL_NONE && e != GL_COMPARE_R_TO_TEXTURE)) return bad_enum();
    p.compare_mode = e;
    break;
  case GL_TEXTURE_COMPARE_FUNC:
    if (!to_enum(x, &e) || !valid_compare_func(e)) return bad_enum();
    p.compare_func = e;
    break;
  default:
    return bad_enum();
  }
  if (same_params(p, tex->params)) return;
  tex->params = p;
  texture_changed(ctx);
}

// The object for glTexParameter / glGetTexParameter on `target`, or null with INVALID_ENUM.
TextureObject* param_object(Context* ctx, GLenum target, const char* func) {
  const int ti = texture_target_index(target);
  if (ti < 0) {
    record_error(ctx, GL_INVALID_ENUM, func, target);
    return nullptr;
  }
  return active_texture_object(ctx, ti);
}

void tex_parameter(GLenum target, GLenum pname, const ParamValue& pv, bool vector,
                   const char* func) {
  PINEDA_CTX_OUTSIDE(func);
  TextureObject* tex = param_object(ctx, target, func);
  if (tex == nullptr) return;
  set_param(ctx, tex, pname, pv, vector, func);
}

// Values of glGetTexParameter (§6.1.3, Table 6.19); count 0 for an unknown pname.
int get_param(const TextureObject& tex, GLenum pname, double* v, bool* color) {
  const TexParams& p = tex.params;
  *color = false;
  switch (pname) {
  case GL_TEXTURE_MIN_FILTER:
    v[0] = p.min_filter;
    return 1;
  case GL_TEXTURE_MAG_FILTER:
    v[0] = p.mag_filter;
    return 1;
  case GL_TEXTURE_WRAP_S:
    v[0] = p.wrap_s;
    return 1;
  case GL_TEXTURE_WRAP_T:
    v[0] = p.wrap_t;
    return 1;
  case GL_TEXTURE_WRAP_R:
    v[0] = p.wrap_r;
    return 1;
  case GL_TEXTURE_BORDER_COLOR:
    *color = true;
    for (int i = 0; i < 4; ++i)
      v[i] = p.border_color[i];
    return 4;
  case GL_TEXTURE_MIN_LOD:
    v[0] = p.min_lod;
    return 1;
  case GL_TEXTURE_MAX_LOD:
    v[0] = p.max_lod;
    return 1;
  case GL_TEXTURE_BASE_LEVEL:
    v[0] = p.base_level;
    return 1;
  case GL_TEXTURE_MAX_LEVEL:
    v[0] = p.max_level;
    return 1;
  case GL_TEXTURE_LOD_BIAS:
    v[0] = p.lod_bias;
    return 1;
  case GL_TEXTURE_PRIORITY:
    v[0] = p.priority;
    return 1;
  case GL_TEXTURE_RESIDENT:
    v[0] = GL_TRUE;
    return 1;
  case GL_GENERATE_MIPMAP:
    v[0] = p.generate_mipmap ? GL_TRUE : GL_FALSE;
    return 1;
  case GL_DEPTH_TEXTURE_MODE:
    v[0] = p.depth_mode;
    return 1;
  case GL_TEXTURE_COMPARE_MODE:
    v[0] = p.compare_mode;
    return 1;
  case GL_TEXTURE_COMPARE_FUNC:
    v[0] = p.compare_func;
    return 1;
  default:
    return 0;
  }
}

// §6.1.2: a colour component as an integer maps [-1,1] to the full integer range.
GLint color_to_int(double c) {
  const double scaled = c * 2147483647.0;
  if (scaled >= 2147483647.0) return std::numeric_limits<GLint>::max();
  if (scaled <= -2147483648.0) return std::numeric_limits<GLint>::min();
  return static_cast<GLint>(std::llround(scaled));
}

GLint to_int(double x) {
  if (!(x == x)) return 0;
  if (x >= 2147483647.0) return std::numeric_limits<GLint>::max();
  if (x <= -2147483648.0) return std::numeric_limits<GLint>::min();
  return static_cast<GLint>(std::llround(x));
}

} // namespace

int texture_target_index(GLenum target) {
  switch (target) {
  case GL_TEXTURE_1D:
    return kTex1D;
  case GL_TEXTURE_2D:
    return kTex2D;
  case GL_TEXTURE_3D:
    return kTex3D;
  case GL_TEXTURE_CUBE_MAP:
    return kTexCube;
  default:
    return -1;
  }
}

TextureObject* active_texture_object(Context* ctx, int target_index) {
  return const_cast<TextureObject*>(
      bound_texture(ctx, static_cast<int>(ctx->texture.active), kTargets[target_index]));
}

TextureState::TextureState() {
  for (int i = 0; i < kTexTargetCount; ++i) {
    defaults[i] = std::make_unique<TextureObject>();
    defaults[i]->target = kTargets[i];
    proxies[i] = std::make_unique<TextureObject>();
    proxies[i]->target = kTargets[i];
  }
}

const TextureObject* bound_texture(const Context* ctx, int unit, GLenum target) {
  const int ti = texture_target_index(target);
  const int t = ti < 0 ? kTex2D : ti;
  const int u = unit >= 0 && unit < kMaxCombinedTextureImageUnits ? unit : 0;
  const GLuint name = ctx->texobj.bound[u][t];
  if (name != 0) {
    auto it = ctx->shared->textures.find(name);
    if (it != ctx->shared->textures.end()) return it->second.get();
  }
  return ctx->texobj.defaults[t].get();
}

namespace {

// glPushAttrib(TEXTURE_BIT), the part the texture objects own (GL 2.1 §6.1.14): the bindings of
// every unit and the parameters of the bound objects (Tables 6.16-6.19).
class SavedTextureObjects final : public SavedAttrib {
public:
  explicit SavedTextureObjects(const Context& ctx) {
    for (int u = 0; u < kMaxCombinedTextureImageUnits; ++u)
      for (int t = 0; t < kTexTargetCount; ++t) {
        bound_[u][t] = ctx.texobj.bound[u][t];
        params_[u][t] = bound_texture(&ctx, u, kTargets[t])->params;
      }
  }
  // §6.1.14: popping TEXTURE_BIT rebinds the saved names and restores the saved parameters of
  // those objects; an object deleted in between is not recreated (its binding reverts to 0).
  void restore(Context& ctx) const override {
    for (int u = 0; u < kMaxCombinedTextureImageUnits; ++u)
      for (int t = 0; t < kTexTargetCount; ++t) {
        const GLuint name = bound_[u][t];
        TextureObject* tex = name == 0 ? ctx.texobj.defaults[t].get() : lookup(&ctx, name);
        ctx.texobj.bound[u][t] = tex != nullptr ? name : 0;
        if (tex != nullptr) tex->params = params_[u][t];
      }
    texture_changed(&ctx);
  }

private:
  GLuint bound_[kMaxCombinedTextureImageUnits][kTexTargetCount];
  TexParams params_[kMaxCombinedTextureImageUnits][kTexTargetCount];
};

std::unique_ptr<SavedAttrib> save_objects(const Context& ctx) {
  return std::make_unique<SavedTextureObjects>(ctx);
}

constexpr AttribGroup kTextureObjectGroups[] = {
    {GL_TEXTURE_BIT, false, true, kDirtyTexture, save_objects},
};

// The bindings of the active unit (Table 6.16) and the texture limits (Table 6.36).
bool get_texture_objects(Context& ctx, GLenum pname, QueryValues& out) {
  const int ti = pname == GL_TEXTURE_BINDING_1D         ? kTex1D
                 : pname == GL_TEXTURE_BINDING_2D       ? kTex2D
                 : pname == GL_TEXTURE_BINDING_3D       ? kTex3D
                 : pname == GL_TEXTURE_BINDING_CUBE_MAP ? kTexCube
                                                        : -1;
  if (ti >= 0) {
    const GLuint name = ctx.texobj.bound[ctx.texture.active][ti];
    out.ints({lookup(&ctx, name) != nullptr ? double(name) : 0.0});
    return true;
  }
  switch (pname) {
  case GL_MAX_TEXTURE_SIZE:
    out.ints({kMaxTextureSize});
    return true;
  case GL_MAX_3D_TEXTURE_SIZE:
    out.ints({kMax3DTextureSize});
    return true;
  case GL_MAX_CUBE_MAP_TEXTURE_SIZE:
    out.ints({kMaxCubeTextureSize});
    return true;
  // GL 2.1 §3.8.1: no specific compressed internal formats (tex_compressed.cpp): an empty list.
  case GL_NUM_COMPRESSED_TEXTURE_FORMATS:
    out.ints({0});
    return true;
  case GL_COMPRESSED_TEXTURE_FORMATS:
    return true;
  case GL_MAX_TEXTURE_LOD_BIAS:
    out.floats({kMaxLodBias});
    return true;
  default:
    return false;
  }
}

} // namespace

const StateArea kTextureObjectArea = {
    .name = "texture objects (GL 2.1 §3.8.12, Tables 6.16-6.19)",
    .get = get_texture_objects,
    .groups = kTextureObjectGroups,
};

namespace exec {

void GLAPIENTRY GenTextures(GLsizei n, GLuint* textures) {
  PINEDA_CTX_OUTSIDE("glGenTextures");
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE, "glGenTextures");
  if (textures == nullptr) return;
  auto& objs = ctx->shared->textures;
  GLuint next = 1;
  for (GLsizei i = 0; i < n; ++i) {
    while (objs.count(next) != 0)
      ++next;
    // A generated name is reserved; it becomes a texture object when first bound (§3.8.12).
    auto obj = std::make_shared<TextureObject>();
    obj->name = next;
    objs.emplace(next, std::move(obj));
    textures[i] = next++;
  }
}

void GLAPIENTRY DeleteTextures(GLsizei n, const GLuint* textures) {
  PINEDA_CTX_OUTSIDE("glDeleteTextures");
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE, "glDeleteTextures");
  if (textures == nullptr) return;
  bool changed = false;
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = textures[i];
    auto it = name == 0 ? ctx->shared->textures.end() : ctx->shared->textures.find(name);
    if (it == ctx->shared->textures.end()) continue;
    // ARB_framebuffer_object §4.4.2.3: detached from the bound framebuffers; others keep it.
    detach_deleted_texture(ctx, it->second.get());
    ctx->shared->textures.erase(it);
    // §3.8.12: a deleted bound texture reverts the binding to the default object (0).
    for (auto& unit : ctx->texobj.bound)
      for (GLuint& b : unit)
        if (b == name) b = 0;
    changed = true;
  }
  if (changed) texture_changed(ctx);
}

GLboolean GLAPIENTRY IsTexture(GLuint texture) {
  Context* ctx = outside_begin_end("glIsTexture");
  if (ctx == nullptr || texture == 0) return GL_FALSE;
  const TextureObject* tex = lookup(ctx, texture);
  return tex != nullptr && tex->target != 0 ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY BindTexture(GLenum target, GLuint texture) {
  PINEDA_CTX_OUTSIDE("glBindTexture");
  const int ti = texture_target_index(target);
  if (ti < 0) return record_error(ctx, GL_INVALID_ENUM, "glBindTexture", target);
  if (texture != 0) {
    auto& slot = ctx->shared->textures[texture];
    if (!slot) {
      slot = std::make_shared<TextureObject>();
      slot->name = texture;
    }
    // §3.8.12: an object keeps the dimensionality of its first binding.
    if (slot->target != 0 && slot->target != target)
      return record_error(ctx, GL_INVALID_OPERATION, "glBindTexture");
    slot->target = target;
  }
  GLuint& binding = ctx->texobj.bound[ctx->texture.active][ti];
  if (binding == texture) return;
  binding = texture;
  texture_changed(ctx);
}

void GLAPIENTRY PrioritizeTextures(GLsizei n, const GLuint* textures, const GLfloat* priorities) {
  PINEDA_CTX_OUTSIDE("glPrioritizeTextures");
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE, "glPrioritizeTextures");
  if (textures == nullptr || priorities == nullptr) return;
  // §3.8.13: names that are zero or not textures are silently ignored.
  for (GLsizei i = 0; i < n; ++i) {
    TextureObject* tex = textures[i] != 0 ? lookup(ctx, textures[i]) : nullptr;
    if (tex == nullptr || tex->target == 0) continue;
    tex->params.priority = clampf01(priorities[i]);
  }
  texture_changed(ctx);
}

GLboolean GLAPIENTRY AreTexturesResident(GLsizei n, const GLuint* textures, GLboolean* residences) {
  Context* ctx = outside_begin_end("glAreTexturesResident");
  if (ctx == nullptr) return GL_FALSE;
  if (n < 0) {
    record_error(ctx, GL_INVALID_VALUE, "glAreTexturesResident");
    return GL_FALSE;
  }
  if (textures == nullptr) return GL_FALSE;
  // §3.8.13: zero or a name that is not a texture is INVALID_VALUE. Every texture is
  // resident, so `residences` is left untouched and TRUE returned.
  for (GLsizei i = 0; i < n; ++i) {
    const TextureObject* tex = textures[i] != 0 ? lookup(ctx, textures[i]) : nullptr;
    if (tex == nullptr || tex->target == 0) {
      record_error(ctx, GL_INVALID_VALUE, "glAreTexturesResident");
      return GL_FALSE;
    }
  }
  (void)residences;
  return GL_TRUE;
}

void GLAPIENTRY TexParameterf(GLenum target, GLenum pname, GLfloat param) {
  ParamValue pv;
  pv.v[0] = param;
  tex_parameter(target, pname, pv, false, "glTexParameterf");
}

void GLAPIENTRY TexParameteri(GLenum target, GLenum pname, GLint param) {
  ParamValue pv;
  pv.v[0] = param;
  pv.from_int = true;
  tex_parameter(target, pname, pv, false, "glTexParameteri");
}

void GLAPIENTRY TexParameterfv(GLenum target, GLenum pname, const GLfloat* params) {
  if (params == nullptr) return;
  ParamValue pv;
  const int count = pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1;
  for (int i = 0; i < count; ++i)
    pv.v[i] = params[i];
  tex_parameter(target, pname, pv, true, "glTexParameterfv");
}

void GLAPIENTRY TexParameteriv(GLenum target, GLenum pname, const GLint* params) {
  if (params == nullptr) return;
  ParamValue pv;
  pv.from_int = true;
  const int count = pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1;
  for (int i = 0; i < count; ++i)
    pv.v[i] = params[i];
  tex_parameter(target, pname, pv, true, "glTexParameteriv");
}

void GLAPIENTRY GetTexParameterfv(GLenum target, GLenum pname, GLfloat* params) {
  PINEDA_CTX_OUTSIDE("glGetTexParameterfv");
  const TextureObject* tex = param_object(ctx, target, "glGetTexParameterfv");
  if (tex == nullptr) return;
  double v[4];
  bool color = false;
  const int n = get_param(*tex, pname, v, &color);
  if (n == 0) return record_error(ctx, GL_INVALID_ENUM, "glGetTexParameterfv", pname);
  if (params == nullptr) return;
  for (int i = 0; i < n; ++i)
    params[i] = static_cast<GLfloat>(v[i]);
}

void GLAPIENTRY GetTexParameteriv(GLenum target, GLenum pname, GLint* params) {
  PINEDA_CTX_OUTSIDE("glGetTexParameteriv");
  const TextureObject* tex = param_object(ctx, target, "glGetTexParameteriv");
  if (tex == nullptr) return;
  double v[4];
  bool color = false;
  const int n = get_param(*tex, pname, v, &color);
  if (n == 0) return record_error(ctx, GL_INVALID_ENUM, "glGetTexParameteriv", pname);
  if (params == nullptr) return;
  for (int i = 0; i < n; ++i)
    params[i] = color ? color_to_int(v[i]) : to_int(v[i]);
}

} // namespace exec

} // namespace pineda
