// Occlusion queries (GL 2.1 §4.1.7, §6.1.12): query object names, BeginQuery/EndQuery for
// SAMPLES_PASSED, and the query state and result queries. While a query is active the
// fragment stage counts the fragments that pass the stencil and depth tests into
// QueryState::samples_passed (RasterState::count_samples selects the counting instances).
// Rendering is synchronous, so a result is available as soon as EndQuery returns.
#include <limits>

#include "state/api_util.h"
#include "dispatch.h"

namespace pineda {

namespace {

// GL 2.1 §6.1.12: QUERY_COUNTER_BITS, at least 32 for SAMPLES_PASSED; the counter is 64 bits
// wide, as in Mesa.
constexpr GLint kQueryCounterBits = 64;

// The result or availability of query `id` (GL 2.1 §6.1.12), shared by the iv and uiv forms;
// false after recording an error.
bool query_object_value(const char* func, GLuint id, GLenum pname, uint64_t* out) {
  Context* ctx = outside_begin_end(func);
  if (ctx == nullptr) return false;
  QueryState& qs = ctx->queries;
  const auto it = qs.objects.find(id);
  // §6.1.12: a name that is not a query object, or the active query, is INVALID_OPERATION.
  if (id == 0 || it == qs.objects.end() || !it->second.created || qs.active == id) {
    record_error(ctx, GL_INVALID_OPERATION, func);
    return false;
  }
  switch (pname) {
  case GL_QUERY_RESULT:
    *out = it->second.result;
    return true;
  case GL_QUERY_RESULT_AVAILABLE:
    *out = GL_TRUE;
    return true;
  default:
    record_error(ctx, GL_INVALID_ENUM, func, pname);
    return false;
  }
}

// Ends the active query: its result is the count so far.
void end_active_query(Context* ctx) {
  QueryState& qs = ctx->queries;
  const auto it = qs.objects.find(qs.active);
  if (it != qs.objects.end()) it->second.result = qs.samples_passed;
  qs.active = 0;
  qs.samples_passed = 0;
  mark_dirty(ctx, kDirtyRenderMode);
}

} // namespace

namespace exec {

void GLAPIENTRY GenQueries(GLsizei n, GLuint* ids) {
  PINEDA_CTX_OUTSIDE("glGenQueries");
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE, "glGenQueries");
  if (ids == nullptr) return;
  // §4.1.7: names not in use, now marked used; the objects come with the first BeginQuery.
  QueryState& qs = ctx->queries;
  GLuint next = 1;
  for (GLsizei i = 0; i < n; ++i) {
    while (qs.objects.count(next) != 0)
      ++next;
    qs.objects.emplace(next, QueryObject{});
    ids[i] = next++;
  }
}

void GLAPIENTRY DeleteQueries(GLsizei n, const GLuint* ids) {
  PINEDA_CTX_OUTSIDE("glDeleteQueries");
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE, "glDeleteQueries");
  if (ids == nullptr) return;
  QueryState& qs = ctx->queries;
  for (GLsizei i = 0; i < n; ++i) {
    // Unused names and zero are silently ignored (§4.1.7). Deleting the active query ends
    // it first, as Mesa does.
    if (ids[i] == 0) continue;
    if (qs.active == ids[i]) end_active_query(ctx);
    qs.objects.erase(ids[i]);
  }
}

GLboolean GLAPIENTRY IsQuery(GLuint id) {
  Context* ctx = outside_begin_end("glIsQuery");
  if (ctx == nullptr) return GL_FALSE;
  // §6.1.12: TRUE only for the name of a query object; a name from GenQueries that no
  // BeginQuery has used is not one yet.
  const auto it = ctx->queries.objects.find(id);
  return id != 0 && it != ctx->queries.objects.end() && it->second.created ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY BeginQuery(GLenum target, GLuint id) {
  PINEDA_CTX_OUTSIDE("glBeginQuery");
  if (target != GL_SAMPLES_PASSED)
    return record_error(ctx, GL_INVALID_ENUM, "glBeginQuery", target);
  QueryState& qs = ctx->queries;
  // §4.1.7: a query already active for the target, or the name zero, is INVALID_OPERATION
  // (the active query's own name is covered by the first test: there is one target).
  if (qs.active != 0 || id == 0) return record_error(ctx, GL_INVALID_OPERATION, "glBeginQuery");
  // An unused name becomes a query object here (GL 2.1 allows names GenQueries did not make).
  QueryObject& q = qs.objects[id];
  q.created = true;
  q.result = 0;
  qs.active = id;
  qs.samples_passed = 0;
  mark_dirty(ctx, kDirtyRenderMode);
}

void GLAPIENTRY EndQuery(GLenum target) {
  PINEDA_CTX_OUTSIDE("glEndQuery");
  if (target != GL_SAMPLES_PASSED) return record_error(ctx, GL_INVALID_ENUM, "glEndQuery", target);
  if (ctx->queries.active == 0) return record_error(ctx, GL_INVALID_OPERATION, "glEndQuery");
  end_active_query(ctx);
}

void GLAPIENTRY GetQueryiv(GLenum target, GLenum pname, GLint* params) {
  PINEDA_CTX_OUTSIDE("glGetQueryiv");
  if (target != GL_SAMPLES_PASSED)
    return record_error(ctx, GL_INVALID_ENUM, "glGetQueryiv", target);
  GLint v = 0;
  switch (pname) {
  case GL_CURRENT_QUERY:
    v = static_cast<GLint>(ctx->queries.active);
    break;
  case GL_QUERY_COUNTER_BITS:
    v = kQueryCounterBits;
    break;
  default:
    return record_error(ctx, GL_INVALID_ENUM, "glGetQueryiv", pname);
  }
  if (params != nullptr) *params = v;
}

void GLAPIENTRY GetQueryObjectiv(GLuint id, GLenum pname, GLint* params) {
  uint64_t v = 0;
  if (!query_object_value("glGetQueryObjectiv", id, pname, &v) || params == nullptr) return;
  // A count beyond the type's range saturates (as later GL versions specify and Mesa does).
  constexpr uint64_t kMax = std::numeric_limits<GLint>::max();
  *params = static_cast<GLint>(v < kMax ? v : kMax);
}

void GLAPIENTRY GetQueryObjectuiv(GLuint id, GLenum pname, GLuint* params) {
  uint64_t v = 0;
  if (!query_object_value("glGetQueryObjectuiv", id, pname, &v) || params == nullptr) return;
  constexpr uint64_t kMax = std::numeric_limits<GLuint>::max();
  *params = static_cast<GLuint>(v < kMax ? v : kMax);
}

} // namespace exec
} // namespace pineda
