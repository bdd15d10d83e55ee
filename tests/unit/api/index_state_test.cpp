// Colour-index state in an RGBA-only GL (GL 2.1 §2.7, §2.8, §4.2.2, §4.2.3): glIndex*,
// glIndexPointer, glIndexMask and glClearIndex set and query state, are saved by the
// attribute stacks and compile into display lists, and never change what is drawn. Values as
// Mesa llvmpipe reports them.
#include "api_fixture.h"

#include <array>
#include <cstdint>
#include <vector>

namespace {

using IndexState = GLTest;

float current_index() {
  GLfloat f = -99;
  glGetFloatv(GL_CURRENT_INDEX, &f);
  return f;
}

GLint get_int(GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  return v;
}

TEST_F(IndexState, InitialValues) {
  EXPECT_EQ(current_index(), 1.0f);
  EXPECT_EQ(get_int(GL_CURRENT_INDEX), 1);
  EXPECT_EQ(get_int(GL_INDEX_WRITEMASK), -1); // all ones
  GLfloat f = 0;
  glGetFloatv(GL_INDEX_WRITEMASK, &f);
  EXPECT_EQ(f, -1.0f);
  EXPECT_EQ(get_int(GL_INDEX_CLEAR_VALUE), 0);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_STRIDE), 0);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(glIsEnabled(GL_INDEX_ARRAY), GL_FALSE);
  void* p = reinterpret_cast<void*>(1);
  glGetPointerv(GL_INDEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, nullptr);
  GLboolean b = GL_TRUE;
  glGetBooleanv(GL_INDEX_MODE, &b);
  EXPECT_EQ(b, GL_FALSE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// §2.7: every variant converts to floating point without normalization.
TEST_F(IndexState, VariantsSetTheCurrentIndex) {
  glIndexs(-5);
  EXPECT_EQ(current_index(), -5.0f);
  glIndexi(70000);
  EXPECT_EQ(current_index(), 70000.0f);
  glIndexf(2.6f);
  EXPECT_EQ(current_index(), 2.6f);
  EXPECT_EQ(get_int(GL_CURRENT_INDEX), 3); // rounded (§6.1.2)
  glIndexd(-2.5);
  EXPECT_EQ(current_index(), -2.5f);
  EXPECT_EQ(get_int(GL_CURRENT_INDEX), -3);
  glIndexub(200);
  EXPECT_EQ(current_index(), 200.0f);
  glIndexub(255);
  EXPECT_EQ(current_index(), 255.0f);
  const GLshort s = 7;
  glIndexsv(&s);
  EXPECT_EQ(current_index(), 7.0f);
  const GLint i = -8;
  glIndexiv(&i);
  EXPECT_EQ(current_index(), -8.0f);
  const GLfloat f = 9.25f;
  glIndexfv(&f);
  EXPECT_EQ(current_index(), 9.25f);
  const GLdouble d = 10.5;
  glIndexdv(&d);
  EXPECT_EQ(current_index(), 10.5f);
  const GLubyte ub = 11;
  glIndexubv(&ub);
  EXPECT_EQ(current_index(), 11.0f);
  glIndexfv(nullptr); // ignored
  EXPECT_EQ(current_index(), 11.0f);
  GLdouble dv = 0;
  glGetDoublev(GL_CURRENT_INDEX, &dv);
  EXPECT_EQ(dv, 11.0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// §2.6.3, §2.7: Index is legal between Begin and End; the other commands are not.
TEST_F(IndexState, BeginEndLegality) {
  glBegin(GL_POINTS);
  glIndexi(3);
  glIndexub(4);
  glIndexd(5);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(current_index(), 5.0f);

  GLint data[4] = {};
  glBegin(GL_POINTS);
  glIndexMask(3);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);
  glClearIndex(3);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);
  glIndexPointer(GL_INT, 0, data);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_INDEX_WRITEMASK), -1);
  EXPECT_EQ(get_int(GL_INDEX_CLEAR_VALUE), 0);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_TYPE), GL_FLOAT);
}

TEST_F(IndexState, IndexMaskKeepsAllBits) {
  glIndexMask(0x12345678u);
  EXPECT_EQ(get_int(GL_INDEX_WRITEMASK), 0x12345678);
  glIndexMask(0x80000001u);
  EXPECT_EQ(static_cast<uint32_t>(get_int(GL_INDEX_WRITEMASK)), 0x80000001u);
  glIndexMask(0);
  GLboolean b = GL_TRUE;
  glGetBooleanv(GL_INDEX_WRITEMASK, &b);
  EXPECT_EQ(b, GL_FALSE);
}

// §4.2.3: the integer part of the clear index (truncated toward zero, as in Mesa).
TEST_F(IndexState, ClearIndexKeepsTheIntegerPart) {
  glClearIndex(2.7f);
  EXPECT_EQ(get_int(GL_INDEX_CLEAR_VALUE), 2);
  GLfloat f = 0;
  glGetFloatv(GL_INDEX_CLEAR_VALUE, &f);
  EXPECT_EQ(f, 2.0f);
  glClearIndex(-3.2f);
  EXPECT_EQ(get_int(GL_INDEX_CLEAR_VALUE), -3);
  glClearIndex(1e20f); // no undefined conversion
  EXPECT_EQ(get_int(GL_INDEX_CLEAR_VALUE), 2147483647);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// §2.8, Table 2.4: UNSIGNED_BYTE, SHORT, INT, FLOAT, DOUBLE; negative stride INVALID_VALUE.
TEST_F(IndexState, IndexPointerTypesAndErrors) {
  std::array<uint8_t, 64> data{};
  for (GLenum t : {GL_UNSIGNED_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}) {
    glIndexPointer(t, 16, data.data());
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    EXPECT_EQ(get_int(GL_INDEX_ARRAY_TYPE), static_cast<GLint>(t));
  }
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_STRIDE), 16);
  void* p = nullptr;
  glGetPointerv(GL_INDEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, data.data());
  for (GLenum t : {GL_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT, GL_RGB}) {
    glIndexPointer(t, 0, nullptr);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  }
  glIndexPointer(GL_INT, -1, nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  // First error wins and nothing changes.
  glIndexPointer(GL_BYTE, -1, nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_TYPE), GL_DOUBLE);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_STRIDE), 16);
}

TEST_F(IndexState, IndexPointerTakesTheArrayBuffer) {
  GLuint buf = 0;
  glGenBuffers(1, &buf);
  glBindBuffer(GL_ARRAY_BUFFER, buf);
  glIndexPointer(GL_SHORT, 0, reinterpret_cast<void*>(8));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_BUFFER_BINDING), static_cast<GLint>(buf));
  glDeleteBuffers(1, &buf);
}

TEST_F(IndexState, ArrayEnableAndClientAttribStack) {
  glEnableClientState(GL_INDEX_ARRAY);
  EXPECT_EQ(glIsEnabled(GL_INDEX_ARRAY), GL_TRUE);
  GLboolean b = GL_FALSE;
  glGetBooleanv(GL_INDEX_ARRAY, &b);
  EXPECT_EQ(b, GL_TRUE);
  GLint data[2] = {};
  glIndexPointer(GL_INT, 4, data);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glDisableClientState(GL_INDEX_ARRAY);
  glIndexPointer(GL_SHORT, 8, nullptr);
  EXPECT_EQ(glIsEnabled(GL_INDEX_ARRAY), GL_FALSE);
  glPopClientAttrib();
  EXPECT_EQ(glIsEnabled(GL_INDEX_ARRAY), GL_TRUE);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_TYPE), GL_INT);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_STRIDE), 4);
  void* p = nullptr;
  glGetPointerv(GL_INDEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, data);
  // §2.8: InterleavedArrays disables the index (and fog coordinate) arrays.
  glEnableClientState(GL_FOG_COORD_ARRAY);
  const float v[2] = {};
  glInterleavedArrays(GL_V2F, 0, v);
  EXPECT_EQ(glIsEnabled(GL_INDEX_ARRAY), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_FOG_COORD_ARRAY), GL_FALSE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// §6.1.14: CURRENT_BIT saves the current index, COLOR_BUFFER_BIT the clear index and mask.
TEST_F(IndexState, PushAttrib) {
  glIndexi(9);
  glClearIndex(5);
  glIndexMask(7);
  glPushAttrib(GL_CURRENT_BIT | GL_COLOR_BUFFER_BIT);
  glIndexi(1);
  glClearIndex(1);
  glIndexMask(1);
  glPopAttrib();
  EXPECT_EQ(current_index(), 9.0f);
  EXPECT_EQ(get_int(GL_INDEX_CLEAR_VALUE), 5);
  EXPECT_EQ(get_int(GL_INDEX_WRITEMASK), 7);

  glPushAttrib(GL_CURRENT_BIT);
  glIndexi(2);
  glClearIndex(2);
  glIndexMask(2);
  glPopAttrib();
  EXPECT_EQ(current_index(), 9.0f);
  EXPECT_EQ(get_int(GL_INDEX_CLEAR_VALUE), 2); // not in CURRENT_BIT
  EXPECT_EQ(get_int(GL_INDEX_WRITEMASK), 2);

  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glIndexi(3);
  glClearIndex(3);
  glIndexMask(3);
  glPopAttrib();
  EXPECT_EQ(current_index(), 3.0f); // not in COLOR_BUFFER_BIT
  EXPECT_EQ(get_int(GL_INDEX_CLEAR_VALUE), 2);
  EXPECT_EQ(get_int(GL_INDEX_WRITEMASK), 2);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// §5.4: the commands compile; Index runs in order with the other commands of the list, also
// inside a Begin/End block; IndexPointer executes at once.
TEST_F(IndexState, DisplayLists) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glIndexi(42);
  glIndexMask(3);
  glClearIndex(4);
  glIndexPointer(GL_SHORT, 2, nullptr);
  glEndList();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(current_index(), 1.0f);
  EXPECT_EQ(get_int(GL_INDEX_WRITEMASK), -1);
  EXPECT_EQ(get_int(GL_INDEX_ARRAY_TYPE), GL_SHORT); // executed immediately
  glCallList(list);
  EXPECT_EQ(current_index(), 42.0f);
  EXPECT_EQ(get_int(GL_INDEX_WRITEMASK), 3);
  EXPECT_EQ(get_int(GL_INDEX_CLEAR_VALUE), 4);

  const GLuint block = glGenLists(1);
  glNewList(block, GL_COMPILE_AND_EXECUTE);
  glBegin(GL_POINTS);
  glIndexf(6);
  glVertex2f(0, 0);
  glIndexub(7);
  glEnd();
  glEndList();
  EXPECT_EQ(current_index(), 7.0f);
  glIndexi(0);
  glCallList(block);
  EXPECT_EQ(current_index(), 7.0f);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glDeleteLists(list, 1);
  glDeleteLists(block, 1);
}

void draw_scene() {
  glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0.5f, 0.25f);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(0, 1);
  glEnd();
  std::vector<float> v = {-0.5f, 0.5f, 0.5f, 0.5f, 0.0f, -0.9f};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, v.data());
  glColor3f(0, 1, 0);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisableClientState(GL_VERTEX_ARRAY);
  glFinish();
}

// §2.7, §4.2.2-§4.2.3: in RGBA mode none of the index state changes the pixels drawn.
TEST_F(IndexState, NoEffectOnRgbaRendering) {
  draw_scene();
  const std::vector<uint8_t> reference = buf_;
  glIndexMask(0);
  glClearIndex(77);
  glIndexi(12);
  std::vector<GLint> idx = {1, 2, 3};
  glIndexPointer(GL_INT, 0, idx.data());
  glEnableClientState(GL_INDEX_ARRAY);
  std::fill(buf_.begin(), buf_.end(), 0);
  glBegin(GL_POINTS);
  glIndexf(3);
  glEnd();
  draw_scene();
  EXPECT_EQ(buf_, reference);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

} // namespace
