// Pixel transfer modes (GL 2.1 §3.6.3): glPixelTransfer, glPixelMap, glGetPixelMap (§6.1.3),
// glPixelZoom (§3.6.4); and the pixel area (Tables 6.23-6.27, pixel.h): its queries, the
// PIXEL_MODE group and the client pixel-store group (glPixelStore is in buffers.cpp).
#include <algorithm>
#include <cmath>

#include "state/api_util.h"
#include "state/pixel_buffer.h"
#include "dispatch.h"
#include "state/area.h"

namespace pineda {

namespace {

// GL 2.1 §3.6.3 (with §3.6.1's rules): integer parameters given as floats are rounded to the
// nearest integer, clamped to the int range first; NaN gives 0.
int round_param(double v) {
  if (std::isnan(v)) return 0;
  v = std::clamp(v, -2147483648.0, 2147483647.0);
  return static_cast<int>(v < 0 ? -std::floor(-v + 0.5) : std::floor(v + 0.5));
}

void pixel_transfer(const char* func, GLenum pname, double value) {
  PINEDA_CTX_OUTSIDE(func);
  PixelTransfer& x = ctx->pixel.transfer;
  const float f = static_cast<float>(value);
  switch (pname) {
  case GL_MAP_COLOR:
    x.map_color = value != 0.0;
    break;
  case GL_MAP_STENCIL:
    x.map_stencil = value != 0.0;
    break;
  case GL_INDEX_SHIFT:
    x.index_shift = round_param(value);
    break;
  case GL_INDEX_OFFSET:
    x.index_offset = round_param(value);
    break;
  case GL_RED_SCALE:
    x.scale[0] = f;
    break;
  case GL_GREEN_SCALE:
    x.scale[1] = f;
    break;
  case GL_BLUE_SCALE:
    x.scale[2] = f;
    break;
  case GL_ALPHA_SCALE:
    x.scale[3] = f;
    break;
  case GL_RED_BIAS:
    x.bias[0] = f;
    break;
  case GL_GREEN_BIAS:
    x.bias[1] = f;
    break;
  case GL_BLUE_BIAS:
    x.bias[2] = f;
    break;
  case GL_ALPHA_BIAS:
    x.bias[3] = f;
    break;
  case GL_DEPTH_SCALE:
    x.depth_scale = f;
    break;
  case GL_DEPTH_BIAS:
    x.depth_bias = f;
    break;
  default:
    return record_error(ctx, GL_INVALID_ENUM, func, pname);
  }
  mark_dirty(ctx, kDirtyPixel);
}

// GL 2.1 §3.6.3: the map name, then the size (1 .. MAX_PIXEL_MAP_TABLE, a power of two for
// the index-addressed maps). `convert(value, id)` turns one entry into the stored float.
template <typename T, typename Convert>
void pixel_map(const char* func, GLenum map, GLsizei size, const T* values, Convert convert) {
  PINEDA_CTX_OUTSIDE(func);
  const int id = pixel_map_id(map);
  if (id < 0) return record_error(ctx, GL_INVALID_ENUM, func, map);
  if (size < 1 || size > kMaxPixelMapTable) return record_error(ctx, GL_INVALID_VALUE, func);
  if (pixel_map_index_addressed(id) && (size & (size - 1)) != 0)
    return record_error(ctx, GL_INVALID_VALUE, func);
  // GL 2.1 §3.6.3: with a pixel unpack buffer bound, values is an offset into it.
  const void* src = nullptr;
  if (!unpack_memory(ctx, values, size_t(size) * sizeof(T), sizeof(T), func, &src)) return;
  values = static_cast<const T*>(src);
  if (values == nullptr) return;
  PixelMap& pm = ctx->pixel_maps.maps[id];
  pm.size = size;
  for (int i = 0; i < size; ++i)
    pm.values[i] = convert(values[i], id);
  mark_dirty(ctx, kDirtyPixel);
}

bool is_index_map(int id) {
  return id == kMapItoI || id == kMapStoS;
}

// §3.6.3: a stencil index given as a float is rounded to the nearest integer.
float stencil_entry(double v) {
  return static_cast<float>(round_param(v));
}

template <typename T, typename Convert>
void get_pixel_map(const char* func, GLenum map, T* values, Convert convert) {
  PINEDA_CTX_OUTSIDE(func);
  const int id = pixel_map_id(map);
  if (id < 0) return record_error(ctx, GL_INVALID_ENUM, func, map);
  const PixelMap& pm = ctx->pixel_maps.maps[id];
  // GL 2.1 §6.1.3: with a pixel pack buffer bound, values is an offset into it.
  void* dst = nullptr;
  if (!pack_memory(ctx, values, size_t(pm.size) * sizeof(T), sizeof(T), func, &dst)) return;
  values = static_cast<T*>(dst);
  if (values == nullptr) return;
  for (int i = 0; i < pm.size; ++i)
    values[i] = convert(pm.values[i], id);
}

// Table 4.7 c = (2^b - 1) f for colour entries read back as integers, f clamped to [0, 1].
double unorm_entry(float f, double max) {
  const double c = std::clamp(static_cast<double>(std::isnan(f) ? 0.0f : f), 0.0, 1.0);
  return std::floor(c * max + 0.5);
}

// An index entry read back as an unsigned integer of at most `max`.
double index_entry(float f, double max) {
  return std::clamp(std::trunc(std::isnan(f) ? 0.0 : static_cast<double>(f)), 0.0, max);
}

} // namespace

namespace {

// Tables 6.23-6.27: pixel store, transfer modes, map sizes, zoom and the read buffer.
bool get_pixel(Context& ctx, GLenum pname, QueryValues& out) {
  const PixelTransfer& x = ctx.pixel.transfer;
  if (const int id = pixel_map_size_id(pname); id >= 0) {
    out.ints({double(ctx.pixel_maps.maps[id].size)});
    return true;
  }
  const PixelStore& pack = ctx.pixel_store.pack;
  const PixelStore& unpack = ctx.pixel_store.unpack;
  switch (pname) {
  case GL_MAP_COLOR:
    out.boolean(x.map_color);
    return true;
  case GL_MAP_STENCIL:
    out.boolean(x.map_stencil);
    return true;
  case GL_INDEX_SHIFT:
    out.ints({double(x.index_shift)});
    return true;
  case GL_INDEX_OFFSET:
    out.ints({double(x.index_offset)});
    return true;
  case GL_RED_SCALE:
    out.floats({x.scale[0]});
    return true;
  case GL_GREEN_SCALE:
    out.floats({x.scale[1]});
    return true;
  case GL_BLUE_SCALE:
    out.floats({x.scale[2]});
    return true;
  case GL_ALPHA_SCALE:
    out.floats({x.scale[3]});
    return true;
  case GL_RED_BIAS:
    out.floats({x.bias[0]});
    return true;
  case GL_GREEN_BIAS:
    out.floats({x.bias[1]});
    return true;
  case GL_BLUE_BIAS:
    out.floats({x.bias[2]});
    return true;
  case GL_ALPHA_BIAS:
    out.floats({x.bias[3]});
    return true;
  case GL_DEPTH_SCALE:
    out.floats({x.depth_scale});
    return true;
  case GL_DEPTH_BIAS:
    out.floats({x.depth_bias});
    return true;
  case GL_ZOOM_X:
    out.floats({ctx.pixel.zoom_x});
    return true;
  case GL_ZOOM_Y:
    out.floats({ctx.pixel.zoom_y});
    return true;
  case GL_MAX_PIXEL_MAP_TABLE:
    out.ints({kMaxPixelMapTable});
    return true;
  case GL_READ_BUFFER:
    out.ints({double(ctx.pixel.read_buffer)});
    return true;
  case GL_PACK_SWAP_BYTES:
    out.boolean(pack.swap_bytes);
    return true;
  case GL_PACK_LSB_FIRST:
    out.boolean(pack.lsb_first);
    return true;
  case GL_PACK_ROW_LENGTH:
    out.ints({double(pack.row_length)});
    return true;
  case GL_PACK_SKIP_ROWS:
    out.ints({double(pack.skip_rows)});
    return true;
  case GL_PACK_SKIP_PIXELS:
    out.ints({double(pack.skip_pixels)});
    return true;
  case GL_PACK_ALIGNMENT:
    out.ints({double(pack.alignment)});
    return true;
  case GL_PACK_IMAGE_HEIGHT:
    out.ints({double(pack.image_height)});
    return true;
  case GL_PACK_SKIP_IMAGES:
    out.ints({double(pack.skip_images)});
    return true;
  case GL_UNPACK_SWAP_BYTES:
    out.boolean(unpack.swap_bytes);
    return true;
  case GL_UNPACK_LSB_FIRST:
    out.boolean(unpack.lsb_first);
    return true;
  case GL_UNPACK_ROW_LENGTH:
    out.ints({double(unpack.row_length)});
    return true;
  case GL_UNPACK_SKIP_ROWS:
    out.ints({double(unpack.skip_rows)});
    return true;
  case GL_UNPACK_SKIP_PIXELS:
    out.ints({double(unpack.skip_pixels)});
    return true;
  case GL_UNPACK_ALIGNMENT:
    out.ints({double(unpack.alignment)});
    return true;
  case GL_UNPACK_IMAGE_HEIGHT:
    out.ints({double(unpack.image_height)});
    return true;
  case GL_UNPACK_SKIP_IMAGES:
    out.ints({double(unpack.skip_images)});
    return true;
  case GL_PIXEL_PACK_BUFFER_BINDING:
    out.ints({double(ctx.pixel_store.pack_buffer)});
    return true;
  case GL_PIXEL_UNPACK_BUFFER_BINDING:
    out.ints({double(ctx.pixel_store.unpack_buffer)});
    return true;
  default:
    return false;
  }
}

constexpr AttribGroup kPixelGroups[] = {
    member_group<&Context::pixel>(GL_PIXEL_MODE_BIT, kDirtyPixel),
    member_group<&Context::pixel_store>(GL_CLIENT_PIXEL_STORE_BIT, 0, true),
};

} // namespace

const StateArea kPixelArea = {
    .name = "pixels (GL 2.1 §3.6, §4.3, Tables 6.23-6.27)",
    .get = get_pixel,
    .groups = kPixelGroups,
};

PixelTransferView pixel_transfer_view(const Context* ctx) {
  return {ctx->pixel.transfer, ctx->pixel_maps};
}

namespace exec {

void GLAPIENTRY PixelTransferf(GLenum pname, GLfloat param) {
  pixel_transfer("glPixelTransferf", pname, param);
}
void GLAPIENTRY PixelTransferi(GLenum pname, GLint param) {
  pixel_transfer("glPixelTransferi", pname, param);
}

void GLAPIENTRY PixelZoom(GLfloat xfactor, GLfloat yfactor) {
  PINEDA_CTX_OUTSIDE("glPixelZoom");
  ctx->pixel.zoom_x = xfactor;
  ctx->pixel.zoom_y = yfactor;
  mark_dirty(ctx, kDirtyPixel);
}

// §3.6.3: colour entries given as integers convert per Table 2.9 (c / (2^b - 1)); index
// entries keep their integer value.
void GLAPIENTRY PixelMapfv(GLenum map, GLsizei mapsize, const GLfloat* values) {
  pixel_map("glPixelMapfv", map, mapsize, values,
            [](GLfloat v, int id) { return id == kMapStoS ? stencil_entry(v) : v; });
}
void GLAPIENTRY PixelMapuiv(GLenum map, GLsizei mapsize, const GLuint* values) {
  pixel_map("glPixelMapuiv", map, mapsize, values, [](GLuint v, int id) {
    return is_index_map(id) ? static_cast<float>(v)
                            : static_cast<float>(static_cast<double>(v) / 4294967295.0);
  });
}
void GLAPIENTRY PixelMapusv(GLenum map, GLsizei mapsize, const GLushort* values) {
  pixel_map("glPixelMapusv", map, mapsize, values, [](GLushort v, int id) {
    return is_index_map(id) ? static_cast<float>(v) : static_cast<float>(v) / 65535.0f;
  });
}

// §6.1.3: colour entries come back per Table 4.7; index entries as their integer value.
void GLAPIENTRY GetPixelMapfv(GLenum map, GLfloat* values) {
  get_pixel_map("glGetPixelMapfv", map, values, [](float v, int) { return v; });
}
void GLAPIENTRY GetPixelMapuiv(GLenum map, GLuint* values) {
  get_pixel_map("glGetPixelMapuiv", map, values, [](float v, int id) {
    return static_cast<GLuint>(is_index_map(id) ? index_entry(v, 4294967295.0)
                                                : unorm_entry(v, 4294967295.0));
  });
}
void GLAPIENTRY GetPixelMapusv(GLenum map, GLushort* values) {
  get_pixel_map("glGetPixelMapusv", map, values, [](float v, int id) {
    return static_cast<GLushort>(is_index_map(id) ? index_entry(v, 65535.0)
                                                  : unorm_entry(v, 65535.0));
  });
}

} // namespace exec
} // namespace pineda
