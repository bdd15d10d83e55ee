// Mipmap generation (GL 2.1 §3.8.8 GENERATE_MIPMAP) for the image commands.
#pragma once

#include "state/texture_object.h"

namespace pineda {

// Fills `dst` (its sizes, border and format already set, texel storage empty) from `src`, the
// next larger level: each texel is the bilinear (trilinear for 3D) sample of `src` at the
// texel's centre with CLAMP_TO_EDGE, in llvmpipe's 8-bit fixed point, which for halved
// power-of-two sizes is the 2x2 (2x2x2) box filter. Border texels come from the source border.
// May throw std::bad_alloc.
void downsample_image(const TexImage& src, TexImage& dst, int dims);

// Rebuilds levels base+1..q of `face` from the base level (GENERATE_MIPMAP, §3.8.8).
void generate_mipmaps(TextureObject& tex, int face, int dims);

} // namespace pineda
