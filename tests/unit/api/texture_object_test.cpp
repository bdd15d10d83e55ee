// Texture objects through the GL API (GL 2.1 §3.8.1, §3.8.4, §3.8.12, §6.1.3): names, binding,
// parameters, image specification, proxies, level queries and their errors.
#include <GL/glext.h>

#include "api_fixture.h"
#include "core/context.h"
#include "texture/sampler.h"
#include "texture/texture_object.h"

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

} // namespace
