// sRGB textures (GL 2.1 §3.8.1 Tables 3.16-3.17, §3.8.15; EXT_texture_sRGB): the internal
// formats and their queries, texels kept as given (GetTexImage returns them unchanged),
// decoding of R, G, B (or L) to linear before filtering with alpha left linear, at every
// filter and SIMD path, and the level-format match of mipmap completeness.
#include <cmath>
#include <cstdlib>
#include <vector>

#define GL_GLEXT_PROTOTYPES
#include "api_fixture.h"

namespace {

using SrgbTexture = GLTest;

// GL 2.1 eq. 3.28 as the 8-bit value a REPLACE texture writes to the colour buffer.
int decoded8(int c) {
  const double v = c / 255.0;
  const double lin = v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  return static_cast<int>(std::lround(lin * 255.0));
}

void pixel_ortho() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 32, 0, 32, -1, 1); // the fixture's 32x32 buffer
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

// The whole window textured with s, t in [0, 1].
void full_quad() {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(0, 0);
  glTexCoord2f(1, 0);
  glVertex2f(32, 0);
  glTexCoord2f(1, 1);
  glVertex2f(32, 32);
  glTexCoord2f(0, 1);
  glVertex2f(0, 32);
  glEnd();
}

GLuint texture_2d(GLint internal, int w, int h, GLenum format, const void* data, GLenum filter) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, internal, w, h, 0, format, GL_UNSIGNED_BYTE, data);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  return t;
}

TEST_F(SrgbTexture, FormatsAndQueries) {
  struct Case {
    GLint internal;
    GLint reported;
    GLint red, alpha, luminance;
  };
  const Case cases[] = {
      {GL_SRGB, GL_SRGB, 8, 0, 0},
      {GL_SRGB8, GL_SRGB8, 8, 0, 0},
      {GL_SRGB_ALPHA, GL_SRGB_ALPHA, 8, 8, 0},
      {GL_SRGB8_ALPHA8, GL_SRGB8_ALPHA8, 8, 8, 0},
      {GL_SLUMINANCE, GL_SLUMINANCE, 0, 0, 8},
      {GL_SLUMINANCE8, GL_SLUMINANCE8, 0, 0, 8},
      {GL_SLUMINANCE_ALPHA, GL_SLUMINANCE_ALPHA, 0, 8, 8},
      {GL_SLUMINANCE8_ALPHA8, GL_SLUMINANCE8_ALPHA8, 0, 8, 8},
      // The generic compressed sRGB formats are stored uncompressed (§3.8.1), read back as
      // their base format.
      {GL_COMPRESSED_SRGB, GL_SRGB, 8, 0, 0},
      {GL_COMPRESSED_SRGB_ALPHA, GL_SRGB_ALPHA, 8, 8, 0},
      {GL_COMPRESSED_SLUMINANCE, GL_SLUMINANCE, 0, 0, 8},
      {GL_COMPRESSED_SLUMINANCE_ALPHA, GL_SLUMINANCE_ALPHA, 0, 8, 8},
  };
  for (const Case& c : cases) {
    glTexImage2D(GL_TEXTURE_2D, 0, c.internal, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << std::hex << c.internal;
    GLint v = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v);
    EXPECT_EQ(v, c.reported) << std::hex << c.internal;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &v);
    EXPECT_EQ(v, c.red) << std::hex << c.internal;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_ALPHA_SIZE, &v);
    EXPECT_EQ(v, c.alpha) << std::hex << c.internal;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_LUMINANCE_SIZE, &v);
    EXPECT_EQ(v, c.luminance) << std::hex << c.internal;
    GLint compressed = -1;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &compressed);
    EXPECT_EQ(compressed, GL_FALSE);
  }
  // Proxies accept them too.
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr);
  GLint w = 0;
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(w, 64);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// §3.8.15: R, G, B decoded, alpha not; GetTexImage returns the stored sRGB values (§6.1.4).
TEST_F(SrgbTexture, DecodedWhenSampledNotWhenRead) {
  pixel_ortho();
  const GLubyte texel[4] = {128, 64, 200, 128};
  const GLuint t = texture_2d(GL_SRGB8_ALPHA8, 1, 1, GL_RGBA, texel, GL_NEAREST);
  full_quad();
  const uint32_t p = pixel(5, 5);
  EXPECT_EQ(static_cast<int>(p & 0xff), decoded8(128));
  EXPECT_EQ(static_cast<int>((p >> 8) & 0xff), decoded8(64));
  EXPECT_EQ(static_cast<int>((p >> 16) & 0xff), decoded8(200));
  EXPECT_EQ(static_cast<int>(p >> 24), 128);
  GLubyte back[4] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  EXPECT_EQ(back[0], 128);
  EXPECT_EQ(back[1], 64);
  EXPECT_EQ(back[2], 200);
  EXPECT_EQ(back[3], 128);
  // SLUMINANCE_ALPHA: L decoded into R, G and B, alpha linear.
  const GLubyte la[2] = {100, 50};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SLUMINANCE8_ALPHA8, 1, 1, 0, GL_LUMINANCE_ALPHA,
               GL_UNSIGNED_BYTE, la);
  full_quad();
  const uint32_t q = pixel(5, 5);
  for (int c = 0; c < 3; ++c)
    EXPECT_EQ(static_cast<int>((q >> (8 * c)) & 0xff), decoded8(100)) << c;
  EXPECT_EQ(static_cast<int>(q >> 24), 50);
  glDeleteTextures(1, &t);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// Filtering happens on linear values: halfway between black and white is linear 0.5 (128),
// not the decoded sRGB midpoint (55). Every magnification and minification path, at every
// position, equals the linear interpolation of the decoded texels to within one step.
TEST_F(SrgbTexture, FilteredAfterDecoding) {
  pixel_ortho();
  // 2x2: black and white columns.
  const GLubyte bw[2 * 2 * 3] = {0, 0, 0, 255, 255, 255, 0, 0, 0, 255, 255, 255};
  for (GLenum min : {GL_LINEAR, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_NEAREST}) {
    const GLuint t = texture_2d(GL_SRGB8, 2, 2, GL_RGB, bw, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(min));
    const GLubyte grey[3] = {128, 128, 128};
    glTexImage2D(GL_TEXTURE_2D, 1, GL_SRGB8, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, grey);
    glClear(GL_COLOR_BUFFER_BIT);
    full_quad(); // magnified 16x: s runs over the two texels
    for (int x = 0; x < kW; ++x) {
      // s at pixel centre; texel centres at 0.25 and 0.75.
      const double s = (x + 0.5) / kW;
      const double w = std::clamp((s - 0.25) * 2.0, 0.0, 1.0);
      const int expect = static_cast<int>(std::lround(w * 255.0));
      const int got = static_cast<int>(pixel(x, 7) & 0xff);
      ASSERT_LE(std::abs(got - expect), 1) << "x " << x << " min " << std::hex << min;
    }
    // Halfway (s = 15.5 / 32, weight 0.46875): 120 in linear; averaging the sRGB values and
    // decoding afterwards would give about 50.
    EXPECT_NEAR(static_cast<int>(pixel(15, 7) & 0xff), 120, 1);
    glDeleteTextures(1, &t);
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// Levels must match the base level's format, sRGB or not (§3.8.10).
TEST_F(SrgbTexture, MipmapLevelsMustMatch) {
  pixel_ortho();
  const GLubyte white[4 * 4] = {255, 255, 255, 255, 255, 255, 255, 255,
                                255, 255, 255, 255, 255, 255, 255, 255};
  const GLuint t = texture_2d(GL_SRGB8_ALPHA8, 2, 2, GL_RGBA, white, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
  glColor4f(0, 0, 0, 1);
  full_quad();
  // Incomplete: texturing is as if disabled (§3.8.10), the fragment keeps its colour.
  EXPECT_EQ(pixel(3, 3), 0xff000000u);
  glTexImage2D(GL_TEXTURE_2D, 1, GL_SRGB8_ALPHA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
  full_quad();
  EXPECT_EQ(pixel(3, 3), 0xffffffffu);
  glDeleteTextures(1, &t);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// GENERATE_MIPMAP of an sRGB image filters in linear space: black and white average to linear
// 0.5, which encodes as 188 (Mesa gives 187); alpha is linear. A linear image averages to 128.
TEST_F(SrgbTexture, GeneratedLevelsAreFilteredInLinearSpace) {
  const GLubyte img[2 * 2 * 4] = {0, 0, 0, 255, 255, 255, 255, 0, 0, 0, 0, 255, 255, 255, 255, 0};
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  GLubyte out[4] = {};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(out[c], 188, 1) << c;
  EXPECT_NEAR(out[3], 128, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_NEAR(out[0], 128, 1);
  glDeleteTextures(1, &t);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

} // namespace
