// Harness operation calling any typed variant of the per-vertex attribute commands (glVertex,
// glColor, glNormal, glTexCoord, glSecondaryColor, glMultiTexCoord in every argument type and
// vector form of src/api/entry_points.txt). Vector forms get arrays of exactly the size the
// command reads, on the stack, where AddressSanitizer's redzones surround them.
#include "fuzz_harness.h"

namespace pineda::fuzz {
namespace {

constexpr GLenum kUnits[] = {GL_TEXTURE0, GL_TEXTURE1, GL_TEXTURE3, GL_TEXTURE4, 0};

} // namespace

void op_vertex_variants(Harness&, Input& in) {
  switch (in.u16() % 146) {
  case 0: {
    glVertex2s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()));
    break;
  }
  case 1: {
    const GLshort v[2] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
    glVertex2sv(v);
    break;
  }
  case 2: {
    glVertex2i(in.i(), in.i());
    break;
  }
  case 3: {
    const GLint v[2] = {in.i(), in.i()};
    glVertex2iv(v);
    break;
  }
  case 4: {
    glVertex2f(in.f(), in.f());
    break;
  }
  case 5: {
    const GLfloat v[2] = {in.f(), in.f()};
    glVertex2fv(v);
    break;
  }
  case 6: {
    glVertex2d(in.d(), in.d());
    break;
  }
  case 7: {
    const GLdouble v[2] = {in.d(), in.d()};
    glVertex2dv(v);
    break;
  }
  case 8: {
    glVertex3s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
               static_cast<GLshort>(in.i()));
    break;
  }
  case 9: {
    const GLshort v[3] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                          static_cast<GLshort>(in.i())};
    glVertex3sv(v);
    break;
  }
  case 10: {
    glVertex3i(in.i(), in.i(), in.i());
    break;
  }
  case 11: {
    const GLint v[3] = {in.i(), in.i(), in.i()};
    glVertex3iv(v);
    break;
  }
  case 12: {
    glVertex3f(in.f(), in.f(), in.f());
    break;
  }
  case 13: {
    const GLfloat v[3] = {in.f(), in.f(), in.f()};
    glVertex3fv(v);
    break;
  }
  case 14: {
    glVertex3d(in.d(), in.d(), in.d());
    break;
  }
  case 15: {
    const GLdouble v[3] = {in.d(), in.d(), in.d()};
    glVertex3dv(v);
    break;
  }
  case 16: {
    glVertex4s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
               static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()));
    break;
  }
  case 17: {
    const GLshort v[4] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                          static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
    glVertex4sv(v);
    break;
  }
  case 18: {
    glVertex4i(in.i(), in.i(), in.i(), in.i());
    break;
  }
  case 19: {
    const GLint v[4] = {in.i(), in.i(), in.i(), in.i()};
    glVertex4iv(v);
    break;
  }
  case 20: {
    glVertex4f(in.f(), in.f(), in.f(), in.f());
    break;
  }
  case 21: {
    const GLfloat v[4] = {in.f(), in.f(), in.f(), in.f()};
    glVertex4fv(v);
    break;
  }
  case 22: {
    glVertex4d(in.d(), in.d(), in.d(), in.d());
    break;
  }
  case 23: {
    const GLdouble v[4] = {in.d(), in.d(), in.d(), in.d()};
    glVertex4dv(v);
    break;
  }
  case 24: {
    glColor3b(static_cast<GLbyte>(in.u8()), static_cast<GLbyte>(in.u8()),
              static_cast<GLbyte>(in.u8()));
    break;
  }
  case 25: {
    const GLbyte v[3] = {static_cast<GLbyte>(in.u8()), static_cast<GLbyte>(in.u8()),
                         static_cast<GLbyte>(in.u8())};
    glColor3bv(v);
    break;
  }
  case 26: {
    glColor3s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
              static_cast<GLshort>(in.i()));
    break;
  }
  case 27: {
    const GLshort v[3] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                          static_cast<GLshort>(in.i())};
    glColor3sv(v);
    break;
  }
  case 28: {
    glColor3i(in.i(), in.i(), in.i());
    break;
  }
  case 29: {
    const GLint v[3] = {in.i(), in.i(), in.i()};
    glColor3iv(v);
    break;
  }
  case 30: {
    glColor3f(in.f(), in.f(), in.f());
    break;
  }
  case 31: {
    const GLfloat v[3] = {in.f(), in.f(), in.f()};
    glColor3fv(v);
    break;
  }
  case 32: {
    glColor3d(in.d(), in.d(), in.d());
    break;
  }
  case 33: {
    const GLdouble v[3] = {in.d(), in.d(), in.d()};
    glColor3dv(v);
    break;
  }
  case 34: {
    glColor3ub(in.u8(), in.u8(), in.u8());
    break;
  }
  case 35: {
    const GLubyte v[3] = {in.u8(), in.u8(), in.u8()};
    glColor3ubv(v);
    break;
  }
  case 36: {
    glColor3us(in.u16(), in.u16(), in.u16());
    break;
  }
  case 37: {
    const GLushort v[3] = {in.u16(), in.u16(), in.u16()};
    glColor3usv(v);
    break;
  }
  case 38: {
    glColor3ui(in.u32(), in.u32(), in.u32());
    break;
  }
  case 39: {
    const GLuint v[3] = {in.u32(), in.u32(), in.u32()};
    glColor3uiv(v);
    break;
  }
  case 40: {
    glColor4b(static_cast<GLbyte>(in.u8()), static_cast<GLbyte>(in.u8()),
              static_cast<GLbyte>(in.u8()), static_cast<GLbyte>(in.u8()));
    break;
  }
  case 41: {
    const GLbyte v[4] = {static_cast<GLbyte>(in.u8()), static_cast<GLbyte>(in.u8()),
                         static_cast<GLbyte>(in.u8()), static_cast<GLbyte>(in.u8())};
    glColor4bv(v);
    break;
  }
  case 42: {
    glColor4s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
              static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()));
    break;
  }
  case 43: {
    const GLshort v[4] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                          static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
    glColor4sv(v);
    break;
  }
  case 44: {
    glColor4i(in.i(), in.i(), in.i(), in.i());
    break;
  }
  case 45: {
    const GLint v[4] = {in.i(), in.i(), in.i(), in.i()};
    glColor4iv(v);
    break;
  }
  case 46: {
    glColor4f(in.f(), in.f(), in.f(), in.f());
    break;
  }
  case 47: {
    const GLfloat v[4] = {in.f(), in.f(), in.f(), in.f()};
    glColor4fv(v);
    break;
  }
  case 48: {
    glColor4d(in.d(), in.d(), in.d(), in.d());
    break;
  }
  case 49: {
    const GLdouble v[4] = {in.d(), in.d(), in.d(), in.d()};
    glColor4dv(v);
    break;
  }
  case 50: {
    glColor4ub(in.u8(), in.u8(), in.u8(), in.u8());
    break;
  }
  case 51: {
    const GLubyte v[4] = {in.u8(), in.u8(), in.u8(), in.u8()};
    glColor4ubv(v);
    break;
  }
  case 52: {
    glColor4us(in.u16(), in.u16(), in.u16(), in.u16());
    break;
  }
  case 53: {
    const GLushort v[4] = {in.u16(), in.u16(), in.u16(), in.u16()};
    glColor4usv(v);
    break;
  }
  case 54: {
    glColor4ui(in.u32(), in.u32(), in.u32(), in.u32());
    break;
  }
  case 55: {
    const GLuint v[4] = {in.u32(), in.u32(), in.u32(), in.u32()};
    glColor4uiv(v);
    break;
  }
  case 56: {
    glNormal3b(static_cast<GLbyte>(in.u8()), static_cast<GLbyte>(in.u8()),
               static_cast<GLbyte>(in.u8()));
    break;
  }
  case 57: {
    const GLbyte v[3] = {static_cast<GLbyte>(in.u8()), static_cast<GLbyte>(in.u8()),
                         static_cast<GLbyte>(in.u8())};
    glNormal3bv(v);
    break;
  }
  case 58: {
    glNormal3s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
               static_cast<GLshort>(in.i()));
    break;
  }
  case 59: {
    const GLshort v[3] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                          static_cast<GLshort>(in.i())};
    glNormal3sv(v);
    break;
  }
  case 60: {
    glNormal3i(in.i(), in.i(), in.i());
    break;
  }
  case 61: {
    const GLint v[3] = {in.i(), in.i(), in.i()};
    glNormal3iv(v);
    break;
  }
  case 62: {
    glNormal3f(in.f(), in.f(), in.f());
    break;
  }
  case 63: {
    const GLfloat v[3] = {in.f(), in.f(), in.f()};
    glNormal3fv(v);
    break;
  }
  case 64: {
    glNormal3d(in.d(), in.d(), in.d());
    break;
  }
  case 65: {
    const GLdouble v[3] = {in.d(), in.d(), in.d()};
    glNormal3dv(v);
    break;
  }
  case 66: {
    glTexCoord1s(static_cast<GLshort>(in.i()));
    break;
  }
  case 67: {
    const GLshort v[1] = {static_cast<GLshort>(in.i())};
    glTexCoord1sv(v);
    break;
  }
  case 68: {
    glTexCoord1i(in.i());
    break;
  }
  case 69: {
    const GLint v[1] = {in.i()};
    glTexCoord1iv(v);
    break;
  }
  case 70: {
    glTexCoord1f(in.f());
    break;
  }
  case 71: {
    const GLfloat v[1] = {in.f()};
    glTexCoord1fv(v);
    break;
  }
  case 72: {
    glTexCoord1d(in.d());
    break;
  }
  case 73: {
    const GLdouble v[1] = {in.d()};
    glTexCoord1dv(v);
    break;
  }
  case 74: {
    glTexCoord2s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()));
    break;
  }
  case 75: {
    const GLshort v[2] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
    glTexCoord2sv(v);
    break;
  }
  case 76: {
    glTexCoord2i(in.i(), in.i());
    break;
  }
  case 77: {
    const GLint v[2] = {in.i(), in.i()};
    glTexCoord2iv(v);
    break;
  }
  case 78: {
    glTexCoord2f(in.f(), in.f());
    break;
  }
  case 79: {
    const GLfloat v[2] = {in.f(), in.f()};
    glTexCoord2fv(v);
    break;
  }
  case 80: {
    glTexCoord2d(in.d(), in.d());
    break;
  }
  case 81: {
    const GLdouble v[2] = {in.d(), in.d()};
    glTexCoord2dv(v);
    break;
  }
  case 82: {
    glTexCoord3s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                 static_cast<GLshort>(in.i()));
    break;
  }
  case 83: {
    const GLshort v[3] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                          static_cast<GLshort>(in.i())};
    glTexCoord3sv(v);
    break;
  }
  case 84: {
    glTexCoord3i(in.i(), in.i(), in.i());
    break;
  }
  case 85: {
    const GLint v[3] = {in.i(), in.i(), in.i()};
    glTexCoord3iv(v);
    break;
  }
  case 86: {
    glTexCoord3f(in.f(), in.f(), in.f());
    break;
  }
  case 87: {
    const GLfloat v[3] = {in.f(), in.f(), in.f()};
    glTexCoord3fv(v);
    break;
  }
  case 88: {
    glTexCoord3d(in.d(), in.d(), in.d());
    break;
  }
  case 89: {
    const GLdouble v[3] = {in.d(), in.d(), in.d()};
    glTexCoord3dv(v);
    break;
  }
  case 90: {
    glTexCoord4s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                 static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()));
    break;
  }
  case 91: {
    const GLshort v[4] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                          static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
    glTexCoord4sv(v);
    break;
  }
  case 92: {
    glTexCoord4i(in.i(), in.i(), in.i(), in.i());
    break;
  }
  case 93: {
    const GLint v[4] = {in.i(), in.i(), in.i(), in.i()};
    glTexCoord4iv(v);
    break;
  }
  case 94: {
    glTexCoord4f(in.f(), in.f(), in.f(), in.f());
    break;
  }
  case 95: {
    const GLfloat v[4] = {in.f(), in.f(), in.f(), in.f()};
    glTexCoord4fv(v);
    break;
  }
  case 96: {
    glTexCoord4d(in.d(), in.d(), in.d(), in.d());
    break;
  }
  case 97: {
    const GLdouble v[4] = {in.d(), in.d(), in.d(), in.d()};
    glTexCoord4dv(v);
    break;
  }
  case 98: {
    glSecondaryColor3b(static_cast<GLbyte>(in.u8()), static_cast<GLbyte>(in.u8()),
                       static_cast<GLbyte>(in.u8()));
    break;
  }
  case 99: {
    const GLbyte v[3] = {static_cast<GLbyte>(in.u8()), static_cast<GLbyte>(in.u8()),
                         static_cast<GLbyte>(in.u8())};
    glSecondaryColor3bv(v);
    break;
  }
  case 100: {
    glSecondaryColor3s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                       static_cast<GLshort>(in.i()));
    break;
  }
  case 101: {
    const GLshort v[3] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                          static_cast<GLshort>(in.i())};
    glSecondaryColor3sv(v);
    break;
  }
  case 102: {
    glSecondaryColor3i(in.i(), in.i(), in.i());
    break;
  }
  case 103: {
    const GLint v[3] = {in.i(), in.i(), in.i()};
    glSecondaryColor3iv(v);
    break;
  }
  case 104: {
    glSecondaryColor3f(in.f(), in.f(), in.f());
    break;
  }
  case 105: {
    const GLfloat v[3] = {in.f(), in.f(), in.f()};
    glSecondaryColor3fv(v);
    break;
  }
  case 106: {
    glSecondaryColor3d(in.d(), in.d(), in.d());
    break;
  }
  case 107: {
    const GLdouble v[3] = {in.d(), in.d(), in.d()};
    glSecondaryColor3dv(v);
    break;
  }
  case 108: {
    glSecondaryColor3ub(in.u8(), in.u8(), in.u8());
    break;
  }
  case 109: {
    const GLubyte v[3] = {in.u8(), in.u8(), in.u8()};
    glSecondaryColor3ubv(v);
    break;
  }
  case 110: {
    glSecondaryColor3us(in.u16(), in.u16(), in.u16());
    break;
  }
  case 111: {
    const GLushort v[3] = {in.u16(), in.u16(), in.u16()};
    glSecondaryColor3usv(v);
    break;
  }
  case 112: {
    glSecondaryColor3ui(in.u32(), in.u32(), in.u32());
    break;
  }
  case 113: {
    const GLuint v[3] = {in.u32(), in.u32(), in.u32()};
    glSecondaryColor3uiv(v);
    break;
  }
  case 114: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord1s(u, static_cast<GLshort>(in.i()));
    break;
  }
  case 115: {
    const GLenum u = in.e(kUnits);
    const GLshort v[1] = {static_cast<GLshort>(in.i())};
    glMultiTexCoord1sv(u, v);
    break;
  }
  case 116: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord1i(u, in.i());
    break;
  }
  case 117: {
    const GLenum u = in.e(kUnits);
    const GLint v[1] = {in.i()};
    glMultiTexCoord1iv(u, v);
    break;
  }
  case 118: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord1f(u, in.f());
    break;
  }
  case 119: {
    const GLenum u = in.e(kUnits);
    const GLfloat v[1] = {in.f()};
    glMultiTexCoord1fv(u, v);
    break;
  }
  case 120: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord1d(u, in.d());
    break;
  }
  case 121: {
    const GLenum u = in.e(kUnits);
    const GLdouble v[1] = {in.d()};
    glMultiTexCoord1dv(u, v);
    break;
  }
  case 122: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord2s(u, static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()));
    break;
  }
  case 123: {
    const GLenum u = in.e(kUnits);
    const GLshort v[2] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
    glMultiTexCoord2sv(u, v);
    break;
  }
  case 124: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord2i(u, in.i(), in.i());
    break;
  }
  case 125: {
    const GLenum u = in.e(kUnits);
    const GLint v[2] = {in.i(), in.i()};
    glMultiTexCoord2iv(u, v);
    break;
  }
  case 126: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord2f(u, in.f(), in.f());
    break;
  }
  case 127: {
    const GLenum u = in.e(kUnits);
    const GLfloat v[2] = {in.f(), in.f()};
    glMultiTexCoord2fv(u, v);
    break;
  }
  case 128: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord2d(u, in.d(), in.d());
    break;
  }
  case 129: {
    const GLenum u = in.e(kUnits);
    const GLdouble v[2] = {in.d(), in.d()};
    glMultiTexCoord2dv(u, v);
    break;
  }
  case 130: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord3s(u, static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                      static_cast<GLshort>(in.i()));
    break;
  }
  case 131: {
    const GLenum u = in.e(kUnits);
    const GLshort v[3] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                          static_cast<GLshort>(in.i())};
    glMultiTexCoord3sv(u, v);
    break;
  }
  case 132: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord3i(u, in.i(), in.i(), in.i());
    break;
  }
  case 133: {
    const GLenum u = in.e(kUnits);
    const GLint v[3] = {in.i(), in.i(), in.i()};
    glMultiTexCoord3iv(u, v);
    break;
  }
  case 134: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord3f(u, in.f(), in.f(), in.f());
    break;
  }
  case 135: {
    const GLenum u = in.e(kUnits);
    const GLfloat v[3] = {in.f(), in.f(), in.f()};
    glMultiTexCoord3fv(u, v);
    break;
  }
  case 136: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord3d(u, in.d(), in.d(), in.d());
    break;
  }
  case 137: {
    const GLenum u = in.e(kUnits);
    const GLdouble v[3] = {in.d(), in.d(), in.d()};
    glMultiTexCoord3dv(u, v);
    break;
  }
  case 138: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord4s(u, static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                      static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()));
    break;
  }
  case 139: {
    const GLenum u = in.e(kUnits);
    const GLshort v[4] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
                          static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
    glMultiTexCoord4sv(u, v);
    break;
  }
  case 140: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord4i(u, in.i(), in.i(), in.i(), in.i());
    break;
  }
  case 141: {
    const GLenum u = in.e(kUnits);
    const GLint v[4] = {in.i(), in.i(), in.i(), in.i()};
    glMultiTexCoord4iv(u, v);
    break;
  }
  case 142: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord4f(u, in.f(), in.f(), in.f(), in.f());
    break;
  }
  case 143: {
    const GLenum u = in.e(kUnits);
    const GLfloat v[4] = {in.f(), in.f(), in.f(), in.f()};
    glMultiTexCoord4fv(u, v);
    break;
  }
  case 144: {
    const GLenum u = in.e(kUnits);
    glMultiTexCoord4d(u, in.d(), in.d(), in.d(), in.d());
    break;
  }
  default: {
    const GLenum u = in.e(kUnits);
    const GLdouble v[4] = {in.d(), in.d(), in.d(), in.d()};
    glMultiTexCoord4dv(u, v);
    break;
  }
  }
}

} // namespace pineda::fuzz
