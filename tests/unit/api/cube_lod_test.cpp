// The level of detail of cube maps (GL 2.1 §3.8.6, §3.8.8) where a primitive covers only part
// of a 2x2 quad, as piglit's `cubemap npot` draws them: each level of a mipmapped 48x48 cube map
// drawn at its own size must show that level's colour for every face.
#include <GL/gl.h>
#include <GL/glext.h>
#include <gtest/gtest.h>

#include <vector>

#include "api_fixture.h"

namespace {

// A colour per (level, face) that no other (level, face) of the texture has.
uint32_t level_face_colour(int level, int face) {
  return 0xff000000u | static_cast<uint32_t>(40 * level + 10) |
         static_cast<uint32_t>(40 * face + 20) << 8 | 0x80u << 16;
}

// Direction of the face's corners in the order lower left, lower right, upper right, upper left
// of the drawn square (Table 3.21's s and t running along x and y).
void corner_direction(int face, float sx, float ty, float out[3]) {
  switch (face) {
  case 0:
    out[0] = 1, out[1] = -ty, out[2] = -sx;
    break;
  case 1:
    out[0] = -1, out[1] = -ty, out[2] = sx;
    break;
  case 2:
    out[0] = sx, out[1] = 1, out[2] = ty;
    break;
  case 3:
    out[0] = sx, out[1] = -1, out[2] = -ty;
    break;
  case 4:
    out[0] = sx, out[1] = -ty, out[2] = 1;
    break;
  default:
    out[0] = -sx, out[1] = -ty, out[2] = -1;
    break;
  }
}

class CubeLod : public GLTest {};

TEST_F(CubeLod, PartlyCoveredQuadsPickTheDrawnLevel) {
  constexpr int kSize = 12; // levels 12, 6, 3, 1
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
  for (int level = 0, dim = kSize; dim > 0; ++level, dim /= 2)
    for (int face = 0; face < 6; ++face) {
      std::vector<uint32_t> texels(dim * dim, level_face_colour(level, face));
      glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, level, GL_RGBA, dim, dim, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, texels.data());
    }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glEnable(GL_TEXTURE_CUBE_MAP);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kW, 0, kH, -1, 1);
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

  // Level 2 (3x3) at every position of a quad: odd and even x and y.
  const int level = 2, dim = 3;
  for (int face = 0; face < 6; ++face)
    for (int offset = 0; offset < 4; ++offset) {
      const int x0 = 4 + (offset & 1), y0 = 4 + (offset >> 1);
      glClear(GL_COLOR_BUFFER_BIT);
      glBegin(GL_QUADS);
      const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (const auto& c : corners) {
        float d[3];
        corner_direction(face, c[0], c[1], d);
        glTexCoord3fv(d);
        glVertex2f(static_cast<float>(x0) + (c[0] + 1) * 0.5f * dim,
                   static_cast<float>(y0) + (c[1] + 1) * 0.5f * dim);
      }
      glEnd();
      for (int y = y0; y < y0 + dim; ++y)
        for (int x = x0; x < x0 + dim; ++x)
          EXPECT_EQ(pixel(x, y), level_face_colour(level, face))
              << "face " << face << " at (" << x << ", " << y << "), square at (" << x0 << ", "
              << y0 << ")";
    }
  glDeleteTextures(1, &tex);
}

} // namespace
