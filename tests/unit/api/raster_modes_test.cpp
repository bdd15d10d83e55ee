// Points, lines, polygon stipple and offset (GL 2.1 §3.3-§3.5; src/state/raster_modes.cpp):
// errors, INVALID_OPERATION between Begin and End, queries and their initial values, the
// attribute groups, and rendered checks against double-precision references: point sizes and
// their attenuation, stipple counters, wide lines, polygon stipple and offset.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "api_fixture.h"

namespace {

class RasterModes : public GLTest {
protected:
  // Counts the lit pixels of the buffer.
  int lit_count() const {
    int n = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        n += (pixel(x, y) & 0xffffff) != 0;
    return n;
  }
};

constexpr int kSize = 32; // the fixture's buffer is kSize x kSize

GLint get_int(GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  return v;
}
GLfloat get_float(GLenum pname, int i = 0) {
  GLfloat v[4] = {-1, -1, -1, -1};
  glGetFloatv(pname, v);
  return v[i];
}

void expect_error(GLenum err) {
  EXPECT_EQ(glGetError(), err);
}

// Pixel-unit projection over the whole 32x32 buffer, cleared to black.
void pixel_setup() {
  glViewport(0, 0, kSize, kSize);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kSize, 0, kSize, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor4f(1, 1, 1, 1);
}

TEST_F(RasterModes, InitialState) {
  EXPECT_EQ(get_float(GL_POINT_SIZE), 1.0f);
  EXPECT_EQ(get_float(GL_LINE_WIDTH), 1.0f);
  EXPECT_EQ(get_int(GL_LINE_STIPPLE_PATTERN), 0xffff);
  EXPECT_EQ(get_int(GL_LINE_STIPPLE_REPEAT), 1);
  EXPECT_EQ(get_float(GL_POINT_SIZE_MIN), 0.0f);
  EXPECT_EQ(get_float(GL_POINT_SIZE_MAX), 255.0f);
  EXPECT_EQ(get_float(GL_POINT_FADE_THRESHOLD_SIZE), 1.0f);
  EXPECT_EQ(get_float(GL_POINT_DISTANCE_ATTENUATION, 0), 1.0f);
  EXPECT_EQ(get_float(GL_POINT_DISTANCE_ATTENUATION, 1), 0.0f);
  EXPECT_EQ(get_float(GL_POINT_DISTANCE_ATTENUATION, 2), 0.0f);
  EXPECT_EQ(get_float(GL_POLYGON_OFFSET_FACTOR), 0.0f);
  EXPECT_EQ(get_float(GL_POLYGON_OFFSET_UNITS), 0.0f);
  for (GLenum cap :
       {GL_POINT_SMOOTH, GL_LINE_SMOOTH, GL_LINE_STIPPLE, GL_POLYGON_SMOOTH, GL_POLYGON_STIPPLE,
        GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT})
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE) << std::hex << cap;
  // GL 2.1 §3.5.2: the initial stipple is all ones.
  GLubyte mask[128];
  glGetPolygonStipple(mask);
  for (GLubyte b : mask)
    EXPECT_EQ(b, 0xff);
  expect_error(GL_NO_ERROR);
}

TEST_F(RasterModes, Limits) {
  for (GLenum pname : {GL_ALIASED_POINT_SIZE_RANGE, GL_POINT_SIZE_RANGE, GL_LINE_WIDTH_RANGE,
                       GL_ALIASED_LINE_WIDTH_RANGE}) {
    EXPECT_EQ(get_float(pname, 0), 1.0f);
    EXPECT_EQ(get_float(pname, 1), 255.0f);
  }
  EXPECT_FLOAT_EQ(get_float(GL_POINT_SIZE_GRANULARITY), 0.1f);
  EXPECT_FLOAT_EQ(get_float(GL_LINE_WIDTH_GRANULARITY), 0.1f);
}

TEST_F(RasterModes, Errors) {
  // GL 2.1 §3.3, §3.4.2: sizes and widths must be positive.
  glPointSize(0.0f);
  expect_error(GL_INVALID_VALUE);
  glPointSize(-2.0f);
  expect_error(GL_INVALID_VALUE);
  glPointSize(NAN);
  expect_error(GL_INVALID_VALUE);
  EXPECT_EQ(get_float(GL_POINT_SIZE), 1.0f);
  glLineWidth(0.0f);
  expect_error(GL_INVALID_VALUE);
  glLineWidth(-1.0f);
  expect_error(GL_INVALID_VALUE);
  EXPECT_EQ(get_float(GL_LINE_WIDTH), 1.0f);
  // Point parameters: negative sizes and thresholds are INVALID_VALUE, unknown names and the
  // attenuation vector through a scalar call INVALID_ENUM.
  glPointParameterf(GL_POINT_SIZE_MIN, -1.0f);
  expect_error(GL_INVALID_VALUE);
  glPointParameterf(GL_POINT_SIZE_MAX, -0.5f);
  expect_error(GL_INVALID_VALUE);
  glPointParameteri(GL_POINT_FADE_THRESHOLD_SIZE, -3);
  expect_error(GL_INVALID_VALUE);
  const GLfloat neg = -2.0f;
  glPointParameterfv(GL_POINT_FADE_THRESHOLD_SIZE, &neg);
  expect_error(GL_INVALID_VALUE);
  glPointParameterf(GL_POINT_DISTANCE_ATTENUATION, 1.0f);
  expect_error(GL_INVALID_ENUM);
  glPointParameteri(GL_POINT_DISTANCE_ATTENUATION, 1);
  expect_error(GL_INVALID_ENUM);
  glPointParameterf(GL_POINT_SIZE, 2.0f);
  expect_error(GL_INVALID_ENUM);
  const GLint iv[3] = {1, 2, 3};
  glPointParameteriv(GL_LINE_WIDTH, iv);
  expect_error(GL_INVALID_ENUM);
  EXPECT_EQ(get_float(GL_POINT_SIZE_MIN), 0.0f);
  EXPECT_EQ(get_float(GL_POINT_SIZE_MAX), 255.0f);
  EXPECT_EQ(get_float(GL_POINT_FADE_THRESHOLD_SIZE), 1.0f);
  // Null pointers are ignored without a crash.
  glPolygonStipple(nullptr);
  glGetPolygonStipple(nullptr);
  glPointParameterfv(GL_POINT_SIZE_MIN, nullptr);
  glPointParameteriv(GL_POINT_SIZE_MIN, nullptr);
  expect_error(GL_NO_ERROR);
}

TEST_F(RasterModes, IllegalInsideBeginEnd) {
  GLubyte mask[128] = {};
  const GLfloat fv[3] = {1, 0, 0};
  const GLint iv[3] = {1, 0, 0};
  const std::vector<std::function<void()>> calls = {
      [] { glPointSize(2.0f); },
      [] { glLineWidth(2.0f); },
      [] { glLineStipple(2, 0xf0f0); },
      [&] { glPolygonStipple(mask); },
      [&] { glGetPolygonStipple(mask); },
      [] { glPolygonOffset(1.0f, 1.0f); },
      [] { glPointParameterf(GL_POINT_SIZE_MIN, 1.0f); },
      [&] { glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, fv); },
      [] { glPointParameteri(GL_POINT_SIZE_MAX, 4); },
      [&] { glPointParameteriv(GL_POINT_DISTANCE_ATTENUATION, iv); },
  };
  for (size_t i = 0; i < calls.size(); ++i) {
    glBegin(GL_POINTS);
    calls[i]();
    glEnd();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION)) << "call " << i;
  }
  EXPECT_EQ(get_float(GL_POINT_SIZE), 1.0f);
  EXPECT_EQ(get_float(GL_LINE_WIDTH), 1.0f);
  EXPECT_EQ(get_int(GL_LINE_STIPPLE_REPEAT), 1);
  EXPECT_EQ(get_float(GL_POLYGON_OFFSET_FACTOR), 0.0f);
}

TEST_F(RasterModes, RoundTrips) {
  glPointSize(3.5f);
  glLineWidth(2.25f);
  EXPECT_EQ(get_float(GL_POINT_SIZE), 3.5f);
  EXPECT_EQ(get_float(GL_LINE_WIDTH), 2.25f);
  // GL 2.1 §3.4.2: the repeat factor is clamped to [1, 256].
  glLineStipple(0, 0x1234);
  EXPECT_EQ(get_int(GL_LINE_STIPPLE_REPEAT), 1);
  EXPECT_EQ(get_int(GL_LINE_STIPPLE_PATTERN), 0x1234);
  glLineStipple(1000, 0xabcd);
  EXPECT_EQ(get_int(GL_LINE_STIPPLE_REPEAT), 256);
  EXPECT_EQ(get_int(GL_LINE_STIPPLE_PATTERN), 0xabcd);
  glPolygonOffset(-1.5f, 4.0f);
  EXPECT_EQ(get_float(GL_POLYGON_OFFSET_FACTOR), -1.5f);
  EXPECT_EQ(get_float(GL_POLYGON_OFFSET_UNITS), 4.0f);
  glPointParameterf(GL_POINT_SIZE_MIN, 2.0f);
  glPointParameteri(GL_POINT_SIZE_MAX, 7);
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 0.5f);
  const GLint atten[3] = {1, 2, 3};
  glPointParameteriv(GL_POINT_DISTANCE_ATTENUATION, atten);
  EXPECT_EQ(get_float(GL_POINT_SIZE_MIN), 2.0f);
  EXPECT_EQ(get_float(GL_POINT_SIZE_MAX), 7.0f);
  EXPECT_EQ(get_float(GL_POINT_FADE_THRESHOLD_SIZE), 0.5f);
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(get_float(GL_POINT_DISTANCE_ATTENUATION, i), i + 1.0f);
  for (GLenum cap :
       {GL_POINT_SMOOTH, GL_LINE_SMOOTH, GL_LINE_STIPPLE, GL_POLYGON_SMOOTH, GL_POLYGON_STIPPLE,
        GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT}) {
    glEnable(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_TRUE) << std::hex << cap;
    GLboolean b = GL_FALSE;
    glGetBooleanv(cap, &b);
    EXPECT_EQ(b, GL_TRUE);
    glDisable(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE);
  }
  expect_error(GL_NO_ERROR);
}

// GL 2.1 §3.6.4: the stipple is unpacked like a bitmap and packed back the same way.
TEST_F(RasterModes, PolygonStippleUnpackAndPack) {
  GLubyte in[128];
  for (int i = 0; i < 128; ++i)
    in[i] = static_cast<GLubyte>(i * 29 + 7);
  glPolygonStipple(in);
  GLubyte out[128] = {};
  glGetPolygonStipple(out);
  for (int i = 0; i < 128; ++i)
    EXPECT_EQ(out[i], in[i]) << i;
  // LSB_FIRST on unpack only: every byte comes back bit-reversed.
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glPolygonStipple(in);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glGetPolygonStipple(out);
  for (int i = 0; i < 128; ++i) {
    GLubyte rev = 0;
    for (int b = 0; b < 8; ++b)
      if (in[i] & (1 << b)) rev = static_cast<GLubyte>(rev | (0x80 >> b));
    EXPECT_EQ(out[i], rev) << i;
  }
  // Row length 40, skip 3 pixels and 2 rows, alignment 2 on pack: rows of 6 bytes (40 bits
  // rounded up to 2-byte units); bits outside the pattern keep their values.
  glPolygonStipple(in);
  glPixelStorei(GL_PACK_ROW_LENGTH, 40);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_PACK_SKIP_ROWS, 2);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  std::vector<GLubyte> big(34 * 6, 0x5a);
  glGetPolygonStipple(big.data());
  for (int r = 0; r < 34; ++r)
    for (int bit = 0; bit < 48; ++bit) {
      const bool got = (big[r * 6 + bit / 8] >> (7 - bit % 8)) & 1;
      const int c = bit - 3, pr = r - 2;
      bool want;
      if (pr >= 0 && c >= 0 && c < 32)
        want = (in[pr * 4 + c / 8] >> (7 - c % 8)) & 1;
      else
        want = (0x5a >> (7 - bit % 8)) & 1;
      EXPECT_EQ(got, want) << r << "," << bit;
    }
  // The same layout on unpack reads the same pattern back.
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 40);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  glPolygonStipple(big.data());
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_PACK_SKIP_ROWS, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetPolygonStipple(out);
  for (int i = 0; i < 128; ++i)
    EXPECT_EQ(out[i], in[i]) << i;
  expect_error(GL_NO_ERROR);
}

TEST_F(RasterModes, AttribGroups) {
  glLineWidth(3.0f);
  glLineStipple(3, 0x00ff);
  glPointSize(4.0f);
  glPointParameterf(GL_POINT_SIZE_MIN, 2.0f);
  glPolygonOffset(2.0f, 3.0f);
  GLubyte ones[128];
  for (GLubyte& b : ones)
    b = 0x0f;
  glPolygonStipple(ones);
  glPushAttrib(GL_LINE_BIT | GL_POINT_BIT | GL_POLYGON_BIT | GL_POLYGON_STIPPLE_BIT);
  glLineWidth(1.0f);
  glLineStipple(1, 0xffff);
  glEnable(GL_LINE_STIPPLE);
  glPointSize(1.0f);
  glPointParameterf(GL_POINT_SIZE_MIN, 0.0f);
  glEnable(GL_POINT_SMOOTH);
  glPolygonOffset(0.0f, 0.0f);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glEnable(GL_POLYGON_STIPPLE);
  GLubyte zeros[128] = {};
  glPolygonStipple(zeros);
  glPopAttrib();
  EXPECT_EQ(get_float(GL_LINE_WIDTH), 3.0f);
  EXPECT_EQ(get_int(GL_LINE_STIPPLE_REPEAT), 3);
  EXPECT_EQ(get_int(GL_LINE_STIPPLE_PATTERN), 0x00ff);
  EXPECT_EQ(glIsEnabled(GL_LINE_STIPPLE), GL_FALSE);
  EXPECT_EQ(get_float(GL_POINT_SIZE), 4.0f);
  EXPECT_EQ(get_float(GL_POINT_SIZE_MIN), 2.0f);
  EXPECT_EQ(glIsEnabled(GL_POINT_SMOOTH), GL_FALSE);
  EXPECT_EQ(get_float(GL_POLYGON_OFFSET_FACTOR), 2.0f);
  EXPECT_EQ(get_float(GL_POLYGON_OFFSET_UNITS), 3.0f);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_OFFSET_FILL), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_STIPPLE), GL_FALSE);
  GLubyte out[128];
  glGetPolygonStipple(out);
  for (GLubyte b : out)
    EXPECT_EQ(b, 0x0f);

  // ENABLE_BIT covers the enables only; other groups are left alone.
  glPushAttrib(GL_ENABLE_BIT);
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_POLYGON_OFFSET_POINT);
  glLineWidth(5.0f);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_LINE_SMOOTH), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_OFFSET_POINT), GL_FALSE);
  EXPECT_EQ(get_float(GL_LINE_WIDTH), 5.0f);
  // POLYGON_STIPPLE_BIT alone does not restore the POLYGON_BIT state.
  glPushAttrib(GL_POLYGON_STIPPLE_BIT);
  glPolygonOffset(7.0f, 7.0f);
  glPolygonStipple(zeros);
  glPopAttrib();
  EXPECT_EQ(get_float(GL_POLYGON_OFFSET_FACTOR), 7.0f);
  glGetPolygonStipple(out);
  for (GLubyte b : out)
    EXPECT_EQ(b, 0x0f);
  expect_error(GL_NO_ERROR);
}

TEST_F(RasterModes, AliasedPointSquares) {
  // GL 2.1 §3.3.1: odd sizes centre on the pixel holding the point, even ones on the nearest
  // pixel corner; fractional sizes round to the nearest integer.
  const struct {
    float size, x, y;
    int x0, y0, w;
  } cases[] = {
      {1.0f, 10.3f, 12.7f, 10, 12, 1}, {3.0f, 10.3f, 12.7f, 9, 11, 3},
      {2.0f, 10.3f, 12.7f, 9, 12, 2},  {4.0f, 10.6f, 12.2f, 9, 10, 4},
      {2.6f, 15.5f, 15.5f, 14, 14, 3}, {1.4f, 5.5f, 5.5f, 5, 5, 1},
      {7.0f, 2.5f, 2.5f, -1, -1, 7}, // partly outside the buffer
  };
  for (const auto& c : cases) {
    pixel_setup();
    glPointSize(c.size);
    glBegin(GL_POINTS);
    glVertex2f(c.x, c.y);
    glEnd();
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const bool in = x >= c.x0 && x < c.x0 + c.w && y >= c.y0 && y < c.y0 + c.w;
        EXPECT_EQ((pixel(x, y) & 0xffffff) != 0, in) << c.size << " at " << x << "," << y;
      }
  }
}

// GL 2.1 §3.3 eq 3.1 against a double reference, with Mesa's distance |z_eye|: the drawn
// square's side is the derived size rounded, clamped by POINT_SIZE_MIN / MAX.
TEST_F(RasterModes, AttenuatedPointSize) {
  const double a = 0.5, b = 0.2, c = 0.05, size = 9.0, lo = 1.5, hi = 7.0;
  for (double z : {-0.1, -1.0, -2.0, -4.0, -6.0, -9.0}) {
    pixel_setup();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, kW, 0, kH, 0.0, 20.0); // eye z in [-20, 0] maps into the depth range
    glMatrixMode(GL_MODELVIEW);
    const GLfloat atten[3] = {static_cast<GLfloat>(a), static_cast<GLfloat>(b),
                              static_cast<GLfloat>(c)};
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, atten);
    glPointParameterf(GL_POINT_SIZE_MIN, static_cast<GLfloat>(lo));
    glPointParameterf(GL_POINT_SIZE_MAX, static_cast<GLfloat>(hi));
    glPointSize(static_cast<GLfloat>(size));
    glBegin(GL_POINTS);
    glVertex3f(16.5f, 16.5f, static_cast<GLfloat>(z));
    glEnd();
    const double d = std::fabs(z);
    double derived = size / std::sqrt(a + b * d + c * d * d);
    derived = std::min(std::max(derived, lo), hi);
    const int w = std::max(1, static_cast<int>(std::ceil(derived - 0.5)));
    EXPECT_EQ(lit_count(), w * w) << "z " << z << " size " << derived;
  }
}

// Stipple counters (GL 2.1 §3.4.2): independent segments restart the pattern, a strip carries it
// on. A horizontal line through pixel centres has one fragment per column, counter = column.
TEST_F(RasterModes, LineStippleCounters) {
  const GLushort pattern = 0x3a5c;
  for (int factor = 1; factor <= 3; ++factor) {
    pixel_setup();
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(factor, pattern);
    glBegin(GL_LINES); // two independent segments on row 3
    glVertex2f(0.5f, 3.5f);
    glVertex2f(12.5f, 3.5f);
    glVertex2f(12.5f, 3.5f);
    glVertex2f(31.5f, 3.5f);
    glEnd();
    glBegin(GL_LINE_STRIP); // one strip of two segments on row 8
    glVertex2f(0.5f, 8.5f);
    glVertex2f(12.5f, 8.5f);
    glVertex2f(31.5f, 8.5f);
    glEnd();
    glDisable(GL_LINE_STIPPLE);
    const auto bit = [&](int i) { return ((pattern >> ((i / factor) % 16)) & 1) != 0; };
    for (int x = 0; x < 31; ++x) {
      const bool seg = bit(x < 12 ? x : x - 12);
      EXPECT_EQ((pixel(x, 3) & 0xffffff) != 0, seg) << "lines factor " << factor << " x " << x;
      EXPECT_EQ((pixel(x, 8) & 0xffffff) != 0, bit(x)) << "strip factor " << factor << " x " << x;
    }
  }
}

// Where strip vertices and outline corners are not at pixel centres the counter follows
// llvmpipe, not a count of fragments: the rows below are what llvmpipe (Mesa 22.3) draws.
TEST_F(RasterModes, LineStippleMatchesLlvmpipe) {
  const auto row = [&](int y) {
    std::string r;
    for (int x = 0; x < kW; ++x)
      r += (pixel(x, y) & 0xffffff) != 0 ? '#' : '.';
    return r;
  };
  const auto strip = [] {
    glBegin(GL_LINE_STRIP);
    glVertex2f(0.5f, 10.5f);
    glVertex2f(7.2f, 10.5f);
    glVertex2f(19.7f, 10.5f);
    glVertex2f(31.5f, 10.5f);
    glEnd();
  };
  pixel_setup();
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(1, 0x0f0f);
  strip();
  EXPECT_EQ(row(10), "####....####....###....####.....");
  pixel_setup();
  glLineStipple(2, 0x0f0f);
  strip();
  EXPECT_EQ(row(10), "########........#######.........");
  // LINE-mode outlines restart the pattern with each triangle and each quad; a triangle's
  // outline starts with its closing edge, a quad's with its last edge.
  glLineStipple(1, 0x0f0f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  pixel_setup();
  glBegin(GL_TRIANGLES);
  glVertex2f(1.5f, 2.5f);
  glVertex2f(14.5f, 2.5f);
  glVertex2f(14.5f, 15.5f);
  glVertex2f(16.5f, 2.5f);
  glVertex2f(30.5f, 2.5f);
  glVertex2f(30.5f, 16.5f);
  glEnd();
  EXPECT_EQ(row(2), "....####....###...####....####..");
  pixel_setup();
  glBegin(GL_QUADS);
  glVertex2f(1.5f, 2.5f);
  glVertex2f(14.5f, 2.5f);
  glVertex2f(14.5f, 15.5f);
  glVertex2f(1.5f, 15.5f);
  glVertex2f(16.5f, 2.5f);
  glVertex2f(30.5f, 2.5f);
  glVertex2f(30.5f, 16.5f);
  glVertex2f(16.5f, 16.5f);
  glEnd();
  EXPECT_EQ(row(2), "....####....###...####....####..");
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDisable(GL_LINE_STIPPLE);
}

// Wide lines: an x-major line gets a vertical run of w pixels per column, centred on the line.
TEST_F(RasterModes, WideLineColumns) {
  for (int w = 2; w <= 5; ++w) {
    pixel_setup();
    glLineWidth(static_cast<float>(w));
    glBegin(GL_LINES);
    glVertex2f(2.0f, 16.25f);
    glVertex2f(30.0f, 16.25f);
    glEnd();
    // Centres y + 1/2 within w/2 of 16.25.
    for (int y = 0; y < kH; ++y) {
      const double c = y + 0.5;
      const bool in = c >= 16.25 - w / 2.0 && c < 16.25 + w / 2.0;
      EXPECT_EQ((pixel(15, y) & 0xffffff) != 0, in) << "w " << w << " y " << y;
    }
    EXPECT_EQ(lit_count(), 28 * w);
  }
  glLineWidth(1.0f);
}

TEST_F(RasterModes, PolygonStippleMasksFill) {
  GLubyte mask[128];
  for (int r = 0; r < 32; ++r)
    for (int b = 0; b < 4; ++b)
      mask[r * 4 + b] = static_cast<GLubyte>(r & 1 ? 0xa5 : 0x3c);
  glPolygonStipple(mask);
  pixel_setup();
  glEnable(GL_POLYGON_STIPPLE);
  glRectf(0, 0, kW, kH);
  glDisable(GL_POLYGON_STIPPLE);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const bool on = (mask[y * 4 + x / 8] >> (7 - x % 8)) & 1;
      EXPECT_EQ((pixel(x, y) & 0xffffff) != 0, on) << x << "," << y;
    }
}

// GL 2.1 §3.5.5: o = factor * max|dz/dxy| + 2 units / (2^24 - 1) (llvmpipe's r), checked
// through the depth test against a reference plane.
TEST_F(RasterModes, PolygonOffsetFill) {
  pixel_setup();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  // A slanted plane z_win from 0.25 to 0.75 across x (slope 0.5/32 per pixel).
  const auto slanted = [] {
    glBegin(GL_QUADS);
    glVertex3f(0, 0, -0.5f);
    glVertex3f(32, 0, 0.5f);
    glVertex3f(32, 32, 0.5f);
    glVertex3f(0, 32, -0.5f);
    glEnd();
  };
  glColor3f(1, 0, 0);
  slanted();
  // The same plane pushed towards the viewer by one slope step: it wins the LESS test
  // everywhere; pushed away it loses.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.0f, 0.0f);
  glColor3f(0, 1, 0);
  slanted();
  for (int x = 0; x < kW; ++x)
    EXPECT_EQ(pixel(x, 10) & 0xffffff, 0x00ff00u) << x;
  glPolygonOffset(1.0f, 0.0f);
  glColor3f(0, 0, 1);
  slanted();
  for (int x = 0; x < kW; ++x)
    EXPECT_EQ(pixel(x, 10) & 0xffffff, 0x00ff00u) << x;
  // Units alone: -1 unit moves by two depth steps, enough to win against the plane; +1 loses.
  glClear(GL_DEPTH_BUFFER_BIT);
  glDisable(GL_POLYGON_OFFSET_FILL);
  slanted();
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0.0f, 1.0f);
  glColor3f(1, 0, 1);
  slanted();
  for (int x = 0; x < kW; ++x)
    EXPECT_EQ(pixel(x, 10) & 0xffffff, 0xff0000u) << x; // the blue plane stays
  glPolygonOffset(0.0f, -1.0f);
  glColor3f(1, 1, 1);
  slanted();
  for (int x = 0; x < kW; ++x)
    EXPECT_EQ(pixel(x, 10) & 0xffffff, 0xffffffu) << x;
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_DEPTH_TEST);
  expect_error(GL_NO_ERROR);
}

} // namespace
