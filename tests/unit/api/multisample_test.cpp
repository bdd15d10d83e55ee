// Multisample state without multisample buffers (GL 2.1 §3.2.1, §4.1.3): SAMPLE_BUFFERS and
// SAMPLES are 0, glSampleCoverage and the four enables are state only, saved by
// MULTISAMPLE_BIT and ENABLE_BIT, compiled into display lists, and change nothing drawn.
#include "api_fixture.h"

#include <GL/glext.h>

#include <vector>

namespace {

using Multisample = GLTest;

GLfloat coverage_value() {
  GLfloat f = -1;
  glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &f);
  return f;
}

GLboolean coverage_invert() {
  GLboolean b = 7;
  glGetBooleanv(GL_SAMPLE_COVERAGE_INVERT, &b);
  return b;
}

constexpr GLenum kEnables[] = {GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE,
                               GL_SAMPLE_COVERAGE};

TEST_F(Multisample, InitialState) {
  GLint v = -1;
  glGetIntegerv(GL_SAMPLE_BUFFERS, &v);
  EXPECT_EQ(v, 0);
  v = -1;
  glGetIntegerv(GL_SAMPLES, &v);
  EXPECT_EQ(v, 0);
  EXPECT_EQ(glIsEnabled(GL_MULTISAMPLE), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_SAMPLE_ALPHA_TO_ONE), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_SAMPLE_COVERAGE), GL_FALSE);
  GLboolean b = GL_FALSE;
  glGetBooleanv(GL_MULTISAMPLE, &b);
  EXPECT_EQ(b, GL_TRUE);
  EXPECT_EQ(coverage_value(), 1.0f);
  EXPECT_EQ(coverage_invert(), GL_FALSE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Multisample, EnablesToggle) {
  for (GLenum cap : kEnables) {
    glEnable(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_TRUE) << cap;
    glDisable(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE) << cap;
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// §4.1.3: value clamped to [0,1]; GetIntegerv rounds the float (as Mesa llvmpipe).
TEST_F(Multisample, SampleCoverageClampsAndQueries) {
  glSampleCoverage(0.3f, GL_TRUE);
  EXPECT_EQ(coverage_value(), 0.3f);
  EXPECT_EQ(coverage_invert(), GL_TRUE);
  GLint i = -1;
  glGetIntegerv(GL_SAMPLE_COVERAGE_VALUE, &i);
  EXPECT_EQ(i, 0);
  glGetIntegerv(GL_SAMPLE_COVERAGE_INVERT, &i);
  EXPECT_EQ(i, 1);
  glSampleCoverage(1.5f, GL_FALSE);
  EXPECT_EQ(coverage_value(), 1.0f);
  EXPECT_EQ(coverage_invert(), GL_FALSE);
  glGetIntegerv(GL_SAMPLE_COVERAGE_VALUE, &i);
  EXPECT_EQ(i, 1);
  glSampleCoverage(-0.5f, 5); // any non-zero boolean is TRUE
  EXPECT_EQ(coverage_value(), 0.0f);
  EXPECT_EQ(coverage_invert(), GL_TRUE);
  GLdouble d = -1;
  glGetDoublev(GL_SAMPLE_COVERAGE_VALUE, &d);
  EXPECT_EQ(d, 0.0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Multisample, IllegalBetweenBeginEnd) {
  glBegin(GL_POINTS);
  glSampleCoverage(0.5f, GL_TRUE);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(coverage_value(), 1.0f);
  EXPECT_EQ(coverage_invert(), GL_FALSE);
  glBegin(GL_POINTS);
  glDisable(GL_MULTISAMPLE);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(glIsEnabled(GL_MULTISAMPLE), GL_TRUE);
}

// §6.1.14, Table 6.15: MULTISAMPLE_BIT saves the enables and the coverage; ENABLE_BIT the
// enables only.
TEST_F(Multisample, PushAttrib) {
  glSampleCoverage(0.25f, GL_TRUE);
  glEnable(GL_SAMPLE_COVERAGE);
  glPushAttrib(GL_MULTISAMPLE_BIT);
  glSampleCoverage(0.75f, GL_FALSE);
  for (GLenum cap : kEnables)
    glEnable(cap);
  glDisable(GL_MULTISAMPLE);
  glPopAttrib();
  EXPECT_EQ(coverage_value(), 0.25f);
  EXPECT_EQ(coverage_invert(), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_MULTISAMPLE), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_SAMPLE_ALPHA_TO_ONE), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_SAMPLE_COVERAGE), GL_TRUE);

  glPushAttrib(GL_ENABLE_BIT);
  glSampleCoverage(0.5f, GL_FALSE);
  glDisable(GL_SAMPLE_COVERAGE);
  glDisable(GL_MULTISAMPLE);
  glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  glPopAttrib();
  EXPECT_EQ(coverage_value(), 0.5f); // not in ENABLE_BIT
  EXPECT_EQ(coverage_invert(), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_SAMPLE_COVERAGE), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_MULTISAMPLE), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_SAMPLE_ALPHA_TO_ONE), GL_FALSE);

  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glSampleCoverage(0.125f, GL_TRUE);
  glDisable(GL_MULTISAMPLE);
  glPopAttrib();
  EXPECT_EQ(coverage_value(), 0.125f);
  EXPECT_EQ(glIsEnabled(GL_MULTISAMPLE), GL_FALSE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Multisample, DisplayLists) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glSampleCoverage(0.25f, GL_TRUE);
  glDisable(GL_MULTISAMPLE);
  glEndList();
  EXPECT_EQ(coverage_value(), 1.0f);
  EXPECT_EQ(glIsEnabled(GL_MULTISAMPLE), GL_TRUE);
  glCallList(list);
  EXPECT_EQ(coverage_value(), 0.25f);
  EXPECT_EQ(coverage_invert(), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_MULTISAMPLE), GL_FALSE);
  glDeleteLists(list, 1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

void draw_scene() {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBegin(GL_TRIANGLES);
  glColor4f(1, 0.5f, 0.25f, 0.5f);
  glVertex2f(-1, -1);
  glVertex2f(1, -0.8f);
  glVertex2f(0.1f, 1);
  glEnd();
  glDisable(GL_BLEND);
  glFinish();
}

// §3.2.1: with SAMPLE_BUFFERS 0 the multisample state has no effect on what is drawn.
TEST_F(Multisample, NoEffectOnRendering) {
  draw_scene();
  const std::vector<uint8_t> reference = buf_;
  for (GLenum cap : {GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE})
    glEnable(cap);
  glSampleCoverage(0.0f, GL_FALSE);
  std::fill(buf_.begin(), buf_.end(), 0);
  draw_scene();
  EXPECT_EQ(buf_, reference);
  glDisable(GL_MULTISAMPLE);
  std::fill(buf_.begin(), buf_.end(), 0);
  draw_scene();
  EXPECT_EQ(buf_, reference);
}

} // namespace
