// Pixel buffer objects (GL 2.1 §2.9, §3.6.1, §4.3.2, ARB_pixel_buffer_object): the
// PIXEL_PACK_BUFFER and PIXEL_UNPACK_BUFFER targets and bindings, every pixel command reading
// from or writing to them at an offset, INVALID_OPERATION for accesses past the end, offsets
// not a multiple of the type's size and mapped buffers (with nothing changed), the
// pixel-store attribute group, and display lists that keep the buffer's data of compile time.
#include <cstdint>
#include <cstring>
#include <vector>

#define GL_GLEXT_PROTOTYPES
#include "api_fixture.h"

namespace {

using PixelBuffer = GLTest;

GLint get_int(GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  return v;
}

const void* at(size_t offset) {
  return reinterpret_cast<const void*>(offset);
}
void* out_at(size_t offset) {
  return reinterpret_cast<void*>(offset);
}

// A buffer bound to `target` holding `bytes`.
GLuint make_buffer(GLenum target, const void* bytes, size_t size) {
  GLuint b = 0;
  glGenBuffers(1, &b);
  glBindBuffer(target, b);
  glBufferData(target, static_cast<GLsizeiptr>(size), bytes, GL_STREAM_DRAW);
  return b;
}

std::vector<uint8_t> buffer_bytes(GLenum target, size_t size) {
  std::vector<uint8_t> v(size);
  glGetBufferSubData(target, 0, static_cast<GLsizeiptr>(size), v.data());
  return v;
}

TEST_F(PixelBuffer, BindingsAndQueries) {
  EXPECT_EQ(get_int(GL_PIXEL_PACK_BUFFER_BINDING), 0);
  EXPECT_EQ(get_int(GL_PIXEL_UNPACK_BUFFER_BINDING), 0);
  GLuint b[2];
  glGenBuffers(2, b);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, b[0]);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, b[1]);
  EXPECT_EQ(get_int(GL_PIXEL_PACK_BUFFER_BINDING), static_cast<GLint>(b[0]));
  EXPECT_EQ(get_int(GL_PIXEL_UNPACK_BUFFER_BINDING), static_cast<GLint>(b[1]));
  glBufferData(GL_PIXEL_PACK_BUFFER, 100, nullptr, GL_STREAM_READ);
  GLint size = 0;
  glGetBufferParameteriv(GL_PIXEL_PACK_BUFFER, GL_BUFFER_SIZE, &size);
  EXPECT_EQ(size, 100);
  // The client pixel-store group saves the bindings.
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glPopClientAttrib();
  EXPECT_EQ(get_int(GL_PIXEL_PACK_BUFFER_BINDING), static_cast<GLint>(b[0]));
  EXPECT_EQ(get_int(GL_PIXEL_UNPACK_BUFFER_BINDING), static_cast<GLint>(b[1]));
  // Deleting a bound buffer binds zero (§2.9).
  glDeleteBuffers(2, b);
  EXPECT_EQ(get_int(GL_PIXEL_PACK_BUFFER_BINDING), 0);
  EXPECT_EQ(get_int(GL_PIXEL_UNPACK_BUFFER_BINDING), 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// ReadPixels into a pack buffer at an offset, then DrawPixels back from it as unpack buffer.
TEST_F(PixelBuffer, ReadPixelsAndDrawPixelsRoundTrip) {
  glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glScissor(0, 0, 4, 4);
  glEnable(GL_SCISSOR_TEST);
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  const GLuint pack = make_buffer(GL_PIXEL_PACK_BUFFER, nullptr, 16 + 8 * 8 * 4);
  glReadPixels(0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, out_at(16));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const std::vector<uint8_t> bytes = buffer_bytes(GL_PIXEL_PACK_BUFFER, 16 + 8 * 8 * 4);
  EXPECT_EQ(bytes[16 + 0], 0); // (0, 0) blue
  EXPECT_EQ(bytes[16 + 2], 255);
  EXPECT_EQ(bytes[16 + (7 * 8 + 7) * 4], 255); // (7, 7) red
  EXPECT_EQ(bytes[0], 0);                      // before the offset: untouched

  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pack);
  glWindowPos2i(16, 16);
  glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, at(16));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(pixel(16, 16), 0xffff0000u);
  EXPECT_EQ(pixel(23, 23), 0xff0000ffu);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glDeleteBuffers(1, &pack);
}

TEST_F(PixelBuffer, AccessErrorsChangeNothing) {
  std::vector<uint8_t> data(64, 0x80);
  const GLuint b = make_buffer(GL_PIXEL_UNPACK_BUFFER, data.data(), data.size());
  glWindowPos2i(0, 0);
  // 4x4 RGBA bytes = 64: fits at offset 0, not at 4.
  glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, at(4));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(pixel(0, 0), 0u);
  // An offset that is not a multiple of the type's size (2 is one for UNSIGNED_SHORT).
  glWindowPos2i(20, 20);
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_SHORT, at(2));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_NE(pixel(20, 20), 0u);
  glWindowPos2i(0, 0);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_SHORT, at(1));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glDrawPixels(1, 1, GL_RGBA, GL_FLOAT, at(6));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  // Texture images.
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  GLint w = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(w, 0); // nothing specified
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, at(1));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, at(0));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  // Bitmap and polygon stipple (32 rows of 4 bytes = 128 > 64).
  glBitmap(8, 80, 0, 0, 3, 0, static_cast<const GLubyte*>(at(0)));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  GLfloat rp[4];
  glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
  EXPECT_EQ(rp[0], 0.0f); // not moved
  glPolygonStipple(static_cast<const GLubyte*>(at(0)));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  // Pixel maps: 16 floats = 64 bytes fit, 17 do not.
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 16, static_cast<const GLfloat*>(at(0)));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(get_int(GL_PIXEL_MAP_R_TO_R_SIZE), 16);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 32, static_cast<const GLfloat*>(at(0)));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_PIXEL_MAP_G_TO_G_SIZE), 1);
  // A mapped buffer cannot be read from (§2.9).
  ASSERT_NE(glMapBuffer(GL_PIXEL_UNPACK_BUFFER, GL_WRITE_ONLY), nullptr);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, at(0));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(pixel(0, 0), 0u);
  glUnmapBuffer(GL_PIXEL_UNPACK_BUFFER);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);

  // Pack: ReadPixels past the end, misaligned, into a mapped buffer; GetTexImage;
  // GetPolygonStipple; GetPixelMap.
  glBindBuffer(GL_PIXEL_PACK_BUFFER, b);
  glReadPixels(0, 0, 5, 5, GL_RGBA, GL_UNSIGNED_BYTE, out_at(0));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, out_at(2));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out_at(0));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)); // 4x4 RGBA: 64 bytes
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out_at(0));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glGetPolygonStipple(static_cast<GLubyte*>(out_at(0)));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, static_cast<GLfloat*>(out_at(0)));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, static_cast<GLfloat*>(out_at(4)));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  ASSERT_NE(glMapBuffer(GL_PIXEL_PACK_BUFFER, GL_READ_ONLY), nullptr);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, out_at(0));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glDeleteBuffers(1, &b);
  glDeleteTextures(1, &tex);
}

// Every unpack command reads from the buffer at the offset, every pack command writes there.
TEST_F(PixelBuffer, TextureStippleBitmapAndMapsThroughBuffers) {
  // 4x4 RGBA texels after 8 bytes of padding.
  std::vector<uint8_t> data(8 + 64);
  for (int i = 0; i < 16; ++i) {
    data[8 + i * 4 + 0] = static_cast<uint8_t>(i * 16);
    data[8 + i * 4 + 1] = static_cast<uint8_t>(255 - i * 16);
    data[8 + i * 4 + 2] = 7;
    data[8 + i * 4 + 3] = 255;
  }
  const GLuint unpack = make_buffer(GL_PIXEL_UNPACK_BUFFER, data.data(), data.size());
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, at(8));
  // TexSubImage2D of texel (1,1) from texel 15's bytes.
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, at(8 + 15 * 4));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  std::vector<uint8_t> got(64);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, got.data());
  EXPECT_EQ(got[0], 0);
  EXPECT_EQ(got[1], 255);
  EXPECT_EQ(got[5 * 4], 240); // (1,1) replaced by texel 15
  EXPECT_EQ(got[6 * 4], 96);
  // GetTexImage into a pack buffer.
  const GLuint pack = make_buffer(GL_PIXEL_PACK_BUFFER, nullptr, 4 + 64);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out_at(4));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const std::vector<uint8_t> packed = buffer_bytes(GL_PIXEL_PACK_BUFFER, 68);
  EXPECT_EQ(0, std::memcmp(packed.data() + 4, got.data(), 64));

  // Polygon stipple in and out.
  std::vector<uint8_t> stipple(128);
  for (int i = 0; i < 128; ++i)
    stipple[i] = static_cast<uint8_t>(i * 37 + 1);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, unpack);
  glBufferData(GL_PIXEL_UNPACK_BUFFER, 128, stipple.data(), GL_STATIC_DRAW);
  glPolygonStipple(nullptr); // offset 0 of the buffer
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glBufferData(GL_PIXEL_PACK_BUFFER, 128, nullptr, GL_STREAM_READ);
  glGetPolygonStipple(nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(buffer_bytes(GL_PIXEL_PACK_BUFFER, 128), stipple);

  // Pixel maps in and out.
  const GLushort map[4] = {0, 21845, 43690, 65535};
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, unpack);
  glBufferData(GL_PIXEL_UNPACK_BUFFER, sizeof map, map, GL_STATIC_DRAW);
  glPixelMapusv(GL_PIXEL_MAP_I_TO_R, 4, nullptr);
  EXPECT_EQ(get_int(GL_PIXEL_MAP_I_TO_R_SIZE), 4);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glGetPixelMapusv(GL_PIXEL_MAP_I_TO_R, nullptr);
  const std::vector<uint8_t> map_out = buffer_bytes(GL_PIXEL_PACK_BUFFER, sizeof map);
  EXPECT_EQ(0, std::memcmp(map_out.data(), map, sizeof map));
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);

  // Bitmap from a buffer: one byte per row.
  const uint8_t bits[4] = {0xf0, 0xf0, 0x0f, 0x0f};
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, unpack);
  glBufferData(GL_PIXEL_UNPACK_BUFFER, 4, bits, GL_STATIC_DRAW);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glColor3f(0, 1, 0);
  glWindowPos2i(0, 0);
  glBitmap(8, 4, 0, 0, 0, 0, nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(pixel(0, 0), 0xff00ff00u);
  EXPECT_EQ(pixel(7, 0), 0u);
  EXPECT_EQ(pixel(7, 3), 0xff00ff00u);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glDeleteBuffers(1, &unpack);
  glDeleteBuffers(1, &pack);
  glDeleteTextures(1, &tex);
}

// GL 2.1 §5.4 with ARB_pixel_buffer_object: a compiled DrawPixels keeps the buffer's bytes of
// compile time; the buffer may change or go away afterwards.
TEST_F(PixelBuffer, DisplayListsKeepTheBuffersData) {
  uint8_t px[4] = {0, 0, 255, 255};
  const GLuint b = make_buffer(GL_PIXEL_UNPACK_BUFFER, px, 4);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glWindowPos2i(3, 3);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, at(4)); // past the end: an error at execution
  glEndList();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(pixel(3, 3), 0u);
  px[0] = 255;
  glBufferSubData(GL_PIXEL_UNPACK_BUFFER, 0, 4, px);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glDeleteBuffers(1, &b);
  glCallList(list);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(pixel(3, 3), 0xffff0000u);
  glDeleteLists(list, 1);
}

} // namespace
