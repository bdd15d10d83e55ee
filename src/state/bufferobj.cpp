// Buffer objects (GL 1.5 §2.9): names, data stores, mapping, queries, and their use as
// vertex array and element sources (fetch.cpp, varray.cpp).
#include <cstring>
#include <new>

#include "state/api_util.h"
#include "dispatch.h"

namespace pineda {

namespace {

GLuint* binding_for(Context* ctx, GLenum target) {
  switch (target) {
  case GL_ARRAY_BUFFER:
    return &ctx->arrays.array_buffer;
  case GL_ELEMENT_ARRAY_BUFFER:
    return &ctx->arrays.element_array_buffer;
  // GL 2.1 §2.9 (ARB_pixel_buffer_object): the sources and destinations of pixel commands.
  case GL_PIXEL_PACK_BUFFER:
    return &ctx->pixel_store.pack_buffer;
  case GL_PIXEL_UNPACK_BUFFER:
    return &ctx->pixel_store.unpack_buffer;
  default:
    return nullptr;
  }
}

// The buffer bound to `target`, or nullptr with the spec's error set: INVALID_ENUM for a bad
// target, INVALID_OPERATION when zero is bound.
BufferObject* bound_buffer(Context* ctx, GLenum target, const char* func) {
  GLuint* binding = binding_for(ctx, target);
  if (binding == nullptr) {
    record_error(ctx, GL_INVALID_ENUM, func, target);
    return nullptr;
  }
  if (*binding == 0) {
    record_error(ctx, GL_INVALID_OPERATION, func);
    return nullptr;
  }
  return ctx->buffers.at(*binding).get();
}

bool valid_usage(GLenum usage) {
  switch (usage) {
  case GL_STREAM_DRAW:
  case GL_STREAM_READ:
  case GL_STREAM_COPY:
  case GL_STATIC_DRAW:
  case GL_STATIC_READ:
  case GL_STATIC_COPY:
  case GL_DYNAMIC_DRAW:
  case GL_DYNAMIC_READ:
  case GL_DYNAMIC_COPY:
    return true;
  default:
    return false;
  }
}

// Range checks shared by BufferSubData and GetBufferSubData (GL 1.5 §2.9.1).
BufferObject* sub_data_buffer(Context* ctx, GLenum target, GLintptr offset, GLsizeiptr size,
                              const char* func) {
  BufferObject* bo = bound_buffer(ctx, target, func);
  if (bo == nullptr) return nullptr;
  if (offset < 0 || size < 0 ||
      static_cast<size_t>(offset) + static_cast<size_t>(size) > bo->data.size()) {
    record_error(ctx, GL_INVALID_VALUE, func);
    return nullptr;
  }
  if (bo->mapped) {
    record_error(ctx, GL_INVALID_OPERATION, func);
    return nullptr;
  }
  return bo;
}

} // namespace

namespace exec {

void GLAPIENTRY GenBuffers(GLsizei n, GLuint* buffers) {
  PINEDA_CTX_OUTSIDE("glGenBuffers");
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE, "glGenBuffers");
  if (buffers == nullptr) return;
  GLuint next = 1;
  for (GLsizei i = 0; i < n; ++i) {
    while (ctx->buffers.count(next) != 0)
      ++next;
    ctx->buffers.emplace(next, std::make_unique<BufferObject>());
    buffers[i] = next++;
  }
}

void GLAPIENTRY DeleteBuffers(GLsizei n, const GLuint* buffers) {
  PINEDA_CTX_OUTSIDE("glDeleteBuffers");
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE, "glDeleteBuffers");
  if (buffers == nullptr) return;
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = buffers[i];
    if (name == 0 || ctx->buffers.erase(name) == 0) continue;
    // GL 1.5 §2.9: bindings of a deleted buffer revert to zero, array bindings included.
    if (ctx->arrays.array_buffer == name) ctx->arrays.array_buffer = 0;
    if (ctx->arrays.element_array_buffer == name) ctx->arrays.element_array_buffer = 0;
    if (ctx->pixel_store.pack_buffer == name) ctx->pixel_store.pack_buffer = 0;
    if (ctx->pixel_store.unpack_buffer == name) ctx->pixel_store.unpack_buffer = 0;
    VertexArrayGroup& a = ctx->arrays;
    for (ClientArray* arr : {&a.vertex, &a.color, &a.normal, &a.edgeflag, &a.texcoord[0],
                             &a.texcoord[1], &a.texcoord[2], &a.texcoord[3], &a.secondary, &a.fog})
      if (arr->buffer == name) arr->buffer = 0;
    for (GenericArray& g : ctx->attrib_arrays.array)
      if (g.buffer == name) g.buffer = 0;
  }
}

GLboolean GLAPIENTRY IsBuffer(GLuint buffer) {
  Context* ctx = outside_begin_end("glIsBuffer");
  if (ctx == nullptr || buffer == 0) return GL_FALSE;
  auto it = ctx->buffers.find(buffer);
  // A generated name becomes a buffer object when first bound (GL 1.5 §2.9).
  return it != ctx->buffers.end() && it->second->ever_bound ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY BindBuffer(GLenum target, GLuint buffer) {
  PINEDA_CTX_OUTSIDE("glBindBuffer");
  GLuint* binding = binding_for(ctx, target);
  if (binding == nullptr) return record_error(ctx, GL_INVALID_ENUM, "glBindBuffer", target);
  if (buffer != 0) {
    auto& slot = ctx->buffers[buffer];
    if (!slot) slot = std::make_unique<BufferObject>();
    slot->ever_bound = true;
  }
  *binding = buffer;
}

void GLAPIENTRY BufferData(GLenum target, GLsizeiptr size, const void* data, GLenum usage) {
  PINEDA_CTX_OUTSIDE("glBufferData");
  if (binding_for(ctx, target) == nullptr)
    return record_error(ctx, GL_INVALID_ENUM, "glBufferData", target);
  if (size < 0) return record_error(ctx, GL_INVALID_VALUE, "glBufferData");
  if (!valid_usage(usage)) return record_error(ctx, GL_INVALID_ENUM, "glBufferData", usage);
  BufferObject* bo = bound_buffer(ctx, target, "glBufferData");
  if (bo == nullptr) return;
  std::vector<uint8_t> store;
  try {
    store.resize(static_cast<size_t>(size));
  } catch (const std::bad_alloc&) {
    return record_error(ctx, GL_OUT_OF_MEMORY, "glBufferData");
  } catch (const std::length_error&) {
    return record_error(ctx, GL_OUT_OF_MEMORY, "glBufferData");
  }
  if (data != nullptr && size > 0) std::memcpy(store.data(), data, static_cast<size_t>(size));
  bo->data.swap(store);
  bo->usage = usage;
  bo->access = GL_READ_WRITE;
  bo->mapped = false;
}

void GLAPIENTRY BufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, const void* data) {
  PINEDA_CTX_OUTSIDE("glBufferSubData");
  BufferObject* bo = sub_data_buffer(ctx, target, offset, size, "glBufferSubData");
  if (bo == nullptr || data == nullptr || size == 0) return;
  std::memcpy(bo->data.data() + offset, data, static_cast<size_t>(size));
}

void GLAPIENTRY GetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, void* data) {
  PINEDA_CTX_OUTSIDE("glGetBufferSubData");
  BufferObject* bo = sub_data_buffer(ctx, target, offset, size, "glGetBufferSubData");
  if (bo == nullptr || data == nullptr || size == 0) return;
  std::memcpy(data, bo->data.data() + offset, static_cast<size_t>(size));
}

void* GLAPIENTRY MapBuffer(GLenum target, GLenum access) {
  Context* ctx = outside_begin_end("glMapBuffer");
  if (ctx == nullptr) return nullptr;
  if (binding_for(ctx, target) == nullptr) {
    record_error(ctx, GL_INVALID_ENUM, "glMapBuffer", target);
    return nullptr;
  }
  if (access != GL_READ_ONLY && access != GL_WRITE_ONLY && access != GL_READ_WRITE) {
    record_error(ctx, GL_INVALID_ENUM, "glMapBuffer", access);
    return nullptr;
  }
  BufferObject* bo = bound_buffer(ctx, target, "glMapBuffer");
  if (bo == nullptr) return nullptr;
  if (bo->mapped) {
    record_error(ctx, GL_INVALID_OPERATION, "glMapBuffer");
    return nullptr;
  }
  bo->mapped = true;
  bo->access = access;
  return bo->data.data();
}

GLboolean GLAPIENTRY UnmapBuffer(GLenum target) {
  Context* ctx = outside_begin_end("glUnmapBuffer");
  if (ctx == nullptr) return GL_FALSE;
  BufferObject* bo = bound_buffer(ctx, target, "glUnmapBuffer");
  if (bo == nullptr) return GL_FALSE;
  if (!bo->mapped) {
    record_error(ctx, GL_INVALID_OPERATION, "glUnmapBuffer");
    return GL_FALSE;
  }
  bo->mapped = false;
  return GL_TRUE;
}

void GLAPIENTRY GetBufferParameteriv(GLenum target, GLenum pname, GLint* params) {
  PINEDA_CTX_OUTSIDE("glGetBufferParameteriv");
  if (pname != GL_BUFFER_SIZE && pname != GL_BUFFER_USAGE && pname != GL_BUFFER_ACCESS &&
      pname != GL_BUFFER_MAPPED)
    return record_error(ctx, GL_INVALID_ENUM, "glGetBufferParameteriv", pname);
  BufferObject* bo = bound_buffer(ctx, target, "glGetBufferParameteriv");
  if (bo == nullptr || params == nullptr) return;
  switch (pname) {
  case GL_BUFFER_SIZE:
    *params = static_cast<GLint>(bo->data.size());
    break;
  case GL_BUFFER_USAGE:
    *params = static_cast<GLint>(bo->usage);
    break;
  case GL_BUFFER_ACCESS:
    *params = static_cast<GLint>(bo->access);
    break;
  default:
    *params = bo->mapped ? GL_TRUE : GL_FALSE;
    break;
  }
}

void GLAPIENTRY GetBufferPointerv(GLenum target, GLenum pname, void** params) {
  PINEDA_CTX_OUTSIDE("glGetBufferPointerv");
  if (pname != GL_BUFFER_MAP_POINTER)
    return record_error(ctx, GL_INVALID_ENUM, "glGetBufferPointerv", pname);
  BufferObject* bo = bound_buffer(ctx, target, "glGetBufferPointerv");
  if (bo == nullptr || params == nullptr) return;
  *params = bo->mapped ? bo->data.data() : nullptr;
}

} // namespace exec
} // namespace pineda
