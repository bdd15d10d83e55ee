// Pixel state (GL 2.1 §3.6, §4.3.2; Tables 6.23-6.27 "Pixels"): the "pixel" attribute group
// (transfer modes, zoom, read buffer), the pixel maps (which no attribute group saves) and the
// pixel store modes (the client "pixel-store" group). Commands in pixel.cpp, buffers.cpp
// (PixelStore) and draw_read_buffer.cpp (ReadBuffer).
#pragma once

#include <GL/gl.h>

#include "framebuffer/pixel_store.h"
#include "pixel/transfer.h"

namespace pineda {

struct Context;
struct StateArea;

// PIXEL_MODE_BIT: Tables 6.24 and 6.27 (the maps of Table 6.25 are not saved).
struct PixelGroup {
  PixelTransfer transfer; // §3.6.3 PixelTransfer
  float zoom_x = 1.0f;    // §3.6.4 PixelZoom
  float zoom_y = 1.0f;
  // §4.3.2: FRONT when the context has no back buffer, BACK otherwise (see
  // ColorBufferGroup::draw_buffer).
  GLenum read_buffer = GL_FRONT;
};

// CLIENT_PIXEL_STORE_BIT: Table 6.23 (§3.6.1 unpack, §4.3.2 pack), with the pixel buffer
// bindings (PIXEL_PACK_BUFFER_BINDING, PIXEL_UNPACK_BUFFER_BINDING: "pixel-store" in GL 2.1
// Table 6.23; pixel_buffer.h).
struct PixelStoreGroup {
  PixelStore pack, unpack;
  GLuint pack_buffer = 0, unpack_buffer = 0;
};

// The transfer operations' view of the context's transfer modes and pixel maps.
PixelTransferView pixel_transfer_view(const Context* ctx);

// glReadPixels through the pixel transfer operations that can change the result (GL 2.1
// §4.3.2): the framebuffer values are read as floats, transformed, and packed per the pack
// state. False when the direct path (framebuffer/read_pixels.h) gives the same result. The
// caller has checked the arguments (draw_pixels.cpp).
bool read_pixels_transfer(Context* ctx, int x, int y, int w, int h, GLenum format, GLenum type,
                          void* pixels);

extern const StateArea kPixelArea; // pixel.cpp

} // namespace pineda
