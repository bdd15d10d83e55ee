// Compressed texture images (GL 2.1 §3.8.3, §6.1.4): glCompressedTexImage{1,2,3}D,
// glCompressedTexSubImage{1,2,3}D and glGetCompressedTexImage. Pineda supports no specific
// compressed internal format (NUM_COMPRESSED_TEXTURE_FORMATS is 0), so no texture image is ever
// stored compressed: the generic compressed formats given to TexImage are stored uncompressed
// (§3.8.1, tex_format.cpp), and each of these commands ends in the error the spec names for
// it. Their display-list savers are here too (src/api/dlist_savers.txt).
#include <cstring>

#include "state/api_util.h"
#include "dispatch.h"
#include "state/texture_internal.h"

namespace pineda {

namespace {

// §3.8.3: the target must be one TexImage of the same dimension takes; internalformat must be
// a specific compressed format, of which there are none ("using any of the six generic
// compressed internal formats as internalformat will result in an INVALID_ENUM error").
void compressed_image(const char* func, int dims, GLenum target, GLenum internalformat) {
  PINEDA_CTX_OUTSIDE(func);
  ImageTarget it;
  if (!image_target(ctx, target, dims, true, it))
    return record_error(ctx, GL_INVALID_ENUM, func, target);
  record_error(ctx, GL_INVALID_ENUM, func, internalformat);
}

// §3.8.3: the target must be one TexSubImage of the same dimension takes, and `format` a
// supported specific compressed format, of which there are none: INVALID_ENUM, checked before
// the level, region and size, as Mesa (the tie-breaker) checks them.
void compressed_sub_image(const char* func, int dims, GLenum target, GLint, int, int, int, int, int,
                          int, GLenum format, GLsizei) {
  PINEDA_CTX_OUTSIDE(func);
  ImageTarget it;
  if (!image_target(ctx, target, dims, false, it))
    return record_error(ctx, GL_INVALID_ENUM, func, target);
  record_error(ctx, GL_INVALID_ENUM, func, format);
}

// The dimension of a GetCompressedTexImage target (cube faces are 2D).
int query_dims(GLenum target) {
  return target == GL_TEXTURE_1D ? 1 : target == GL_TEXTURE_3D ? 3 : 2;
}

// ---- display lists (§5.4) ------------------------------------------------------------------
// Every compressed image command is an error here and never reads its data, so a list keeps
// the other arguments only and replays the call without data: the error is generated when the
// list executes, against the texture state of that time. Proxy targets are executed at once,
// as for TexImage.

struct ImageArgs {
  GLenum target, internalformat;
  GLint dims;
};

void replay_image(const void* p) {
  ImageArgs a;
  std::memcpy(&a, p, sizeof a);
  const char* const names[] = {"glCompressedTexImage1D", "glCompressedTexImage2D",
                               "glCompressedTexImage3D"};
  compressed_image(names[a.dims - 1], a.dims, a.target, a.internalformat);
}

void save_image(int dims, GLenum target, GLenum internalformat) {
  const ImageArgs a{target, internalformat, dims};
  if (is_proxy_texture_target(target) || dlist_record(&replay_image, &a, sizeof a))
    replay_image(&a);
}

struct SubImageArgs {
  GLenum target, format;
  GLint dims, level, x, y, z, w, h, d;
  GLsizei image_size;
};

void replay_sub_image(const void* p) {
  SubImageArgs a;
  std::memcpy(&a, p, sizeof a);
  const char* const names[] = {"glCompressedTexSubImage1D", "glCompressedTexSubImage2D",
                               "glCompressedTexSubImage3D"};
  compressed_sub_image(names[a.dims - 1], a.dims, a.target, a.level, a.x, a.y, a.z, a.w, a.h, a.d,
                       a.format, a.image_size);
}

void save_sub_image(const SubImageArgs& a) {
  if (dlist_record(&replay_sub_image, &a, sizeof a)) replay_sub_image(&a);
}

} // namespace

namespace exec {

void GLAPIENTRY CompressedTexImage1D(GLenum target, GLint, GLenum internalformat, GLsizei, GLint,
                                     GLsizei, const void*) {
  compressed_image("glCompressedTexImage1D", 1, target, internalformat);
}

void GLAPIENTRY CompressedTexImage2D(GLenum target, GLint, GLenum internalformat, GLsizei, GLsizei,
                                     GLint, GLsizei, const void*) {
  compressed_image("glCompressedTexImage2D", 2, target, internalformat);
}

void GLAPIENTRY CompressedTexImage3D(GLenum target, GLint, GLenum internalformat, GLsizei, GLsizei,
                                     GLsizei, GLint, GLsizei, const void*) {
  compressed_image("glCompressedTexImage3D", 3, target, internalformat);
}

void GLAPIENTRY CompressedTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLsizei width,
                                        GLenum format, GLsizei imageSize, const void*) {
  compressed_sub_image("glCompressedTexSubImage1D", 1, target, level, xoffset, 0, 0, width, 1, 1,
                       format, imageSize);
}

void GLAPIENTRY CompressedTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                        GLsizei width, GLsizei height, GLenum format,
                                        GLsizei imageSize, const void*) {
  compressed_sub_image("glCompressedTexSubImage2D", 2, target, level, xoffset, yoffset, 0, width,
                       height, 1, format, imageSize);
}

void GLAPIENTRY CompressedTexSubImage3D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                        GLint zoffset, GLsizei width, GLsizei height, GLsizei depth,
                                        GLenum format, GLsizei imageSize, const void*) {
  compressed_sub_image("glCompressedTexSubImage3D", 3, target, level, xoffset, yoffset, zoffset,
                       width, height, depth, format, imageSize);
}

// §6.1.4: target as for GetTexImage (no proxies, no CUBE_MAP); a level outside [0, max) is
// INVALID_VALUE; an image stored uncompressed, which every image is, INVALID_OPERATION. A level
// with no image is INVALID_VALUE, as in Mesa llvmpipe (it holds no image to return at all).
void GLAPIENTRY GetCompressedTexImage(GLenum target, GLint level, void*) {
  PINEDA_CTX_OUTSIDE("glGetCompressedTexImage");
  ImageTarget it;
  if (!image_target(ctx, target, query_dims(target), false, it))
    return record_error(ctx, GL_INVALID_ENUM, "glGetCompressedTexImage", target);
  if (level < 0 || level >= it.max_levels || it.tex->images[it.face][level].width == 0)
    return record_error(ctx, GL_INVALID_VALUE, "glGetCompressedTexImage");
  record_error(ctx, GL_INVALID_OPERATION, "glGetCompressedTexImage");
}

} // namespace exec

namespace saver {

void GLAPIENTRY CompressedTexImage1D(GLenum target, GLint, GLenum internalformat, GLsizei, GLint,
                                     GLsizei, const void*) {
  save_image(1, target, internalformat);
}

void GLAPIENTRY CompressedTexImage2D(GLenum target, GLint, GLenum internalformat, GLsizei, GLsizei,
                                     GLint, GLsizei, const void*) {
  save_image(2, target, internalformat);
}

void GLAPIENTRY CompressedTexImage3D(GLenum target, GLint, GLenum internalformat, GLsizei, GLsizei,
                                     GLsizei, GLint, GLsizei, const void*) {
  save_image(3, target, internalformat);
}

void GLAPIENTRY CompressedTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLsizei width,
                                        GLenum format, GLsizei imageSize, const void*) {
  save_sub_image({target, format, 1, level, xoffset, 0, 0, width, 1, 1, imageSize});
}

void GLAPIENTRY CompressedTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                        GLsizei width, GLsizei height, GLenum format,
                                        GLsizei imageSize, const void*) {
  save_sub_image({target, format, 2, level, xoffset, yoffset, 0, width, height, 1, imageSize});
}

void GLAPIENTRY CompressedTexSubImage3D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                        GLint zoffset, GLsizei width, GLsizei height, GLsizei depth,
                                        GLenum format, GLsizei imageSize, const void*) {
  save_sub_image(
      {target, format, 3, level, xoffset, yoffset, zoffset, width, height, depth, imageSize});
}

} // namespace saver
} // namespace pineda
