// Texture objects through the GL API (GL 2.1 §3.8.1, §3.8.4, §3.8.12, §6.1.3): names, binding,
// parameters, image specification, proxies, level queries and their errors.
#include <GL/glext.h>

#include <array>
#include <functional>
#include <cmath>
#include <vector>

#include "api_fixture.h"
#include "state/context.h"
#include "texture/sampler.h"
#include "state/texture_object.h"

namespace {

class TextureTest : public GLTest {
protected:
  GLenum err() { return glGetError(); }
  // Samples the 2D texture bound to unit 0 at (s, t) with lambda 0 (magnification).
  std::array<float, 4> sample2d(float s, float t, float lambda = 0.0f) {
    pineda::Context* ctx = pineda::current_context();
    const pineda::TextureObject* tex = pineda::bound_texture(ctx, 0, GL_TEXTURE_2D);
    pineda::SamplerView v;
    EXPECT_TRUE(pineda::make_sampler_view(*tex, v));
    float out[1][4];
    pineda::sample_texture(v, 1, &s, &t, nullptr, &lambda, 0.0f, out);
    return {out[0][0], out[0][1], out[0][2], out[0][3]};
  }
};

TEST_F(TextureTest, GenBindIsDelete) {
  GLuint names[3] = {};
  glGenTextures(3, names);
  EXPECT_NE(names[0], 0u);
  EXPECT_NE(names[0], names[1]);
  EXPECT_FALSE(glIsTexture(names[0])); // a name is not an object until bound
  glBindTexture(GL_TEXTURE_2D, names[0]);
  EXPECT_TRUE(glIsTexture(names[0]));
  GLint b = -1;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &b);
  EXPECT_EQ(b, GLint(names[0]));
  // §3.8.12: rebinding to another dimensionality is INVALID_OPERATION.
  glBindTexture(GL_TEXTURE_1D, names[0]);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glDeleteTextures(3, names);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &b);
  EXPECT_EQ(b, 0);
  EXPECT_FALSE(glIsTexture(names[0]));
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 1);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glGenTextures(-1, names);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

TEST_F(TextureTest, TexImage2DAndNearestLinear) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  const uint8_t px[2 * 2 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 0};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  auto c = sample2d(0.25f, 0.25f);
  EXPECT_FLOAT_EQ(c[0], 1.0f);
  EXPECT_FLOAT_EQ(c[1], 0.0f);
  c = sample2d(0.75f, 0.75f);
  EXPECT_FLOAT_EQ(c[3], 0.0f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  c = sample2d(0.5f, 0.5f); // the average of the four, in 8-bit steps
  EXPECT_NEAR(c[0], 0.5f, 2.0f / 255.0f);
  EXPECT_NEAR(c[3], 0.75f, 2.0f / 255.0f);
  GLint w = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  glDeleteTextures(1, &t);
}

TEST_F(TextureTest, ParameterDefaultsAndErrors) {
  GLint v = 0;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &v);
  EXPECT_EQ(v, GL_NEAREST_MIPMAP_LINEAR);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &v);
  EXPECT_EQ(v, GL_LINEAR);
  glGetTexParameteriv(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, &v);
  EXPECT_EQ(v, GL_REPEAT);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, &v);
  EXPECT_EQ(v, 1000);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_RESIDENT, &v);
  EXPECT_EQ(v, GL_TRUE);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, &v);
  EXPECT_EQ(v, GL_LUMINANCE);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, &v);
  EXPECT_EQ(v, GL_LEQUAL);
  GLfloat f = 0;
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, &f);
  EXPECT_EQ(f, -1000.0f);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &f);
  EXPECT_EQ(f, 1.0f);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));

  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_NEAREST);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_RESIDENT, GL_TRUE); // query only
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0); // needs the vector form
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -1);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, -2.0f);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_LEQUAL);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_RGB);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_PROXY_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glGetTexParameteriv(GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_MIN_FILTER, &v);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));

  // Values round-trip; the border colour is clamped and converted per Table 2.9.
  const GLfloat bc[4] = {-1.0f, 0.5f, 2.0f, 0.25f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, bc);
  GLfloat got[4];
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, got);
  EXPECT_EQ(got[0], 0.0f);
  EXPECT_EQ(got[1], 0.5f);
  EXPECT_EQ(got[2], 1.0f);
  GLint gi[4];
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, gi);
  EXPECT_EQ(gi[2], 2147483647);
  const GLint ic[4] = {2147483647, 0, 0, 2147483647};
  glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, ic);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, got);
  EXPECT_EQ(got[0], 1.0f);
  EXPECT_NEAR(got[1], 0.0f, 1e-9);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 3.0f);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &f);
  EXPECT_EQ(f, 1.0f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, -2.5f);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, &f);
  EXPECT_EQ(f, -2.5f);
  for (GLenum wrap : {GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT}) {
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GLint(wrap));
    glGetTexParameteriv(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, &v);
    EXPECT_EQ(GLenum(v), wrap);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, &v);
  EXPECT_EQ(v, GL_TRUE);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

TEST_F(TextureTest, TexImageErrors) {
  const uint8_t px[64] = {};
  glTexImage2D(GL_TEXTURE_1D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexImage2D(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_STENCIL_INDEX, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_2D, 12, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_2D, 0, 5, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -1, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px); // < 2b
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4096, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_2D, 3, GL_RGBA, 512, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE)); // level 3 holds at most 2048 >> 3
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 2, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glTexImage3D(GL_TEXTURE_3D, 0, GL_DEPTH_COMPONENT, 2, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_DEPTH_COMPONENT, 2, 2, 0, GL_DEPTH_COMPONENT,
               GL_FLOAT, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // Non-power-of-two sizes are fine (GL 2.0), and so are zero sizes.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  glBegin(GL_POINTS);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  glEnd();
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
}

// Sizes llvmpipe reports for each internal format (GL 2.1 Table 6.20 queries).
TEST_F(TextureTest, LevelParametersPerFormat) {
  const struct {
    GLint fmt;
    GLint r, g, b, a, l, i, d;
  } cases[] = {
      {GL_ALPHA, 0, 0, 0, 8, 0, 0, 0},
      {GL_ALPHA12, 0, 0, 0, 16, 0, 0, 0},
      {GL_LUMINANCE4, 0, 0, 0, 0, 8, 0, 0},
      {1, 0, 0, 0, 0, 8, 0, 0},
      {2, 0, 0, 0, 8, 8, 0, 0},
      {GL_LUMINANCE4_ALPHA4, 0, 0, 0, 4, 4, 0, 0},
      {GL_INTENSITY16, 0, 0, 0, 0, 0, 16, 0},
      {GL_R3_G3_B2, 3, 3, 2, 0, 0, 0, 0},
      {GL_RGB5, 5, 5, 5, 0, 0, 0, 0},
      {GL_RGB10, 10, 10, 10, 0, 0, 0, 0},
      {GL_RGBA2, 4, 4, 4, 4, 0, 0, 0},
      {GL_RGB5_A1, 5, 5, 5, 1, 0, 0, 0},
      {GL_RGB10_A2, 10, 10, 10, 2, 0, 0, 0},
      {4, 8, 8, 8, 8, 0, 0, 0},
      {GL_DEPTH_COMPONENT, 0, 0, 0, 0, 0, 0, 24},
      {GL_DEPTH_COMPONENT16, 0, 0, 0, 0, 0, 0, 16},
  };
  for (const auto& c : cases) {
    const bool depth = c.d != 0;
    glTexImage2D(GL_TEXTURE_2D, 1, c.fmt, 3, 2, 0, depth ? GL_DEPTH_COMPONENT : GL_RGBA,
                 depth ? GL_FLOAT : GL_UNSIGNED_BYTE, nullptr);
    ASSERT_EQ(err(), GLenum(GL_NO_ERROR)) << c.fmt;
    const GLenum pn[] = {GL_TEXTURE_RED_SIZE,       GL_TEXTURE_GREEN_SIZE,
                         GL_TEXTURE_BLUE_SIZE,      GL_TEXTURE_ALPHA_SIZE,
                         GL_TEXTURE_LUMINANCE_SIZE, GL_TEXTURE_INTENSITY_SIZE,
                         GL_TEXTURE_DEPTH_SIZE};
    const GLint want[] = {c.r, c.g, c.b, c.a, c.l, c.i, c.d};
    for (int k = 0; k < 7; ++k) {
      GLint v = -1;
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, pn[k], &v);
      EXPECT_EQ(v, want[k]) << c.fmt << " " << k;
    }
    GLint v = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_INTERNAL_FORMAT, &v);
    EXPECT_EQ(v, c.fmt);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_WIDTH, &v);
    EXPECT_EQ(v, 3);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_HEIGHT, &v);
    EXPECT_EQ(v, 2);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_COMPRESSED, &v);
    EXPECT_EQ(v, GL_FALSE);
  }
  // An unspecified image: zero sizes, internal format 1.
  GLint v = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 5, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(v, 0);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 5, GL_TEXTURE_INTERNAL_FORMAT, &v);
  EXPECT_EQ(v, 1);
  glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glGetTexLevelParameteriv(GL_TEXTURE_2D, -1, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_MIN_FILTER, &v);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &v);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
}

// §3.8.11: proxies record supported images and read back zeros for unsupported ones,
// without errors; the bound texture is untouched.
TEST_F(TextureTest, Proxies) {
  GLint v = -1;
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA8, 64, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(v, 64);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &v);
  EXPECT_EQ(v, 8);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(v, 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA8, 4096, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(v, 0);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &v);
  EXPECT_EQ(v, 0);
  glTexImage1D(GL_PROXY_TEXTURE_1D, 0, GL_LUMINANCE, 2048, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_1D, 0, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(v, 2048);
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 2048, 2048, 2048, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr); // 32 GiB: beyond what Pineda accepts
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &v);
  EXPECT_EQ(v, 0);
  glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(v, 16);
  glTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &v);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glGetTexImage(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &v);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  GLint limits[3];
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &limits[0]);
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &limits[1]);
  glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &limits[2]);
  EXPECT_EQ(limits[0], 2048);
  EXPECT_EQ(limits[1], 2048);
  EXPECT_EQ(limits[2], 2048);
  GLfloat bias = 0;
  glGetFloatv(GL_MAX_TEXTURE_LOD_BIAS, &bias);
  EXPECT_EQ(bias, 16.0f);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

// An image Pineda cannot store is OUT_OF_MEMORY and leaves the old image in place.
TEST_F(TextureTest, OutOfMemoryChangesNothing) {
  const uint8_t px[4] = {1, 2, 3, 4};
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2048, 2048, 2048, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(err(), GLenum(GL_OUT_OF_MEMORY));
  GLint v = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(v, 1);
  uint8_t back[4] = {};
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  EXPECT_EQ(back[2], 3);
}

// Uploads through the unpack state and read back through the pack state (§3.8.1, §6.1.4).
TEST_F(TextureTest, SubImageAndGetTexImage) {
  std::vector<uint8_t> img(4 * 4 * 3);
  for (size_t i = 0; i < img.size(); ++i)
    img[i] = uint8_t(i * 5);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, img.data());
  const uint8_t patch[2 * 4] = {9, 8, 7, 6, 5, 4, 3, 2};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 2, 2, 1, GL_BGRA, GL_UNSIGNED_BYTE, patch);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  std::vector<uint8_t> back(4 * 4 * 4);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back.data());
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const uint8_t* b = &back[(y * 4 + x) * 4];
      if (y == 2 && (x == 1 || x == 2)) {
        const uint8_t* p = &patch[(x - 1) * 4];
        EXPECT_EQ(b[0], p[2]);
        EXPECT_EQ(b[1], p[1]);
        EXPECT_EQ(b[2], p[0]);
      } else {
        const uint8_t* p = &img[(y * 4 + x) * 3];
        EXPECT_EQ(b[0], p[0]);
        EXPECT_EQ(b[2], p[2]);
      }
      EXPECT_EQ(b[3], 255); // RGB reads back alpha 1
    }
  // Region checks (§3.8.2).
  glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, patch);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glTexSubImage2D(GL_TEXTURE_2D, 0, -1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, patch);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, patch);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION)); // level 1 never specified
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, patch);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back.data());
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glGetTexImage(GL_TEXTURE_2D, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, back.data());
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  // A luminance texture reads back as L in red (Table 6.1).
  const uint8_t lum[2] = {40, 200};
  glTexImage1D(GL_TEXTURE_1D, 0, GL_LUMINANCE, 2, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
  uint8_t lb[8] = {};
  glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, lb);
  EXPECT_EQ(lb[0], 40);
  EXPECT_EQ(lb[1], 0);
  EXPECT_EQ(lb[4], 200);
  EXPECT_EQ(lb[7], 255);
  // An RGBA texture read back as LUMINANCE_ALPHA: L is R alone (llvmpipe).
  const uint8_t rgba[4] = {40, 50, 60, 70};
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glGetTexImage(GL_TEXTURE_1D, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, lb);
  EXPECT_EQ(lb[0], 40);
  EXPECT_EQ(lb[1], 70);
  // 3D with IMAGE_HEIGHT and SKIP_IMAGES.
  std::vector<float> vol(2 * 3 * 3, 0.0f); // 2x2 images of height 3, 3 images
  for (size_t i = 0; i < vol.size(); ++i)
    vol[i] = float(i) / 17.0f;
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 3);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_LUMINANCE, 2, 2, 2, 0, GL_LUMINANCE, GL_FLOAT, vol.data());
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
  float vb[8];
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RED, GL_FLOAT, vb);
  EXPECT_NEAR(vb[0], std::lround(6 / 17.0 * 255) / 255.0, 1e-6);  // image 1, row 0
  EXPECT_NEAR(vb[4], std::lround(12 / 17.0 * 255) / 255.0, 1e-6); // image 2
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

// Depth textures: floats rounded to the depth size, read back as depth.
TEST_F(TextureTest, DepthTextureRoundTrip) {
  const float z[2] = {0.25f, 0.8f};
  glTexImage1D(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT16, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, z);
  float back[2] = {};
  glGetTexImage(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back);
  EXPECT_NEAR(back[0], 0.25f, 1.0f / 65535);
  EXPECT_NEAR(back[1], 0.8f, 1.0f / 65535);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

// GENERATE_MIPMAP rebuilds the levels when the base level changes; the box filter of llvmpipe's
// blit (8-bit linear steps).
TEST_F(TextureTest, GenerateMipmap) {
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  std::vector<uint8_t> img(4 * 4 * 4, 0);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      img[(y * 4 + x) * 4] = uint8_t((x + y) % 2 ? 255 : 0);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  GLint w = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 2, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(w, 1);
  uint8_t l1[2 * 2 * 4];
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, l1);
  // lerp(lerp(0, 255, 128), lerp(255, 0, 128), 128) = lerp(128, 128, 128) = 128, as llvmpipe
  EXPECT_EQ(l1[0], 128);
  const uint8_t one[4] = {255, 255, 255, 255};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, one);
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, l1);
  EXPECT_EQ(l1[0], 192); // lerp(255, lerp(255, 0, 128), 128), llvmpipe's value
  EXPECT_EQ(l1[4], 128);
  // A 5x3 base level: level 1 is 2x1, sampled at the texel centres; the values are llvmpipe's.
  uint8_t im2[5 * 3 * 4];
  for (int i = 0; i < 15; ++i) {
    im2[i * 4] = uint8_t(i * 17), im2[i * 4 + 1] = uint8_t(255 - i * 13);
    im2[i * 4 + 2] = uint8_t(i * i), im2[i * 4 + 3] = 200;
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 5, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, im2);
  uint8_t l2[2 * 4];
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, l2);
  const uint8_t want[8] = {98, 180, 33, 200, 140, 148, 68, 200};
  for (int i = 0; i < 8; ++i)
    EXPECT_EQ(l2[i], want[i]) << i;
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

// glCopyTexImage reads the colour buffer; 1..4 are not internal formats there (§3.8.2).
TEST_F(TextureTest, CopyTexImage) {
  glClearColor(1.0f, 0.5f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 3, 4, 4, 0);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  uint8_t back[4 * 4 * 4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  EXPECT_EQ(back[0], 255);
  EXPECT_EQ(back[1], 128);
  EXPECT_EQ(back[2], 0);
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 0, 0, 2, 2);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  EXPECT_EQ(back[(1 * 4 + 1) * 4 + 2], 255);
  EXPECT_EQ(back[0], 255);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, 3, 0, 0, 4, 4, 0);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM)); // §3.8.2: INVALID_ENUM for CopyTexImage
  glCopyTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGB, 0, 0, 4, 4, 0);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 3, 3, 0, 0, 2, 2);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 0, 0, 1, 1);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));                     // no 3D image yet
  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT, 0, 0, 4, 0); // has a depth buffer
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

TEST_F(TextureTest, PrioritiesAndResidency) {
  GLuint t[2];
  glGenTextures(2, t);
  glBindTexture(GL_TEXTURE_2D, t[0]);
  glBindTexture(GL_TEXTURE_2D, t[1]);
  const GLfloat pr[2] = {0.25f, -3.0f};
  glPrioritizeTextures(2, t, pr);
  GLfloat f = 0;
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &f);
  EXPECT_EQ(f, 0.0f);
  GLboolean res[2] = {GL_FALSE, GL_FALSE};
  EXPECT_EQ(glAreTexturesResident(2, t, res), GL_TRUE);
  const GLuint bad[2] = {t[0], 999};
  EXPECT_EQ(glAreTexturesResident(2, bad, res), GL_FALSE);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glPrioritizeTextures(-1, t, pr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
}

// glPushAttrib(TEXTURE_BIT) restores bindings and the bound objects' parameters.
TEST_F(TextureTest, AttribStackRestoresBindingsAndParameters) {
  GLuint t[2];
  glGenTextures(2, t);
  glBindTexture(GL_TEXTURE_2D, t[0]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glPushAttrib(GL_TEXTURE_BIT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glBindTexture(GL_TEXTURE_2D, t[1]);
  glPopAttrib();
  GLint v = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &v);
  EXPECT_EQ(GLuint(v), t[0]);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &v);
  EXPECT_EQ(v, GL_NEAREST);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

// GL 2.1 §2.6.3: every texture object and image command is illegal between Begin and End.
TEST_F(TextureTest, IllegalInsideBeginEnd) {
  GLuint name = 0;
  GLint iv[4] = {};
  GLfloat fv[4] = {};
  GLboolean res = GL_FALSE;
  uint8_t px[64] = {};
  const std::function<void()> calls[] = {
      [&] { glGenTextures(1, &name); },
      [&] { glDeleteTextures(1, &name); },
      [&] { glIsTexture(1); },
      [&] { glBindTexture(GL_TEXTURE_2D, 1); },
      [&] { glPrioritizeTextures(1, &name, fv); },
      [&] { glAreTexturesResident(1, &name, &res); },
      [&] { glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR); },
      [&] { glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR); },
      [&] { glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, fv); },
      [&] { glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, iv); },
      [&] { glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, fv); },
      [&] { glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, iv); },
      [&] { glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, iv); },
      [&] { glGetTexLevelParameterfv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, fv); },
      [&] { glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px); },
      [&] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px); },
      [&] { glTexSubImage1D(GL_TEXTURE_1D, 0, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, px); },
      [&] { glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px); },
      [&] { glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 0, 0, 1, 0); },
      [&] { glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 1, 1, 0); },
      [&] { glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 0, 0, 0, 1); },
      [&] { glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 1, 1); },
      [&] { glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, px); },
  };
  int i = 0;
  for (const auto& call : calls) {
    glBegin(GL_TRIANGLES);
    call();
    glEnd();
    EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION)) << "call " << i;
    ++i;
  }
  // The GL 1.2 commands, through the proc-address table as applications get them.
  const auto tex_image_3d =
      reinterpret_cast<PFNGLTEXIMAGE3DPROC>(OSMesaGetProcAddress("glTexImage3D"));
  const auto tex_sub_image_3d =
      reinterpret_cast<PFNGLTEXSUBIMAGE3DPROC>(OSMesaGetProcAddress("glTexSubImage3D"));
  const auto copy_tex_sub_image_3d =
      reinterpret_cast<PFNGLCOPYTEXSUBIMAGE3DPROC>(OSMesaGetProcAddress("glCopyTexSubImage3D"));
  ASSERT_TRUE(tex_image_3d && tex_sub_image_3d && copy_tex_sub_image_3d);
  glBegin(GL_POINTS);
  tex_image_3d(GL_TEXTURE_3D, 0, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  glEnd();
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);
  tex_sub_image_3d(GL_TEXTURE_3D, 0, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  glEnd();
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);
  copy_tex_sub_image_3d(GL_TEXTURE_3D, 0, 0, 0, 0, 0, 0, 1, 1);
  glEnd();
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
}

// Texture objects are shared between contexts of one share group (GLX 1.4 §3.3.7).
TEST_F(TextureTest, SharedBetweenContexts) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  const uint8_t px[4] = {10, 20, 30, 40};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  // A second context of the same share group (what GLX share lists create).
  pineda::Context* mine = pineda::current_context();
  {
    pineda::Context other(mine->shared);
    pineda::set_current_context(&other);
    EXPECT_TRUE(glIsTexture(t));
    glBindTexture(GL_TEXTURE_2D, t);
    uint8_t back[4] = {};
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    EXPECT_EQ(back[1], 20);
    glDeleteTextures(1, &t);
    pineda::set_current_context(mine);
  }
  EXPECT_FALSE(glIsTexture(t));
  GLint b = -1;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &b);
  EXPECT_EQ(b, 0); // the name no longer names an object here either
}

// No compressed formats: generic compressed internal formats store uncompressed, the
// compressed-image commands always name an unsupported format (§3.8.3).
TEST_F(TextureTest, CompressedFormats) {
  GLint n = -1;
  glGetIntegerv(GL_NUM_COMPRESSED_TEXTURE_FORMATS, &n);
  EXPECT_EQ(n, 0);
  GLint list[4] = {-7, -7, -7, -7};
  glGetIntegerv(GL_COMPRESSED_TEXTURE_FORMATS, list);
  EXPECT_EQ(list[0], -7);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  const uint8_t px[4] = {10, 20, 30, 40};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  GLint v = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &v);
  EXPECT_EQ(v, GL_FALSE);
  // §3.8.1: with no specific compressed format the base format replaces the generic one.
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v);
  EXPECT_EQ(v, GL_RGBA);
  uint8_t back[4] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  EXPECT_EQ(back[3], 40);
  const auto cti2d = reinterpret_cast<PFNGLCOMPRESSEDTEXIMAGE2DPROC>(
      OSMesaGetProcAddress("glCompressedTexImage2D"));
  const auto ctsi2d = reinterpret_cast<PFNGLCOMPRESSEDTEXSUBIMAGE2DPROC>(
      OSMesaGetProcAddress("glCompressedTexSubImage2D"));
  const auto gcti = reinterpret_cast<PFNGLGETCOMPRESSEDTEXIMAGEPROC>(
      OSMesaGetProcAddress("glGetCompressedTexImage"));
  ASSERT_TRUE(cti2d && ctsi2d && gcti);
  cti2d(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 4, 4, 0, 8, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  cti2d(GL_TEXTURE_3D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 4, 4, 0, 8, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  ctsi2d(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  gcti(GL_TEXTURE_2D, 0, back);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  gcti(GL_TEXTURE_2D, -1, back);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  gcti(GL_PROXY_TEXTURE_2D, 0, back);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
}

} // namespace
