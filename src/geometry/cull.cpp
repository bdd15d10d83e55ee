// Facing and culling helpers (GL 2.1 §3.5.1) and the vertex copies that two-sided lighting
// (§2.14.1) and flat-shaded polygon points (§2.14.7) need.
#include "geometry/cull.h"

#include <cmath>

namespace pineda {

void init_face_state(FaceState& fs, const RasterState& rs) {
  fs.front_ccw = rs.front_face != GL_CW;
  const bool cull = rs.cull_enabled;
  fs.cull_front = cull && (rs.cull_face == GL_FRONT || rs.cull_face == GL_FRONT_AND_BACK);
  fs.cull_back = cull && (rs.cull_face == GL_BACK || rs.cull_face == GL_FRONT_AND_BACK);
  fs.mode[0] = rs.polygon_mode[0];
  fs.mode[1] = rs.polygon_mode[1];
  fs.two_sided = rs.two_sided;
  fs.flat = rs.flat;
  const int n = rs.attr_count;
  fs.copy_count = n < 0 ? 0 : (n > kMaxAttr ? kMaxAttr : n);
  const RasterModes& m = rs.modes;
  fs.offset_line = m.offset_line;
  fs.offset_point = m.offset_point;
  fs.offset_factor = m.offset_factor;
  fs.offset_units_z = 2.0 * m.offset_units * m.depth_mrd;
}

double polygon_offset_z(const FaceState& fs, const PVertex* const* v, int n) {
  double m = 0.0;
  const double x0 = v[0]->win[0], y0 = v[0]->win[1], z0 = v[0]->win[2];
  for (int i = 1; i + 1 < n; ++i) {
    const double x1 = v[i]->win[0] - x0, y1 = v[i]->win[1] - y0, z1 = v[i]->win[2] - z0;
    const double x2 = v[i + 1]->win[0] - x0, y2 = v[i + 1]->win[1] - y0;
    const double z2 = v[i + 1]->win[2] - z0;
    const double det = x1 * y2 - x2 * y1;
    if (det == 0.0) continue;
    const double dzdx = std::fabs((z1 * y2 - z2 * y1) / det);
    const double dzdy = std::fabs((x1 * z2 - x2 * z1) / det);
    m = dzdx > dzdy ? dzdx : dzdy;
    break;
  }
  return fs.offset_factor * m + fs.offset_units_z;
}

int64_t polygon_area2(const PVertex* const* v, int n) {
  // Shoelace over the snapped coordinates: equal to the sum of the fan triangles' areas as
  // fixed_area2 computes them. Coordinates stay within the guard band (2^22 subpixels), so
  // each term stays below 2^46 and the sum of a clipped polygon cannot overflow.
  if (n < 3) return 0;
  int64_t sum = 0;
  int64_t px = to_fixed(v[n - 1]->win[0]), py = to_fixed(v[n - 1]->win[1]);
  for (int i = 0; i < n; ++i) {
    const int64_t x = to_fixed(v[i]->win[0]), y = to_fixed(v[i]->win[1]);
    sum += px * y - x * py;
    px = x;
    py = y;
  }
  return sum;
}

void copy_vertex(const FaceState& fs, PVertex& dst, const PVertex& src) {
  for (int k = 0; k < 4; ++k) {
    dst.clip[k] = src.clip[k];
    dst.win[k] = src.win[k];
  }
  for (int k = 0; k < fs.copy_count; ++k)
    dst.attr[k] = src.attr[k];
  dst.clipmask = src.clipmask;
  dst.edgeflag = src.edgeflag;
}

void copy_back_colored(const FaceState& fs, PVertex& dst, const PVertex& src) {
  copy_vertex(fs, dst, src);
  // The back slots keep the back colours too: raster_triangle selects kAttrBackColor itself
  // for back-facing polygons, and copy_count need not reach the back slots.
  for (int k = 0; k < 4; ++k) {
    dst.attr[kAttrColor + k] = src.attr[kAttrBackColor + k];
    dst.attr[kAttrColor2 + k] = src.attr[kAttrBackColor2 + k];
    dst.attr[kAttrBackColor + k] = src.attr[kAttrBackColor + k];
    dst.attr[kAttrBackColor2 + k] = src.attr[kAttrBackColor2 + k];
  }
}

void copy_flat_colors(PVertex& dst, const PVertex& provoking) {
  for (int k = 0; k < 4; ++k) {
    dst.attr[kAttrColor + k] = provoking.attr[kAttrColor + k];
    dst.attr[kAttrColor2 + k] = provoking.attr[kAttrColor2 + k];
  }
}

} // namespace pineda
