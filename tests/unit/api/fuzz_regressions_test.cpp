// Regression tests for the bugs the libFuzzer harness (tests/fuzz) found. Each passes client
// arrays of exactly the size the GL may touch for the arguments, so that a sanitizer build
// (scripts/fuzz.sh, the ASan/UBSan CI job) reports any access beyond them.
#include <GL/gl.h>
#include <GL/glext.h>

#include <memory>

#include "api_fixture.h"

namespace {

class FuzzRegressionTest : public GLTest {};

// glTexGen*v read four values for any pname other than TEXTURE_GEN_MODE, so an invalid pname
// read past a one-value array (GL 2.1 §2.11.4: only the planes take four).
TEST_F(FuzzRegressionTest, TexGenVectorInvalidPnameReadsNothingPastOneValue) {
  auto f = std::make_unique<GLfloat[]>(1);
  auto i = std::make_unique<GLint[]>(1);
  auto d = std::make_unique<GLdouble[]>(1);
  f[0] = 1.0f;
  i[0] = 1;
  d[0] = 1.0;
  glTexGenfv(GL_S, GL_TEXTURE_ENV_MODE, f.get());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glTexGeniv(GL_T, GL_TEXTURE_ENV_MODE, i.get());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glTexGendv(GL_R, GL_TEXTURE_ENV_MODE, d.get());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  // The mode still takes one value.
  f[0] = static_cast<GLfloat>(GL_SPHERE_MAP);
  glTexGenfv(GL_S, GL_TEXTURE_GEN_MODE, f.get());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  GLint mode = 0;
  glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &mode);
  EXPECT_EQ(mode, GL_SPHERE_MAP);
}

} // namespace
