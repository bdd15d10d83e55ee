// Texture image specification from client memory (GL 2.1 §3.8.1, §3.8.2, §3.8.11):
// glTexImage1D/2D/3D, glTexSubImage1D/2D/3D, proxies, automatic mipmap generation (§3.8.8), and
// the image queries of §6.1.3-§6.1.4 (glGetTexLevelParameter, glGetTexImage).
#include "state/tex_image.h"

#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>
#include <stdexcept>
#include <vector>

#include "state/api_util.h"
#include "state/pixel_buffer.h"
#include "dispatch.h"
#include "pixel/unpack.h"
#include "state/tex_format.h"
#include "state/texture_internal.h"

namespace pineda {

namespace {

// ---- client images (src/pixel/unpack.h) ----

// The format/type error of a texture image command (§3.8.1): unknown enums and STENCIL_INDEX
// are INVALID_ENUM; packed types with the wrong format INVALID_OPERATION. COLOR_INDEX with
// BITMAP is allowed, as for DrawPixels (§3.8.1 excludes only STENCIL_INDEX): each bit is an
// index that the I_TO_R .. I_TO_A maps turn into RGBA (§3.6.5).
GLenum client_format_type_error(GLenum format, GLenum type) {
  if (format == GL_STENCIL_INDEX) return GL_INVALID_ENUM;
  return check_pixel_format_type(format, type);
}

// §3.8.1 as GL 3.3 words it with EXT_packed_depth_stencil: images of a DEPTH_COMPONENT or
// DEPTH_STENCIL base format take DEPTH_COMPONENT or DEPTH_STENCIL data (a depth image keeps
// the depth of DEPTH_STENCIL groups; a depth-stencil image given depth alone keeps its
// stencil), other images neither (INVALID_OPERATION otherwise).
bool format_matches(bool depth, GLenum format) {
  const bool depth_data = format == GL_DEPTH_COMPONENT || format == GL_DEPTH_STENCIL;
  return depth == depth_data;
}

// STENCIL_INDEX data is INVALID_ENUM for texture images (§3.8.1), except for depth images,
// where the mismatch of base format and data is the error (INVALID_OPERATION), as GL 3.3 and
// Mesa order them.
GLenum stencil_data_error(bool depth) {
  return depth ? GL_INVALID_OPERATION : GL_INVALID_ENUM;
}

// 1D and 2D images ignore IMAGE_HEIGHT and SKIP_IMAGES (§3.8.1).
PixelStore store_for(const PixelStore& st, int dims) {
  return dims == 3 ? st : store_2d(st);
}

// Unpacks a w x h x d client image into the region of `im` at border-relative (x, y, z), one
// image slice at a time, with the pixel transfer operations (§3.8.1: as DrawPixels, up to the
// final expansion to RGBA). May throw std::bad_alloc.
// RGBA unsigned bytes into an image of 8-bit RGBA texels with no pixel transfer operation on:
// each component c goes to c / 255 (Table 2.9) and back to round(c / 255 * 255) = c (checked
// for all 256 values in float), so the rows are copied as they are.
bool copy_rgba8(const Context* ctx, TexImage& im, int dims, int x, int y, int z, int w, int h,
                int d, GLenum format, GLenum type, const void* pixels) {
  if (im.is_depth || format != GL_RGBA || type != GL_UNSIGNED_BYTE || im.base != TexBase::RGBA ||
      im.red_size != 8 || im.green_size != 8 || im.blue_size != 8 || im.alpha_size != 8 ||
      rgba_transfer_active(pixel_transfer_view(ctx)))
    return false;
  PixelStore st = store_for(ctx->pixel_store.unpack, dims);
  const int skip = st.skip_images;
  const int bi = im.border, bj = dims >= 2 ? im.border : 0, bk = dims >= 3 ? im.border : 0;
  const uint8_t* src = static_cast<const uint8_t*>(pixels);
  for (int k = 0; k < d; ++k) {
    st.skip_images = skip + k;
    ClientLayout l;
    if (!client_layout(w, h, format, type, st, l)) return false;
    for (int j = 0; j < h; ++j) {
      const size_t idx =
          (size_t(z + k + bk) * size_t(im.height) + size_t(y + j + bj)) * size_t(im.width) +
          size_t(x + bi);
      std::memcpy(&im.rgba[idx * 4], src + l.row_offset(j, 0), size_t(w) * 4);
    }
  }
  return true;
}

void unpack_into(const Context* ctx, TexImage& im, int dims, int x, int y, int z, int w, int h,
                 int d, GLenum format, GLenum type, const void* pixels) {
  if (copy_rgba8(ctx, im, dims, x, y, z, w, h, d, format, type, pixels)) return;
  PixelStore st = store_for(ctx->pixel_store.unpack, dims);
  std::vector<float> tmp(size_t(w) * size_t(h) * (im.is_depth ? 1 : 4));
  const int skip = st.skip_images;
  if (format == GL_DEPTH_STENCIL) {
    // EXT_packed_depth_stencil: depth and stencil of each group.
    std::vector<uint32_t> s(tmp.size());
    for (int k = 0; k < d; ++k) {
      st.skip_images = skip + k;
      unpack_depth_stencil(pixels, w, h, 1, st, pixel_transfer_view(ctx), tmp.data(), s.data());
      store_region(im, dims, x, y, z + k, w, h, 1, tmp.data());
      store_stencil_region(im, dims, x, y, z + k, w, h, s.data());
    }
    return;
  }
  for (int k = 0; k < d; ++k) {
    st.skip_images = skip + k;
    if (im.is_depth)
      unpack_depth(pixels, w, h, 1, type, st, pixel_transfer_view(ctx), tmp.data());
    else
      unpack_rgba(pixels, w, h, 1, format, type, st, pixel_transfer_view(ctx), tmp.data());
    store_region(im, dims, x, y, z + k, w, h, 1, tmp.data());
  }
}

// Packs RGBA or depth floats into client memory per the pack state (§6.1.4, §4.3.2).
void pack_groups(const Context* ctx, const float* in, int w, int h, int d, int dims, GLenum format,
                 GLenum type, void* pixels) {
  const PixelStore st = store_for(ctx->pixel_store.pack, dims);
  if (format == GL_DEPTH_STENCIL) {
    // `in` holds w*h*d depths followed by as many stencil indices (as floats).
    const size_t n = size_t(w) * size_t(h) * size_t(d);
    std::vector<uint32_t> s(n);
    for (size_t i = 0; i < n; ++i)
      s[i] = uint32_t(in[n + i]);
    pack_depth_stencil(in, s.data(), w, h, d, st, pixels);
  } else if (format == GL_DEPTH_COMPONENT)
    pack_depth(in, w, h, d, type, st, pixels);
  else
    pack_rgba(in, w, h, d, format, type, st, pixels);
}

// ---- image commands ----

// Resets an image to the unspecified state (§3.8.11: a failed proxy query reads back zeros).
void clear_image(TexImage& im) {
  im = TexImage{};
}

// The body of glTexImage1D/2D/3D (§3.8.1).
void tex_image(const char* func, int dims, GLenum target, GLint level, GLint internalformat,
               GLsizei width, GLsizei height, GLsizei depth, GLint border, GLenum format,
               GLenum type, const void* pixels) {
  PINEDA_CTX_OUTSIDE(func);
  ImageTarget it;
  if (!image_target(ctx, target, dims, true, it))
    return record_error(ctx, GL_INVALID_ENUM, func, target);
  if (format == GL_STENCIL_INDEX) {
    TexFormatInfo f;
    const bool depth_image = lookup_internal_format(internalformat, f) && f.depth;
    return record_error(ctx, stencil_data_error(depth_image), func, format);
  }
  const GLenum fe = client_format_type_error(format, type);
  if (fe == GL_INVALID_ENUM) return record_error(ctx, fe, func, format);
  if (level < 0 || level >= it.max_levels) return record_error(ctx, GL_INVALID_VALUE, func);
  TexFormatInfo info;
  if (!lookup_internal_format(internalformat, info))
    return record_error(ctx, GL_INVALID_VALUE, func);
  if (border != 0 && border != 1) return record_error(ctx, GL_INVALID_VALUE, func);
  if (dims < 2) height = 1;
  if (dims < 3) depth = 1;
  const int bb = 2 * border;
  if (width < bb || (dims >= 2 && height < bb) || (dims >= 3 && depth < bb))
    return record_error(ctx, GL_INVALID_VALUE, func);
  if (it.cube && width != height) return record_error(ctx, GL_INVALID_VALUE, func);
  if (fe != GL_NO_ERROR) return record_error(ctx, fe, func);
  // §3.8.1: depth formats go only with 1D and 2D targets, and with DEPTH_COMPONENT data.
  if (info.depth && (dims == 3 || it.cube)) return record_error(ctx, GL_INVALID_OPERATION, func);
  if (!format_matches(info.depth, format)) return record_error(ctx, GL_INVALID_OPERATION, func);
  // The sizes the implementation supports at this level (§3.8.1, Table 6.36 limits).
  const int limit = it.max_size >> level;
  const bool fits = width - bb <= limit && (dims < 2 || height - bb <= limit) &&
                    (dims < 3 || depth - bb <= limit);
  const int w = width, h = height, d = depth;
  // Storage beyond kMaxTextureImageBytes is refused as memory the implementation lacks:
  // OUT_OF_MEMORY for an image, an unsupported proxy (§3.8.11).
  const bool affordable = uint64_t(w) * uint64_t(h) * uint64_t(d) * 4u <= kMaxTextureImageBytes;
  if (it.proxy) {
    // §3.8.11: a proxy records the image's state when supported, zeros otherwise.
    TexImage& im = it.tex->images[it.face][level];
    if (fits && affordable)
      set_image_info(im, GLenum(internalformat), info, w, h, d, border);
    else
      clear_image(im);
    if (it.cube)
      for (int f = 1; f < 6; ++f)
        it.tex->images[f][level] = im;
    return;
  }
  if (!fits) return record_error(ctx, GL_INVALID_VALUE, func);
  if (!affordable) return record_error(ctx, GL_OUT_OF_MEMORY, func);

  // The new image is built completely before the object changes: OUT_OF_MEMORY changes
  // nothing (§2.5).
  TexImage im;
  set_image_info(im, GLenum(internalformat), info, w, h, d, border);
  const size_t count = size_t(w) * size_t(h) * size_t(d);
  // §3.8.1: from the pixel unpack buffer when one is bound.
  if (!unpack_memory(
          ctx, pixels,
          client_image_bytes(w, h, d, format, type, store_for(ctx->pixel_store.unpack, dims)),
          pixel_type_unit(type), func, &pixels))
    return;
  try {
    if (info.depth) {
      im.z.assign(count, 0u);
      if (info.s != 0) im.stencil.assign(count, 0);
    } else {
      im.rgba.assign(count * 4, 0);
    }
    if (pixels != nullptr && count > 0)
      unpack_into(ctx, im, dims, -border, dims >= 2 ? -border : 0, dims >= 3 ? -border : 0, w, h, d,
                  format, type, pixels);
  } catch (const std::bad_alloc&) {
    return record_error(ctx, GL_OUT_OF_MEMORY, func);
  } catch (const std::length_error&) {
    return record_error(ctx, GL_OUT_OF_MEMORY, func);
  }
  it.tex->images[it.face][level] = std::move(im);
  image_changed(ctx, *it.tex, it.face, level, dims, func);
}

// The body of glTexSubImage1D/2D/3D (§3.8.2).
void tex_sub_image(const char* func, int dims, GLenum target, GLint level, GLint x, GLint y,
                   GLint z, GLsizei w, GLsizei h, GLsizei d, GLenum format, GLenum type,
                   const void* pixels) {
  PINEDA_CTX_OUTSIDE(func);
  ImageTarget it;
  if (!image_target(ctx, target, dims, false, it))
    return record_error(ctx, GL_INVALID_ENUM, func, target);
  const GLenum fe = client_format_type_error(format, type);
  if (fe == GL_INVALID_ENUM && format != GL_STENCIL_INDEX)
    return record_error(ctx, fe, func, format);
  TexImage* im = sub_image_target(ctx, func, it, level, x, y, z, w, h, d);
  if (im == nullptr) return;
  if (format == GL_STENCIL_INDEX) return record_error(ctx, stencil_data_error(im->is_depth), func);
  if (fe != GL_NO_ERROR) return record_error(ctx, fe, func);
  if (!format_matches(im->is_depth, format)) return record_error(ctx, GL_INVALID_OPERATION, func);
  const size_t count = size_t(w) * size_t(h) * size_t(d);
  if (count == 0) return;
  // §3.8.2: from the pixel unpack buffer when one is bound.
  if (!unpack_memory(
          ctx, pixels,
          client_image_bytes(w, h, d, format, type, store_for(ctx->pixel_store.unpack, dims)),
          pixel_type_unit(type), func, &pixels))
    return;
  if (pixels == nullptr) return;
  try {
    unpack_into(ctx, *im, dims, x, y, z, w, h, d, format, type, pixels);
  } catch (const std::bad_alloc&) {
    return record_error(ctx, GL_OUT_OF_MEMORY, func);
  }
  image_changed(ctx, *it.tex, it.face, level, dims, func);
}

int dims_of_query_target(GLenum target) {
  switch (target) {
  case GL_TEXTURE_1D:
  case GL_PROXY_TEXTURE_1D:
    return 1;
  case GL_TEXTURE_3D:
  case GL_PROXY_TEXTURE_3D:
    return 3;
  default:
    return 2;
  }
}

// glGetTexLevelParameter's image (§6.1.3): any image target and the proxies, not CUBE_MAP.
const TexImage* level_image(Context* ctx, GLenum target, GLint level, const char* func) {
  ImageTarget it;
  if (!image_target(ctx, target, dims_of_query_target(target), true, it)) {
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
  case GL_TEXTURE_STENCIL_SIZE: // EXT_packed_depth_stencil
    *v = im.stencil_size;
    return true;
  case GL_TEXTURE_COMPRESSED:
    *v = GL_FALSE;
    return true;
  default:
    return false;
  }
}

bool level_query(Context* ctx, GLenum target, GLint level, GLenum pname, GLint* v,
                 const char* func) {
  const TexImage* im = level_image(ctx, target, level, func);
  if (im == nullptr) return false;
  // TEXTURE_COMPRESSED_IMAGE_SIZE exists for compressed images only, which Pineda never has.
  if (pname == GL_TEXTURE_COMPRESSED_IMAGE_SIZE) {
    record_error(ctx, GL_INVALID_OPERATION, func);
    return false;
  }
  if (!level_param(*im, pname, v)) {
    record_error(ctx, GL_INVALID_ENUM, func, pname);
    return false;
  }
  return true;
}

} // namespace

bool image_target(Context* ctx, GLenum target, int dims, bool allow_proxy, ImageTarget& out) {
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
  if (ti < 0 || (out.proxy && !allow_proxy)) return false;
  out.tex = out.proxy ? ctx->texobj.proxies[ti].get() : active_texture_object(ctx, ti);
  out.max_size = ti == kTex3D     ? kMax3DTextureSize
                 : ti == kTexCube ? kMaxCubeTextureSize
                                  : kMaxTextureSize;
  out.max_levels = ti == kTex3D ? kMax3DTexLevels : kMaxTexLevels;
  return true;
}

void set_image_info(TexImage& im, GLenum internalformat, const TexFormatInfo& f, int w, int h,
                    int d, int border) {
  im.width = w, im.height = h, im.depth = d, im.border = border;
  im.internal_format = uncompressed_internal_format(internalformat); // §3.8.1
  im.base = f.base;
  im.is_depth = f.depth;
  im.srgb = f.srgb;
  im.red_size = f.r, im.green_size = f.g, im.blue_size = f.b, im.alpha_size = f.a;
  im.luminance_size = f.l, im.intensity_size = f.i, im.depth_size = f.d;
  im.stencil_size = f.s;
}

void image_changed(Context* ctx, TextureObject& tex, int face, int level, int dims,
                   const char* func) {
  if (tex.params.generate_mipmap && level == tex.params.base_level) {
    try {
      generate_mipmaps(tex, face, dims);
    } catch (const std::bad_alloc&) {
      record_error(ctx, GL_OUT_OF_MEMORY, func);
    }
  }
  texture_changed(ctx);
}

TexImage* sub_image_target(Context* ctx, const char* func, const ImageTarget& it, GLint level,
                           int x, int y, int z, int w, int h, int d) {
  if (level < 0 || level >= it.max_levels) {
    record_error(ctx, GL_INVALID_VALUE, func);
    return nullptr;
  }
  TexImage& im = it.tex->images[it.face][level];
  const int dims = it.dims;
  if (w < 0 || (dims >= 2 && h < 0) || (dims >= 3 && d < 0)) {
    record_error(ctx, GL_INVALID_VALUE, func);
    return nullptr;
  }
  if (im.width == 0) {
    record_error(ctx, GL_INVALID_OPERATION, func);
    return nullptr;
  }
  // §3.8.2: the region must lie within the image, border included.
  const int b = im.border;
  const auto outside = [b](int off, int size, int full) {
    return off < -b || int64_t(off) + size > int64_t(full) - b;
  };
  if (outside(x, w, im.width) || (dims >= 2 && outside(y, h, im.height)) ||
      (dims >= 3 && outside(z, d, im.depth))) {
    record_error(ctx, GL_INVALID_VALUE, func);
    return nullptr;
  }
  return &im;
}

void store_region(TexImage& im, int dims, int x, int y, int z, int w, int h, int d,
                  const float* groups) {
  TexFormatInfo f;
  lookup_internal_format(GLint(im.internal_format), f);
  const int bi = im.border, bj = dims >= 2 ? im.border : 0, bk = dims >= 3 ? im.border : 0;
  for (int k = 0; k < d; ++k) {
    for (int j = 0; j < h; ++j) {
      const size_t idx =
          (size_t(z + k + bk) * size_t(im.height) + size_t(y + j + bj)) * size_t(im.width) +
          size_t(x + bi);
      const size_t g = (size_t(k) * size_t(h) + size_t(j)) * size_t(w);
      if (im.is_depth)
        depth_to_texels(f, groups + g, w, &im.z[idx]);
      else
        rgba_to_texels(f, groups + g * 4, w, &im.rgba[idx * 4]);
    }
  }
}

namespace {

// GL 2.1 §3.8.15: a linear value encoded as an 8-bit sRGB component (the inverse of eq. 3.28).
uint8_t encode_srgb8(float linear) {
  const double c = std::clamp(static_cast<double>(linear), 0.0, 1.0);
  const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
  return static_cast<uint8_t>(std::lround(s * 255.0));
}

// The next level of an sRGB image: each texel the bilinear (trilinear) sample of the decoded
// source at its centre (for halved power-of-two sizes the 2x2 (2x2x2) box), encoded again, so
// a level keeps the brightness of the one above (§3.8.8 leaves the filter open; Mesa filters
// sRGB levels in linear space too). Alpha is linear. Border texels come from the source border.
void downsample_srgb(const TexImage& src, TexImage& dst, int dims) {
  const float* lin = srgb_decode_table();
  const int b = src.border, bj = dims >= 2 ? b : 0, bk = dims >= 3 ? b : 0;
  const int ss[3] = {src.width - 2 * b, src.height - 2 * bj, src.depth - 2 * bk};
  const int ds[3] = {dst.width - 2 * b, dst.height - 2 * bj, dst.depth - 2 * bk};
  struct Ax {
    int i0, i1;
    float w;
  };
  const auto axis = [](int i, int dsize, int ssize) {
    if (i < 0) return Ax{-1, -1, 0.0f};
    if (i >= dsize) return Ax{ssize, ssize, 0.0f};
    const float u =
        std::clamp((float(i) + 0.5f) * float(ssize) / float(dsize) - 0.5f, 0.0f, float(ssize - 1));
    const int i0 = static_cast<int>(u);
    return Ax{i0, std::min(i0 + 1, ssize - 1), u - float(i0)};
  };
  const auto at = [&](int i, int j, int k) {
    return &src.rgba[((size_t(k + bk) * size_t(src.height) + size_t(j + bj)) * size_t(src.width) +
                      size_t(i + b)) *
                     4];
  };
  size_t o = 0;
  for (int k = -bk; k < ds[2] + bk; ++k) {
    const Ax ak = dims >= 3 ? axis(k, ds[2], ss[2]) : Ax{0, 0, 0.0f};
    for (int j = -bj; j < ds[1] + bj; ++j) {
      const Ax aj = dims >= 2 ? axis(j, ds[1], ss[1]) : Ax{0, 0, 0.0f};
      for (int i = -b; i < ds[0] + b; ++i, ++o) {
        const Ax ai = axis(i, ds[0], ss[0]);
        float acc[4] = {};
        for (int kk = 0; kk < (dims >= 3 ? 2 : 1); ++kk)
          for (int jj = 0; jj < (dims >= 2 ? 2 : 1); ++jj)
            for (int ii = 0; ii < 2; ++ii) {
              const float w = (ii ? ai.w : 1.0f - ai.w) *
                              (dims >= 2 ? (jj ? aj.w : 1.0f - aj.w) : 1.0f) *
                              (dims >= 3 ? (kk ? ak.w : 1.0f - ak.w) : 1.0f);
              const uint8_t* t = at(ii ? ai.i1 : ai.i0, jj ? aj.i1 : aj.i0, kk ? ak.i1 : ak.i0);
              for (int c = 0; c < 3; ++c)
                acc[c] += w * lin[t[c]];
              acc[3] += w * (t[3] * (1.0f / 255.0f));
            }
        for (int c = 0; c < 3; ++c)
          dst.rgba[o * 4 + c] = encode_srgb8(acc[c]);
        dst.rgba[o * 4 + 3] =
            static_cast<uint8_t>(std::lround(std::clamp(acc[3], 0.0f, 1.0f) * 255.0f));
      }
    }
  }
}

} // namespace

void store_stencil_region(TexImage& im, int dims, int x, int y, int z, int w, int h,
                          const uint32_t* s) {
  if (im.stencil.empty()) return;
  const int bi = im.border, bj = dims >= 2 ? im.border : 0, bk = dims >= 3 ? im.border : 0;
  for (int j = 0; j < h; ++j) {
    const size_t idx =
        (size_t(z + bk) * size_t(im.height) + size_t(y + j + bj)) * size_t(im.width) +
        size_t(x + bi);
    for (int i = 0; i < w; ++i)
      im.stencil[idx + size_t(i)] = uint8_t(s[size_t(j) * size_t(w) + size_t(i)] & 0xffu);
  }
}

void downsample_image(const TexImage& src, TexImage& dst, int dims) {
  const size_t count = size_t(dst.width) * size_t(dst.height) * size_t(dst.depth);
  TexelImage from, to;
  from.width = src.width, from.height = src.height, from.depth = src.depth;
  from.border = src.border;
  from.is_depth = src.is_depth;
  to.width = dst.width, to.height = dst.height, to.depth = dst.depth;
  to.border = dst.border;
  if (src.is_depth) {
    dst.z.assign(count, 0u);
    from.z = src.z.data();
    from.z_max = depth_texel_max(src.depth_size);
    to.z_out = dst.z.data();
  } else if (src.srgb) {
    dst.rgba.assign(count * 4, 0);
    return downsample_srgb(src, dst, dims);
  } else {
    dst.rgba.assign(count * 4, 0);
    from.rgba = src.rgba.data();
    to.rgba_out = dst.rgba.data();
  }
  downsample_texels(from, to, dims);
  if (!src.stencil.empty()) {
    // Stencil indices are not filtered: each texel takes its source's nearest one.
    dst.stencil.assign(count, 0);
    for (int k = 0; k < dst.depth; ++k)
      for (int j = 0; j < dst.height; ++j)
        for (int i = 0; i < dst.width; ++i) {
          const int si = std::min(src.width - 1, i * src.width / std::max(dst.width, 1));
          const int sj = std::min(src.height - 1, j * src.height / std::max(dst.height, 1));
          const int sk = std::min(src.depth - 1, k * src.depth / std::max(dst.depth, 1));
          dst.stencil[(size_t(k) * size_t(dst.height) + size_t(j)) * size_t(dst.width) +
                      size_t(i)] =
              src.stencil[(size_t(sk) * size_t(src.height) + size_t(sj)) * size_t(src.width) +
                          size_t(si)];
        }
  }
}

void generate_mipmaps(TextureObject& tex, int face, int dims) {
  const int base = tex.params.base_level;
  if (base < 0 || base >= kMaxTexLevels) return;
  if (tex.images[face][base].width == 0) return;
  const int max_levels = dims == 3 ? kMax3DTexLevels : kMaxTexLevels;
  for (int level = base + 1; level < max_levels; ++level) {
    const TexImage& src = tex.images[face][level - 1];
    const int b = src.border, bj = dims >= 2 ? b : 0, bk = dims >= 3 ? b : 0;
    const int sw = src.width - 2 * b, sh = src.height - 2 * bj, sd = src.depth - 2 * bk;
    if (sw <= 1 && sh <= 1 && sd <= 1) break;
    TexImage next;
    TexFormatInfo f;
    lookup_internal_format(GLint(src.internal_format), f);
    set_image_info(next, src.internal_format, f, std::max(1, sw / 2) + 2 * b,
                   std::max(1, sh / 2) + 2 * bj, std::max(1, sd / 2) + 2 * bk, b);
    downsample_image(src, next, dims);
    tex.images[face][level] = std::move(next);
  }
}

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

void GLAPIENTRY TexSubImage1D(GLenum target, GLint level, GLint xoffset, GLsizei width,
                              GLenum format, GLenum type, const void* pixels) {
  tex_sub_image("glTexSubImage1D", 1, target, level, xoffset, 0, 0, width, 1, 1, format, type,
                pixels);
}

void GLAPIENTRY TexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                              GLsizei width, GLsizei height, GLenum format, GLenum type,
                              const void* pixels) {
  tex_sub_image("glTexSubImage2D", 2, target, level, xoffset, yoffset, 0, width, height, 1, format,
                type, pixels);
}

void GLAPIENTRY TexSubImage3D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                              GLint zoffset, GLsizei width, GLsizei height, GLsizei depth,
                              GLenum format, GLenum type, const void* pixels) {
  tex_sub_image("glTexSubImage3D", 3, target, level, xoffset, yoffset, zoffset, width, height,
                depth, format, type, pixels);
}

void GLAPIENTRY GetTexLevelParameteriv(GLenum target, GLint level, GLenum pname, GLint* params) {
  PINEDA_CTX_OUTSIDE("glGetTexLevelParameteriv");
  GLint v = 0;
  if (level_query(ctx, target, level, pname, &v, "glGetTexLevelParameteriv") && params) *params = v;
}

void GLAPIENTRY GetTexLevelParameterfv(GLenum target, GLint level, GLenum pname, GLfloat* params) {
  PINEDA_CTX_OUTSIDE("glGetTexLevelParameterfv");
  GLint v = 0;
  if (level_query(ctx, target, level, pname, &v, "glGetTexLevelParameterfv") && params)
    *params = static_cast<GLfloat>(v);
}

// §6.1.4: the image as RGBA (Table 6.1) or depth values, packed per the pack state.
void GLAPIENTRY GetTexImage(GLenum target, GLint level, GLenum format, GLenum type, void* pixels) {
  PINEDA_CTX_OUTSIDE("glGetTexImage");
  const int dims = dims_of_query_target(target);
  ImageTarget it;
  if (!image_target(ctx, target, dims, false, it))
    return record_error(ctx, GL_INVALID_ENUM, "glGetTexImage", target);
  // §6.1.4: no index formats for reading back texture images.
  const GLenum fe =
      format == GL_COLOR_INDEX ? GL_INVALID_ENUM : client_format_type_error(format, type);
  if (fe == GL_INVALID_ENUM) return record_error(ctx, fe, "glGetTexImage", format);
  if (level < 0 || level >= it.max_levels)
    return record_error(ctx, GL_INVALID_VALUE, "glGetTexImage");
  if (fe != GL_NO_ERROR) return record_error(ctx, fe, "glGetTexImage");
  const TexImage& im = it.tex->images[it.face][level];
  if (im.width == 0) return;
  // A depth-stencil image reads back as DEPTH_STENCIL or as its depth alone.
  const bool ok =
      format_matches(im.is_depth, format) && (format != GL_DEPTH_STENCIL || !im.stencil.empty());
  if (!ok) return record_error(ctx, GL_INVALID_OPERATION, "glGetTexImage");
  // §6.1.4: into the pixel pack buffer when one is bound.
  if (!pack_memory(ctx, pixels,
                   client_image_bytes(im.width, im.height, im.depth, format, type,
                                      store_for(ctx->pixel_store.pack, dims)),
                   pixel_type_unit(type), "glGetTexImage", &pixels))
    return;
  if (pixels == nullptr) return;
  // What drawing wrote into an attached image is read in its base format.
  normalize_drawn_images(ctx);
  const size_t count = size_t(im.width) * size_t(im.height) * size_t(im.depth);
  try {
    std::vector<float> tmp;
    if (im.is_depth) {
      const double max = depth_texel_max(im.depth_size);
      tmp.reserve(im.z.size());
      for (const uint32_t z : im.z)
        tmp.push_back(float(double(z) / max));
      if (format == GL_DEPTH_STENCIL)
        for (const uint8_t s : im.stencil)
          tmp.push_back(float(s));
    } else {
      tmp.resize(count * 4);
      // Luminance read-backs take L from R alone (not R + G + B as ReadPixels does), as
      // llvmpipe does, so that a luminance texture reads back unchanged.
      const bool lum = format == GL_LUMINANCE || format == GL_LUMINANCE_ALPHA;
      for (size_t i = 0; i < count; ++i) {
        texel_to_rgba(im.base, &im.rgba[i * 4], &tmp[i * 4]);
        if (lum) tmp[i * 4 + 1] = tmp[i * 4 + 2] = 0.0f;
      }
    }
    pack_groups(ctx, tmp.data(), im.width, im.height, im.depth, dims, format, type, pixels);
  } catch (const std::bad_alloc&) {
    record_error(ctx, GL_OUT_OF_MEMORY, "glGetTexImage");
  }
}

// ---- GenerateMipmap (§3.8.8) ----

void GLAPIENTRY GenerateMipmap(GLenum target) {
  PINEDA_CTX_OUTSIDE("glGenerateMipmap");
  const int ti = texture_target_index(target);
  if (ti < 0) return record_error(ctx, GL_INVALID_ENUM, "glGenerateMipmap", target);
  TextureObject* tex = active_texture_object(ctx, ti);
  const int base = tex->params.base_level;
  if (base >= kMaxTexLevels) return record_error(ctx, GL_INVALID_OPERATION, "glGenerateMipmap");
  const int faces = target == GL_TEXTURE_CUBE_MAP ? 6 : 1;
  if (faces == 6) {
    // A cube map must be cube complete (§3.8.10): square base images of one size and format.
    const TexImage& first = tex->images[0][base];
    for (int f = 0; f < 6; ++f) {
      const TexImage& im = tex->images[f][base];
      if (im.width == 0 || im.width != im.height || im.width != first.width ||
          im.internal_format != first.internal_format || im.border != first.border)
        return record_error(ctx, GL_INVALID_OPERATION, "glGenerateMipmap");
    }
  }
  // What drawing wrote into the base level is read in its base format.
  normalize_drawn_images(ctx);
  try {
    for (int f = 0; f < faces; ++f)
      generate_mipmaps(*tex, f, texture_dims(target));
  } catch (const std::bad_alloc&) {
    record_error(ctx, GL_OUT_OF_MEMORY, "glGenerateMipmap");
  }
  texture_changed(ctx);
}

} // namespace exec

} // namespace pineda
