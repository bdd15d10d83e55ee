// State queries (GL 2.1 §6.1): glGetError, glGetString, glGet{Boolean,Integer,Float,Double}v,
// glGetPointerv. One table-like switch produces typed values; the conversions between types
// follow §6.1.2.
#include <cmath>
#include <limits>

#include "core/api_util.h"
#include "core/version.h"
#include "dispatch.h"
#include "state/raster_modes_hooks.h"

namespace pineda {

bool query_enabled(Context* ctx, GLenum cap, bool* value); // enable.cpp
// texenv.cpp: up to 16 values; kind 0 integer, 1 boolean, 2 float, 3 normalized.
bool texpipe_get(Context* ctx, GLenum pname, int* kind, double* values, int* count);
int texture_get_values(Context* ctx, GLenum pname, double* v, bool* is_float); // texture/
// Pixel transfer, pixel map sizes, zoom and raster position (pixel.cpp): the number of values
// written to v (0: not a pixel query) and their kind as the Kind enum's index.
int pixel_query(const Context* ctx, GLenum pname, double* v, int* kind);
// Evaluator limits and grids (eval.cpp), as pixel_query.
int eval_query(const Context* ctx, GLenum pname, double* v, int* kind);
// EXT_vertex_array's *_ARRAY_COUNT_EXT (ext_commands.cpp): one integer.
bool varray_ext_count(const Context* ctx, GLenum pname, double* value);

namespace {

enum class Kind { Int, Bool, Float, Normalized };

// Up to 16 values of one kind. Normalized values (colours, depth range, depth clear value,
// normals) map to the full integer range in GetIntegerv (§6.1.2).
struct Values {
  Kind kind = Kind::Int;
  int n = 0;
  double v[16] = {};
  void add(double x) { v[n++] = x; }
};

void put_matrix(Values& out, const glm::mat4& m, bool transpose) {
  out.kind = Kind::Float;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      out.add(transpose ? m[r][c] : m[c][r]);
}

const ClientArray* array_for(Context* ctx, GLenum pname) {
  switch (pname) {
  case GL_VERTEX_ARRAY_SIZE:
  case GL_VERTEX_ARRAY_TYPE:
  case GL_VERTEX_ARRAY_STRIDE:
  case GL_VERTEX_ARRAY_BUFFER_BINDING:
    return &ctx->arrays.vertex;
  case GL_COLOR_ARRAY_SIZE:
  case GL_COLOR_ARRAY_TYPE:
  case GL_COLOR_ARRAY_STRIDE:
  case GL_COLOR_ARRAY_BUFFER_BINDING:
    return &ctx->arrays.color;
  case GL_NORMAL_ARRAY_TYPE:
  case GL_NORMAL_ARRAY_STRIDE:
  case GL_NORMAL_ARRAY_BUFFER_BINDING:
    return &ctx->arrays.normal;
  case GL_TEXTURE_COORD_ARRAY_SIZE:
  case GL_TEXTURE_COORD_ARRAY_TYPE:
  case GL_TEXTURE_COORD_ARRAY_STRIDE:
  case GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING:
    return &ctx->arrays.texcoord[ctx->client_active_texture];
  case GL_EDGE_FLAG_ARRAY_STRIDE:
  case GL_EDGE_FLAG_ARRAY_BUFFER_BINDING:
    return &ctx->arrays.edgeflag;
  case GL_SECONDARY_COLOR_ARRAY_SIZE:
  case GL_SECONDARY_COLOR_ARRAY_TYPE:
  case GL_SECONDARY_COLOR_ARRAY_STRIDE:
  case GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING:
    return &ctx->arrays.secondary;
  case GL_FOG_COORD_ARRAY_TYPE:
  case GL_FOG_COORD_ARRAY_STRIDE:
  case GL_FOG_COORD_ARRAY_BUFFER_BINDING:
    return &ctx->arrays.fog;
  default:
    return nullptr;
  }
}

// Fill `out` for pname; false when pname is not a state Pineda has.
bool get_values(Context* ctx, GLenum pname, Values& out) {
  bool enabled = false;
  if (query_enabled(ctx, pname, &enabled)) {
    out.kind = Kind::Bool;
    out.add(enabled ? 1 : 0);
    return true;
  }
  // Texture object bindings and limits (src/texture/texture_object.cpp).
  double tv[4];
  bool tf = false;
  if (const int tn = texture_get_values(ctx, pname, tv, &tf)) {
    if (tf) out.kind = Kind::Float;
    for (int i = 0; i < tn; ++i)
      out.add(tv[i]);
    return true;
  }
  {
    // Selection, feedback and accumulation-buffer state (src/state/select.cpp).
    bool normalized = false;
    if (select_state_values(ctx, pname, out.v, &out.n, &normalized)) {
      if (normalized) out.kind = Kind::Normalized;
      return true;
    }
  }
  if (int kind = 0; (out.n = pixel_query(ctx, pname, out.v, &kind)) > 0) {
    out.kind = static_cast<Kind>(kind);
    return true;
  }
  if (int kind = 0; (out.n = eval_query(ctx, pname, out.v, &kind)) > 0) {
    out.kind = static_cast<Kind>(kind);
    return true;
  }
  if (const ClientArray* a = array_for(ctx, pname)) {
    switch (pname) {
    case GL_VERTEX_ARRAY_SIZE:
    case GL_COLOR_ARRAY_SIZE:
    case GL_TEXTURE_COORD_ARRAY_SIZE:
    case GL_SECONDARY_COLOR_ARRAY_SIZE:
      out.add(a->size);
      break;
    case GL_VERTEX_ARRAY_TYPE:
    case GL_COLOR_ARRAY_TYPE:
    case GL_NORMAL_ARRAY_TYPE:
    case GL_TEXTURE_COORD_ARRAY_TYPE:
    case GL_SECONDARY_COLOR_ARRAY_TYPE:
    case GL_FOG_COORD_ARRAY_TYPE:
      out.add(a->type);
      break;
    case GL_VERTEX_ARRAY_STRIDE:
    case GL_COLOR_ARRAY_STRIDE:
    case GL_NORMAL_ARRAY_STRIDE:
    case GL_TEXTURE_COORD_ARRAY_STRIDE:
    case GL_EDGE_FLAG_ARRAY_STRIDE:
    case GL_SECONDARY_COLOR_ARRAY_STRIDE:
    case GL_FOG_COORD_ARRAY_STRIDE:
      out.add(a->stride);
      break;
    default:
      out.add(a->buffer);
      break;
    }
    return true;
  }
  RasterModeValues rm; // point, line and polygon modes and their limits (raster_modes.cpp)
  if (raster_mode_query(ctx, pname, rm)) {
    out.kind = rm.is_float ? Kind::Float : Kind::Int;
    for (int i = 0; i < rm.n; ++i)
      out.add(rm.v[i]);
    return true;
  }
  double list_value = 0;
  if (query_display_list(ctx, pname, &list_value)) {
    out.add(list_value);
    return true;
  }
  // Colour index, index array and multisample state (src/state/multisample.cpp).
  if (int kind = 0; (out.n = misc_query(ctx, pname, out.v, &kind)) > 0) {
    out.kind = static_cast<Kind>(kind);
    return true;
  }
  const Framebuffer& fb = ctx->fb;
  switch (pname) {
  // Current values (Table 6.5).
  case GL_CURRENT_COLOR:
    out.kind = Kind::Normalized;
    for (float c : ctx->cur_color)
      out.add(c);
    return true;
  case GL_CURRENT_SECONDARY_COLOR:
    out.kind = Kind::Normalized;
    for (float c : ctx->cur_color2)
      out.add(c);
    return true;
  case GL_CURRENT_NORMAL:
    out.kind = Kind::Normalized;
    for (float c : ctx->cur_normal)
      out.add(c);
    return true;
  case GL_CURRENT_TEXTURE_COORDS:
    out.kind = Kind::Float;
    for (float c : ctx->cur_tex[ctx->active_texture])
      out.add(c);
    return true;
  case GL_EDGE_FLAG:
    out.kind = Kind::Bool;
    out.add(ctx->cur_edge ? 1 : 0);
    return true;

  // Transformation (Table 6.6).
  case GL_MATRIX_MODE:
    out.add(ctx->matrix_mode);
    return true;
  case GL_MODELVIEW_MATRIX:
    put_matrix(out, ctx->modelview.top(), false);
    return true;
  case GL_PROJECTION_MATRIX:
    put_matrix(out, ctx->projection.top(), false);
    return true;
  case GL_TEXTURE_MATRIX:
    put_matrix(out, ctx->texture[ctx->active_texture].top(), false);
    return true;
  case GL_TRANSPOSE_MODELVIEW_MATRIX:
    put_matrix(out, ctx->modelview.top(), true);
    return true;
  case GL_TRANSPOSE_PROJECTION_MATRIX:
    put_matrix(out, ctx->projection.top(), true);
    return true;
  case GL_TRANSPOSE_TEXTURE_MATRIX:
    put_matrix(out, ctx->texture[ctx->active_texture].top(), true);
    return true;
  case GL_MODELVIEW_STACK_DEPTH:
    out.add(double(ctx->modelview.stack.size()));
    return true;
  case GL_PROJECTION_STACK_DEPTH:
    out.add(double(ctx->projection.stack.size()));
    return true;
  case GL_TEXTURE_STACK_DEPTH:
    out.add(double(ctx->texture[ctx->active_texture].stack.size()));
    return true;
  case GL_VIEWPORT:
    out.add(ctx->vp_x), out.add(ctx->vp_y), out.add(ctx->vp_w), out.add(ctx->vp_h);
    return true;
  case GL_DEPTH_RANGE:
    out.kind = Kind::Normalized;
    out.add(ctx->depth_near), out.add(ctx->depth_far);
    return true;

  // Lighting (Tables 6.11-6.13); lights and materials are read with GetLight / GetMaterial.
  case GL_COLOR_MATERIAL_FACE:
    out.add(ctx->lighting.color_material_face);
    return true;
  case GL_COLOR_MATERIAL_PARAMETER:
    out.add(ctx->lighting.color_material_mode);
    return true;
  case GL_LIGHT_MODEL_AMBIENT:
    out.kind = Kind::Normalized;
    for (float c : ctx->lighting.model_ambient)
      out.add(c);
    return true;
  case GL_LIGHT_MODEL_LOCAL_VIEWER:
    out.kind = Kind::Bool;
    out.add(ctx->lighting.local_viewer ? 1 : 0);
    return true;
  case GL_LIGHT_MODEL_TWO_SIDE:
    out.kind = Kind::Bool;
    out.add(ctx->lighting.two_side ? 1 : 0);
    return true;
  case GL_LIGHT_MODEL_COLOR_CONTROL:
    out.add(ctx->lighting.color_control);
    return true;

  // Rasterization (Tables 6.11-6.12).
  case GL_CULL_FACE_MODE:
    out.add(ctx->cull_face);
    return true;
  case GL_FRONT_FACE:
    out.add(ctx->front_face);
    return true;
  case GL_POLYGON_MODE:
    out.add(ctx->polygon_mode[0]), out.add(ctx->polygon_mode[1]);
    return true;
  case GL_SHADE_MODEL:
    out.add(ctx->shade_model);
    return true;
  case GL_POINT_SIZE:
    out.kind = Kind::Float;
    out.add(ctx->point_size);
    return true;
  case GL_LINE_WIDTH:
    out.kind = Kind::Float;
    out.add(ctx->line_width);
    return true;

  // Pixel operations and framebuffer control (Tables 6.20-6.22).
  case GL_DEPTH_FUNC:
    out.add(ctx->depth_func);
    return true;
  case GL_DEPTH_WRITEMASK:
    out.kind = Kind::Bool;
    out.add(ctx->depth_mask ? 1 : 0);
    return true;
  case GL_DEPTH_CLEAR_VALUE:
    out.kind = Kind::Normalized;
    out.add(ctx->clear_depth);
    return true;
  case GL_COLOR_CLEAR_VALUE:
    out.kind = Kind::Normalized;
    for (float c : ctx->clear_color)
      out.add(c);
    return true;
  case GL_COLOR_WRITEMASK:
    out.kind = Kind::Bool;
    for (bool b : ctx->color_mask)
      out.add(b ? 1 : 0);
    return true;
  case GL_STENCIL_CLEAR_VALUE:
    out.add(ctx->clear_stencil);
    return true;
  case GL_SCISSOR_BOX:
    for (GLint v : ctx->scissor_box)
      out.add(v);
    return true;
  case GL_ALPHA_TEST_FUNC:
    out.add(ctx->alpha_func);
    return true;
  case GL_ALPHA_TEST_REF:
    out.kind = Kind::Normalized;
    out.add(ctx->alpha_ref);
    return true;
  case GL_STENCIL_FUNC:
    out.add(ctx->stencil_func);
    return true;
  // GL 2.1 §4.1.5: the reference reads back clamped to [0, 2^s - 1].
  case GL_STENCIL_REF: {
    const int top = fb.stencil ? (1 << fb.stencil_bits) - 1 : 0;
    out.add(ctx->stencil_ref < 0 ? 0 : (ctx->stencil_ref > top ? top : ctx->stencil_ref));
    return true;
  }
  case GL_STENCIL_VALUE_MASK:
    out.add(ctx->stencil_value_mask);
    return true;
  case GL_STENCIL_WRITEMASK:
    out.add(ctx->stencil_writemask);
    return true;
  case GL_STENCIL_FAIL:
    out.add(ctx->stencil_fail);
    return true;
  case GL_STENCIL_PASS_DEPTH_FAIL:
    out.add(ctx->stencil_depth_fail);
    return true;
  case GL_STENCIL_PASS_DEPTH_PASS:
    out.add(ctx->stencil_depth_pass);
    return true;
  case GL_LOGIC_OP_MODE:
    out.add(ctx->logic_op);
    return true;
  case GL_DRAW_BUFFER:
    out.add(ctx->draw_buffer);
    return true;
  case GL_READ_BUFFER:
    out.add(ctx->read_buffer);
    return true;
  case GL_BLEND_SRC:
  case GL_BLEND_SRC_RGB:
    out.add(ctx->blend_src_rgb);
    return true;
  case GL_BLEND_DST:
  case GL_BLEND_DST_RGB:
    out.add(ctx->blend_dst_rgb);
    return true;
  case GL_BLEND_SRC_ALPHA:
    out.add(ctx->blend_src_a);
    return true;
  case GL_BLEND_DST_ALPHA:
    out.add(ctx->blend_dst_a);
    return true;
  case GL_BLEND_EQUATION:
    out.add(ctx->blend_eq_rgb);
    return true;
  case GL_BLEND_EQUATION_ALPHA:
    out.add(ctx->blend_eq_a);
    return true;
  case GL_BLEND_COLOR:
    out.kind = Kind::Normalized;
    for (float c : ctx->blend_color)
      out.add(c);
    return true;

  // Hints (Table 6.38).
  case GL_PERSPECTIVE_CORRECTION_HINT:
    out.add(ctx->hint_perspective);
    return true;
  case GL_POINT_SMOOTH_HINT:
    out.add(ctx->hint_point_smooth);
    return true;
  case GL_LINE_SMOOTH_HINT:
    out.add(ctx->hint_line_smooth);
    return true;
  case GL_POLYGON_SMOOTH_HINT:
    out.add(ctx->hint_polygon_smooth);
    return true;
  case GL_FOG_HINT:
    out.add(ctx->hint_fog);
    return true;
  case GL_GENERATE_MIPMAP_HINT:
    out.add(ctx->hint_generate_mipmap);
    return true;
  case GL_TEXTURE_COMPRESSION_HINT:
    out.add(ctx->hint_texture_compression);
    return true;

  // Pixel store (Table 6.23).
  case GL_PACK_SWAP_BYTES:
    out.kind = Kind::Bool;
    out.add(ctx->pack.swap_bytes);
    return true;
  case GL_PACK_LSB_FIRST:
    out.kind = Kind::Bool;
    out.add(ctx->pack.lsb_first);
    return true;
  case GL_PACK_ROW_LENGTH:
    out.add(ctx->pack.row_length);
    return true;
  case GL_PACK_SKIP_ROWS:
    out.add(ctx->pack.skip_rows);
    return true;
  case GL_PACK_SKIP_PIXELS:
    out.add(ctx->pack.skip_pixels);
    return true;
  case GL_PACK_ALIGNMENT:
    out.add(ctx->pack.alignment);
    return true;
  case GL_PACK_IMAGE_HEIGHT:
    out.add(ctx->pack.image_height);
    return true;
  case GL_PACK_SKIP_IMAGES:
    out.add(ctx->pack.skip_images);
    return true;
  case GL_UNPACK_SWAP_BYTES:
    out.kind = Kind::Bool;
    out.add(ctx->unpack.swap_bytes);
    return true;
  case GL_UNPACK_LSB_FIRST:
    out.kind = Kind::Bool;
    out.add(ctx->unpack.lsb_first);
    return true;
  case GL_UNPACK_ROW_LENGTH:
    out.add(ctx->unpack.row_length);
    return true;
  case GL_UNPACK_SKIP_ROWS:
    out.add(ctx->unpack.skip_rows);
    return true;
  case GL_UNPACK_SKIP_PIXELS:
    out.add(ctx->unpack.skip_pixels);
    return true;
  case GL_UNPACK_ALIGNMENT:
    out.add(ctx->unpack.alignment);
    return true;
  case GL_UNPACK_IMAGE_HEIGHT:
    out.add(ctx->unpack.image_height);
    return true;
  case GL_UNPACK_SKIP_IMAGES:
    out.add(ctx->unpack.skip_images);
    return true;

  // Vertex arrays and buffer objects (Tables 6.7-6.9).
  case GL_ARRAY_BUFFER_BINDING:
    out.add(ctx->array_buffer);
    return true;
  case GL_ELEMENT_ARRAY_BUFFER_BINDING:
    out.add(ctx->element_array_buffer);
    return true;
  case GL_CLIENT_ATTRIB_STACK_DEPTH:
    out.add(double(ctx->client_attrib_stack.size()));
    return true;
  case GL_ATTRIB_STACK_DEPTH:
    out.add(double(ctx->attrib_stack.size()));
    return true; // §6.1.14

  // Framebuffer (Table 6.34 / 6.35).
  case GL_RED_BITS:
  case GL_GREEN_BITS:
  case GL_BLUE_BITS:
    out.add(fb.color ? 8 : 0);
    return true;
  case GL_ALPHA_BITS:
    out.add(fb.color ? fb.alpha_bits : 0);
    return true;
  case GL_DEPTH_BITS:
    out.add(fb.depth ? fb.depth_bits : 0);
    return true;
  case GL_STENCIL_BITS:
    out.add(fb.stencil ? fb.stencil_bits : 0);
    return true;
  case GL_AUX_BUFFERS:
  case GL_INDEX_BITS:
    out.add(0);
    return true;
  case GL_RGBA_MODE:
    out.kind = Kind::Bool;
    out.add(1);
    return true;
  case GL_INDEX_MODE:
  case GL_DOUBLEBUFFER:
  case GL_STEREO:
    out.kind = Kind::Bool;
    out.add(0);
    return true;

  // Implementation limits (Tables 6.36-6.37).
  case GL_SUBPIXEL_BITS:
    out.add(kSubpixelBits);
    return true;
  case GL_MAX_VIEWPORT_DIMS:
    out.add(kMaxViewportDim), out.add(kMaxViewportDim);
    return true;
  case GL_MAX_CLIP_PLANES:
    out.add(kMaxClipPlanes);
    return true;
  case GL_MAX_LIGHTS:
    out.add(kMaxLights);
    return true;
  case GL_MAX_MODELVIEW_STACK_DEPTH:
    out.add(double(kModelviewStackDepth));
    return true;
  case GL_MAX_PROJECTION_STACK_DEPTH:
    out.add(double(kProjectionStackDepth));
    return true;
  case GL_MAX_TEXTURE_STACK_DEPTH:
    out.add(double(kTextureStackDepth));
    return true;
  case GL_MAX_CLIENT_ATTRIB_STACK_DEPTH:
    out.add(double(kClientAttribStackDepth));
    return true;
  case GL_MAX_ATTRIB_STACK_DEPTH:
    out.add(double(kAttribStackDepth));
    return true;
  // GL 1.2 DrawRangeElements recommendations: Pineda has no such limit; report large values.
  case GL_MAX_ELEMENTS_VERTICES:
  case GL_MAX_ELEMENTS_INDICES:
    out.add(kMaxElementsVertices);
    return true;
  // GL 2.1 §3.8.1: no specific compressed internal formats (src/texture/tex_compressed.cpp).
  case GL_NUM_COMPRESSED_TEXTURE_FORMATS:
    out.add(0);
    return true;
  case GL_COMPRESSED_TEXTURE_FORMATS:
    return true;
  default: {
    if (varray_ext_count(ctx, pname, out.v)) {
      out.n = 1;
      return true;
    }
    // Texture units, texture environment and generation, fog (src/state/texenv.cpp).
    int kind = 0;
    if (!texpipe_get(ctx, pname, &kind, out.v, &out.n)) return false;
    out.kind = static_cast<Kind>(kind);
    return true;
  }
  }
}

// Shared front half of every glGet*v: context, Begin/End check, lookup, error.
bool lookup(const char* func, GLenum pname, Values& out, Context** ctx_out) {
  Context* ctx = outside_begin_end(func);
  if (ctx == nullptr) return false;
  *ctx_out = ctx;
  if (!get_values(ctx, pname, out)) {
    record_error(ctx, GL_INVALID_ENUM, func, pname);
    return false;
  }
  return true;
}

// §6.1.2: floating-point to integer conversion.
GLint to_int(const Values& vals, int i) {
  const double x = vals.v[i];
  if (vals.kind == Kind::Normalized) {
    // 1.0 maps to the most positive integer, -1.0 to the most negative.
    const double scaled = x * 2147483647.0;
    if (scaled >= 2147483647.0) return std::numeric_limits<GLint>::max();
    if (scaled <= -2147483648.0) return std::numeric_limits<GLint>::min();
    return static_cast<GLint>(std::llround(scaled));
  }
  if (!(x == x)) return 0;
  if (x >= 2147483647.0) return std::numeric_limits<GLint>::max();
  if (x <= -2147483648.0) return std::numeric_limits<GLint>::min();
  return static_cast<GLint>(std::llround(x));
}

} // namespace

namespace exec {

GLenum GLAPIENTRY GetError() {
  Context* ctx = current_context();
  if (ctx == nullptr) return GL_NO_ERROR;
  if (ctx->begin_mode != kOutsideBeginEnd) {
    record_error(ctx, GL_INVALID_OPERATION, "glGetError");
    return GL_NO_ERROR;
  }
  const GLenum e = ctx->error;
  ctx->error = GL_NO_ERROR;
  return e;
}

const GLubyte* GLAPIENTRY GetString(GLenum name) {
  Context* ctx = outside_begin_end("glGetString");
  if (ctx == nullptr) return nullptr;
  const char* s = nullptr;
  switch (name) {
  case GL_VENDOR:
    s = "Pineda";
    break;
  case GL_RENDERER:
    s = "Pineda (CPU rasterizer)";
    break;
  case GL_VERSION:
    s = kGLVersionString;
    break; // core/version.h
  case GL_EXTENSIONS:
    s = kGLExtensions;
    break;
  default:
    record_error(ctx, GL_INVALID_ENUM, "glGetString", name);
    return nullptr;
  }
  return reinterpret_cast<const GLubyte*>(s);
}

void GLAPIENTRY GetBooleanv(GLenum pname, GLboolean* params) {
  Values v;
  Context* ctx = nullptr;
  if (!lookup("glGetBooleanv", pname, v, &ctx) || params == nullptr) return;
  for (int i = 0; i < v.n; ++i)
    params[i] = v.v[i] != 0.0 ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY GetIntegerv(GLenum pname, GLint* params) {
  Values v;
  Context* ctx = nullptr;
  if (!lookup("glGetIntegerv", pname, v, &ctx) || params == nullptr) return;
  for (int i = 0; i < v.n; ++i)
    params[i] = to_int(v, i);
}

void GLAPIENTRY GetFloatv(GLenum pname, GLfloat* params) {
  Values v;
  Context* ctx = nullptr;
  if (!lookup("glGetFloatv", pname, v, &ctx) || params == nullptr) return;
  for (int i = 0; i < v.n; ++i)
    params[i] = static_cast<GLfloat>(v.v[i]);
}

void GLAPIENTRY GetDoublev(GLenum pname, GLdouble* params) {
  Values v;
  Context* ctx = nullptr;
  if (!lookup("glGetDoublev", pname, v, &ctx) || params == nullptr) return;
  for (int i = 0; i < v.n; ++i)
    params[i] = v.v[i];
}

void GLAPIENTRY GetPointerv(GLenum pname, void** params) {
  PINEDA_CTX_OUTSIDE("glGetPointerv");
  const void* p = nullptr;
  void* special = nullptr; // selection and feedback arrays (src/state/select.cpp)
  if (select_state_pointer(ctx, pname, &special)) {
    if (params != nullptr) *params = special;
    return;
  }
  switch (pname) {
  case GL_VERTEX_ARRAY_POINTER:
    p = ctx->arrays.vertex.pointer;
    break;
  case GL_COLOR_ARRAY_POINTER:
    p = ctx->arrays.color.pointer;
    break;
  case GL_NORMAL_ARRAY_POINTER:
    p = ctx->arrays.normal.pointer;
    break;
  case GL_TEXTURE_COORD_ARRAY_POINTER:
    p = ctx->arrays.texcoord[ctx->client_active_texture].pointer;
    break;
  case GL_EDGE_FLAG_ARRAY_POINTER:
    p = ctx->arrays.edgeflag.pointer;
    break;
  case GL_SECONDARY_COLOR_ARRAY_POINTER:
    p = ctx->arrays.secondary.pointer;
    break;
  case GL_FOG_COORD_ARRAY_POINTER:
    p = ctx->arrays.fog.pointer;
    break;
  case GL_INDEX_ARRAY_POINTER:
    p = ctx->arrays.index.pointer;
    break;
  default:
    return record_error(ctx, GL_INVALID_ENUM, "glGetPointerv", pname);
  }
  if (params != nullptr) *params = const_cast<void*>(p);
}

} // namespace exec
} // namespace pineda
