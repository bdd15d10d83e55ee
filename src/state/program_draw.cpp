// The program's side of the draws (program.h ProgramDerived): where each stage's inputs and
// outputs live in the processed vertex, the built-in uniform state a program reads (GLSL 1.20
// §7.5, derived from the GL state of this context), the texture views of its samplers, and
// the preparation of its executables (shader/engine.h) when any of that changed.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "geometry/clip.h"
#include "shader/engine.h"
#include "state/program_draw.h"
#include "state/context.h"
#include "state/program_internal.h"
#include "texture/shader_sampler.h"

namespace pineda {

namespace {

using namespace shader;

// ---- built-in uniforms ----

enum BuiltinKind : uint16_t {
  kBuiltinNone,
  kBuiltinModelView,     // field: 0 plain, 1 inverse, 2 transpose, 3 inverse transpose
  kBuiltinProjection,    // the same
  kBuiltinMvp,           // the same
  kBuiltinTextureMatrix, // the same; index: unit
  kBuiltinNormalMatrix,
  kBuiltinNormalScale,
  kBuiltinDepthRange, // field: near, far, diff
  kBuiltinClipPlane,  // index
  kBuiltinPoint,      // field: size, sizeMin, sizeMax, fadeThresholdSize, constant, linear,
                      // quadratic
  kBuiltinMaterial,   // index: face; field: emission, ambient, diffuse, specular, shininess
  kBuiltinLight,      // index: light; field: ambient, diffuse, specular, position, halfVector,
                      // spotDirection, spotExponent, spotCutoff, spotCosCutoff, constant, linear,
                      // quadratic attenuation
  kBuiltinLightModelAmbient,
  kBuiltinSceneColor,   // index: face
  kBuiltinLightProduct, // index: light; field: face * 3 + (ambient, diffuse, specular)
  kBuiltinTexEnvColor,  // index: unit
  kBuiltinEyePlane,     // index: unit; field: s, t, r, q
  kBuiltinObjectPlane,  // the same
  kBuiltinFog,          // field: color, density, start, end, scale
};

int field_of(const std::string& name, std::initializer_list<const char*> fields) {
  int i = 0;
  for (const char* f : fields) {
    if (name == f) return i;
    ++i;
  }
  return -1;
}

// "gl_Foo[3].bar" -> base "gl_Foo", index 3, member "bar".
void split_name(const std::string& full, std::string& base, int& index, std::string& member) {
  index = 0;
  member.clear();
  std::string rest = full;
  const size_t dot = rest.find('.');
  if (dot != std::string::npos) {
    member = rest.substr(dot + 1);
    rest = rest.substr(0, dot);
  }
  const size_t open = rest.find('[');
  if (open != std::string::npos) {
    index = std::atoi(rest.c_str() + open + 1);
    rest = rest.substr(0, open);
  }
  base = rest;
}

BuiltinSlot decode(const glsl::BuiltinUniform& b) {
  std::string base, member;
  int index = 0;
  split_name(b.name, base, index, member);
  BuiltinSlot s;
  s.word = b.word;
  s.index = static_cast<uint8_t>(std::clamp(index, 0, 255));
  const auto matrix = [&](const char* stem, BuiltinKind kind) {
    const std::string st = stem;
    if (base.rfind(st, 0) != 0) return false;
    const int form =
        field_of(base.substr(st.size()), {"", "Inverse", "Transpose", "InverseTranspose"});
    if (form < 0) return false;
    s.kind = kind;
    s.field = static_cast<uint8_t>(form);
    return true;
  };
  if (matrix("gl_ModelViewProjectionMatrix", kBuiltinMvp) ||
      matrix("gl_ModelViewMatrix", kBuiltinModelView) ||
      matrix("gl_ProjectionMatrix", kBuiltinProjection) ||
      matrix("gl_TextureMatrix", kBuiltinTextureMatrix))
    return s;
  int f = -1;
  if (base == "gl_NormalMatrix") {
    s.kind = kBuiltinNormalMatrix;
  } else if (base == "gl_NormalScale") {
    s.kind = kBuiltinNormalScale;
  } else if (base == "gl_DepthRange" && (f = field_of(member, {"near", "far", "diff"})) >= 0) {
    s.kind = kBuiltinDepthRange;
  } else if (base == "gl_ClipPlane") {
    s.kind = kBuiltinClipPlane;
  } else if (base == "gl_Point" &&
             (f = field_of(member, {"size", "sizeMin", "sizeMax", "fadeThresholdSize",
                                    "distanceConstantAttenuation", "distanceLinearAttenuation",
                                    "distanceQuadraticAttenuation"})) >= 0) {
    s.kind = kBuiltinPoint;
  } else if ((base == "gl_FrontMaterial" || base == "gl_BackMaterial") &&
             (f = field_of(member, {"emission", "ambient", "diffuse", "specular", "shininess"})) >=
                 0) {
    s.kind = kBuiltinMaterial;
    s.index = base == "gl_BackMaterial" ? 1 : 0;
  } else if (base == "gl_LightSource" &&
             (f = field_of(member, {"ambient", "diffuse", "specular", "position", "halfVector",
                                    "spotDirection", "spotExponent", "spotCutoff", "spotCosCutoff",
                                    "constantAttenuation", "linearAttenuation",
                                    "quadraticAttenuation"})) >= 0) {
    s.kind = kBuiltinLight;
  } else if (base == "gl_LightModel" && member == "ambient") {
    s.kind = kBuiltinLightModelAmbient;
  } else if ((base == "gl_FrontLightModelProduct" || base == "gl_BackLightModelProduct") &&
             member == "sceneColor") {
    s.kind = kBuiltinSceneColor;
    s.index = base == "gl_BackLightModelProduct" ? 1 : 0;
  } else if ((base == "gl_FrontLightProduct" || base == "gl_BackLightProduct") &&
             (f = field_of(member, {"ambient", "diffuse", "specular"})) >= 0) {
    s.kind = kBuiltinLightProduct;
    f += base == "gl_BackLightProduct" ? 3 : 0;
  } else if (base == "gl_TextureEnvColor") {
    s.kind = kBuiltinTexEnvColor;
  } else if ((f = field_of(
                  base, {"gl_EyePlaneS", "gl_EyePlaneT", "gl_EyePlaneR", "gl_EyePlaneQ"})) >= 0) {
    s.kind = kBuiltinEyePlane;
  } else if ((f = field_of(base, {"gl_ObjectPlaneS", "gl_ObjectPlaneT", "gl_ObjectPlaneR",
                                  "gl_ObjectPlaneQ"})) >= 0) {
    s.kind = kBuiltinObjectPlane;
  } else if (base == "gl_Fog" &&
             (f = field_of(member, {"color", "density", "start", "end", "scale"})) >= 0) {
    s.kind = kBuiltinFog;
  }
  s.field = static_cast<uint8_t>(std::max(f, 0));
  return s;
}

void put(std::vector<uint32_t>& w, int at, float v) {
  if (at >= 0 && static_cast<size_t>(at) < w.size())
    w[static_cast<size_t>(at)] = std::bit_cast<uint32_t>(v);
}
void put4(std::vector<uint32_t>& w, int at, const float* v, int n = 4) {
  for (int k = 0; k < n; ++k)
    put(w, at + k, v[k]);
}
void put_mat4(std::vector<uint32_t>& w, int at, const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      put(w, at + 4 * c + r, m[c][r]);
}

glm::mat4 matrix_form(const glm::mat4& m, int form) {
  switch (form) {
  case 1:
    return glm::inverse(m);
  case 2:
    return glm::transpose(m);
  case 3:
    return glm::transpose(glm::inverse(m));
  default:
    return m;
  }
}

void write_builtin(const Context& ctx, const BuiltinSlot& s, std::vector<uint32_t>& w) {
  const glm::mat4& mv = ctx.modelview.top();
  const glm::mat4& proj = ctx.projection.top();
  switch (s.kind) {
  case kBuiltinModelView:
    return put_mat4(w, s.word, matrix_form(mv, s.field));
  case kBuiltinProjection:
    return put_mat4(w, s.word, matrix_form(proj, s.field));
  case kBuiltinMvp:
    return put_mat4(w, s.word, matrix_form(proj * mv, s.field));
  case kBuiltinTextureMatrix:
    if (s.index < kMaxTexUnits)
      put_mat4(w, s.word, matrix_form(ctx.texture_matrix[s.index].top(), s.field));
    else
      put_mat4(w, s.word, glm::mat4(1.0f));
    return;
  case kBuiltinNormalMatrix: {
    // GLSL 1.20 §7.5: the transpose of the inverse of the upper 3x3 of the model-view matrix.
    const glm::mat3 nm = glm::transpose(glm::inverse(glm::mat3(mv)));
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r)
        put(w, s.word + 3 * c + r, nm[c][r]);
    return;
  }
  case kBuiltinNormalScale: {
    // §2.11.3's rescale factor.
    const glm::mat3 inv = glm::inverse(glm::mat3(mv));
    const float len =
        std::sqrt(inv[0][2] * inv[0][2] + inv[1][2] * inv[1][2] + inv[2][2] * inv[2][2]);
    return put(w, s.word, len > 0.0f ? 1.0f / len : 1.0f);
  }
  case kBuiltinDepthRange: {
    const auto n = static_cast<float>(ctx.viewport.near), f = static_cast<float>(ctx.viewport.far);
    return put(w, s.word, s.field == 0 ? n : s.field == 1 ? f : f - n);
  }
  case kBuiltinClipPlane: {
    float p[4] = {};
    if (s.index < kMaxClipPlanes)
      for (int k = 0; k < 4; ++k)
        p[k] = static_cast<float>(ctx.transform.clip_plane[s.index][k]);
    return put4(w, s.word, p);
  }
  case kBuiltinPoint: {
    const PointGroup& pt = ctx.point;
    const float v[7] = {pt.size,           pt.size_min,       pt.size_max,      pt.fade_threshold,
                        pt.attenuation[0], pt.attenuation[1], pt.attenuation[2]};
    return put(w, s.word, v[s.field % 7]);
  }
  case kBuiltinMaterial: {
    const Material& m = ctx.lighting.material[s.index & 1];
    const float* v[4] = {m.emission, m.ambient, m.diffuse, m.specular};
    if (s.field == 4) return put(w, s.word, m.shininess);
    return put4(w, s.word, v[s.field & 3]);
  }
  case kBuiltinLight: {
    if (s.index >= kMaxLights) return;
    const Light& l = ctx.lighting.light[s.index];
    switch (s.field) {
    case 0:
      return put4(w, s.word, l.ambient);
    case 1:
      return put4(w, s.word, l.diffuse);
    case 2:
      return put4(w, s.word, l.specular);
    case 3:
      return put4(w, s.word, l.position);
    case 4: {
      // GLSL 1.20 §7.5 halfVector: the half vector of an infinite viewer, normalize(P + (0, 0,
      // 1)) with P the normalized light direction.
      glm::vec3 p(l.position[0], l.position[1], l.position[2]);
      if (glm::length(p) > 0.0f) p = glm::normalize(p);
      glm::vec3 h = p + glm::vec3(0.0f, 0.0f, 1.0f);
      if (glm::length(h) > 0.0f) h = glm::normalize(h);
      const float hv[4] = {h.x, h.y, h.z, 1.0f};
      return put4(w, s.word, hv);
    }
    case 5: {
      const float d[4] = {l.spot_direction[0], l.spot_direction[1], l.spot_direction[2], 0.0f};
      return put4(w, s.word, d, 3);
    }
    case 6:
      return put(w, s.word, l.spot_exponent);
    case 7:
      return put(w, s.word, l.spot_cutoff);
    case 8:
      return put(w, s.word,
                 static_cast<float>(std::cos(static_cast<double>(l.spot_cutoff) * M_PI / 180.0)));
    default:
      return put(w, s.word, l.attenuation[std::min(s.field - 9, 2)]);
    }
  }
  case kBuiltinLightModelAmbient:
    return put4(w, s.word, ctx.lighting.model_ambient);
  case kBuiltinSceneColor: {
    // ecm + acm * acs; the alpha is the material's diffuse alpha (§2.14.1).
    const Material& m = ctx.lighting.material[s.index & 1];
    float v[4];
    for (int k = 0; k < 3; ++k)
      v[k] = m.emission[k] + m.ambient[k] * ctx.lighting.model_ambient[k];
    v[3] = m.diffuse[3];
    return put4(w, s.word, v);
  }
  case kBuiltinLightProduct: {
    if (s.index >= kMaxLights) return;
    const Light& l = ctx.lighting.light[s.index];
    const Material& m = ctx.lighting.material[s.field >= 3 ? 1 : 0];
    const float* a[3] = {m.ambient, m.diffuse, m.specular};
    const float* b[3] = {l.ambient, l.diffuse, l.specular};
    const int f = s.field % 3;
    float v[4];
    for (int k = 0; k < 4; ++k)
      v[k] = a[f][k] * b[f][k];
    return put4(w, s.word, v);
  }
  case kBuiltinTexEnvColor:
    if (s.index < kMaxTexUnits) put4(w, s.word, ctx.texture.unit[s.index].env.color);
    return;
  case kBuiltinEyePlane:
    if (s.index < kMaxTexUnits)
      put4(w, s.word, ctx.texture.unit[s.index].gen[s.field & 3].eye_plane);
    return;
  case kBuiltinObjectPlane:
    if (s.index < kMaxTexUnits)
      put4(w, s.word, ctx.texture.unit[s.index].gen[s.field & 3].object_plane);
    return;
  case kBuiltinFog: {
    const FogGroup& fog = ctx.fog;
    switch (s.field) {
    case 0:
      return put4(w, s.word, fog.color);
    case 1:
      return put(w, s.word, fog.density);
    case 2:
      return put(w, s.word, fog.start);
    case 3:
      return put(w, s.word, fog.end);
    default:
      return put(w, s.word, fog.end != fog.start ? 1.0f / (fog.end - fog.start) : 0.0f);
    }
  }
  default:
    return;
  }
}

// ---- the processed vertex's layout ----

// Where fragment input component c (shader/io.h) lives in PVertex::attr, or -1 (computed by
// the fragment stage, or not supplied: read as zero).
int fragment_input_attr(int c) {
  const int slot = c / 4, k = c % 4;
  if (slot == kFragColor) return kAttrColor + k;
  if (slot == kFragSecondaryColor) return kAttrColor2 + k;
  if (slot >= kFragTexCoord0 && slot < kFragTexCoord0 + kMaxTexUnits)
    return kAttrTex0 + 4 * (slot - kFragTexCoord0) + k;
  if (slot == kFragFogFragCoord) return k == 0 ? kAttrFog : -1;
  if (slot >= kFragVarying0) {
    const int j = c - kFragVarying0 * 4;
    return j < kMaxVaryingAttr ? kAttrVarying0 + j : -1;
  }
  return -1;
}

// Where vertex output component c goes, or -1.
int vertex_output_attr(int c, bool two_side) {
  const int slot = c / 4, k = c % 4;
  switch (slot) {
  case kOutFrontColor:
    return kAttrColor + k;
  case kOutFrontSecondaryColor:
    return kAttrColor2 + k;
  case kOutBackColor:
    return two_side ? kAttrBackColor + k : -1;
  case kOutBackSecondaryColor:
    return two_side ? kAttrBackColor2 + k : -1;
  case kOutFogFragCoord:
    return k == 0 ? kAttrFog : -1;
  default:
    break;
  }
  if (slot >= kOutTexCoord0 && slot < kOutTexCoord0 + kMaxTexUnits)
    return kAttrTex0 + 4 * (slot - kOutTexCoord0) + k;
  if (slot >= kOutVarying0) {
    const int j = c - kOutVarying0 * 4;
    return j < kMaxVaryingAttr ? kAttrVarying0 + j : -1;
  }
  return -1;
}

} // namespace

std::vector<BuiltinSlot> decode_builtins(const glsl::Program& program) {
  std::vector<BuiltinSlot> out;
  for (const glsl::BuiltinUniform& b : program.builtin_uniforms()) {
    const BuiltinSlot s = decode(b);
    if (s.kind != kBuiltinNone) out.push_back(s);
  }
  return out;
}

uint32_t fixed_vertex_program_inputs(const Context& ctx, bool* fog) {
  *fog = false;
  const LinkedProgram* lp = active_program(&ctx);
  if (lp == nullptr || lp->program->vertex() != nullptr || lp->program->fragment() == nullptr)
    return 0;
  uint32_t units = 0;
  for (int c : lp->program->fragment()->inputs_read()) {
    const int slot = c / 4;
    if (slot >= kFragTexCoord0 && slot < kFragTexCoord0 + kMaxTexUnits)
      units |= 1u << (slot - kFragTexCoord0);
    if (slot == kFragFogFragCoord) *fog = true;
  }
  return units;
}

void derive_program(Context& ctx, uint32_t) {
  ProgramDerived& d = *ctx.program_draw;
  d.linked = ctx.program.object != nullptr ? ctx.program.object->active : nullptr;
  const LinkedProgram* lp = d.linked.get();
  const Executable* vs = lp != nullptr ? lp->program->vertex() : nullptr;
  const Executable* fs = lp != nullptr ? lp->program->fragment() : nullptr;
  d.has_vertex = vs != nullptr;
  d.has_fragment = fs != nullptr;
  d.vs_tex_units = 0;
  d.fs_tex_units = 0;
  d.fs_fog = false;
  if (lp == nullptr) return;
  if (!d.sampler) d.sampler = std::make_shared<ShaderSampler>();
  if (!d.vs_prepared) d.vs_prepared = std::make_shared<Prepared>();
  if (!d.fs_prepared) d.fs_prepared = std::make_shared<Prepared>();
  const bool two_side = ctx.program.two_side;

  // What the fragment stage reads of the processed vertex.
  int fs_count = 0;
  if (fs != nullptr) {
    FragmentProgram& f = d.fragment;
    f = FragmentProgram{};
    f.exe = fs;
    f.prepared = d.fs_prepared.get();
    f.sampler = d.sampler.get();
    f.discards = fs->discards();
    f.writes_depth = lp->program->writes_frag_depth();
    f.frag_data = !lp->program->writes_frag_color();
    for (int c : fs->inputs_read()) {
      const int slot = c / 4;
      if (slot == kFragCoord) f.frag_coord = true;
      if (slot == kFragPointCoord) f.point_coord = true;
      if (slot == kFragFrontFacing) continue;
      int a = fragment_input_attr(c);
      if (slot == kFragCoord || slot == kFragPointCoord) continue;
      // Inputs nothing supplies (gl_TexCoord beyond the units) read the spare fog slot's zero.
      if (a < 0) a = kAttrFog + 1;
      if (f.input_count < kMaxAttr) {
        f.input_comp[f.input_count] = static_cast<int16_t>(c);
        f.input_attr[f.input_count] = static_cast<int16_t>(a);
        ++f.input_count;
      }
      fs_count = std::max(fs_count, a + 1);
      if (slot >= kFragTexCoord0 && slot < kFragTexCoord0 + kMaxTexUnits)
        d.fs_tex_units |= 1u << (slot - kFragTexCoord0);
      if (slot == kFragFogFragCoord) d.fs_fog = true;
    }
    if (!d.shade) d.shade = std::make_shared<ShadeSetup>();
    d.shade->program = &d.fragment;
  }
  d.attr_count = std::max(fs_count, 4);

  if (vs != nullptr) {
    VertexProgram& v = d.vertex;
    v.exe = vs;
    v.prepared = d.vs_prepared.get();
    v.sampler = d.sampler.get();
    for (int c : vs->inputs_read()) {
      const int slot = c / 4;
      if (slot >= kInMultiTexCoord0 && slot < kInMultiTexCoord0 + kMaxTexUnits)
        d.vs_tex_units |= 1u << (slot - kInMultiTexCoord0);
    }
    // What the next stage reads: the fragment shader's inputs, or the fixed-function
    // fragment stage's (colours, the enabled units' coordinates, the fog coordinate).
    // §3.9: without a fragment shader the colour sum follows COLOR_SUM alone; folded into
    // the vertex colours when the fragment stage does not shade per fragment.
    v.fold_sum = fs == nullptr && ctx.fog.color_sum && !ctx.texpipe.shading;
    int downstream = fs != nullptr ? d.attr_count : ctx.texpipe.attr_count;
    if (v.fold_sum) downstream = std::max(downstream, kAttrColor2 + 4);
    int count = downstream;
    if (two_side) count = std::max(count, kAttrBackColor2 + 4);
    for (int c = 0; c < kNumVertexOutputs * 4; ++c) {
      const int a = vertex_output_attr(c, two_side);
      const bool back = a >= kAttrBackColor && a < kAttrVarying0;
      v.out_attr[c] = static_cast<int16_t>(a >= 0 && (a < downstream || back) ? a : -1);
    }
    v.attr_count = count;
    v.point_size = ctx.program.point_size;
    v.point_size_min = ctx.point.size_min;
    v.point_size_max = std::min(ctx.point.size_max, kMaxPointSize);
  }
}

bool program_raster_pos(Context* ctx, const float obj[4], RasterPos& rp) {
  refresh_program(ctx);
  const ProgramDerived& d = *ctx->program_draw;
  // The vertex stage of the draws, with every output kept and the current generic values.
  VertexProgram vp = d.vertex;
  vp.generic = nullptr;
  for (int i = 0; i < shader::kMaxVertexAttribs; ++i) {
    vp.generic_column[i] = -1;
    std::copy(ctx->vertex_attrib.value[i], ctx->vertex_attrib.value[i] + 4, vp.generic_current[i]);
  }
  for (int c = 0; c < kNumVertexOutputs * 4; ++c)
    vp.out_attr[c] = static_cast<int16_t>(vertex_output_attr(c, false));
  vp.attr_count = kMaxAttr;
  vp.fold_sum = false;
  vp.point_size = false;
  InputVertex in;
  const CurrentGroup& cur = ctx->current;
  std::copy(obj, obj + 4, in.pos);
  std::copy(cur.color, cur.color + 4, in.color);
  std::copy(cur.normal, cur.normal + 3, in.normal);
  std::copy(cur.color2, cur.color2 + 3, in.color2);
  in.fog = cur.fog_coord;
  in.edge = 1;
  for (int u = 0; u < kMaxTexUnits; ++u)
    std::copy(cur.tex[u], cur.tex[u] + 4, in.tex[u]);
  ClipSetup cs;
  init_clip_setup(cs, ctx->raster);
  PVertex out;
  run_vertex_program(vp, cs, ctx->raster.viewport, &in, 0, &out, 1);
  // §2.13: clipped as a point against the view volume and the user planes (tested, as for
  // the draws, on the shader's clip coordinates).
  const uint32_t outside = out.clipmask & ~static_cast<uint32_t>(kClipGuard);
  if (outside != 0 || !(out.clip[3] > 0.0f)) {
    rp.valid = false;
    return false;
  }
  for (int i = 0; i < 3; ++i)
    rp.win[i] = out.win[i];
  rp.win[3] = out.clip[3];
  rp.valid = true;
  // The associated data are the shader's outputs (§2.13): colours (clamped), texture
  // coordinates and gl_FogFragCoord as the distance.
  for (int c = 0; c < 4; ++c) {
    rp.color[c] = out.attr[kAttrColor + c];
    rp.color2[c] = out.attr[kAttrColor2 + c];
  }
  for (int u = 0; u < kMaxTexUnits; ++u)
    for (int c = 0; c < 4; ++c)
      rp.tex[u][c] = out.attr[kAttrTex0 + 4 * u + c];
  rp.distance = out.attr[kAttrFog];
  return true;
}

void check_program_link(Context* ctx) {
  if (active_program(ctx) != ctx->program_draw->linked.get()) mark_dirty(ctx, kDirtyProgram);
}

void refresh_program(Context* ctx) {
  ProgramDerived& d = *ctx->program_draw;
  const LinkedProgram* lp = d.linked.get();
  if (lp == nullptr) return;
  // The uniform buffer with this context's built-in state.
  d.words.assign(lp->uniforms.begin(), lp->uniforms.end());
  for (const BuiltinSlot& s : lp->builtins)
    write_builtin(*ctx, s, d.words);
  // The views follow the objects (texture_generation), the bindings and unit state (any
  // validation advances raster_serial) and the sampler uniforms.
  const uint64_t generation = ctx->shared->texture_generation;
  const bool same = d.prepared_for == d.linked && d.prepared_words == d.words;
  if (!same || d.sampler_generation != generation || d.sampler_serial != ctx->raster_serial) {
    // The views of the textures bound to the units the samplers name (§2.15.3 samplers).
    ShaderSampler& smp = *d.sampler;
    for (int u = 0; u < kMaxCombinedTextureImageUnits; ++u) {
      smp.unit_bias[u] = ctx->texture.lod_bias[u];
      for (int t = 0; t < 4; ++t)
        smp.complete[u][t] = false;
    }
    for (const glsl::ActiveUniform& un : lp->program->uniforms()) {
      if (!is_sampler_type(un.type)) continue;
      int target = kTex2D;
      GLenum gl_target = GL_TEXTURE_2D;
      switch (un.type) {
      case GL_SAMPLER_1D:
      case GL_SAMPLER_1D_SHADOW:
        target = kTex1D, gl_target = GL_TEXTURE_1D;
        break;
      case GL_SAMPLER_3D:
        target = kTex3D, gl_target = GL_TEXTURE_3D;
        break;
      case GL_SAMPLER_CUBE:
        target = kTexCube, gl_target = GL_TEXTURE_CUBE_MAP;
        break;
      default:
        break;
      }
      for (int e = 0; e < un.size; ++e) {
        const auto unit =
            static_cast<int32_t>(d.words[static_cast<size_t>(un.word + e * un.stride)]);
        if (unit < 0 || unit >= kMaxCombinedTextureImageUnits || smp.complete[unit][target])
          continue;
        smp.complete[unit][target] =
            make_sampler_view(*bound_texture(ctx, unit, gl_target), smp.views[unit][target]);
      }
    }
    d.sampler_generation = generation;
    d.sampler_serial = ctx->raster_serial;
  }
  if (same) return;
  // The runs read the uniforms through the Prepared: they point into prepared_words, which
  // stays as it is until the next preparation.
  d.prepared_words = d.words;
  d.prepared_for = d.linked;
  if (const Executable* vs = lp->program->vertex())
    vs->prepare(d.prepared_words.data(), *d.vs_prepared);
  if (const Executable* fs = lp->program->fragment())
    fs->prepare(d.prepared_words.data(), *d.fs_prepared);
}

} // namespace pineda
