// Harness operation calling any typed variant of the raster position, colour index,
// rectangle, edge flag, evaluator coordinate/grid and matrix commands (every argument type and
// vector form of src/api/entry_points.txt). Vector forms get arrays of exactly the size the
// command reads, on the stack, where AddressSanitizer's redzones surround them.
#include "fuzz_harness.h"

namespace pineda::fuzz {

void op_other_variants(Harness&, Input& in) {
  switch (in.u16() % 85) {
  case 0: {
    glRasterPos2s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()));
    break;
  }
  case 1: {
    const GLshort v[2] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
    glRasterPos2sv(v);
    break;
  }
  case 2: {
    glRasterPos2i(in.i(), in.i());
    break;
  }
  case 3: {
    const GLint v[2] = {in.i(), in.i()};
    glRasterPos2iv(v);
    break;
  }
  case 4: {
    glRasterPos2f(in.f(), in.f());
    break;
  }
  case 5: {
    const GLfloat v[2] = {in.f(), in.f()};
    glRasterPos2fv(v);
    break;
  }
  case 6: {
    glRasterPos2d(in.d(), in.d());
    break;
  }
  case 7: {
    const GLdouble v[2] = {in.d(), in.d()};
    glRasterPos2dv(v);
    break;
  }
  case 8: {
    glRasterPos3s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                  static_cast<GLshort>(in.i()));
    break;
  }
  case 9: {
    const GLshort v[3] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                          static_cast<GLshort>(in.i())};
    glRasterPos3sv(v);
    break;
  }
  case 10: {
    glRasterPos3i(in.i(), in.i(), in.i());
    break;
  }
  case 11: {
    const GLint v[3] = {in.i(), in.i(), in.i()};
    glRasterPos3iv(v);
    break;
  }
  case 12: {
    glRasterPos3f(in.f(), in.f(), in.f());
    break;
  }
  case 13: {
    const GLfloat v[3] = {in.f(), in.f(), in.f()};
    glRasterPos3fv(v);
    break;
  }
  case 14: {
    glRasterPos3d(in.d(), in.d(), in.d());
    break;
  }
  case 15: {
    const GLdouble v[3] = {in.d(), in.d(), in.d()};
    glRasterPos3dv(v);
    break;
  }
  case 16: {
    glRasterPos4s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                  static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()));
    break;
  }
  case 17: {
    const GLshort v[4] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                          static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
    glRasterPos4sv(v);
    break;
  }
  case 18: {
    glRasterPos4i(in.i(), in.i(), in.i(), in.i());
    break;
  }
  case 19: {
    const GLint v[4] = {in.i(), in.i(), in.i(), in.i()};
    glRasterPos4iv(v);
    break;
  }
  case 20: {
    glRasterPos4f(in.f(), in.f(), in.f(), in.f());
    break;
  }
  case 21: {
    const GLfloat v[4] = {in.f(), in.f(), in.f(), in.f()};
    glRasterPos4fv(v);
    break;
  }
  case 22: {
    glRasterPos4d(in.d(), in.d(), in.d(), in.d());
    break;
  }
  case 23: {
    const GLdouble v[4] = {in.d(), in.d(), in.d(), in.d()};
    glRasterPos4dv(v);
    break;
  }
  case 24: {
    glWindowPos2s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()));
    break;
  }
  case 25: {
    const GLshort v[2] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
    glWindowPos2sv(v);
    break;
  }
  case 26: {
    glWindowPos2i(in.i(), in.i());
    break;
  }
  case 27: {
    const GLint v[2] = {in.i(), in.i()};
    glWindowPos2iv(v);
    break;
  }
  case 28: {
    glWindowPos2f(in.f(), in.f());
    break;
  }
  case 29: {
    const GLfloat v[2] = {in.f(), in.f()};
    glWindowPos2fv(v);
    break;
  }
  case 30: {
    glWindowPos2d(in.d(), in.d());
    break;
  }
  case 31: {
    const GLdouble v[2] = {in.d(), in.d()};
    glWindowPos2dv(v);
    break;
  }
  case 32: {
    glWindowPos3s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                  static_cast<GLshort>(in.i()));
    break;
  }
  case 33: {
    const GLshort v[3] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                          static_cast<GLshort>(in.i())};
    glWindowPos3sv(v);
    break;
  }
  case 34: {
    glWindowPos3i(in.i(), in.i(), in.i());
    break;
  }
  case 35: {
    const GLint v[3] = {in.i(), in.i(), in.i()};
    glWindowPos3iv(v);
    break;
  }
  case 36: {
    glWindowPos3f(in.f(), in.f(), in.f());
    break;
  }
  case 37: {
    const GLfloat v[3] = {in.f(), in.f(), in.f()};
    glWindowPos3fv(v);
    break;
  }
  case 38: {
    glWindowPos3d(in.d(), in.d(), in.d());
    break;
  }
  case 39: {
    const GLdouble v[3] = {in.d(), in.d(), in.d()};
    glWindowPos3dv(v);
    break;
  }
  case 40: {
    glEvalCoord1f(in.f());
    break;
  }
  case 41: {
    const GLfloat v[1] = {in.f()};
    glEvalCoord1fv(v);
    break;
  }
  case 42: {
    glEvalCoord1d(in.d());
    break;
  }
  case 43: {
    const GLdouble v[1] = {in.d()};
    glEvalCoord1dv(v);
    break;
  }
  case 44: {
    glEvalCoord2f(in.f(), in.f());
    break;
  }
  case 45: {
    const GLfloat v[2] = {in.f(), in.f()};
    glEvalCoord2fv(v);
    break;
  }
  case 46: {
    glEvalCoord2d(in.d(), in.d());
    break;
  }
  case 47: {
    const GLdouble v[2] = {in.d(), in.d()};
    glEvalCoord2dv(v);
    break;
  }
  case 48: {
    glIndexs(static_cast<GLshort>(in.i()));
    break;
  }
  case 49: {
    const GLshort v[1] = {static_cast<GLshort>(in.i())};
    glIndexsv(v);
    break;
  }
  case 50: {
    glIndexi(in.i());
    break;
  }
  case 51: {
    const GLint v[1] = {in.i()};
    glIndexiv(v);
    break;
  }
  case 52: {
    glIndexf(in.f());
    break;
  }
  case 53: {
    const GLfloat v[1] = {in.f()};
    glIndexfv(v);
    break;
  }
  case 54: {
    glIndexd(in.d());
    break;
  }
  case 55: {
    const GLdouble v[1] = {in.d()};
    glIndexdv(v);
    break;
  }
  case 56: {
    glIndexub(in.u8());
    break;
  }
  case 57: {
    const GLubyte v[1] = {in.u8()};
    glIndexubv(v);
    break;
  }
  case 58: {
    glRects(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
            static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()));
    break;
  }
  case 59: {
    const GLshort a[2] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
    const GLshort b[2] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
    glRectsv(a, b);
    break;
  }
  case 60: {
    glRecti(in.i(), in.i(), in.i(), in.i());
    break;
  }
  case 61: {
    const GLint a[2] = {in.i(), in.i()};
    const GLint b[2] = {in.i(), in.i()};
    glRectiv(a, b);
    break;
  }
  case 62: {
    glRectf(in.f(), in.f(), in.f(), in.f());
    break;
  }
  case 63: {
    const GLfloat a[2] = {in.f(), in.f()};
    const GLfloat b[2] = {in.f(), in.f()};
    glRectfv(a, b);
    break;
  }
  case 64: {
    glRectd(in.d(), in.d(), in.d(), in.d());
    break;
  }
  case 65: {
    const GLdouble a[2] = {in.d(), in.d()};
    const GLdouble b[2] = {in.d(), in.d()};
    glRectdv(a, b);
    break;
  }
  case 66: {
    const GLboolean v[1] = {static_cast<GLboolean>(in.u8() & 1)};
    glEdgeFlagv(v);
    break;
  }
  case 67: {
    const GLint n = in.i();
    const GLfloat a = in.f(), b = in.f();
    glMapGrid1f(n, a, b);
    break;
  }
  case 68: {
    const GLint n = in.i();
    const GLdouble a = in.d(), b = in.d();
    glMapGrid1d(n, a, b);
    break;
  }
  case 69: {
    const GLint n = in.i();
    const GLfloat a = in.f(), b = in.f();
    const GLint m = in.i();
    const GLfloat c = in.f(), d = in.f();
    glMapGrid2f(n, a, b, m, c, d);
    break;
  }
  case 70: {
    const GLint n = in.i();
    const GLdouble a = in.d(), b = in.d();
    const GLint m = in.i();
    const GLdouble c = in.d(), d = in.d();
    glMapGrid2d(n, a, b, m, c, d);
    break;
  }
  case 71: {
    GLfloat m[16];
    for (GLfloat& x : m)
      x = in.f();
    glLoadMatrixf(m);
    break;
  }
  case 72: {
    GLdouble m[16];
    for (GLdouble& x : m)
      x = in.d();
    glLoadMatrixd(m);
    break;
  }
  case 73: {
    GLfloat m[16];
    for (GLfloat& x : m)
      x = in.f();
    glMultMatrixf(m);
    break;
  }
  case 74: {
    GLdouble m[16];
    for (GLdouble& x : m)
      x = in.d();
    glMultMatrixd(m);
    break;
  }
  case 75: {
    GLfloat m[16];
    for (GLfloat& x : m)
      x = in.f();
    glLoadTransposeMatrixf(m);
    break;
  }
  case 76: {
    GLdouble m[16];
    for (GLdouble& x : m)
      x = in.d();
    glLoadTransposeMatrixd(m);
    break;
  }
  case 77: {
    GLfloat m[16];
    for (GLfloat& x : m)
      x = in.f();
    glMultTransposeMatrixf(m);
    break;
  }
  case 78: {
    GLdouble m[16];
    for (GLdouble& x : m)
      x = in.d();
    glMultTransposeMatrixd(m);
    break;
  }
  case 79: {
    glRotatef(in.f(), in.f(), in.f(), in.f());
    break;
  }
  case 80: {
    glRotated(in.d(), in.d(), in.d(), in.d());
    break;
  }
  case 81: {
    glTranslatef(in.f(), in.f(), in.f());
    break;
  }
  case 82: {
    glTranslated(in.d(), in.d(), in.d());
    break;
  }
  case 83: {
    glScalef(in.f(), in.f(), in.f());
    break;
  }
  default: {
    glScaled(in.d(), in.d(), in.d());
    break;
  }
  }
}

} // namespace pineda::fuzz
