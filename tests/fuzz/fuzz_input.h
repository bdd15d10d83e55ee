// Decoding of fuzzer bytes into GL arguments. Arguments are drawn from tables of values that
// matter to an implementation (special floats, boundary integers, the enums GL 1.5 defines)
// most of the time and from raw bytes otherwise, so that mutations reach deep states quickly
// while every bit pattern stays reachable. Running out of input yields zeros.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

namespace pineda::fuzz {

class Input {
public:
  Input(const uint8_t* data, size_t size) : p_(data), end_(data + size) {}

  bool empty() const { return p_ >= end_; }

  uint8_t u8() { return p_ < end_ ? *p_++ : 0; }
  uint8_t peek() const { return p_ < end_ ? *p_ : 0; }

  uint16_t u16() { return static_cast<uint16_t>(u8() | (u8() << 8)); }

  uint32_t u32() {
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i)
      v |= static_cast<uint32_t>(u8()) << (8 * i);
    return v;
  }

  // A float: one tag byte picks a special value, a small multiple of 1/8, or four raw bytes.
  float f() {
    const uint8_t tag = u8();
    if (tag < kSpecialCount) return special(tag);
    if (tag < 200) return static_cast<float>(static_cast<int>(tag) - 100) * 0.125f;
    const uint32_t bits = u32();
    float v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }

  double d() { return static_cast<double>(f()); }

  // A signed integer: small values, boundary values, or four raw bytes.
  int32_t i() {
    const uint8_t tag = u8();
    if (tag < 160) return static_cast<int32_t>(tag) - 16;
    if (tag < 160 + kIntCount) return kInts[tag - 160];
    return static_cast<int32_t>(u32());
  }

  // An enum: mostly from the table of GL enums, sometimes raw.
  GLenum e() {
    const uint8_t tag = u8();
    if (tag < 250) return kEnums[tag % kEnumCount];
    return u32();
  }

  // An enum from a family table (the arguments one command takes, with invalid neighbours),
  // sometimes from the general table, sometimes raw.
  template <size_t N> GLenum e(const GLenum (&table)[N]) {
    const uint8_t tag = u8();
    if (tag < 200) return table[tag % N];
    if (tag < 250) return kEnums[tag % kEnumCount];
    return u32();
  }

private:
  static constexpr int kSpecialCount = 24;
  static float special(int k) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    const float table[kSpecialCount] = {0.0f,
                                        -0.0f,
                                        1.0f,
                                        -1.0f,
                                        0.5f,
                                        std::numeric_limits<float>::quiet_NaN(),
                                        inf,
                                        -inf,
                                        1e30f,
                                        -1e30f,
                                        1e-30f,
                                        std::numeric_limits<float>::max(),
                                        -std::numeric_limits<float>::max(),
                                        std::numeric_limits<float>::min(),
                                        std::numeric_limits<float>::denorm_min(),
                                        16384.0f,
                                        -16384.0f,
                                        1e9f,
                                        1e-9f,
                                        2.0f,
                                        255.0f,
                                        65535.0f,
                                        0.999999f,
                                        1.000001f};
    return table[k];
  }

  static constexpr int kIntCount = 16;
  static constexpr int32_t kInts[kIntCount] = {std::numeric_limits<int32_t>::max(),
                                               std::numeric_limits<int32_t>::min(),
                                               16384,
                                               16385,
                                               16383,
                                               65535,
                                               65536,
                                               -65536,
                                               4096,
                                               1 << 20,
                                               -(1 << 20),
                                               1 << 30,
                                               255,
                                               256,
                                               1000000,
                                               -2};

  static constexpr GLenum kEnums[] = {
      // Primitive modes and invalid neighbours.
      GL_POINTS,
      GL_LINES,
      GL_LINE_LOOP,
      GL_LINE_STRIP,
      GL_TRIANGLES,
      GL_TRIANGLE_STRIP,
      GL_TRIANGLE_FAN,
      GL_QUADS,
      GL_QUAD_STRIP,
      GL_POLYGON,
      10,
      // Capabilities.
      GL_DEPTH_TEST,
      GL_BLEND,
      GL_CULL_FACE,
      GL_CLIP_PLANE0,
      GL_CLIP_PLANE1,
      GL_CLIP_PLANE2,
      GL_CLIP_PLANE3,
      GL_CLIP_PLANE4,
      GL_CLIP_PLANE5,
      GL_CLIP_PLANE5 + 1,
      GL_LIGHTING,
      GL_TEXTURE_2D,
      GL_FOG,
      GL_STENCIL_TEST,
      GL_ALPHA_TEST,
      GL_SCISSOR_TEST,
      GL_DITHER,
      GL_NORMALIZE,
      GL_POLYGON_OFFSET_FILL,
      GL_LINE_STIPPLE,
      GL_COLOR_LOGIC_OP,
      // Client state.
      GL_VERTEX_ARRAY,
      GL_COLOR_ARRAY,
      GL_NORMAL_ARRAY,
      GL_TEXTURE_COORD_ARRAY,
      GL_EDGE_FLAG_ARRAY,
      GL_INDEX_ARRAY,
      // Types.
      GL_BYTE,
      GL_UNSIGNED_BYTE,
      GL_SHORT,
      GL_UNSIGNED_SHORT,
      GL_INT,
      GL_UNSIGNED_INT,
      GL_FLOAT,
      GL_DOUBLE,
      GL_BITMAP,
      GL_UNSIGNED_BYTE_3_3_2,
      GL_UNSIGNED_SHORT_5_6_5,
      GL_UNSIGNED_SHORT_4_4_4_4_REV,
      GL_UNSIGNED_INT_8_8_8_8,
      GL_UNSIGNED_INT_2_10_10_10_REV,
      GL_UNSIGNED_INT_10_10_10_2,
      GL_UNSIGNED_SHORT_1_5_5_5_REV,
      // Pixel formats.
      GL_RGBA,
      GL_RGB,
      GL_BGRA,
      GL_BGR,
      GL_RED,
      GL_GREEN,
      GL_BLUE,
      GL_ALPHA,
      GL_LUMINANCE,
      GL_LUMINANCE_ALPHA,
      GL_DEPTH_COMPONENT,
      GL_STENCIL_INDEX,
      GL_COLOR_INDEX,
      // Matrices.
      GL_MODELVIEW,
      GL_PROJECTION,
      GL_TEXTURE,
      GL_COLOR,
      // Faces, winding, polygon modes, shading.
      GL_FRONT,
      GL_BACK,
      GL_FRONT_AND_BACK,
      GL_CW,
      GL_CCW,
      GL_POINT,
      GL_LINE,
      GL_FILL,
      GL_FLAT,
      GL_SMOOTH,
      // Depth functions.
      GL_NEVER,
      GL_LESS,
      GL_EQUAL,
      GL_LEQUAL,
      GL_GREATER,
      GL_NOTEQUAL,
      GL_GEQUAL,
      GL_ALWAYS,
      // Blending.
      GL_ZERO,
      GL_ONE,
      GL_SRC_COLOR,
      GL_ONE_MINUS_SRC_COLOR,
      GL_SRC_ALPHA,
      GL_ONE_MINUS_SRC_ALPHA,
      GL_DST_ALPHA,
      GL_ONE_MINUS_DST_ALPHA,
      GL_DST_COLOR,
      GL_ONE_MINUS_DST_COLOR,
      GL_SRC_ALPHA_SATURATE,
      GL_CONSTANT_COLOR,
      GL_ONE_MINUS_CONSTANT_COLOR,
      GL_CONSTANT_ALPHA,
      GL_ONE_MINUS_CONSTANT_ALPHA,
      GL_FUNC_ADD,
      GL_FUNC_SUBTRACT,
      GL_FUNC_REVERSE_SUBTRACT,
      GL_MIN,
      GL_MAX,
      // Pixel store.
      GL_PACK_ALIGNMENT,
      GL_PACK_ROW_LENGTH,
      GL_PACK_SKIP_ROWS,
      GL_PACK_SKIP_PIXELS,
      GL_PACK_SWAP_BYTES,
      GL_PACK_LSB_FIRST,
      GL_PACK_IMAGE_HEIGHT,
      GL_PACK_SKIP_IMAGES,
      GL_UNPACK_ALIGNMENT,
      GL_UNPACK_ROW_LENGTH,
      // Buffers.
      GL_ARRAY_BUFFER,
      GL_ELEMENT_ARRAY_BUFFER,
      GL_PIXEL_PACK_BUFFER,
      GL_STATIC_DRAW,
      GL_DYNAMIC_DRAW,
      GL_STREAM_READ,
      GL_READ_ONLY,
      GL_WRITE_ONLY,
      GL_READ_WRITE,
      GL_BUFFER_SIZE,
      GL_BUFFER_USAGE,
      GL_BUFFER_ACCESS,
      GL_BUFFER_MAPPED,
      GL_BUFFER_MAP_POINTER,
      // Interleaved formats.
      GL_V2F,
      GL_V3F,
      GL_C4UB_V2F,
      GL_C4UB_V3F,
      GL_C3F_V3F,
      GL_N3F_V3F,
      GL_C4F_N3F_V3F,
      GL_T2F_V3F,
      GL_T4F_V4F,
      GL_T2F_C4UB_V3F,
      GL_T2F_C3F_V3F,
      GL_T2F_N3F_V3F,
      GL_T2F_C4F_N3F_V3F,
      GL_T4F_C4F_N3F_V4F,
      // Queries.
      GL_VIEWPORT,
      GL_DEPTH_RANGE,
      GL_MODELVIEW_MATRIX,
      GL_PROJECTION_MATRIX,
      GL_TRANSPOSE_MODELVIEW_MATRIX,
      GL_CURRENT_COLOR,
      GL_CURRENT_NORMAL,
      GL_CURRENT_TEXTURE_COORDS,
      GL_MAX_VIEWPORT_DIMS,
      GL_COLOR_CLEAR_VALUE,
      GL_BLEND_COLOR,
      GL_COLOR_WRITEMASK,
      GL_POLYGON_MODE,
      GL_VERTEX_ARRAY_POINTER,
      GL_COLOR_ARRAY_POINTER,
      GL_VERTEX_ARRAY_SIZE,
      GL_VERTEX_ARRAY_STRIDE,
      GL_CLIENT_ATTRIB_STACK_DEPTH,
      GL_MODELVIEW_STACK_DEPTH,
      GL_MAX_CLIP_PLANES,
      GL_SUBPIXEL_BITS,
      GL_EDGE_FLAG,
      GL_VENDOR,
      GL_RENDERER,
      GL_VERSION,
      GL_EXTENSIONS,
      // Hints.
      GL_PERSPECTIVE_CORRECTION_HINT,
      GL_NICEST,
      GL_FASTEST,
      GL_DONT_CARE,
      // Capabilities and queries of the later command families.
      GL_TEXTURE_1D,
      GL_TEXTURE_3D,
      GL_TEXTURE_CUBE_MAP,
      GL_TEXTURE_GEN_S,
      GL_TEXTURE_GEN_Q,
      GL_MAP1_VERTEX_3,
      GL_MAP2_VERTEX_4,
      GL_MAP2_TEXTURE_COORD_2,
      GL_AUTO_NORMAL,
      GL_COLOR_MATERIAL,
      GL_LIGHT0,
      GL_LIGHT7,
      GL_POINT_SMOOTH,
      GL_LINE_SMOOTH,
      GL_POLYGON_SMOOTH,
      GL_POLYGON_STIPPLE,
      GL_COLOR_SUM,
      GL_FOG_COORD_ARRAY,
      GL_SECONDARY_COLOR_ARRAY,
      GL_MULTISAMPLE,
      GL_SAMPLE_ALPHA_TO_COVERAGE,
      GL_RESCALE_NORMAL,
      GL_POLYGON_OFFSET_LINE,
      GL_MAP_COLOR,
      GL_MAP_STENCIL,
      GL_LIST_INDEX,
      GL_LIST_MODE,
      GL_NAME_STACK_DEPTH,
      GL_FEEDBACK_BUFFER_POINTER,
      GL_SELECTION_BUFFER_POINTER,
      GL_CURRENT_RASTER_POSITION,
      GL_CURRENT_RASTER_TEXTURE_COORDS,
      GL_ACCUM_CLEAR_VALUE,
      GL_FOG_COLOR,
      GL_PIXEL_MAP_I_TO_R_SIZE,
      GL_MAP1_GRID_DOMAIN,
      GL_MAP2_GRID_SEGMENTS,
      GL_TEXTURE_BINDING_2D,
      GL_TEXTURE_MATRIX,
      GL_ACTIVE_TEXTURE,
      GL_CLIENT_ACTIVE_TEXTURE,
      GL_POINT_DISTANCE_ATTENUATION,
      GL_LINE_STIPPLE_PATTERN,
      GL_ZOOM_X,
      GL_RED_SCALE,
      GL_INDEX_SHIFT,
      GL_LIGHT_MODEL_AMBIENT,
      GL_CURRENT_SECONDARY_COLOR,
      GL_CURRENT_FOG_COORD,
      GL_ATTRIB_STACK_DEPTH,
      GL_UNPACK_SKIP_IMAGES,
      GL_UNPACK_IMAGE_HEIGHT,
      GL_UNPACK_SKIP_ROWS,
      GL_UNPACK_SKIP_PIXELS,
      GL_UNPACK_LSB_FIRST,
      GL_UNPACK_SWAP_BYTES,
  };
  static constexpr int kEnumCount = static_cast<int>(sizeof(kEnums) / sizeof(kEnums[0]));

  const uint8_t* p_;
  const uint8_t* end_;
};

} // namespace pineda::fuzz
