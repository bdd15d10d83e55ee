// The errors of every entry point: INVALID_OPERATION between Begin and End for every command
// that is illegal there (GL 2.1 §2.6.3), first-error-wins (§2.5), and each command's own
// INVALID_ENUM / INVALID_VALUE cases leaving state unchanged.
#include <functional>
#include <string>
#include <utility>

#include "api_fixture.h"

namespace {

struct Call {
  const char* name;
  std::function<void()> fn;
};

// Every implemented command that is not allowed between Begin and End.
std::vector<Call> illegal_inside_begin_end() {
  static GLfloat m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  static GLdouble md[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  static GLint iv[16];
  static GLfloat fv[16];
  static GLdouble dv[16];
  static GLboolean bv[16];
  static void* pv;
  static GLuint names[2];
  static uint8_t pixels[64];
  static const GLdouble plane[4] = {1, 0, 0, 0};
  return {
      {"glGetBooleanv", [] { glGetBooleanv(GL_DEPTH_TEST, bv); }},
      {"glGetIntegerv", [] { glGetIntegerv(GL_VIEWPORT, iv); }},
      {"glGetFloatv", [] { glGetFloatv(GL_VIEWPORT, fv); }},
      {"glGetDoublev", [] { glGetDoublev(GL_VIEWPORT, dv); }},
      {"glGetPointerv", [] { glGetPointerv(GL_VERTEX_ARRAY_POINTER, &pv); }},
      {"glGetString", [] { glGetString(GL_VENDOR); }},
      {"glEnable", [] { glEnable(GL_DEPTH_TEST); }},
      {"glDisable", [] { glDisable(GL_DEPTH_TEST); }},
      {"glIsEnabled", [] { glIsEnabled(GL_DEPTH_TEST); }},
      {"glEnableClientState", [] { glEnableClientState(GL_VERTEX_ARRAY); }},
      {"glDisableClientState", [] { glDisableClientState(GL_VERTEX_ARRAY); }},
      {"glHint", [] { glHint(GL_FOG_HINT, GL_NICEST); }},
      {"glFlush", [] { glFlush(); }},
      {"glFinish", [] { glFinish(); }},
      {"glMatrixMode", [] { glMatrixMode(GL_PROJECTION); }},
      {"glLoadIdentity", [] { glLoadIdentity(); }},
      {"glLoadMatrixf", [] { glLoadMatrixf(m); }},
      {"glLoadMatrixd", [] { glLoadMatrixd(md); }},
      {"glMultMatrixf", [] { glMultMatrixf(m); }},
      {"glMultMatrixd", [] { glMultMatrixd(md); }},
      {"glLoadTransposeMatrixf", [] { glLoadTransposeMatrixf(m); }},
      {"glLoadTransposeMatrixd", [] { glLoadTransposeMatrixd(md); }},
      {"glMultTransposeMatrixf", [] { glMultTransposeMatrixf(m); }},
      {"glMultTransposeMatrixd", [] { glMultTransposeMatrixd(md); }},
      {"glRotatef", [] { glRotatef(10, 0, 0, 1); }},
      {"glRotated", [] { glRotated(10, 0, 0, 1); }},
      {"glTranslatef", [] { glTranslatef(1, 0, 0); }},
      {"glTranslated", [] { glTranslated(1, 0, 0); }},
      {"glScalef", [] { glScalef(2, 2, 2); }},
      {"glScaled", [] { glScaled(2, 2, 2); }},
      {"glFrustum", [] { glFrustum(-1, 1, -1, 1, 1, 10); }},
      {"glOrtho", [] { glOrtho(-1, 1, -1, 1, 1, 10); }},
      {"glPushMatrix", [] { glPushMatrix(); }},
      {"glPopMatrix", [] { glPopMatrix(); }},
      {"glViewport", [] { glViewport(0, 0, 4, 4); }},
      {"glDepthRange", [] { glDepthRange(0.2, 0.8); }},
      {"glClipPlane", [] { glClipPlane(GL_CLIP_PLANE0, plane); }},
      {"glGetClipPlane", [] { glGetClipPlane(GL_CLIP_PLANE0, dv); }},
      {"glFrontFace", [] { glFrontFace(GL_CW); }},
      {"glCullFace", [] { glCullFace(GL_FRONT); }},
      {"glPolygonMode", [] { glPolygonMode(GL_FRONT_AND_BACK, GL_LINE); }},
      {"glShadeModel", [] { glShadeModel(GL_FLAT); }},
      {"glDepthFunc", [] { glDepthFunc(GL_GREATER); }},
      {"glDepthMask", [] { glDepthMask(GL_FALSE); }},
      {"glClearDepth", [] { glClearDepth(0.5); }},
      {"glBlendFunc", [] { glBlendFunc(GL_ONE, GL_ONE); }},
      {"glBlendFuncSeparate", [] { glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE); }},
      {"glBlendEquation", [] { glBlendEquation(GL_MAX); }},
      {"glBlendColor", [] { glBlendColor(1, 1, 1, 1); }},
      {"glClear", [] { glClear(GL_COLOR_BUFFER_BIT); }},
      {"glClearColor", [] { glClearColor(1, 0, 0, 1); }},
      {"glClearStencil", [] { glClearStencil(3); }},
      {"glColorMask", [] { glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE); }},
      {"glPixelStorei", [] { glPixelStorei(GL_PACK_ALIGNMENT, 1); }},
      {"glPixelStoref", [] { glPixelStoref(GL_PACK_ALIGNMENT, 1); }},
      {"glReadPixels", [] { glReadPixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels); }},
      {"glBegin", [] { glBegin(GL_POINTS); }},
      {"glRectf", [] { glRectf(0, 0, 1, 1); }},
      {"glVertexPointer", [] { glVertexPointer(3, GL_FLOAT, 0, nullptr); }},
      {"glColorPointer", [] { glColorPointer(4, GL_FLOAT, 0, nullptr); }},
      {"glNormalPointer", [] { glNormalPointer(GL_FLOAT, 0, nullptr); }},
      {"glTexCoordPointer", [] { glTexCoordPointer(2, GL_FLOAT, 0, nullptr); }},
      {"glEdgeFlagPointer", [] { glEdgeFlagPointer(0, nullptr); }},
      {"glDrawArrays", [] { glDrawArrays(GL_TRIANGLES, 0, 3); }},
      {"glDrawElements", [] { glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, pixels); }},
      {"glDrawRangeElements",
       [] { glDrawRangeElements(GL_TRIANGLES, 0, 2, 3, GL_UNSIGNED_BYTE, pixels); }},
      {"glMultiDrawArrays",
       [] {
         GLint first = 0;
         GLsizei count = 3;
         glMultiDrawArrays(GL_TRIANGLES, &first, &count, 1);
       }},
      {"glMultiDrawElements",
       [] {
         GLsizei count = 3;
         const void* idx = pixels;
         glMultiDrawElements(GL_TRIANGLES, &count, GL_UNSIGNED_BYTE, &idx, 1);
       }},
      {"glInterleavedArrays", [] { glInterleavedArrays(GL_V3F, 0, nullptr); }},
      {"glPushClientAttrib", [] { glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS); }},
      {"glPopClientAttrib", [] { glPopClientAttrib(); }},
      {"glGenBuffers", [] { glGenBuffers(2, names); }},
      {"glDeleteBuffers", [] { glDeleteBuffers(2, names); }},
      {"glIsBuffer", [] { glIsBuffer(1); }},
      {"glBindBuffer", [] { glBindBuffer(GL_ARRAY_BUFFER, 1); }},
      {"glBufferData", [] { glBufferData(GL_ARRAY_BUFFER, 4, nullptr, GL_STATIC_DRAW); }},
      {"glBufferSubData", [] { glBufferSubData(GL_ARRAY_BUFFER, 0, 4, pixels); }},
      {"glGetBufferSubData", [] { glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, pixels); }},
      {"glMapBuffer", [] { glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY); }},
      {"glUnmapBuffer", [] { glUnmapBuffer(GL_ARRAY_BUFFER); }},
      {"glGetBufferParameteriv",
       [] { glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, iv); }},
      {"glGetBufferPointerv",
       [] { glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &pv); }},
      {"glLightf", [] { glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 2); }},
      {"glLighti", [] { glLighti(GL_LIGHT0, GL_SPOT_EXPONENT, 2); }},
      {"glLightfv", [] { glLightfv(GL_LIGHT0, GL_AMBIENT, fv); }},
      {"glLightiv", [] { glLightiv(GL_LIGHT0, GL_AMBIENT, iv); }},
      {"glGetLightfv", [] { glGetLightfv(GL_LIGHT0, GL_AMBIENT, fv); }},
      {"glGetLightiv", [] { glGetLightiv(GL_LIGHT0, GL_AMBIENT, iv); }},
      {"glGetMaterialfv", [] { glGetMaterialfv(GL_FRONT, GL_AMBIENT, fv); }},
      {"glGetMaterialiv", [] { glGetMaterialiv(GL_FRONT, GL_AMBIENT, iv); }},
      {"glLightModelf", [] { glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 1); }},
      {"glLightModeli", [] { glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1); }},
      {"glLightModelfv", [] { glLightModelfv(GL_LIGHT_MODEL_AMBIENT, fv); }},
      {"glLightModeliv", [] { glLightModeliv(GL_LIGHT_MODEL_AMBIENT, iv); }},
      {"glColorMaterial", [] { glColorMaterial(GL_FRONT, GL_DIFFUSE); }},
      {"glSecondaryColorPointer", [] { glSecondaryColorPointer(3, GL_FLOAT, 0, nullptr); }},
      {"glScissor", [] { glScissor(0, 0, 4, 4); }},
      {"glAlphaFunc", [] { glAlphaFunc(GL_LESS, 0.5f); }},
      {"glStencilFunc", [] { glStencilFunc(GL_LESS, 1, 0xff); }},
      {"glStencilOp", [] { glStencilOp(GL_KEEP, GL_KEEP, GL_INCR); }},
      {"glStencilMask", [] { glStencilMask(0x0f); }},
      {"glLogicOp", [] { glLogicOp(GL_XOR); }},
      {"glDrawBuffer", [] { glDrawBuffer(GL_FRONT); }},
      {"glReadBuffer", [] { glReadBuffer(GL_FRONT); }},
      {"glPushAttrib", [] { glPushAttrib(GL_ALL_ATTRIB_BITS); }},
      {"glPopAttrib", [] { glPopAttrib(); }},
  };
}

class Errors : public GLTest {};

// Every exported command is either in the list above or allowed between Begin and End
// (GL 2.1 §2.6.3: vertex attributes, EdgeFlag, Material, ArrayElement, CallList(s)).
TEST_F(Errors, EveryCommandIllegalInsideBeginEndGivesInvalidOperation) {
  for (const Call& c : illegal_inside_begin_end()) {
    glBegin(GL_TRIANGLES);
    c.fn();
    glEnd();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION)) << c.name;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << c.name;
  }
}

TEST_F(Errors, StateIsUnchangedByIllegalCallsInsideBeginEnd) {
  glBegin(GL_TRIANGLES);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glMatrixMode(GL_PROJECTION);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_FALSE);
  GLint v = 0;
  glGetIntegerv(GL_DEPTH_FUNC, &v);
  EXPECT_EQ(v, GL_LESS);
  glGetIntegerv(GL_MATRIX_MODE, &v);
  EXPECT_EQ(v, GL_MODELVIEW);
}

TEST_F(Errors, FirstErrorWins) {
  glEnable(0x1234);        // INVALID_ENUM
  glViewport(0, 0, -1, 1); // INVALID_VALUE
  glPopMatrix();           // STACK_UNDERFLOW
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Errors, EndWithoutBeginAndNestedBegin) {
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glBegin(GL_TRIANGLES);
  glBegin(GL_TRIANGLES);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glBegin(GL_POLYGON + 1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glGetError(); // GetError inside Begin/End is itself an error
}

// Each command's own argument errors: (call, expected error).
TEST_F(Errors, InvalidArguments) {
  GLint iv[4];
  uint8_t px[16];
  const std::vector<std::pair<std::function<void()>, GLenum>> cases = {
      {[] { glEnable(GL_TEXTURE_2D + 1000); }, GL_INVALID_ENUM},
      {[] { glDisable(0); }, GL_INVALID_ENUM},
      {[] { glIsEnabled(0); }, GL_INVALID_ENUM},
      {[] { glEnableClientState(GL_DEPTH_TEST); }, GL_INVALID_ENUM},
      {[] { glHint(GL_FOG_HINT, GL_LESS); }, GL_INVALID_ENUM},
      {[] { glHint(GL_LESS, GL_NICEST); }, GL_INVALID_ENUM},
      {[&] { glGetIntegerv(0xdead, iv); }, GL_INVALID_ENUM},
      {[] { glGetString(0xdead); }, GL_INVALID_ENUM},
      {[] { glMatrixMode(GL_COLOR); }, GL_INVALID_ENUM},
      {[] { glFrustum(-1, 1, -1, 1, 0, 10); }, GL_INVALID_VALUE},
      {[] { glFrustum(-1, 1, -1, 1, 1, -10); }, GL_INVALID_VALUE},
      {[] { glFrustum(1, 1, -1, 1, 1, 10); }, GL_INVALID_VALUE},
      {[] { glFrustum(-1, 1, -1, 1, 2, 2); }, GL_INVALID_VALUE},
      {[] { glOrtho(-1, 1, 2, 2, 1, 10); }, GL_INVALID_VALUE},
      {[] { glOrtho(-1, 1, -1, 1, 3, 3); }, GL_INVALID_VALUE},
      {[] { glPopMatrix(); }, GL_STACK_UNDERFLOW},
      {[] { glViewport(0, 0, 1, -1); }, GL_INVALID_VALUE},
      {[] { glClipPlane(GL_CLIP_PLANE0 + 6, nullptr); }, GL_INVALID_ENUM},
      {[] { glFrontFace(GL_FRONT); }, GL_INVALID_ENUM},
      {[] { glCullFace(GL_CW); }, GL_INVALID_ENUM},
      {[] { glPolygonMode(GL_FRONT, GL_FRONT); }, GL_INVALID_ENUM},
      {[] { glPolygonMode(GL_LINE, GL_LINE); }, GL_INVALID_ENUM},
      {[] { glShadeModel(GL_LINE); }, GL_INVALID_ENUM},
      {[] { glDepthFunc(GL_LINE); }, GL_INVALID_ENUM},
      {[] { glBlendFunc(GL_ONE, GL_SRC_ALPHA_SATURATE); }, GL_INVALID_ENUM},
      {[] { glBlendFunc(GL_LESS, GL_ONE); }, GL_INVALID_ENUM},
      {[] { glBlendEquation(GL_ONE); }, GL_INVALID_ENUM},
      {[] { glClear(0x80000000u); }, GL_INVALID_VALUE},
      {[] { glPixelStorei(GL_PACK_ALIGNMENT, 3); }, GL_INVALID_VALUE},
      {[] { glPixelStorei(GL_UNPACK_ROW_LENGTH, -1); }, GL_INVALID_VALUE},
      {[] { glPixelStorei(GL_DEPTH_TEST, 1); }, GL_INVALID_ENUM},
      {[&] { glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px); }, GL_INVALID_VALUE},
      {[&] { glReadPixels(0, 0, 1, 1, GL_LESS, GL_UNSIGNED_BYTE, px); }, GL_INVALID_ENUM},
      {[&] { glReadPixels(0, 0, 1, 1, GL_RGBA, GL_LESS, px); }, GL_INVALID_ENUM},
      {[&] { glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, px); },
       GL_INVALID_OPERATION},
      {[&] { glReadPixels(0, 0, 1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, px); },
       GL_INVALID_OPERATION},
      {[] { glVertexPointer(1, GL_FLOAT, 0, nullptr); }, GL_INVALID_VALUE},
      {[] { glVertexPointer(3, GL_UNSIGNED_BYTE, 0, nullptr); }, GL_INVALID_ENUM},
      {[] { glVertexPointer(3, GL_FLOAT, -4, nullptr); }, GL_INVALID_VALUE},
      {[] { glColorPointer(2, GL_FLOAT, 0, nullptr); }, GL_INVALID_VALUE},
      {[] { glNormalPointer(GL_UNSIGNED_BYTE, 0, nullptr); }, GL_INVALID_ENUM},
      {[] { glTexCoordPointer(5, GL_FLOAT, 0, nullptr); }, GL_INVALID_VALUE},
      {[] { glEdgeFlagPointer(-1, nullptr); }, GL_INVALID_VALUE},
      {[] { glDrawArrays(GL_POLYGON + 1, 0, 3); }, GL_INVALID_ENUM},
      {[] { glDrawArrays(GL_TRIANGLES, 0, -1); }, GL_INVALID_VALUE},
      {[&] { glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, px); }, GL_INVALID_ENUM},
      {[&] { glDrawElements(GL_TRIANGLES, -3, GL_UNSIGNED_BYTE, px); }, GL_INVALID_VALUE},
      {[&] { glDrawRangeElements(GL_TRIANGLES, 5, 2, 3, GL_UNSIGNED_BYTE, px); }, GL_INVALID_VALUE},
      {[] { glMultiDrawArrays(GL_TRIANGLES, nullptr, nullptr, -1); }, GL_INVALID_VALUE},
      {[] { glInterleavedArrays(GL_RGBA, 0, nullptr); }, GL_INVALID_ENUM},
      {[] { glPopClientAttrib(); }, GL_STACK_UNDERFLOW},
      {[] { glGenBuffers(-1, nullptr); }, GL_INVALID_VALUE},
      {[] { glDeleteBuffers(-1, nullptr); }, GL_INVALID_VALUE},
      {[] { glBindBuffer(GL_TEXTURE_2D, 1); }, GL_INVALID_ENUM},
      {[] { glBufferData(GL_ARRAY_BUFFER, 4, nullptr, GL_STATIC_DRAW); }, GL_INVALID_OPERATION},
      {[&] { glBufferSubData(GL_ARRAY_BUFFER, 0, 4, px); }, GL_INVALID_OPERATION},
      {[] { glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY); }, GL_INVALID_OPERATION},
      {[] { glUnmapBuffer(GL_ARRAY_BUFFER); }, GL_INVALID_OPERATION},
  };
  int i = 0;
  for (const auto& [fn, expected] : cases) {
    fn();
    EXPECT_EQ(glGetError(), expected) << "case " << i;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << "case " << i;
    ++i;
  }
}

TEST_F(Errors, ReadPixelsWithoutDepthOrStencilBuffer) {
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
  std::vector<uint8_t> b(16 * 16 * 4);
  ASSERT_EQ(OSMesaMakeCurrent(c, b.data(), GL_UNSIGNED_BYTE, 16, 16), GL_TRUE);
  float z;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_FLOAT, &z);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  OSMesaMakeCurrent(ctx_, buf_.data(), GL_UNSIGNED_BYTE, kW, kH);
  OSMesaDestroyContext(c);
}

TEST(NoContext, CommandsAreNoOps) {
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  glEnable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLES);
  glVertex3f(0, 0, 0);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(glGetString(GL_VERSION), nullptr);
}

} // namespace
