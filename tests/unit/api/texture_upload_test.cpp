// glTexImage2D/glTexSubImage2D of RGBA unsigned bytes into RGBA8 textures (GL 2.1 §3.8.1), which
// tex_image.cpp copies row by row when no pixel transfer operation is on: the texels must be
// those of the general path (conversion to float, Table 2.9, and back), with the unpack state
// (§3.6.4 row length, skips, alignment) honoured, and pixel transfer still applied when on.
#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "api_fixture.h"

namespace {

class TextureUpload : public GLTest {
protected:
  std::vector<uint8_t> read_back(int w, int h) {
    std::vector<uint8_t> out(static_cast<size_t>(w * h * 4), 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    return out;
  }
};

TEST_F(TextureUpload, BytesArriveUnchanged) {
  std::vector<uint8_t> src(5 * 3 * 4);
  for (size_t i = 0; i < src.size(); ++i)
    src[i] = static_cast<uint8_t>(i * 37 + 11);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 5, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, src.data());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(read_back(5, 3), src);
}

TEST_F(TextureUpload, EveryByteValueSurvives) {
  // All 256 values in every channel: the copy must equal round(c / 255 * 255).
  std::vector<uint8_t> src(16 * 16 * 4);
  for (int i = 0; i < 256; ++i)
    for (int c = 0; c < 4; ++c)
      src[static_cast<size_t>(i * 4 + c)] = static_cast<uint8_t>((i + 64 * c) & 255);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, src.data());
  EXPECT_EQ(read_back(16, 16), src);
}

TEST_F(TextureUpload, UnpackRowLengthSkipsAndAlignment) {
  // A 3x2 region out of a 7-texel-wide client image, skipping 2 rows and 1 texel; with
  // alignment 8 a row of 28 bytes occupies 32 (§3.6.4 eq. 3.13).
  std::vector<uint8_t> client(32 * 4);
  for (size_t i = 0; i < client.size(); ++i)
    client[i] = static_cast<uint8_t>(i);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 7);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, client.data());
  std::vector<uint8_t> expected;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      for (int c = 0; c < 4; ++c)
        expected.push_back(client[static_cast<size_t>((2 + y) * 32 + (1 + x) * 4 + c)]);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  EXPECT_EQ(read_back(3, 2), expected);
}

TEST_F(TextureUpload, SubImageIntoTheMiddle) {
  std::vector<uint8_t> zero(4 * 4 * 4, 0), patch(2 * 2 * 4);
  for (size_t i = 0; i < patch.size(); ++i)
    patch[i] = static_cast<uint8_t>(200 + i);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, zero.data());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 2, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, patch.data());
  const std::vector<uint8_t> got = read_back(4, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int c = 0; c < 4; ++c) {
        const bool inside = x >= 1 && x < 3 && y >= 2;
        const uint8_t want =
            inside ? patch[static_cast<size_t>(((y - 2) * 2 + (x - 1)) * 4 + c)] : uint8_t{0};
        EXPECT_EQ(got[static_cast<size_t>((y * 4 + x) * 4 + c)], want) << x << "," << y;
      }
}

TEST_F(TextureUpload, PixelTransferStillApplies) {
  // §3.8.1: the pixel transfer operations of DrawPixels apply; RED_SCALE 0.5 halves red.
  const uint8_t src[4] = {200, 100, 50, 255};
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  const std::vector<uint8_t> got = read_back(1, 1);
  EXPECT_EQ(got[0], 100);
  EXPECT_EQ(got[1], 100);
  EXPECT_EQ(got[2], 50);
  EXPECT_EQ(got[3], 255);
}

TEST_F(TextureUpload, LowerPrecisionFormatsStillQuantize) {
  // RGBA4 keeps 4 bits: 0x7f -> round(127 / 255 * 15) = 7 -> 7 * 17 = 119.
  const uint8_t src[4] = {0x7f, 0xff, 0x00, 0x80};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA4, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
  const std::vector<uint8_t> got = read_back(1, 1);
  EXPECT_EQ(got[0], 119);
  EXPECT_EQ(got[1], 255);
  EXPECT_EQ(got[2], 0);
  EXPECT_EQ(got[3], 136);
}

} // namespace
