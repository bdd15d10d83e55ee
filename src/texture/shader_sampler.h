// Texture lookups of GLSL shaders (GL 2.1 §3.8, GLSL 1.20 §8.7): the shader engine's
// TextureSampler (shader/engine.h) over the sampler's views of the objects bound to each
// texture image unit. Fragment lookups without an explicit level take the level of detail from
// the 2x2 quads the engine runs (§3.8.8, as the fixed-function path does, fragment/shade.cpp);
// vertex lookups give the level.
#pragma once

#include "core/limits.h"
#include "shader/engine.h"
#include "texture/sampler.h"

namespace pineda {

class ShaderSampler final : public shader::TextureSampler {
public:
  // The view of the object bound to each unit's target (TexTarget order: 1D, 2D, 3D, cube),
  // when it is complete; an incomplete texture samples as (0, 0, 0, 1).
  // Every texture image unit a sampler may name (MAX_COMBINED_TEXTURE_IMAGE_UNITS, §2.15.4).
  SamplerView views[kMaxCombinedTextureImageUnits][4];
  bool complete[kMaxCombinedTextureImageUnits][4] = {};
  float unit_bias[kMaxCombinedTextureImageUnits] = {}; // TEXTURE_LOD_BIAS (§3.8.8)

  void sample(const shader::TexRequest& req) override;
};

} // namespace pineda
