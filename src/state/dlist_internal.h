// Shared between dlist.cpp (list management, the command stream, replay) and dlist_save.cpp
// (the hand-written savers): compiled vertex blocks and the compilation helpers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

#include "state/context.h"

namespace pineda {

// A compiled primitive (GL 2.1 §5.4): the vertices of a Begin/End block, or of an array draw
// whose arrays were dereferenced at compile time, ready for the geometry stage. Attributes the
// list had not set when a vertex was compiled are taken from the current values when the list
// executes: for attribute a, vertices [0, inherit_count[a]) inherit. Those vertices are
// rewritten in place when the current values differ from the ones they hold, under
// `patch_mutex` (a shared list may execute on several threads), so that a list drawn again and
// again with the same current values draws straight from `verts`.
struct PrimBlock final : DlistObject {
  GLenum mode = GL_POINTS;
  bool arrays = false;  // DrawArrays/DrawElements: no Begin/End, current values untouched
  bool has_end = false; // Begin/End block closed by its End within the list
  bool rect = false;    // from glRect: an error, not a Begin, between Begin and End (§2.10)
  std::vector<InputVertex> verts;
  std::vector<uint32_t> indices; // array draws with indices into verts; empty: in order
  uint32_t inherit_count[kListAttribCount] = {};
  uint32_t inherit_mask = 0;
  // Begin/End blocks: the attributes set inside the block, current after it (§2.7).
  uint32_t final_mask = 0;
  ListAttribs final_values{};
  std::mutex patch_mutex;
  bool patched = false; // the inheriting vertices hold `patched_values`
  ListAttribs patched_values{};
};

using ReplayFn = void (*)(const void* args);

// The current context when it is compiling a display list, else nullptr (then a saver only
// executes its command).
inline Context* compiling_list() {
  Context* ctx = current_context();
  return ctx != nullptr && ctx->dlist.list != nullptr ? ctx : nullptr;
}

// Whether the list being compiled also executes its commands (COMPILE_AND_EXECUTE).
inline bool list_executes(const Context* ctx) {
  return ctx->dlist.mode == GL_COMPILE_AND_EXECUTE;
}

// Before a command other than a vertex or attribute is compiled: an open Begin/End block is
// stored as it stands (it ends up executed call by call) and pending attributes are recorded.
void prepare_command(Context* ctx);

// Appends a record without prepare_command.
void append_record(Context* ctx, ReplayFn fn, const void* args, size_t size);

// Records an error the command will generate when the list executes (GL 2.1 §5.4: errors of
// compiled commands are generated at execution time).
void record_error_at_execution(Context* ctx, GLenum error, const char* func);

// Compiled attributes and vertices (dlist_save.cpp calls these for every variant).
void compile_attrib(Context* ctx, uint32_t bit, const float* values);
void compile_vertex(Context* ctx, float x, float y, float z, float w);
void compile_begin(Context* ctx, GLenum mode);
void compile_end(Context* ctx);
// The open block is a Rect (compiled as its Begin, vertices and End, §2.10).
inline void mark_rect_block(Context* ctx) {
  static_cast<PrimBlock*>(ctx->dlist.block.get())->rect = true;
}
// Appends a compiled array draw; attributes of disabled arrays inherit what the list knows.
void compile_array_block(Context* ctx, GLenum mode, std::vector<InputVertex>&& verts,
                         std::vector<uint32_t>&& indices);
// The attributes of the enabled conventional arrays of one array element, compiled as the
// commands ArrayElement stands for (§2.8), without the vertex.
void compile_array_attribs(Context* ctx, const InputVertex& v);
// Array elements while generic arrays are enabled (dlist_save_program.cpp): each compiled as
// ArrayElement, the generic attributes as VertexAttrib calls, generic array 0 as the vertex.
void compile_generic_elements(Context* ctx, const uint32_t* elements, size_t count);
// A whole array draw of those elements: Begin, the elements, End.
void compile_generic_draw(Context* ctx, GLenum mode, const uint32_t* elements, size_t count);
// After a command whose effect on the current attributes is unknown at compile time.
inline void forget_attribs(Context* ctx) {
  ctx->dlist.known = 0;
}

// The list offset element i of a CallLists array of `type` (GL 2.1 §5.4); `type` is valid.
GLuint call_lists_offset(GLenum type, const void* lists, size_t i);
bool valid_call_lists_type(GLenum type);
// Executes list `name` if it exists and the nesting limit allows (§5.4).
void call_list(Context* ctx, GLuint name);

} // namespace pineda
