// Harness operations on the pixel paths (GL 2.1 §3.6, §3.7, §4.3) and texture images (§3.8.1
// to §3.8.3, §6.1.4): every client image is an exact-size block whose extent the harness
// computes from the pixel-store state it reads back (§3.6.4 and, for 3D images, §3.8.1).
#include <cstdio>

#include "fuzz_harness.h"

namespace pineda::fuzz {
namespace {

constexpr GLenum kPixelFormats[] = {GL_RGBA,
                                    GL_RGB,
                                    GL_BGRA,
                                    GL_BGR,
                                    GL_RED,
                                    GL_GREEN,
                                    GL_BLUE,
                                    GL_ALPHA,
                                    GL_LUMINANCE,
                                    GL_LUMINANCE_ALPHA,
                                    GL_DEPTH_COMPONENT,
                                    GL_STENCIL_INDEX,
                                    GL_COLOR_INDEX,
                                    0x8000 /* ABGR_EXT */,
                                    0};

constexpr GLenum kPixelTypes[] = {GL_UNSIGNED_BYTE,
                                  GL_BYTE,
                                  GL_UNSIGNED_SHORT,
                                  GL_SHORT,
                                  GL_UNSIGNED_INT,
                                  GL_INT,
                                  GL_FLOAT,
                                  GL_BITMAP,
                                  GL_UNSIGNED_BYTE_3_3_2,
                                  GL_UNSIGNED_BYTE_2_3_3_REV,
                                  GL_UNSIGNED_SHORT_5_6_5,
                                  GL_UNSIGNED_SHORT_5_6_5_REV,
                                  GL_UNSIGNED_SHORT_4_4_4_4,
                                  GL_UNSIGNED_SHORT_4_4_4_4_REV,
                                  GL_UNSIGNED_SHORT_5_5_5_1,
                                  GL_UNSIGNED_SHORT_1_5_5_5_REV,
                                  GL_UNSIGNED_INT_8_8_8_8,
                                  GL_UNSIGNED_INT_8_8_8_8_REV,
                                  GL_UNSIGNED_INT_10_10_10_2,
                                  GL_UNSIGNED_INT_2_10_10_10_REV,
                                  GL_DOUBLE,
                                  0};

constexpr GLenum kTexTargets[] = {GL_TEXTURE_1D,
                                  GL_TEXTURE_2D,
                                  GL_TEXTURE_3D,
                                  GL_TEXTURE_CUBE_MAP,
                                  GL_TEXTURE_CUBE_MAP_POSITIVE_X,
                                  GL_TEXTURE_CUBE_MAP_NEGATIVE_X,
                                  GL_TEXTURE_CUBE_MAP_POSITIVE_Y,
                                  GL_TEXTURE_CUBE_MAP_NEGATIVE_Y,
                                  GL_TEXTURE_CUBE_MAP_POSITIVE_Z,
                                  GL_TEXTURE_CUBE_MAP_NEGATIVE_Z,
                                  GL_PROXY_TEXTURE_1D,
                                  GL_PROXY_TEXTURE_2D,
                                  GL_PROXY_TEXTURE_3D,
                                  GL_PROXY_TEXTURE_CUBE_MAP,
                                  0x84F5 /* TEXTURE_RECTANGLE */,
                                  0};

constexpr GLenum kInternalFormats[] = {1,
                                       2,
                                       3,
                                       4,
                                       GL_ALPHA,
                                       GL_ALPHA4,
                                       GL_ALPHA8,
                                       GL_ALPHA12,
                                       GL_ALPHA16,
                                       GL_LUMINANCE,
                                       GL_LUMINANCE4,
                                       GL_LUMINANCE8,
                                       GL_LUMINANCE16,
                                       GL_LUMINANCE_ALPHA,
                                       GL_LUMINANCE4_ALPHA4,
                                       GL_LUMINANCE6_ALPHA2,
                                       GL_LUMINANCE12_ALPHA12,
                                       GL_INTENSITY,
                                       GL_INTENSITY4,
                                       GL_INTENSITY16,
                                       GL_RGB,
                                       GL_R3_G3_B2,
                                       GL_RGB4,
                                       GL_RGB5,
                                       GL_RGB8,
                                       GL_RGB10,
                                       GL_RGB16,
                                       GL_RGBA,
                                       GL_RGBA2,
                                       GL_RGBA4,
                                       GL_RGB5_A1,
                                       GL_RGBA8,
                                       GL_RGB10_A2,
                                       GL_RGBA16,
                                       GL_DEPTH_COMPONENT,
                                       GL_DEPTH_COMPONENT16,
                                       GL_DEPTH_COMPONENT24,
                                       GL_DEPTH_COMPONENT32,
                                       GL_COMPRESSED_RGB,
                                       GL_COMPRESSED_RGBA,
                                       GL_COMPRESSED_ALPHA,
                                       GL_COMPRESSED_INTENSITY,
                                       GL_COMPRESSED_LUMINANCE,
                                       GL_COMPRESSED_LUMINANCE_ALPHA,
                                       GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
                                       GL_STENCIL_INDEX,
                                       GL_COLOR_INDEX,
                                       GL_BGRA,
                                       GL_SLUMINANCE,
                                       0,
                                       5};

constexpr GLenum kPixelMaps[] = {GL_PIXEL_MAP_I_TO_I, GL_PIXEL_MAP_S_TO_S,      GL_PIXEL_MAP_I_TO_R,
                                 GL_PIXEL_MAP_I_TO_G, GL_PIXEL_MAP_I_TO_B,      GL_PIXEL_MAP_I_TO_A,
                                 GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_G_TO_G,      GL_PIXEL_MAP_B_TO_B,
                                 GL_PIXEL_MAP_A_TO_A, GL_PIXEL_MAP_I_TO_I_SIZE, 0};

constexpr GLenum kTransferParams[] = {GL_MAP_COLOR,
                                      GL_MAP_STENCIL,
                                      GL_INDEX_SHIFT,
                                      GL_INDEX_OFFSET,
                                      GL_RED_SCALE,
                                      GL_GREEN_SCALE,
                                      GL_BLUE_SCALE,
                                      GL_ALPHA_SCALE,
                                      GL_DEPTH_SCALE,
                                      GL_RED_BIAS,
                                      GL_GREEN_BIAS,
                                      GL_BLUE_BIAS,
                                      GL_ALPHA_BIAS,
                                      GL_DEPTH_BIAS,
                                      GL_POST_COLOR_MATRIX_RED_SCALE,
                                      0};

constexpr GLenum kStoreParams[] = {GL_UNPACK_ALIGNMENT,
                                   GL_UNPACK_ROW_LENGTH,
                                   GL_UNPACK_SKIP_ROWS,
                                   GL_UNPACK_SKIP_PIXELS,
                                   GL_UNPACK_SKIP_IMAGES,
                                   GL_UNPACK_IMAGE_HEIGHT,
                                   GL_UNPACK_SWAP_BYTES,
                                   GL_UNPACK_LSB_FIRST,
                                   GL_PACK_ALIGNMENT,
                                   GL_PACK_ROW_LENGTH,
                                   GL_PACK_SKIP_ROWS,
                                   GL_PACK_SKIP_PIXELS,
                                   GL_PACK_SKIP_IMAGES,
                                   GL_PACK_IMAGE_HEIGHT,
                                   GL_PACK_SWAP_BYTES,
                                   GL_PACK_LSB_FIRST,
                                   0};

constexpr GLenum kCopyTypes[] = {GL_COLOR, GL_DEPTH, GL_STENCIL, GL_RGBA, 0};

} // namespace

Store read_store(bool pack) {
  Store s;
  s.row_length = get_int(pack ? GL_PACK_ROW_LENGTH : GL_UNPACK_ROW_LENGTH);
  s.skip_rows = get_int(pack ? GL_PACK_SKIP_ROWS : GL_UNPACK_SKIP_ROWS);
  s.skip_pixels = get_int(pack ? GL_PACK_SKIP_PIXELS : GL_UNPACK_SKIP_PIXELS);
  s.alignment = get_int(pack ? GL_PACK_ALIGNMENT : GL_UNPACK_ALIGNMENT);
  s.image_height = get_int(pack ? GL_PACK_IMAGE_HEIGHT : GL_UNPACK_IMAGE_HEIGHT);
  s.skip_images = get_int(pack ? GL_PACK_SKIP_IMAGES : GL_UNPACK_SKIP_IMAGES);
  return s;
}

namespace {

// The store a call uses: read back from the GL, or inside Begin/End (where queries fail, but a
// list compiled with COMPILE_AND_EXECUTE still takes image commands) the one taken before the
// primitive began; PixelStore cannot change until End.
Store store_of(const Harness& h, bool pack) {
  if (inside_begin()) return h.begin_store[pack ? 1 : 0];
  return read_store(pack);
}

// Bytes from the client pointer to the last byte of a w x h x d image (GL 2.1 §3.6.4 eq.
// 3.12-3.14; §3.8.1 adds IMAGE_HEIGHT and SKIP_IMAGES for 3D images, `three_d`). 0 when no
// byte may be touched (an empty size, an unknown format or type: the call fails); INT64_MAX
// when the image is beyond anything the harness hands out.
int64_t image_bytes(int64_t w, int64_t h, int64_t d, GLenum format, GLenum type, const Store& st,
                    bool three_d) {
  if (w <= 0 || h <= 0 || d <= 0) return 0;
  int64_t n;
  switch (format) {
  case GL_RED:
  case GL_GREEN:
  case GL_BLUE:
  case GL_ALPHA:
  case GL_LUMINANCE:
  case GL_DEPTH_COMPONENT:
  case GL_STENCIL_INDEX:
  case GL_COLOR_INDEX:
    n = 1;
    break;
  case GL_LUMINANCE_ALPHA:
    n = 2;
    break;
  case GL_RGB:
  case GL_BGR:
    n = 3;
    break;
  case GL_RGBA:
  case GL_BGRA:
    n = 4;
    break;
  default:
    return 0;
  }
  int64_t s = 0;
  switch (type) {
  case GL_UNSIGNED_BYTE:
  case GL_BYTE:
    s = 1;
    break;
  case GL_UNSIGNED_SHORT:
  case GL_SHORT:
    s = 2;
    break;
  case GL_UNSIGNED_INT:
  case GL_INT:
  case GL_FLOAT:
    s = 4;
    break;
  // Packed types: one element per group (Table 3.8).
  case GL_UNSIGNED_BYTE_3_3_2:
  case GL_UNSIGNED_BYTE_2_3_3_REV:
    s = 1, n = 1;
    break;
  case GL_UNSIGNED_SHORT_5_6_5:
  case GL_UNSIGNED_SHORT_5_6_5_REV:
  case GL_UNSIGNED_SHORT_4_4_4_4:
  case GL_UNSIGNED_SHORT_4_4_4_4_REV:
  case GL_UNSIGNED_SHORT_5_5_5_1:
  case GL_UNSIGNED_SHORT_1_5_5_5_REV:
    s = 2, n = 1;
    break;
  case GL_UNSIGNED_INT_8_8_8_8:
  case GL_UNSIGNED_INT_8_8_8_8_REV:
  case GL_UNSIGNED_INT_10_10_10_2:
  case GL_UNSIGNED_INT_2_10_10_10_REV:
    s = 4, n = 1;
    break;
  case GL_BITMAP:
    break;
  default:
    return 0;
  }
  constexpr int64_t kHuge = int64_t{1} << 24;
  if (w > kHuge || h > kHuge || d > kHuge || st.row_length > kHuge || st.skip_rows > kHuge ||
      st.skip_pixels > kHuge || st.image_height > kHuge || st.skip_images > kHuge)
    return INT64_MAX;
  const int64_t a = st.alignment;
  if (a <= 0) return 0;
  const int64_t l = st.row_length > 0 ? st.row_length : w;
  // Row stride in bytes: for BITMAP (one bit per element) k = a * ceil(n l / 8a) (§3.6.4);
  // otherwise k elements of s bytes, k = n l when s >= a, else a/s * ceil(s n l / a) (eq.
  // 3.13). Images of a 3D image follow every IMAGE_HEIGHT (or h) rows (§3.8.1).
  const bool bitmap = type == GL_BITMAP;
  const int64_t row = bitmap ? a * ((n * l + 8 * a - 1) / (8 * a))
                             : (s >= a ? n * l : (a / s) * ((s * n * l + a - 1) / a)) * s;
  int64_t images = 0;
  if (three_d) {
    const int64_t rows_per_image = st.image_height > 0 ? st.image_height : h;
    images = (st.skip_images + d - 1) * rows_per_image * row;
  }
  // The last row: SKIP_PIXELS skips bits of each row for BITMAP.
  if (bitmap) return images + (st.skip_rows + h - 1) * row + (st.skip_pixels * n + w * n + 7) / 8;
  return images + (st.skip_rows + h - 1) * row + (st.skip_pixels + w) * n * s;
}

// An image size: small values most of the time, and any value outside what the GL could
// allocate (negative, or beyond every MAX_*_SIZE); valid sizes between are folded down so
// that executions stay fast.
int32_t dim(Input& in, int32_t max_small) {
  const int32_t v = in.i();
  if (v > max_small + 2 && v <= (1 << 24)) return v % (max_small + 3);
  return v;
}

} // namespace

void op_read_pixels(Harness& h, Input& in) {
  const GLint x = in.i(), y = in.i();
  const GLsizei w = dim(in, kMaxSurface + 8), hgt = dim(in, kMaxSurface + 8);
  const GLenum format = in.e(kPixelFormats), type = in.e(kPixelTypes);
  const int64_t need = image_bytes(w, hgt, 1, format, type, store_of(h, true), false);
  if (need > kMaxImageBytes) return;
  Block dst(h, need);
  glReadPixels(x, y, w, hgt, format, type, dst.get());
}

namespace {

void op_draw_pixels(Harness& h, Input& in) {
  const GLsizei w = dim(in, kMaxSurface), hgt = dim(in, kMaxSurface);
  const GLenum format = in.e(kPixelFormats), type = in.e(kPixelTypes);
  const uint16_t off = in.u16();
  const int64_t need = image_bytes(w, hgt, 1, format, type, store_of(h, false), false);
  if (need > kMaxImageBytes) return;
  Block src(h, need, off);
  glDrawPixels(w, hgt, format, type, src.get());
}

void op_bitmap(Harness& h, Input& in) {
  const GLsizei w = dim(in, kMaxSurface), hgt = dim(in, kMaxSurface);
  const GLfloat xo = in.f(), yo = in.f(), xm = in.f(), ym = in.f();
  const uint16_t off = in.u16();
  const int64_t need = image_bytes(w, hgt, 1, GL_COLOR_INDEX, GL_BITMAP, store_of(h, false), false);
  if (need > kMaxImageBytes) return;
  Block src(h, need, off);
  // A null bitmap is allowed when nothing is drawn (w or h zero): raster position moves only.
  glBitmap(w, hgt, xo, yo, xm, ym, (in.u8() & 7) == 0 && need == 0 ? nullptr : src.as<GLubyte>());
}

void op_pixel_map(Harness& h, Input& in) {
  const GLenum map = in.e(kPixelMaps);
  const GLint size = in.i();
  const uint16_t off = in.u16();
  // GL reads `size` values when 0 < size <= MAX_PIXEL_MAP_TABLE (§3.6.3); larger sizes are
  // errors and get a block too small for them.
  const int64_t count = size > 0 && size <= 4096 ? size : 0;
  switch (in.u8() % 3) {
  case 0: {
    Block b(h, count * 4, off);
    glPixelMapfv(map, size, b.as<GLfloat>());
    break;
  }
  case 1: {
    Block b(h, count * 4, off);
    glPixelMapuiv(map, size, b.as<GLuint>());
    break;
  }
  default: {
    Block b(h, count * 2, off);
    glPixelMapusv(map, size, b.as<GLushort>());
    break;
  }
  }
}

void op_get_pixel_map(Harness& h, Input& in) {
  const GLenum map = in.e(kPixelMaps);
  // The size query of a map is the map's enum plus 0x40 (Table 6.19 / gl.h).
  const bool known = map >= GL_PIXEL_MAP_I_TO_I && map <= GL_PIXEL_MAP_A_TO_A;
  const int64_t count = known ? get_int(map + 0x40) : 0;
  switch (in.u8() % 3) {
  case 0: {
    Block b(h, count * 4);
    glGetPixelMapfv(map, b.as<GLfloat>());
    break;
  }
  case 1: {
    Block b(h, count * 4);
    glGetPixelMapuiv(map, b.as<GLuint>());
    break;
  }
  default: {
    Block b(h, count * 2);
    glGetPixelMapusv(map, b.as<GLushort>());
    break;
  }
  }
}

void op_stipple(Harness& h, Input& in) {
  // A 32 x 32 bitmap through the unpack (PolygonStipple) or pack (GetPolygonStipple) state.
  const bool get = in.u8() & 1;
  const int64_t need = image_bytes(32, 32, 1, GL_COLOR_INDEX, GL_BITMAP, store_of(h, get), false);
  if (need > kMaxImageBytes) return;
  Block b(h, need, in.u16());
  if (get)
    glGetPolygonStipple(b.as<GLubyte>());
  else
    glPolygonStipple(b.as<GLubyte>());
}

// Level size of a texture image as the GL reports it (0 when the query fails).
int64_t level_param(GLenum target, GLint level, GLenum pname) {
  GLint v = 0;
  glGetTexLevelParameteriv(target, level, pname, &v);
  return v;
}

void op_tex_image(Harness& h, Input& in, int dims, bool sub) {
  const GLenum target = in.e(kTexTargets);
  const GLint level = in.i();
  const GLint xoff = sub ? in.i() : 0, yoff = sub && dims > 1 ? in.i() : 0;
  const GLint zoff = sub && dims > 2 ? in.i() : 0;
  const GLint internal = sub ? 0 : static_cast<GLint>(in.e(kInternalFormats));
  const int32_t small = dims == 3 ? 16 : kMaxSurface;
  const GLsizei w = dim(in, small), hgt = dims > 1 ? dim(in, small) : 1;
  const GLsizei d = dims > 2 ? dim(in, small) : 1;
  const GLint border = sub ? 0 : static_cast<GLint>(in.u8() % 4) - 1;
  const GLenum format = in.e(kPixelFormats), type = in.e(kPixelTypes);
  const uint8_t how = in.u8();
  const int64_t need = image_bytes(w, hgt, d, format, type, store_of(h, false), dims == 3);
  if (tracing()) {
    const Store st = store_of(h, false);
    std::fprintf(stderr,
                 "  tex image %dD%s %dx%dx%d format 0x%x type 0x%x row %lld skip %lld/%lld/%lld "
                 "align %lld height %lld: %lld bytes\n",
                 dims, sub ? " sub" : "", w, hgt, d, format, type,
                 static_cast<long long>(st.row_length), static_cast<long long>(st.skip_pixels),
                 static_cast<long long>(st.skip_rows), static_cast<long long>(st.skip_images),
                 static_cast<long long>(st.alignment), static_cast<long long>(st.image_height),
                 static_cast<long long>(need));
  }
  // TexImage with a null pointer is legal (the image is left undefined); TexSubImage without
  // data is not, so a subimage the harness cannot back is skipped.
  const bool null_data = need > kMaxImageBytes || (!sub && (how & 15) == 0);
  if (sub && null_data) return;
  Block src(h, null_data ? 0 : need, static_cast<size_t>(how) * 97);
  const void* p = null_data ? nullptr : src.get();
  switch (dims * 2 + sub) {
  case 2:
    glTexImage1D(target, level, internal, w, border, format, type, p);
    break;
  case 3:
    glTexSubImage1D(target, level, xoff, w, format, type, p);
    break;
  case 4:
    glTexImage2D(target, level, internal, w, hgt, border, format, type, p);
    break;
  case 5:
    glTexSubImage2D(target, level, xoff, yoff, w, hgt, format, type, p);
    break;
  case 6:
    glTexImage3D(target, level, internal, w, hgt, d, border, format, type, p);
    break;
  default:
    glTexSubImage3D(target, level, xoff, yoff, zoff, w, hgt, d, format, type, p);
    break;
  }
}

void op_copy_tex(Input& in) {
  const GLenum target = in.e(kTexTargets);
  const GLint level = in.i();
  const GLint x = in.i(), y = in.i();
  const GLsizei w = dim(in, kMaxSurface), hgt = dim(in, kMaxSurface);
  switch (in.u8() % 5) {
  case 0: {
    const GLenum internal = in.e(kInternalFormats);
    glCopyTexImage1D(target, level, internal, x, y, w, static_cast<GLint>(in.u8() % 4) - 1);
    break;
  }
  case 1: {
    const GLenum internal = in.e(kInternalFormats);
    glCopyTexImage2D(target, level, internal, x, y, w, hgt, static_cast<GLint>(in.u8() % 4) - 1);
    break;
  }
  case 2:
    glCopyTexSubImage1D(target, level, in.i(), x, y, w);
    break;
  case 3: {
    const GLint xo = in.i(), yo = in.i();
    glCopyTexSubImage2D(target, level, xo, yo, x, y, w, hgt);
    break;
  }
  default: {
    const GLint xo = in.i(), yo = in.i(), zo = in.i();
    glCopyTexSubImage3D(target, level, xo, yo, zo, x, y, w, hgt);
    break;
  }
  }
}

void op_get_tex_image(Harness& h, Input& in) {
  const GLenum target = in.e(kTexTargets);
  const GLint level = in.i();
  const GLenum format = in.e(kPixelFormats), type = in.e(kPixelTypes);
  const int64_t w = level_param(target, level, GL_TEXTURE_WIDTH);
  const int64_t hgt = level_param(target, level, GL_TEXTURE_HEIGHT);
  const int64_t d = level_param(target, level, GL_TEXTURE_DEPTH);
  glGetError();
  const int64_t need =
      image_bytes(w, hgt, d, format, type, store_of(h, true), target == GL_TEXTURE_3D);
  if (need > kMaxImageBytes) return;
  Block dst(h, need);
  glGetTexImage(target, level, format, type, dst.get());
}

void op_compressed(Harness& h, Input& in) {
  const GLenum target = in.e(kTexTargets);
  const GLint level = in.i();
  const GLenum internal = in.e(kInternalFormats);
  const GLsizei w = dim(in, kMaxSurface), hgt = dim(in, kMaxSurface), d = dim(in, 8);
  const GLsizei size = in.i();
  const GLint xo = in.i(), yo = in.i(), zo = in.i();
  const uint8_t which = in.u8() % 7;
  // imageSize bytes are read when the call succeeds; a size the harness cannot back is
  // skipped unless it is negative (an error before any read).
  if (size > kMaxImageBytes) return;
  Block src(h, size > 0 ? size : 0, in.u16());
  const void* p = src.get();
  switch (which) {
  case 0:
    glCompressedTexImage1D(target, level, internal, w, 0, size, p);
    break;
  case 1:
    glCompressedTexImage2D(target, level, internal, w, hgt, 0, size, p);
    break;
  case 2:
    glCompressedTexImage3D(target, level, internal, w, hgt, d, 0, size, p);
    break;
  case 3:
    glCompressedTexSubImage1D(target, level, xo, w, internal, size, p);
    break;
  case 4:
    glCompressedTexSubImage2D(target, level, xo, yo, w, hgt, internal, size, p);
    break;
  case 5:
    glCompressedTexSubImage3D(target, level, xo, yo, zo, w, hgt, d, internal, size, p);
    break;
  default: {
    // Writes TEXTURE_COMPRESSED_IMAGE_SIZE bytes of a compressed image.
    const int64_t have = level_param(target, level, GL_TEXTURE_COMPRESSED_IMAGE_SIZE);
    glGetError();
    if (have > kMaxImageBytes) return;
    Block dst(h, have);
    glGetCompressedTexImage(target, level, dst.get());
    break;
  }
  }
}

} // namespace

void op_pixels(Harness& h, Input& in) {
  switch (in.u8() % 14) {
  case 0:
    op_read_pixels(h, in);
    break;
  case 1:
  case 2:
    op_draw_pixels(h, in);
    break;
  case 3:
    op_bitmap(h, in);
    break;
  case 4: {
    const GLint x = in.i(), y = in.i();
    const GLsizei w = dim(in, kMaxSurface), hgt = dim(in, kMaxSurface);
    glCopyPixels(x, y, w, hgt, in.e(kCopyTypes));
    break;
  }
  case 5:
    op_pixel_map(h, in);
    break;
  case 6:
    op_get_pixel_map(h, in);
    break;
  case 7:
    glPixelTransferf(in.e(kTransferParams), in.f());
    break;
  case 8:
    glPixelTransferi(in.e(kTransferParams), in.i());
    break;
  case 9:
    glPixelZoom(in.f(), in.f());
    break;
  case 10:
    glPixelStorei(in.e(kStoreParams), in.i());
    break;
  case 11:
    glPixelStoref(in.e(kStoreParams), in.f());
    break;
  case 12:
    op_stipple(h, in);
    break;
  default: {
    // Small values for the store parameters, so that extents stay within the harness's
    // limits more often.
    const GLenum p = in.e(kStoreParams);
    glPixelStorei(p, in.u8() % 20);
    break;
  }
  }
}

void op_texture_image(Harness& h, Input& in) {
  switch (in.u8() % 12) {
  case 0:
    op_tex_image(h, in, 1, false);
    break;
  case 1:
  case 2:
    op_tex_image(h, in, 2, false);
    break;
  case 3:
    op_tex_image(h, in, 3, false);
    break;
  case 4:
    op_tex_image(h, in, 1, true);
    break;
  case 5:
    op_tex_image(h, in, 2, true);
    break;
  case 6:
    op_tex_image(h, in, 3, true);
    break;
  case 7:
    op_copy_tex(in);
    break;
  case 8:
    op_get_tex_image(h, in);
    break;
  case 9:
    op_compressed(h, in);
    break;
  case 10: {
    const GLenum target = in.e(kTexTargets);
    const GLint level = in.i();
    GLint iv[4] = {};
    glGetTexLevelParameteriv(target, level, in.e(), iv);
    break;
  }
  default: {
    const GLenum target = in.e(kTexTargets);
    const GLint level = in.i();
    GLfloat fv[4] = {};
    glGetTexLevelParameterfv(target, level, in.e(), fv);
    break;
  }
  }
}

} // namespace pineda::fuzz
