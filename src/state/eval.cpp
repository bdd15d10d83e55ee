// Evaluators (GL 2.1 §5.1): glMap1/2, glGetMap, glMapGrid1/2, glEvalCoord1/2, glEvalPoint1/2,
// glEvalMesh1/2, and the evaluator area (Table 6.28, eval.h): the MAP1_*/MAP2_* and
// AUTO_NORMAL enables, the grid queries and EVAL_BIT.
//
// Maps are Bézier polynomials in Bernstein form, evaluated in double precision. An evaluation
// emits the vertex with its evaluated attributes straight into the primitive being assembled:
// §5.1 says evaluated values replace the current ones for that vertex only ("use of evaluators
// has no effect on the current color, normal, or texture coordinates"), which is also what Mesa
// does.
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <type_traits>

#include "state/api_util.h"
#include "dispatch.h"
#include "state/area.h"
#include "state/draw_call.h"
#include "state/eval.h"

namespace pineda {

namespace {

constexpr GLenum kMap1Base = GL_MAP1_COLOR_4; // 0x0D90 .. MAP1_VERTEX_4 0x0D98
constexpr GLenum kMap2Base = GL_MAP2_COLOR_4; // 0x0DB0 .. MAP2_VERTEX_4 0x0DB8

// Values per control point of each kind (§5.1 Table 5.1).
constexpr int kComponents[kEvalKindCount] = {4, 1, 3, 1, 2, 3, 4, 3, 4};

// The kind of a MAP1_* (dim 1) or MAP2_* (dim 2) target, or -1.
int map_kind(GLenum target, int dim) {
  const GLenum base = dim == 1 ? kMap1Base : kMap2Base;
  if (target < base || target >= base + kEvalKindCount) return -1;
  return static_cast<int>(target - base);
}

// §5.1: the initial maps are constant: vertices (0,0,0,1), normals (0,0,1), RGBA (1,1,1,1),
// index 1, texture coordinates (0,0,0,1), each as the subset its kind has.
void initial_point(int kind, float* p) {
  switch (kind) {
  case kEvalColor4:
    p[0] = p[1] = p[2] = p[3] = 1.0f;
    break;
  case kEvalIndex:
    p[0] = 1.0f;
    break;
  case kEvalNormal:
    p[0] = 0.0f, p[1] = 0.0f, p[2] = 1.0f;
    break;
  case kEvalTex4:
  case kEvalVertex4:
    p[0] = p[1] = p[2] = 0.0f, p[3] = 1.0f;
    break;
  default:
    for (int c = 0; c < kComponents[kind]; ++c)
      p[c] = 0.0f;
    break;
  }
}

// The Bernstein basis of degree order-1 at t in b[0..order), and its derivative in db when
// db is not null: B'_i^n = n (B_{i-1}^{n-1} - B_i^{n-1}).
void bernstein(int order, double t, double* b, double* db) {
  const double s = 1.0 - t;
  b[0] = 1.0;
  if (db != nullptr) db[0] = 0.0;
  for (int d = 1; d < order; ++d) {
    // b holds the basis of degree d-1 (d entries).
    if (db != nullptr && d == order - 1) {
      for (int i = 0; i <= d; ++i)
        db[i] = d * ((i > 0 ? b[i - 1] : 0.0) - (i < d ? b[i] : 0.0));
    }
    b[d] = t * b[d - 1];
    for (int i = d - 1; i >= 1; --i)
      b[i] = s * b[i] + t * b[i - 1];
    b[0] = s * b[0];
  }
}

// Value of a one-dimensional map at domain coordinate u into out[0..k).
void eval_map1(const EvalMap1& m, int k, double u, float* out) {
  double b[kMaxEvalOrder];
  bernstein(m.order, (u - m.u1) / (double(m.u2) - m.u1), b, nullptr);
  for (int c = 0; c < k; ++c) {
    double sum = 0.0;
    for (int i = 0; i < m.order; ++i)
      sum += b[i] * m.points[size_t(i) * k + c];
    out[c] = static_cast<float>(sum);
  }
}

// Value of a two-dimensional map at (u, v); with du and dv also its partial derivatives with
// respect to the normalized coordinates.
void eval_map2(const EvalMap2& m, int k, double u, double v, double* out, double* du, double* dv) {
  double bu[kMaxEvalOrder], bv[kMaxEvalOrder], dbu[kMaxEvalOrder], dbv[kMaxEvalOrder];
  const bool deriv = du != nullptr;
  bernstein(m.uorder, (u - m.u1) / (double(m.u2) - m.u1), bu, deriv ? dbu : nullptr);
  bernstein(m.vorder, (v - m.v1) / (double(m.v2) - m.v1), bv, deriv ? dbv : nullptr);
  for (int c = 0; c < k; ++c) {
    double p = 0.0, pu = 0.0, pv = 0.0;
    for (int i = 0; i < m.uorder; ++i) {
      double row = 0.0, row_dv = 0.0;
      for (int j = 0; j < m.vorder; ++j) {
        const double r = m.points[(size_t(i) * m.vorder + j) * k + c];
        row += bv[j] * r;
        if (deriv) row_dv += dbv[j] * r;
      }
      p += bu[i] * row;
      if (deriv) pu += dbu[i] * row, pv += bu[i] * row_dv;
    }
    out[c] = p;
    if (deriv) du[c] = pu, dv[c] = pv;
  }
}

// §5.1: of several enabled texture-coordinate maps only the one with the most coordinates
// is used; -1 when none is enabled.
int tex_kind(const bool* enabled) {
  for (int kind = kEvalTex4; kind >= kEvalTex1; --kind)
    if (enabled[kind]) return kind;
  return -1;
}

// The vertex map in use (VERTEX_4 before VERTEX_3), or -1.
int vertex_kind(const bool* enabled) {
  return enabled[kEvalVertex4] ? kEvalVertex4 : enabled[kEvalVertex3] ? kEvalVertex3 : -1;
}

// §5.1 EvalCoord1: every enabled one-dimensional map is evaluated; the Vertex comes last, and
// without a vertex map nothing is issued that could be observed (the colour, normal and
// texture coordinate commands do not change current state). A Vertex outside Begin/End has no
// effect (§2.7).
void eval_coord1(Context* ctx, double u) {
  const EvalGroup& e = ctx->eval;
  const int vk = vertex_kind(e.map1_enabled);
  if (vk < 0 || ctx->imm.mode == kOutsideBeginEnd) return;
  InputVertex& v = append_current_vertex(ctx);
  if (e.map1_enabled[kEvalColor4]) eval_map1(e.map1[kEvalColor4], 4, u, v.color);
  if (e.map1_enabled[kEvalNormal]) eval_map1(e.map1[kEvalNormal], 3, u, v.normal);
  if (const int tk = tex_kind(e.map1_enabled); tk >= 0) {
    float* t = v.tex[0]; // §5.1: the maps generate coordinates for TEXTURE0 only
    t[0] = t[1] = t[2] = 0.0f, t[3] = 1.0f;
    eval_map1(e.map1[tk], kComponents[tk], u, t);
  }
  v.pos[0] = v.pos[1] = v.pos[2] = 0.0f, v.pos[3] = 1.0f;
  eval_map1(e.map1[vk], kComponents[vk], u, v.pos);
}

void to_float(const double* d, float* f, int k) {
  for (int c = 0; c < k; ++c)
    f[c] = static_cast<float>(d[c]);
}

// §5.1 EvalCoord2, as eval_coord1. With AUTO_NORMAL the normal is the normalized cross
// product of the partial derivatives of q, the vertex map (VERTEX_3) or its projection
// (x/w, y/w, z/w) (VERTEX_4); it takes precedence over a normal map. The derivatives are
// taken with respect to the map's normalized coordinates, as Mesa does.
void eval_coord2(Context* ctx, double u, double w) {
  const EvalGroup& e = ctx->eval;
  const int vk = vertex_kind(e.map2_enabled);
  if (vk < 0 || ctx->imm.mode == kOutsideBeginEnd) return;
  InputVertex& v = append_current_vertex(ctx);
  double val[4];
  if (e.map2_enabled[kEvalColor4]) {
    eval_map2(e.map2[kEvalColor4], 4, u, w, val, nullptr, nullptr);
    to_float(val, v.color, 4);
  }
  if (e.map2_enabled[kEvalNormal]) {
    eval_map2(e.map2[kEvalNormal], 3, u, w, val, nullptr, nullptr);
    to_float(val, v.normal, 3);
  }
  if (const int tk = tex_kind(e.map2_enabled); tk >= 0) {
    double t[4] = {0.0, 0.0, 0.0, 1.0};
    eval_map2(e.map2[tk], kComponents[tk], u, w, t, nullptr, nullptr);
    to_float(t, v.tex[0], 4);
  }
  const int k = kComponents[vk];
  double p[4] = {0.0, 0.0, 0.0, 1.0};
  if (e.auto_normal) {
    double pu[4], pv[4];
    eval_map2(e.map2[vk], k, u, w, p, pu, pv);
    if (k == 4) {
      // d(x/w) = (dx w - x dw) / w^2; the common factor 1/w^2 does not change the direction.
      for (int c = 0; c < 3; ++c) {
        pu[c] = pu[c] * p[3] - pu[3] * p[c];
        pv[c] = pv[c] * p[3] - pv[3] * p[c];
      }
    }
    double n[3] = {pu[1] * pv[2] - pu[2] * pv[1], pu[2] * pv[0] - pu[0] * pv[2],
                   pu[0] * pv[1] - pu[1] * pv[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    // A zero-length normal (a degenerate patch) stays zero, as in Mesa.
    if (len > 0.0)
      for (double& c : n)
        c /= len;
    to_float(n, v.normal, 3);
  } else {
    eval_map2(e.map2[vk], k, u, w, p, nullptr, nullptr);
  }
  to_float(p, v.pos, 4);
}

// Grid coordinate i of n partitions of [a, b]; §5.1 requires i = 0 and i = n to give a and b
// exactly.
double grid_coord(int i, int n, float a, float b) {
  if (i == n) return b;
  return a + i * ((double(b) - a) / n);
}

// ---- Map1 / Map2 ---------------------------------------------------------------------------

// §5.1 errors, in Mesa's order; then the control points are copied into packed storage.
template <typename T>
void map1(const char* func, GLenum target, T u1, T u2, GLint stride, GLint order, const T* points) {
  PINEDA_CTX_OUTSIDE(func);
  if (u1 == u2) return record_error(ctx, GL_INVALID_VALUE, func);
  if (order < 1 || order > kMaxEvalOrder) return record_error(ctx, GL_INVALID_VALUE, func);
  if (points == nullptr) return record_error(ctx, GL_INVALID_VALUE, func);
  const int kind = map_kind(target, 1);
  if (kind < 0) return record_error(ctx, GL_INVALID_ENUM, func, target);
  const int k = kComponents[kind];
  if (stride < k) return record_error(ctx, GL_INVALID_VALUE, func);
  if (ctx->texture.active != 0) return record_error(ctx, GL_INVALID_OPERATION, func);
  EvalMap1& m = ctx->eval.map1[kind];
  m.order = order;
  m.u1 = static_cast<float>(u1);
  m.u2 = static_cast<float>(u2);
  m.points.resize(size_t(order) * k);
  for (ptrdiff_t i = 0; i < order; ++i)
    for (int c = 0; c < k; ++c)
      m.points[size_t(i) * k + c] = static_cast<float>(points[i * stride + c]);
}

template <typename T>
void map2(const char* func, GLenum target, T u1, T u2, GLint ustride, GLint uorder, T v1, T v2,
          GLint vstride, GLint vorder, const T* points) {
  PINEDA_CTX_OUTSIDE(func);
  if (u1 == u2 || v1 == v2) return record_error(ctx, GL_INVALID_VALUE, func);
  if (uorder < 1 || uorder > kMaxEvalOrder || vorder < 1 || vorder > kMaxEvalOrder)
    return record_error(ctx, GL_INVALID_VALUE, func);
  if (points == nullptr) return record_error(ctx, GL_INVALID_VALUE, func);
  const int kind = map_kind(target, 2);
  if (kind < 0) return record_error(ctx, GL_INVALID_ENUM, func, target);
  const int k = kComponents[kind];
  if (ustride < k || vstride < k) return record_error(ctx, GL_INVALID_VALUE, func);
  if (ctx->texture.active != 0) return record_error(ctx, GL_INVALID_OPERATION, func);
  EvalMap2& m = ctx->eval.map2[kind];
  m.uorder = uorder;
  m.vorder = vorder;
  m.u1 = static_cast<float>(u1);
  m.u2 = static_cast<float>(u2);
  m.v1 = static_cast<float>(v1);
  m.v2 = static_cast<float>(v2);
  m.points.resize(size_t(uorder) * vorder * k);
  size_t n = 0;
  for (ptrdiff_t i = 0; i < uorder; ++i)
    for (ptrdiff_t j = 0; j < vorder; ++j)
      for (int c = 0; c < k; ++c)
        m.points[n++] = static_cast<float>(points[i * ustride + j * vstride + c]);
}

// §6.1.9 GetMap: COEFF (the control points), ORDER and DOMAIN of the map `target`. Integer
// queries round, as Mesa does.
template <typename T> void get_map(const char* func, GLenum target, GLenum query, T* out) {
  PINEDA_CTX_OUTSIDE(func);
  const int dim = map_kind(target, 1) >= 0 ? 1 : 2;
  const int kind = map_kind(target, dim);
  if (kind < 0) return record_error(ctx, GL_INVALID_ENUM, func, target);
  if (query != GL_COEFF && query != GL_ORDER && query != GL_DOMAIN)
    return record_error(ctx, GL_INVALID_ENUM, func, query);
  if (out == nullptr) return;
  auto put = [&](size_t i, double x) {
    // Values beyond the integer range clamp to it (converting them would be undefined).
    if constexpr (std::is_integral_v<T>)
      out[i] = x >= 2147483647.0    ? std::numeric_limits<T>::max()
               : x <= -2147483648.0 ? std::numeric_limits<T>::min()
                                    : static_cast<T>(std::lround(x));
    else
      out[i] = static_cast<T>(x);
  };
  const EvalGroup& e = ctx->eval;
  if (dim == 1) {
    const EvalMap1& m = e.map1[kind];
    if (query == GL_COEFF)
      for (size_t i = 0; i < m.points.size(); ++i)
        put(i, m.points[i]);
    else if (query == GL_ORDER)
      out[0] = static_cast<T>(m.order);
    else
      put(0, m.u1), put(1, m.u2);
  } else {
    const EvalMap2& m = e.map2[kind];
    if (query == GL_COEFF) {
      for (size_t i = 0; i < m.points.size(); ++i)
        put(i, m.points[i]);
    } else if (query == GL_ORDER) {
      out[0] = static_cast<T>(m.uorder);
      out[1] = static_cast<T>(m.vorder);
    } else {
      put(0, m.u1), put(1, m.u2), put(2, m.v1), put(3, m.v2);
    }
  }
}

// §5.1 MapGrid1/MapGrid2: n <= 0 is INVALID_VALUE.
void map_grid1(const char* func, GLint n, double u1, double u2) {
  PINEDA_CTX_OUTSIDE(func);
  if (n <= 0) return record_error(ctx, GL_INVALID_VALUE, func);
  EvalGroup& e = ctx->eval;
  e.grid1_n = n;
  e.grid1_u1 = static_cast<float>(u1);
  e.grid1_u2 = static_cast<float>(u2);
}

void map_grid2(const char* func, GLint un, double u1, double u2, GLint vn, double v1, double v2) {
  PINEDA_CTX_OUTSIDE(func);
  if (un <= 0 || vn <= 0) return record_error(ctx, GL_INVALID_VALUE, func);
  EvalGroup& e = ctx->eval;
  e.grid2_un = un;
  e.grid2_u1 = static_cast<float>(u1);
  e.grid2_u2 = static_cast<float>(u2);
  e.grid2_vn = vn;
  e.grid2_v1 = static_cast<float>(v1);
  e.grid2_v2 = static_cast<float>(v2);
}

} // namespace

EvalGroup::EvalGroup() {
  for (int kind = 0; kind < kEvalKindCount; ++kind) {
    map1[kind].points.resize(size_t(kComponents[kind]));
    initial_point(kind, map1[kind].points.data());
    map2[kind].points.resize(size_t(kComponents[kind]));
    initial_point(kind, map2[kind].points.data());
  }
}

namespace {

// MAX_EVAL_ORDER and the grids (Tables 6.28, 6.36).
bool get_eval(Context& ctx, GLenum pname, QueryValues& out) {
  const EvalGroup& e = ctx.eval;
  switch (pname) {
  case GL_MAX_EVAL_ORDER:
    out.ints({kMaxEvalOrder});
    return true;
  case GL_MAP1_GRID_DOMAIN:
    out.floats({e.grid1_u1, e.grid1_u2});
    return true;
  case GL_MAP1_GRID_SEGMENTS:
    out.ints({double(e.grid1_n)});
    return true;
  case GL_MAP2_GRID_DOMAIN:
    out.floats({e.grid2_u1, e.grid2_u2, e.grid2_v1, e.grid2_v2});
    return true;
  case GL_MAP2_GRID_SEGMENTS:
    out.ints({double(e.grid2_un), double(e.grid2_vn)});
    return true;
  default:
    return false;
  }
}

// MAP1_COLOR_4 .. MAP1_VERTEX_4 and MAP2_COLOR_4 .. MAP2_VERTEX_4 are consecutive enums in
// EvalKind order. No derived state depends on them.
constexpr Capability kEvalCaps[] = {
    {GL_MAP1_COLOR_4, kEvalKindCount, CapabilityKind::kServer, 0,
     [](Context& c, unsigned i, unsigned) { return &c.eval.map1_enabled[i]; }},
    {GL_MAP2_COLOR_4, kEvalKindCount, CapabilityKind::kServer, 0,
     [](Context& c, unsigned i, unsigned) { return &c.eval.map2_enabled[i]; }},
    {GL_AUTO_NORMAL, 1, CapabilityKind::kServer, 0,
     [](Context& c, unsigned, unsigned) { return &c.eval.auto_normal; }},
};

constexpr AttribGroup kEvalGroups[] = {
    member_group<&Context::eval>(GL_EVAL_BIT, 0),
};

} // namespace

const StateArea kEvalArea = {
    .name = "evaluators (GL 2.1 §5.1, Table 6.28)",
    .capabilities = kEvalCaps,
    .get = get_eval,
    .groups = kEvalGroups,
};

namespace exec {

void GLAPIENTRY Map1f(GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order,
                      const GLfloat* points) {
  map1("glMap1f", target, u1, u2, stride, order, points);
}
void GLAPIENTRY Map1d(GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order,
                      const GLdouble* points) {
  map1("glMap1d", target, u1, u2, stride, order, points);
}
void GLAPIENTRY Map2f(GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder,
                      GLfloat v1, GLfloat v2, GLint vstride, GLint vorder, const GLfloat* points) {
  map2("glMap2f", target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}
void GLAPIENTRY Map2d(GLenum target, GLdouble u1, GLdouble u2, GLint ustride, GLint uorder,
                      GLdouble v1, GLdouble v2, GLint vstride, GLint vorder,
                      const GLdouble* points) {
  map2("glMap2d", target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}

void GLAPIENTRY GetMapfv(GLenum target, GLenum query, GLfloat* v) {
  get_map("glGetMapfv", target, query, v);
}
void GLAPIENTRY GetMapdv(GLenum target, GLenum query, GLdouble* v) {
  get_map("glGetMapdv", target, query, v);
}
void GLAPIENTRY GetMapiv(GLenum target, GLenum query, GLint* v) {
  get_map("glGetMapiv", target, query, v);
}

void GLAPIENTRY MapGrid1f(GLint n, GLfloat u1, GLfloat u2) {
  map_grid1("glMapGrid1f", n, u1, u2);
}
void GLAPIENTRY MapGrid1d(GLint n, GLdouble u1, GLdouble u2) {
  map_grid1("glMapGrid1d", n, u1, u2);
}
void GLAPIENTRY MapGrid2f(GLint un, GLfloat u1, GLfloat u2, GLint vn, GLfloat v1, GLfloat v2) {
  map_grid2("glMapGrid2f", un, u1, u2, vn, v1, v2);
}
void GLAPIENTRY MapGrid2d(GLint un, GLdouble u1, GLdouble u2, GLint vn, GLdouble v1, GLdouble v2) {
  map_grid2("glMapGrid2d", un, u1, u2, vn, v1, v2);
}

// EvalCoord and EvalPoint are legal between Begin and End (§2.6.3).
void GLAPIENTRY EvalCoord1f(GLfloat u) {
  if (Context* ctx = current_context()) eval_coord1(ctx, u);
}
void GLAPIENTRY EvalCoord1d(GLdouble u) {
  if (Context* ctx = current_context()) eval_coord1(ctx, u);
}
void GLAPIENTRY EvalCoord1fv(const GLfloat* u) {
  if (u) EvalCoord1f(u[0]);
}
void GLAPIENTRY EvalCoord1dv(const GLdouble* u) {
  if (u) EvalCoord1d(u[0]);
}
void GLAPIENTRY EvalCoord2f(GLfloat u, GLfloat v) {
  if (Context* ctx = current_context()) eval_coord2(ctx, u, v);
}
void GLAPIENTRY EvalCoord2d(GLdouble u, GLdouble v) {
  if (Context* ctx = current_context()) eval_coord2(ctx, u, v);
}
void GLAPIENTRY EvalCoord2fv(const GLfloat* u) {
  if (u) EvalCoord2f(u[0], u[1]);
}
void GLAPIENTRY EvalCoord2dv(const GLdouble* u) {
  if (u) EvalCoord2d(u[0], u[1]);
}

void GLAPIENTRY EvalPoint1(GLint i) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  const EvalGroup& e = ctx->eval;
  eval_coord1(ctx, grid_coord(i, e.grid1_n, e.grid1_u1, e.grid1_u2));
}

void GLAPIENTRY EvalPoint2(GLint i, GLint j) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  const EvalGroup& e = ctx->eval;
  eval_coord2(ctx, grid_coord(i, e.grid2_un, e.grid2_u1, e.grid2_u2),
              grid_coord(j, e.grid2_vn, e.grid2_v1, e.grid2_v2));
}

// §5.1 EvalMesh1: Begin(POINTS or LINE_STRIP), EvalCoord1 at grid points i1..i2, End. Without
// a vertex map the sequence draws nothing, so it is skipped (as Mesa does).
void GLAPIENTRY EvalMesh1(GLenum mode, GLint i1, GLint i2) {
  PINEDA_CTX_OUTSIDE("glEvalMesh1");
  GLenum prim;
  switch (mode) {
  case GL_POINT:
    prim = GL_POINTS;
    break;
  case GL_LINE:
    prim = GL_LINE_STRIP;
    break;
  default:
    return record_error(ctx, GL_INVALID_ENUM, "glEvalMesh1", mode);
  }
  const EvalGroup& e = ctx->eval;
  if (vertex_kind(e.map1_enabled) < 0) return;
  Begin(prim);
  // A 64-bit counter, so that i2 == INT_MAX terminates.
  for (long long i = i1; i <= i2; ++i)
    eval_coord1(ctx, grid_coord(GLint(i), e.grid1_n, e.grid1_u1, e.grid1_u2));
  End();
}

// §5.1 EvalMesh2. FILL draws each row of quads as a triangle strip with the vertex order of
// the spec's QUAD_STRIP (the same quads; Mesa splits them the same way).
void GLAPIENTRY EvalMesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2) {
  PINEDA_CTX_OUTSIDE("glEvalMesh2");
  if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL)
    return record_error(ctx, GL_INVALID_ENUM, "glEvalMesh2", mode);
  const EvalGroup& e = ctx->eval;
  if (vertex_kind(e.map2_enabled) < 0 || i1 > i2 || j1 > j2) return;
  auto u = [&](GLint i) { return grid_coord(i, e.grid2_un, e.grid2_u1, e.grid2_u2); };
  auto v = [&](GLint j) { return grid_coord(j, e.grid2_vn, e.grid2_v1, e.grid2_v2); };
  // Loops run with 64-bit counters so that i2 or j2 == INT_MAX terminates.
  const long long ia = i1, ib = i2, ja = j1, jb = j2;
  switch (mode) {
  case GL_POINT:
    Begin(GL_POINTS);
    for (long long j = ja; j <= jb; ++j)
      for (long long i = ia; i <= ib; ++i)
        eval_coord2(ctx, u(GLint(i)), v(GLint(j)));
    End();
    break;
  case GL_LINE:
    for (long long j = ja; j <= jb; ++j) {
      Begin(GL_LINE_STRIP);
      for (long long i = ia; i <= ib; ++i)
        eval_coord2(ctx, u(GLint(i)), v(GLint(j)));
      End();
    }
    for (long long i = ia; i <= ib; ++i) {
      Begin(GL_LINE_STRIP);
      for (long long j = ja; j <= jb; ++j)
        eval_coord2(ctx, u(GLint(i)), v(GLint(j)));
      End();
    }
    break;
  default:
    for (long long j = ja; j < jb; ++j) {
      Begin(GL_TRIANGLE_STRIP);
      for (long long i = ia; i <= ib; ++i) {
        eval_coord2(ctx, u(GLint(i)), v(GLint(j)));
        eval_coord2(ctx, u(GLint(i)), v(GLint(j + 1)));
      }
      End();
    }
    break;
  }
}

} // namespace exec
} // namespace pineda
