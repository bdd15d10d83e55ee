// Context lifetime, the per-thread current context, and the error helper.
#include "state/context.h"

#include <cstdio>
#include <cstdlib>

#include "state/api_util.h"
#include "state/program_draw.h"
#include "dispatch.h"

namespace pineda {

namespace {
thread_local Context* t_current = nullptr;

bool debug_enabled() {
  static const bool enabled = [] {
    const char* v = std::getenv("PINEDA_DEBUG");
    return v != nullptr && v[0] != '\0' && v[0] != '0';
  }();
  return enabled;
}
} // namespace

Context::Context() : Context(std::make_shared<SharedObjects>()) {}

Context::Context(std::shared_ptr<SharedObjects> objects)
    : shared(std::move(objects)), buffers(shared->buffers) {
  imm.verts.reserve(1024);
  program_draw = std::make_unique<ProgramDerived>();
  // What the draw home reads of the derived state and where it draws (draw/draw.h).
  DrawSources& src = draw.src;
  src.raster = &raster;
  src.raster_serial = &raster_serial;
  src.mvp = &mvp;
  src.modelview = &modelview_matrix;
  src.light = &light_setup;
  src.tex = &texpipe.vertex;
  src.fb = &fb;
  src.workers = &workers;
  src.samples_passed = &queries.samples_passed;
}

Context::~Context() {
  release_program(this); // §2.15.2: a program waiting for deletion may go with its last user
}

Context* current_context() {
  return t_current;
}

void set_current_context(Context* ctx) {
  t_current = ctx;
  // GL 2.1 §2.1: without a current context GL commands are no-ops. A context in the middle of
  // compiling a display list (§5.4) keeps compiling on the thread it is made current on.
  if (ctx == nullptr)
    t_dispatch = &kNoopDispatch;
  else
    t_dispatch = ctx->dlist.list != nullptr ? &kSaveDispatch : &kExecDispatch;
}

void record_error(Context* ctx, GLenum err, const char* func, GLenum offending) {
  if (debug_enabled()) {
    const char* name = enum_name(err);
    if (offending != 0) {
      const char* arg = enum_name(offending);
      if (arg != nullptr)
        std::fprintf(stderr, "pineda: %s(%s): %s\n", func, arg, name ? name : "?");
      else
        std::fprintf(stderr, "pineda: %s(0x%x): %s\n", func, offending, name ? name : "?");
    } else {
      std::fprintf(stderr, "pineda: %s: %s\n", func, name ? name : "?");
    }
  }
  if (ctx->error == GL_NO_ERROR) ctx->error = err;
}

} // namespace pineda
