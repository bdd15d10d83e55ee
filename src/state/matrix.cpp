// Matrices and matrix stacks (GL 2.1 §2.11.2): glMatrixMode, load/mult (also transposed),
// rotate/translate/scale, frustum/ortho, push/pop; and the transformation area (Table 6.7,
// transform.h): the matrix, clip-plane and normal-processing queries, capabilities, the
// TRANSFORM_BIT group and the composite matrix derived for the draws.
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "state/api_util.h"
#include "dispatch.h"
#include "state/area.h"

namespace pineda {

namespace {

// The stack the matrix commands act on, or null with INVALID_OPERATION: in TEXTURE mode the
// active texture's coordinate set has one only below MAX_TEXTURE_COORDS (GL 2.1 §2.7).
MatrixStack* current_stack(Context* ctx, const char* func) {
  switch (ctx->transform.matrix_mode) {
  case GL_PROJECTION:
    return &ctx->projection;
  case GL_TEXTURE:
    if (ctx->texture.active >= GLuint(kMaxTexCoordSets)) {
      record_error(ctx, GL_INVALID_OPERATION, func);
      return nullptr;
    }
    return &ctx->texture_matrix[ctx->texture.active];
  default:
    return &ctx->modelview;
  }
}

// Only the modelview and projection matrices feed the composite; texture matrices feed the
// per-vertex texture coordinate setup (validate_texpipe.cpp).
void matrix_changed(Context* ctx) {
  if (ctx->transform.matrix_mode != GL_TEXTURE)
    mark_dirty(ctx, kDirtyTransform | kDirtyClipPlanes);
  else
    mark_dirty(ctx, kDirtyTexture);
}

void load(const char* func, const glm::mat4& m) {
  PINEDA_CTX_OUTSIDE(func);
  MatrixStack* s = current_stack(ctx, func);
  if (s == nullptr) return;
  s->top() = m;
  matrix_changed(ctx);
}

void mult(const char* func, const glm::mat4& m) {
  PINEDA_CTX_OUTSIDE(func);
  MatrixStack* s = current_stack(ctx, func);
  if (s == nullptr) return;
  glm::mat4& top = s->top();
  top = top * m; // GL 2.1 §2.11.2: C' = C * M
  matrix_changed(ctx);
}

template <typename T> glm::mat4 from_column_major(const T* m) {
  glm::mat4 r;
  for (int c = 0; c < 4; ++c)
    for (int rr = 0; rr < 4; ++rr)
      r[c][rr] = static_cast<float>(m[c * 4 + rr]);
  return r;
}

template <typename T> glm::mat4 from_row_major(const T* m) {
  glm::mat4 r;
  for (int c = 0; c < 4; ++c)
    for (int rr = 0; rr < 4; ++rr)
      r[c][rr] = static_cast<float>(m[rr * 4 + c]);
  return r;
}

// GL 2.1 §2.11.2 equation for Rotate: angle in degrees, axis normalized; a zero axis leaves
// the matrix unchanged (Mesa does the same; the spec divides by |v|).
glm::mat4 rotation(double angle_deg, double x, double y, double z) {
  const double len = std::sqrt(x * x + y * y + z * z);
  glm::mat4 r(1.0f);
  if (!(len > 0.0) || !std::isfinite(len)) return r;
  x /= len, y /= len, z /= len;
  const double a = angle_deg * (3.14159265358979323846 / 180.0);
  const double c = std::cos(a), s = std::sin(a), t = 1.0 - c;
  // Column-major: r[column][row].
  r[0][0] = static_cast<float>(x * x * t + c);
  r[0][1] = static_cast<float>(y * x * t + z * s);
  r[0][2] = static_cast<float>(z * x * t - y * s);
  r[1][0] = static_cast<float>(x * y * t - z * s);
  r[1][1] = static_cast<float>(y * y * t + c);
  r[1][2] = static_cast<float>(z * y * t + x * s);
  r[2][0] = static_cast<float>(x * z * t + y * s);
  r[2][1] = static_cast<float>(y * z * t - x * s);
  r[2][2] = static_cast<float>(z * z * t + c);
  return r;
}

glm::mat4 translation(double x, double y, double z) {
  glm::mat4 r(1.0f);
  r[3][0] = static_cast<float>(x);
  r[3][1] = static_cast<float>(y);
  r[3][2] = static_cast<float>(z);
  return r;
}

glm::mat4 scaling(double x, double y, double z) {
  glm::mat4 r(1.0f);
  r[0][0] = static_cast<float>(x);
  r[1][1] = static_cast<float>(y);
  r[2][2] = static_cast<float>(z);
  return r;
}

void put_matrix(QueryValues& out, const glm::mat4& m, bool transpose) {
  out.kind = QueryKind::kFloat;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      out.add(transpose ? m[r][c] : m[c][r]);
}

// Tables 6.7, 6.36, 6.37.
bool get_transform(Context& ctx, GLenum pname, QueryValues& out) {
  // §6.1.2: the texture matrix queries of an active texture without a coordinate set are
  // INVALID_OPERATION.
  const bool has_tex = ctx.texture.active < GLuint(kMaxTexCoordSets);
  const MatrixStack& tex = ctx.texture_matrix[has_tex ? ctx.texture.active : 0];
  if (!has_tex && (pname == GL_TEXTURE_MATRIX || pname == GL_TRANSPOSE_TEXTURE_MATRIX ||
                   pname == GL_TEXTURE_STACK_DEPTH)) {
    out.error = GL_INVALID_OPERATION;
    return true;
  }
  switch (pname) {
  case GL_MATRIX_MODE:
    out.ints({double(ctx.transform.matrix_mode)});
    return true;
  case GL_MODELVIEW_MATRIX:
    put_matrix(out, ctx.modelview.top(), false);
    return true;
  case GL_PROJECTION_MATRIX:
    put_matrix(out, ctx.projection.top(), false);
    return true;
  case GL_TEXTURE_MATRIX:
    put_matrix(out, tex.top(), false);
    return true;
  case GL_TRANSPOSE_MODELVIEW_MATRIX:
    put_matrix(out, ctx.modelview.top(), true);
    return true;
  case GL_TRANSPOSE_PROJECTION_MATRIX:
    put_matrix(out, ctx.projection.top(), true);
    return true;
  case GL_TRANSPOSE_TEXTURE_MATRIX:
    put_matrix(out, tex.top(), true);
    return true;
  case GL_MODELVIEW_STACK_DEPTH:
    out.ints({double(ctx.modelview.stack.size())});
    return true;
  case GL_PROJECTION_STACK_DEPTH:
    out.ints({double(ctx.projection.stack.size())});
    return true;
  case GL_TEXTURE_STACK_DEPTH:
    out.ints({double(tex.stack.size())});
    return true;
  case GL_MAX_MODELVIEW_STACK_DEPTH:
    out.ints({double(kModelviewStackDepth)});
    return true;
  case GL_MAX_PROJECTION_STACK_DEPTH:
    out.ints({double(kProjectionStackDepth)});
    return true;
  case GL_MAX_TEXTURE_STACK_DEPTH:
    out.ints({double(kTextureStackDepth)});
    return true;
  case GL_MAX_CLIP_PLANES:
    out.ints({double(kMaxClipPlanes)});
    return true;
  default:
    return false;
  }
}

// The composite matrix (§2.11): projection * modelview; and the model-view matrix itself at an
// address that does not move with the stack (the draws' DrawSources).
void derive_transform(Context& ctx, uint32_t) {
  ctx.mvp = ctx.projection.top() * ctx.modelview.top();
  ctx.modelview_matrix = ctx.modelview.top();
}

constexpr Capability kTransformCaps[] = {
    // §2.12: user clip planes.
    {GL_CLIP_PLANE0, kMaxClipPlanes, CapabilityKind::kServer, kDirtyClipPlanes,
     [](Context& c, unsigned i, unsigned) { return &c.transform.clip_enabled[i]; }},
    // §2.11.3: normals are rescaled or normalized before lighting.
    {GL_NORMALIZE, 1, CapabilityKind::kServer, kDirtyLighting,
     [](Context& c, unsigned, unsigned) { return &c.transform.normalize; }},
    {GL_RESCALE_NORMAL, 1, CapabilityKind::kServer, kDirtyLighting,
     [](Context& c, unsigned, unsigned) { return &c.transform.rescale_normal; }},
};

constexpr AttribGroup kTransformGroups[] = {
    member_group<&Context::transform>(GL_TRANSFORM_BIT, kDirtyClipPlanes | kDirtyLighting),
};

} // namespace

const StateArea kTransformArea = {
    .name = "transformation (GL 2.1 §2.11, §2.12, Table 6.7)",
    .capabilities = kTransformCaps,
    .get = get_transform,
    .groups = kTransformGroups,
    .derive_on = kDirtyTransform,
    .derive = derive_transform,
};

namespace exec {

void GLAPIENTRY MatrixMode(GLenum mode) {
  PINEDA_CTX_OUTSIDE("glMatrixMode");
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE) {
    record_error(ctx, GL_INVALID_ENUM, "glMatrixMode", mode);
    return;
  }
  ctx->transform.matrix_mode = mode;
}

void GLAPIENTRY LoadIdentity() {
  load("glLoadIdentity", glm::mat4(1.0f));
}
void GLAPIENTRY LoadMatrixf(const GLfloat* m) {
  if (m != nullptr) load("glLoadMatrixf", from_column_major(m));
}
void GLAPIENTRY LoadMatrixd(const GLdouble* m) {
  if (m != nullptr) load("glLoadMatrixd", from_column_major(m));
}
void GLAPIENTRY MultMatrixf(const GLfloat* m) {
  if (m != nullptr) mult("glMultMatrixf", from_column_major(m));
}
void GLAPIENTRY MultMatrixd(const GLdouble* m) {
  if (m != nullptr) mult("glMultMatrixd", from_column_major(m));
}
// GL 2.1 §2.11.2: the transpose variants take row-major matrices.
void GLAPIENTRY LoadTransposeMatrixf(const GLfloat* m) {
  if (m != nullptr) load("glLoadTransposeMatrixf", from_row_major(m));
}
void GLAPIENTRY LoadTransposeMatrixd(const GLdouble* m) {
  if (m != nullptr) load("glLoadTransposeMatrixd", from_row_major(m));
}
void GLAPIENTRY MultTransposeMatrixf(const GLfloat* m) {
  if (m != nullptr) mult("glMultTransposeMatrixf", from_row_major(m));
}
void GLAPIENTRY MultTransposeMatrixd(const GLdouble* m) {
  if (m != nullptr) mult("glMultTransposeMatrixd", from_row_major(m));
}

void GLAPIENTRY Rotatef(GLfloat a, GLfloat x, GLfloat y, GLfloat z) {
  mult("glRotatef", rotation(a, x, y, z));
}
void GLAPIENTRY Rotated(GLdouble a, GLdouble x, GLdouble y, GLdouble z) {
  mult("glRotated", rotation(a, x, y, z));
}
void GLAPIENTRY Translatef(GLfloat x, GLfloat y, GLfloat z) {
  mult("glTranslatef", translation(x, y, z));
}
void GLAPIENTRY Translated(GLdouble x, GLdouble y, GLdouble z) {
  mult("glTranslated", translation(x, y, z));
}
void GLAPIENTRY Scalef(GLfloat x, GLfloat y, GLfloat z) {
  mult("glScalef", scaling(x, y, z));
}
void GLAPIENTRY Scaled(GLdouble x, GLdouble y, GLdouble z) {
  mult("glScaled", scaling(x, y, z));
}

// GL 2.1 §2.11.2 Frustum: INVALID_VALUE when n or f <= 0, l == r, b == t or n == f.
void GLAPIENTRY Frustum(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  PINEDA_CTX_OUTSIDE("glFrustum");
  if (n <= 0.0 || f <= 0.0 || l == r || b == t || n == f) {
    record_error(ctx, GL_INVALID_VALUE, "glFrustum");
    return;
  }
  glm::mat4 m(0.0f);
  m[0][0] = static_cast<float>(2.0 * n / (r - l));
  m[1][1] = static_cast<float>(2.0 * n / (t - b));
  m[2][0] = static_cast<float>((r + l) / (r - l));
  m[2][1] = static_cast<float>((t + b) / (t - b));
  m[2][2] = static_cast<float>(-(f + n) / (f - n));
  m[2][3] = -1.0f;
  m[3][2] = static_cast<float>(-2.0 * f * n / (f - n));
  MatrixStack* s = current_stack(ctx, "glFrustum");
  if (s == nullptr) return;
  glm::mat4& top = s->top();
  top = top * m;
  matrix_changed(ctx);
}

// GL 2.1 §2.11.2 Ortho: INVALID_VALUE when l == r, b == t or n == f.
void GLAPIENTRY Ortho(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  PINEDA_CTX_OUTSIDE("glOrtho");
  if (l == r || b == t || n == f) {
    record_error(ctx, GL_INVALID_VALUE, "glOrtho");
    return;
  }
  glm::mat4 m(1.0f);
  m[0][0] = static_cast<float>(2.0 / (r - l));
  m[1][1] = static_cast<float>(2.0 / (t - b));
  m[2][2] = static_cast<float>(-2.0 / (f - n));
  m[3][0] = static_cast<float>(-(r + l) / (r - l));
  m[3][1] = static_cast<float>(-(t + b) / (t - b));
  m[3][2] = static_cast<float>(-(f + n) / (f - n));
  MatrixStack* s = current_stack(ctx, "glOrtho");
  if (s == nullptr) return;
  glm::mat4& top = s->top();
  top = top * m;
  matrix_changed(ctx);
}

// GL 2.1 §2.11.2: STACK_OVERFLOW / STACK_UNDERFLOW leave the stack unchanged.
void GLAPIENTRY PushMatrix() {
  PINEDA_CTX_OUTSIDE("glPushMatrix");
  MatrixStack* stack = current_stack(ctx, "glPushMatrix");
  if (stack == nullptr) return;
  MatrixStack& s = *stack;
  if (s.stack.size() >= s.max_depth) {
    record_error(ctx, GL_STACK_OVERFLOW, "glPushMatrix");
    return;
  }
  s.stack.push_back(s.top());
}

void GLAPIENTRY PopMatrix() {
  PINEDA_CTX_OUTSIDE("glPopMatrix");
  MatrixStack* stack = current_stack(ctx, "glPopMatrix");
  if (stack == nullptr) return;
  MatrixStack& s = *stack;
  if (s.stack.size() <= 1) {
    record_error(ctx, GL_STACK_UNDERFLOW, "glPopMatrix");
    return;
  }
  s.stack.pop_back();
  matrix_changed(ctx);
}

} // namespace exec
} // namespace pineda
