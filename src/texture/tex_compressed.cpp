// Compressed texture images (GL 2.1 §3.8.3, §6.1.4). Pineda supports no specific compressed
// format (NUM_COMPRESSED_TEXTURE_FORMATS is 0) and stores images given a generic compressed
// internal format (COMPRESSED_RGB ...) uncompressed, as §3.8.1 allows. So every compressed
// image command names an unsupported format (INVALID_ENUM) and no image is ever compressed
// (GetCompressedTexImage: INVALID_OPERATION).
#include "core/api_util.h"
#include "dispatch.h"
#include "texture/texture_internal.h"

namespace pineda {

namespace {

// The checks of CompressedTex[Sub]Image: a target the uncompressed command takes, then the
// format, which is never a supported specific compressed format.
void compressed_image(const char* func, int dims, GLenum target, bool allow_proxy) {
  PINEDA_CTX_OUTSIDE(func);
  ImageTarget it;
  if (!image_target(ctx, target, dims, allow_proxy, it))
    return record_error(ctx, GL_INVALID_ENUM, func, target);
  record_error(ctx, GL_INVALID_ENUM, func);
}

int dims_of_target(GLenum target) {
  switch (target) {
  case GL_TEXTURE_1D:
    return 1;
  case GL_TEXTURE_3D:
    return 3;
  default:
    return 2;
  }
}

} // namespace

namespace exec {

void GLAPIENTRY CompressedTexImage1D(GLenum target, GLint, GLenum, GLsizei, GLint, GLsizei,
                                     const void*) {
  compressed_image("glCompressedTexImage1D", 1, target, true);
}

void GLAPIENTRY CompressedTexImage2D(GLenum target, GLint, GLenum, GLsizei, GLsizei, GLint, GLsizei,
                                     const void*) {
  compressed_image("glCompressedTexImage2D", 2, target, true);
}

void GLAPIENTRY CompressedTexImage3D(GLenum target, GLint, GLenum, GLsizei, GLsizei, GLsizei, GLint,
                                     GLsizei, const void*) {
  compressed_image("glCompressedTexImage3D", 3, target, true);
}

void GLAPIENTRY CompressedTexSubImage1D(GLenum target, GLint, GLint, GLsizei, GLenum, GLsizei,
                                        const void*) {
  compressed_image("glCompressedTexSubImage1D", 1, target, false);
}

void GLAPIENTRY CompressedTexSubImage2D(GLenum target, GLint, GLint, GLint, GLsizei, GLsizei,
                                        GLenum, GLsizei, const void*) {
  compressed_image("glCompressedTexSubImage2D", 2, target, false);
}

void GLAPIENTRY CompressedTexSubImage3D(GLenum target, GLint, GLint, GLint, GLint, GLsizei, GLsizei,
                                        GLsizei, GLenum, GLsizei, const void*) {
  compressed_image("glCompressedTexSubImage3D", 3, target, false);
}

void GLAPIENTRY GetCompressedTexImage(GLenum target, GLint level, void*) {
  PINEDA_CTX_OUTSIDE("glGetCompressedTexImage");
  ImageTarget it;
  if (!image_target(ctx, target, dims_of_target(target), false, it))
    return record_error(ctx, GL_INVALID_ENUM, "glGetCompressedTexImage", target);
  if (level < 0 || level >= it.max_levels)
    return record_error(ctx, GL_INVALID_VALUE, "glGetCompressedTexImage");
  // §6.1.4: reading back an image that is not compressed is INVALID_OPERATION.
  record_error(ctx, GL_INVALID_OPERATION, "glGetCompressedTexImage");
}

} // namespace exec

} // namespace pineda
