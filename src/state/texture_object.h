// Texture objects (GL 2.1 §3.8.12) and their images (§3.8.1-§3.8.5), and the per-context
// texture bindings: GL state of the texture area (Tables 6.16-6.19). Objects live in
// SharedObjects (state/context.h); texture_object.cpp implements the commands that create, bind
// and delete them and set their parameters, tex_image.cpp, tex_copy.cpp and tex_compressed.cpp
// the image commands, texture_view.cpp the sampler's view of a complete object
// (texture/sampler.h, the back end).
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "core/limits.h"
#include "texture/sampler.h"

namespace pineda {

struct Context;

// One image of a texture object: a mipmap level of a 1D, 2D or 3D texture or of one cube face.
// An image with width 0 is unspecified (§3.8.1: zero-sized images are allowed and unspecified).
struct TexImage {
  int width = 0, height = 0, depth = 0; // including the border on each side
  int border = 0;
  GLenum internal_format = 1; // TEXTURE_INTERNAL_FORMAT as the application gave it (Table 6.20)
  TexBase base = TexBase::RGBA;
  bool is_depth = false; // DEPTH_COMPONENT base format; `base` is then unused
  bool srgb = false;     // an sRGB internal format (tex_format.h): decoded when sampled
  // Component resolutions reported by glGetTexLevelParameter (TEXTURE_RED_SIZE ...).
  uint8_t red_size = 0, green_size = 0, blue_size = 0, alpha_size = 0;
  uint8_t luminance_size = 0, intensity_size = 0, depth_size = 0;
  uint8_t stencil_size = 0;  // 8 for DEPTH_STENCIL images (EXT_packed_depth_stencil)
  std::vector<uint8_t> rgba; // colour: 4 bytes per texel, expanded by Table 3.23, rows bottom up
  // depth: one value per texel of depth_size bits, as a depth buffer of that many bits stores
  // it (sampler.h depth_texel_max), so that framebuffer objects render into it directly
  std::vector<uint32_t> z;
  std::vector<uint8_t> stencil; // DEPTH_STENCIL images: one stencil index per texel
};

// The parameters of a texture object (GL 2.1 Table 6.19, §3.8.4, §3.8.14).
struct TexParams {
  GLenum min_filter = GL_NEAREST_MIPMAP_LINEAR;
  GLenum mag_filter = GL_LINEAR;
  GLenum wrap_s = GL_REPEAT, wrap_t = GL_REPEAT, wrap_r = GL_REPEAT;
  float border_color[4] = {0, 0, 0, 0};
  float min_lod = -1000.0f, max_lod = 1000.0f;
  GLint base_level = 0, max_level = 1000;
  float lod_bias = 0.0f;
  float priority = 1.0f;
  bool generate_mipmap = false;
  GLenum depth_mode = GL_LUMINANCE;
  GLenum compare_mode = GL_NONE;
  GLenum compare_func = GL_LEQUAL;
};

struct TextureObject {
  GLuint name = 0;
  GLenum target = 0; // 0 until first bound; then GL_TEXTURE_1D/2D/3D/CUBE_MAP for good
  TexParams params;
  // images[face][level]; faces other than 0 are used by cube maps only, in the order
  // POSITIVE_X, NEGATIVE_X, POSITIVE_Y, NEGATIVE_Y, POSITIVE_Z, NEGATIVE_Z.
  TexImage images[6][kMaxTexLevels];
};

// Index of the texture targets in TextureState's per-unit arrays.
enum TexTargetIndex : int { kTex1D = 0, kTex2D, kTex3D, kTexCube, kTexTargetCount };

// Per-context texture object state (GL 2.1 Table 6.17 bindings): the default objects (name 0,
// one per target) and each unit's bound names; also the proxy images (§3.8.11).
struct TextureState {
  TextureState();
  std::unique_ptr<TextureObject> defaults[kTexTargetCount];
  GLuint bound[kMaxCombinedTextureImageUnits][kTexTargetCount] = {};
  // Proxy targets keep only level state (sizes, formats), never texels.
  std::unique_ptr<TextureObject> proxies[kTexTargetCount];
};

// Snapshot of `tex` for one draw; false when `tex` is not complete (§3.8.10), in which case the
// unit behaves as if texturing were disabled for it (§3.8.15). For depth textures, `base` is the
// one DEPTH_TEXTURE_MODE selects (Luminance, Intensity or Alpha). The view points into `tex`'s
// images: it stays valid until the next change of SharedObjects::texture_generation.
bool make_sampler_view(const TextureObject& tex, SamplerView& out);

// The object bound to `target` (GL_TEXTURE_1D/2D/3D/CUBE_MAP) of texture unit `unit` (default
// object when 0 is bound); never null.
const TextureObject* bound_texture(const Context* ctx, int unit, GLenum target);

struct StateArea;
// Texture bindings and limits for glGet, and the bindings with the bound objects' parameters
// that TEXTURE_BIT saves (texture_object.cpp).
extern const StateArea kTextureObjectArea;

} // namespace pineda
