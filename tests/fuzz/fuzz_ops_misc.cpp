// Harness operations on lighting and fog (GL 2.1 §2.14, §3.10), the fragment operations and
// rasterization parameters (§3.3-§3.5, §4.1, §4.2), accumulation (§4.2.4), attribute stacks
// (§6.1.14), occlusion queries (§4.1.7) and raster positions (§2.13). Vector arguments get
// exactly the values each command reads for its pname.
#include "fuzz_harness.h"

namespace pineda::fuzz {
namespace {

constexpr GLenum kLights[] = {GL_LIGHT0, GL_LIGHT1, GL_LIGHT7, GL_LIGHT0 + 8, 0};

constexpr GLenum kLightParams[] = {GL_AMBIENT,
                                   GL_DIFFUSE,
                                   GL_SPECULAR,
                                   GL_POSITION,
                                   GL_SPOT_DIRECTION,
                                   GL_SPOT_EXPONENT,
                                   GL_SPOT_CUTOFF,
                                   GL_CONSTANT_ATTENUATION,
                                   GL_LINEAR_ATTENUATION,
                                   GL_QUADRATIC_ATTENUATION,
                                   0};

constexpr GLenum kFaces[] = {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK, 0};

constexpr GLenum kMaterialParams[] = {
    GL_AMBIENT,       GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS, GL_AMBIENT_AND_DIFFUSE,
    GL_COLOR_INDEXES, 0};

constexpr GLenum kLightModelParams[] = {GL_LIGHT_MODEL_AMBIENT, GL_LIGHT_MODEL_LOCAL_VIEWER,
                                        GL_LIGHT_MODEL_TWO_SIDE, GL_LIGHT_MODEL_COLOR_CONTROL, 0};

constexpr GLenum kFogParams[] = {GL_FOG_MODE,  GL_FOG_DENSITY, GL_FOG_START,     GL_FOG_END,
                                 GL_FOG_INDEX, GL_FOG_COLOR,   GL_FOG_COORD_SRC, 0};

constexpr GLenum kFogValues[] = {GL_LINEAR, GL_EXP, GL_EXP2, GL_FOG_COORD, GL_FRAGMENT_DEPTH, 0};

constexpr GLenum kPointParams[] = {GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX,
                                   GL_POINT_FADE_THRESHOLD_SIZE, GL_POINT_DISTANCE_ATTENUATION, 0};

constexpr GLenum kQueryTargets[] = {GL_SAMPLES_PASSED, 0};

constexpr GLenum kQueryParams[] = {GL_QUERY_COUNTER_BITS, GL_CURRENT_QUERY, GL_QUERY_RESULT,
                                   GL_QUERY_RESULT_AVAILABLE, 0};

constexpr GLenum kAccumOps[] = {GL_ACCUM, GL_LOAD, GL_RETURN, GL_MULT, GL_ADD, 0};

constexpr GLenum kBuffers[] = {GL_FRONT,       GL_BACK,           GL_FRONT_LEFT,
                               GL_FRONT_RIGHT, GL_LEFT,           GL_NONE,
                               GL_AUX0,        GL_FRONT_AND_BACK, 0};

constexpr GLenum kStencilOps[] = {GL_KEEP,   GL_ZERO,      GL_REPLACE,   GL_INCR, GL_DECR,
                                  GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP, 0};

constexpr GLenum kLogicOps[] = {GL_CLEAR, GL_AND,    GL_COPY, GL_XOR, GL_OR,   GL_NOR,
                                GL_EQUIV, GL_INVERT, GL_NAND, GL_SET, GL_NOOP, 0};

constexpr GLenum kFuncs[] = {GL_NEVER,    GL_LESS,   GL_EQUAL,  GL_LEQUAL, GL_GREATER,
                             GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS, 0};

// Values GL reads or writes through the vector forms, per pname (Tables 6.x).
int64_t fog_count(GLenum p) {
  return p == GL_FOG_COLOR ? 4 : 1;
}
int64_t light_count(GLenum p) {
  switch (p) {
  case GL_AMBIENT:
  case GL_DIFFUSE:
  case GL_SPECULAR:
  case GL_POSITION:
    return 4;
  case GL_SPOT_DIRECTION:
    return 3;
  default:
    return 1;
  }
}
int64_t material_count(GLenum p) {
  switch (p) {
  case GL_AMBIENT:
  case GL_DIFFUSE:
  case GL_SPECULAR:
  case GL_EMISSION:
  case GL_AMBIENT_AND_DIFFUSE:
    return 4;
  case GL_COLOR_INDEXES:
    return 3;
  default:
    return 1;
  }
}
int64_t light_model_count(GLenum p) {
  return p == GL_LIGHT_MODEL_AMBIENT ? 4 : 1;
}
int64_t point_count(GLenum p) {
  return p == GL_POINT_DISTANCE_ATTENUATION ? 3 : 1;
}

} // namespace

void op_lighting(Harness& h, Input& in) {
  static constexpr ParamFamily kLight = {glLightf,  glLighti,     glLightfv,
                                         glLightiv, glGetLightfv, glGetLightiv};
  switch (in.u8() % 12) {
  case 0:
  case 1:
  case 2:
  case 3:
  case 4: {
    const GLenum l = in.e(kLights), p = in.e(kLightParams);
    call_param(h, in, kLight, l, p, light_count(p), in.i());
    break;
  }
  case 5: {
    const GLenum f = in.e(kFaces), p = in.e(kMaterialParams);
    glMaterialf(f, p, in.f());
    break;
  }
  case 6: {
    const GLenum f = in.e(kFaces), p = in.e(kMaterialParams);
    Floats v(h, in, material_count(p));
    glMaterialfv(f, p, v.get());
    break;
  }
  case 7: {
    const GLenum f = in.e(kFaces), p = in.e(kMaterialParams);
    Ints v(h, in, material_count(p));
    if (in.u8() & 1)
      glMaterialiv(f, p, v.get());
    else
      glMateriali(f, p, v.get()[0]);
    break;
  }
  case 8: {
    const GLenum f = in.e(kFaces), p = in.e(kMaterialParams);
    Block v(h, material_count(p) * 4);
    if (in.u8() & 1)
      glGetMaterialfv(f, p, v.as<GLfloat>());
    else
      glGetMaterialiv(f, p, v.as<GLint>());
    break;
  }
  case 9: {
    const GLenum p = in.e(kLightModelParams);
    switch (in.u8() % 4) {
    case 0:
      glLightModelf(p, in.f());
      break;
    case 1:
      glLightModeli(p, in.i());
      break;
    case 2: {
      Floats v(h, in, light_model_count(p));
      glLightModelfv(p, v.get());
      break;
    }
    default: {
      Ints v(h, in, light_model_count(p));
      glLightModeliv(p, v.get());
      break;
    }
    }
    break;
  }
  case 10: {
    const GLenum f = in.e(kFaces), p = in.e(kMaterialParams);
    glColorMaterial(f, p);
    break;
  }
  default: {
    // Fog and the fog coordinate (§3.10, §2.7).
    const GLenum p = in.e(kFogParams);
    switch (in.u8() % 9) {
    case 0:
      glFogf(p, in.f());
      break;
    case 1:
      glFogi(p, static_cast<GLint>(in.e(kFogValues)));
      break;
    case 2: {
      Floats v(h, in, fog_count(p));
      glFogfv(p, v.get());
      break;
    }
    case 3: {
      Ints v(h, in, fog_count(p));
      glFogiv(p, v.get());
      break;
    }
    case 4:
      glFogCoordf(in.f());
      break;
    case 5:
      glFogCoordd(in.d());
      break;
    case 6: {
      const GLfloat v = in.f();
      glFogCoordfv(&v);
      break;
    }
    case 7: {
      const GLdouble v = in.d();
      glFogCoorddv(&v);
      break;
    }
    default: {
      const GLenum type = in.e();
      const GLsizei stride = in.i();
      glFogCoordPointer(type, stride, array_pointer(h, in));
      break;
    }
    }
    break;
  }
  }
}

void op_fragment_misc(Harness& h, Input& in) {
  switch (in.u8() % 24) {
  case 0:
    glScissor(in.i(), in.i(), in.i(), in.i());
    break;
  case 1:
    glAlphaFunc(in.e(kFuncs), in.f());
    break;
  case 2:
    glStencilFunc(in.e(kFuncs), in.i(), in.u32());
    break;
  case 3:
    glStencilOp(in.e(kStencilOps), in.e(kStencilOps), in.e(kStencilOps));
    break;
  case 4:
    glStencilMask(in.u32());
    break;
  case 5:
    glLogicOp(in.e(kLogicOps));
    break;
  case 6:
    glDrawBuffer(in.e(kBuffers));
    break;
  case 7:
    glReadBuffer(in.e(kBuffers));
    break;
  case 8:
    glPointSize(in.f());
    break;
  case 9: {
    const GLenum p = in.e(kPointParams);
    switch (in.u8() % 4) {
    case 0:
      glPointParameterf(p, in.f());
      break;
    case 1:
      glPointParameteri(p, in.i());
      break;
    case 2: {
      Floats v(h, in, point_count(p));
      glPointParameterfv(p, v.get());
      break;
    }
    default: {
      Ints v(h, in, point_count(p));
      glPointParameteriv(p, v.get());
      break;
    }
    }
    break;
  }
  case 10:
    glLineWidth(in.f());
    break;
  case 11:
    glLineStipple(in.i(), static_cast<GLushort>(in.u16()));
    break;
  case 12:
    glPolygonOffset(in.f(), in.f());
    break;
  case 13:
    glAccum(in.e(kAccumOps), in.f());
    break;
  case 14:
    glClearAccum(in.f(), in.f(), in.f(), in.f());
    break;
  case 15:
    glSampleCoverage(in.f(), in.u8() & 1);
    break;
  case 16:
    glIndexMask(in.u32());
    break;
  case 17:
    glClearIndex(in.f());
    break;
  case 18: {
    switch (in.u8() % 5) {
    case 0:
      glIndexi(in.i());
      break;
    case 1:
      glIndexf(in.f());
      break;
    case 2:
      glIndexd(in.d());
      break;
    case 3:
      glIndexub(in.u8());
      break;
    default: {
      const GLshort v = static_cast<GLshort>(in.i());
      glIndexsv(&v);
      break;
    }
    }
    break;
  }
  case 19: {
    const GLenum type = in.e();
    const GLsizei stride = in.i();
    glIndexPointer(type, stride, array_pointer(h, in));
    break;
  }
  case 20: {
    switch (in.u8() % 6) {
    case 0:
      glSecondaryColor3f(in.f(), in.f(), in.f());
      break;
    case 1:
      glSecondaryColor3ub(in.u8(), in.u8(), in.u8());
      break;
    case 2:
      glSecondaryColor3d(in.d(), in.d(), in.d());
      break;
    case 3:
      glSecondaryColor3i(in.i(), in.i(), in.i());
      break;
    case 4: {
      const GLushort v[3] = {in.u16(), in.u16(), in.u16()};
      glSecondaryColor3usv(v);
      break;
    }
    default: {
      const GLbyte v[3] = {static_cast<GLbyte>(in.u8()), static_cast<GLbyte>(in.u8()),
                           static_cast<GLbyte>(in.u8())};
      glSecondaryColor3bv(v);
      break;
    }
    }
    break;
  }
  case 21: {
    const GLint size = in.i();
    const GLenum type = in.e();
    const GLsizei stride = in.i();
    glSecondaryColorPointer(size, type, stride, array_pointer(h, in));
    break;
  }
  case 22:
    glFlush();
    break;
  default:
    glFinish();
    break;
  }
}

void op_attrib2(Harness&, Input& in) {
  switch (in.u8() % 4) {
  case 0: {
    // Mostly single groups and ALL_ATTRIB_BITS, sometimes any mask.
    static constexpr GLbitfield kMasks[] = {GL_CURRENT_BIT,
                                            GL_POINT_BIT,
                                            GL_LINE_BIT,
                                            GL_POLYGON_BIT,
                                            GL_POLYGON_STIPPLE_BIT,
                                            GL_PIXEL_MODE_BIT,
                                            GL_LIGHTING_BIT,
                                            GL_FOG_BIT,
                                            GL_DEPTH_BUFFER_BIT,
                                            GL_ACCUM_BUFFER_BIT,
                                            GL_STENCIL_BUFFER_BIT,
                                            GL_VIEWPORT_BIT,
                                            GL_TRANSFORM_BIT,
                                            GL_ENABLE_BIT,
                                            GL_COLOR_BUFFER_BIT,
                                            GL_HINT_BIT,
                                            GL_EVAL_BIT,
                                            GL_LIST_BIT,
                                            GL_TEXTURE_BIT,
                                            GL_SCISSOR_BIT,
                                            GL_MULTISAMPLE_BIT,
                                            GL_ALL_ATTRIB_BITS};
    const uint8_t v = in.u8();
    glPushAttrib(v < 220 ? kMasks[v % 22] : in.u32());
    break;
  }
  case 1:
    glPopAttrib();
    break;
  case 2: {
    const uint8_t v = in.u8();
    glPushClientAttrib(v < 200 ? (v % 3 == 0   ? GL_CLIENT_PIXEL_STORE_BIT
                                  : v % 3 == 1 ? GL_CLIENT_VERTEX_ARRAY_BIT
                                               : GL_CLIENT_ALL_ATTRIB_BITS)
                               : in.u32());
    break;
  }
  default:
    glPopClientAttrib();
    break;
  }
}

void op_queries2(Harness& h, Input& in) {
  switch (in.u8() % 8) {
  case 0: {
    const GLsizei n = name_count(in);
    Block names(h, n > 0 ? n * 4 : 0);
    glGenQueries(n, names.as<GLuint>());
    break;
  }
  case 1: {
    const GLsizei n = name_count(in);
    Names names(h, in, n);
    glDeleteQueries(n, names.get());
    break;
  }
  case 2:
    glIsQuery(name(in));
    break;
  case 3: {
    const GLenum t = in.e(kQueryTargets);
    glBeginQuery(t, name(in));
    break;
  }
  case 4:
    glEndQuery(in.e(kQueryTargets));
    break;
  case 5: {
    GLint* v = static_cast<GLint*>(std::malloc(4));
    const GLenum t = in.e(kQueryTargets);
    glGetQueryiv(t, in.e(kQueryParams), v);
    std::free(v);
    break;
  }
  case 6: {
    GLint* v = static_cast<GLint*>(std::malloc(4));
    const GLuint id = name(in);
    glGetQueryObjectiv(id, in.e(kQueryParams), v);
    std::free(v);
    break;
  }
  default: {
    GLuint* v = static_cast<GLuint*>(std::malloc(4));
    const GLuint id = name(in);
    glGetQueryObjectuiv(id, in.e(kQueryParams), v);
    std::free(v);
    break;
  }
  }
}

void op_raster_pos(Harness&, Input& in) {
  switch (in.u8() % 14) {
  case 0:
    glRasterPos2f(in.f(), in.f());
    break;
  case 1:
    glRasterPos3d(in.d(), in.d(), in.d());
    break;
  case 2:
    glRasterPos4f(in.f(), in.f(), in.f(), in.f());
    break;
  case 3:
    glRasterPos2i(in.i(), in.i());
    break;
  case 4:
    glRasterPos3s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                  static_cast<GLshort>(in.i()));
    break;
  case 5: {
    const GLdouble v[4] = {in.d(), in.d(), in.d(), in.d()};
    glRasterPos4dv(v);
    break;
  }
  case 6: {
    const GLint v[3] = {in.i(), in.i(), in.i()};
    glRasterPos3iv(v);
    break;
  }
  case 7:
    glWindowPos2f(in.f(), in.f());
    break;
  case 8:
    glWindowPos3d(in.d(), in.d(), in.d());
    break;
  case 9:
    glWindowPos2i(in.i(), in.i());
    break;
  case 10:
    glWindowPos3s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                  static_cast<GLshort>(in.i()));
    break;
  case 11: {
    const GLfloat v[3] = {in.f(), in.f(), in.f()};
    glWindowPos3fv(v);
    break;
  }
  case 12: {
    const GLdouble v[2] = {in.d(), in.d()};
    glWindowPos2dv(v);
    break;
  }
  default: {
    const GLshort v[4] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                          static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
    glRasterPos4sv(v);
    break;
  }
  }
}

} // namespace pineda::fuzz
