// Helpers shared by the texture command files of the state layer (texture_object.cpp,
// tex_image.cpp, tex_copy.cpp, tex_compressed.cpp, and the display-list savers of
// dlist_save_texpix.cpp).
#pragma once

#include <GL/gl.h>

#include "state/context.h"
#include "state/tex_format.h"
#include "state/texture_object.h"

namespace pineda {

// kTex1D... for GL_TEXTURE_1D/2D/3D/CUBE_MAP, -1 otherwise.
int texture_target_index(GLenum target);

// The object bound to `target` (a TexTargetIndex) on the active unit; never null.
TextureObject* active_texture_object(Context* ctx, int target_index);

// Records that a texture image or parameter changed (SharedObjects::texture_generation and
// the kDirtyTexture bit).
inline void texture_changed(Context* ctx) {
  ++ctx->shared->texture_generation;
  mark_dirty(ctx, kDirtyTexture);
}

// Where the images of an image-command target live: the object (bound or proxy), the cube
// face and the limits of the target.
struct ImageTarget {
  TextureObject* tex = nullptr;
  int face = 0;
  int dims = 2;
  bool proxy = false;
  bool cube = false;
  int max_size = 0;
  int max_levels = 0;
};

// The four proxy targets (§3.8.11): image commands on them only check and record sizes, and
// display lists execute them at once (§5.4).
inline bool is_proxy_texture_target(GLenum target) {
  return target == GL_PROXY_TEXTURE_1D || target == GL_PROXY_TEXTURE_2D ||
         target == GL_PROXY_TEXTURE_3D || target == GL_PROXY_TEXTURE_CUBE_MAP;
}

// Resolves `target` for a command on `dims`-dimensional images (cube faces and
// PROXY_TEXTURE_CUBE_MAP count as 2D); false when the command does not take it. `allow_proxy`
// false rejects the proxy targets too.
bool image_target(Context* ctx, GLenum target, int dims, bool allow_proxy, ImageTarget& out);

// Sets an image's sizes and format fields (no texels).
void set_image_info(TexImage& im, GLenum internalformat, const TexFormatInfo& f, int w, int h,
                    int d, int border);

// After an image of level `level` changed: GENERATE_MIPMAP rebuilds the levels above the base
// level (§3.8.8), and the change is recorded (texture_changed).
void image_changed(Context* ctx, TextureObject& tex, int face, int level, int dims,
                   const char* func);

// The checks of the sub-image commands (§3.8.2 TexSubImage, CopyTexSubImage): the image, or
// null with the error recorded (INVALID_VALUE for a bad level or a region outside the image,
// INVALID_OPERATION when the image was never specified). Offsets are border-relative.
TexImage* sub_image_target(Context* ctx, const char* func, const ImageTarget& it, GLint level,
                           int x, int y, int z, int w, int h, int d);

// Writes w x h x d unpacked groups (RGBA floats, or depth floats for a depth image) into the
// region at border-relative offset (x, y, z), converted to the image's internal format.
void store_region(TexImage& im, int dims, int x, int y, int z, int w, int h, int d,
                  const float* groups);

// Writes w x h stencil indices into the stencil of a DEPTH_STENCIL image at border-relative
// (x, y) of slice z (EXT_packed_depth_stencil); nothing for other images.
void store_stencil_region(TexImage& im, int dims, int x, int y, int z, int w, int h,
                          const uint32_t* s);

} // namespace pineda
