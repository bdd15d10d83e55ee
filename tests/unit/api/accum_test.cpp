// The accumulation buffer (GL 2.1 §4.2.4): glAccum and glClearAccum errors and state, the
// buffer's presence and size, the five operations against a double-precision reference and
// against values llvmpipe produces, scissor and colour mask, glPushAttrib(ACCUM_BUFFER_BIT).
#include <cmath>
#include <functional>
#include <vector>

#include "api_fixture.h"

namespace {

// A context with an accumulation buffer.
class Accum : public ::testing::Test {
protected:
  static constexpr int kW = 16, kH = 16;
  void SetUp() override {
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, nullptr);
    ASSERT_NE(ctx_, nullptr);
    buf_.assign(kW * kH * 4, 0);
    ASSERT_EQ(OSMesaMakeCurrent(ctx_, buf_.data(), GL_UNSIGNED_BYTE, kW, kH), GL_TRUE);
  }
  void TearDown() override {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(ctx_);
  }
  const uint8_t* px(int x, int y) const { return &buf_[(y * kW + x) * 4]; }
  void clear_color(float r, float g, float b, float a) {
    glClearColor(r, g, b, a);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  OSMesaContext ctx_ = nullptr;
  std::vector<uint8_t> buf_;
};

using NoAccum = GLTest;

GLint get_int(GLenum pname) {
  GLint v = -1;
  glGetIntegerv(pname, &v);
  return v;
}

TEST_F(NoAccum, ErrorsWithoutABuffer) {
  for (GLenum p : {GL_ACCUM_RED_BITS, GL_ACCUM_GREEN_BITS, GL_ACCUM_BLUE_BITS, GL_ACCUM_ALPHA_BITS})
    EXPECT_EQ(get_int(p), 0);
  glAccum(GL_ACCUM, 1.0f); // §4.2.4
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glAccum(GL_ADD + 100, 1.0f); // the enum is checked first (as Mesa does)
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glClear(GL_ACCUM_BUFFER_BIT); // §4.2.3: no such buffer, no effect, no error
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Accum, BitsStateAndErrors) {
  // Mesa's 16 signed bits per channel, alpha included.
  for (GLenum p : {GL_ACCUM_RED_BITS, GL_ACCUM_GREEN_BITS, GL_ACCUM_BLUE_BITS, GL_ACCUM_ALPHA_BITS})
    EXPECT_EQ(get_int(p), 16);
  GLfloat c[4] = {9, 9, 9, 9};
  glGetFloatv(GL_ACCUM_CLEAR_VALUE, c);
  for (float v : c)
    EXPECT_EQ(v, 0.0f);
  glClearAccum(-2.0f, 0.5f, 3.0f, -0.25f); // clamped to [-1, 1]
  glGetFloatv(GL_ACCUM_CLEAR_VALUE, c);
  EXPECT_EQ(c[0], -1.0f);
  EXPECT_EQ(c[1], 0.5f);
  EXPECT_EQ(c[2], 1.0f);
  EXPECT_EQ(c[3], -0.25f);
  GLint ic[4];
  glGetIntegerv(GL_ACCUM_CLEAR_VALUE, ic); // normalized to the full integer range
  EXPECT_LE(ic[0], -2147483647);
  EXPECT_EQ(ic[2], 2147483647);
  glAccum(GL_FLOAT, 1.0f);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glBegin(GL_POINTS);
  glAccum(GL_RETURN, 1.0f);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);
  glClearAccum(0, 0, 0, 0);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glGetFloatv(GL_ACCUM_CLEAR_VALUE, c);
  EXPECT_EQ(c[1], 0.5f);
}

TEST_F(Accum, PushAttribSavesTheClearValue) {
  glClearAccum(0.25f, 0.5f, 0.75f, 1.0f);
  glPushAttrib(GL_ACCUM_BUFFER_BIT);
  glClearAccum(0, 0, 0, 0);
  glPopAttrib();
  GLfloat c[4];
  glGetFloatv(GL_ACCUM_CLEAR_VALUE, c);
  EXPECT_EQ(c[0], 0.25f);
  EXPECT_EQ(c[1], 0.5f);
  EXPECT_EQ(c[2], 0.75f);
  EXPECT_EQ(c[3], 1.0f);
}

// LOAD 0.3, ACCUM 0.3, RETURN 1; then MULT 0.7, ADD 0.01, RETURN 1.5, for a grey level v:
// what llvmpipe returns (measured), and the ideal values in double precision, which the
// 16-bit buffer may miss by one step.
TEST_F(Accum, ArithmeticMatchesLlvmpipeAndTheReference) {
  struct Row {
    int v, first, second;
  };
  const Row llvmpipe[] = {
      {0, 0, 4},       {17, 10, 15},    {34, 20, 25},    {51, 31, 36},
      {68, 41, 47},    {85, 51, 57},    {102, 61, 68},   {119, 71, 79},
      {136, 82, 89},   {153, 92, 100},  {170, 102, 111}, {187, 112, 122},
      {204, 122, 132}, {221, 133, 143}, {238, 143, 154}, {255, 153, 164},
  };
  for (const Row& r : llvmpipe) {
    const float c = static_cast<float>(r.v) / 255.0f;
    clear_color(c, c, c, 1.0f);
    glAccum(GL_LOAD, 0.3f);
    glAccum(GL_ACCUM, 0.3f);
    glAccum(GL_RETURN, 1.0f);
    EXPECT_EQ(px(3, 3)[0], r.first) << "v " << r.v;
    glAccum(GL_MULT, 0.7f);
    glAccum(GL_ADD, 0.01f);
    glAccum(GL_RETURN, 1.5f);
    EXPECT_EQ(px(3, 3)[0], r.second) << "v " << r.v;
    EXPECT_EQ(px(3, 3)[3], 164); // alpha 1: as v = 255
    const double a = 0.6 * r.v / 255.0;
    const double b = (a * 0.7 + 0.01) * 1.5;
    EXPECT_NEAR(px(3, 3)[0], std::min(1.0, b) * 255.0, 1.0) << "v " << r.v;
    EXPECT_NEAR(r.first, a * 255.0, 1.0);
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Accum, ClearValuesAsLlvmpipeStoresThem) {
  struct Row {
    float c;
    int returned;
  };
  // glClearAccum(c), glClear, glAccum(RETURN, 1) in llvmpipe (measured).
  const Row rows[] = {{0.0f, 0},  {0.5f, 127}, {0.25f, 64}, {1.0f, 255}, {-1.0f, 0},
                      {0.1f, 25}, {0.3f, 76},  {-0.5f, 0},  {0.7f, 178}};
  for (const Row& r : rows) {
    glClearAccum(r.c, r.c, r.c, r.c);
    glClear(GL_ACCUM_BUFFER_BIT);
    glAccum(GL_RETURN, 1.0f);
    EXPECT_EQ(px(0, 0)[0], r.returned) << r.c;
    EXPECT_NEAR(px(0, 0)[0], std::max(0.0f, r.c) * 255.0, 1.0) << r.c;
  }
}

TEST_F(Accum, NegativeValuesAndReturnScale) {
  // ACCUM with a negative value subtracts: 0.5 - 0.25 = 0.25; RETURN 2 doubles it.
  clear_color(0.5f, 0.5f, 0.5f, 0.5f);
  glAccum(GL_LOAD, 1.0f);
  clear_color(0.25f, 0.25f, 0.25f, 0.25f);
  glAccum(GL_ACCUM, -1.0f);
  glAccum(GL_RETURN, 2.0f);
  EXPECT_NEAR(px(1, 1)[0], 127.5, 1.0);
  // RETURN clamps negative results to 0.
  glAccum(GL_ADD, -0.5f);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_EQ(px(1, 1)[0], 0);
}

TEST_F(Accum, ScissorLimitsAccumAndClear) {
  glClearAccum(1, 1, 1, 1);
  glClear(GL_ACCUM_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(4, 4, 4, 4);
  glClearAccum(0, 0, 0, 0);
  glClear(GL_ACCUM_BUFFER_BIT); // only the scissor box becomes 0
  glDisable(GL_SCISSOR_TEST);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_EQ(px(5, 5)[0], 0);
  EXPECT_EQ(px(0, 0)[0], 255);
  clear_color(0, 0, 0, 0);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 2, 2);
  glAccum(GL_RETURN, 1.0f); // only (0..1, 0..1) written
  glDisable(GL_SCISSOR_TEST);
  EXPECT_EQ(px(1, 1)[0], 255);
  EXPECT_EQ(px(2, 2)[0], 0);
}

TEST_F(Accum, ReturnHonoursTheColourMask) {
  glClearAccum(1, 1, 1, 1);
  glClear(GL_ACCUM_BUFFER_BIT);
  clear_color(0, 0, 0, 0);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glAccum(GL_RETURN, 1.0f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  EXPECT_EQ(px(2, 2)[0], 255);
  EXPECT_EQ(px(2, 2)[1], 0);
  EXPECT_EQ(px(2, 2)[2], 255);
  EXPECT_EQ(px(2, 2)[3], 0);
}

TEST_F(Accum, NothingHappensInSelectMode) {
  glClearAccum(1, 1, 1, 1);
  glClear(GL_ACCUM_BUFFER_BIT);
  GLuint sel[4];
  glSelectBuffer(4, sel);
  glRenderMode(GL_SELECT);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glRenderMode(GL_RENDER);
  EXPECT_EQ(px(0, 0)[0], 0);
}

TEST(AccumRgb, ThreeByteBuffer) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGB, 0, 0, 8, nullptr);
  ASSERT_NE(ctx, nullptr);
  std::vector<uint8_t> buf(4 * 4 * 3, 0);
  ASSERT_EQ(OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, 4, 4), GL_TRUE);
  EXPECT_EQ(get_int(GL_ACCUM_ALPHA_BITS), 16);
  glClearColor(0.2f, 0.4f, 0.6f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glAccum(GL_LOAD, 1.0f);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_NEAR(buf[0], 51, 1);
  EXPECT_NEAR(buf[1], 102, 1);
  EXPECT_NEAR(buf[2], 153, 1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);
}

} // namespace
