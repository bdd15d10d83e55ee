// A texture object as the sampler sees it for one draw (GL 2.1 §3.8.10 completeness, §3.8.14
// depth textures): the texture area's derived state, a plain SamplerView
// (texture/sampler.h) made from the object's images and parameters.
#include <algorithm>

#include "state/texture_object.h"

namespace pineda {

namespace {

bool is_mipmap_filter(GLenum f) {
  return f != GL_NEAREST && f != GL_LINEAR;
}

// Whether a level sequence matches the base level's format and border (§3.8.10).
bool same_format(const TexImage& a, const TexImage& b) {
  return a.is_depth == b.is_depth && a.base == b.base && a.srgb == b.srgb && a.border == b.border &&
         a.red_size == b.red_size && a.green_size == b.green_size && a.blue_size == b.blue_size &&
         a.alpha_size == b.alpha_size && a.luminance_size == b.luminance_size &&
         a.intensity_size == b.intensity_size && a.depth_size == b.depth_size;
}

// Mipmap completeness of one face (§3.8.10): levels base..q present with the halved sizes.
// Returns q, or -1 when incomplete.
int complete_levels(const TextureObject& tex, int face, int dims, bool mipmapped) {
  const TexParams& p = tex.params;
  const int base = p.base_level;
  if (base < 0 || base >= kMaxTexLevels || p.max_level < base) return -1;
  const TexImage& b = tex.images[face][base];
  int w = b.width - 2 * b.border;
  int h = dims >= 2 ? b.height - 2 * b.border : 1;
  int d = dims >= 3 ? b.depth - 2 * b.border : 1;
  if (b.width == 0 || w <= 0 || h <= 0 || d <= 0) return -1;
  if (!mipmapped) return base;
  int largest = std::max(w, std::max(h, d));
  int p_levels = 0;
  while (largest > 1)
    largest >>= 1, ++p_levels;
  const int q = std::min({base + p_levels, p.max_level, kMaxTexLevels - 1});
  for (int level = base + 1; level <= q; ++level) {
    w = std::max(1, w / 2), h = std::max(1, h / 2), d = std::max(1, d / 2);
    const TexImage& im = tex.images[face][level];
    if (!same_format(im, b)) return -1;
    if (im.width - 2 * im.border != w) return -1;
    if (dims >= 2 && im.height - 2 * im.border != h) return -1;
    if (dims >= 3 && im.depth - 2 * im.border != d) return -1;
  }
  // Levels past the largest computed size are not needed when max_level is above p.
  return q;
}

void expand_border(TexBase base, bool depth, const float* c, float* out) {
  const float r = std::clamp(c[0], 0.0f, 1.0f), g = std::clamp(c[1], 0.0f, 1.0f);
  const float b = std::clamp(c[2], 0.0f, 1.0f), a = std::clamp(c[3], 0.0f, 1.0f);
  if (depth) { // the depth value is the border colour's first component; expanded later
    out[0] = out[1] = out[2] = out[3] = r;
    return;
  }
  switch (base) {
  case TexBase::Alpha:
    out[0] = out[1] = out[2] = 0.0f, out[3] = a;
    break;
  case TexBase::Luminance:
    out[0] = out[1] = out[2] = r, out[3] = 1.0f;
    break;
  case TexBase::LuminanceAlpha:
    out[0] = out[1] = out[2] = r, out[3] = a;
    break;
  case TexBase::Intensity:
    out[0] = out[1] = out[2] = out[3] = r;
    break;
  case TexBase::RGB:
    out[0] = r, out[1] = g, out[2] = b, out[3] = 1.0f;
    break;
  case TexBase::RGBA:
    out[0] = r, out[1] = g, out[2] = b, out[3] = a;
    break;
  }
}

} // namespace

bool make_sampler_view(const TextureObject& tex, SamplerView& out) {
  out = SamplerView{};
  const GLenum target = tex.target == 0 ? GL_TEXTURE_2D : tex.target;
  const int dims = texture_dims(target);
  const TexParams& p = tex.params;
  const bool mipmapped = is_mipmap_filter(p.min_filter);
  const int faces = target == GL_TEXTURE_CUBE_MAP ? 6 : 1;
  int q = -1;
  for (int f = 0; f < faces; ++f) {
    const int qf = complete_levels(tex, f, dims, mipmapped);
    if (qf < 0) return false;
    q = qf;
  }
  const TexImage& b = tex.images[0][p.base_level];
  if (faces == 6) { // cube completeness: square base images of one size and format
    for (int f = 0; f < 6; ++f) {
      const TexImage& im = tex.images[f][p.base_level];
      if (im.width != im.height || im.width != b.width || !same_format(im, b)) return false;
    }
  }
  out.target = target;
  out.is_depth = b.is_depth;
  out.srgb = b.srgb;
  if (b.is_depth) {
    out.base = p.depth_mode == GL_INTENSITY ? TexBase::Intensity
               : p.depth_mode == GL_ALPHA   ? TexBase::Alpha
                                            : TexBase::Luminance;
  } else {
    out.base = b.base;
  }
  out.border = b.border;
  out.width = b.width - 2 * b.border;
  out.height = dims >= 2 ? b.height - 2 * b.border : 1;
  out.depth = dims >= 3 ? b.depth - 2 * b.border : 1;
  out.base_level = p.base_level;
  out.max_level = q;
  out.faces = faces;
  for (int f = 0; f < faces; ++f) {
    for (int l = p.base_level; l <= q; ++l) {
      const TexImage& im = tex.images[f][l];
      SamplerLevel& sl = out.levels[f][l];
      sl.rgba = im.rgba.empty() ? nullptr : im.rgba.data();
      sl.z = im.z.empty() ? nullptr : im.z.data();
      sl.z_max = depth_texel_max(im.depth_size);
      sl.width = im.width;
      sl.height = dims >= 2 ? im.height : 1;
      sl.depth = dims >= 3 ? im.depth : 1;
    }
  }
  out.min_filter = p.min_filter;
  out.mag_filter = p.mag_filter;
  out.wrap_s = p.wrap_s;
  out.wrap_t = p.wrap_t;
  out.wrap_r = p.wrap_r;
  expand_border(out.base, b.is_depth, p.border_color, out.border_color);
  out.min_lod = p.min_lod;
  out.max_lod = p.max_lod;
  out.lod_bias = p.lod_bias;
  out.c = 0.0f;
  out.compare = b.is_depth && p.compare_mode == GL_COMPARE_R_TO_TEXTURE;
  out.compare_func = p.compare_func;
  out.quads = quad_sampling_supported(out);
  return true;
}

} // namespace pineda
