// Lighting parameters (GL 2.1 §2.14.2), ColorMaterial (§2.14.3) and their queries
// (§6.1.3 GetLight, GetMaterial); the lighting area (Tables 6.9-6.11, lighting.h): its
// capabilities, queries, LIGHTING_BIT and the per-draw constants it derives for the geometry
// stage (setup_lighting).
#include <cmath>
#include <limits>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "state/api_util.h"
#include "dispatch.h"
#include "state/area.h"

namespace pineda {

namespace {

// GL 2.1 §2.14.2: integer colour parameters convert as signed integers in Table 2.9.
inline float int_color(GLint c) {
  return static_cast<float>((2.0 * c + 1.0) / 4294967295.0);
}

// GL 2.1 §6.1.2: colours read back as integers map [-1,1] linearly onto the integer range
// (the same mapping glGetIntegerv uses in get.cpp).
GLint color_to_int(float c) {
  const double scaled = static_cast<double>(c) * 2147483647.0;
  if (scaled >= 2147483647.0) return std::numeric_limits<GLint>::max();
  if (scaled <= -2147483648.0) return std::numeric_limits<GLint>::min();
  return static_cast<GLint>(std::llround(scaled));
}

// Other values read back as integers are rounded to the nearest integer (§6.1.2).
GLint float_to_int(float v) {
  if (!(v == v)) return 0;
  if (v >= 2147483647.0f) return std::numeric_limits<GLint>::max();
  if (v <= -2147483648.0f) return std::numeric_limits<GLint>::min();
  return static_cast<GLint>(std::lround(v));
}

// The number of values of a Light parameter (Table 2.11), 0 for an unknown pname.
int light_param_count(GLenum pname) {
  switch (pname) {
  case GL_AMBIENT:
  case GL_DIFFUSE:
  case GL_SPECULAR:
  case GL_POSITION:
    return 4;
  case GL_SPOT_DIRECTION:
    return 3;
  case GL_SPOT_EXPONENT:
  case GL_SPOT_CUTOFF:
  case GL_CONSTANT_ATTENUATION:
  case GL_LINEAR_ATTENUATION:
  case GL_QUADRATIC_ATTENUATION:
    return 1;
  default:
    return 0;
  }
}

bool is_light_color(GLenum pname) {
  return pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR;
}

int material_param_count(GLenum pname) {
  switch (pname) {
  case GL_AMBIENT:
  case GL_DIFFUSE:
  case GL_SPECULAR:
  case GL_EMISSION:
  case GL_AMBIENT_AND_DIFFUSE:
    return 4;
  case GL_COLOR_INDEXES:
    return 3;
  case GL_SHININESS:
    return 1;
  default:
    return 0;
  }
}

bool is_material_color(GLenum pname) {
  return pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR ||
         pname == GL_EMISSION || pname == GL_AMBIENT_AND_DIFFUSE;
}

// Which faces a ColorMaterial / Material face argument names: bit 0 front, bit 1 back.
int face_mask(GLenum face) {
  switch (face) {
  case GL_FRONT:
    return 1;
  case GL_BACK:
    return 2;
  case GL_FRONT_AND_BACK:
    return 3;
  default:
    return 0;
  }
}

bool valid_color_material_mode(GLenum mode) {
  return mode == GL_EMISSION || mode == GL_AMBIENT || mode == GL_DIFFUSE || mode == GL_SPECULAR ||
         mode == GL_AMBIENT_AND_DIFFUSE;
}

// Whether material property `pname` currently tracks the colour on the faces in `faces`
// (GL 2.1 §2.14.3), as a face mask.
int tracked_faces(const LightingGroup& ls, GLenum pname) {
  if (!ls.color_material) return 0;
  const GLenum mode = ls.color_material_mode;
  const bool tracked = mode == pname || (mode == GL_AMBIENT_AND_DIFFUSE &&
                                         (pname == GL_AMBIENT || pname == GL_DIFFUSE));
  return tracked ? face_mask(ls.color_material_face) : 0;
}

void copy4(float* dst, const float* src) {
  for (int i = 0; i < 4; ++i)
    dst[i] = src[i];
}

// Store one material parameter into the faces of `faces` (already validated).
void store_material(LightingGroup& ls, int faces, GLenum pname, const float* v) {
  for (int f = 0; f < 2; ++f) {
    if (!(faces & (1 << f))) continue;
    Material& m = ls.material[f];
    // GL 2.1 §2.14.3: while COLOR_MATERIAL is enabled the tracked properties always follow
    // the current colour, so a Material call does not override them.
    const int tracked_amb = tracked_faces(ls, GL_AMBIENT) & (1 << f);
    const int tracked_dif = tracked_faces(ls, GL_DIFFUSE) & (1 << f);
    switch (pname) {
    case GL_AMBIENT:
      if (!tracked_amb) copy4(m.ambient, v);
      break;
    case GL_DIFFUSE:
      if (!tracked_dif) copy4(m.diffuse, v);
      break;
    case GL_AMBIENT_AND_DIFFUSE:
      if (!tracked_amb) copy4(m.ambient, v);
      if (!tracked_dif) copy4(m.diffuse, v);
      break;
    case GL_SPECULAR:
      if (!(tracked_faces(ls, GL_SPECULAR) & (1 << f))) copy4(m.specular, v);
      break;
    case GL_EMISSION:
      if (!(tracked_faces(ls, GL_EMISSION) & (1 << f))) copy4(m.emission, v);
      break;
    case GL_SHININESS:
      m.shininess = v[0];
      break;
    default:
      for (int i = 0; i < 3; ++i)
        m.color_indexes[i] = v[i];
      break;
    }
  }
}

// Common body of glLight*: `v` holds the parameter's values already converted to float.
void set_light(Context* ctx, const char* func, GLenum light, GLenum pname, const float* v) {
  if (light < GL_LIGHT0 || light >= GL_LIGHT0 + kMaxLights) {
    record_error(ctx, GL_INVALID_ENUM, func, light);
    return;
  }
  Light& l = ctx->lighting.light[light - GL_LIGHT0];
  // GL 2.1 Table 2.10: the allowed ranges; INVALID_VALUE outside them (§2.14.2). The tests
  // are written so that NaN fails them.
  switch (pname) {
  case GL_AMBIENT:
    copy4(l.ambient, v);
    break;
  case GL_DIFFUSE:
    copy4(l.diffuse, v);
    break;
  case GL_SPECULAR:
    copy4(l.specular, v);
    break;
  case GL_POSITION: {
    // §2.14.2: the position is transformed by the model-view matrix when it is specified.
    const glm::vec4 p = ctx->modelview.top() * glm::vec4(v[0], v[1], v[2], v[3]);
    for (int i = 0; i < 4; ++i)
      l.position[i] = p[i];
    break;
  }
  case GL_SPOT_DIRECTION: {
    // §2.14.2: the spot direction is transformed by the upper left 3x3 only.
    const glm::vec3 d = glm::mat3(ctx->modelview.top()) * glm::vec3(v[0], v[1], v[2]);
    for (int i = 0; i < 3; ++i)
      l.spot_direction[i] = d[i];
    break;
  }
  case GL_SPOT_EXPONENT:
    if (!(v[0] >= 0.0f && v[0] <= 128.0f)) return record_error(ctx, GL_INVALID_VALUE, func);
    l.spot_exponent = v[0];
    break;
  case GL_SPOT_CUTOFF:
    if (!((v[0] >= 0.0f && v[0] <= 90.0f) || v[0] == 180.0f))
      return record_error(ctx, GL_INVALID_VALUE, func);
    l.spot_cutoff = v[0];
    break;
  case GL_CONSTANT_ATTENUATION:
  case GL_LINEAR_ATTENUATION:
  case GL_QUADRATIC_ATTENUATION:
    if (!(v[0] >= 0.0f)) return record_error(ctx, GL_INVALID_VALUE, func);
    l.attenuation[pname - GL_CONSTANT_ATTENUATION] = v[0];
    break;
  default:
    return record_error(ctx, GL_INVALID_ENUM, func, pname);
  }
  mark_dirty(ctx, kDirtyLighting);
}

void light_scalar(const char* func, GLenum light, GLenum pname, float value) {
  PINEDA_CTX_OUTSIDE(func);
  // §2.14.2: the non-vector form with a multi-valued parameter is INVALID_ENUM.
  if (light_param_count(pname) != 1 && light >= GL_LIGHT0 && light < GL_LIGHT0 + kMaxLights)
    return record_error(ctx, GL_INVALID_ENUM, func, pname);
  set_light(ctx, func, light, pname, &value);
}

void set_material(Context* ctx, const char* func, GLenum face, GLenum pname, const float* v) {
  const int faces = face_mask(face);
  if (faces == 0) return record_error(ctx, GL_INVALID_ENUM, func, face);
  if (material_param_count(pname) == 0) return record_error(ctx, GL_INVALID_ENUM, func, pname);
  if (pname == GL_SHININESS && !(v[0] >= 0.0f && v[0] <= 128.0f))
    return record_error(ctx, GL_INVALID_VALUE, func);
  LightingGroup& ls = ctx->lighting;
  if (ctx->imm.mode != kOutsideBeginEnd) {
    // §2.14.2: Material is legal between Begin and End and applies to the vertices that
    // follow; remember where in the primitive the material changed.
    BeginEndState& imm = ctx->imm;
    if (imm.material_changes.empty()) {
      imm.begin_material[0] = ls.material[0];
      imm.begin_material[1] = ls.material[1];
    }
    store_material(ls, faces, pname, v);
    MaterialChange& c = imm.material_changes.emplace_back();
    c.vertex = ctx->imm.verts.size();
    c.material[0] = ls.material[0];
    c.material[1] = ls.material[1];
  } else {
    store_material(ls, faces, pname, v);
  }
  mark_dirty(ctx, kDirtyLighting);
}

void material_scalar(const char* func, GLenum face, GLenum pname, float value) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  if (material_param_count(pname) != 1 && face_mask(face) != 0)
    return record_error(ctx, GL_INVALID_ENUM, func, pname);
  set_material(ctx, func, face, pname, &value);
}

void set_light_model(Context* ctx, const char* func, GLenum pname, const float* v) {
  LightingGroup& ls = ctx->lighting;
  switch (pname) {
  case GL_LIGHT_MODEL_AMBIENT:
    copy4(ls.model_ambient, v);
    break;
  case GL_LIGHT_MODEL_LOCAL_VIEWER:
    ls.local_viewer = v[0] != 0.0f;
    break;
  case GL_LIGHT_MODEL_TWO_SIDE:
    ls.two_side = v[0] != 0.0f;
    break;
  case GL_LIGHT_MODEL_COLOR_CONTROL: {
    // Compared as floats: converting a float outside GLenum's range (or NaN) to GLenum is
    // undefined behaviour.
    GLenum mode = 0;
    if (v[0] == static_cast<float>(GL_SINGLE_COLOR)) mode = GL_SINGLE_COLOR;
    if (v[0] == static_cast<float>(GL_SEPARATE_SPECULAR_COLOR)) mode = GL_SEPARATE_SPECULAR_COLOR;
    if (mode == 0) return record_error(ctx, GL_INVALID_ENUM, func, pname);
    ls.color_control = mode;
    break;
  }
  default:
    return record_error(ctx, GL_INVALID_ENUM, func, pname);
  }
  mark_dirty(ctx, kDirtyLighting);
}

void light_model_scalar(const char* func, GLenum pname, float value) {
  PINEDA_CTX_OUTSIDE(func);
  if (pname == GL_LIGHT_MODEL_AMBIENT) return record_error(ctx, GL_INVALID_ENUM, func, pname);
  set_light_model(ctx, func, pname, &value);
}

// Values of a GetLight query; false for an unknown light or pname (recorded).
bool get_light(Context* ctx, const char* func, GLenum light, GLenum pname, float* out, int* n) {
  if (light < GL_LIGHT0 || light >= GL_LIGHT0 + kMaxLights) {
    record_error(ctx, GL_INVALID_ENUM, func, light);
    return false;
  }
  const Light& l = ctx->lighting.light[light - GL_LIGHT0];
  *n = light_param_count(pname);
  switch (pname) {
  case GL_AMBIENT:
    copy4(out, l.ambient);
    return true;
  case GL_DIFFUSE:
    copy4(out, l.diffuse);
    return true;
  case GL_SPECULAR:
    copy4(out, l.specular);
    return true;
  case GL_POSITION:
    copy4(out, l.position);
    return true;
  case GL_SPOT_DIRECTION:
    for (int i = 0; i < 3; ++i)
      out[i] = l.spot_direction[i];
    return true;
  case GL_SPOT_EXPONENT:
    out[0] = l.spot_exponent;
    return true;
  case GL_SPOT_CUTOFF:
    out[0] = l.spot_cutoff;
    return true;
  case GL_CONSTANT_ATTENUATION:
  case GL_LINEAR_ATTENUATION:
  case GL_QUADRATIC_ATTENUATION:
    out[0] = l.attenuation[pname - GL_CONSTANT_ATTENUATION];
    return true;
  default:
    record_error(ctx, GL_INVALID_ENUM, func, pname);
    return false;
  }
}

// GL 2.1 §6.1.3: GetMaterial takes FRONT or BACK, and AMBIENT_AND_DIFFUSE is not a query.
bool get_material(Context* ctx, const char* func, GLenum face, GLenum pname, float* out, int* n) {
  if (face != GL_FRONT && face != GL_BACK) {
    record_error(ctx, GL_INVALID_ENUM, func, face);
    return false;
  }
  const Material& m = ctx->lighting.material[face == GL_FRONT ? 0 : 1];
  *n = material_param_count(pname);
  switch (pname) {
  case GL_AMBIENT:
    copy4(out, m.ambient);
    return true;
  case GL_DIFFUSE:
    copy4(out, m.diffuse);
    return true;
  case GL_SPECULAR:
    copy4(out, m.specular);
    return true;
  case GL_EMISSION:
    copy4(out, m.emission);
    return true;
  case GL_SHININESS:
    out[0] = m.shininess;
    return true;
  case GL_COLOR_INDEXES:
    for (int i = 0; i < 3; ++i)
      out[i] = m.color_indexes[i];
    return true;
  default:
    record_error(ctx, GL_INVALID_ENUM, func, pname);
    return false;
  }
}

bool get_lighting(Context& ctx, GLenum pname, QueryValues& out) {
  const LightingGroup& ls = ctx.lighting;
  switch (pname) {
  // Lights and materials are read with GetLight / GetMaterial.
  case GL_COLOR_MATERIAL_FACE:
    out.ints({double(ls.color_material_face)});
    return true;
  case GL_COLOR_MATERIAL_PARAMETER:
    out.ints({double(ls.color_material_mode)});
    return true;
  case GL_LIGHT_MODEL_AMBIENT:
    out.normalized(ls.model_ambient, 4);
    return true;
  case GL_LIGHT_MODEL_LOCAL_VIEWER:
    out.boolean(ls.local_viewer);
    return true;
  case GL_LIGHT_MODEL_TWO_SIDE:
    out.boolean(ls.two_side);
    return true;
  case GL_LIGHT_MODEL_COLOR_CONTROL:
    out.ints({double(ls.color_control)});
    return true;
  case GL_SHADE_MODEL:
    out.ints({double(ls.shade_model)});
    return true;
  case GL_MAX_LIGHTS:
    out.ints({kMaxLights});
    return true;
  default:
    return false;
  }
}

// GL 2.1 §2.14.1: light positions are already in eye space; the normal matrix and the
// per-light constants depend on the model-view matrix.
void derive_lighting(Context& ctx, uint32_t) {
  if (ctx.lighting.enabled)
    setup_lighting(ctx.light_setup, ctx.lighting, ctx.modelview.top(), ctx.transform.normalize,
                   ctx.transform.rescale_normal);
}

// GL 2.1 §2.14.3: while COLOR_MATERIAL is enabled the tracked material properties follow the
// current colour, whichever of the two was restored.
uint32_t lighting_restored(Context& ctx, GLbitfield mask) {
  if ((mask & (GL_CURRENT_BIT | GL_LIGHTING_BIT | GL_ENABLE_BIT)) == 0 ||
      !ctx.lighting.color_material)
    return 0;
  update_color_material(&ctx);
  return kDirtyLighting;
}

constexpr Capability kLightingCaps[] = {
    // §2.14.1, §2.14.3.
    {GL_LIGHTING, 1, CapabilityKind::kServer, kDirtyLighting,
     [](Context& c, unsigned, unsigned) { return &c.lighting.enabled; }},
    {GL_LIGHT0, kMaxLights, CapabilityKind::kServer, kDirtyLighting,
     [](Context& c, unsigned i, unsigned) { return &c.lighting.light[i].enabled; }},
    // Enabling COLOR_MATERIAL makes the tracked properties take the current colour at once.
    {GL_COLOR_MATERIAL, 1, CapabilityKind::kServer, kDirtyLighting,
     [](Context& c, unsigned, unsigned) { return &c.lighting.color_material; },
     [](Context& c, bool value) {
       if (value) update_color_material(&c);
     }},
};

constexpr AttribGroup kLightingGroups[] = {
    member_group<&Context::lighting>(GL_LIGHTING_BIT, kDirtyLighting | kDirtyPolygon),
};

} // namespace

void update_color_material(Context* ctx) {
  LightingGroup& ls = ctx->lighting;
  if (!ls.color_material) return;
  const int faces = face_mask(ls.color_material_face);
  for (int f = 0; f < 2; ++f) {
    if (!(faces & (1 << f))) continue;
    Material& m = ls.material[f];
    switch (ls.color_material_mode) {
    case GL_AMBIENT:
      copy4(m.ambient, ctx->current.color);
      break;
    case GL_DIFFUSE:
      copy4(m.diffuse, ctx->current.color);
      break;
    case GL_SPECULAR:
      copy4(m.specular, ctx->current.color);
      break;
    case GL_EMISSION:
      copy4(m.emission, ctx->current.color);
      break;
    default:
      copy4(m.ambient, ctx->current.color);
      copy4(m.diffuse, ctx->current.color);
      break;
    }
  }
}

void setup_lighting(LightSetup& s, const LightingGroup& ls, const glm::mat4& modelview,
                    bool normalize, bool rescale) {
  s.count = 0;
  s.local_viewer = ls.local_viewer;
  s.two_side = ls.two_side;
  s.separate_specular = ls.color_control == GL_SEPARATE_SPECULAR_COLOR;
  s.need_eye_position = ls.local_viewer;
  for (int c = 0; c < 4; ++c)
    s.scene_ambient[c] = ls.model_ambient[c];
  for (int i = 0; i < kMaxLights; ++i) {
    const Light& src = ls.light[i];
    if (!src.enabled) continue;
    LightConstants& l = s.light[s.count++];
    for (int c = 0; c < 3; ++c) {
      l.ambient[c] = src.ambient[c];
      l.diffuse[c] = src.diffuse[c];
      l.specular[c] = src.specular[c];
    }
    const float w = src.position[3];
    l.positional = w != 0.0f;
    if (l.positional) {
      // The vector from a vertex to the light is between two points (§2.14.1), so the
      // homogeneous position is projected first.
      for (int c = 0; c < 3; ++c)
        l.position[c] = src.position[c] / w;
      s.need_eye_position = true;
    } else {
      for (int c = 0; c < 3; ++c)
        l.direction[c] = src.position[c];
      light_normalize3(l.direction);
      // Eq. 2.3 with an infinite viewer: h = VPpli + (0, 0, 1), the same for every vertex.
      l.half[0] = l.direction[0];
      l.half[1] = l.direction[1];
      l.half[2] = l.direction[2] + 1.0f;
      light_normalize3(l.half);
    }
    l.spot = src.spot_cutoff != 180.0f;
    for (int c = 0; c < 3; ++c)
      l.spot_direction[c] = src.spot_direction[c];
    light_normalize3(l.spot_direction);
    l.spot_cos = static_cast<float>(std::cos(src.spot_cutoff * (3.14159265358979323846 / 180.0)));
    l.spot_exponent = src.spot_exponent;
    l.spot_factor = 1.0f;
    if (l.spot && !l.positional) {
      // Eq. 2.5 for a light at infinity: PpliV is -VPpli for every vertex.
      const float d = -light_dot3(l.direction, l.spot_direction);
      l.spot_factor = d >= l.spot_cos ? std::pow(d, l.spot_exponent) : 0.0f;
    }
    // Eq. 2.4: attenuation applies to positional lights only.
    for (int c = 0; c < 3; ++c)
      l.k[c] = src.attenuation[c];
    l.attenuated = l.positional && (l.k[0] != 1.0f || l.k[1] != 0.0f || l.k[2] != 0.0f);
  }

  // COLOR_MATERIAL (§2.14.3).
  const GLenum mode = ls.color_material_mode;
  const GLenum face = ls.color_material_face;
  s.track[0] = ls.color_material && face != GL_BACK;
  s.track[1] = ls.color_material && face != GL_FRONT;
  s.track_ambient = mode == GL_AMBIENT || mode == GL_AMBIENT_AND_DIFFUSE;
  s.track_diffuse = mode == GL_DIFFUSE || mode == GL_AMBIENT_AND_DIFFUSE;
  s.track_specular = mode == GL_SPECULAR;
  s.track_emission = mode == GL_EMISSION;

  // §2.11.3: normals go to eye space by the inverse of the model-view's upper left 3x3
  // (multiplying the row vector from the left); as a column-vector product that is the
  // inverse transpose. Rescale multiplies by 1 / |third row of the inverse|; NORMALIZE makes
  // every normal unit length after the transformation and takes precedence.
  const glm::dmat3 inv = glm::inverse(glm::dmat3(glm::dmat4(modelview)));
  const glm::dmat3 nm = glm::transpose(inv);
  double f = 1.0;
  if (rescale && !normalize) {
    const double len2 = inv[0][2] * inv[0][2] + inv[1][2] * inv[1][2] + inv[2][2] * inv[2][2];
    if (len2 > 0.0) f = 1.0 / std::sqrt(len2);
  }
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row)
      s.normal_matrix[col * 3 + row] = static_cast<float>(nm[col][row] * f);
  s.normalize = normalize;
  const float* mv = &modelview[0][0];
  for (int i = 0; i < 16; ++i)
    s.modelview[i] = mv[i];
}

const StateArea kLightingArea = {
    .name = "lighting (GL 2.1 §2.14, Tables 6.9-6.11)",
    .capabilities = kLightingCaps,
    .get = get_lighting,
    .groups = kLightingGroups,
    .restored = lighting_restored,
    .derive_on = kDirtyLighting | kDirtyTransform,
    .derive = derive_lighting,
};

namespace exec {

void GLAPIENTRY Lightf(GLenum light, GLenum pname, GLfloat param) {
  light_scalar("glLightf", light, pname, param);
}
void GLAPIENTRY Lighti(GLenum light, GLenum pname, GLint param) {
  light_scalar("glLighti", light, pname, static_cast<float>(param));
}
void GLAPIENTRY Lightfv(GLenum light, GLenum pname, const GLfloat* params) {
  PINEDA_CTX_OUTSIDE("glLightfv");
  if (params == nullptr) return;
  set_light(ctx, "glLightfv", light, pname, params);
}
void GLAPIENTRY Lightiv(GLenum light, GLenum pname, const GLint* params) {
  PINEDA_CTX_OUTSIDE("glLightiv");
  if (params == nullptr) return;
  float v[4] = {0, 0, 0, 0};
  const int n = light_param_count(pname);
  for (int i = 0; i < n; ++i)
    v[i] = is_light_color(pname) ? int_color(params[i]) : static_cast<float>(params[i]);
  set_light(ctx, "glLightiv", light, pname, v);
}

void GLAPIENTRY Materialf(GLenum face, GLenum pname, GLfloat param) {
  material_scalar("glMaterialf", face, pname, param);
}
void GLAPIENTRY Materiali(GLenum face, GLenum pname, GLint param) {
  material_scalar("glMateriali", face, pname, static_cast<float>(param));
}
void GLAPIENTRY Materialfv(GLenum face, GLenum pname, const GLfloat* params) {
  Context* ctx = current_context();
  if (ctx == nullptr || params == nullptr) return;
  set_material(ctx, "glMaterialfv", face, pname, params);
}
void GLAPIENTRY Materialiv(GLenum face, GLenum pname, const GLint* params) {
  Context* ctx = current_context();
  if (ctx == nullptr || params == nullptr) return;
  float v[4] = {0, 0, 0, 0};
  const int n = material_param_count(pname);
  for (int i = 0; i < n; ++i)
    v[i] = is_material_color(pname) ? int_color(params[i]) : static_cast<float>(params[i]);
  set_material(ctx, "glMaterialiv", face, pname, v);
}

void GLAPIENTRY LightModelf(GLenum pname, GLfloat param) {
  light_model_scalar("glLightModelf", pname, param);
}
void GLAPIENTRY LightModeli(GLenum pname, GLint param) {
  light_model_scalar("glLightModeli", pname, static_cast<float>(param));
}
void GLAPIENTRY LightModelfv(GLenum pname, const GLfloat* params) {
  PINEDA_CTX_OUTSIDE("glLightModelfv");
  if (params == nullptr) return;
  set_light_model(ctx, "glLightModelfv", pname, params);
}
void GLAPIENTRY LightModeliv(GLenum pname, const GLint* params) {
  PINEDA_CTX_OUTSIDE("glLightModeliv");
  if (params == nullptr) return;
  float v[4] = {static_cast<float>(params[0]), 0, 0, 0};
  if (pname == GL_LIGHT_MODEL_AMBIENT)
    for (int i = 0; i < 4; ++i)
      v[i] = int_color(params[i]);
  set_light_model(ctx, "glLightModeliv", pname, v);
}

void GLAPIENTRY ColorMaterial(GLenum face, GLenum mode) {
  PINEDA_CTX_OUTSIDE("glColorMaterial");
  if (face_mask(face) == 0) return record_error(ctx, GL_INVALID_ENUM, "glColorMaterial", face);
  if (!valid_color_material_mode(mode))
    return record_error(ctx, GL_INVALID_ENUM, "glColorMaterial", mode);
  LightingGroup& ls = ctx->lighting;
  ls.color_material_face = face;
  ls.color_material_mode = mode;
  // §2.14.3: with COLOR_MATERIAL enabled the newly selected properties take the current
  // colour at once.
  update_color_material(ctx);
  mark_dirty(ctx, kDirtyLighting);
}

void GLAPIENTRY GetLightfv(GLenum light, GLenum pname, GLfloat* params) {
  PINEDA_CTX_OUTSIDE("glGetLightfv");
  float v[4];
  int n = 0;
  if (!get_light(ctx, "glGetLightfv", light, pname, v, &n) || params == nullptr) return;
  for (int i = 0; i < n; ++i)
    params[i] = v[i];
}
void GLAPIENTRY GetLightiv(GLenum light, GLenum pname, GLint* params) {
  PINEDA_CTX_OUTSIDE("glGetLightiv");
  float v[4];
  int n = 0;
  if (!get_light(ctx, "glGetLightiv", light, pname, v, &n) || params == nullptr) return;
  for (int i = 0; i < n; ++i)
    params[i] = is_light_color(pname) ? color_to_int(v[i]) : float_to_int(v[i]);
}

void GLAPIENTRY GetMaterialfv(GLenum face, GLenum pname, GLfloat* params) {
  PINEDA_CTX_OUTSIDE("glGetMaterialfv");
  float v[4];
  int n = 0;
  if (!get_material(ctx, "glGetMaterialfv", face, pname, v, &n) || params == nullptr) return;
  for (int i = 0; i < n; ++i)
    params[i] = v[i];
}
void GLAPIENTRY GetMaterialiv(GLenum face, GLenum pname, GLint* params) {
  PINEDA_CTX_OUTSIDE("glGetMaterialiv");
  float v[4];
  int n = 0;
  if (!get_material(ctx, "glGetMaterialiv", face, pname, v, &n) || params == nullptr) return;
  for (int i = 0; i < n; ++i)
    params[i] = is_material_color(pname) ? color_to_int(v[i]) : float_to_int(v[i]);
}

} // namespace exec
} // namespace pineda
