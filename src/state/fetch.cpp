// Vertex fetch: convert array elements to InputVertex (GL 2.1 §2.8). Each attribute is a
// separate loop with the component type hoisted out, so the inner loop is a plain copy and
// convert.
#include "state/fetch.h"

#include <cstddef>
#include <cstring>
#include <type_traits>

#include "raster/workers.h"

namespace pineda {

size_t type_size(GLenum type) {
  switch (type) {
  case GL_BYTE:
  case GL_UNSIGNED_BYTE:
  case GL_BOOL:
    return 1;
  case GL_SHORT:
  case GL_UNSIGNED_SHORT:
    return 2;
  case GL_INT:
  case GL_UNSIGNED_INT:
  case GL_FLOAT:
    return 4;
  case GL_DOUBLE:
    return 8;
  default:
    return 0;
  }
}

size_t array_stride(const ClientArray& a) {
  return a.stride != 0 ? static_cast<size_t>(a.stride)
                       : static_cast<size_t>(a.size) * type_size(a.type);
}

namespace {

// Element k of the draw: either first + k or list[k].
// from(k0): the elements from k of the draw on.
struct RangeElements {
  size_t first;
  size_t operator[](size_t k) const { return first + k; }
  RangeElements from(size_t k0) const { return {first + k0}; }
};
struct ListElements {
  const uint32_t* list;
  size_t operator[](size_t k) const { return list[k]; }
  ListElements from(size_t k0) const { return {list + k0}; }
};

// Draws of at least this many elements are fetched by every worker thread.
constexpr size_t kShareFetchCount = 8192;

// GL 2.1 Table 2.9 conversions for normalized attributes (colours, normals).
template <typename T> inline float to_float(T v, bool normalized) {
  if (!normalized) return static_cast<float>(v);
  if constexpr (std::is_same_v<T, GLubyte>) return static_cast<float>(v) * (1.0f / 255.0f);
  if constexpr (std::is_same_v<T, GLbyte>) return (2.0f * v + 1.0f) * (1.0f / 255.0f);
  if constexpr (std::is_same_v<T, GLushort>) return static_cast<float>(v) * (1.0f / 65535.0f);
  if constexpr (std::is_same_v<T, GLshort>) return (2.0f * v + 1.0f) * (1.0f / 65535.0f);
  if constexpr (std::is_same_v<T, GLuint>)
    return static_cast<float>(static_cast<double>(v) / 4294967295.0);
  if constexpr (std::is_same_v<T, GLint>) return static_cast<float>((2.0 * v + 1.0) / 4294967295.0);
  return static_cast<float>(v);
}

// Copy kSize components of each element into dst (one float[4] per vertex, at byte offset
// `field` inside InputVertex), leaving the remaining components as they are.
template <typename T, int kSize, typename Elements>
void convert_n(const uint8_t* base, size_t stride, bool normalized, Elements el, size_t n,
               InputVertex* out, size_t field) {
  for (size_t k = 0; k < n; ++k) {
    const uint8_t* src = base + el[k] * stride;
    float* dst = reinterpret_cast<float*>(reinterpret_cast<uint8_t*>(&out[k]) + field);
    for (int c = 0; c < kSize; ++c) {
      T v;
      std::memcpy(&v, src + c * sizeof(T), sizeof(T));
      dst[c] = to_float(v, normalized);
    }
  }
}

// The component count as a constant, so that the per-element copy has no inner loop.
template <typename T, typename Elements>
void convert(const uint8_t* base, size_t stride, int size, bool normalized, Elements el, size_t n,
             InputVertex* out, size_t field) {
  switch (size) {
  case 1:
    return convert_n<T, 1>(base, stride, normalized, el, n, out, field);
  case 2:
    return convert_n<T, 2>(base, stride, normalized, el, n, out, field);
  case 3:
    return convert_n<T, 3>(base, stride, normalized, el, n, out, field);
  case 4:
    return convert_n<T, 4>(base, stride, normalized, el, n, out, field);
  default:
    return;
  }
}

template <typename Elements>
void convert_any(const ClientArray& a, const uint8_t* base, bool normalized, Elements el, size_t n,
                 InputVertex* out, size_t field) {
  const size_t stride = array_stride(a);
  switch (a.type) {
  case GL_BYTE:
    convert<GLbyte>(base, stride, a.size, normalized, el, n, out, field);
    break;
  case GL_UNSIGNED_BYTE:
    convert<GLubyte>(base, stride, a.size, normalized, el, n, out, field);
    break;
  case GL_SHORT:
    convert<GLshort>(base, stride, a.size, normalized, el, n, out, field);
    break;
  case GL_UNSIGNED_SHORT:
    convert<GLushort>(base, stride, a.size, normalized, el, n, out, field);
    break;
  case GL_INT:
    convert<GLint>(base, stride, a.size, normalized, el, n, out, field);
    break;
  case GL_UNSIGNED_INT:
    convert<GLuint>(base, stride, a.size, normalized, el, n, out, field);
    break;
  case GL_FLOAT:
    convert<GLfloat>(base, stride, a.size, normalized, el, n, out, field);
    break;
  case GL_DOUBLE:
    convert<GLdouble>(base, stride, a.size, normalized, el, n, out, field);
    break;
  default:
    break;
  }
}

// Where the array's data starts, or nullptr when a buffer-backed array would read past its
// buffer for the largest element `max_element`.
const uint8_t* array_base(Context* ctx, const ClientArray& a, size_t max_element) {
  if (a.buffer == 0) return static_cast<const uint8_t*>(a.pointer);
  auto it = ctx->buffers.find(a.buffer);
  if (it == ctx->buffers.end()) return nullptr;
  const std::vector<uint8_t>& data = it->second->data;
  const size_t offset = reinterpret_cast<uintptr_t>(a.pointer);
  const size_t need =
      offset + max_element * array_stride(a) + static_cast<size_t>(a.size) * type_size(a.type);
  if (need > data.size() || need < offset) return nullptr;
  return data.data() + offset;
}

// Every client array in a fixed order: vertex, colour, normal, edge flag, secondary colour,
// fog coordinate, then the texture coordinate array of each unit.
constexpr int kArrayCount = 6 + kMaxTexUnits;
inline void all_arrays(const VertexArrayGroup& arr, const ClientArray* (&out)[kArrayCount]) {
  out[0] = &arr.vertex;
  out[1] = &arr.color;
  out[2] = &arr.normal;
  out[3] = &arr.edgeflag;
  out[4] = &arr.secondary;
  out[5] = &arr.fog;
  for (int u = 0; u < kMaxTexUnits; ++u)
    out[6 + u] = &arr.texcoord[u];
}

template <typename Elements>
bool fetch(Context* ctx, Elements el, size_t n, size_t max_element, uint32_t tex_units,
           InputVertex* out) {
  const VertexArrayGroup& arr = ctx->arrays;
  const ClientArray* arrays[kArrayCount];
  all_arrays(arr, arrays);
  const uint8_t* bases[kArrayCount] = {};
  for (int i = 0; i < kArrayCount; ++i) {
    if (!arrays[i]->enabled) continue;
    bases[i] = array_base(ctx, *arrays[i], max_element);
    if (bases[i] == nullptr) return false;
  }
  // Defaults: current values for disabled arrays (GL 2.1 §2.8), and the spec's (0,0,0,1)
  // completion of partial positions and texture coordinates.
  InputVertex def;
  def.pos[0] = def.pos[1] = def.pos[2] = 0.0f;
  def.pos[3] = 1.0f;
  for (int i = 0; i < 4; ++i)
    def.color[i] = ctx->current.color[i];
  for (int i = 0; i < 3; ++i)
    def.normal[i] = ctx->current.normal[i];
  for (int u = 0; u < kMaxTexUnits; ++u)
    for (int i = 0; i < 4; ++i)
      def.tex[u][i] = arr.texcoord[u].enabled ? (i == 3 ? 1.0f : 0.0f) : ctx->current.tex[u][i];
  if (arr.color.enabled && arr.color.size == 3) def.color[3] = 1.0f;
  for (int i = 0; i < 3; ++i)
    def.color2[i] = ctx->current.color2[i];
  def.fog = ctx->current.fog_coord;
  def.edge = ctx->current.edge ? 1u : 0u;
  // Elements [k0, k1) of the draw: independent of each other, so a large draw's are split
  // among the worker threads as the transform's are (draw/draw.cpp).
  const auto fill = [&](size_t k0, size_t k1) {
    const Elements sub = el.from(k0);
    const size_t m = k1 - k0;
    InputVertex* dst = out + k0;
    // The attributes before `tex` always, then only the units asked for.
    constexpr size_t kHead = offsetof(InputVertex, tex);
    for (size_t k = 0; k < m; ++k) {
      std::memcpy(static_cast<void*>(&dst[k]), &def, kHead); // trivially copyable
      for (uint32_t units = tex_units; units != 0; units &= units - 1) {
        const int u = __builtin_ctz(units);
        std::memcpy(dst[k].tex[u], def.tex[u], sizeof def.tex[u]);
      }
    }
    if (bases[0]) convert_any(arr.vertex, bases[0], false, sub, m, dst, offsetof(InputVertex, pos));
    if (bases[1]) convert_any(arr.color, bases[1], true, sub, m, dst, offsetof(InputVertex, color));
    if (bases[2])
      convert_any(arr.normal, bases[2], true, sub, m, dst, offsetof(InputVertex, normal));
    if (bases[4])
      convert_any(arr.secondary, bases[4], true, sub, m, dst, offsetof(InputVertex, color2));
    if (bases[5]) convert_any(arr.fog, bases[5], false, sub, m, dst, offsetof(InputVertex, fog));
    for (int u = 0; u < kMaxTexUnits; ++u)
      if (bases[6 + u] && (tex_units >> u & 1u) != 0)
        convert_any(arr.texcoord[u], bases[6 + u], false, sub, m, dst,
                    offsetof(InputVertex, tex) + sizeof(float[4]) * static_cast<size_t>(u));
    if (bases[3]) {
      const size_t stride = array_stride(arr.edgeflag);
      for (size_t k = 0; k < m; ++k)
        dst[k].edge = bases[3][sub[k] * stride] != 0 ? 1u : 0u;
    }
  };
  const int threads = n >= kShareFetchCount ? ctx->workers.threads() : 1;
  if (threads > 1) {
    auto part = [&](int i) {
      const auto t = static_cast<size_t>(threads);
      fill(n * static_cast<size_t>(i) / t, n * static_cast<size_t>(i + 1) / t);
    };
    ctx->workers.run(part);
  } else {
    fill(0, n);
  }
  return true;
}

} // namespace

bool arrays_hold(Context* ctx, size_t max_element) {
  const ClientArray* arrays[kArrayCount];
  all_arrays(ctx->arrays, arrays);
  for (const ClientArray* a : arrays)
    if (a->enabled && array_base(ctx, *a, max_element) == nullptr) return false;
  return true;
}

bool fetch_range(Context* ctx, size_t first, size_t n, InputVertex* out, uint32_t tex_units) {
  if (n == 0) return true;
  return fetch(ctx, RangeElements{first}, n, first + n - 1, tex_units, out);
}

bool fetch_list(Context* ctx, const uint32_t* elements, size_t n, InputVertex* out,
                uint32_t tex_units) {
  uint32_t max_element = 0;
  for (size_t k = 0; k < n; ++k)
    max_element = elements[k] > max_element ? elements[k] : max_element;
  return fetch(ctx, ListElements{elements}, n, max_element, tex_units, out);
}

} // namespace pineda
