// Selection and feedback (GL 2.1 §5.2, §5.3): glRenderMode, the name stack, hit records of
// known scenes value by value, feedback arrays of every type for points, lines and polygons
// (clipped ones too), LINE_RESET_TOKEN, overflow, glPassThrough, the state queries, and
// INVALID_OPERATION between Begin and End. Expected values are worked out from the spec.
//
// Every test draws with identity matrices on the 32x32 window: object coordinates are clip
// coordinates, window x = 16 (x + 1), y = 16 (y + 1), z = (z + 1) / 2.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "api_fixture.h"

namespace {

using Select = GLTest;
using Feedback = GLTest;

GLint get_int(GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  return v;
}

// GL 2.1 §5.2: a window z in [0, 1] times 2^32 - 1, rounded to the nearest integer.
GLuint zscale(double z) {
  return static_cast<GLuint>(std::llround(z * 4294967295.0));
}

// Window z of object z under identity matrices and the default depth range.
double wz(double z) {
  return (z + 1.0) / 2.0;
}

void triangle(float x0, float y0, float z0, float x1, float y1, float z1, float x2, float y2,
              float z2) {
  glBegin(GL_TRIANGLES);
  glVertex3f(x0, y0, z0);
  glVertex3f(x1, y1, z1);
  glVertex3f(x2, y2, z2);
  glEnd();
}

TEST_F(Select, InitialState) {
  EXPECT_EQ(get_int(GL_RENDER_MODE), GL_RENDER);
  EXPECT_EQ(get_int(GL_NAME_STACK_DEPTH), 0);
  EXPECT_GE(get_int(GL_MAX_NAME_STACK_DEPTH), 64);
  EXPECT_EQ(get_int(GL_SELECTION_BUFFER_SIZE), 0);
  EXPECT_EQ(get_int(GL_FEEDBACK_BUFFER_SIZE), 0);
  EXPECT_EQ(get_int(GL_FEEDBACK_BUFFER_TYPE), GL_2D);
  void* p = reinterpret_cast<void*>(1);
  glGetPointerv(GL_SELECTION_BUFFER_POINTER, &p);
  EXPECT_EQ(p, nullptr);
  p = reinterpret_cast<void*>(1);
  glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &p);
  EXPECT_EQ(p, nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Select, RenderModeErrors) {
  EXPECT_EQ(glRenderMode(GL_POINT), 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  // §5.2, §5.3: entering SELECT or FEEDBACK before the array is specified.
  EXPECT_EQ(glRenderMode(GL_SELECT), 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_RENDER_MODE), GL_RENDER);
  EXPECT_EQ(glRenderMode(GL_FEEDBACK), 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_RENDER_MODE), GL_RENDER);
  // RENDER to RENDER returns 0.
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Select, SelectBufferErrorsAndState) {
  GLuint buf[8];
  glSelectBuffer(-1, buf);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(get_int(GL_SELECTION_BUFFER_SIZE), 0);
  glSelectBuffer(8, buf);
  EXPECT_EQ(get_int(GL_SELECTION_BUFFER_SIZE), 8);
  void* p = nullptr;
  glGetPointerv(GL_SELECTION_BUFFER_POINTER, &p);
  EXPECT_EQ(p, static_cast<void*>(buf));
  EXPECT_EQ(glRenderMode(GL_SELECT), 0);
  EXPECT_EQ(get_int(GL_RENDER_MODE), GL_SELECT);
  // §5.2: SelectBuffer in selection mode.
  GLuint other[4];
  glSelectBuffer(4, other);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_SELECTION_BUFFER_SIZE), 8);
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Select, NameStackIgnoredOutsideSelectMode) {
  // §5.2: no effect, and no error, outside selection mode.
  glLoadName(3);
  glPopName();
  glPushName(1);
  glInitNames();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(get_int(GL_NAME_STACK_DEPTH), 0);
}

TEST_F(Select, NameStackErrors) {
  GLuint buf[16];
  glSelectBuffer(16, buf);
  glRenderMode(GL_SELECT);
  glLoadName(1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glPopName();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_STACK_UNDERFLOW));
  const GLint max = get_int(GL_MAX_NAME_STACK_DEPTH);
  for (GLint i = 0; i < max; ++i)
    glPushName(static_cast<GLuint>(i));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(get_int(GL_NAME_STACK_DEPTH), max);
  glPushName(99);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_STACK_OVERFLOW));
  EXPECT_EQ(get_int(GL_NAME_STACK_DEPTH), max);
  glPopName();
  EXPECT_EQ(get_int(GL_NAME_STACK_DEPTH), max - 1);
  glInitNames();
  EXPECT_EQ(get_int(GL_NAME_STACK_DEPTH), 0);
  glPushName(5);
  // §5.2: RenderMode clears the name stack.
  EXPECT_EQ(glRenderMode(GL_RENDER), 0); // no hits
  EXPECT_EQ(get_int(GL_NAME_STACK_DEPTH), 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Select, HitRecordsOfAKnownScene) {
  std::vector<GLuint> buf(64, 0xdeadbeefu);
  glSelectBuffer(64, buf.data());
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(7);
  // Hit 1: a triangle at z -0.5, 0, 0.5.
  triangle(-0.5f, -0.5f, -0.5f, 0.5f, -0.5f, 0.0f, 0.0f, 0.5f, 0.5f);
  glLoadName(8); // writes {1, min, max, 7}
  // No hit: a point outside the clip volume, then a back-facing triangle with culling on.
  glBegin(GL_POINTS);
  glVertex3f(2.0f, 0.0f, 0.0f);
  glEnd();
  glEnable(GL_CULL_FACE);
  triangle(-0.5f, -0.5f, 0.0f, 0.0f, 0.5f, 0.0f, 0.5f, -0.5f, 0.0f);
  glDisable(GL_CULL_FACE);
  glPushName(9); // no hit since the last change: no record
  // Hit 2: a line from x = -3 to x = 1 (z 0.75 to -0.25), clipped at x = -1 where z = 0.25;
  // and a point at z = -1 in the same record.
  glBegin(GL_LINES);
  glVertex3f(-3.0f, 0.0f, 0.75f);
  glVertex3f(1.0f, 0.0f, -0.25f);
  glEnd();
  glBegin(GL_POINTS);
  glVertex3f(0.0f, 0.0f, -1.0f);
  glEnd();
  glPopName(); // writes {2, min, max, 8, 9}
  // Hit 3: a polygon in LINE mode whose edges are all hidden still hits (§5.2: selection
  // ignores PolygonMode); its z comes from its vertices.
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glEdgeFlag(GL_FALSE);
  triangle(-0.5f, -0.5f, 0.25f, 0.5f, -0.5f, 0.25f, 0.0f, 0.5f, 0.5f);
  glEdgeFlag(GL_TRUE);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  EXPECT_EQ(glRenderMode(GL_RENDER), 3); // writes {1, min, max, 8}
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const std::vector<GLuint> want = {
      1, zscale(wz(-0.5)), zscale(wz(0.5)),  7,    //
      2, zscale(wz(-1.0)), zscale(wz(0.25)), 8, 9, //
      1, zscale(wz(0.25)), zscale(wz(0.5)),  8,    //
  };
  for (size_t i = 0; i < want.size(); ++i)
    EXPECT_EQ(buf[i], want[i]) << "value " << i;
  EXPECT_EQ(buf[want.size()], 0xdeadbeefu);
  // Nothing was drawn.
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      ASSERT_EQ(pixel(x, y), 0u);
}

TEST_F(Select, DepthRangeScalesHitDepths) {
  GLuint buf[8] = {};
  glDepthRange(0.25, 0.75);
  glSelectBuffer(8, buf);
  glRenderMode(GL_SELECT);
  glPushName(1);
  glBegin(GL_POINTS);
  glVertex3f(0.0f, 0.0f, -1.0f); // window z 0.25
  glVertex3f(0.0f, 0.0f, 1.0f);  // window z 0.75
  glEnd();
  EXPECT_EQ(glRenderMode(GL_RENDER), 1);
  EXPECT_EQ(buf[0], 1u);
  EXPECT_EQ(buf[1], zscale(0.25));
  EXPECT_EQ(buf[2], zscale(0.75));
  EXPECT_EQ(buf[3], 1u);
}

TEST_F(Select, FullRangeDepths) {
  GLuint buf[4] = {};
  glSelectBuffer(4, buf);
  glRenderMode(GL_SELECT);
  glBegin(GL_LINES);
  glVertex3f(0.0f, 0.0f, -1.0f);
  glVertex3f(0.5f, 0.0f, 1.0f);
  glEnd();
  EXPECT_EQ(glRenderMode(GL_RENDER), 1);
  EXPECT_EQ(buf[0], 0u); // empty name stack
  EXPECT_EQ(buf[1], 0u);
  EXPECT_EQ(buf[2], 0xffffffffu);
}

TEST_F(Select, OverflowWritesWhatFitsAndReturnsMinusOne) {
  GLuint buf[7];
  for (GLuint& v : buf)
    v = 0xdeadbeefu;
  glSelectBuffer(6, buf);
  glRenderMode(GL_SELECT);
  glPushName(1);
  glPushName(2);
  triangle(-0.5f, -0.5f, 0.0f, 0.5f, -0.5f, 0.0f, 0.0f, 0.5f, 0.0f);
  glLoadName(3); // 5 values fit
  triangle(-0.5f, -0.5f, 0.0f, 0.5f, -0.5f, 0.0f, 0.0f, 0.5f, 0.0f);
  EXPECT_EQ(glRenderMode(GL_RENDER), -1); // the second record gets one value in
  EXPECT_EQ(buf[0], 2u);
  EXPECT_EQ(buf[3], 1u);
  EXPECT_EQ(buf[4], 2u);
  EXPECT_EQ(buf[5], 2u); // first value of the second record
  EXPECT_EQ(buf[6], 0xdeadbeefu);
  // The overflow flag is cleared: a new selection pass starts clean.
  glRenderMode(GL_SELECT);
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);
}

TEST_F(Select, RasterModeBuffersUntouchedAndClearIgnored) {
  GLuint buf[4];
  glSelectBuffer(4, buf);
  glRenderMode(GL_SELECT);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT); // §5.2: no framebuffer updates
  glRecti(-1, -1, 1, 1);
  EXPECT_EQ(glRenderMode(GL_RENDER), 1);
  EXPECT_EQ(pixel(5, 5), 0u);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(pixel(5, 5), 0xffffffffu);
}

TEST_F(Select, ArraysHitToo) {
  GLuint buf[8] = {};
  glSelectBuffer(8, buf);
  glRenderMode(GL_SELECT);
  glPushName(4);
  const GLfloat v[] = {-0.5f, -0.5f, 0.5f, 0.5f, -0.5f, 0.5f, 0.0f, 0.5f, -0.5f};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, v);
  const GLuint idx[] = {0, 1, 2};
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, idx);
  glDisableClientState(GL_VERTEX_ARRAY);
  EXPECT_EQ(glRenderMode(GL_RENDER), 1);
  EXPECT_EQ(buf[1], zscale(wz(-0.5)));
  EXPECT_EQ(buf[2], zscale(wz(0.5)));
  EXPECT_EQ(buf[3], 4u);
}

// ---- feedback ----

struct FeedbackRun {
  std::vector<GLfloat> values;
  GLint returned = 0;
};

FeedbackRun feedback(GLenum type, const std::function<void()>& draw, GLsizei size = 512) {
  FeedbackRun r;
  r.values.assign(static_cast<size_t>(size) + 1, -999.0f);
  glFeedbackBuffer(size, type, r.values.data());
  glRenderMode(GL_FEEDBACK);
  draw();
  r.returned = glRenderMode(GL_RENDER);
  return r;
}

void expect_values(const FeedbackRun& r, const std::vector<float>& want) {
  ASSERT_EQ(r.returned, static_cast<GLint>(want.size()));
  for (size_t i = 0; i < want.size(); ++i)
    EXPECT_FLOAT_EQ(r.values[i], want[i]) << "value " << i;
}

constexpr float kPoint = GL_POINT_TOKEN, kLine = GL_LINE_TOKEN, kReset = GL_LINE_RESET_TOKEN,
                kPoly = GL_POLYGON_TOKEN, kPass = GL_PASS_THROUGH_TOKEN;

TEST_F(Feedback, BufferErrorsAndState) {
  GLfloat buf[8];
  glFeedbackBuffer(8, GL_RGBA, buf);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glFeedbackBuffer(-1, GL_2D, buf);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(get_int(GL_FEEDBACK_BUFFER_SIZE), 0);
  glFeedbackBuffer(8, GL_3D_COLOR, buf);
  EXPECT_EQ(get_int(GL_FEEDBACK_BUFFER_SIZE), 8);
  EXPECT_EQ(get_int(GL_FEEDBACK_BUFFER_TYPE), GL_3D_COLOR);
  void* p = nullptr;
  glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &p);
  EXPECT_EQ(p, static_cast<void*>(buf));
  glRenderMode(GL_FEEDBACK);
  EXPECT_EQ(get_int(GL_RENDER_MODE), GL_FEEDBACK);
  glFeedbackBuffer(8, GL_2D, buf); // §5.3: not while in feedback mode
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_FEEDBACK_BUFFER_TYPE), GL_3D_COLOR);
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Feedback, PointOfEveryType) {
  const auto draw = [] {
    glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
    glTexCoord4f(1.0f, 2.0f, 3.0f, 4.0f);
    glBegin(GL_POINTS);
    // Clip (0.5, -0.25, 0.5, 2): window x 16 (0.25 + 1) = 20, y 16 (-0.125 + 1) = 14,
    // z (0.25 + 1) / 2 = 0.625, w 2.
    glVertex4f(0.5f, -0.25f, 0.5f, 2.0f);
    glEnd();
  };
  expect_values(feedback(GL_2D, draw), {kPoint, 20, 14});
  expect_values(feedback(GL_3D, draw), {kPoint, 20, 14, 0.625f});
  expect_values(feedback(GL_3D_COLOR, draw), {kPoint, 20, 14, 0.625f, 0.25f, 0.5f, 0.75f, 1});
  expect_values(feedback(GL_3D_COLOR_TEXTURE, draw),
                {kPoint, 20, 14, 0.625f, 0.25f, 0.5f, 0.75f, 1, 1, 2, 3, 4});
  expect_values(feedback(GL_4D_COLOR_TEXTURE, draw),
                {kPoint, 20, 14, 0.625f, 2, 0.25f, 0.5f, 0.75f, 1, 1, 2, 3, 4});
}

TEST_F(Feedback, PointsOutsideTheClipVolumeAreDropped) {
  const auto r = feedback(GL_2D, [] {
    glBegin(GL_POINTS);
    glVertex2f(1.5f, 0.0f);
    glVertex2f(0.0f, 0.0f);
    glVertex3f(0.0f, 0.0f, -1.5f);
    glEnd();
  });
  expect_values(r, {kPoint, 16, 16});
}

TEST_F(Feedback, LineResetTokens) {
  // §3.4.2: the stipple counter restarts at Begin and before every independent segment.
  const auto lines = feedback(GL_2D, [] {
    glBegin(GL_LINES);
    glVertex2f(0.0f, 0.0f);
    glVertex2f(0.5f, 0.0f);
    glVertex2f(0.0f, 0.5f);
    glVertex2f(0.5f, 0.5f);
    glEnd();
  });
  expect_values(lines, {kReset, 16, 16, 24, 16, kReset, 16, 24, 24, 24});
  const auto strip = feedback(GL_2D, [] {
    glBegin(GL_LINE_STRIP);
    glVertex2f(0.0f, 0.0f);
    glVertex2f(0.5f, 0.0f);
    glVertex2f(0.5f, 0.5f);
    glEnd();
  });
  expect_values(strip, {kReset, 16, 16, 24, 16, kLine, 24, 16, 24, 24});
  const auto loop = feedback(GL_2D, [] {
    glBegin(GL_LINE_LOOP);
    glVertex2f(0.0f, 0.0f);
    glVertex2f(0.5f, 0.0f);
    glVertex2f(0.5f, 0.5f);
    glEnd();
  });
  expect_values(loop, {kReset, 16, 16, 24, 16, kLine, 24, 16, 24, 24, kLine, 24, 24, 16, 16});
}

TEST_F(Feedback, ClippedLine) {
  // From x = -3 to x = 1 at y = 0.5, z from 1 to 0 (clip): cut at x = -1, where z = 0.5.
  const auto r = feedback(GL_4D_COLOR_TEXTURE, [] {
    glColor4f(1.0f, 0.0f, 0.0f, 1.0f);
    glBegin(GL_LINES);
    glVertex3f(-3.0f, 0.5f, 1.0f);
    glColor4f(0.0f, 0.0f, 1.0f, 1.0f);
    glVertex3f(1.0f, 0.5f, 0.0f);
    glEnd();
  });
  // The new vertex is half way in colour (§2.14.8), at window x 0, z (0.5 + 1) / 2.
  expect_values(r, {kReset, 0,  24,   0.75f, 1, 0.5f, 0, 0.5f, 1, 0, 0, 0, 1,
                    32,     24, 0.5f, 1,     0, 0,    1, 1,    0, 0, 0, 1});
}

TEST_F(Feedback, TriangleAndCulling) {
  const auto draw = [] {
    glBegin(GL_TRIANGLES);
    glVertex3f(-0.5f, -0.5f, 0.0f);
    glVertex3f(0.5f, -0.5f, 0.5f);
    glVertex3f(0.0f, 0.5f, -0.5f);
    glEnd();
  };
  expect_values(feedback(GL_3D, draw), {kPoly, 3, 8, 8, 0.5f, 24, 8, 0.75f, 16, 24, 0.25f});
  // §5.3: feedback happens after culling.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  expect_values(feedback(GL_3D, draw), {});
  glDisable(GL_CULL_FACE);
}

TEST_F(Feedback, QuadsSplitAsMesaReportsThem) {
  glShadeModel(GL_FLAT);
  const auto r = feedback(GL_3D_COLOR, [] {
    glBegin(GL_QUADS);
    glColor3f(1, 0, 0);
    glVertex2f(-0.5f, -0.5f);
    glVertex2f(0.5f, -0.5f);
    glVertex2f(0.5f, 0.5f);
    glColor3f(0, 0, 1); // the fourth vertex provokes (GL 2.1 Table 2.12)
    glVertex2f(-0.5f, 0.5f);
    glEnd();
  });
  const std::vector<float> q0 = {8, 8, 0.5f, 0, 0, 1, 1}, q1 = {24, 8, 0.5f, 0, 0, 1, 1},
                           q2 = {24, 24, 0.5f, 0, 0, 1, 1}, q3 = {8, 24, 0.5f, 0, 0, 1, 1};
  std::vector<float> want;
  for (const auto* tri : {&q0, &q1, &q3, &q1, &q2, &q3}) {
    if (want.size() % 23 == 0) {
      want.push_back(kPoly);
      want.push_back(3);
    }
    want.insert(want.end(), tri->begin(), tri->end());
  }
  expect_values(r, want);
  glShadeModel(GL_SMOOTH);
}

TEST_F(Feedback, ClippedTriangleStaysInsideTheViewport) {
  const auto r = feedback(GL_3D, [] {
    glBegin(GL_TRIANGLES);
    glVertex2f(-2.0f, -0.5f);
    glVertex2f(0.5f, -0.5f);
    glVertex2f(0.5f, 0.5f);
    glEnd();
  });
  // The triangle crosses x = -1 once: a quadrilateral, fed back as two triangles whose
  // vertices all lie in the window, two of them on its left edge.
  ASSERT_EQ(r.returned, 2 * (2 + 9));
  int on_left = 0;
  for (int t = 0; t < 2; ++t) {
    const float* p = &r.values[static_cast<size_t>(t) * 11];
    EXPECT_EQ(p[0], kPoly);
    EXPECT_EQ(p[1], 3.0f);
    for (int v = 0; v < 3; ++v) {
      const float x = p[2 + 3 * v], y = p[3 + 3 * v];
      EXPECT_GE(x, 0.0f);
      EXPECT_LE(x, 24.0f);
      EXPECT_GE(y, 8.0f);
      EXPECT_LE(y, 24.0f);
      on_left += x == 0.0f;
    }
  }
  EXPECT_GE(on_left, 2);
}

TEST_F(Feedback, PolygonModes) {
  const auto draw = [] {
    glBegin(GL_QUADS);
    glVertex2f(-0.5f, -0.5f);
    glVertex2f(0.5f, -0.5f);
    glVertex2f(0.5f, 0.5f);
    glVertex2f(-0.5f, 0.5f);
    glEnd();
  };
  // LINE: the quad's four boundary edges, the first with the stipple reset (§3.5.4).
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  const auto lines = feedback(GL_2D, draw);
  ASSERT_EQ(lines.returned, 4 * 5);
  EXPECT_EQ(lines.values[0], kReset);
  std::vector<std::array<float, 4>> edges;
  for (int i = 0; i < 4; ++i) {
    const float* p = &lines.values[static_cast<size_t>(i) * 5];
    if (i > 0) {
      EXPECT_EQ(p[0], kLine);
    }
    edges.push_back({p[1], p[2], p[3], p[4]});
  }
  for (const std::array<float, 4>& e : std::vector<std::array<float, 4>>{
           {8, 8, 24, 8}, {24, 8, 24, 24}, {24, 24, 8, 24}, {8, 24, 8, 8}})
    EXPECT_NE(std::find(edges.begin(), edges.end(), e), edges.end())
        << e[0] << "," << e[1] << " -> " << e[2] << "," << e[3];
  // Two quads: each restarts the counter.
  const auto two = feedback(GL_2D, [&] {
    draw();
    draw();
  });
  ASSERT_EQ(two.returned, 8 * 5);
  EXPECT_EQ(two.values[0], kReset);
  EXPECT_EQ(two.values[20], kReset);
  // POINT: the four vertices.
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  const auto points = feedback(GL_2D, draw);
  ASSERT_EQ(points.returned, 4 * 3);
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ(points.values[static_cast<size_t>(i) * 3], kPoint);
  // An edge flag of FALSE hides the edge that starts at that vertex.
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  const auto flagged = feedback(GL_2D, [] {
    glBegin(GL_TRIANGLES);
    glEdgeFlag(GL_FALSE);
    glVertex2f(-0.5f, -0.5f);
    glEdgeFlag(GL_TRUE);
    glVertex2f(0.5f, -0.5f);
    glVertex2f(0.0f, 0.5f);
    glEnd();
  });
  ASSERT_EQ(flagged.returned, 2 * 5);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

TEST_F(Feedback, FlatShadingUsesTheProvokingColour) {
  glShadeModel(GL_FLAT);
  const auto r = feedback(GL_3D_COLOR, [] {
    glBegin(GL_LINES);
    glColor3f(1, 0, 0);
    glVertex2f(0.0f, 0.0f);
    glColor3f(0, 1, 0);
    glVertex2f(0.5f, 0.0f);
    glEnd();
  });
  // §2.14.7: the second vertex of a segment provokes.
  expect_values(r, {kReset, 16, 16, 0.5f, 0, 1, 0, 1, 24, 16, 0.5f, 0, 1, 0, 1});
  glShadeModel(GL_SMOOTH);
}

TEST_F(Feedback, TextureMatrixAndPrimaryColourOnly) {
  glMatrixMode(GL_TEXTURE);
  glScalef(2.0f, 3.0f, 4.0f);
  glMatrixMode(GL_MODELVIEW);
  // §5.3: the primary colour, without the secondary colour the colour sum would add.
  glEnable(GL_COLOR_SUM);
  glSecondaryColor3f(0.5f, 0.5f, 0.5f);
  const auto r = feedback(GL_3D_COLOR_TEXTURE, [] {
    glColor4f(0.25f, 0.0f, 0.125f, 0.5f);
    glTexCoord2f(0.5f, 0.25f);
    glBegin(GL_POINTS);
    glVertex2f(0.0f, 0.0f);
    glEnd();
  });
  expect_values(r, {kPoint, 16, 16, 0.5f, 0.25f, 0, 0.125f, 0.5f, 1, 0.75f, 0, 1});
  glDisable(GL_COLOR_SUM);
}

TEST_F(Feedback, PassThroughAndOverflow) {
  const auto r = feedback(GL_2D, [] {
    glPassThrough(42.0f);
    glBegin(GL_POINTS);
    glVertex2f(0.0f, 0.0f);
    glEnd();
  });
  expect_values(r, {kPass, 42, kPoint, 16, 16});
  // Four values fit: the point's last value is dropped and RenderMode returns -1 (§5.3).
  const auto small = feedback(
      GL_2D,
      [] {
        glPassThrough(42.0f);
        glBegin(GL_POINTS);
        glVertex2f(0.0f, 0.0f);
        glEnd();
      },
      4);
  EXPECT_EQ(small.returned, -1);
  EXPECT_EQ(small.values[3], 16.0f);
  EXPECT_EQ(small.values[4], -999.0f);
  // The flag is cleared by RenderMode.
  glRenderMode(GL_FEEDBACK);
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);
  // PassThrough outside feedback mode does nothing.
  glPassThrough(1.0f);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Feedback, NothingIsDrawn) {
  const auto r = feedback(GL_2D, [] { glRecti(-1, -1, 1, 1); });
  EXPECT_EQ(r.returned, 2 * (2 + 3 * 2));
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      ASSERT_EQ(pixel(x, y), 0u);
}

TEST_F(Select, IllegalBetweenBeginAndEnd) {
  GLuint sbuf[4];
  GLfloat fbuf[4];
  const std::vector<std::pair<const char*, std::function<void()>>> calls = {
      {"glRenderMode", [] { EXPECT_EQ(glRenderMode(GL_RENDER), 0); }},
      {"glSelectBuffer", [&] { glSelectBuffer(4, sbuf); }},
      {"glFeedbackBuffer", [&] { glFeedbackBuffer(4, GL_2D, fbuf); }},
      {"glInitNames", [] { glInitNames(); }},
      {"glPushName", [] { glPushName(1); }},
      {"glPopName", [] { glPopName(); }},
      {"glLoadName", [] { glLoadName(1); }},
      {"glPassThrough", [] { glPassThrough(1.0f); }},
  };
  for (const auto& [name, call] : calls) {
    glBegin(GL_POINTS);
    call();
    glEnd();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION)) << name;
  }
  EXPECT_EQ(get_int(GL_SELECTION_BUFFER_SIZE), 0);
  EXPECT_EQ(get_int(GL_FEEDBACK_BUFFER_SIZE), 0);
}

} // namespace
