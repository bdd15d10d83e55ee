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

namespace {

// glLightModelf(LIGHT_MODEL_COLOR_CONTROL, 1e30) converted the float to GLenum before checking
// it (undefined behaviour, UBSan float-cast-overflow); now INVALID_ENUM and no change.
TEST_F(FuzzRegressionTest, LightModelColorControlHugeFloatIsInvalidEnum) {
  for (const float v : {1e30f, -1.0f, -1e30f, 0.5f}) {
    glLightModelf(GL_LIGHT_MODEL_COLOR_CONTROL, v);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM)) << v;
  }
  const GLfloat nan_value = __builtin_nanf("");
  glLightModelfv(GL_LIGHT_MODEL_COLOR_CONTROL, &nan_value);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  GLint mode = 0;
  glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL, &mode);
  EXPECT_EQ(mode, GL_SINGLE_COLOR);
  glLightModelf(GL_LIGHT_MODEL_COLOR_CONTROL, static_cast<float>(GL_SEPARATE_SPECULAR_COLOR));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL, &mode);
  EXPECT_EQ(mode, GL_SEPARATE_SPECULAR_COLOR);
}

} // namespace

namespace {

// Compiling a 1D or 2D image command copied the client image as if UNPACK_SKIP_IMAGES and
// UNPACK_IMAGE_HEIGHT applied to it, reading far past the image (GL 2.1 §3.8.1: they apply to
// 3D images only).
TEST_F(FuzzRegressionTest, CompiledSubImageIgnoresSkipImages) {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_1D, tex);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 3);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 7);
  // Exactly the 4 RGBA bytes of a 1 x 1 image (alignment 4).
  auto texel = std::make_unique<GLubyte[]>(4);
  for (int k = 0; k < 4; ++k)
    texel[k] = static_cast<GLubyte>(0x40 * k + 0x10);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexSubImage1D(GL_TEXTURE_1D, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texel.get());
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texel.get());
  glEndList();
  texel.reset();
  glCallList(list);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  GLubyte back[16] = {};
  glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  EXPECT_EQ(back[4], 0x10);
  EXPECT_EQ(back[7], 0xD0);
  glDeleteLists(list, 1);
  glDeleteTextures(1, &tex);
}

// Compiling TexParameterfv, TexGenfv and the other vector commands copied as many values as
// any command takes for the pname (four for TEXTURE_ENV_COLOR even in TexParameterfv, where it
// is invalid), reading past a one-value array.
TEST_F(FuzzRegressionTest, CompiledVectorCommandsReadOnlyTheirOwnCounts) {
  auto one = std::make_unique<GLfloat[]>(1);
  auto one_i = std::make_unique<GLint[]>(1);
  one[0] = 1.0f;
  one_i[0] = 1;
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_ENV_COLOR, one.get());
  glTexParameteriv(GL_TEXTURE_2D, GL_FOG_COLOR, one_i.get());
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_BORDER_COLOR, one.get());
  glTexGenfv(GL_S, GL_FOG_COLOR, one.get());
  glFogfv(GL_TEXTURE_BORDER_COLOR, one.get());
  glPointParameterfv(GL_EYE_PLANE, one.get());
  glEndList();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // Each is an invalid pname for its command: the errors come when the list executes.
  glCallList(list);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glDeleteLists(list, 1);
}

} // namespace

namespace {

// Compiling glPixelMap* with a size beyond MAX_PIXEL_MAP_TABLE copied that many values (up to
// 65536) from a shorter array; the size is an error at execution, so nothing is read.
TEST_F(FuzzRegressionTest, CompiledPixelMapTooLargeReadsNothing) {
  auto one = std::make_unique<GLuint[]>(1);
  one[0] = 7;
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 32768, one.get());
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 257, reinterpret_cast<const GLfloat*>(one.get()));
  glEndList();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glCallList(list);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  GLint size = 0;
  glGetIntegerv(GL_PIXEL_MAP_I_TO_I_SIZE, &size);
  EXPECT_EQ(size, 1);
  glDeleteLists(list, 1);
}

} // namespace

namespace {

// Executing a compiled PixelMap or PrioritizeTextures with no values copied them with memcpy
// to an empty vector's null pointer (UBSan: null passed as nonnull argument).
TEST_F(FuzzRegressionTest, CompiledEmptyValueArraysReplayWithoutNullMemcpy) {
  const GLfloat value = 0.5f;
  const GLuint name = 1;
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, &value);
  glPrioritizeTextures(0, &name, &value);
  glEndList();
  glCallList(list);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glDeleteLists(list, 1);
}

} // namespace

namespace {

// Compiling glLightfv/glMaterialfv/glLightModelfv copied as many values as any of the three
// takes for the pname (three for COLOR_INDEXES even in Lightfv, where it is invalid), reading
// past a one-value array.
TEST_F(FuzzRegressionTest, CompiledLightingVectorsReadOnlyTheirOwnCounts) {
  auto one = std::make_unique<GLfloat[]>(1);
  auto one_i = std::make_unique<GLint[]>(1);
  one[0] = 1.0f;
  one_i[0] = 1;
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glLightfv(GL_LIGHT0, GL_COLOR_INDEXES, one.get());
  glLightiv(GL_LIGHT0, GL_EMISSION, one_i.get());
  glMaterialfv(GL_FRONT, GL_POSITION, one.get());
  glLightModelfv(GL_AMBIENT, one.get());
  glEndList();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glCallList(list);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glDeleteLists(list, 1);
}

} // namespace
