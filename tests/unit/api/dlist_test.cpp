// Display lists (GL 2.1 §5.4): compile and execute semantics, CallLists offsets of every type
// with ListBase, nesting, name management, errors (generated when the list executes), the
// commands executed immediately while compiling, client data copied at compile time, shared
// lists, and compiled geometry drawing exactly what immediate mode draws.
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "api_fixture.h"
#include "dispatch.h"

namespace {

using DList = GLTest;

GLint get_int(GLenum pname) {
  GLint v = -1;
  glGetIntegerv(pname, &v);
  return v;
}

std::vector<float> current_color() {
  std::vector<float> c(4);
  glGetFloatv(GL_CURRENT_COLOR, c.data());
  return c;
}

float modelview_x() {
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  return m[12];
}

// The generated save table (src/api/dlist_*.txt): §5.4's immediate commands execute, the
// others are saved by generated or hand-written savers.
TEST(DListSaveTable, ImmediateGeneratedAndHandWritten) {
  const pineda::Dispatch& save = pineda::kSaveDispatch;
  EXPECT_EQ(save.GetIntegerv, &pineda::exec::GetIntegerv);
  EXPECT_EQ(save.GenLists, &pineda::exec::GenLists);
  EXPECT_EQ(save.EndList, &pineda::exec::EndList);
  EXPECT_EQ(save.VertexPointer, &pineda::exec::VertexPointer);
  EXPECT_EQ(save.PixelStorei, &pineda::exec::PixelStorei);
  EXPECT_EQ(save.Flush, &pineda::exec::Flush);
  EXPECT_NE(save.Rotatef, &pineda::exec::Rotatef);
  EXPECT_NE(save.Enable, &pineda::exec::Enable);
  EXPECT_NE(save.ListBase, &pineda::exec::ListBase);
  EXPECT_EQ(save.Begin, &pineda::saver::Begin);
  EXPECT_EQ(save.CallLists, &pineda::saver::CallLists);
  EXPECT_EQ(save.Lightfv, &pineda::saver::Lightfv);
}

TEST_F(DList, Queries) {
  EXPECT_EQ(get_int(GL_LIST_BASE), 0);
  EXPECT_EQ(get_int(GL_LIST_INDEX), 0);
  EXPECT_EQ(get_int(GL_LIST_MODE), 0);
  EXPECT_GE(get_int(GL_MAX_LIST_NESTING), 64);
  glNewList(7, GL_COMPILE);
  EXPECT_EQ(get_int(GL_LIST_INDEX), 7); // Get* executes immediately (§5.4)
  EXPECT_EQ(get_int(GL_LIST_MODE), GL_COMPILE);
  glEndList();
  glNewList(8, GL_COMPILE_AND_EXECUTE);
  EXPECT_EQ(get_int(GL_LIST_MODE), GL_COMPILE_AND_EXECUTE);
  glEndList();
  EXPECT_EQ(get_int(GL_LIST_INDEX), 0);
  EXPECT_EQ(get_int(GL_LIST_MODE), 0);
  glListBase(1234);
  EXPECT_EQ(get_int(GL_LIST_BASE), 1234);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(DList, Errors) {
  glNewList(0, GL_COMPILE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  glNewList(1, 0x1234);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glEndList();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glCallList(0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  glCallLists(-1, 0x1234, nullptr); // the type is checked first, as Mesa does
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glCallLists(-1, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(glGenLists(-1), 0u);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(glGenLists(0), 0u);
  glDeleteLists(1, -1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  glNewList(1, GL_COMPILE);
  glNewList(2, GL_COMPILE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_LIST_INDEX), 1);
  glEndList();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(glIsList(2), GL_FALSE);
  // Nothing happens for names without a list.
  glCallList(999);
  const GLuint none[2] = {998, 997};
  glCallLists(2, GL_UNSIGNED_INT, none);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// GL 2.1 §2.6.3: only CallList and CallLists of the list commands are legal between Begin and
// End.
TEST_F(DList, InsideBeginEnd) {
  glNewList(1, GL_COMPILE);
  glEndList();
  // glGetError itself is illegal between Begin and End: each command gets its own pair.
  auto inside = [](auto command) {
    glBegin(GL_POINTS);
    command();
    glEnd();
    return glGetError();
  };
  const GLenum op = GL_INVALID_OPERATION;
  EXPECT_EQ(inside([] { glNewList(2, GL_COMPILE); }), op);
  EXPECT_EQ(get_int(GL_LIST_INDEX), 0);
  EXPECT_EQ(inside([] { glEndList(); }), op);
  EXPECT_EQ(inside([] { EXPECT_EQ(glGenLists(1), 0u); }), op);
  EXPECT_EQ(inside([] { glDeleteLists(1, 1); }), op);
  EXPECT_EQ(inside([] { EXPECT_EQ(glIsList(1), GL_FALSE); }), op);
  EXPECT_EQ(inside([] { glListBase(3); }), op);
  EXPECT_EQ(inside([] { glCallList(1); }), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(inside([] {
              const GLubyte one = 1;
              glCallLists(1, GL_UNSIGNED_BYTE, &one);
            }),
            static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(get_int(GL_LIST_BASE), 0);
  EXPECT_EQ(glIsList(1), GL_TRUE);
}

TEST_F(DList, CompileDoesNotExecute) {
  glColor3f(0, 0, 1);
  glNewList(1, GL_COMPILE);
  glColor3f(1, 0, 0);
  glTranslatef(5, 0, 0);
  glListBase(9);
  glEndList();
  EXPECT_EQ(current_color(), (std::vector<float>{0, 0, 1, 1}));
  EXPECT_EQ(modelview_x(), 0.0f);
  EXPECT_EQ(get_int(GL_LIST_BASE), 0);
  glCallList(1);
  EXPECT_EQ(current_color(), (std::vector<float>{1, 0, 0, 1}));
  EXPECT_EQ(modelview_x(), 5.0f);
  EXPECT_EQ(get_int(GL_LIST_BASE), 9);
  glCallList(1);
  EXPECT_EQ(modelview_x(), 10.0f);
}

TEST_F(DList, CompileAndExecute) {
  glNewList(1, GL_COMPILE_AND_EXECUTE);
  glColor3f(0, 1, 0);
  glTranslatef(2, 0, 0);
  EXPECT_EQ(current_color(), (std::vector<float>{0, 1, 0, 1}));
  EXPECT_EQ(modelview_x(), 2.0f);
  glEndList();
  glCallList(1);
  EXPECT_EQ(modelview_x(), 4.0f);
  // An error in COMPILE_AND_EXECUTE is generated by the execution and again by each call.
  glNewList(2, GL_COMPILE_AND_EXECUTE);
  glEnable(0x1234);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glEndList();
  glCallList(2);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
}

// GL 2.1 §5.4: a list under construction is associated with its name only at EndList, so a
// list that calls its own name calls the previous list of that name.
TEST_F(DList, ReplacedAtEndList) {
  glNewList(1, GL_COMPILE);
  glTranslatef(1, 0, 0);
  glEndList();
  glNewList(1, GL_COMPILE_AND_EXECUTE);
  glCallList(1);
  glTranslatef(10, 0, 0);
  EXPECT_EQ(modelview_x(), 11.0f);
  glEndList();
  // Now CallList(1) inside list 1 is the new list itself: +10 at each of the 64 levels.
  glLoadIdentity();
  glCallList(1);
  EXPECT_EQ(modelview_x(), 10.0f * static_cast<float>(get_int(GL_MAX_LIST_NESTING)));
}

TEST_F(DList, ErrorsAtExecutionNotCompilation) {
  glNewList(1, GL_COMPILE);
  glBegin(0x99);    // INVALID_ENUM when executed
  glEnable(0x1234); // INVALID_ENUM
  glCallList(0);    // INVALID_VALUE
  glCallLists(1, 0x1234, nullptr);
  glDrawArrays(0x99, 0, 3);
  glEndList();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glCallList(1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM)); // the first error wins
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // A command illegal between Begin and End inside a compiled block fails when executed; the
  // rest of the block still draws.
  glNewList(2, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glVertex2f(-1, -1);
  glRotatef(30, 0, 0, 1);
  glVertex2f(1, -1);
  glVertex2f(-1, 1);
  glEnd();
  glEndList();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glCallList(2);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(modelview_x(), 0.0f);
  EXPECT_EQ(pixel(4, 4), 0xffffffffu);
}

// §5.4: these execute immediately while a list is compiled, and are not in the list.
TEST_F(DList, ImmediateCommands) {
  GLfloat verts[6] = {-1, -1, 1, -1, -1, 1};
  glNewList(1, GL_COMPILE);
  GLuint base = glGenLists(2);
  EXPECT_NE(base, 0u);
  EXPECT_EQ(glIsList(base), GL_TRUE);
  glDeleteLists(base, 1);
  EXPECT_EQ(glIsList(base), GL_FALSE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  EXPECT_EQ(get_int(GL_UNPACK_ALIGNMENT), 2);
  glEnableClientState(GL_VERTEX_ARRAY);
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_TRUE);
  glVertexPointer(2, GL_FLOAT, 0, verts);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glPopClientAttrib();
  EXPECT_EQ(get_int(GL_UNPACK_ALIGNMENT), 2);
  GLuint buf = 0;
  glGenBuffers(1, &buf);
  glBindBuffer(GL_ARRAY_BUFFER, buf);
  EXPECT_EQ(get_int(GL_ARRAY_BUFFER_BINDING), static_cast<GLint>(buf));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glEnable(0x1234); // compiled: no error now
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glFlush();
  glFinish();
  glEndList();
  // Executing the list changes none of that state again.
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glDisableClientState(GL_VERTEX_ARRAY);
  glCallList(1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_UNPACK_ALIGNMENT), 4);
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_FALSE);
  EXPECT_EQ(glIsList(base + 1), GL_TRUE);
}

// Each list n..n+5 appends its tag to a decimal number in the model-view translation:
// M := M * T(tag) * S(10), so after lists a, b, c the x translation is a + 10 b + 100 c.
class CallListsTypes : public GLTest {
protected:
  void SetUp() override {
    GLTest::SetUp();
    first_ = glGenLists(8);
    ASSERT_NE(first_, 0u);
    for (GLuint i = 0; i < 8; ++i) {
      glNewList(first_ + i, GL_COMPILE);
      glTranslatef(static_cast<float>(i), 0, 0);
      glScalef(10, 1, 1);
      glEndList();
    }
  }
  float run(GLuint base, GLsizei n, GLenum type, const void* lists) {
    glLoadIdentity();
    glListBase(base);
    glCallLists(n, type, lists);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    return modelview_x();
  }
  GLuint first_ = 0;
};

TEST_F(CallListsTypes, EveryType) {
  const GLbyte b[3] = {1, 2, 3};
  EXPECT_EQ(run(first_, 3, GL_BYTE, b), 321.0f);
  const GLbyte neg[2] = {-1, -2}; // negative offsets with a base above them
  EXPECT_EQ(run(first_ + 3, 2, GL_BYTE, neg), 12.0f);
  const GLubyte ub[2] = {4, 5};
  EXPECT_EQ(run(first_, 2, GL_UNSIGNED_BYTE, ub), 54.0f);
  const GLshort s[2] = {6, -1};
  EXPECT_EQ(run(first_ + 1, 2, GL_SHORT, s), 7.0f);
  const GLushort us[2] = {7, 1};
  EXPECT_EQ(run(first_, 2, GL_UNSIGNED_SHORT, us), 17.0f);
  const GLint i[3] = {2, 0, 3};
  EXPECT_EQ(run(first_, 3, GL_INT, i), 302.0f);
  const GLuint ui[2] = {3, 3};
  EXPECT_EQ(run(first_, 2, GL_UNSIGNED_INT, ui), 33.0f);
  const GLfloat f[3] = {2.9f, 0.5f, 5.0f}; // truncated
  EXPECT_EQ(run(first_, 3, GL_FLOAT, f), 502.0f);
  const GLubyte two[4] = {0, 3, 0, 6}; // big-endian pairs
  EXPECT_EQ(run(first_, 2, GL_2_BYTES, two), 63.0f);
  const GLubyte three[6] = {0, 0, 1, 0, 0, 4};
  EXPECT_EQ(run(first_, 2, GL_3_BYTES, three), 41.0f);
  const GLubyte four[4] = {0, 0, 0, 5};
  EXPECT_EQ(run(first_, 1, GL_4_BYTES, four), 5.0f);
  // With base 0 the offsets are the names themselves.
  const GLuint names[2] = {first_ + 1, first_ + 2};
  EXPECT_EQ(run(0, 2, GL_UNSIGNED_INT, names), 21.0f);
  // 1 + 256 * first_ + ... : a 2-byte offset that overflows into the high byte.
  const GLubyte high[2] = {1, 0};
  EXPECT_EQ(run(first_ - 256 + 2, 1, GL_2_BYTES, high), 2.0f);
  EXPECT_EQ(run(first_, 0, GL_BYTE, b), 0.0f);
}

// §5.4: the offsets are read when CallLists is compiled; the base is the one at execution.
TEST_F(CallListsTypes, CompiledArrayIsCopied) {
  GLubyte offsets[2] = {1, 2};
  const GLuint list = glGenLists(1);
  glListBase(first_);
  glNewList(list, GL_COMPILE);
  glCallLists(2, GL_UNSIGNED_BYTE, offsets);
  glEndList();
  offsets[0] = offsets[1] = 7;
  glLoadIdentity();
  glCallList(list);
  EXPECT_EQ(modelview_x(), 21.0f);
  glLoadIdentity();
  glListBase(first_ + 1);
  glCallList(list);
  EXPECT_EQ(modelview_x(), 32.0f);
}

TEST_F(DList, NestingLimit) {
  // A list that calls itself runs MAX_LIST_NESTING times, then the call is ignored.
  glNewList(1, GL_COMPILE);
  glTranslatef(1, 0, 0);
  glCallList(1);
  glEndList();
  glCallList(1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(modelview_x(), static_cast<float>(get_int(GL_MAX_LIST_NESTING)));
  // Lists calling lists.
  glNewList(2, GL_COMPILE);
  glTranslatef(100, 0, 0);
  glEndList();
  glNewList(3, GL_COMPILE);
  glCallList(2);
  glCallList(2);
  glEndList();
  glLoadIdentity();
  glCallList(3);
  EXPECT_EQ(modelview_x(), 200.0f);
}

TEST_F(DList, GenDeleteIs) {
  const GLuint base = glGenLists(10);
  ASSERT_NE(base, 0u);
  for (GLuint i = 0; i < 10; ++i)
    EXPECT_EQ(glIsList(base + i), GL_TRUE);
  EXPECT_EQ(glIsList(base + 10), GL_FALSE);
  EXPECT_EQ(glIsList(0), GL_FALSE);
  glCallList(base); // an empty list
  glDeleteLists(base + 2, 3);
  for (GLuint i = 0; i < 10; ++i)
    EXPECT_EQ(glIsList(base + i), i < 2 || i >= 5) << i;
  glDeleteLists(base, 0); // nothing
  EXPECT_EQ(glIsList(base), GL_TRUE);
  glDeleteLists(base + 100, 5); // names without lists are ignored
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // GenLists returns names that were unused, and makes them used.
  const GLuint more = glGenLists(3);
  ASSERT_NE(more, 0u);
  for (GLuint i = 0; i < 3; ++i) {
    EXPECT_TRUE(more + i < base || (more + i >= base + 2 && more + i < base + 5) ||
                more + i >= base + 10);
    EXPECT_EQ(glIsList(more + i), GL_TRUE);
  }
  // A defined list is a used name too; deleting near the top of the name space is safe.
  glNewList(0xfffffffeu, GL_COMPILE);
  glEndList();
  EXPECT_EQ(glIsList(0xfffffffeu), GL_TRUE);
  glDeleteLists(0xfffffff0u, 0x7fffffff);
  EXPECT_EQ(glIsList(0xfffffffeu), GL_FALSE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(DList, PushAttribListBit) {
  glListBase(5);
  glPushAttrib(GL_LIST_BIT);
  glListBase(6);
  glPopAttrib();
  EXPECT_EQ(get_int(GL_LIST_BASE), 5);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glListBase(7);
  glPopAttrib();
  EXPECT_EQ(get_int(GL_LIST_BASE), 5);
}

// §5.4: client data is dereferenced when the command is compiled.
TEST_F(DList, ClientDataCopied) {
  GLfloat m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 3, 0, 0, 1};
  GLfloat diffuse[4] = {0.5f, 0.25f, 0.125f, 1};
  GLfloat color[3] = {0, 1, 0};
  glNewList(1, GL_COMPILE);
  glLoadMatrixf(m);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, diffuse);
  glColor3fv(color);
  glLoadMatrixf(nullptr); // a null pointer stays a null pointer (and does nothing)
  glEndList();
  m[12] = 9;
  diffuse[0] = 1;
  color[0] = 1;
  glCallList(1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(modelview_x(), 3.0f);
  GLfloat got[4];
  glGetLightfv(GL_LIGHT1, GL_DIFFUSE, got);
  EXPECT_EQ(got[0], 0.5f);
  EXPECT_EQ(got[2], 0.125f);
  EXPECT_EQ(current_color(), (std::vector<float>{0, 1, 0, 1}));
}

// Contexts of one share group see each other's lists (OSMesa sharelist, GLX share lists).
TEST_F(DList, SharedBetweenContexts) {
  OSMesaContext other = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, ctx_);
  OSMesaContext alone = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  ASSERT_NE(other, nullptr);
  ASSERT_NE(alone, nullptr);
  glNewList(5, GL_COMPILE);
  glTranslatef(4, 0, 0);
  glEndList();
  std::vector<uint8_t> buf(kW * kH * 4);
  ASSERT_TRUE(OSMesaMakeCurrent(other, buf.data(), GL_UNSIGNED_BYTE, kW, kH));
  EXPECT_EQ(glIsList(5), GL_TRUE);
  glCallList(5);
  EXPECT_EQ(modelview_x(), 4.0f);
  glDeleteLists(5, 1);
  ASSERT_TRUE(OSMesaMakeCurrent(alone, buf.data(), GL_UNSIGNED_BYTE, kW, kH));
  glNewList(6, GL_COMPILE);
  glEndList();
  ASSERT_TRUE(OSMesaMakeCurrent(ctx_, buf_.data(), GL_UNSIGNED_BYTE, kW, kH));
  EXPECT_EQ(glIsList(5), GL_FALSE);
  EXPECT_EQ(glIsList(6), GL_FALSE);
  OSMesaDestroyContext(other);
  OSMesaDestroyContext(alone);
}

// The compiling state belongs to the context: another context made current meanwhile
// executes its commands, and the first resumes compiling when it is current again.
TEST_F(DList, CompilationFollowsTheContext) {
  OSMesaContext other = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  std::vector<uint8_t> buf(kW * kH * 4);
  glNewList(1, GL_COMPILE);
  glTranslatef(1, 0, 0);
  ASSERT_TRUE(OSMesaMakeCurrent(other, buf.data(), GL_UNSIGNED_BYTE, kW, kH));
  glTranslatef(50, 0, 0);
  EXPECT_EQ(modelview_x(), 50.0f);
  ASSERT_TRUE(OSMesaMakeCurrent(ctx_, buf_.data(), GL_UNSIGNED_BYTE, kW, kH));
  glTranslatef(2, 0, 0);
  EXPECT_EQ(modelview_x(), 0.0f);
  glEndList();
  glCallList(1);
  EXPECT_EQ(modelview_x(), 3.0f);
  OSMesaDestroyContext(other);
}

// ---- compiled geometry draws what immediate mode draws -----------------------------------

class DListDraw : public GLTest {
protected:
  // Runs `draw` in immediate mode, then compiled into a list (COMPILE, then called), then
  // in COMPILE_AND_EXECUTE mode, each from the same state, and expects identical images and
  // current colours.
  template <typename Setup, typename Draw> void expect_same(Setup setup, Draw draw) {
    auto frame = [&](int how) {
      glClearColor(0, 0, 0, 0);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      setup();
      if (how == 0) {
        draw();
      } else {
        glNewList(100, how == 1 ? GL_COMPILE : GL_COMPILE_AND_EXECUTE);
        draw();
        glEndList();
        if (how == 1) {
          setup(); // the list must not depend on state it did not set
          glCallList(100);
        }
      }
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << how;
      return std::make_pair(buf_, current_color());
    };
    const auto immediate = frame(0);
    const auto compiled = frame(1);
    const auto both = frame(2);
    EXPECT_TRUE(immediate.first == compiled.first) << "COMPILE differs";
    EXPECT_TRUE(immediate.first == both.first) << "COMPILE_AND_EXECUTE differs";
    EXPECT_EQ(immediate.second, compiled.second);
    EXPECT_EQ(immediate.second, both.second);
    int lit = 0;
    for (size_t i = 0; i < buf_.size(); i += 4)
      lit += buf_[i] | buf_[i + 1] | buf_[i + 2] ? 1 : 0;
    EXPECT_GT(lit, 0) << "the test draws nothing";
  }
};

void lighting_setup() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat pos[4] = {1, 1, 2, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glColor3f(0.2f, 0.4f, 0.9f);
  glNormal3f(0, 0, 1);
}

// A small gear-like ring: normals inside the block, flat and smooth shading.
void ring() {
  glShadeModel(GL_FLAT);
  const GLfloat red[4] = {0.8f, 0.1f, 0.0f, 1.0f};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
  glNormal3f(0, 0, 1);
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= 12; ++i) {
    const float a = static_cast<float>(i) * 6.2831853f / 12;
    glNormal3f(std::cos(a), std::sin(a), 0.5f);
    glVertex3f(0.4f * std::cos(a), 0.4f * std::sin(a), 0);
    glVertex3f(0.9f * std::cos(a), 0.9f * std::sin(a), 0);
  }
  glEnd();
  glShadeModel(GL_SMOOTH);
}

TEST_F(DListDraw, LitBlocks) {
  expect_same(lighting_setup, ring);
}

void unlit_setup() {
  glDisable(GL_LIGHTING);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glColor3f(0.25f, 0.5f, 0.75f);
  glEdgeFlag(GL_TRUE);
}

// Vertices that inherit the current colour at execution, colours set in the block, a colour
// left current after the block, edge flags with polygon lines, and Rect.
TEST_F(DListDraw, InheritedAndSetAttributes) {
  expect_same(unlit_setup, [] {
    glBegin(GL_TRIANGLES);
    glVertex2f(-1, -1);
    glVertex2f(0, -1);
    glColor3ub(255, 0, 0);
    glVertex2f(-1, 0);
    glColor4f(0, 1, 0, 1);
    glVertex2f(0, 0);
    glSecondaryColor3f(0.1f, 0.2f, 0.3f);
    glVertex2f(1, 0);
    glVertex2f(0, 1);
    glColor3f(0.5f, 0.5f, 0);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glBegin(GL_TRIANGLES);
    glEdgeFlag(GL_FALSE);
    glVertex2f(0.2f, -0.8f);
    glEdgeFlag(GL_TRUE);
    glVertex2f(0.9f, -0.8f);
    glVertex2f(0.9f, -0.1f);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glRectf(-0.9f, 0.5f, -0.5f, 0.9f);
  });
}

// COLOR_MATERIAL: colours inside the block feed the tracked material per vertex, and the
// last one stays in the material after the block.
TEST_F(DListDraw, ColorMaterial) {
  expect_same(
      [] {
        lighting_setup();
        glEnable(GL_COLOR_MATERIAL);
        glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
      },
      [] {
        glBegin(GL_TRIANGLE_STRIP);
        glVertex2f(-1, -1);
        glColor3f(1, 0, 0);
        glVertex2f(1, -1);
        glColor3f(0, 1, 0);
        glVertex2f(-1, 1);
        glColor3f(0, 0, 1);
        glVertex2f(1, 1);
        glColor3f(1, 1, 0);
        glEnd();
        glDisable(GL_COLOR_MATERIAL);
        glBegin(GL_TRIANGLES); // lit with the material the last colour left
        glVertex2f(-0.5f, -0.5f);
        glVertex2f(0.5f, -0.5f);
        glVertex2f(0, 0.5f);
        glEnd();
      });
}

// Material between Begin and End (the block then runs call by call) and vertices of a list
// called between Begin and End.
TEST_F(DListDraw, MaterialInsideBlock) {
  expect_same(lighting_setup, [] {
    const GLfloat green[4] = {0, 1, 0, 1}, blue[4] = {0, 0, 1, 1};
    glBegin(GL_TRIANGLES);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, green);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, blue);
    glVertex2f(0, 1);
    glEnd();
  });
}

TEST_F(DList, VerticesCalledInsideBeginEnd) {
  glNewList(1, GL_COMPILE);
  glColor3f(1, 0, 0);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(-1, 1);
  glEndList();
  glColor3f(0, 0, 1);
  glBegin(GL_TRIANGLES);
  glCallList(1);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(pixel(4, 4), 0xff0000ffu);
  // A list holding a whole block, called inside Begin/End: its Begin is an error and its
  // vertices join the open primitive; its End ends it.
  glNewList(2, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glColor3f(0, 1, 0);
  glVertex2f(1, 1);
  glVertex2f(-1, 1);
  glEnd();
  glEndList();
  glShadeModel(GL_FLAT); // the last vertex, from the list, colours the triangle
  glBegin(GL_TRIANGLES);
  glVertex2f(1, -1);
  glCallList(2);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION)); // End outside
  EXPECT_EQ(pixel(kW - 4, kH - 4), 0xff00ff00u);
}

// Vertices that inherit the current colour take the one of each call, whichever came before.
TEST_F(DList, InheritedColourFollowsEachCall) {
  glNewList(1, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(-1, 1);
  glEnd();
  glEndList();
  const GLubyte colours[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 255, 0}, {255, 0, 0}};
  for (const auto& c : colours) {
    glColor3ubv(c);
    glCallList(1);
    EXPECT_EQ(pixel(4, 4), 0xff000000u | c[0] | (c[1] << 8));
  }
  glDrawArrays(GL_TRIANGLES, 0, 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// A list whose block has no End: the End comes from the caller.
TEST_F(DList, BlockWithoutEnd) {
  glNewList(1, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 1, 0);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glEndList();
  glCallList(1);
  glVertex2f(-1, 1);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(pixel(4, 4), 0xff00ffffu);
}

void array_setup() {
  unlit_setup();
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

// §5.4: array contents are read when DrawArrays/DrawElements/ArrayElement are compiled.
TEST_F(DListDraw, ArraysDereferencedAtCompileTime) {
  static GLfloat verts[8];
  static GLubyte colors[16];
  auto fill = [](float scale) {
    const GLfloat v[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
    for (int i = 0; i < 8; ++i)
      verts[i] = v[i] * scale;
    for (int i = 0; i < 16; ++i)
      colors[i] = static_cast<GLubyte>(i * 16 + static_cast<int>(scale * 10));
  };
  // The draw fills the arrays, draws, and refills them: a list that read the arrays when it
  // executes would draw the second contents (or nothing, the arrays being disabled then).
  expect_same(array_setup, [&] {
    fill(0.8f);
    glVertexPointer(2, GL_FLOAT, 0, verts);
    glEnableClientState(GL_VERTEX_ARRAY);
    glDrawArrays(GL_LINE_LOOP, 0, 4);
    glEnableClientState(GL_COLOR_ARRAY);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    const GLubyte idx[6] = {0, 1, 2, 0, 2, 3};
    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, idx);
    glBegin(GL_TRIANGLES);
    glArrayElement(0);
    glArrayElement(2);
    glArrayElement(3);
    glEnd();
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    fill(0.3f);
  });
}

} // namespace
