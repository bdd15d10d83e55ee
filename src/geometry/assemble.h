// Primitive assembly (GL 2.1 §2.6.1): the ten Begin modes become points, segments and
// triangles, which are clipped (clip.h), culled (cull.h) and handed to the rasterizer, to a
// PrimitiveSink, or set up into the bins of a binned draw (raster/bin.h). The draw home
// (draw/draw.cpp) decides whether a draw is shared among the worker threads
// (raster/schedule.h), which then call these for their share.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>

#include "core/vertex.h"
#include "raster/raster.h"

namespace pineda {

class PrimitiveSink; // cull.h
struct TriBins;      // raster/bin.h

// Primitive assembly, clipping, culling and rasterization of `count` vertices in `mode`
// (GL_POINTS .. GL_POLYGON) on the calling thread, for the rows of dc.bands. With indices ==
// nullptr the vertices are taken in order verts[0..count); otherwise verts[indices[i]].
// Incomplete primitives are ignored (GL 2.1 §2.6.1). With dc.samples_passed the samples that
// passed are added there.
void draw_primitives(const DrawCall& dc, GLenum mode, const PVertex* verts, const uint32_t* indices,
                     size_t count);

// The same primitives into `sink` (selection, feedback, tests).
void draw_primitives_to(PrimitiveSink& sink, const DrawCall& dc, GLenum mode, const PVertex* verts,
                        const uint32_t* indices, size_t count);

// The units a triangle mode's primitives are counted in, for splitting a draw among threads:
// triangles, or quads for QUADS and QUAD_STRIP (two triangles each). 0 for other modes.
size_t primitive_units(GLenum mode, size_t count);

// Assembly, clipping, culling and triangle setup of units [lo, hi) of a triangle mode into
// `bins` (phase 1 of a binned draw, raster/bin.h). Only for draws that fill both faces.
void assemble_to_bins(TriBins& bins, const DrawCall& dc, GLenum mode, const PVertex* verts,
                      const uint32_t* indices, size_t count, size_t lo, size_t hi);

} // namespace pineda
