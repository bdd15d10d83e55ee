// What a window-system layer (OSMesa, GLX, EGL) does to a GL context: the one place where they
// touch the Context. A drawable's buffers are described to the context, the context is told
// when it is made current for the first time, and it is given the hooks glFlush and
// DrawBuffer/ReadBuffer call back into the window system through.
#pragma once

#include <cstddef>
#include <cstdint>

#include "framebuffer/framebuffer.h"

namespace pineda {

struct Context;

namespace winsys {

// The buffers of one drawable, rows in GL order (row 0 at the bottom; strides may be negative).
struct SurfaceBuffers {
  int width = 0, height = 0;
  ColorFormat format = ColorFormat::RGBA8;
  int alpha_bits = 8;
  uint8_t* color = nullptr; // the buffer GL renders into: the back buffer when there is one
  ptrdiff_t stride = 0;
  // The front buffer of a drawable with two (a double-buffered window), laid out as `color`;
  // nullptr for a drawable with one colour buffer.
  uint8_t* front = nullptr;
  // `color` is a back buffer (GL 2.1 table 4.4): a double-buffered drawable, also one whose
  // front buffer is never seen (a pbuffer).
  bool back = false;
  int depth_bits = 0;
  uint32_t* depth = nullptr;
  int stencil_bits = 0;
  uint8_t* stencil = nullptr;
  int accum_bits = 0;
  int16_t* accum = nullptr;
};

// Describes the drawable's buffers to ctx (its framebuffer and colour buffers). With a front
// buffer, the draw and read buffers are reselected without calling the front_selected hook.
void bind_buffers(Context* ctx, const SurfaceBuffers& b);
// The drawable is gone: ctx renders nowhere until it is bound again.
void unbind_buffers(Context* ctx);
// GL 2.1 §2.11.1, §4.1.2, §4.2.1, §4.3.2: the first time a context is made current, its
// viewport and scissor box become the whole drawable and its draw and read buffers BACK when
// the drawable has a back buffer, FRONT otherwise. Does nothing after the first time.
void first_make_current(Context* ctx, int width, int height, bool has_back);
// Whether this is the context's first make-current (before first_make_current).
bool never_current(const Context* ctx);

// glFlush and glFinish call `present_front` (a single-buffered window shows what was rendered,
// GL 2.1 §5.5); DrawBuffer/ReadBuffer call `front_selected` when they select the front buffer
// of a double-buffered drawable (its contents may have to be fetched).
void set_hooks(Context* ctx, void (*present_front)(Context*), void (*front_selected)(Context*));

// Whether ctx draws into (shown at glFlush) or reads from the front buffer it was given.
bool draws_front(const Context* ctx);
bool uses_front(const Context* ctx);

} // namespace winsys
} // namespace pineda
