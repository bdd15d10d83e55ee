// Texture image specification (GL 2.1 §3.8.1-§3.8.3, §3.8.11): glTexImage1D/2D/3D,
// glTexSubImage1D/2D/3D, proxies, mipmap generation (§3.8.8 GENERATE_MIPMAP), and the level
// queries of §6.1.3 (glGetTexLevelParameter).
#include <algorithm>
#include <cstring>
#include <new>
#include <vector>

#include "core/api_util.h"
#include "dispatch.h"
#include "framebuffer/read_pixels.h"
#include "texture/tex_format.h"
#include "texture/tex_image.h"
#include "texture/texture_internal.h"

namespace pineda {

namespace {

// Where a target's images live: the object (bound or proxy), the face and the dimensionality.
struct ImageTarget {
  TextureObject* tex = nullptr;
  int face = 0;
  int dims = 2;
  bool proxy = false;
  int max_size = kMaxTextureSize;
  int max_levels = kMaxTexLevels;
  bool cube = false;
};

// Resolves an image target of a glTexImage{dims}D-style command; false for a target that
// command does not take (INVALID_ENUM).
bool image_target(Context* ctx, GLenum target, int dims, ImageTarget& out) {
  out = ImageTarget{};
  out.dims = dims;
  int ti = -1;
  switch (target) {
  case GL_TEXTURE_1D:
    ti = dims == 1 ? kTex1D : -1;
    break;
  case GL_PROXY_TEXTURE_1D:
    ti = dims == 1 ? kTex1D : -1, out.proxy = true;
    break;
  case GL_TEXTURE_2D:
    ti = dims == 2 ? kTex2D : -1;
    break;
  case GL_PROXY_TEXTURE_2D:
    ti = dims == 2 ? kTex2D : -1, out.proxy = true;
    break;
  case GL_TEXTURE_3D:
    ti = dims == 3 ? kTex3D : -1;
    break;
  case GL_PROXY_TEXTURE_3D:
    ti = dims == 3 ? kTex3D : -1, out.proxy = true;
    break;
  case GL_PROXY_TEXTURE_CUBE_MAP:
    ti = dims == 2 ? kTexCube : -1, out.proxy = true, out.cube = true;
    break;
  case GL_TEXTURE_CUBE_MAP_POSITIVE_X:
  case GL_TEXTURE_CUBE_MAP_NEGATIVE_X:
  case GL_TEXTURE_CUBE_MAP_POSITIVE_Y:
  case GL_TEXTURE_CUBE_MAP_NEGATIVE_Y:
  case GL_TEXTURE_CUBE_MAP_POSITIVE_Z:
  case GL_TEXTURE_CUBE_MAP_NEGATIVE_Z:
    ti = dims == 2 ? kTexCube : -1;
    out.face = static_cast<int>(target - GL_TEXTURE_CUBE_MAP_POSITIVE_X);
    out.cube = true;
    break;
  default:
    break;
  }
  if (ti < 0) return false;
  out.tex = out.proxy ? ctx->texobj.proxies[ti].get() : active_texture_object(ctx, ti);
  if (ti == kTex3D) {
    out.max_size = kMax3DTextureSize;
    out.max_levels = kMax3DTexLevels;
  } else if (ti == kTexCube) {
    out.max_size = kMaxCubeTextureSize;
  }
  return true;
}

// Unpacked groups of a client image as RGBA floats (colour) or depth floats.
// (Temporary: UNSIGNED_BYTE and FLOAT only until the pixel unpack module exists.)
int format_components_for_unpack(GLenum format) {
  return pixel_format_components(format);
}

bool unpack_supported(GLenum format, GLenum type) {
  (void)format;
  return type == GL_UNSIGNED_BYTE || type == GL_FLOAT;
}

void unpack_groups(const Context* ctx, const void* pixels, int w, int h, int d, GLenum format,
                   GLenum type, bool depth, float* out) {
  const PixelStore& ps = ctx->unpack;
  const int comps = format_components_for_unpack(format);
  const size_t elem = type == GL_FLOAT ? 4 : 1;
  const size_t group = size_t(comps) * elem;
  const size_t row = packed_row_stride(w, format, type, ps);
  const size_t image = row * size_t(ps.image_height > 0 ? ps.image_height : h);
  const uint8_t* base = static_cast<const uint8_t*>(pixels) + size_t(ps.skip_images) * image +
                        size_t(ps.skip_rows) * row + size_t(ps.skip_pixels) * group;
  for (int k = 0; k < d; ++k) {
    for (int j = 0; j < h; ++j) {
      const uint8_t* p = base + size_t(k) * image + size_t(j) * row;
      for (int i = 0; i < w; ++i, p += group) {
        float c[4];
        for (int q = 0; q < comps; ++q) {
          if (type == GL_FLOAT) {
            std::memcpy(&c[q], p + 4 * q, 4);
          } else {
            c[q] = p[q] * (1.0f / 255.0f);
          }
        }
        if (depth) {
          *out++ = c[0];
          continue;
        }
        float rgba[4] = {0, 0, 0, 1};
        switch (format) {
        case GL_RED:
          rgba[0] = c[0];
          break;
        case GL_GREEN:
          rgba[1] = c[0];
          break;
        case GL_BLUE:
          rgba[2] = c[0];
          break;
        case GL_ALPHA:
          rgba[3] = c[0];
          break;
        case GL_LUMINANCE:
          rgba[0] = rgba[1] = rgba[2] = c[0];
          break;
        case GL_LUMINANCE_ALPHA:
          rgba[0] = rgba[1] = rgba[2] = c[0], rgba[3] = c[1];
          break;
        case GL_RGB:
          rgba[0] = c[0], rgba[1] = c[1], rgba[2] = c[2];
          break;
        case GL_BGR:
          rgba[0] = c[2], rgba[1] = c[1], rgba[2] = c[0];
          break;
        case GL_RGBA:
          rgba[0] = c[0], rgba[1] = c[1], rgba[2] = c[2], rgba[3] = c[3];
          break;
        case GL_BGRA:
          rgba[0] = c[2], rgba[1] = c[1], rgba[2] = c[0], rgba[3] = c[3];
          break;
        default:
          break;
        }
        for (int q = 0; q < 4; ++q)
          *out++ = rgba[q];
      }
    }
  }
}

// §3.8.1: the format/type pair's error for a texture image of `info`'s kind.
GLenum format_type_error(GLenum format, GLenum type) {
  if (format == GL_DEPTH_COMPONENT) {
    if (!is_valid_type(type) || type == GL_BITMAP) return GL_INVALID_ENUM;
    if (is_packed_pixel_type(type)) return GL_INVALID_OPERATION;
    return GL_NO_ERROR;
  }
  if (format == GL_STENCIL_INDEX || format == GL_COLOR_INDEX) return GL_INVALID_ENUM;
  return read_format_type_error(format, type);
}

bool is_pot(int v) {
  return v > 0 && (v & (v - 1)) == 0;
}

// Resets an image to the unspecified state (§3.8.11: a failed proxy query reads back zeros).
void clear_image(TexImage& im) {
  im = TexImage{};
}

void set_image_info(TexImage& im, GLint internalformat, const TexFormatInfo& f, int w, int h, int d,
                    int border) {
  im.width = w, im.height = h, im.depth = d, im.border = border;
  im.internal_format = static_cast<GLenum>(internalformat);
  im.base = f.base;
  im.is_depth = f.depth;
  im.red_size = f.r, im.green_size = f.g, im.blue_size = f.b, im.alpha_size = f.a;
  im.luminance_size = f.l, im.intensity_size = f.i, im.depth_size = f.d;
}

} // namespace

// Fills levels base+1 .. q from level base (§3.8.8 "Automatic Mipmap Generation"), each level
// from the previous one with the filtering llvmpipe's blit uses (see downsample_image).
void generate_mipmaps(TextureObject& tex, int face, int dims) {
  const int base = tex.params.base_level;
  if (base < 0 || base >= kMaxTexLevels) return;
  const TexImage& b = tex.images[face][base];
  if (b.width == 0) return;
  const int max_levels = tex.target == GL_TEXTURE_3D ? kMax3DTexLevels : kMaxTexLevels;
  for (int level = base + 1; level < max_levels && level <= tex.params.max_level; ++level) {
    const TexImage& src = tex.images[face][level - 1];
    const int bw = src.border;
    const int sw = src.width - 2 * bw, sh = src.height - 2 * bw, sd = src.depth - 2 * bw;
    if (sw <= 1 && (dims < 2 || sh <= 1) && (dims < 3 || sd <= 1)) break;
    TexImage& dst = tex.images[face][level];
    const int w = std::max(1, sw / 2) + 2 * bw;
    const int h = dims >= 2 ? std::max(1, sh / 2) + 2 * bw : 1;
    const int d = dims >= 3 ? std::max(1, sd / 2) + 2 * bw : 1;
    TexImage next;
    next = src;
    next.rgba.clear();
    next.z.clear();
    next.width = w, next.height = h, next.depth = d;
    downsample_image(src, next, dims);
    dst = std::move(next);
  }
}

namespace {

// The body of glTexImage1D/2D/3D.
void tex_image(const char* func, int dims, GLenum target, GLint level, GLint internalformat,
               GLsizei width, GLsizei height, GLsizei depth, GLint border, GLenum format,
               GLenum type, const void* pixels) {
  PINEDA_CTX_OUTSIDE(func);
  ImageTarget it;
  if (!image_target(ctx, target, dims, it)) return record_error(ctx, GL_INVALID_ENUM, func, target);
  const GLenum fe = format_type_error(format, type);
  if (fe == GL_INVALID_ENUM) return record_error(ctx, fe, func, format);
  if (level < 0 || level >= it.max_levels) return record_error(ctx, GL_INVALID_VALUE, func);
  TexFormatInfo info;
  if (!lookup_internal_format(internalformat, info))
    return record_error(ctx, GL_INVALID_VALUE, func);
  if (border != 0 && border != 1) return record_error(ctx, GL_INVALID_VALUE, func);
  if (dims < 2) height = 1;
  if (dims < 3) depth = 1;
  const int bb = dims >= 1 ? 2 * border : 0;
  if (width < bb || (dims >= 2 && height < bb) || (dims >= 3 && depth < bb))
    return record_error(ctx, GL_INVALID_VALUE, func);
  if (it.cube && width != height) return record_error(ctx, GL_INVALID_VALUE, func);
  if (fe != GL_NO_ERROR) return record_error(ctx, fe, func);
  // §3.8.1: depth formats go only with 1D and 2D targets, and with DEPTH_COMPONENT data.
  if (info.depth && (dims == 3 || it.cube)) return record_error(ctx, GL_INVALID_OPERATION, func);
  if (info.depth != (format == GL_DEPTH_COMPONENT))
    return record_error(ctx, GL_INVALID_OPERATION, func);
  if (!unpack_supported(format, type)) return record_error(ctx, GL_INVALID_ENUM, func, type);
  // Sizes the implementation supports at this level (Table 6.36 limits).
  const int limit = it.max_size >> level;
  const bool fits = width - bb <= limit && (dims < 2 || height - bb <= limit) &&
                    (dims < 3 || depth - bb <= limit);
  const int w = dims >= 1 ? width : 1, h = dims >= 2 ? height : 1, d = dims >= 3 ? depth : 1;
  if (it.proxy) {
    TexImage& im = it.tex->images[it.face][level];
    if (fits) {
      set_image_info(im, internalformat, info, w, h, d, border);
    } else {
      clear_image(im);
    }
    if (it.cube)
      for (int f = 0; f < 6; ++f)
        it.tex->images[f][level] = TexImage(im);
    return;
  }
  if (!fits) return record_error(ctx, GL_INVALID_VALUE, func);
  (void)is_pot;

  // Build the new image completely before touching the object (OUT_OF_MEMORY changes nothing).
  TexImage im;
  set_image_info(im, internalformat, info, w, h, d, border);
  const size_t count = size_t(w) * size_t(h) * size_t(d);
  try {
    if (info.depth) {
      im.z.assign(count, 0.0f);
      if (pixels != nullptr && count > 0) {
        std::vector<float> tmp(count);
        unpack_groups(ctx, pixels, w, h, d, format, type, true, tmp.data());
        depth_to_texels(info, tmp.data(), int(count), im.z.data());
      }
    } else {
      im.rgba.assign(count * 4, 0);
      if (pixels != nullptr && count > 0) {
        std::vector<float> tmp(count * 4);
        unpack_groups(ctx, pixels, w, h, d, format, type, false, tmp.data());
        rgba_to_texels(info, tmp.data(), int(count), im.rgba.data());
      }
    }
  } catch (const std::bad_alloc&) {
    return record_error(ctx, GL_OUT_OF_MEMORY, func);
  } catch (const std::length_error&) {
    return record_error(ctx, GL_OUT_OF_MEMORY, func);
  }
  TextureObject& tex = *it.tex;
  tex.images[it.face][level] = std::move(im);
  if (tex.params.generate_mipmap && level == tex.params.base_level) {
    try {
      generate_mipmaps(tex, it.face, dims);
    } catch (const std::bad_alloc&) {
      record_error(ctx, GL_OUT_OF_MEMORY, func);
    }
  }
  texture_changed(ctx);
}

} // namespace

namespace {

// glGetTexLevelParameter's image (§6.1.3): any image target and the proxies, not CUBE_MAP.
const TexImage* level_image(Context* ctx, GLenum target, GLint level, const char* func) {
  ImageTarget it;
  const int dims = target == GL_TEXTURE_1D || target == GL_PROXY_TEXTURE_1D   ? 1
                   : target == GL_TEXTURE_3D || target == GL_PROXY_TEXTURE_3D ? 3
                                                                              : 2;
  if (!image_target(ctx, target, dims, it)) {
    record_error(ctx, GL_INVALID_ENUM, func, target);
    return nullptr;
  }
  if (level < 0 || level >= it.max_levels) {
    record_error(ctx, GL_INVALID_VALUE, func);
    return nullptr;
  }
  return &it.tex->images[it.face][level];
}

// The value of `pname` for image `im` (Table 6.20); false for an unknown pname.
bool level_param(const TexImage& im, GLenum pname, GLint* v) {
  switch (pname) {
  case GL_TEXTURE_WIDTH:
    *v = im.width;
    return true;
  case GL_TEXTURE_HEIGHT:
    *v = im.height;
    return true;
  case GL_TEXTURE_DEPTH:
    *v = im.depth;
    return true;
  case GL_TEXTURE_BORDER:
    *v = im.border;
    return true;
  case GL_TEXTURE_INTERNAL_FORMAT:
    *v = GLint(im.internal_format);
    return true;
  case GL_TEXTURE_RED_SIZE:
    *v = im.red_size;
    return true;
  case GL_TEXTURE_GREEN_SIZE:
    *v = im.green_size;
    return true;
  case GL_TEXTURE_BLUE_SIZE:
    *v = im.blue_size;
    return true;
  case GL_TEXTURE_ALPHA_SIZE:
    *v = im.alpha_size;
    return true;
  case GL_TEXTURE_LUMINANCE_SIZE:
    *v = im.luminance_size;
    return true;
  case GL_TEXTURE_INTENSITY_SIZE:
    *v = im.intensity_size;
    return true;
  case GL_TEXTURE_DEPTH_SIZE:
    *v = im.depth_size;
    return true;
  case GL_TEXTURE_COMPRESSED:
    *v = GL_FALSE;
    return true;
  default:
    return false;
  }
}

} // namespace

namespace exec {

void GLAPIENTRY TexImage1D(GLenum target, GLint level, GLint internalformat, GLsizei width,
                           GLint border, GLenum format, GLenum type, const void* pixels) {
  tex_image("glTexImage1D", 1, target, level, internalformat, width, 1, 1, border, format, type,
            pixels);
}

void GLAPIENTRY TexImage2D(GLenum target, GLint level, GLint internalformat, GLsizei width,
                           GLsizei height, GLint border, GLenum format, GLenum type,
                           const void* pixels) {
  tex_image("glTexImage2D", 2, target, level, internalformat, width, height, 1, border, format,
            type, pixels);
}

void GLAPIENTRY TexImage3D(GLenum target, GLint level, GLint internalformat, GLsizei width,
                           GLsizei height, GLsizei depth, GLint border, GLenum format, GLenum type,
                           const void* pixels) {
  tex_image("glTexImage3D", 3, target, level, internalformat, width, height, depth, border, format,
            type, pixels);
}

void GLAPIENTRY GetTexLevelParameteriv(GLenum target, GLint level, GLenum pname, GLint* params) {
  PINEDA_CTX_OUTSIDE("glGetTexLevelParameteriv");
  const TexImage* im = level_image(ctx, target, level, "glGetTexLevelParameteriv");
  if (im == nullptr) return;
  GLint v = 0;
  // TEXTURE_COMPRESSED_IMAGE_SIZE exists for compressed images only, which Pineda never has.
  if (pname == GL_TEXTURE_COMPRESSED_IMAGE_SIZE)
    return record_error(ctx, GL_INVALID_OPERATION, "glGetTexLevelParameteriv");
  if (!level_param(*im, pname, &v))
    return record_error(ctx, GL_INVALID_ENUM, "glGetTexLevelParameteriv", pname);
  if (params != nullptr) *params = v;
}

void GLAPIENTRY GetTexLevelParameterfv(GLenum target, GLint level, GLenum pname, GLfloat* params) {
  PINEDA_CTX_OUTSIDE("glGetTexLevelParameterfv");
  const TexImage* im = level_image(ctx, target, level, "glGetTexLevelParameterfv");
  if (im == nullptr) return;
  GLint v = 0;
  if (pname == GL_TEXTURE_COMPRESSED_IMAGE_SIZE)
    return record_error(ctx, GL_INVALID_OPERATION, "glGetTexLevelParameterfv");
  if (!level_param(*im, pname, &v))
    return record_error(ctx, GL_INVALID_ENUM, "glGetTexLevelParameterfv", pname);
  if (params != nullptr) *params = static_cast<GLfloat>(v);
}

} // namespace exec

} // namespace pineda
