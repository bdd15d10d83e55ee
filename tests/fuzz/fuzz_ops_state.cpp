// Harness operations on the GL 1.5 state and commands other than geometry and pixels: texture
// objects and environment, display lists (§5.4), selection and feedback (§5.2, §5.3),
// evaluators (§5.1), lighting, fog, the fragment operations, attribute stacks, occlusion
// queries, raster positions and the typed queries whose result sizes depend on the pname.
#include "fuzz_harness.h"

namespace pineda::fuzz {
namespace {

constexpr GLenum kTexTargets[] = {GL_TEXTURE_1D,
                                  GL_TEXTURE_2D,
                                  GL_TEXTURE_3D,
                                  GL_TEXTURE_CUBE_MAP,
                                  GL_TEXTURE_CUBE_MAP_POSITIVE_X,
                                  GL_PROXY_TEXTURE_2D,
                                  0};

constexpr GLenum kTexParams[] = {GL_TEXTURE_MIN_FILTER,
                                 GL_TEXTURE_MAG_FILTER,
                                 GL_TEXTURE_WRAP_S,
                                 GL_TEXTURE_WRAP_T,
                                 GL_TEXTURE_WRAP_R,
                                 GL_TEXTURE_BORDER_COLOR,
                                 GL_TEXTURE_PRIORITY,
                                 GL_TEXTURE_RESIDENT,
                                 GL_TEXTURE_MIN_LOD,
                                 GL_TEXTURE_MAX_LOD,
                                 GL_TEXTURE_BASE_LEVEL,
                                 GL_TEXTURE_MAX_LEVEL,
                                 GL_TEXTURE_LOD_BIAS,
                                 GL_DEPTH_TEXTURE_MODE,
                                 GL_TEXTURE_COMPARE_MODE,
                                 GL_TEXTURE_COMPARE_FUNC,
                                 GL_GENERATE_MIPMAP,
                                 GL_TEXTURE_MAX_ANISOTROPY_EXT,
                                 0};

constexpr GLenum kTexValues[] = {GL_NEAREST,
                                 GL_LINEAR,
                                 GL_NEAREST_MIPMAP_NEAREST,
                                 GL_LINEAR_MIPMAP_NEAREST,
                                 GL_NEAREST_MIPMAP_LINEAR,
                                 GL_LINEAR_MIPMAP_LINEAR,
                                 GL_CLAMP,
                                 GL_REPEAT,
                                 GL_CLAMP_TO_EDGE,
                                 GL_CLAMP_TO_BORDER,
                                 GL_MIRRORED_REPEAT,
                                 GL_LUMINANCE,
                                 GL_INTENSITY,
                                 GL_ALPHA,
                                 GL_COMPARE_R_TO_TEXTURE,
                                 GL_NONE,
                                 GL_LEQUAL,
                                 GL_GEQUAL,
                                 GL_NEVER,
                                 GL_TRUE,
                                 0};

constexpr GLenum kEnvTargets[] = {GL_TEXTURE_ENV, GL_TEXTURE_FILTER_CONTROL, GL_POINT_SPRITE, 0};

constexpr GLenum kEnvParams[] = {GL_TEXTURE_ENV_MODE, GL_TEXTURE_ENV_COLOR, GL_COMBINE_RGB,
                                 GL_COMBINE_ALPHA,    GL_SOURCE0_RGB,       GL_SOURCE1_RGB,
                                 GL_SOURCE2_RGB,      GL_SOURCE0_ALPHA,     GL_SOURCE2_ALPHA,
                                 GL_OPERAND0_RGB,     GL_OPERAND2_RGB,      GL_OPERAND0_ALPHA,
                                 GL_OPERAND1_ALPHA,   GL_RGB_SCALE,         GL_ALPHA_SCALE,
                                 GL_TEXTURE_LOD_BIAS, GL_COORD_REPLACE,     0};

constexpr GLenum kEnvValues[] = {GL_MODULATE,
                                 GL_DECAL,
                                 GL_BLEND,
                                 GL_REPLACE,
                                 GL_ADD,
                                 GL_COMBINE,
                                 GL_ADD_SIGNED,
                                 GL_INTERPOLATE,
                                 GL_SUBTRACT,
                                 GL_DOT3_RGB,
                                 GL_DOT3_RGBA,
                                 GL_TEXTURE,
                                 GL_CONSTANT,
                                 GL_PRIMARY_COLOR,
                                 GL_PREVIOUS,
                                 GL_TEXTURE0,
                                 GL_TEXTURE3,
                                 GL_TEXTURE4,
                                 GL_SRC_COLOR,
                                 GL_ONE_MINUS_SRC_COLOR,
                                 GL_SRC_ALPHA,
                                 GL_ONE_MINUS_SRC_ALPHA,
                                 0};

constexpr GLenum kCoords[] = {GL_S, GL_T, GL_R, GL_Q, 0};
constexpr GLenum kGenParams[] = {GL_TEXTURE_GEN_MODE, GL_OBJECT_PLANE, GL_EYE_PLANE, 0};
constexpr GLenum kGenModes[] = {GL_OBJECT_LINEAR, GL_EYE_LINEAR,     GL_SPHERE_MAP,
                                GL_NORMAL_MAP,    GL_REFLECTION_MAP, 0};

constexpr GLenum kUnits[] = {GL_TEXTURE0, GL_TEXTURE1,      GL_TEXTURE2,     GL_TEXTURE3,
                             GL_TEXTURE4, GL_TEXTURE0 + 31, GL_TEXTURE0 - 1, 0};

constexpr GLenum kListModes[] = {GL_COMPILE, GL_COMPILE_AND_EXECUTE, 0};
constexpr GLenum kListTypes[] = {GL_BYTE,    GL_UNSIGNED_BYTE, GL_SHORT,  GL_UNSIGNED_SHORT,
                                 GL_INT,     GL_UNSIGNED_INT,  GL_FLOAT,  GL_2_BYTES,
                                 GL_3_BYTES, GL_4_BYTES,       GL_DOUBLE, 0};

constexpr GLenum kRenderModes[] = {GL_RENDER, GL_SELECT, GL_FEEDBACK, 0};
constexpr GLenum kFeedbackTypes[] = {
    GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE, 0};

constexpr GLenum kMap1[] = {GL_MAP1_VERTEX_3,
                            GL_MAP1_VERTEX_4,
                            GL_MAP1_INDEX,
                            GL_MAP1_COLOR_4,
                            GL_MAP1_NORMAL,
                            GL_MAP1_TEXTURE_COORD_1,
                            GL_MAP1_TEXTURE_COORD_2,
                            GL_MAP1_TEXTURE_COORD_3,
                            GL_MAP1_TEXTURE_COORD_4,
                            GL_MAP2_VERTEX_3,
                            0};
constexpr GLenum kMap2[] = {GL_MAP2_VERTEX_3,
                            GL_MAP2_VERTEX_4,
                            GL_MAP2_INDEX,
                            GL_MAP2_COLOR_4,
                            GL_MAP2_NORMAL,
                            GL_MAP2_TEXTURE_COORD_1,
                            GL_MAP2_TEXTURE_COORD_2,
                            GL_MAP2_TEXTURE_COORD_3,
                            GL_MAP2_TEXTURE_COORD_4,
                            GL_MAP1_VERTEX_4,
                            0};
constexpr GLenum kMapQueries[] = {GL_COEFF, GL_ORDER, GL_DOMAIN, 0};

// Values GL reads or writes through the vector forms, per pname (Tables 6.x).
int64_t tex_param_count(GLenum p) {
  return p == GL_TEXTURE_BORDER_COLOR ? 4 : 1;
}
int64_t env_count(GLenum p) {
  return p == GL_TEXTURE_ENV_COLOR ? 4 : 1;
}
int64_t gen_count(GLenum p) {
  return p == GL_OBJECT_PLANE || p == GL_EYE_PLANE ? 4 : 1;
}

} // namespace

void op_texture_state(Harness& h, Input& in) {
  switch (in.u8() % 20) {
  case 0: {
    const GLsizei n = name_count(in);
    Block names(h, n > 0 ? n * 4 : 0);
    glGenTextures(n, names.as<GLuint>());
    break;
  }
  case 1: {
    const GLsizei n = name_count(in);
    Names names(h, in, n);
    glDeleteTextures(n, names.get());
    break;
  }
  case 2:
  case 3: {
    const GLenum t = in.e(kTexTargets);
    glBindTexture(t, name(in));
    break;
  }
  case 4:
    glIsTexture(name(in));
    break;
  case 5: {
    const GLsizei n = name_count(in);
    Names names(h, in, n);
    Floats prio(h, in, n > 0 ? n : 0);
    glPrioritizeTextures(n, names.get(), prio.get());
    break;
  }
  case 6: {
    const GLsizei n = name_count(in);
    Names names(h, in, n);
    Block res(h, n > 0 ? n : 0);
    glAreTexturesResident(n, names.get(), res.as<GLboolean>());
    break;
  }
  case 7:
  case 8:
  case 9:
  case 10:
  case 11: {
    static constexpr ParamFamily kTexParameter = {glTexParameterf,     glTexParameteri,
                                                  glTexParameterfv,    glTexParameteriv,
                                                  glGetTexParameterfv, glGetTexParameteriv};
    const GLenum t = in.e(kTexTargets), p = in.e(kTexParams);
    const auto value = static_cast<GLint>(in.e(kTexValues));
    call_param(h, in, kTexParameter, t, p, tex_param_count(p), value);
    break;
  }
  case 12:
  case 13: {
    static constexpr ParamFamily kTexEnv = {glTexEnvf,  glTexEnvi,     glTexEnvfv,
                                            glTexEnviv, glGetTexEnvfv, glGetTexEnviv};
    const GLenum t = in.e(kEnvTargets), p = in.e(kEnvParams);
    const auto value = static_cast<GLint>(in.e(kEnvValues));
    call_param(h, in, kTexEnv, t, p, env_count(p), value);
    break;
  }
  case 14: {
    const GLenum c = in.e(kCoords), p = in.e(kGenParams);
    switch (in.u8() % 7) {
    case 0:
      glTexGeni(c, p, static_cast<GLint>(in.e(kGenModes)));
      break;
    case 1:
      glTexGenf(c, p, in.f());
      break;
    case 2:
      glTexGend(c, p, in.d());
      break;
    case 3: {
      Floats v(h, in, gen_count(p));
      glTexGenfv(c, p, v.get());
      break;
    }
    case 4: {
      Ints v(h, in, gen_count(p));
      glTexGeniv(c, p, v.get());
      break;
    }
    case 5: {
      Block v(h, gen_count(p) * 8);
      for (int64_t k = 0; k < gen_count(p); ++k)
        v.as<GLdouble>()[k] = in.d();
      glTexGendv(c, p, v.as<GLdouble>());
      break;
    }
    default: {
      Block v(h, gen_count(p) * 8);
      switch (in.u8() % 3) {
      case 0:
        glGetTexGeniv(c, p, v.as<GLint>());
        break;
      case 1:
        glGetTexGenfv(c, p, v.as<GLfloat>());
        break;
      default:
        glGetTexGendv(c, p, v.as<GLdouble>());
        break;
      }
      break;
    }
    }
    break;
  }
  case 15:
    glActiveTexture(in.e(kUnits));
    break;
  case 16:
    glClientActiveTexture(in.e(kUnits));
    break;
  case 17: {
    const GLenum u = in.e(kUnits);
    switch (in.u8() % 6) {
    case 0:
      glMultiTexCoord1f(u, in.f());
      break;
    case 1:
      glMultiTexCoord2f(u, in.f(), in.f());
      break;
    case 2:
      glMultiTexCoord3d(u, in.d(), in.d(), in.d());
      break;
    case 3:
      glMultiTexCoord4i(u, in.i(), in.i(), in.i(), in.i());
      break;
    case 4: {
      const GLshort v[4] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                            static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
      glMultiTexCoord4sv(u, v);
      break;
    }
    default: {
      const GLfloat v[4] = {in.f(), in.f(), in.f(), in.f()};
      glMultiTexCoord4fv(u, v);
      break;
    }
    }
    break;
  }
  case 18: {
    // A texture coordinate array of the client active unit.
    const GLint size = in.i();
    const GLenum type = in.e();
    const GLsizei stride = in.i();
    glTexCoordPointer(size, type, stride, array_pointer(h, in));
    break;
  }
  default:
    glTexCoord3s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                 static_cast<GLshort>(in.i()));
    break;
  }
}

void op_lists(Harness& h, Input& in) {
  const bool compiling = h.compiling;
  switch (in.u8() % 9) {
  case 0: {
    const GLuint list = name(in);
    const GLenum mode = in.e(kListModes);
    glNewList(list, mode);
    if (!compiling && !inside_begin() && get_int(GL_LIST_INDEX) != 0) {
      h.compiling = true;
      h.list_calls = 0;
    }
    break;
  }
  case 1:
    glEndList();
    if (!inside_begin()) h.compiling = get_int(GL_LIST_INDEX) != 0;
    break;
  case 2:
  case 3: {
    const GLuint list = name(in);
    if (compiling && h.list_calls++ > 0) return;
    before_begin(h);
    glCallList(list);
    break;
  }
  case 4: {
    // n names of `type` (2_BYTES..4_BYTES: that many bytes per name, §5.4).
    const GLenum type = in.e(kListTypes);
    const uint8_t nb = in.u8();
    const GLsizei n = nb >= 250 ? -1 : nb % 17;
    if (compiling && (n > 1 || h.list_calls++ > 0)) return;
    int64_t per = type_bytes(type);
    if (type == GL_2_BYTES || type == GL_3_BYTES || type == GL_4_BYTES)
      per = 2 + static_cast<int64_t>(type - GL_2_BYTES);
    if (type == GL_DOUBLE) per = 0;
    Block names(h, n > 0 ? n * per : 0);
    for (int64_t k = 0; k < (n > 0 ? n * per : 0); ++k)
      names.as<uint8_t>()[k] = in.u8() % 14;
    before_begin(h);
    glCallLists(n, type, names.get());
    break;
  }
  case 5:
    glListBase(name(in));
    break;
  case 6: {
    // Ranges beyond a few thousand names only make Gen/DeleteLists slow, not different.
    const GLsizei range = in.u8() >= 250 ? -1 : static_cast<GLsizei>(in.u8() % 40);
    glGenLists(range);
    break;
  }
  case 7: {
    const GLuint first = name(in);
    const GLsizei range = in.u8() >= 250 ? -1 : static_cast<GLsizei>(in.u8() % 40);
    glDeleteLists(first, range);
    break;
  }
  default:
    glIsList(name(in));
    break;
  }
}

void op_select_feedback(Harness& h, Input& in) {
  switch (in.u8() % 9) {
  case 0: {
    const GLint size = in.i();
    if (size > 65536) return;
    auto* buf = static_cast<GLuint*>(std::malloc(size > 0 ? size * 4u : 1u));
    h.keep.push_back(buf);
    glSelectBuffer(size, buf);
    break;
  }
  case 1: {
    const GLint size = in.i();
    const GLenum type = in.e(kFeedbackTypes);
    if (size > 65536) return;
    auto* buf = static_cast<GLfloat*>(std::malloc(size > 0 ? size * 4u : 1u));
    h.keep.push_back(buf);
    glFeedbackBuffer(size, type, buf);
    break;
  }
  case 2:
    glRenderMode(in.e(kRenderModes));
    break;
  case 3:
    glInitNames();
    break;
  case 4:
    glPushName(name(in));
    break;
  case 5:
    glPopName();
    break;
  case 6:
    glLoadName(name(in));
    break;
  case 7:
    glPassThrough(in.f());
    break;
  default: {
    void* p = nullptr;
    glGetPointerv(in.u8() & 1 ? GL_SELECTION_BUFFER_POINTER : GL_FEEDBACK_BUFFER_POINTER, &p);
    break;
  }
  }
}

namespace {

// Values per control point of an evaluator target (GL 2.1 Table 5.1), 0 when unknown.
int64_t map_k(GLenum target) {
  switch (target) {
  case GL_MAP1_INDEX:
  case GL_MAP2_INDEX:
  case GL_MAP1_TEXTURE_COORD_1:
  case GL_MAP2_TEXTURE_COORD_1:
    return 1;
  case GL_MAP1_TEXTURE_COORD_2:
  case GL_MAP2_TEXTURE_COORD_2:
    return 2;
  case GL_MAP1_VERTEX_3:
  case GL_MAP2_VERTEX_3:
  case GL_MAP1_NORMAL:
  case GL_MAP2_NORMAL:
  case GL_MAP1_TEXTURE_COORD_3:
  case GL_MAP2_TEXTURE_COORD_3:
    return 3;
  case GL_MAP1_VERTEX_4:
  case GL_MAP2_VERTEX_4:
  case GL_MAP1_COLOR_4:
  case GL_MAP2_COLOR_4:
  case GL_MAP1_TEXTURE_COORD_4:
  case GL_MAP2_TEXTURE_COORD_4:
    return 4;
  default:
    return 0;
  }
}

bool is_map2(GLenum target) {
  return target >= GL_MAP2_COLOR_4 && target <= GL_MAP2_VERTEX_4;
}

// An order or stride: small, sometimes anything.
GLint small_or_any(Input& in) {
  const uint8_t v = in.u8();
  return v < 240 ? static_cast<GLint>(v % 40) - 2 : in.i();
}

void op_map(Harness& h, Input& in, bool two, bool dbl) {
  const GLenum target = in.e(two ? kMap2 : kMap1);
  const double u1 = in.d(), u2 = in.d();
  const GLint ustride = small_or_any(in), uorder = small_or_any(in);
  const double v1 = two ? in.d() : 0, v2 = two ? in.d() : 0;
  const GLint vstride = two ? small_or_any(in) : 0, vorder = two ? small_or_any(in) : 1;
  const uint16_t off = in.u16();
  // §5.1: the points are read only for a valid call: order in [1, MAX_EVAL_ORDER], each
  // stride >= k. The last value read is at (uorder-1) ustride + (vorder-1) vstride + k - 1.
  const int64_t k = map_k(target);
  int64_t count = 0;
  if (k > 0 && uorder >= 1 && uorder <= 64 && vorder >= 1 && vorder <= 64 && ustride >= k &&
      (!two || vstride >= k))
    count = (int64_t{uorder} - 1) * ustride + (int64_t{vorder} - 1) * vstride + k;
  if (count * 8 > kMaxImageBytes) return;
  Block pts(h, count * (dbl ? 8 : 4), off);
  if (dbl) {
    // The arena holds floats: widen them in place, last first (double j overlaps only
    // floats 2j and 2j + 1, both already read).
    auto* bytes = pts.as<uint8_t>();
    for (int64_t j = count - 1; j >= 0; --j) {
      float f;
      std::memcpy(&f, bytes + 4 * j, 4);
      const double dv = f;
      std::memcpy(bytes + 8 * j, &dv, 8);
    }
  }
  if (!two) {
    if (dbl)
      glMap1d(target, u1, u2, ustride, uorder, pts.as<GLdouble>());
    else
      glMap1f(target, static_cast<float>(u1), static_cast<float>(u2), ustride, uorder,
              pts.as<GLfloat>());
  } else if (dbl) {
    glMap2d(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, pts.as<GLdouble>());
  } else {
    glMap2f(target, static_cast<float>(u1), static_cast<float>(u2), ustride, uorder,
            static_cast<float>(v1), static_cast<float>(v2), vstride, vorder, pts.as<GLfloat>());
  }
}

void op_get_map(Harness& h, Input& in) {
  const GLenum target = in.e(in.u8() & 1 ? kMap1 : kMap2);
  const GLenum query = in.e(kMapQueries);
  const int64_t k = map_k(target);
  const bool two = is_map2(target);
  // §6.1.3: COEFF returns the control points (uorder [* vorder] * k values), ORDER 1 or 2
  // values, DOMAIN 2 or 4.
  int64_t count = 0;
  if (k > 0) {
    GLint order[2] = {0, 0};
    glGetMapiv(target, GL_ORDER, order);
    switch (query) {
    case GL_COEFF:
      count = int64_t{order[0]} * (two ? order[1] : 1) * k;
      break;
    case GL_ORDER:
      count = two ? 2 : 1;
      break;
    case GL_DOMAIN:
      count = two ? 4 : 2;
      break;
    default:
      break;
    }
  }
  if (count * 8 > kMaxImageBytes) return;
  switch (in.u8() % 3) {
  case 0: {
    Block b(h, count * 4);
    glGetMapfv(target, query, b.as<GLfloat>());
    break;
  }
  case 1: {
    Block b(h, count * 8);
    glGetMapdv(target, query, b.as<GLdouble>());
    break;
  }
  default: {
    Block b(h, count * 4);
    glGetMapiv(target, query, b.as<GLint>());
    break;
  }
  }
}

// A grid point index for EvalMesh/EvalPoint: small, sometimes anything.
GLint grid(Input& in) {
  const uint8_t v = in.u8();
  return v < 240 ? static_cast<GLint>(v % 80) - 8 : in.i();
}

} // namespace

void op_eval(Harness& h, Input& in) {
  switch (in.u8() % 14) {
  case 0:
    op_map(h, in, false, false);
    break;
  case 1:
    op_map(h, in, false, true);
    break;
  case 2:
    op_map(h, in, true, false);
    break;
  case 3:
    op_map(h, in, true, true);
    break;
  case 4:
    op_get_map(h, in);
    break;
  case 5:
    glMapGrid1f(grid(in), in.f(), in.f());
    break;
  case 6:
    glMapGrid2d(grid(in), in.d(), in.d(), grid(in), in.d(), in.d());
    break;
  case 7:
    glEvalCoord1f(in.f());
    break;
  case 8:
    glEvalCoord2d(in.d(), in.d());
    break;
  case 9: {
    const GLfloat v[2] = {in.f(), in.f()};
    if (in.u8() & 1)
      glEvalCoord2fv(v);
    else
      glEvalCoord1fv(v);
    break;
  }
  case 10:
    glEvalPoint1(grid(in));
    break;
  case 11:
    glEvalPoint2(grid(in), grid(in));
    break;
  case 12: {
    // Meshes are bounded: an 80 x 80 grid at most per call.
    const GLenum mode = in.e();
    const GLint a = grid(in), b = grid(in);
    if (int64_t{b} - a > 4096) return;
    glEvalMesh1(mode, a, b);
    break;
  }
  default: {
    const GLenum mode = in.e();
    const GLint i1 = grid(in), i2 = grid(in), j1 = grid(in), j2 = grid(in);
    if (int64_t{i2} - i1 > 96 || int64_t{j2} - j1 > 96) return;
    glEvalMesh2(mode, i1, i2, j1, j2);
    break;
  }
  }
}

} // namespace pineda::fuzz
