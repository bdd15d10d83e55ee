// Pixel transfer modes (GL 2.1 §3.6.3): glPixelTransfer, glPixelMap, glGetPixelMap (§6.1.3),
// glPixelZoom (§3.6.4), and the glGet values of the pixel and raster position state
// (Tables 6.5, 6.23-6.27).
#include <algorithm>
#include <cmath>

#include "core/api_util.h"
#include "dispatch.h"

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
  PixelTransfer& x = ctx->pixel_transfer;
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
  if (values == nullptr) return;
  PixelMap& pm = ctx->pixel_transfer.maps[id];
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
  if (values == nullptr) return;
  const PixelMap& pm = ctx->pixel_transfer.maps[id];
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

int pixel_query(const Context* ctx, GLenum pname, double* v, int* kind) {
  enum { kInt, kBool, kFloat, kNormalized }; // get.cpp's Kind, in order
  const PixelTransfer& x = ctx->pixel_transfer;
  const RasterPos& rp = ctx->raster_pos;
  const auto put = [&](int k, std::initializer_list<double> vals) {
    *kind = k;
    int n = 0;
    for (double d : vals)
      v[n++] = d;
    return n;
  };
  if (const int id = pixel_map_size_id(pname); id >= 0) return put(kInt, {double(x.maps[id].size)});
  switch (pname) {
  case GL_MAP_COLOR:
    return put(kBool, {x.map_color ? 1.0 : 0.0});
  case GL_MAP_STENCIL:
    return put(kBool, {x.map_stencil ? 1.0 : 0.0});
  case GL_INDEX_SHIFT:
    return put(kInt, {double(x.index_shift)});
  case GL_INDEX_OFFSET:
    return put(kInt, {double(x.index_offset)});
  case GL_RED_SCALE:
    return put(kFloat, {x.scale[0]});
  case GL_GREEN_SCALE:
    return put(kFloat, {x.scale[1]});
  case GL_BLUE_SCALE:
    return put(kFloat, {x.scale[2]});
  case GL_ALPHA_SCALE:
    return put(kFloat, {x.scale[3]});
  case GL_RED_BIAS:
    return put(kFloat, {x.bias[0]});
  case GL_GREEN_BIAS:
    return put(kFloat, {x.bias[1]});
  case GL_BLUE_BIAS:
    return put(kFloat, {x.bias[2]});
  case GL_ALPHA_BIAS:
    return put(kFloat, {x.bias[3]});
  case GL_DEPTH_SCALE:
    return put(kFloat, {x.depth_scale});
  case GL_DEPTH_BIAS:
    return put(kFloat, {x.depth_bias});
  case GL_ZOOM_X:
    return put(kFloat, {x.zoom_x});
  case GL_ZOOM_Y:
    return put(kFloat, {x.zoom_y});
  case GL_MAX_PIXEL_MAP_TABLE:
    return put(kInt, {double(kMaxPixelMapTable)});
  // Table 6.5: the current raster position and its associated data.
  case GL_CURRENT_RASTER_POSITION:
    return put(kFloat, {rp.win[0], rp.win[1], rp.win[2], rp.win[3]});
  case GL_CURRENT_RASTER_POSITION_VALID:
    return put(kBool, {rp.valid ? 1.0 : 0.0});
  case GL_CURRENT_RASTER_DISTANCE:
    return put(kFloat, {rp.distance});
  case GL_CURRENT_RASTER_COLOR:
    return put(kNormalized, {rp.color[0], rp.color[1], rp.color[2], rp.color[3]});
  case GL_CURRENT_RASTER_SECONDARY_COLOR:
    return put(kNormalized, {rp.color2[0], rp.color2[1], rp.color2[2], rp.color2[3]});
  case GL_CURRENT_RASTER_INDEX:
    return put(kFloat, {rp.index});
  case GL_CURRENT_RASTER_TEXTURE_COORDS: {
    const float* t = rp.tex[ctx->active_texture];
    return put(kFloat, {t[0], t[1], t[2], t[3]});
  }
  default:
    return 0;
  }
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
  ctx->pixel_transfer.zoom_x = xfactor;
  ctx->pixel_transfer.zoom_y = yfactor;
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
