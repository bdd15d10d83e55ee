// Rasterization modes (GL 2.1 §3.3 points, §3.4 lines, §3.5 polygons): glPointSize,
// glPointParameter*, glLineWidth, glLineStipple, glPolygonStipple, glGetPolygonStipple,
// glPolygonOffset; their enables, queries, attribute groups and the derived RasterModes.
#include <algorithm>
#include <cmath>

#include "core/api_util.h"
#include "dispatch.h"
#include "state/raster_modes_hooks.h"

namespace pineda {

namespace {

// GL 2.1 §3.6.4-§3.6.5: a 32x32 bitmap (format COLOR_INDEX, type BITMAP) is laid out like any
// bitmap: rows of row_length (or 32) bits padded to the alignment, after skip_rows rows and
// skip_pixels bits; within a byte the first bit is the most significant unless LSB_FIRST.
// SWAP_BYTES does not apply to bitmaps.
struct BitmapLayout {
  size_t row_bytes;
  size_t first_bit;
  bool lsb_first;
  size_t row_offset(int r, const PixelStore& ps) const {
    return static_cast<size_t>(ps.skip_rows + r) * row_bytes;
  }
};

BitmapLayout bitmap_layout(const PixelStore& ps) {
  const size_t row_bits = static_cast<size_t>(ps.row_length > 0 ? ps.row_length : 32);
  const size_t a = static_cast<size_t>(ps.alignment > 0 ? ps.alignment : 1);
  BitmapLayout l;
  l.row_bytes = a * ((row_bits + 8 * a - 1) / (8 * a));
  l.first_bit = static_cast<size_t>(ps.skip_pixels);
  l.lsb_first = ps.lsb_first;
  return l;
}

inline unsigned bit_mask(size_t bit, bool lsb_first) {
  return lsb_first ? (1u << (bit & 7)) : (0x80u >> (bit & 7));
}

bool valid_point_pname(GLenum pname) {
  return pname == GL_POINT_SIZE_MIN || pname == GL_POINT_SIZE_MAX ||
         pname == GL_POINT_FADE_THRESHOLD_SIZE || pname == GL_POINT_DISTANCE_ATTENUATION;
}

// glPointParameter* with pname validated by the caller and `n` values (3 for the attenuation).
void point_parameter(Context* ctx, const char* func, GLenum pname, const float* v) {
  RasterModeState& s = ctx->raster_modes;
  if (pname == GL_POINT_DISTANCE_ATTENUATION) {
    if (s.point_attenuation[0] == v[0] && s.point_attenuation[1] == v[1] &&
        s.point_attenuation[2] == v[2])
      return;
    std::copy(v, v + 3, s.point_attenuation);
    mark_dirty(ctx, kDirtyRasterMode);
    return;
  }
  // GL 2.1 §3.3: negative (or NaN) sizes and thresholds are INVALID_VALUE.
  if (!(v[0] >= 0.0f)) return record_error(ctx, GL_INVALID_VALUE, func);
  float* slot = pname == GL_POINT_SIZE_MIN   ? &s.point_size_min
                : pname == GL_POINT_SIZE_MAX ? &s.point_size_max
                                             : &s.point_fade_threshold;
  if (*slot == v[0]) return;
  *slot = v[0];
  mark_dirty(ctx, kDirtyRasterMode);
}

} // namespace

bool* raster_mode_capability(Context* ctx, GLenum cap) {
  RasterModeState& s = ctx->raster_modes;
  switch (cap) {
  case GL_POINT_SMOOTH:
    return &s.point_smooth;
  case GL_LINE_SMOOTH:
    return &s.line_smooth;
  case GL_LINE_STIPPLE:
    return &s.line_stipple;
  case GL_POLYGON_SMOOTH:
    return &s.polygon_smooth;
  case GL_POLYGON_STIPPLE:
    return &s.polygon_stipple;
  case GL_POLYGON_OFFSET_POINT:
    return &s.offset_point;
  case GL_POLYGON_OFFSET_LINE:
    return &s.offset_line;
  case GL_POLYGON_OFFSET_FILL:
    return &s.offset_fill;
  default:
    return nullptr;
  }
}

bool raster_mode_query(Context* ctx, GLenum pname, RasterModeValues& out) {
  const RasterModeState& s = ctx->raster_modes;
  out.n = 0;
  out.is_float = true;
  const auto add = [&](double v) { out.v[out.n++] = v; };
  switch (pname) {
  case GL_POINT_SIZE_MIN:
    add(s.point_size_min);
    return true;
  case GL_POINT_SIZE_MAX:
    add(s.point_size_max);
    return true;
  case GL_POINT_FADE_THRESHOLD_SIZE:
    add(s.point_fade_threshold);
    return true;
  case GL_POINT_DISTANCE_ATTENUATION:
    for (float a : s.point_attenuation)
      add(a);
    return true;
  case GL_POLYGON_OFFSET_FACTOR:
    add(s.offset_factor);
    return true;
  case GL_POLYGON_OFFSET_UNITS:
    add(s.offset_units);
    return true;
  case GL_LINE_STIPPLE_PATTERN:
    out.is_float = false;
    add(s.line_stipple_pattern);
    return true;
  case GL_LINE_STIPPLE_REPEAT:
    out.is_float = false;
    add(s.line_stipple_repeat);
    return true;
  // Implementation limits (Table 6.36), the values llvmpipe reports.
  case GL_ALIASED_POINT_SIZE_RANGE:
  case GL_POINT_SIZE_RANGE:
    add(1.0), add(kMaxPointSize);
    return true;
  case GL_ALIASED_LINE_WIDTH_RANGE:
  case GL_LINE_WIDTH_RANGE:
    add(1.0), add(kMaxLineWidth);
    return true;
  case GL_POINT_SIZE_GRANULARITY:
  case GL_LINE_WIDTH_GRANULARITY:
    add(kSizeGranularity);
    return true;
  default:
    return false;
  }
}

void save_raster_modes(const Context* ctx, RasterModeAttrib& a) {
  a.s = ctx->raster_modes;
  a.point_size = ctx->point_size;
  a.line_width = ctx->line_width;
}

uint32_t restore_raster_modes(Context* ctx, const RasterModeAttrib& a, GLbitfield mask) {
  RasterModeState& s = ctx->raster_modes;
  const RasterModeState& f = a.s;
  // GL 2.1 §6.1.14, Table 6.14's attribute column.
  if (mask & (GL_POINT_BIT | GL_ENABLE_BIT)) s.point_smooth = f.point_smooth;
  if (mask & (GL_LINE_BIT | GL_ENABLE_BIT)) {
    s.line_smooth = f.line_smooth;
    s.line_stipple = f.line_stipple;
  }
  if (mask & (GL_POLYGON_BIT | GL_ENABLE_BIT)) {
    s.polygon_smooth = f.polygon_smooth;
    s.polygon_stipple = f.polygon_stipple;
    s.offset_point = f.offset_point;
    s.offset_line = f.offset_line;
    s.offset_fill = f.offset_fill;
  }
  if (mask & GL_POINT_BIT) {
    ctx->point_size = a.point_size;
    s.point_size_min = f.point_size_min;
    s.point_size_max = f.point_size_max;
    s.point_fade_threshold = f.point_fade_threshold;
    std::copy(f.point_attenuation, f.point_attenuation + 3, s.point_attenuation);
  }
  if (mask & GL_LINE_BIT) {
    ctx->line_width = a.line_width;
    s.line_stipple_repeat = f.line_stipple_repeat;
    s.line_stipple_pattern = f.line_stipple_pattern;
  }
  if (mask & GL_POLYGON_BIT) {
    s.offset_factor = f.offset_factor;
    s.offset_units = f.offset_units;
  }
  if (mask & GL_POLYGON_STIPPLE_BIT)
    std::copy(f.polygon_stipple_rows, f.polygon_stipple_rows + 32, s.polygon_stipple_rows);
  const GLbitfield groups =
      GL_POINT_BIT | GL_LINE_BIT | GL_POLYGON_BIT | GL_POLYGON_STIPPLE_BIT | GL_ENABLE_BIT;
  return (mask & groups) ? kDirtyRasterMode : 0u;
}

void derive_raster_modes(const Context* ctx, RasterModes& m) {
  const RasterModeState& s = ctx->raster_modes;
  m.line_width = std::clamp(ctx->line_width, 1.0f, kMaxLineWidth);
  m.line_smooth = s.line_smooth;
  m.line_stipple = s.line_stipple;
  m.line_stipple_factor = s.line_stipple_repeat;
  m.line_stipple_pattern = s.line_stipple_pattern;
  m.point_smooth = s.point_smooth;
  m.point_attenuated = s.point_attenuation[0] != 1.0f || s.point_attenuation[1] != 0.0f ||
                       s.point_attenuation[2] != 0.0f;
  // GL 2.1 §3.3 eq 3.1: the derived size is clamped to POINT_SIZE_MIN / MAX, also without
  // attenuation (llvmpipe does the same); with attenuation the geometry stage derives and clamps
  // it per vertex from the unclamped size.
  m.point_size = ctx->point_size;
  if (!m.point_attenuated)
    m.point_size = std::min(std::max(std::min(ctx->point_size, s.point_size_max), s.point_size_min),
                            kMaxPointSize);
  m.point_size_min = s.point_size_min;
  m.point_size_max = std::min(s.point_size_max, kMaxPointSize);
  m.point_fade_threshold = s.point_fade_threshold;
  std::copy(s.point_attenuation, s.point_attenuation + 3, m.point_attenuation);
  // The stipple pattern all ones stipples nothing: skip the per-block AND.
  bool all_ones = true;
  for (uint32_t r : s.polygon_stipple_rows)
    all_ones = all_ones && r == 0xffffffffu;
  m.polygon_stipple = s.polygon_stipple && !all_ones;
  std::copy(s.polygon_stipple_rows, s.polygon_stipple_rows + 32, m.polygon_stipple_rows);
  m.offset_point = s.offset_point;
  m.offset_line = s.offset_line;
  m.offset_fill = s.offset_fill;
  m.offset_factor = s.offset_factor;
  m.offset_units = s.offset_units;
  const Framebuffer& fb = ctx->fb;
  const int bits = fb.depth != nullptr ? fb.depth_bits : 24;
  m.depth_mrd = 1.0 / (bits >= 32 ? 4294967295.0 : static_cast<double>((uint64_t{1} << bits) - 1));
}

namespace exec {

void GLAPIENTRY PointSize(GLfloat size) {
  PINEDA_CTX_OUTSIDE("glPointSize");
  // GL 2.1 §3.3: a size <= 0 is INVALID_VALUE.
  if (!(size > 0.0f)) return record_error(ctx, GL_INVALID_VALUE, "glPointSize");
  if (ctx->point_size == size) return;
  ctx->point_size = size;
  mark_dirty(ctx, kDirtyRasterMode);
}

void GLAPIENTRY PointParameterf(GLenum pname, GLfloat param) {
  PINEDA_CTX_OUTSIDE("glPointParameterf");
  // The attenuation is a vector: the scalar forms do not accept it.
  if (!valid_point_pname(pname) || pname == GL_POINT_DISTANCE_ATTENUATION)
    return record_error(ctx, GL_INVALID_ENUM, "glPointParameterf", pname);
  point_parameter(ctx, "glPointParameterf", pname, &param);
}

void GLAPIENTRY PointParameterfv(GLenum pname, const GLfloat* params) {
  PINEDA_CTX_OUTSIDE("glPointParameterfv");
  if (!valid_point_pname(pname))
    return record_error(ctx, GL_INVALID_ENUM, "glPointParameterfv", pname);
  if (params == nullptr) return;
  point_parameter(ctx, "glPointParameterfv", pname, params);
}

void GLAPIENTRY PointParameteri(GLenum pname, GLint param) {
  PINEDA_CTX_OUTSIDE("glPointParameteri");
  if (!valid_point_pname(pname) || pname == GL_POINT_DISTANCE_ATTENUATION)
    return record_error(ctx, GL_INVALID_ENUM, "glPointParameteri", pname);
  const float v = static_cast<float>(param);
  point_parameter(ctx, "glPointParameteri", pname, &v);
}

void GLAPIENTRY PointParameteriv(GLenum pname, const GLint* params) {
  PINEDA_CTX_OUTSIDE("glPointParameteriv");
  if (!valid_point_pname(pname))
    return record_error(ctx, GL_INVALID_ENUM, "glPointParameteriv", pname);
  if (params == nullptr) return;
  const int n = pname == GL_POINT_DISTANCE_ATTENUATION ? 3 : 1;
  float v[3] = {};
  for (int i = 0; i < n; ++i)
    v[i] = static_cast<float>(params[i]);
  point_parameter(ctx, "glPointParameteriv", pname, v);
}

void GLAPIENTRY LineWidth(GLfloat width) {
  PINEDA_CTX_OUTSIDE("glLineWidth");
  // GL 2.1 §3.4.2: a width <= 0 is INVALID_VALUE.
  if (!(width > 0.0f)) return record_error(ctx, GL_INVALID_VALUE, "glLineWidth");
  if (ctx->line_width == width) return;
  ctx->line_width = width;
  mark_dirty(ctx, kDirtyRasterMode);
}

void GLAPIENTRY LineStipple(GLint factor, GLushort pattern) {
  PINEDA_CTX_OUTSIDE("glLineStipple");
  // GL 2.1 §3.4.2: the factor is clamped to [1, 256].
  const GLint repeat = std::clamp(factor, 1, 256);
  RasterModeState& s = ctx->raster_modes;
  if (s.line_stipple_repeat == repeat && s.line_stipple_pattern == pattern) return;
  s.line_stipple_repeat = repeat;
  s.line_stipple_pattern = pattern;
  mark_dirty(ctx, kDirtyRasterMode);
}

void GLAPIENTRY PolygonStipple(const GLubyte* mask) {
  PINEDA_CTX_OUTSIDE("glPolygonStipple");
  if (mask == nullptr) return;
  const PixelStore& ps = ctx->unpack;
  const BitmapLayout l = bitmap_layout(ps);
  RasterModeState& s = ctx->raster_modes;
  // GL 2.1 §3.5.2: the first row of the image is the bottom row of the pattern.
  for (int r = 0; r < 32; ++r) {
    const GLubyte* row = mask + l.row_offset(r, ps);
    uint32_t bits = 0;
    for (size_t c = 0; c < 32; ++c) {
      const size_t b = l.first_bit + c;
      if (row[b >> 3] & bit_mask(b, l.lsb_first)) bits |= 1u << c;
    }
    s.polygon_stipple_rows[r] = bits;
  }
  mark_dirty(ctx, kDirtyRasterMode);
}

void GLAPIENTRY GetPolygonStipple(GLubyte* mask) {
  PINEDA_CTX_OUTSIDE("glGetPolygonStipple");
  if (mask == nullptr) return;
  // GL 2.1 §6.1.5: packed like ReadPixels of a 32x32 bitmap with the pack state; bits of the
  // destination outside the pattern keep their values.
  const PixelStore& ps = ctx->pack;
  const BitmapLayout l = bitmap_layout(ps);
  const RasterModeState& s = ctx->raster_modes;
  for (int r = 0; r < 32; ++r) {
    GLubyte* row = mask + l.row_offset(r, ps);
    for (size_t c = 0; c < 32; ++c) {
      const size_t b = l.first_bit + c;
      const unsigned m = bit_mask(b, l.lsb_first);
      if (s.polygon_stipple_rows[r] & (1u << c))
        row[b >> 3] = static_cast<GLubyte>(row[b >> 3] | m);
      else
        row[b >> 3] = static_cast<GLubyte>(row[b >> 3] & ~m);
    }
  }
}

void GLAPIENTRY PolygonOffset(GLfloat factor, GLfloat units) {
  PINEDA_CTX_OUTSIDE("glPolygonOffset");
  RasterModeState& s = ctx->raster_modes;
  if (s.offset_factor == factor && s.offset_units == units) return;
  s.offset_factor = factor;
  s.offset_units = units;
  mark_dirty(ctx, kDirtyRasterMode);
}

} // namespace exec
} // namespace pineda
