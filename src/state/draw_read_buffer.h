// The colour buffers drawing writes and reading reads (GL 2.1 §4.2.1, §4.3.2), for
// window-system layers that give a context a front and a back buffer; and the framebuffer
// area (Table 6.35: the framebuffer's configuration for glGet).
#pragma once

#include "state/context.h"

namespace pineda {

// Points ctx->fb.color, color_also and read_color at the buffers DRAW_BUFFER and READ_BUFFER
// name. Call when either changes or when the window-system layer attaches new buffers; does
// nothing for a framebuffer with a single colour buffer.
void select_color_buffers(Context* ctx);

struct StateArea;
extern const StateArea kFramebufferArea; // draw_read_buffer.cpp

} // namespace pineda
