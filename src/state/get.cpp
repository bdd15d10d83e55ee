// State queries (GL 2.1 §6.1): glGetError, glGetString, glGet{Boolean,Integer,Float,Double}v,
// glGetPointerv. Every area answers for its own state (area.h: StateArea::get, get_pointer);
// the conversions between types follow §6.1.2.
#include <cmath>
#include <limits>

#include "core/version.h"
#include "dispatch.h"
#include "state/api_util.h"
#include "state/area.h"

namespace pineda {

namespace {

// Fill `out` for pname; false when pname is not a state Pineda has. A capability reads as
// glIsEnabled does (§6.1.1).
bool get_values(Context* ctx, GLenum pname, QueryValues& out) {
  const Capability* c = nullptr;
  if (const bool* flag = capability_flag(*ctx, pname, &c)) {
    out.boolean(*flag);
    return true;
  }
  if (c != nullptr) {
    // A texture enable of an active texture above the conventional units (§2.7, §6.1.2).
    out.error = GL_INVALID_OPERATION;
    return true;
  }
  for (const StateArea* area : state_areas())
    if (area->get != nullptr && area->get(*ctx, pname, out)) return true;
  return false;
}

// Shared front half of every glGet*v: context, Begin/End check, lookup, error.
bool lookup(const char* func, GLenum pname, QueryValues& out, Context** ctx_out) {
  Context* ctx = outside_begin_end(func);
  if (ctx == nullptr) return false;
  *ctx_out = ctx;
  if (!get_values(ctx, pname, out)) {
    record_error(ctx, GL_INVALID_ENUM, func, pname);
    return false;
  }
  if (out.error != GL_NO_ERROR) {
    record_error(ctx, out.error, func);
    return false;
  }
  return true;
}

// §6.1.2: floating-point to integer conversion.
GLint to_int(const QueryValues& vals, int i) {
  const double x = vals.v[i];
  if (vals.kind == QueryKind::kNormalized) {
    // 1.0 maps to the most positive integer, -1.0 to the most negative.
    const double scaled = x * 2147483647.0;
    if (scaled >= 2147483647.0) return std::numeric_limits<GLint>::max();
    if (scaled <= -2147483648.0) return std::numeric_limits<GLint>::min();
    return static_cast<GLint>(std::llround(scaled));
  }
  if (!(x == x)) return 0;
  if (x >= 2147483647.0) return std::numeric_limits<GLint>::max();
  if (x <= -2147483648.0) return std::numeric_limits<GLint>::min();
  return static_cast<GLint>(std::llround(x));
}

} // namespace

namespace exec {

GLenum GLAPIENTRY GetError() {
  Context* ctx = current_context();
  if (ctx == nullptr) return GL_NO_ERROR;
  if (ctx->imm.mode != kOutsideBeginEnd) {
    record_error(ctx, GL_INVALID_OPERATION, "glGetError");
    return GL_NO_ERROR;
  }
  const GLenum e = ctx->error;
  ctx->error = GL_NO_ERROR;
  return e;
}

const GLubyte* GLAPIENTRY GetString(GLenum name) {
  Context* ctx = outside_begin_end("glGetString");
  if (ctx == nullptr) return nullptr;
  const char* s = nullptr;
  switch (name) {
  case GL_VENDOR:
    s = "Pineda";
    break;
  case GL_RENDERER:
    s = "Pineda (CPU rasterizer)";
    break;
  case GL_VERSION:
    s = kGLVersionString;
    break; // core/version.h
  case GL_SHADING_LANGUAGE_VERSION:
    s = kGLSLVersionString;
    break;
  case GL_EXTENSIONS:
    s = kGLExtensions;
    break;
  default:
    record_error(ctx, GL_INVALID_ENUM, "glGetString", name);
    return nullptr;
  }
  return reinterpret_cast<const GLubyte*>(s);
}

void GLAPIENTRY GetBooleanv(GLenum pname, GLboolean* params) {
  QueryValues v;
  Context* ctx = nullptr;
  if (!lookup("glGetBooleanv", pname, v, &ctx) || params == nullptr) return;
  for (int i = 0; i < v.n; ++i)
    params[i] = v.v[i] != 0.0 ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY GetIntegerv(GLenum pname, GLint* params) {
  QueryValues v;
  Context* ctx = nullptr;
  if (!lookup("glGetIntegerv", pname, v, &ctx) || params == nullptr) return;
  for (int i = 0; i < v.n; ++i)
    params[i] = to_int(v, i);
}

void GLAPIENTRY GetFloatv(GLenum pname, GLfloat* params) {
  QueryValues v;
  Context* ctx = nullptr;
  if (!lookup("glGetFloatv", pname, v, &ctx) || params == nullptr) return;
  for (int i = 0; i < v.n; ++i)
    params[i] = static_cast<GLfloat>(v.v[i]);
}

void GLAPIENTRY GetDoublev(GLenum pname, GLdouble* params) {
  QueryValues v;
  Context* ctx = nullptr;
  if (!lookup("glGetDoublev", pname, v, &ctx) || params == nullptr) return;
  for (int i = 0; i < v.n; ++i)
    params[i] = v.v[i];
}

void GLAPIENTRY GetPointerv(GLenum pname, void** params) {
  PINEDA_CTX_OUTSIDE("glGetPointerv");
  void* p = nullptr;
  for (const StateArea* area : state_areas())
    if (area->get_pointer != nullptr && area->get_pointer(*ctx, pname, &p)) {
      if (params != nullptr) *params = p;
      return;
    }
  record_error(ctx, GL_INVALID_ENUM, "glGetPointerv", pname);
}

} // namespace exec
} // namespace pineda
