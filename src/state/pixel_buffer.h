// Pixel buffer objects (GL 2.1 §2.9, §3.6.1, §4.3.2; ARB_pixel_buffer_object): with a buffer
// bound to PIXEL_UNPACK_BUFFER the pointer argument of a command that reads an image
// (DrawPixels, Bitmap, PolygonStipple, TexImage*, TexSubImage*, PixelMap*) is an offset into
// that buffer's data store; with one bound to PIXEL_PACK_BUFFER the pointer of a command that
// writes one (ReadPixels, GetTexImage, GetPolygonStipple, GetPixelMap*) is. The bindings are
// client pixel-store state (PixelStoreGroup, pixel.h).
#pragma once

#include <GL/gl.h>

#include <cstddef>

namespace pineda {

struct Context;

// Bytes of the GL data type of one element of `type` (Table 3.5): the unit a buffer offset
// must be a multiple of (§3.6.4 "Unpacking", §4.3.2). 1 for BITMAP and unknown types.
size_t pixel_type_unit(GLenum type);

// The memory a command reads `bytes` bytes of image data from: `pointer` itself when no
// buffer is bound to PIXEL_UNPACK_BUFFER. Otherwise the bound buffer's store at offset
// `pointer`, provided the buffer is not mapped (§2.9), the access ends inside the store and the
// offset is a multiple of `unit`; if not, INVALID_OPERATION is recorded and false returned.
bool unpack_memory(Context* ctx, const void* pointer, size_t bytes, size_t unit, const char* func,
                   const void** out);

// The same for a command that writes `bytes` bytes, with PIXEL_PACK_BUFFER.
bool pack_memory(Context* ctx, void* pointer, size_t bytes, size_t unit, const char* func,
                 void** out);

// unpack_memory without recording an error: display lists compile the buffer's bytes (GL 2.1
// §5.4 with ARB_pixel_buffer_object: the data are taken when the list is compiled) and report
// an invalid access when the list executes.
bool unpack_memory_quiet(const Context* ctx, const void* pointer, size_t bytes, size_t unit,
                         const void** out);

// A buffer is bound to PIXEL_UNPACK_BUFFER.
bool unpack_buffer_bound(const Context* ctx);

} // namespace pineda
