// The texture sampler (GL 2.1 §3.8.8-§3.8.10, §3.8.14).
#include "texture/sampler.h"

#include "texture/texture_object.h"

namespace pineda {

bool make_sampler_view(const TextureObject& tex, SamplerView& out) {
  (void)tex;
  out = SamplerView{};
  return false; // no command specifies images yet: every texture is incomplete
}

void sample_texture(const SamplerView& v, int n, const float* s, const float* t, const float* r,
                    const float* lambda, float bias, float (*rgba)[4]) {
  (void)v, (void)s, (void)t, (void)r, (void)lambda, (void)bias;
  for (int i = 0; i < n; ++i) {
    rgba[i][0] = rgba[i][1] = rgba[i][2] = 0.0f;
    rgba[i][3] = 1.0f;
  }
}

} // namespace pineda
