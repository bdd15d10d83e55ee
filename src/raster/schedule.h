// How the back end's work is shared among a context's worker threads (workers.h): the
// primitives of a large draw by bands of rows or by bins of tiles (bin.h), a large clear by
// runs of rows. The draw home (draw/draw.cpp) chooses; the threads run the geometry stage's
// primitive assembly for their share through the AssemblyJob it hands down.
#pragma once

#include <GL/gl.h>

#include "framebuffer/clear.h"
#include "framebuffer/framebuffer.h"
#include "raster/raster.h"
#include "raster/workers.h"

namespace pineda {

struct FragCtx; // fragment/fragment_ops.h
struct TriBins; // bin.h

// One draw's primitives and the geometry stage's assembly of them (geometry/assemble.h),
// handed down to the schedulers.
struct AssemblyJob {
  GLenum mode;
  const PVertex* verts;
  const uint32_t* indices; // optional
  size_t count;
  size_t units; // triangle units of a triangle mode (geometry's primitive_units), else 0
  // Every primitive into the rasterizer, for the rows of dc.bands (draw_primitives).
  void (*all)(const DrawCall& dc, GLenum mode, const PVertex* verts, const uint32_t* indices,
              size_t count);
  // Triangle units [lo, hi) into `bins` (assemble_to_bins).
  void (*range)(TriBins& bins, const DrawCall& dc, GLenum mode, const PVertex* verts,
                const uint32_t* indices, size_t count, size_t lo, size_t hi);
};

// Runs a draw on `n` threads: each assembles every primitive in order (with its own fragment
// context, stipple counter and sample count) and rasterizes only its bands' rows (workers.h
// Bands). `frag` is the draw's fragment setup; dc.samples_passed receives the sum.
void draw_banded(const DrawCall& dc, const FragCtx& frag, RasterWorkers& workers, int n,
                 const AssemblyJob& job);

// Runs a draw of filled triangles on `n` threads in batches of two phases (bin.h): setup into
// each thread's bins, then the tiles.
void draw_binned(const DrawCall& dc, const FragCtx& frag, RasterWorkers& workers, int n,
                 const AssemblyJob& job);

// glClear's buffers of `mask` (GL 2.1 §4.2.3): a large clear is split into one run of rows per
// worker thread of `workers` (when given); each pixel is written once whoever writes it, so
// the result is the same.
void clear_buffers_shared(RasterWorkers* workers, Framebuffer& fb, const ClearState& cs,
                          GLbitfield mask);

} // namespace pineda
