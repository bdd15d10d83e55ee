// Pixel buffer objects: the pointer arguments of pixel commands as offsets into the buffers
// bound to PIXEL_PACK_BUFFER and PIXEL_UNPACK_BUFFER (pixel_buffer.h).
#include "state/pixel_buffer.h"

#include <cstdint>

#include "state/api_util.h"

namespace pineda {

namespace {

// The store of buffer `name` for an access of `bytes` bytes at offset `pointer`, or nullptr.
uint8_t* buffer_store(const Context* ctx, GLuint name, const void* pointer, size_t bytes,
                      size_t unit) {
  const auto it = ctx->buffers.find(name);
  BufferObject* bo = it == ctx->buffers.end() ? nullptr : it->second.get();
  const auto offset = reinterpret_cast<uintptr_t>(pointer);
  // GL 2.1 §2.9: sourcing data from (or writing it to) a mapped buffer is INVALID_OPERATION;
  // §3.6.4, §4.3.2: so is an access past the end of the store or an offset that is not a
  // multiple of the data type's size.
  if (bo == nullptr || bo->mapped || (unit > 1 && offset % unit != 0) || offset > bo->data.size() ||
      bytes > bo->data.size() - offset)
    return nullptr;
  return bo->data.data() + offset;
}

// buffer_store, recording INVALID_OPERATION when it fails.
uint8_t* buffer_access(Context* ctx, GLuint name, const void* pointer, size_t bytes, size_t unit,
                       const char* func) {
  uint8_t* p = buffer_store(ctx, name, pointer, bytes, unit);
  if (p == nullptr) record_error(ctx, GL_INVALID_OPERATION, func);
  return p;
}

} // namespace

size_t pixel_type_unit(GLenum type) {
  switch (type) {
  case GL_SHORT:
  case GL_UNSIGNED_SHORT:
  case GL_UNSIGNED_SHORT_5_6_5:
  case GL_UNSIGNED_SHORT_5_6_5_REV:
  case GL_UNSIGNED_SHORT_4_4_4_4:
  case GL_UNSIGNED_SHORT_4_4_4_4_REV:
  case GL_UNSIGNED_SHORT_5_5_5_1:
  case GL_UNSIGNED_SHORT_1_5_5_5_REV:
    return 2;
  case GL_INT:
  case GL_UNSIGNED_INT:
  case GL_FLOAT:
  case GL_UNSIGNED_INT_8_8_8_8:
  case GL_UNSIGNED_INT_8_8_8_8_REV:
  case GL_UNSIGNED_INT_10_10_10_2:
  case GL_UNSIGNED_INT_2_10_10_10_REV:
    return 4;
  default:
    return 1;
  }
}

bool unpack_buffer_bound(const Context* ctx) {
  return ctx->pixel_store.unpack_buffer != 0;
}

bool unpack_memory(Context* ctx, const void* pointer, size_t bytes, size_t unit, const char* func,
                   const void** out) {
  const GLuint name = ctx->pixel_store.unpack_buffer;
  if (name == 0) {
    *out = pointer;
    return true;
  }
  const uint8_t* p = buffer_access(ctx, name, pointer, bytes, unit, func);
  *out = p;
  return p != nullptr;
}

bool unpack_memory_quiet(const Context* ctx, const void* pointer, size_t bytes, size_t unit,
                         const void** out) {
  const GLuint name = ctx->pixel_store.unpack_buffer;
  if (name == 0) {
    *out = pointer;
    return true;
  }
  const uint8_t* p = buffer_store(ctx, name, pointer, bytes, unit);
  *out = p;
  return p != nullptr;
}

bool pack_memory(Context* ctx, void* pointer, size_t bytes, size_t unit, const char* func,
                 void** out) {
  const GLuint name = ctx->pixel_store.pack_buffer;
  if (name == 0) {
    *out = pointer;
    return true;
  }
  uint8_t* p = buffer_access(ctx, name, pointer, bytes, unit, func);
  *out = p;
  return p != nullptr;
}

} // namespace pineda
