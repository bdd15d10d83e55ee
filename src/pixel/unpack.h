// Client-memory pixel images in both directions (GL 2.1 §3.6.4 "Unpacking" through "Final
// Expansion to RGBA" and the pixel transfer operations of §3.6.5; §4.3.2 "Final Conversion" and
// placement for packing). DrawPixels, Bitmap, ReadPixels with pixel transfer on, and the
// texture image commands share it. Images are w x h x d groups; 1D and 2D callers pass d = 1
// and a PixelStore whose image_height and skip_images are 0 (store_2d), since those two apply
// to 3D images only (§3.8.1).
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>

#include "framebuffer/pixel_store.h"
#include "pixel/transfer.h"

namespace pineda {

// GL 2.1 §3.6.4 for unpacking commands: GL_NO_ERROR, GL_INVALID_ENUM (unknown format or type;
// BITMAP with a format other than COLOR_INDEX or STENCIL_INDEX, as §3.6.4 and Mesa say) or
// GL_INVALID_OPERATION (a packed type with a format it does not fit, Table 3.8, checked
// before the format itself as Mesa does).
GLenum check_pixel_format_type(GLenum format, GLenum type);

// `st` without the 3D-only parameters, for 1D and 2D images.
inline PixelStore store_2d(PixelStore st) {
  st.image_height = 0;
  st.skip_images = 0;
  return st;
}

// Where an image lives in client memory (§3.6.4 eq. 3.12-3.14; images of a 3D image follow
// each other every image_stride bytes, §3.8.1).
struct ClientLayout {
  size_t group_bytes = 0;  // bytes per group; 0 for BITMAP
  size_t row_stride = 0;   // k of eq. 3.13 / 3.14, in bytes
  size_t image_stride = 0; // row_stride times IMAGE_HEIGHT (or h when it is 0)
  size_t origin = 0;       // byte offset of group (0, 0, 0) (BITMAP: of the byte with its bit)
  size_t origin_bit = 0;   // BITMAP only: the SKIP_PIXELS bits before element 0 of each row

  size_t row_offset(int row, int image) const {
    return origin + static_cast<size_t>(image) * image_stride +
           static_cast<size_t>(row) * row_stride;
  }
};

// Fills `out` for a w x h image; false for an unknown format/type pair.
bool client_layout(int w, int h, GLenum format, GLenum type, const PixelStore& st,
                   ClientLayout& out);

// Bytes of client memory a w x h x d image occupies under `st`, from the start of the client
// pointer to its last byte, skips included (for buffer-object bounds checks). 0 when a
// dimension is not positive or the pair is unknown.
size_t client_image_bytes(int w, int h, int d, GLenum format, GLenum type, const PixelStore& st);

// Unpacks to float RGBA (4 floats per group; rows, then images) through §3.6.4 conversion to
// float (Table 2.9; packed fields c / (2^N - 1)), luminance to RGB and final expansion to RGBA,
// then the §3.6.5 operations of `xfer`: scale/bias and MAP_COLOR for components; for
// COLOR_INDEX shift/offset and the I_TO_R .. I_TO_A maps (no scale/bias, Figure 3.7). No
// clamping: that belongs to the final conversion of whoever stores the values.
// `format` must be a colour format or COLOR_INDEX and the pair must pass
// check_pixel_format_type; otherwise `out` is left untouched.
void unpack_rgba(const void* pixels, int w, int h, int d, GLenum format, GLenum type,
                 const PixelStore& st, const PixelTransferView& xfer, float* out);

// DEPTH_COMPONENT groups to floats (Table 2.9), depth scale and bias applied (§3.6.5); not
// clamped.
void unpack_depth(const void* pixels, int w, int h, int d, GLenum type, const PixelStore& st,
                  const PixelTransferView& xfer, float* out);

// EXT_packed_depth_stencil: DEPTH_STENCIL / UNSIGNED_INT_24_8 groups to depth floats (with
// depth scale and bias) and stencil indices (with the stencil index arithmetic and map).
void unpack_depth_stencil(const void* pixels, int w, int h, int d, const PixelStore& st,
                          const PixelTransferView& xfer, float* depth, uint32_t* stencil);

// Depth floats (clamped) and stencil indices to DEPTH_STENCIL / UNSIGNED_INT_24_8 groups.
void pack_depth_stencil(const float* depth, const uint32_t* stencil, int w, int h, int d,
                        const PixelStore& st, void* pixels);

// COLOR_INDEX or STENCIL_INDEX groups to integer indices (floats truncated), with §3.6.5
// "Arithmetic on Indices" applied; for STENCIL_INDEX also the S_TO_S lookup when MAP_STENCIL.
void unpack_index(const void* pixels, int w, int h, int d, GLenum format, GLenum type,
                  const PixelStore& st, const PixelTransferView& xfer, uint32_t* out);

// Float RGBA (after any transfer operations) to client memory (§4.3.2): L = R + G + B for the
// luminance formats, every component clamped to [0, 1], converted per Table 4.7 and placed
// per `st`. `format` must be a colour format (not COLOR_INDEX) matching `type`.
void pack_rgba(const float* rgba, int w, int h, int d, GLenum format, GLenum type,
               const PixelStore& st, void* pixels);

// Depth floats to client memory: clamped to [0, 1], converted per Table 4.7.
void pack_depth(const float* depth, int w, int h, int d, GLenum type, const PixelStore& st,
                void* pixels);

// Indices to client memory, masked per Table 4.6 (FLOAT: not masked); BITMAP per LSB_FIRST.
void pack_index(const uint32_t* index, int w, int h, int d, GLenum type, const PixelStore& st,
                void* pixels);

} // namespace pineda
