// Rasterization modes (GL 2.1 §3.3 points, §3.4 lines, §3.5 polygons): glPointSize,
// glPointParameter*, glLineWidth, glLineStipple, glPolygonStipple, glGetPolygonStipple,
// glPolygonOffset; and the rasterization area (Tables 6.12-6.14, rasterization.h): its
// capabilities, queries and the POINT, LINE, POLYGON and POLYGON_STIPPLE groups.
#include <algorithm>
#include <cmath>

#include "state/api_util.h"
#include "dispatch.h"
#include "state/area.h"
#include "pixel/unpack.h"
#include "state/pixel_buffer.h"

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
         pname == GL_POINT_FADE_THRESHOLD_SIZE || pname == GL_POINT_DISTANCE_ATTENUATION ||
         pname == GL_POINT_SPRITE_COORD_ORIGIN;
}

// glPointParameter* with pname validated by the caller and `n` values (3 for the attenuation).
void point_parameter(Context* ctx, const char* func, GLenum pname, const float* v) {
  PointGroup& s = ctx->point;
  if (pname == GL_POINT_DISTANCE_ATTENUATION) {
    if (s.attenuation[0] == v[0] && s.attenuation[1] == v[1] && s.attenuation[2] == v[2]) return;
    std::copy(v, v + 3, s.attenuation);
    mark_dirty(ctx, kDirtyRasterMode);
    return;
  }
  if (pname == GL_POINT_SPRITE_COORD_ORIGIN) {
    // GL 2.1 §3.3: LOWER_LEFT or UPPER_LEFT; another value is INVALID_VALUE (as in Mesa).
    const GLenum origin = v[0] == static_cast<float>(GL_LOWER_LEFT)   ? GL_LOWER_LEFT
                          : v[0] == static_cast<float>(GL_UPPER_LEFT) ? GL_UPPER_LEFT
                                                                      : GL_NONE;
    if (origin == GL_NONE) return record_error(ctx, GL_INVALID_VALUE, func);
    if (s.sprite_origin == origin) return;
    s.sprite_origin = origin;
    mark_dirty(ctx, kDirtyRasterMode);
    return;
  }
  // GL 2.1 §3.3: negative (or NaN) sizes and thresholds are INVALID_VALUE.
  if (!(v[0] >= 0.0f)) return record_error(ctx, GL_INVALID_VALUE, func);
  float* slot = pname == GL_POINT_SIZE_MIN   ? &s.size_min
                : pname == GL_POINT_SIZE_MAX ? &s.size_max
                                             : &s.fade_threshold;
  if (*slot == v[0]) return;
  *slot = v[0];
  mark_dirty(ctx, kDirtyRasterMode);
}

} // namespace

namespace {

// Tables 6.12-6.14 and the rasterization limits of Table 6.36, the values llvmpipe reports.
bool get_rasterization(Context& ctx, GLenum pname, QueryValues& out) {
  const PointGroup& point = ctx.point;
  const LineGroup& line = ctx.line;
  const PolygonGroup& polygon = ctx.polygon;
  switch (pname) {
  case GL_POINT_SIZE:
    out.floats({point.size});
    return true;
  case GL_POINT_SIZE_MIN:
    out.floats({point.size_min});
    return true;
  case GL_POINT_SIZE_MAX:
    out.floats({point.size_max});
    return true;
  case GL_POINT_FADE_THRESHOLD_SIZE:
    out.floats({point.fade_threshold});
    return true;
  case GL_POINT_SPRITE_COORD_ORIGIN:
    out.ints({double(point.sprite_origin)});
    return true;
  case GL_POINT_DISTANCE_ATTENUATION:
    out.floats(point.attenuation, 3);
    return true;
  case GL_LINE_WIDTH:
    out.floats({line.width});
    return true;
  case GL_LINE_STIPPLE_PATTERN:
    out.ints({double(line.stipple_pattern)});
    return true;
  case GL_LINE_STIPPLE_REPEAT:
    out.ints({double(line.stipple_repeat)});
    return true;
  case GL_CULL_FACE_MODE:
    out.ints({double(polygon.cull_face)});
    return true;
  case GL_FRONT_FACE:
    out.ints({double(polygon.front_face)});
    return true;
  case GL_POLYGON_MODE:
    out.ints({double(polygon.mode[0]), double(polygon.mode[1])});
    return true;
  case GL_POLYGON_OFFSET_FACTOR:
    out.floats({polygon.offset_factor});
    return true;
  case GL_POLYGON_OFFSET_UNITS:
    out.floats({polygon.offset_units});
    return true;
  case GL_ALIASED_POINT_SIZE_RANGE:
  case GL_POINT_SIZE_RANGE:
    out.floats({1.0, kMaxPointSize});
    return true;
  case GL_ALIASED_LINE_WIDTH_RANGE:
  case GL_LINE_WIDTH_RANGE:
    out.floats({1.0, kMaxLineWidth});
    return true;
  case GL_POINT_SIZE_GRANULARITY:
  case GL_LINE_WIDTH_GRANULARITY:
    out.floats({kSizeGranularity});
    return true;
  case GL_SUBPIXEL_BITS:
    out.ints({kSubpixelBits});
    return true;
  default:
    return false;
  }
}

constexpr Capability kRasterizationCaps[] = {
    {GL_CULL_FACE, 1, CapabilityKind::kServer, kDirtyPolygon,
     [](Context& c, unsigned, unsigned) { return &c.polygon.cull_enabled; }},
    {GL_POINT_SMOOTH, 1, CapabilityKind::kServer, kDirtyRasterMode,
     [](Context& c, unsigned, unsigned) { return &c.point.smooth; }},
    // GL 2.1 §3.3 (ARB_point_sprite).
    {GL_POINT_SPRITE, 1, CapabilityKind::kServer, kDirtyRasterMode,
     [](Context& c, unsigned, unsigned) { return &c.point.sprite; }},
    {GL_LINE_SMOOTH, 1, CapabilityKind::kServer, kDirtyRasterMode,
     [](Context& c, unsigned, unsigned) { return &c.line.smooth; }},
    {GL_LINE_STIPPLE, 1, CapabilityKind::kServer, kDirtyRasterMode,
     [](Context& c, unsigned, unsigned) { return &c.line.stipple; }},
    {GL_POLYGON_SMOOTH, 1, CapabilityKind::kServer, kDirtyRasterMode,
     [](Context& c, unsigned, unsigned) { return &c.polygon.smooth; }},
    {GL_POLYGON_STIPPLE, 1, CapabilityKind::kServer, kDirtyRasterMode,
     [](Context& c, unsigned, unsigned) { return &c.polygon.stipple; }},
    {GL_POLYGON_OFFSET_POINT, 1, CapabilityKind::kServer, kDirtyRasterMode,
     [](Context& c, unsigned, unsigned) { return &c.polygon.offset_point; }},
    {GL_POLYGON_OFFSET_LINE, 1, CapabilityKind::kServer, kDirtyRasterMode,
     [](Context& c, unsigned, unsigned) { return &c.polygon.offset_line; }},
    {GL_POLYGON_OFFSET_FILL, 1, CapabilityKind::kServer, kDirtyRasterMode,
     [](Context& c, unsigned, unsigned) { return &c.polygon.offset_fill; }},
};

constexpr AttribGroup kRasterizationGroups[] = {
    member_group<&Context::point>(GL_POINT_BIT, kDirtyRasterMode),
    member_group<&Context::line>(GL_LINE_BIT, kDirtyRasterMode),
    member_group<&Context::polygon>(GL_POLYGON_BIT, kDirtyPolygon | kDirtyRasterMode),
    member_group<&Context::polygon_stipple>(GL_POLYGON_STIPPLE_BIT, kDirtyRasterMode),
};

} // namespace

const StateArea kRasterizationArea = {
    .name = "rasterization (GL 2.1 §3.3-§3.5, Tables 6.12-6.14)",
    .capabilities = kRasterizationCaps,
    .get = get_rasterization,
    .groups = kRasterizationGroups,
};

namespace exec {

void GLAPIENTRY PointSize(GLfloat size) {
  PINEDA_CTX_OUTSIDE("glPointSize");
  // GL 2.1 §3.3: a size <= 0 is INVALID_VALUE.
  if (!(size > 0.0f)) return record_error(ctx, GL_INVALID_VALUE, "glPointSize");
  if (ctx->point.size == size) return;
  ctx->point.size = size;
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
  if (ctx->line.width == width) return;
  ctx->line.width = width;
  mark_dirty(ctx, kDirtyRasterMode);
}

void GLAPIENTRY LineStipple(GLint factor, GLushort pattern) {
  PINEDA_CTX_OUTSIDE("glLineStipple");
  // GL 2.1 §3.4.2: the factor is clamped to [1, 256].
  const GLint repeat = std::clamp(factor, 1, 256);
  LineGroup& s = ctx->line;
  if (s.stipple_repeat == repeat && s.stipple_pattern == pattern) return;
  s.stipple_repeat = repeat;
  s.stipple_pattern = pattern;
  mark_dirty(ctx, kDirtyRasterMode);
}

void GLAPIENTRY PolygonStipple(const GLubyte* mask) {
  PINEDA_CTX_OUTSIDE("glPolygonStipple");
  const PixelStore& ps = ctx->pixel_store.unpack;
  // GL 2.1 §3.5.2: from the pixel unpack buffer when one is bound.
  const void* src = nullptr;
  if (!unpack_memory(ctx, mask,
                     client_image_bytes(32, 32, 1, GL_COLOR_INDEX, GL_BITMAP, store_2d(ps)), 1,
                     "glPolygonStipple", &src))
    return;
  mask = static_cast<const GLubyte*>(src);
  if (mask == nullptr) return;
  const BitmapLayout l = bitmap_layout(ps);
  PolygonStippleGroup& s = ctx->polygon_stipple;
  // GL 2.1 §3.5.2: the first row of the image is the bottom row of the pattern.
  for (int r = 0; r < 32; ++r) {
    const GLubyte* row = mask + l.row_offset(r, ps);
    uint32_t bits = 0;
    for (size_t c = 0; c < 32; ++c) {
      const size_t b = l.first_bit + c;
      if (row[b >> 3] & bit_mask(b, l.lsb_first)) bits |= 1u << c;
    }
    s.rows[r] = bits;
  }
  mark_dirty(ctx, kDirtyRasterMode);
}

void GLAPIENTRY GetPolygonStipple(GLubyte* mask) {
  PINEDA_CTX_OUTSIDE("glGetPolygonStipple");
  // GL 2.1 §6.1.5: packed like ReadPixels of a 32x32 bitmap with the pack state (into the
  // pixel pack buffer when one is bound); bits of the destination outside the pattern keep
  // their values.
  const PixelStore& ps = ctx->pixel_store.pack;
  void* dst = nullptr;
  if (!pack_memory(ctx, mask,
                   client_image_bytes(32, 32, 1, GL_COLOR_INDEX, GL_BITMAP, store_2d(ps)), 1,
                   "glGetPolygonStipple", &dst))
    return;
  mask = static_cast<GLubyte*>(dst);
  if (mask == nullptr) return;
  const BitmapLayout l = bitmap_layout(ps);
  const PolygonStippleGroup& s = ctx->polygon_stipple;
  for (int r = 0; r < 32; ++r) {
    GLubyte* row = mask + l.row_offset(r, ps);
    for (size_t c = 0; c < 32; ++c) {
      const size_t b = l.first_bit + c;
      const unsigned m = bit_mask(b, l.lsb_first);
      if (s.rows[r] & (1u << c))
        row[b >> 3] = static_cast<GLubyte>(row[b >> 3] | m);
      else
        row[b >> 3] = static_cast<GLubyte>(row[b >> 3] & ~m);
    }
  }
}

void GLAPIENTRY PolygonOffset(GLfloat factor, GLfloat units) {
  PINEDA_CTX_OUTSIDE("glPolygonOffset");
  PolygonGroup& s = ctx->polygon;
  if (s.offset_factor == factor && s.offset_units == units) return;
  s.offset_factor = factor;
  s.offset_units = units;
  mark_dirty(ctx, kDirtyRasterMode);
}

} // namespace exec
} // namespace pineda
