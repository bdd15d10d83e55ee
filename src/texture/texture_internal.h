// Helpers shared by the texture command files (texture_object.cpp, tex_image.cpp); not for use
// outside src/texture.
#pragma once

#include <GL/gl.h>

#include "core/context.h"
#include "texture/texture_object.h"

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

} // namespace pineda
