// Texture internal formats (GL 2.1 §3.8.1 Tables 3.15-3.17): base format, the component
// resolutions Pineda reports, and the conversion of unpacked RGBA or depth groups into the
// stored texels. Colour texels are stored as four 8-bit components already expanded by base
// format (Table 3.23); components the format keeps with fewer than 8 bits are rounded to that
// resolution first, as Mesa llvmpipe stores RGBA4, RGB5_A1, R3_G3_B2 ... in packed formats.
// Depth texels are unsigned integers of the depth resolution, as a depth buffer stores them;
// DEPTH_STENCIL images (EXT_packed_depth_stencil) have an 8-bit stencil index beside.
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "texture/sampler.h"

namespace pineda {

struct TexFormatInfo {
  TexBase base = TexBase::RGBA;
  bool depth = false;
  // Resolutions reported by glGetTexLevelParameter (those llvmpipe reports: 12-bit components
  // are kept in 16). Stored resolution is min(size, 8) for colour.
  uint8_t r = 0, g = 0, b = 0, a = 0, l = 0, i = 0, d = 0;
  // GL 2.1 §3.8.1 Table 3.16 (EXT_texture_sRGB): SRGB*, SLUMINANCE*. The texels are stored as
  // given, sRGB-encoded, and decoded when sampled (§3.8.15).
  bool srgb = false;
  uint8_t s = 0; // stencil bits: 8 for DEPTH_STENCIL formats (depth is then true too)
};

// The format `internalformat` names (Tables 3.16, 3.17 and the legacy 1-4), or false for a
// value TexImage rejects with INVALID_VALUE (GL 2.1 §3.8.1).
bool lookup_internal_format(GLint internalformat, TexFormatInfo& out);

// GL 2.1 §3.8.1: with no specific compressed formats, a generic compressed internal format
// (Table 3.17) "is instead replaced by the corresponding base internal format": the image is
// stored uncompressed and TEXTURE_INTERNAL_FORMAT reads the base format. Other values unchanged.
GLenum uncompressed_internal_format(GLenum internalformat);

// Converts `n` unpacked RGBA groups (floats, clamped to [0,1] here) into stored texels:
// components selected by base format (Table 3.15), rounded to their resolution, expanded by
// Table 3.23.
void rgba_to_texels(const TexFormatInfo& f, const float* rgba, int n, uint8_t* texels);

// Rounds `n` depth values (clamped to [0,1]) to the format's depth resolution.
void depth_to_texels(const TexFormatInfo& f, const float* z, int n, uint32_t* out);

// The RGBA group a stored texel stands for, as glGetTexImage returns it (§6.1.4): components
// missing from the base format read as 0 (colour) or 1 (alpha); luminance and intensity appear
// in red (Table 6.1).
void texel_to_rgba(TexBase base, const uint8_t* texel, float* rgba);

} // namespace pineda
