// Vertex arrays (GL 2.1 §2.8): array pointers, glArrayElement, the Draw* commands,
// glInterleavedArrays; and the vertex-array area (Tables 6.6-6.9, varray.h): client
// capabilities, queries, pointers and the client vertex-array group.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>

#include "state/api_util.h"
#include "dispatch.h"
#include "state/area.h"
#include "state/fetch.h"
#include "state/draw_call.h"

namespace pineda {

namespace {

bool valid_mode(GLenum mode) {
  return mode <= GL_POLYGON;
}

void set_pointer(const char* func, ClientArray& a, GLint size, GLenum type, GLsizei stride,
                 const void* ptr, Context* ctx) {
  (void)func;
  a.size = size;
  a.type = type;
  a.stride = stride;
  a.pointer = ptr;
  a.buffer = ctx->arrays.array_buffer;
}

bool type_in(GLenum type, std::initializer_list<GLenum> allowed) {
  return std::find(allowed.begin(), allowed.end(), type) != allowed.end();
}

// GL 1.5 §2.9: drawing from a mapped buffer is INVALID_OPERATION.
bool arrays_mapped(Context* ctx, bool with_elements) {
  auto mapped = [ctx](GLuint name) {
    if (name == 0) return false;
    auto it = ctx->buffers.find(name);
    return it != ctx->buffers.end() && it->second->mapped;
  };
  const VertexArrayGroup& a = ctx->arrays;
  if ((a.vertex.enabled && mapped(a.vertex.buffer)) ||
      (a.color.enabled && mapped(a.color.buffer)) ||
      (a.normal.enabled && mapped(a.normal.buffer)) ||
      (a.texcoord[0].enabled && mapped(a.texcoord[0].buffer)) ||
      (a.texcoord[1].enabled && mapped(a.texcoord[1].buffer)) ||
      (a.texcoord[2].enabled && mapped(a.texcoord[2].buffer)) ||
      (a.texcoord[3].enabled && mapped(a.texcoord[3].buffer)) ||
      (a.fog.enabled && mapped(a.fog.buffer)) ||
      (a.edgeflag.enabled && mapped(a.edgeflag.buffer)) ||
      (a.secondary.enabled && mapped(a.secondary.buffer)))
    return true;
  for (const GenericArray& g : ctx->attrib_arrays.array)
    if (g.enabled && mapped(g.buffer)) return true;
  return with_elements && mapped(ctx->arrays.element_array_buffer);
}

// GL 2.1 §2.8: a draw needs the vertex array or generic array 0, which takes its place.
bool has_vertex_array(const Context* ctx) {
  return ctx->arrays.vertex.enabled || generic_array0_enabled(ctx);
}

// The generic arrays of a draw: the enabled ones the vertex shader reads.
uint32_t generic_draw_mask(const Context* ctx) {
  const LinkedProgram* program = active_program(ctx);
  if (program == nullptr || !program->has_vertex) return 0;
  return program->generic_inputs & enabled_generic_arrays(ctx);
}

// After the conventional arrays were fetched into verts[0..n) for elements el: the positions
// of generic array 0 when it is enabled, and the generic arrays of the draw into
// ctx->generic_scratch. False when an array would be read outside its buffer.
template <typename Fetch>
bool fetch_generics(Context* ctx, InputVertex* verts, size_t n, Fetch fetch, GenericVertices& out) {
  if (generic_array0_enabled(ctx)) {
    std::vector<float> pos(4 * n);
    if (!fetch(1u, pos.data())) return false;
    for (size_t k = 0; k < n; ++k)
      std::copy(&pos[4 * k], &pos[4 * k] + 4, verts[k].pos);
  }
  const uint32_t mask = generic_draw_mask(ctx);
  if (mask == 0) return true;
  ctx->generic_scratch.resize(4 * static_cast<size_t>(std::popcount(mask)) * n);
  if (!fetch(mask, ctx->generic_scratch.data())) return false;
  out = {ctx->generic_scratch.data(), mask};
  return true;
}

// Draw elements [first, first+count) of the enabled arrays.
void draw_range(Context* ctx, GLenum mode, size_t first, size_t count) {
  // GL 2.1 §2.8: without the vertex array enabled nothing is drawn.
  if (count == 0 || !has_vertex_array(ctx)) return;
  if (!arrays_hold(ctx, first + count - 1)) return;
  ctx->fetch_scratch.resize(count);
  if (!fetch_range(ctx, first, count, ctx->fetch_scratch.data(), input_tex_units(ctx))) return;
  GenericVertices generic;
  if (!fetch_generics(
          ctx, ctx->fetch_scratch.data(), count,
          [&](uint32_t mask, float* out) {
            return fetch_generic_range(ctx, mask, first, count, out);
          },
          generic))
    return;
  draw_vertices(ctx, mode, ctx->fetch_scratch.data(), count, nullptr, count, generic);
}

// Read `count` indices of `type` at `indices` (a buffer offset when an element buffer is
// bound) into ctx->index_scratch; false when they would be read outside the buffer.
bool read_indices(Context* ctx, GLsizei count, GLenum type, const void* indices) {
  const uint8_t* src = static_cast<const uint8_t*>(indices);
  const size_t bytes = static_cast<size_t>(count) * type_size(type);
  if (ctx->arrays.element_array_buffer != 0) {
    auto it = ctx->buffers.find(ctx->arrays.element_array_buffer);
    if (it == ctx->buffers.end()) return false;
    const size_t offset = reinterpret_cast<uintptr_t>(indices);
    if (offset > it->second->data.size() || bytes > it->second->data.size() - offset) return false;
    src = it->second->data.data() + offset;
  } else if (src == nullptr) {
    return false;
  }
  ctx->index_scratch.resize(static_cast<size_t>(count));
  uint32_t* dst = ctx->index_scratch.data();
  switch (type) {
  case GL_UNSIGNED_BYTE:
    for (GLsizei i = 0; i < count; ++i)
      dst[i] = src[i];
    break;
  case GL_UNSIGNED_SHORT:
    for (GLsizei i = 0; i < count; ++i) {
      GLushort v;
      std::memcpy(&v, src + 2 * i, 2);
      dst[i] = v;
    }
    break;
  default:
    std::memcpy(dst, src, bytes);
    break;
  }
  return true;
}

// Fetch the index range [lo, hi] once and rebase the indices, unless the range is much wider
// than the draw, in which case each index is fetched on its own.
void draw_indexed(Context* ctx, GLenum mode, GLsizei count, GLenum type, const void* indices) {
  if (count == 0 || !has_vertex_array(ctx)) return;
  if (!read_indices(ctx, count, type, indices)) return;
  std::vector<uint32_t>& idx = ctx->index_scratch;
  const auto [lo_it, hi_it] = std::minmax_element(idx.begin(), idx.end());
  const uint32_t lo = *lo_it, hi = *hi_it;
  const size_t span = static_cast<size_t>(hi) - lo + 1;
  if (!arrays_hold(ctx, hi)) return;
  if (span <= 4 * static_cast<size_t>(count) + 1024) {
    ctx->fetch_scratch.resize(span);
    if (!fetch_range(ctx, lo, span, ctx->fetch_scratch.data(), input_tex_units(ctx))) return;
    GenericVertices generic;
    if (!fetch_generics(
            ctx, ctx->fetch_scratch.data(), span,
            [&](uint32_t mask, float* out) {
              return fetch_generic_range(ctx, mask, lo, span, out);
            },
            generic))
      return;
    for (uint32_t& i : idx)
      i -= lo;
    draw_vertices(ctx, mode, ctx->fetch_scratch.data(), span, idx.data(), idx.size(), generic);
  } else {
    ctx->fetch_scratch.resize(idx.size());
    if (!fetch_list(ctx, idx.data(), idx.size(), ctx->fetch_scratch.data(), input_tex_units(ctx)))
      return;
    GenericVertices generic;
    if (!fetch_generics(
            ctx, ctx->fetch_scratch.data(), idx.size(),
            [&](uint32_t mask, float* out) {
              return fetch_generic_list(ctx, mask, idx.data(), idx.size(), out);
            },
            generic))
      return;
    draw_vertices(ctx, mode, ctx->fetch_scratch.data(), idx.size(), nullptr, idx.size(), generic);
  }
}

// Validation shared by DrawElements, DrawRangeElements and MultiDrawElements.
bool check_elements(Context* ctx, const char* func, GLenum mode, GLsizei count, GLenum type) {
  if (!valid_mode(mode)) {
    record_error(ctx, GL_INVALID_ENUM, func, mode);
    return false;
  }
  if (count < 0) {
    record_error(ctx, GL_INVALID_VALUE, func);
    return false;
  }
  if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT) {
    record_error(ctx, GL_INVALID_ENUM, func, type);
    return false;
  }
  if (arrays_mapped(ctx, true)) {
    record_error(ctx, GL_INVALID_OPERATION, func);
    return false;
  }
  return true;
}

ClientArray* array_for(Context& ctx, GLenum pname) {
  switch (pname) {
  case GL_VERTEX_ARRAY_SIZE:
  case GL_VERTEX_ARRAY_TYPE:
  case GL_VERTEX_ARRAY_STRIDE:
  case GL_VERTEX_ARRAY_BUFFER_BINDING:
  case GL_VERTEX_ARRAY_COUNT_EXT:
    return &ctx.arrays.vertex;
  case GL_COLOR_ARRAY_SIZE:
  case GL_COLOR_ARRAY_TYPE:
  case GL_COLOR_ARRAY_STRIDE:
  case GL_COLOR_ARRAY_BUFFER_BINDING:
  case GL_COLOR_ARRAY_COUNT_EXT:
    return &ctx.arrays.color;
  case GL_NORMAL_ARRAY_TYPE:
  case GL_NORMAL_ARRAY_STRIDE:
  case GL_NORMAL_ARRAY_BUFFER_BINDING:
  case GL_NORMAL_ARRAY_COUNT_EXT:
    return &ctx.arrays.normal;
  case GL_TEXTURE_COORD_ARRAY_SIZE:
  case GL_TEXTURE_COORD_ARRAY_TYPE:
  case GL_TEXTURE_COORD_ARRAY_STRIDE:
  case GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING:
  case GL_TEXTURE_COORD_ARRAY_COUNT_EXT:
    return &ctx.arrays.texcoord[ctx.arrays.client_active_texture];
  case GL_EDGE_FLAG_ARRAY_STRIDE:
  case GL_EDGE_FLAG_ARRAY_BUFFER_BINDING:
  case GL_EDGE_FLAG_ARRAY_COUNT_EXT:
    return &ctx.arrays.edgeflag;
  case GL_SECONDARY_COLOR_ARRAY_SIZE:
  case GL_SECONDARY_COLOR_ARRAY_TYPE:
  case GL_SECONDARY_COLOR_ARRAY_STRIDE:
  case GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING:
    return &ctx.arrays.secondary;
  case GL_FOG_COORD_ARRAY_TYPE:
  case GL_FOG_COORD_ARRAY_STRIDE:
  case GL_FOG_COORD_ARRAY_BUFFER_BINDING:
    return &ctx.arrays.fog;
  case GL_INDEX_ARRAY_TYPE:
  case GL_INDEX_ARRAY_STRIDE:
  case GL_INDEX_ARRAY_BUFFER_BINDING:
  case GL_INDEX_ARRAY_COUNT_EXT:
    return &ctx.arrays.index;
  default:
    return nullptr;
  }
}

// Tables 6.6-6.9 and the *_ARRAY_COUNT_EXT queries of EXT_vertex_array ("New State").
bool get_arrays(Context& ctx, GLenum pname, QueryValues& out) {
  if (const ClientArray* a = array_for(ctx, pname)) {
    switch (pname) {
    case GL_VERTEX_ARRAY_SIZE:
    case GL_COLOR_ARRAY_SIZE:
    case GL_TEXTURE_COORD_ARRAY_SIZE:
    case GL_SECONDARY_COLOR_ARRAY_SIZE:
      out.ints({double(a->size)});
      return true;
    case GL_VERTEX_ARRAY_TYPE:
    case GL_COLOR_ARRAY_TYPE:
    case GL_NORMAL_ARRAY_TYPE:
    case GL_TEXTURE_COORD_ARRAY_TYPE:
    case GL_SECONDARY_COLOR_ARRAY_TYPE:
    case GL_FOG_COORD_ARRAY_TYPE:
    case GL_INDEX_ARRAY_TYPE:
      out.ints({double(a->type)});
      return true;
    case GL_VERTEX_ARRAY_STRIDE:
    case GL_COLOR_ARRAY_STRIDE:
    case GL_NORMAL_ARRAY_STRIDE:
    case GL_TEXTURE_COORD_ARRAY_STRIDE:
    case GL_EDGE_FLAG_ARRAY_STRIDE:
    case GL_SECONDARY_COLOR_ARRAY_STRIDE:
    case GL_FOG_COORD_ARRAY_STRIDE:
    case GL_INDEX_ARRAY_STRIDE:
      out.ints({double(a->stride)});
      return true;
    case GL_VERTEX_ARRAY_COUNT_EXT:
    case GL_NORMAL_ARRAY_COUNT_EXT:
    case GL_COLOR_ARRAY_COUNT_EXT:
    case GL_INDEX_ARRAY_COUNT_EXT:
    case GL_TEXTURE_COORD_ARRAY_COUNT_EXT:
    case GL_EDGE_FLAG_ARRAY_COUNT_EXT:
      out.ints({double(a->count_ext)});
      return true;
    default:
      out.ints({double(a->buffer)});
      return true;
    }
  }
  switch (pname) {
  case GL_CLIENT_ACTIVE_TEXTURE:
    out.ints({double(GL_TEXTURE0 + ctx.arrays.client_active_texture)});
    return true;
  case GL_ARRAY_BUFFER_BINDING:
    out.ints({double(ctx.arrays.array_buffer)});
    return true;
  case GL_ELEMENT_ARRAY_BUFFER_BINDING:
    out.ints({double(ctx.arrays.element_array_buffer)});
    return true;
  // GL 1.2 DrawRangeElements recommendations.
  case GL_MAX_ELEMENTS_VERTICES:
  case GL_MAX_ELEMENTS_INDICES:
    out.ints({kMaxElementsVertices});
    return true;
  default:
    return false;
  }
}

bool get_array_pointer(Context& ctx, GLenum pname, void** out) {
  const VertexArrayGroup& a = ctx.arrays;
  const void* p = nullptr;
  switch (pname) {
  case GL_VERTEX_ARRAY_POINTER:
    p = a.vertex.pointer;
    break;
  case GL_COLOR_ARRAY_POINTER:
    p = a.color.pointer;
    break;
  case GL_NORMAL_ARRAY_POINTER:
    p = a.normal.pointer;
    break;
  case GL_TEXTURE_COORD_ARRAY_POINTER:
    p = a.texcoord[a.client_active_texture].pointer;
    break;
  case GL_EDGE_FLAG_ARRAY_POINTER:
    p = a.edgeflag.pointer;
    break;
  case GL_SECONDARY_COLOR_ARRAY_POINTER:
    p = a.secondary.pointer;
    break;
  case GL_FOG_COORD_ARRAY_POINTER:
    p = a.fog.pointer;
    break;
  case GL_INDEX_ARRAY_POINTER:
    p = a.index.pointer;
    break;
  default:
    return false;
  }
  *out = const_cast<void*>(p);
  return true;
}

// EnableClientState (§2.8); Enable takes them too (enable.cpp). The texture coordinate array
// is the client active unit's.
constexpr Capability kArrayCaps[] = {
    {GL_VERTEX_ARRAY, 1, CapabilityKind::kClient, 0,
     [](Context& c, unsigned, unsigned) { return &c.arrays.vertex.enabled; }},
    {GL_NORMAL_ARRAY, 1, CapabilityKind::kClient, 0,
     [](Context& c, unsigned, unsigned) { return &c.arrays.normal.enabled; }},
    {GL_COLOR_ARRAY, 1, CapabilityKind::kClient, 0,
     [](Context& c, unsigned, unsigned) { return &c.arrays.color.enabled; }},
    {GL_INDEX_ARRAY, 1, CapabilityKind::kClient, 0,
     [](Context& c, unsigned, unsigned) { return &c.arrays.index.enabled; }},
    {GL_TEXTURE_COORD_ARRAY, 1, CapabilityKind::kClient, 0,
     [](Context& c, unsigned, unsigned) {
       return &c.arrays.texcoord[c.arrays.client_active_texture].enabled;
     }},
    {GL_EDGE_FLAG_ARRAY, 1, CapabilityKind::kClient, 0,
     [](Context& c, unsigned, unsigned) { return &c.arrays.edgeflag.enabled; }},
    {GL_SECONDARY_COLOR_ARRAY, 1, CapabilityKind::kClient, 0,
     [](Context& c, unsigned, unsigned) { return &c.arrays.secondary.enabled; }},
    {GL_FOG_COORD_ARRAY, 1, CapabilityKind::kClient, 0,
     [](Context& c, unsigned, unsigned) { return &c.arrays.fog.enabled; }},
};

constexpr AttribGroup kArrayGroups[] = {
    member_group<&Context::arrays>(GL_CLIENT_VERTEX_ARRAY_BIT, 0, true),
};

} // namespace

const StateArea kVertexArrayArea = {
    .name = "vertex arrays and buffer objects (GL 2.1 §2.8, §2.9, Tables 6.6-6.9)",
    .capabilities = kArrayCaps,
    .get = get_arrays,
    .get_pointer = get_array_pointer,
    .groups = kArrayGroups,
};

namespace exec {

void GLAPIENTRY VertexPointer(GLint size, GLenum type, GLsizei stride, const void* ptr) {
  PINEDA_CTX_OUTSIDE("glVertexPointer");
  if (size < 2 || size > 4 || stride < 0)
    return record_error(ctx, GL_INVALID_VALUE, "glVertexPointer");
  if (!type_in(type, {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}))
    return record_error(ctx, GL_INVALID_ENUM, "glVertexPointer", type);
  set_pointer("glVertexPointer", ctx->arrays.vertex, size, type, stride, ptr, ctx);
}

void GLAPIENTRY ColorPointer(GLint size, GLenum type, GLsizei stride, const void* ptr) {
  PINEDA_CTX_OUTSIDE("glColorPointer");
  if (size < 3 || size > 4 || stride < 0)
    return record_error(ctx, GL_INVALID_VALUE, "glColorPointer");
  if (!type_in(type, {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT,
                      GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE}))
    return record_error(ctx, GL_INVALID_ENUM, "glColorPointer", type);
  set_pointer("glColorPointer", ctx->arrays.color, size, type, stride, ptr, ctx);
}

// GL 2.1 §2.8: the secondary colour array always has three components.
void GLAPIENTRY SecondaryColorPointer(GLint size, GLenum type, GLsizei stride, const void* ptr) {
  PINEDA_CTX_OUTSIDE("glSecondaryColorPointer");
  if (size != 3 || stride < 0)
    return record_error(ctx, GL_INVALID_VALUE, "glSecondaryColorPointer");
  if (!type_in(type, {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT,
                      GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE}))
    return record_error(ctx, GL_INVALID_ENUM, "glSecondaryColorPointer", type);
  set_pointer("glSecondaryColorPointer", ctx->arrays.secondary, size, type, stride, ptr, ctx);
}

// GL 1.4 §2.8: one fog coordinate per element, FLOAT or DOUBLE.
void GLAPIENTRY FogCoordPointer(GLenum type, GLsizei stride, const void* ptr) {
  PINEDA_CTX_OUTSIDE("glFogCoordPointer");
  if (stride < 0) return record_error(ctx, GL_INVALID_VALUE, "glFogCoordPointer");
  if (!type_in(type, {GL_FLOAT, GL_DOUBLE}))
    return record_error(ctx, GL_INVALID_ENUM, "glFogCoordPointer", type);
  set_pointer("glFogCoordPointer", ctx->arrays.fog, 1, type, stride, ptr, ctx);
}

void GLAPIENTRY NormalPointer(GLenum type, GLsizei stride, const void* ptr) {
  PINEDA_CTX_OUTSIDE("glNormalPointer");
  if (stride < 0) return record_error(ctx, GL_INVALID_VALUE, "glNormalPointer");
  if (!type_in(type, {GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}))
    return record_error(ctx, GL_INVALID_ENUM, "glNormalPointer", type);
  set_pointer("glNormalPointer", ctx->arrays.normal, 3, type, stride, ptr, ctx);
}

void GLAPIENTRY TexCoordPointer(GLint size, GLenum type, GLsizei stride, const void* ptr) {
  PINEDA_CTX_OUTSIDE("glTexCoordPointer");
  if (size < 1 || size > 4 || stride < 0)
    return record_error(ctx, GL_INVALID_VALUE, "glTexCoordPointer");
  if (!type_in(type, {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}))
    return record_error(ctx, GL_INVALID_ENUM, "glTexCoordPointer", type);
  set_pointer("glTexCoordPointer", ctx->arrays.texcoord[ctx->arrays.client_active_texture], size,
              type, stride, ptr, ctx);
}

void GLAPIENTRY EdgeFlagPointer(GLsizei stride, const void* ptr) {
  PINEDA_CTX_OUTSIDE("glEdgeFlagPointer");
  if (stride < 0) return record_error(ctx, GL_INVALID_VALUE, "glEdgeFlagPointer");
  set_pointer("glEdgeFlagPointer", ctx->arrays.edgeflag, 1, GL_BOOL, stride, ptr, ctx);
}

// GL 2.1 §2.8: ArrayElement acts as the Color/Normal/TexCoord/EdgeFlag commands for each
// enabled array, then Vertex when the vertex array is enabled.
void GLAPIENTRY ArrayElement(GLint i) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  if (i < 0) return record_error(ctx, GL_INVALID_VALUE, "glArrayElement");
  InputVertex v;
  if (!fetch_range(ctx, static_cast<size_t>(i), 1, &v)) return;
  const VertexArrayGroup& a = ctx->arrays;
  if (a.color.enabled) {
    std::copy(v.color, v.color + 4, ctx->current.color);
    if (ctx->lighting.color_material) update_color_material(ctx); // as Color does (§2.14.3)
  }
  if (a.secondary.enabled) std::copy(v.color2, v.color2 + 3, ctx->current.color2);
  if (a.normal.enabled) std::copy(v.normal, v.normal + 3, ctx->current.normal);
  for (int u = 0; u < kMaxTexUnits; ++u)
    if (a.texcoord[u].enabled) std::copy(v.tex[u], v.tex[u] + 4, ctx->current.tex[u]);
  if (a.fog.enabled) ctx->current.fog_coord = v.fog;
  if (a.edgeflag.enabled) ctx->current.edge = v.edge != 0;
  // The generic arrays act as VertexAttrib (§2.8), attribute 0 (the vertex) last.
  const uint32_t generic = enabled_generic_arrays(ctx);
  if (generic != 0) {
    float values[4 * kMaxVertexAttribs];
    if (!fetch_generic_range(ctx, generic, static_cast<size_t>(i), 1, values)) return;
    int k = 0;
    for (uint32_t m = generic; m != 0; m &= m - 1, ++k)
      std::copy(values + 4 * k, values + 4 * k + 4, ctx->vertex_attrib.value[std::countr_zero(m)]);
  }
  bool vertex = a.vertex.enabled;
  if (generic_array0_enabled(ctx)) {
    if (!fetch_generic_range(ctx, 1u, static_cast<size_t>(i), 1, v.pos)) return;
    vertex = true;
  }
  if (vertex && ctx->imm.mode != kOutsideBeginEnd) {
    ctx->imm.verts.push_back(v);
    if (ctx->imm.generic_mask != 0) append_current_generics(ctx);
  }
}

void GLAPIENTRY DrawArrays(GLenum mode, GLint first, GLsizei count) {
  PINEDA_CTX_OUTSIDE("glDrawArrays");
  if (!valid_mode(mode)) return record_error(ctx, GL_INVALID_ENUM, "glDrawArrays", mode);
  if (count < 0 || first < 0) return record_error(ctx, GL_INVALID_VALUE, "glDrawArrays");
  if (arrays_mapped(ctx, false)) return record_error(ctx, GL_INVALID_OPERATION, "glDrawArrays");
  draw_range(ctx, mode, static_cast<size_t>(first), static_cast<size_t>(count));
}

void GLAPIENTRY DrawElements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
  PINEDA_CTX_OUTSIDE("glDrawElements");
  if (!check_elements(ctx, "glDrawElements", mode, count, type)) return;
  draw_indexed(ctx, mode, count, type, indices);
}

// GL 2.1 §2.8: the range is a promise; Pineda checks only end >= start and draws as
// DrawElements (indices outside the range are still fetched correctly).
void GLAPIENTRY DrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type,
                                  const void* indices) {
  PINEDA_CTX_OUTSIDE("glDrawRangeElements");
  if (end < start) return record_error(ctx, GL_INVALID_VALUE, "glDrawRangeElements");
  if (!check_elements(ctx, "glDrawRangeElements", mode, count, type)) return;
  draw_indexed(ctx, mode, count, type, indices);
}

void GLAPIENTRY MultiDrawArrays(GLenum mode, const GLint* first, const GLsizei* count,
                                GLsizei drawcount) {
  PINEDA_CTX_OUTSIDE("glMultiDrawArrays");
  if (!valid_mode(mode)) return record_error(ctx, GL_INVALID_ENUM, "glMultiDrawArrays", mode);
  if (drawcount < 0) return record_error(ctx, GL_INVALID_VALUE, "glMultiDrawArrays");
  if (drawcount == 0 || first == nullptr || count == nullptr) return;
  for (GLsizei i = 0; i < drawcount; ++i)
    if (count[i] < 0 || first[i] < 0)
      return record_error(ctx, GL_INVALID_VALUE, "glMultiDrawArrays");
  if (arrays_mapped(ctx, false))
    return record_error(ctx, GL_INVALID_OPERATION, "glMultiDrawArrays");
  for (GLsizei i = 0; i < drawcount; ++i)
    draw_range(ctx, mode, static_cast<size_t>(first[i]), static_cast<size_t>(count[i]));
}

void GLAPIENTRY MultiDrawElements(GLenum mode, const GLsizei* count, GLenum type,
                                  const void* const* indices, GLsizei drawcount) {
  PINEDA_CTX_OUTSIDE("glMultiDrawElements");
  if (drawcount < 0) return record_error(ctx, GL_INVALID_VALUE, "glMultiDrawElements");
  if (!check_elements(ctx, "glMultiDrawElements", mode, 0, type)) return;
  if (drawcount == 0 || count == nullptr || indices == nullptr) return;
  for (GLsizei i = 0; i < drawcount; ++i)
    if (count[i] < 0) return record_error(ctx, GL_INVALID_VALUE, "glMultiDrawElements");
  for (GLsizei i = 0; i < drawcount; ++i)
    draw_indexed(ctx, mode, count[i], type, indices[i]);
}

// GL 2.1 §2.8 Table 2.5: the fourteen interleaved layouts.
void GLAPIENTRY InterleavedArrays(GLenum format, GLsizei stride, const void* pointer) {
  PINEDA_CTX_OUTSIDE("glInterleavedArrays");
  if (stride < 0) return record_error(ctx, GL_INVALID_VALUE, "glInterleavedArrays");
  struct Layout {
    GLenum format;
    bool et, ec;
    int st, sc, sv;
    GLenum tc;
    int pc, pn, pv, s; // offsets and size in units of float, colour ubyte counted as 1 float
  };
  constexpr int f = 4;
  static constexpr Layout kLayouts[] = {
      {GL_V2F, false, false, 0, 0, 2, 0, 0, 0, 0, 2 * f},
      {GL_V3F, false, false, 0, 0, 3, 0, 0, 0, 0, 3 * f},
      {GL_C4UB_V2F, false, true, 0, 4, 2, GL_UNSIGNED_BYTE, 0, 0, f, 3 * f},
      {GL_C4UB_V3F, false, true, 0, 4, 3, GL_UNSIGNED_BYTE, 0, 0, f, 4 * f},
      {GL_C3F_V3F, false, true, 0, 3, 3, GL_FLOAT, 0, 0, 3 * f, 6 * f},
      {GL_N3F_V3F, false, false, 0, 0, 3, 0, 0, 0, 3 * f, 6 * f},
      {GL_C4F_N3F_V3F, false, true, 0, 4, 3, GL_FLOAT, 0, 4 * f, 7 * f, 10 * f},
      {GL_T2F_V3F, true, false, 2, 0, 3, 0, 0, 0, 2 * f, 5 * f},
      {GL_T4F_V4F, true, false, 4, 0, 4, 0, 0, 0, 4 * f, 8 * f},
      {GL_T2F_C4UB_V3F, true, true, 2, 4, 3, GL_UNSIGNED_BYTE, 2 * f, 0, 3 * f, 6 * f},
      {GL_T2F_C3F_V3F, true, true, 2, 3, 3, GL_FLOAT, 2 * f, 0, 5 * f, 8 * f},
      {GL_T2F_N3F_V3F, true, false, 2, 0, 3, 0, 0, 2 * f, 5 * f, 8 * f},
      {GL_T2F_C4F_N3F_V3F, true, true, 2, 4, 3, GL_FLOAT, 2 * f, 6 * f, 9 * f, 12 * f},
      {GL_T4F_C4F_N3F_V4F, true, true, 4, 4, 4, GL_FLOAT, 4 * f, 8 * f, 11 * f, 15 * f},
  };
  const Layout* l = nullptr;
  for (const Layout& c : kLayouts)
    if (c.format == format) l = &c;
  if (l == nullptr) return record_error(ctx, GL_INVALID_ENUM, "glInterleavedArrays", format);
  const bool has_normal = format == GL_N3F_V3F || format == GL_C4F_N3F_V3F ||
                          format == GL_T2F_N3F_V3F || format == GL_T2F_C4F_N3F_V3F ||
                          format == GL_T4F_C4F_N3F_V4F;
  const GLsizei s = stride != 0 ? stride : l->s;
  // `pointer` is often an offset into a buffer object, zero included: the field offsets are
  // added as integers, since arithmetic on a null pointer is undefined.
  const auto field = [pointer](int offset) {
    return reinterpret_cast<const void*>(reinterpret_cast<uintptr_t>(pointer) +
                                         static_cast<uintptr_t>(offset));
  };
  VertexArrayGroup& a = ctx->arrays;
  ClientArray& tex = a.texcoord[ctx->arrays.client_active_texture];
  a.edgeflag.enabled = false;
  a.index.enabled = false;
  a.fog.enabled = false;
  a.secondary.enabled = false; // GL 2.1 §2.8: InterleavedArrays disables the other arrays
  tex.enabled = l->et;
  if (l->et) set_pointer("glInterleavedArrays", tex, l->st, GL_FLOAT, s, pointer, ctx);
  a.color.enabled = l->ec;
  if (l->ec) set_pointer("glInterleavedArrays", a.color, l->sc, l->tc, s, field(l->pc), ctx);
  a.normal.enabled = has_normal;
  if (has_normal) set_pointer("glInterleavedArrays", a.normal, 3, GL_FLOAT, s, field(l->pn), ctx);
  a.vertex.enabled = true;
  set_pointer("glInterleavedArrays", a.vertex, l->sv, GL_FLOAT, s, field(l->pv), ctx);
}

} // namespace exec
} // namespace pineda
