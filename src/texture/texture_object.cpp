// Texture objects (GL 2.1 §3.8.12): the per-context bindings and default objects.
#include "texture/texture_object.h"

#include "core/api_util.h"

namespace pineda {

namespace {
constexpr GLenum kTargets[kTexTargetCount] = {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D,
                                              GL_TEXTURE_CUBE_MAP};

int target_index(GLenum target) {
  switch (target) {
  case GL_TEXTURE_1D:
    return kTex1D;
  case GL_TEXTURE_2D:
    return kTex2D;
  case GL_TEXTURE_3D:
    return kTex3D;
  case GL_TEXTURE_CUBE_MAP:
    return kTexCube;
  default:
    return -1;
  }
}
} // namespace

TextureState::TextureState() {
  for (int i = 0; i < kTexTargetCount; ++i) {
    defaults[i] = std::make_unique<TextureObject>();
    defaults[i]->target = kTargets[i];
    proxies[i] = std::make_unique<TextureObject>();
    proxies[i]->target = kTargets[i];
  }
}

const TextureObject* bound_texture(const Context* ctx, int unit, GLenum target) {
  const int ti = target_index(target);
  const int t = ti < 0 ? kTex2D : ti;
  const GLuint name = ctx->texobj.bound[unit][t];
  if (name != 0) {
    auto it = ctx->shared->textures.find(name);
    if (it != ctx->shared->textures.end()) return it->second.get();
  }
  return ctx->texobj.defaults[t].get();
}

} // namespace pineda
