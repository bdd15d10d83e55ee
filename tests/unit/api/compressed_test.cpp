// Compressed textures with no specific compressed format (GL 2.1 §3.8.1, §3.8.3, §6.1.4):
// every CompressedTexImage is INVALID_ENUM, CompressedTexSubImage and GetCompressedTexImage
// fail as the spec says for uncompressed images, and the generic compressed internal formats
// are stored uncompressed as their base formats.
#include "api_fixture.h"

#include <GL/glext.h>

#include <array>
#include <cstdint>

namespace {

using Compressed = GLTest;

GLenum err() {
  return glGetError();
}

GLint level_param(GLenum target, GLenum pname) {
  GLint v = -1;
  glGetTexLevelParameteriv(target, 0, pname, &v);
  return v;
}

constexpr GLenum kGeneric[] = {
    GL_COMPRESSED_ALPHA,     GL_COMPRESSED_LUMINANCE, GL_COMPRESSED_LUMINANCE_ALPHA,
    GL_COMPRESSED_INTENSITY, GL_COMPRESSED_RGB,       GL_COMPRESSED_RGBA};

TEST_F(Compressed, NoSpecificFormats) {
  GLint n = -1;
  glGetIntegerv(GL_NUM_COMPRESSED_TEXTURE_FORMATS, &n);
  EXPECT_EQ(n, 0);
  GLint formats[4] = {-7, -7, -7, -7};
  glGetIntegerv(GL_COMPRESSED_TEXTURE_FORMATS, formats); // writes nothing
  EXPECT_EQ(formats[0], -7);
  GLint hint = 0;
  glGetIntegerv(GL_TEXTURE_COMPRESSION_HINT, &hint);
  EXPECT_EQ(hint, GL_DONT_CARE);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
}

// §3.8.3: internalformat must be a specific compressed format; generic ones, uncompressed
// ones and S3TC (not supported) are all INVALID_ENUM, as is a bad target. Nothing changes.
TEST_F(Compressed, CompressedTexImageIsInvalidEnum) {
  std::array<uint8_t, 256> data{};
  for (GLenum f : {GLenum(GL_COMPRESSED_RGB), GLenum(GL_COMPRESSED_RGBA), GLenum(GL_RGB),
                   GLenum(GL_RGBA8), GLenum(GL_COMPRESSED_RGB_S3TC_DXT1_EXT), GLenum(0)}) {
    glCompressedTexImage1D(GL_TEXTURE_1D, 0, f, 4, 0, 8, data.data());
    EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, f, 4, 4, 0, 8, data.data());
    EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
    glCompressedTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, f, 4, 4, 0, 8, data.data());
    EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
    glCompressedTexImage3D(GL_TEXTURE_3D, 0, f, 4, 4, 4, 0, 8, data.data());
    EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  }
  // Bad arguments of other kinds are still INVALID_ENUM (the format error).
  glCompressedTexImage2D(GL_TEXTURE_2D, -1, GL_COMPRESSED_RGB, -4, 4, 7, -1, nullptr);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glCompressedTexImage2D(GL_TEXTURE_3D, 0, GL_COMPRESSED_RGB, 4, 4, 0, 8, data.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glCompressedTexImage1D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 4, 0, 8, data.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 4, 4, 0, 8, data.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(level_param(GL_TEXTURE_2D, GL_TEXTURE_WIDTH), 0);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, GL_TEXTURE_WIDTH), 0);
}

// §3.8.3: format must be a supported specific compressed format and there are none, so every
// call is INVALID_ENUM (Mesa checks the format before the level, region and image), whatever
// the texture holds; a bad target is INVALID_ENUM as well.
TEST_F(Compressed, CompressedTexSubImageErrors) {
  std::array<uint8_t, 256> data{};
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGB, 16, data.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, data.data());
  ASSERT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
  for (GLenum f : {GLenum(GL_RGB), GLenum(GL_COMPRESSED_RGB_S3TC_DXT1_EXT)}) {
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, f, 16, data.data());
    EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  }
  for (GLenum f : kGeneric) {
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, f, 16, data.data());
    EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  }
  glCompressedTexSubImage2D(GL_TEXTURE_3D, 0, 0, 0, 4, 4, GL_RGB, 16, data.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glCompressedTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGB, 16, data.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glCompressedTexSubImage2D(GL_TEXTURE_2D, -1, 0, 0, 4, 4, GL_RGB, -1, data.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glCompressedTexSubImage1D(GL_TEXTURE_1D, 0, 0, 4, GL_RGB, 16, data.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glCompressedTexSubImage1D(GL_TEXTURE_2D, 0, 0, 4, GL_RGBA, 16, data.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glCompressedTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 2, 2, 2, GL_RGB, 16, data.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
}

// §6.1.4: bad target INVALID_ENUM (no proxies, no CUBE_MAP), bad level INVALID_VALUE, an
// uncompressed image INVALID_OPERATION; img is never written.
TEST_F(Compressed, GetCompressedTexImageErrors) {
  std::array<uint8_t, 64> data{};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, data.data());
  std::array<uint8_t, 64> out;
  out.fill(0xcd);
  glGetCompressedTexImage(GL_TEXTURE_2D, 0, out.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(out[0], 0xcd);
  glGetCompressedTexImage(GL_TEXTURE_2D, -1, out.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  glGetCompressedTexImage(GL_TEXTURE_2D, 1000, out.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  glGetCompressedTexImage(GL_TEXTURE_2D, 3, out.data()); // no such image (as Mesa)
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  for (GLenum t : {GL_PROXY_TEXTURE_2D, GL_TEXTURE_CUBE_MAP, GL_PROXY_TEXTURE_CUBE_MAP,
                   GL_PROXY_TEXTURE_1D, GL_PROXY_TEXTURE_3D, GL_RGBA}) {
    glGetCompressedTexImage(t, 0, out.data());
    EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  }
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_COMPRESSED_RGBA, 2, 2, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, data.data());
  glGetCompressedTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, out.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glTexImage1D(GL_TEXTURE_1D, 0, GL_COMPRESSED_LUMINANCE, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               data.data());
  glGetCompressedTexImage(GL_TEXTURE_1D, 0, out.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glGetCompressedTexImage(GL_TEXTURE_3D, 0, nullptr);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(out[0], 0xcd);
}

// §3.8.1: "If no specific compressed format is available, internalformat is instead replaced
// by the corresponding base internal format": stored uncompressed, read back as such.
TEST_F(Compressed, GenericFormatsAreStoredUncompressed) {
  const GLenum base[] = {GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_INTENSITY, GL_RGB, GL_RGBA};
  const uint8_t texel[4] = {10, 20, 30, 40};
  // Table 6.1: luminance and intensity read back in red.
  const uint8_t expect[6][4] = {{0, 0, 0, 40},   {10, 0, 0, 255},   {10, 0, 0, 40},
                                {10, 0, 0, 255}, {10, 20, 30, 255}, {10, 20, 30, 40}};
  for (int k = 0; k < 6; ++k) {
    glTexImage2D(GL_TEXTURE_2D, 0, kGeneric[k], 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    ASSERT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR)) << k;
    EXPECT_EQ(level_param(GL_TEXTURE_2D, GL_TEXTURE_INTERNAL_FORMAT), static_cast<GLint>(base[k]));
    EXPECT_EQ(level_param(GL_TEXTURE_2D, GL_TEXTURE_COMPRESSED), GL_FALSE);
    GLint size = -1;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
    EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
    uint8_t back[4] = {};
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    for (int c = 0; c < 4; ++c)
      EXPECT_EQ(back[c], expect[k][c]) << k << " " << c;
  }
  // Proxies, CopyTexImage and 1D/3D images take them too.
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_COMPRESSED_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, GL_TEXTURE_INTERNAL_FORMAT), GL_RGBA);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_LUMINANCE, 0, 0, 4, 4, 0);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(level_param(GL_TEXTURE_2D, GL_TEXTURE_INTERNAL_FORMAT), GL_LUMINANCE);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_COMPRESSED_INTENSITY, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               texel);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(level_param(GL_TEXTURE_3D, GL_TEXTURE_INTERNAL_FORMAT), GL_INTENSITY);
}

// A texture with a generic compressed format draws like its base format.
TEST_F(Compressed, GenericFormatDraws) {
  const uint8_t texel[4] = {255, 0, 0, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  glTexCoord2f(0.5f, 0.5f);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 1);
  glVertex2f(-1, 1);
  glEnd();
  glFinish();
  EXPECT_EQ(pixel(5, 5), 0xff0000ffu);
}

TEST_F(Compressed, IllegalBetweenBeginEnd) {
  std::array<uint8_t, 64> data{};
  glBegin(GL_POINTS);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 4, 4, 0, 8, data.data());
  glEnd();
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGB, 16, data.data());
  glEnd();
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);
  glGetCompressedTexImage(GL_TEXTURE_2D, 0, data.data());
  glEnd();
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);
  glCompressedTexImage1D(GL_TEXTURE_1D, 0, GL_COMPRESSED_RGB, 4, 0, 8, data.data());
  glCompressedTexImage3D(GL_TEXTURE_3D, 0, GL_COMPRESSED_RGB, 4, 4, 4, 0, 8, data.data());
  glCompressedTexSubImage1D(GL_TEXTURE_1D, 0, 0, 4, GL_RGB, 16, data.data());
  glCompressedTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 2, 2, 2, GL_RGB, 16, data.data());
  glEnd();
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_OPERATION));
}

// §5.4: compiled calls generate their errors when the list executes, against the state of
// that time; proxy targets execute at once.
TEST_F(Compressed, DisplayLists) {
  std::array<uint8_t, 64> data{};
  const GLuint list = glGenLists(2);
  glNewList(list, GL_COMPILE);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 4, 4, 0, 8, data.data());
  glEndList();
  EXPECT_EQ(err(), static_cast<GLenum>(GL_NO_ERROR));
  glCallList(list);
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));

  glNewList(list + 1, GL_COMPILE);
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, 16, data.data());
  glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 4, 4, 0, 8, data.data());
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM)); // the proxy one, at once
  glEndList();
  glCallList(list + 1); // the recorded sub-image call's error, at execution
  EXPECT_EQ(err(), static_cast<GLenum>(GL_INVALID_ENUM));
  glDeleteLists(list, 2);
}

} // namespace
