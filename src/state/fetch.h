// Vertex fetch from client arrays and buffer objects (GL 2.1 §2.8, §2.9).
#pragma once

#include <cstddef>
#include <cstdint>

#include "state/context.h"

namespace pineda {

// Fill out[k] for element (first + k), k < n, from the enabled arrays; disabled arrays give
// the current values. Of the texture coordinates only the units in `tex_units` are filled
// (the draw's input_tex_units; kAllTexUnits where the vertices are kept). Returns false (and
// fills nothing) when a buffer-backed array would be read outside its buffer's storage.
bool fetch_range(Context* ctx, size_t first, size_t n, InputVertex* out,
                 uint32_t tex_units = kAllTexUnits);

// Whether every enabled buffer-backed array holds element `max_element`; lets a draw reject
// an out-of-range call before it allocates anything for it.
bool arrays_hold(Context* ctx, size_t max_element);

// The same for an explicit list of element numbers.
bool fetch_list(Context* ctx, const uint32_t* elements, size_t n, InputVertex* out,
                uint32_t tex_units = kAllTexUnits);

// Bytes from one element of `a` to the next (the effective stride).
size_t array_stride(const ClientArray& a);

// Size in bytes of one component of `type`.
size_t type_size(GLenum type);

} // namespace pineda
