// State queries: initial values (GL 2.1 chapter 6 tables), set/get round trips, type
// conversions (§6.1.2), matrices against a GLM reference, and the stacks' limits.
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <climits>
#include <cmath>

#include "api_fixture.h"

namespace {

class State : public GLTest {};

GLint geti(GLenum pname) {
  GLint v[16] = {};
  glGetIntegerv(pname, v);
  return v[0];
}

TEST_F(State, InitialValues) {
  EXPECT_EQ(geti(GL_MATRIX_MODE), GL_MODELVIEW);
  EXPECT_EQ(geti(GL_DEPTH_FUNC), GL_LESS);
  EXPECT_EQ(geti(GL_CULL_FACE_MODE), GL_BACK);
  EXPECT_EQ(geti(GL_FRONT_FACE), GL_CCW);
  EXPECT_EQ(geti(GL_SHADE_MODEL), GL_SMOOTH);
  EXPECT_EQ(geti(GL_BLEND_SRC), GL_ONE);
  EXPECT_EQ(geti(GL_BLEND_DST), GL_ZERO);
  EXPECT_EQ(geti(GL_BLEND_EQUATION), GL_FUNC_ADD);
  EXPECT_EQ(geti(GL_PACK_ALIGNMENT), 4);
  EXPECT_EQ(geti(GL_UNPACK_ALIGNMENT), 4);
  EXPECT_EQ(geti(GL_SUBPIXEL_BITS), 8);
  EXPECT_EQ(geti(GL_DEPTH_BITS), 24);
  EXPECT_EQ(geti(GL_STENCIL_BITS), 8);
  EXPECT_EQ(geti(GL_RED_BITS), 8);
  EXPECT_EQ(geti(GL_ALPHA_BITS), 8);
  EXPECT_EQ(geti(GL_MODELVIEW_STACK_DEPTH), 1);
  EXPECT_GE(geti(GL_MAX_MODELVIEW_STACK_DEPTH), 32);
  EXPECT_GE(geti(GL_MAX_PROJECTION_STACK_DEPTH), 2);
  EXPECT_GE(geti(GL_MAX_CLIP_PLANES), 6);
  GLint vp[4];
  glGetIntegerv(GL_VIEWPORT, vp);
  EXPECT_EQ(vp[0], 0);
  EXPECT_EQ(vp[1], 0);
  EXPECT_EQ(vp[2], kW);
  EXPECT_EQ(vp[3], kH);
  GLint pm[2];
  glGetIntegerv(GL_POLYGON_MODE, pm);
  EXPECT_EQ(pm[0], GL_FILL);
  EXPECT_EQ(pm[1], GL_FILL);
  GLboolean cm[4];
  glGetBooleanv(GL_COLOR_WRITEMASK, cm);
  for (GLboolean b : cm)
    EXPECT_EQ(b, GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_DITHER), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_FALSE);
  GLfloat c[4];
  glGetFloatv(GL_CURRENT_COLOR, c);
  for (GLfloat f : c)
    EXPECT_EQ(f, 1.0f);
  GLdouble dr[2];
  glGetDoublev(GL_DEPTH_RANGE, dr);
  EXPECT_EQ(dr[0], 0.0);
  EXPECT_EQ(dr[1], 1.0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// The version number itself is checked against the registry in version_test.cpp.
TEST_F(State, StringsAreHonest) {
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  ASSERT_NE(version, nullptr);
  EXPECT_EQ(std::string(version).substr(0, 4), "2.1 ");
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(glGetString(GL_SHADING_LANGUAGE_VERSION))),
            "1.20");
  EXPECT_NE(std::string(reinterpret_cast<const char*>(glGetString(GL_RENDERER))).find("Pineda"),
            std::string::npos);
  EXPECT_NE(glGetString(GL_EXTENSIONS), nullptr);
}

TEST_F(State, RoundTrips) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GEQUAL);
  glCullFace(GL_FRONT_AND_BACK);
  glFrontFace(GL_CW);
  glPolygonMode(GL_BACK, GL_POINT);
  glShadeModel(GL_FLAT);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO);
  glBlendEquation(GL_MIN);
  glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
  glViewport(1, 2, 30, 20);
  glDepthRange(2.0, -1.0); // clamped
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glClearStencil(7);
  glPixelStorei(GL_PACK_ROW_LENGTH, 9);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_TRUE);
  EXPECT_EQ(geti(GL_DEPTH_FUNC), GL_GEQUAL);
  EXPECT_EQ(geti(GL_CULL_FACE_MODE), GL_FRONT_AND_BACK);
  EXPECT_EQ(geti(GL_FRONT_FACE), GL_CW);
  GLint pm[2];
  glGetIntegerv(GL_POLYGON_MODE, pm);
  EXPECT_EQ(pm[0], GL_FILL);
  EXPECT_EQ(pm[1], GL_POINT);
  EXPECT_EQ(geti(GL_SHADE_MODEL), GL_FLAT);
  EXPECT_EQ(geti(GL_BLEND_SRC_RGB), GL_SRC_ALPHA);
  EXPECT_EQ(geti(GL_BLEND_DST_RGB), GL_ONE_MINUS_SRC_ALPHA);
  EXPECT_EQ(geti(GL_BLEND_SRC_ALPHA), GL_ONE);
  EXPECT_EQ(geti(GL_BLEND_DST_ALPHA), GL_ZERO);
  EXPECT_EQ(geti(GL_BLEND_EQUATION), GL_MIN);
  EXPECT_EQ(geti(GL_PERSPECTIVE_CORRECTION_HINT), GL_NICEST);
  GLint vp[4];
  glGetIntegerv(GL_VIEWPORT, vp);
  EXPECT_EQ(vp[0], 1);
  EXPECT_EQ(vp[3], 20);
  GLfloat dr[2];
  glGetFloatv(GL_DEPTH_RANGE, dr);
  EXPECT_EQ(dr[0], 1.0f);
  EXPECT_EQ(dr[1], 0.0f);
  GLboolean cm[4];
  glGetBooleanv(GL_COLOR_WRITEMASK, cm);
  EXPECT_EQ(cm[1], GL_FALSE);
  EXPECT_EQ(cm[2], GL_TRUE);
  GLboolean dm;
  glGetBooleanv(GL_DEPTH_WRITEMASK, &dm);
  EXPECT_EQ(dm, GL_FALSE);
  EXPECT_EQ(geti(GL_STENCIL_CLEAR_VALUE), 7);
  EXPECT_EQ(geti(GL_PACK_ROW_LENGTH), 9);
}

TEST_F(State, ConversionsFollowSection612) {
  glClearColor(1.0f, 0.0f, 0.5f, 0.25f);
  GLint c[4];
  glGetIntegerv(GL_COLOR_CLEAR_VALUE, c);
  EXPECT_EQ(c[0], INT_MAX);
  EXPECT_EQ(c[1], 0);
  EXPECT_NEAR(static_cast<double>(c[2]), 0.5 * INT_MAX, 2.0);
  glClearColor(-3.0f, 2.0f, 0.0f, 0.0f); // clamped to [0,1]
  GLfloat f[4];
  glGetFloatv(GL_COLOR_CLEAR_VALUE, f);
  EXPECT_EQ(f[0], 0.0f);
  EXPECT_EQ(f[1], 1.0f);
  GLboolean b;
  glGetBooleanv(GL_DEPTH_FUNC, &b);
  EXPECT_EQ(b, GL_TRUE);
  glColor4ub(255, 0, 128, 255);
  glGetFloatv(GL_CURRENT_COLOR, f);
  EXPECT_FLOAT_EQ(f[2], 128.0f / 255.0f);
  glColor3b(127, -128, 0); // (2c+1)/255
  glGetFloatv(GL_CURRENT_COLOR, f);
  EXPECT_FLOAT_EQ(f[0], 1.0f);
  EXPECT_FLOAT_EQ(f[1], -1.0f);
  EXPECT_FLOAT_EQ(f[3], 1.0f);
}

void expect_matrix(GLenum pname, const glm::mat4& ref) {
  GLfloat m[16];
  glGetFloatv(pname, m);
  const float* r = glm::value_ptr(ref);
  for (int i = 0; i < 16; ++i)
    EXPECT_NEAR(m[i], r[i], 1e-5f) << "element " << i;
}

TEST_F(State, MatricesMatchReference) {
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(1, 2, 3);
  glRotatef(30, 1, 1, 0);
  glScalef(2, 3, 4);
  glm::mat4 ref(1.0f);
  ref = glm::translate(ref, glm::vec3(1, 2, 3));
  ref = glm::rotate(ref, glm::radians(30.0f), glm::normalize(glm::vec3(1, 1, 0)));
  ref = glm::scale(ref, glm::vec3(2, 3, 4));
  expect_matrix(GL_MODELVIEW_MATRIX, ref);
  expect_matrix(GL_TRANSPOSE_MODELVIEW_MATRIX, glm::transpose(ref));

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 2, -3, 4, 1.5, 100);
  expect_matrix(GL_PROJECTION_MATRIX, glm::frustum(-1.0f, 2.0f, -3.0f, 4.0f, 1.5f, 100.0f));
  glLoadIdentity();
  glOrtho(-1, 2, -3, 4, -5, 6);
  expect_matrix(GL_PROJECTION_MATRIX, glm::ortho(-1.0f, 2.0f, -3.0f, 4.0f, -5.0f, 6.0f));

  const GLfloat rows[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
  glLoadTransposeMatrixf(rows);
  expect_matrix(GL_PROJECTION_MATRIX, glm::transpose(glm::make_mat4(rows)));
  glLoadIdentity();
  glMultTransposeMatrixf(rows);
  expect_matrix(GL_PROJECTION_MATRIX, glm::transpose(glm::make_mat4(rows)));
  const GLdouble cols[16] = {2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 1, 1, 1, 1};
  glLoadMatrixd(cols);
  glMultMatrixd(cols);
  glm::mat4 c(1.0f);
  for (int i = 0; i < 16; ++i)
    glm::value_ptr(c)[i] = static_cast<float>(cols[i]);
  expect_matrix(GL_PROJECTION_MATRIX, c * c);
}

TEST_F(State, StackLimits) {
  const GLint depth = geti(GL_MAX_MODELVIEW_STACK_DEPTH);
  for (GLint i = 1; i < depth; ++i)
    glPushMatrix();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(geti(GL_MODELVIEW_STACK_DEPTH), depth);
  glTranslatef(5, 0, 0);
  glPushMatrix();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_STACK_OVERFLOW));
  EXPECT_EQ(geti(GL_MODELVIEW_STACK_DEPTH), depth);
  for (GLint i = 1; i < depth; ++i)
    glPopMatrix();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glPopMatrix();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_STACK_UNDERFLOW));
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  EXPECT_EQ(m[12], 0.0f); // the translated copy was popped

  glMatrixMode(GL_PROJECTION);
  const GLint pdepth = geti(GL_MAX_PROJECTION_STACK_DEPTH);
  for (GLint i = 1; i < pdepth; ++i)
    glPushMatrix();
  glPushMatrix();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_STACK_OVERFLOW));
}

TEST_F(State, ClipPlaneStoredInEyeSpace) {
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(0, 0, -5);
  const GLdouble p[4] = {0, 0, 1, 0};
  glClipPlane(GL_CLIP_PLANE2, p);
  GLdouble e[4];
  glGetClipPlane(GL_CLIP_PLANE2, e);
  // plane * inverse(T(0,0,-5)) = (0,0,1,5)
  EXPECT_DOUBLE_EQ(e[2], 1.0);
  EXPECT_DOUBLE_EQ(e[3], 5.0);
  glEnable(GL_CLIP_PLANE2);
  EXPECT_EQ(glIsEnabled(GL_CLIP_PLANE2), GL_TRUE);
}

TEST_F(State, ClientAttribStackRestoresArrays) {
  GLfloat data[6] = {};
  glVertexPointer(2, GL_FLOAT, 8, data);
  glEnableClientState(GL_VERTEX_ARRAY);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  glDisableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_SHORT, 0, nullptr);
  glPixelStorei(GL_PACK_ALIGNMENT, 8);
  glPopClientAttrib();
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_TRUE);
  EXPECT_EQ(geti(GL_VERTEX_ARRAY_SIZE), 2);
  EXPECT_EQ(geti(GL_VERTEX_ARRAY_STRIDE), 8);
  EXPECT_EQ(geti(GL_PACK_ALIGNMENT), 1);
  void* p = nullptr;
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, data);
  glInterleavedArrays(GL_T2F_C4UB_V3F, 0, data);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_COORD_ARRAY), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_COLOR_ARRAY), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_NORMAL_ARRAY), GL_FALSE);
  EXPECT_EQ(geti(GL_COLOR_ARRAY_TYPE), GL_UNSIGNED_BYTE);
  EXPECT_EQ(geti(GL_VERTEX_ARRAY_STRIDE), 24);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(State, BufferObjects) {
  GLuint b[2];
  glGenBuffers(2, b);
  EXPECT_NE(b[0], b[1]);
  EXPECT_EQ(glIsBuffer(b[0]), GL_FALSE); // a name only, until bound
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  EXPECT_EQ(glIsBuffer(b[0]), GL_TRUE);
  const uint8_t src[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  glBufferData(GL_ARRAY_BUFFER, 8, src, GL_DYNAMIC_DRAW);
  glBufferSubData(GL_ARRAY_BUFFER, 2, 2, src);
  uint8_t got[8] = {};
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 8, got);
  EXPECT_EQ(got[2], 1);
  EXPECT_EQ(got[3], 2);
  EXPECT_EQ(got[7], 8);
  glBufferSubData(GL_ARRAY_BUFFER, 6, 4, src);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  GLint v = 0;
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
  EXPECT_EQ(v, 8);
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_USAGE, &v);
  EXPECT_EQ(v, GL_DYNAMIC_DRAW);
  auto* p = static_cast<uint8_t*>(glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY));
  ASSERT_NE(p, nullptr);
  p[0] = 42;
  glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  void* mp = nullptr;
  glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &mp);
  EXPECT_EQ(mp, p);
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED, &v);
  EXPECT_EQ(v, GL_TRUE);
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 1, got);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  // Drawing from a mapped buffer is an error.
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_POINTS, 0, 1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 1, got);
  EXPECT_EQ(got[0], 42);
  EXPECT_EQ(geti(GL_VERTEX_ARRAY_BUFFER_BINDING), static_cast<GLint>(b[0]));
  glDeleteBuffers(2, b);
  EXPECT_EQ(geti(GL_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(geti(GL_VERTEX_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(glIsBuffer(b[0]), GL_FALSE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(State, OutOfRangeBufferDrawIsIgnoredSafely) {
  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  const float tri[6] = {-1, -1, 1, -1, 0, 1};
  glBufferData(GL_ARRAY_BUFFER, sizeof(tri), tri, GL_STATIC_DRAW);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLES, 0, 3000000); // far past the buffer: nothing is read
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glDeleteBuffers(1, &b);
}

} // namespace
