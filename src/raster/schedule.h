// How the back end's work is shared among a context's worker threads (workers.h): a large clear
// by runs of rows.
#pragma once

#include <GL/gl.h>

#include "framebuffer/clear.h"
#include "framebuffer/framebuffer.h"
#include "raster/workers.h"

namespace pineda {

// glClear's buffers of `mask` (GL 2.1 §4.2.3): a large clear is split into one run of rows per
// worker thread of `workers` (when given); each pixel is written once whoever writes it, so
// the result is the same.
void clear_buffers_shared(RasterWorkers* workers, Framebuffer& fb, const ClearState& cs,
                          GLbitfield mask);

} // namespace pineda
