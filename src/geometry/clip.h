// Clipping of triangles (as polygons) and line segments in homogeneous clip space
// (GL 2.1 §2.12): the six frustum planes, the enabled user planes and the four guard-band
// planes that keep window x and y within +-kGuardBand pixels. Pure functions of plain data so
// that they can be tested without a rasterizer.
#pragma once

#include <cstdint>

#include "core/vertex.h"
#include "raster/raster.h"

namespace pineda {

// Plane indices. 0..5 are the frustum planes in ClipBit order (left, right, bottom, top, near,
// far), 6..11 the user planes (kClipUser0 << i), 12..15 the guard band (x min, x max, y min,
// y max). A "plane set" is a bit mask over these indices; planes_for_mask() turns a
// primitive's OR of vertex clip codes into the planes it must be clipped against.
constexpr int kNumClipPlanes = 16;
constexpr int kFirstUserPlane = 6;
constexpr int kFirstGuardPlane = 12;
constexpr uint32_t kGuardPlaneBits = 0xf000u;

inline uint32_t planes_for_mask(uint32_t clipmask_or) {
  return (clipmask_or & 0xfffu) | ((clipmask_or & kClipGuard) ? kGuardPlaneBits : 0u);
}

// A clipped polygon holds at most its 3 input vertices plus one per plane (convex input gains
// at most one vertex per plane); the slack absorbs rounding that makes the intermediate
// polygon very slightly non-convex. A pass that would overflow drops the primitive.
constexpr int kMaxClipVerts = 3 + kNumClipPlanes + 13;
// New vertices a single clip_polygon call may create (at most two per plane when convex).
constexpr int kClipPoolSize = 2 * kNumClipPlanes + 16;

// Per-draw clipping state derived from RasterState.
struct ClipSetup {
  Viewport viewport;
  uint32_t user_mask = 0; // bit i: user plane i enabled
  float user[6][4] = {};  // user planes in clip space; inside when dot >= 0
  // Guard band in normalized device coordinates: x/w within [gx0, gx1], y/w within [gy0, gy1].
  // Computed with the same float expressions as the front end's clip codes, so the clipper
  // and the codes agree on which side of each plane a vertex lies.
  float gx0 = -1, gx1 = 1, gy0 = -1, gy1 = 1;
  // Leading attribute floats interpolated at new vertices. Covers the back colours under
  // two-sided lighting even when attr_count does not (they are swapped in after clipping).
  int lerp_count = 4;
  // With a vertex shader (RasterState::user_dist): `user` holds the planes in eye space, the
  // vertex stage writes each vertex's distance to enabled plane i at attr[user_dist + i] and
  // sets its user clip bits; the clipper interpolates and reads those distances. -1: the
  // planes are in clip space and tested on the clip coordinates.
  int user_dist = -1;
};

void init_clip_setup(ClipSetup& cs, const RasterState& rs);

// Signed distance of vertex v to plane p; >= 0 is inside. Evaluated exactly as the front
// end's clip-code tests (a < b rewritten as b - a, whose sign IEEE arithmetic keeps).
inline float plane_distance(const ClipSetup& cs, int p, const PVertex& v) {
  const float* c = v.clip;
  switch (p) {
  case 0:
    return c[0] + c[3];
  case 1:
    return c[3] - c[0];
  case 2:
    return c[1] + c[3];
  case 3:
    return c[3] - c[1];
  case 4:
    return c[2] + c[3];
  case 5:
    return c[3] - c[2];
  case 12:
    return c[0] - cs.gx0 * c[3];
  case 13:
    return cs.gx1 * c[3] - c[0];
  case 14:
    return c[1] - cs.gy0 * c[3];
  case 15:
    return cs.gy1 * c[3] - c[1];
  default: {
    if (cs.user_dist >= 0) return v.attr[cs.user_dist + p - kFirstUserPlane];
    const float* q = cs.user[p - kFirstUserPlane];
    return q[0] * c[0] + q[1] * c[1] + q[2] * c[2] + q[3] * c[3];
  }
  }
}

// The clip code of a clip-space position (ClipBit set), with NaN outside every plane and a
// w that is not positive and finite flagged as kClipGuard; the front end's rules (plus the
// infinite-w case). Without the user planes when the vertex stage sets their bits
// (user_dist >= 0).
uint32_t clip_code(const ClipSetup& cs, const float* clip);

// A polygon as the clipper sees it: vertex pointers and, per vertex, the boundary flag of the
// edge that starts there (GL 2.1 §2.6.2).
struct ClipPolygon {
  int n = 0;
  const PVertex* v[kMaxClipVerts];
  bool edge[kMaxClipVerts];
};

// Storage for the vertices the clipper creates. Left uninitialized on purpose: declare it
// without braces so that it costs nothing until used.
struct ClipScratch {
  int used;
  PVertex pool[kClipPoolSize];
};

// Clip `poly` in place against the planes in `planes` (Sutherland-Hodgman, GL 2.1 §2.12).
// Returns false when nothing remains or the input is not finite. On success every vertex has
// w > 0 and finite window coordinates; new vertices live in `scratch` and carry the edge
// flags of GL 2.1 §2.12 as Mesa applies them: an edge along a user plane is a boundary edge,
// an edge along a frustum or guard-band plane is not, and the surviving part of a cut edge
// keeps its original flag.
bool clip_polygon(const ClipSetup& cs, uint32_t planes, ClipPolygon& poly, ClipScratch& scratch);

// Clip segment a-b against `planes`. Returns false when it is clipped away; otherwise *out_a
// and *out_b point at the originals or at new vertices in `scratch`.
bool clip_segment(const ClipSetup& cs, uint32_t planes, const PVertex& a, const PVertex& b,
                  ClipScratch& scratch, const PVertex** out_a, const PVertex** out_b);

} // namespace pineda
