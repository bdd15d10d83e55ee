// Occlusion queries (GL 2.1 §4.1.7, §6.1.12): names, errors, INVALID_OPERATION between Begin
// and End, and SAMPLES_PASSED counts of scenes whose covered pixels are known exactly.
#include <functional>
#include <vector>

#include "api_fixture.h"

namespace {

using Query = GLTest;

GLuint result_of(GLuint q) {
  GLuint v = 0xdeadbeefu;
  glGetQueryObjectuiv(q, GL_QUERY_RESULT, &v);
  return v;
}

// Samples passed while `draw` runs.
GLuint count(const std::function<void()>& draw) {
  GLuint q = 0;
  glGenQueries(1, &q);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  draw();
  glEndQuery(GL_SAMPLES_PASSED);
  const GLuint r = result_of(q);
  glDeleteQueries(1, &q);
  return r;
}

// A w x h pixel rectangle at (x, y) at depth z (window z = (z + 1) / 2) in window coordinates.
void rect(int x, int y, int w, int h, float z = 0.0f) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 32, 0, 32, 1, -1); // object z is NDC z
  glMatrixMode(GL_MODELVIEW);
  glBegin(GL_QUADS);
  glVertex3f(static_cast<float>(x), static_cast<float>(y), z);
  glVertex3f(static_cast<float>(x + w), static_cast<float>(y), z);
  glVertex3f(static_cast<float>(x + w), static_cast<float>(y + h), z);
  glVertex3f(static_cast<float>(x), static_cast<float>(y + h), z);
  glEnd();
}

TEST_F(Query, Names) {
  GLuint q[3] = {0, 0, 0};
  glGenQueries(3, q);
  EXPECT_NE(q[0], 0u);
  EXPECT_NE(q[0], q[1]);
  EXPECT_NE(q[1], q[2]);
  // §6.1.12: a generated name is not a query object until BeginQuery uses it.
  EXPECT_EQ(glIsQuery(q[0]), GL_FALSE);
  EXPECT_EQ(glIsQuery(0), GL_FALSE);
  glBeginQuery(GL_SAMPLES_PASSED, q[0]);
  EXPECT_EQ(glIsQuery(q[0]), GL_TRUE);
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_EQ(glIsQuery(q[0]), GL_TRUE);
  glDeleteQueries(3, q);
  EXPECT_EQ(glIsQuery(q[0]), GL_FALSE);
  // A name GenQueries did not return becomes a query object at BeginQuery (GL 2.1).
  glBeginQuery(GL_SAMPLES_PASSED, 77);
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_EQ(glIsQuery(77), GL_TRUE);
  // Deleting zero or unused names is silently ignored.
  const GLuint odd[2] = {0, 12345};
  glDeleteQueries(2, odd);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // Generated names skip the ones in use.
  GLuint more[80];
  glGenQueries(80, more);
  for (GLuint n : more)
    EXPECT_NE(n, 77u);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Query, Errors) {
  GLuint q = 0;
  glGenQueries(-1, &q);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  glDeleteQueries(-1, &q);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  glGenQueries(1, &q);
  glBeginQuery(GL_TIME_ELAPSED, q);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glBeginQuery(GL_SAMPLES_PASSED, 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glEndQuery(GL_SAMPLES_PASSED); // none active
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  // Result of a name that is not a query object yet.
  GLint v = -7;
  glGetQueryObjectiv(q, GL_QUERY_RESULT, &v);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(v, -7);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  GLuint q2 = 0;
  glGenQueries(1, &q2);
  glBeginQuery(GL_SAMPLES_PASSED, q2); // one already active
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glGetQueryObjectiv(q, GL_QUERY_RESULT_AVAILABLE, &v); // the active query
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glEndQuery(GL_TIME_ELAPSED);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glGetQueryObjectiv(q, GL_CURRENT_QUERY, &v);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glGetQueryiv(GL_TIME_ELAPSED, GL_CURRENT_QUERY, &v);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glGetQueryiv(GL_SAMPLES_PASSED, GL_QUERY_RESULT, &v);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glGetQueryObjectuiv(0, GL_QUERY_RESULT, reinterpret_cast<GLuint*>(&v));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
}

TEST_F(Query, StateQueries) {
  GLint v = -1;
  glGetQueryiv(GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS, &v);
  EXPECT_GE(v, 32);
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v);
  EXPECT_EQ(v, 0);
  GLuint q = 0;
  glGenQueries(1, &q);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v);
  EXPECT_EQ(static_cast<GLuint>(v), q);
  glEndQuery(GL_SAMPLES_PASSED);
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v);
  EXPECT_EQ(v, 0);
  glGetQueryObjectiv(q, GL_QUERY_RESULT_AVAILABLE, &v);
  EXPECT_EQ(v, GL_TRUE); // rendering is synchronous
  glGetQueryObjectiv(q, GL_QUERY_RESULT, &v);
  EXPECT_EQ(v, 0);
  // Deleting the active query ends it.
  glBeginQuery(GL_SAMPLES_PASSED, q);
  glDeleteQueries(1, &q);
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v);
  EXPECT_EQ(v, 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Query, CountsCoveredPixels) {
  EXPECT_EQ(count([] { rect(2, 3, 10, 7); }), 70u);
  // Two draws in one query add up.
  EXPECT_EQ(count([] {
              rect(0, 0, 4, 4);
              rect(10, 10, 5, 2);
            }),
            26u);
  // Nothing drawn, nothing counted; a draw outside the query does not count.
  rect(0, 0, 8, 8);
  EXPECT_EQ(count([] {}), 0u);
}

TEST_F(Query, CountsWithoutColourWrites) {
  // §4.1.7: samples passing the depth and stencil tests count whatever is written.
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  EXPECT_EQ(count([] { rect(0, 0, 6, 5); }), 30u);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

TEST_F(Query, DepthTestDecides) {
  glEnable(GL_DEPTH_TEST);
  glClear(GL_DEPTH_BUFFER_BIT);
  rect(0, 0, 16, 32, -0.5f); // near occluder over the left half
  // A far rectangle over the whole window passes only on the right half.
  EXPECT_EQ(count([] { rect(0, 0, 32, 32, 0.5f); }), 16u * 32u);
  // A nearer one passes everywhere.
  EXPECT_EQ(count([] { rect(0, 0, 32, 32, -0.75f); }), 32u * 32u);
  glDisable(GL_DEPTH_TEST);
}

TEST_F(Query, StencilScissorAndAlphaTests) {
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  rect(0, 0, 8, 8);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  EXPECT_EQ(count([] { rect(4, 4, 8, 8); }), 16u);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 3, 32);
  EXPECT_EQ(count([] { rect(0, 0, 32, 10); }), 30u);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  glColor4f(1, 1, 1, 0.25f);
  EXPECT_EQ(count([] { rect(0, 0, 4, 4); }), 0u);
  glColor4f(1, 1, 1, 1);
  EXPECT_EQ(count([] { rect(0, 0, 4, 4); }), 16u);
  glDisable(GL_ALPHA_TEST);
}

TEST_F(Query, PointsAndLinesCount) {
  EXPECT_EQ(count([] {
              glMatrixMode(GL_PROJECTION);
              glLoadIdentity();
              glOrtho(0, kW, 0, kH, -1, 1);
              glBegin(GL_POINTS);
              glVertex2f(1.5f, 1.5f);
              glVertex2f(5.5f, 7.5f);
              glEnd();
              glBegin(GL_LINES); // a horizontal line through 10 pixel centres
              glVertex2f(2.2f, 20.5f);
              glVertex2f(12.2f, 20.5f);
              glEnd();
            }),
            12u);
}

TEST_F(Query, NothingCountsInSelectMode) {
  GLuint sel[8];
  glSelectBuffer(8, sel);
  glRenderMode(GL_SELECT);
  EXPECT_EQ(count([] { rect(0, 0, 8, 8); }), 0u);
  EXPECT_EQ(glRenderMode(GL_RENDER), 1);
}

TEST_F(Query, IllegalBetweenBeginAndEnd) {
  GLuint q = 0;
  glGenQueries(1, &q);
  GLint v = 0;
  GLuint uv = 0;
  const std::vector<std::pair<const char*, std::function<void()>>> calls = {
      {"glGenQueries", [&] { glGenQueries(1, &q); }},
      {"glDeleteQueries", [&] { glDeleteQueries(1, &q); }},
      {"glIsQuery", [&] { EXPECT_EQ(glIsQuery(q), GL_FALSE); }},
      {"glBeginQuery", [&] { glBeginQuery(GL_SAMPLES_PASSED, q); }},
      {"glEndQuery", [] { glEndQuery(GL_SAMPLES_PASSED); }},
      {"glGetQueryiv", [&] { glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v); }},
      {"glGetQueryObjectiv", [&] { glGetQueryObjectiv(q, GL_QUERY_RESULT, &v); }},
      {"glGetQueryObjectuiv", [&] { glGetQueryObjectuiv(q, GL_QUERY_RESULT, &uv); }},
  };
  for (const auto& [name, call] : calls) {
    glBegin(GL_POINTS);
    call();
    glEnd();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION)) << name;
  }
  GLint cur = -1;
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &cur);
  EXPECT_EQ(cur, 0);
}

} // namespace
