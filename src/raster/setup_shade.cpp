// Interpolation planes of the per-fragment shading path (GL 2.1 §3.5.1 eq 3.9 for triangles,
// §3.4.1 eq 3.7 for lines: every attribute perspective-correct, as value/w and 1/w planes).
#include "raster/setup_shade.h"

#include "shader/io.h"

namespace pineda {

namespace {

// Calls f(slot, out_plane) for every live attribute plane but the colours.
template <typename F> void for_each_plane(const ShadeSetup& ss, ShadeInputs& out, F f) {
  for (int k = 0; k < ss.unit_count; ++k) {
    const int u = ss.unit[k].index;
    for (int c = 0; c < 4; ++c)
      f(kAttrTex0 + 4 * u + c, out.tex_w[u][c]);
  }
  if (ss.fog) f(kAttrFog, out.fog_w);
}

void const_colors(const ShadeSetup& ss, const PVertex& v, int slot, ShadeInputs& out) {
  // Clamped as the interpolated colours are (GL 2.1 §2.14.6 range of fragment colours).
  const auto clamp01 = [](float x) { return x > 0.0f ? (x < 1.0f ? x : 1.0f) : 0.0f; };
  out.const_colors = true;
  for (int c = 0; c < 4; ++c)
    out.color[c] = clamp01(v.attr[slot + c]);
  for (int c = 0; c < 3; ++c)
    out.color2[c] = ss.color_sum ? clamp01(v.attr[slot + 4 + c]) : 0.0f;
}

bool same_colors(const ShadeSetup& ss, const PVertex* const* v, int n, int slot) {
  const int count = ss.color_sum ? 7 : 4;
  for (int i = 1; i < n; ++i)
    for (int c = 0; c < count; ++c)
      if (v[i]->attr[slot + c] != v[0]->attr[slot + c]) return false;
  return true;
}

// A fragment shader's input planes (FragmentProgram): every input perspective-correct; the
// colours from `color_slot` on (the back colours of a back-facing polygon under two-sided
// colouring), constant from `provoking` under flat shading (§2.14.7). `plane(slot, p)` makes
// the value/w plane of an attribute slot.
template <typename F>
void program_planes(const FragmentProgram& fp, const PVertex& provoking, bool flat, int color_slot,
                    ShadeInputs& out, F plane) {
  // gl_PointCoord is zero but for point sprites (setup_shade_sprite).
  if (fp.point_coord) out.point_coord[0] = out.point_coord[1] = PlaneF{};
  for (int i = 0; i < fp.input_count; ++i) {
    const int at = fp.input_attr[i];
    PlaneF p;
    if (at >= kAttrTex0) {
      plane(at, p);
    } else if (flat) {
      const float v = provoking.attr[color_slot + at];
      p = PlaneF{out.inv_w.v0 * v, out.inv_w.dx * v, out.inv_w.dy * v};
    } else {
      plane(color_slot + at, p);
    }
    out.prog_w[i] = {p.v0, p.dx, p.dy};
  }
}

} // namespace

void setup_shade_triangle(const ShadeSetup& ss, const PlaneSetup& ps, const PVertex& a,
                          const PVertex& b, const PVertex& c, const PVertex& provoking, bool flat,
                          int color_slot, bool back_facing, ShadeInputs& out) {
  const double wa = a.win[3], wb = b.win[3], wc = c.win[3];
  out.inv_w = plane_f(ps, wa, wb, wc);
  if (ss.program != nullptr) {
    out.front_facing = !back_facing;
    program_planes(*ss.program, provoking, flat, color_slot, out, [&](int slot, PlaneF& p) {
      p = plane_f(ps, a.attr[slot] * wa, b.attr[slot] * wb, c.attr[slot] * wc);
    });
    return;
  }
  const auto plane = [&](int slot, PlaneF& p) {
    p = plane_f(ps, a.attr[slot] * wa, b.attr[slot] * wb, c.attr[slot] * wc);
  };
  for_each_plane(ss, out, plane);
  const PVertex* v[3] = {&a, &b, &c};
  // GL 2.1 §2.14.7: flat shading takes the provoking vertex's colours.
  if (flat || same_colors(ss, v, 3, color_slot)) {
    const_colors(ss, flat ? provoking : a, color_slot, out);
    return;
  }
  out.const_colors = false;
  for (int k = 0; k < 4; ++k)
    plane(color_slot + k, out.color_w[k]);
  if (ss.color_sum)
    for (int k = 0; k < 3; ++k)
      plane(color_slot + 4 + k, out.color2_w[k]);
}

void setup_shade_line(const ShadeSetup& ss, const PVertex& a, const PVertex& b,
                      const PVertex& provoking, bool flat, double t0, double tdx, double tdy,
                      ShadeInputs& out) {
  const double wa = a.win[3], wb = b.win[3];
  const auto line_plane = [&](double va, double vb) {
    const double dv = vb - va;
    return PlaneF{static_cast<float>(va + dv * t0), static_cast<float>(dv * tdx),
                  static_cast<float>(dv * tdy)};
  };
  out.inv_w = line_plane(wa, wb);
  const auto plane = [&](int slot, PlaneF& p) {
    p = line_plane(a.attr[slot] * wa, b.attr[slot] * wb);
  };
  if (ss.program != nullptr) {
    out.front_facing = true; // §3.11.2: lines and points are front-facing
    program_planes(*ss.program, provoking, flat, kAttrColor, out, plane);
    return;
  }
  for_each_plane(ss, out, plane);
  const PVertex* v[2] = {&a, &b};
  if (flat || same_colors(ss, v, 2, kAttrColor)) {
    const_colors(ss, flat ? provoking : a, kAttrColor, out);
    return;
  }
  out.const_colors = false;
  for (int k = 0; k < 4; ++k)
    plane(kAttrColor + k, out.color_w[k]);
  if (ss.color_sum)
    for (int k = 0; k < 3; ++k)
      plane(kAttrColor + 4 + k, out.color2_w[k]);
}

void setup_shade_point(const ShadeSetup& ss, const PVertex& p, ShadeInputs& out) {
  out.inv_w = PlaneF{1.0f, 0.0f, 0.0f};
  if (ss.program != nullptr) {
    out.front_facing = true;
    program_planes(*ss.program, p, true, kAttrColor, out, [&](int slot, PlaneF& pl) {
      pl = PlaneF{p.attr[slot], 0.0f, 0.0f};
    });
    return;
  }
  for_each_plane(ss, out, [&](int slot, PlaneF& pl) { pl = PlaneF{p.attr[slot], 0.0f, 0.0f}; });
  const_colors(ss, p, kAttrColor, out);
}

namespace {

// The sprite coordinates s and t (§3.3.1 eqs. 3.3, 3.4) of a square of side `size` centred on
// (x, y), as planes from pixel (ox, oy); t upwards when `lower_left`.
void sprite_planes(bool lower_left, double x, double y, double size, int ox, int oy,
                   PlaneF& s_plane, PlaneF& t_plane) {
  const double inv = 1.0 / size;
  const double s0 = 0.5 + (ox + 0.5 - x) * inv;
  const double t_up = (oy + 0.5 - y) * inv;
  const double t0 = lower_left ? 0.5 + t_up : 0.5 - t_up;
  const double dt = lower_left ? inv : -inv;
  s_plane = PlaneF{static_cast<float>(s0), static_cast<float>(inv), 0.0f};
  t_plane = PlaneF{static_cast<float>(t0), 0.0f, static_cast<float>(dt)};
}

} // namespace

void setup_point_coord(double x, double y, double size, int ox, int oy, ShadeInputs& out) {
  sprite_planes(false, x, y, size, ox, oy, out.point_coord[0], out.point_coord[1]);
}

void setup_shade_sprite(const ShadeSetup& ss, const RasterModes& modes, const PVertex& p,
                        float size, int ox, int oy, ShadeInputs& out) {
  setup_shade_point(ss, p, out);
  PlaneF s_plane, t_plane;
  sprite_planes(modes.sprite_lower_left, p.win[0], p.win[1], size, ox, oy, s_plane, t_plane);
  if (ss.program != nullptr) {
    // A fragment shader: gl_PointCoord is (s, t), and gl_TexCoord[u] of the units with
    // COORD_REPLACE is (s, t, 0, 1) (every plane is a value plane: 1/w is 1 for points).
    const FragmentProgram& fp = *ss.program;
    if (fp.point_coord) {
      out.point_coord[0] = s_plane;
      out.point_coord[1] = t_plane;
    }
    for (int i = 0; i < fp.input_count; ++i) {
      const int slot = fp.input_comp[i] / 4 - shader::kFragTexCoord0, c = fp.input_comp[i] % 4;
      if (slot < 0 || slot >= kMaxTexUnits || !((modes.sprite_coord_replace >> slot) & 1u))
        continue;
      const PlaneF pl = c == 0 ? s_plane : c == 1 ? t_plane : PlaneF{c == 3 ? 1.0f : 0.0f, 0, 0};
      out.prog_w[i] = {pl.v0, pl.dx, pl.dy};
    }
    return;
  }
  for (int k = 0; k < ss.unit_count; ++k) {
    const int u = ss.unit[k].index;
    if (!((modes.sprite_coord_replace >> u) & 1u)) continue;
    out.tex_w[u][0] = s_plane;
    out.tex_w[u][1] = t_plane;
    out.tex_w[u][2] = PlaneF{0.0f, 0.0f, 0.0f};
    out.tex_w[u][3] = PlaneF{1.0f, 0.0f, 0.0f};
  }
}

} // namespace pineda
