// Facing, culling and polygon mode (GL 2.1 §3.5.1, §3.5.4), and two-sided colour selection
// (§2.14.1): the last step of the geometry back end before raster_triangle / raster_line /
// raster_point. The emitter is a template over a Sink with triangle/line/point members so that
// production calls the rasterizer directly and tests can record what would be drawn.
#pragma once

#include <cstddef>
#include <cstdint>

#include "geometry/clip.h"
#include "core/vertex.h"
#include "raster/raster.h"

namespace pineda {

// Per-draw facing and polygon state derived from RasterState.
struct FaceState {
  bool front_ccw = true; // FrontFace(CCW): positive window-space area is front facing
  bool cull_front = false;
  bool cull_back = false;
  GLenum mode[2] = {GL_FILL, GL_FILL}; // [0] front, [1] back
  bool two_sided = false;
  bool flat = false;
  int copy_count = 4; // leading attribute floats a local vertex copy must carry
  // GL 2.1 §3.5.5: polygon offset of polygons drawn in LINE and POINT mode, applied to the
  // window z of their vertices (FILL is offset by raster_triangle).
  bool offset_line = false, offset_point = false;
  double offset_factor = 0.0;
  double offset_units_z = 0.0; // units * r in window z (see polygon_offset_depth)
};

// The polygon offset in window z of the polygon v[0..n): the depth slopes of the plane
// through its first three vertices that span an area.
double polygon_offset_z(const FaceState& fs, const PVertex* const* v, int n);

void init_face_state(FaceState& fs, const RasterState& rs);

// Twice the signed window-space area of a polygon (GL 2.1 §2.14.1 eq. 2.6) from the same
// fixed-point coordinates the rasterizer uses, summed exactly in 64 bits.
int64_t polygon_area2(const PVertex* const* v, int n);

// GL 2.1 §3.5.1: front facing iff the (FrontFace-adjusted) area is positive; a zero area is
// therefore back facing, as in Mesa.
inline bool is_back_facing(const FaceState& fs, int64_t area2) {
  return fs.front_ccw ? !(area2 > 0) : !(area2 < 0);
}

inline bool is_culled(const FaceState& fs, bool back) {
  return back ? fs.cull_back : fs.cull_front;
}

// Copy the live part of src into dst (position, window coordinates, flags, fs.copy_count
// attribute floats).
void copy_vertex(const FaceState& fs, PVertex& dst, const PVertex& src);

// dst = src with the back colours in the colour slots (GL 2.1 §2.14.1: back-facing polygons
// take the back colours when two-sided lighting is on).
void copy_back_colored(const FaceState& fs, PVertex& dst, const PVertex& src);

// Overwrite dst's primary and secondary colours with the provoking vertex's (GL 2.1 §2.14.7).
void copy_flat_colors(PVertex& dst, const PVertex& provoking);

// Rasterize one polygon that survived clipping and culling, in the polygon mode of its face
// (GL 2.1 §3.5.4). v[0..n) are in order, edge[i] flags the edge v[i] -> v[i+1] as boundary;
// `first_edge` is where LINE mode starts walking (Mesa's order for an unclipped triangle
// starts at the closing edge). FILL draws the fan v0, vi, vi+1; LINE the boundary edges;
// POINT the vertices that start a boundary edge. A zero-area polygon fills nothing but still
// outlines in LINE and POINT mode (it is a back-facing polygon, GL 2.1 §3.5.1); sinks with
// kKeepsZeroArea (selection, feedback) receive it in FILL mode too.
template <class Sink>
void emit_polygon(const FaceState& fs, Sink& sink, const PVertex* const* v, const bool* edge, int n,
                  int first_edge, const PVertex& provoking, bool back, int64_t area2) {
  const GLenum mode = fs.mode[back ? 1 : 0];
  if ((mode == GL_FILL && area2 == 0 && !Sink::kKeepsZeroArea) || n < 3 || n > kMaxClipVerts)
    return;

  // Two-sided lighting: local copies with the back colours in the colour slots, so the
  // rasterizer needs to know nothing about it.
  PVertex swapped[kMaxClipVerts];
  PVertex swapped_prov;
  const PVertex* const* vs = v;
  const PVertex* local[kMaxClipVerts];
  const PVertex* prov = &provoking;
  if (fs.two_sided && back) {
    for (int i = 0; i < n; ++i) {
      copy_back_colored(fs, swapped[i], *v[i]);
      local[i] = &swapped[i];
    }
    copy_back_colored(fs, swapped_prov, provoking);
    vs = local;
    prov = &swapped_prov;
  }

  // Polygon offset for the outline and vertex modes: local copies with the z moved.
  PVertex shifted[kMaxClipVerts];
  const PVertex* shifted_ptr[kMaxClipVerts];
  if ((mode == GL_LINE && fs.offset_line) || (mode == GL_POINT && fs.offset_point)) {
    const float dz = static_cast<float>(polygon_offset_z(fs, vs, n));
    for (int i = 0; i < n; ++i) {
      copy_vertex(fs, shifted[i], *vs[i]);
      shifted[i].win[2] += dz;
      shifted_ptr[i] = &shifted[i];
    }
    vs = shifted_ptr;
  }

  if (mode == GL_FILL) {
    for (int i = 1; i + 1 < n; ++i)
      sink.triangle(*vs[0], *vs[i], *vs[i + 1], *prov, back);
  } else if (mode == GL_LINE) {
    for (int k = 0, i = first_edge; k < n; ++k, i = (i + 1 == n) ? 0 : i + 1)
      if (edge[i]) sink.line(*vs[i], *vs[i + 1 == n ? 0 : i + 1], *prov, back);
  } else if (mode == GL_POINT) {
    for (int i = 0; i < n; ++i) {
      if (!edge[i]) continue;
      if (fs.flat) {
        PVertex p;
        copy_vertex(fs, p, *vs[i]);
        copy_flat_colors(p, *prov);
        sink.point(p, back);
      } else {
        sink.point(*vs[i], back);
      }
    }
  }
}

// The test seam and the selection and feedback path: a sink with virtual members, and the
// assembler instantiated for it (draw_primitives_to, assemble.h). draw_primitives() itself uses
// a sink that calls raster_* directly (no indirection).
class PrimitiveSink {
public:
  // GL 2.1 §5.2, §5.3: selection and feedback report every polygon that survives clipping and
  // culling, a zero-area one too (culling is the only test of its facing), as Mesa does.
  static constexpr bool kKeepsZeroArea = true;
  virtual ~PrimitiveSink() = default;
  virtual void triangle(const PVertex& a, const PVertex& b, const PVertex& c,
                        const PVertex& provoking, bool back_facing) = 0;
  // back_facing: an outline of a back-facing polygon (emit_polygon), false for lines and
  // points of their own.
  virtual void line(const PVertex& a, const PVertex& b, const PVertex& provoking,
                    bool back_facing) = 0;
  virtual void point(const PVertex& p, bool back_facing) = 0;
};

} // namespace pineda
