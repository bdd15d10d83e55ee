// The colour buffers drawing writes and reading reads (GL 2.1 §4.2.1, §4.3.2), for
// window-system layers that give a context a front and a back buffer; and the framebuffer
// area (Table 6.35: the framebuffer's configuration for glGet).
#pragma once

#include "state/context.h"

namespace pineda {

struct StateArea;
extern const StateArea kFramebufferArea; // draw_read_buffer.cpp

} // namespace pineda
