// glReadPixels back end (GL 2.1 §4.3.2): reads a window rectangle from the colour, depth or
// stencil buffer, converts it per Table 4.7 / Table 4.6 and places it in client memory per the
// pack state (§3.6.4 Unpacking, run backwards). The front end checks enums, sizes and buffer
// presence first; read_format_type_error gives it the GL error for a format/type pair.
#pragma once

#include <GL/gl.h>

#include <cstddef>

#include "framebuffer/framebuffer.h"
#include "framebuffer/pixel_store.h"

namespace pineda {

// Formats ReadPixels accepts as enums (GL 2.1 Table 3.6). COLOR_INDEX is among them: it is a
// legal enum that fails with INVALID_OPERATION in RGBA mode (§4.3.2).
bool is_valid_read_format(GLenum format);

// Types of GL 2.1 Table 3.5, BITMAP and the GL 1.2 packed types included.
bool is_valid_type(GLenum type);

// True for the packed types of GL 2.1 Table 3.8.
bool is_packed_pixel_type(GLenum type);

// Where each component of a packed type sits (GL 2.1 Tables 3.9-3.11), in group order: the
// first component is red for RGB/RGBA and blue for BGRA (Table 3.12).
struct PackedLayout {
  int components = 0;
  int bytes = 0;
  int shift[4] = {};
  int bits[4] = {};
};

// The layout of a packed type of Table 3.8; false for any other type.
bool packed_layout(GLenum type, PackedLayout& out);

// Elements in one group of `format` (Table 3.6): 1 to 4. 0 for an unknown format.
int pixel_format_components(GLenum format);

// Bytes of one element of `type` (Table 3.5); for packed types the whole packed group.
// 0 for BITMAP (one bit) and unknown types.
int pixel_type_size(GLenum type);

// GL error of a glReadPixels format/type pair before the framebuffer is looked at:
// GL_NO_ERROR, GL_INVALID_ENUM (unknown enum; BITMAP with a non-index format, §3.6.4) or
// GL_INVALID_OPERATION (packed type with a format it does not match, Table 3.8; COLOR_INDEX
// in RGBA mode, §4.3.2). Missing depth/stencil buffers are the caller's check.
GLenum read_format_type_error(GLenum format, GLenum type);

// Reads the rectangle (x, y, w, h) in window coordinates, converts it and packs it into dst.
// Pixels outside the framebuffer have undefined values per §4.3.2; their bytes in dst are left
// untouched. Returns false, writing nothing, for a format/type pair this cannot do (anything
// read_format_type_error rejects) or a format whose buffer the framebuffer lacks.
bool read_pixels(const Framebuffer& fb, int x, int y, int w, int h, GLenum format, GLenum type,
                 const PixelStore& pack, void* dst);

// Bytes from the start of client memory up to and including the last byte a packed w x h image
// touches, skips included (§3.6.4 eq. 3.12-3.14). The same layout rules serve unpacking.
// 0 when w or h is not positive or the format/type pair is unknown.
size_t packed_image_size(int w, int h, GLenum format, GLenum type, const PixelStore& pack);

// Bytes from one row of an image to the next (k of §3.6.4 eq. 3.13 / 3.14).
size_t packed_row_stride(int w, GLenum format, GLenum type, const PixelStore& pack);

} // namespace pineda
