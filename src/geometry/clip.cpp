// Homogeneous clipping (GL 2.1 §2.12, §2.14.8). New vertices are computed from the edge's
// inside and outside endpoints in that canonical order, whichever way the polygon walks the
// edge, so two triangles sharing a clipped edge make bit-identical vertices and no crack
// opens between them.
#include "geometry/clip.h"

#include <cmath>
#include <limits>

namespace pineda {

namespace {

// Near and far first: once the w <= 0 region is gone the remaining intersections are
// computed on well-conditioned geometry. Any fixed order keeps shared edges identical.
constexpr int kPlaneOrder[kNumClipPlanes] = {4, 5, 0, 1, 2, 3, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};

// Window coordinates the rasterizer can take. Guard-band clipping keeps |x|, |y| within
// kGuardBand up to rounding; the factor 2 is margin, not a second guard band.
constexpr float kWindowLimit = 2.0f * kGuardBand;

// dst = p + t (q - p) for position and the live attributes, interpolating from whichever end
// is nearer so the step stays small (GL 2.1 §2.12: P = t P1 + (1 - t) P2). `u` is 1 - t
// computed by the caller from the plane distances: 1.0 - t itself rounds to 0 when the
// crossing lies within 1e-16 of q (a far vertex against a near one), which would put the new
// vertex on q, possibly behind the eye.
void lerp_vertex(const ClipSetup& cs, const PVertex& p, const PVertex& q, double t, double u,
                 PVertex& dst) {
  const PVertex* base = &p;
  const PVertex* toward = &q;
  if (t > 0.5) {
    base = &q;
    toward = &p;
    t = u;
  }
  const float s = static_cast<float>(t);
  for (int k = 0; k < 4; ++k)
    dst.clip[k] = base->clip[k] + s * (toward->clip[k] - base->clip[k]);
  for (int k = 0; k < cs.lerp_count; ++k)
    dst.attr[k] = base->attr[k] + s * (toward->attr[k] - base->attr[k]);
  dst.point_size = base->point_size + s * (toward->point_size - base->point_size);
  dst.clipmask = 0;
  dst.edgeflag = 1;
}

// Put a vertex made on frustum plane p exactly on it, so that it maps exactly onto the
// viewport edge or the depth-range end (x/w = +-1 gives window x = vp.x or vp.x + vp.w).
inline void snap_to_plane(int p, PVertex& v) {
  if (p >= 6) return;
  const int axis = p >> 1;
  v.clip[axis] = (p & 1) ? v.clip[3] : -v.clip[3];
}

// The vertex where edge in-out crosses plane p; d_in >= 0 > d_out. t is taken from the inside
// end, so the result depends only on the unordered edge.
void intersect(const ClipSetup& cs, int p, const PVertex& in, float d_in, const PVertex& out,
               float d_out, PVertex& dst) {
  const double din = d_in, dout = d_out;
  lerp_vertex(cs, in, out, din / (din - dout), -dout / (din - dout), dst);
  snap_to_plane(p, dst);
  to_window(dst, cs.viewport);
}

inline bool window_ok(const PVertex& v) {
  return v.clip[3] > 0.0f && std::fabs(v.win[0]) <= kWindowLimit &&
         std::fabs(v.win[1]) <= kWindowLimit && std::isfinite(v.win[2]) && std::isfinite(v.win[3]);
}

inline bool in_pool(const ClipScratch& s, const PVertex* v) {
  return v >= s.pool && v < s.pool + kClipPoolSize;
}

// A vertex that survives clipping is inside every plane the clipper looked at, so its clip
// code is zero unless the code and the clipper disagree at a plane's edge; its window
// coordinates are then computed here rather than trusted (they are only valid for code 0).
const PVertex* finish_vertex(const ClipSetup& cs, const PVertex* v, ClipScratch& scratch) {
  if (v->clipmask != 0 && !in_pool(scratch, v)) {
    if (scratch.used == kClipPoolSize) return nullptr;
    PVertex& c = scratch.pool[scratch.used++];
    c = *v;
    c.clipmask = 0;
    to_window(c, cs.viewport);
    v = &c;
  }
  return window_ok(*v) ? v : nullptr;
}

} // namespace

void init_clip_setup(ClipSetup& cs, const RasterState& rs) {
  cs.viewport = rs.viewport;
  cs.user_mask = rs.user_clip_mask & 0x3fu;
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 4; ++k)
      cs.user[i][k] = rs.user_planes[i][k];
  const Viewport& vp = rs.viewport;
  // The same expressions as the front end's guard-band codes (transform.cpp).
  if (vp.w > 0.0f) {
    cs.gx0 = (-kGuardBand - vp.x) * 2.0f / vp.w - 1.0f;
    cs.gx1 = (kGuardBand - vp.x) * 2.0f / vp.w - 1.0f;
  }
  if (vp.h > 0.0f) {
    cs.gy0 = (-kGuardBand - vp.y) * 2.0f / vp.h - 1.0f;
    cs.gy1 = (kGuardBand - vp.y) * 2.0f / vp.h - 1.0f;
  }
  int n = rs.attr_count;
  // The back colours are swapped in after clipping.
  if (rs.two_sided && n < kAttrBackColor2 + 4) n = kAttrBackColor2 + 4;
  // The vertex shader's plane distances are interpolated with the attributes.
  cs.user_dist = cs.user_mask != 0 ? rs.user_dist : -1;
  if (cs.user_dist >= 0 && n < cs.user_dist + kMaxClipPlanes) n = cs.user_dist + kMaxClipPlanes;
  cs.lerp_count = n < 0 ? 0 : (n > kMaxAttr ? kMaxAttr : n);
}

uint32_t clip_code(const ClipSetup& cs, const float* clip) {
  // plane_distance's expressions written out, without its switch.
  const float x = clip[0], y = clip[1], z = clip[2], w = clip[3];
  uint32_t m = (!(x + w >= 0.0f) ? kClipLeft : 0u) | (!(w - x >= 0.0f) ? kClipRight : 0u) |
               (!(y + w >= 0.0f) ? kClipBottom : 0u) | (!(w - y >= 0.0f) ? kClipTop : 0u) |
               (!(z + w >= 0.0f) ? kClipNear : 0u) | (!(w - z >= 0.0f) ? kClipFar : 0u);
  for (uint32_t planes = cs.user_dist < 0 ? cs.user_mask : 0u; planes != 0; planes &= planes - 1) {
    const int i = __builtin_ctz(planes);
    const float* q = cs.user[i];
    if (!(q[0] * x + q[1] * y + q[2] * z + q[3] * w >= 0.0f)) m |= kClipUser0 << i;
  }
  // w <= 0 only survives the frustum tests at the origin, which has no projection; an
  // infinite w would pass every test yet poisons interpolation; a denormal w passes too, but
  // its reciprocal (to_window) overflows to infinity. All go to the clipper.
  const bool w_ok =
      w >= std::numeric_limits<float>::min() && w <= std::numeric_limits<float>::max();
  const bool inside_guard = x - cs.gx0 * w >= 0.0f && cs.gx1 * w - x >= 0.0f &&
                            y - cs.gy0 * w >= 0.0f && cs.gy1 * w - y >= 0.0f;
  if (!(w_ok && inside_guard)) m |= kClipGuard;
  return m;
}

bool clip_polygon(const ClipSetup& cs, uint32_t planes, ClipPolygon& poly, ClipScratch& scratch) {
  scratch.used = 0;
  if (poly.n < 3 || poly.n > kMaxClipVerts) return false;
  ClipPolygon other;
  ClipPolygon* in = &poly;
  ClipPolygon* out = &other;
  float d[kMaxClipVerts];
  for (const int p : kPlaneOrder) {
    if (!(planes & (1u << p))) continue;
    const int n = in->n;
    int outside = 0;
    for (int i = 0; i < n; ++i) {
      d[i] = plane_distance(cs, p, *in->v[i]);
      if (!std::isfinite(d[i])) return false; // NaN or infinite input: drop (as Mesa does)
      outside += d[i] < 0.0f;
    }
    if (outside == 0) continue;
    if (outside == n) return false;
    // GL 2.1 §2.12: an edge introduced along a user plane is a boundary edge. Along frustum
    // and guard planes it is not, following Mesa (and NVIDIA): polygon-mode outlines do not
    // trace the viewport border, and the guard band must stay invisible.
    const bool new_edge_flag = p >= kFirstUserPlane && p < kFirstGuardPlane;
    int m = 0;
    for (int i = 0; i < n; ++i) {
      const int j = i + 1 == n ? 0 : i + 1;
      const bool in_i = d[i] >= 0.0f;
      if (in_i) {
        if (m == kMaxClipVerts) return false;
        out->v[m] = in->v[i];
        out->edge[m++] = in->edge[i];
      }
      if (in_i == (d[j] >= 0.0f)) continue;
      if (m == kMaxClipVerts || scratch.used == kClipPoolSize) return false;
      PVertex& nv = scratch.pool[scratch.used++];
      if (in_i) {
        // Leaving: the new vertex starts the edge that runs along the plane.
        intersect(cs, p, *in->v[i], d[i], *in->v[j], d[j], nv);
        out->edge[m] = new_edge_flag;
      } else {
        // Entering: the new vertex starts what is left of the original edge i -> j.
        intersect(cs, p, *in->v[j], d[j], *in->v[i], d[i], nv);
        out->edge[m] = in->edge[i];
      }
      nv.edgeflag = out->edge[m];
      out->v[m++] = &nv;
    }
    out->n = m;
    ClipPolygon* t = in;
    in = out;
    out = t;
    if (m < 3) return false;
  }
  if (in != &poly) {
    poly.n = in->n;
    for (int i = 0; i < in->n; ++i) {
      poly.v[i] = in->v[i];
      poly.edge[i] = in->edge[i];
    }
  }
  for (int i = 0; i < poly.n; ++i) {
    poly.v[i] = finish_vertex(cs, poly.v[i], scratch);
    if (poly.v[i] == nullptr) return false;
  }
  return true;
}

bool clip_segment(const ClipSetup& cs, uint32_t planes, const PVertex& a, const PVertex& b,
                  ClipScratch& scratch, const PVertex** out_a, const PVertex** out_b) {
  scratch.used = 0;
  // Liang-Barsky in clip space: t0 is the fraction cut from a's end, t1 from b's end.
  double t0 = 0.0, t1 = 0.0;
  double u0 = 1.0, u1 = 1.0; // 1 - t0 and 1 - t1, computed from the distances (lerp_vertex)
  int plane0 = -1, plane1 = -1;
  for (const int p : kPlaneOrder) {
    if (!(planes & (1u << p))) continue;
    const float da = plane_distance(cs, p, a);
    const float db = plane_distance(cs, p, b);
    if (!std::isfinite(da) || !std::isfinite(db)) return false;
    if (da < 0.0f && db < 0.0f) return false;
    if (da < 0.0f) {
      const double t = static_cast<double>(da) / (static_cast<double>(da) - db);
      if (t > t0) {
        t0 = t;
        u0 = -static_cast<double>(db) / (static_cast<double>(da) - db);
        plane0 = p;
      }
    } else if (db < 0.0f) {
      const double t = static_cast<double>(db) / (static_cast<double>(db) - da);
      if (t > t1) {
        t1 = t;
        u1 = -static_cast<double>(da) / (static_cast<double>(db) - da);
        plane1 = p;
      }
    }
  }
  if (t0 + t1 >= 1.0) return false;
  const PVertex* ra = &a;
  const PVertex* rb = &b;
  if (plane0 >= 0) {
    PVertex& nv = scratch.pool[scratch.used++];
    lerp_vertex(cs, a, b, t0, u0, nv);
    snap_to_plane(plane0, nv);
    to_window(nv, cs.viewport);
    ra = &nv;
  }
  if (plane1 >= 0) {
    PVertex& nv = scratch.pool[scratch.used++];
    lerp_vertex(cs, b, a, t1, u1, nv);
    snap_to_plane(plane1, nv);
    to_window(nv, cs.viewport);
    rb = &nv;
  }
  ra = finish_vertex(cs, ra, scratch);
  rb = finish_vertex(cs, rb, scratch);
  if (ra == nullptr || rb == nullptr) return false;
  *out_a = ra;
  *out_b = rb;
  return true;
}

} // namespace pineda
