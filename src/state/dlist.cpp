// Display lists (GL 2.1 §5.4): NewList/EndList, CallList/CallLists/ListBase, GenLists,
// DeleteLists, IsList, the command stream and its replay.
//
// While a list is compiled the thread's dispatch table is kSaveDispatch (generated from
// src/api/dlist_*.txt). Most commands are recorded as {replay function, copied arguments} and
// replayed through pineda::exec. Vertices are not: glBegin..glEnd blocks of vertex and
// attribute calls, and array draws (dereferenced at compile time), compile into PrimBlocks,
// InputVertex arrays that execution hands to the geometry stage in one call.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "state/api_util.h"
#include "dispatch.h"
#include "state/area.h"
#include "state/draw_call.h"
#include "state/dlist_internal.h"

namespace pineda {

// Compiled vertices carry, and inherit at execution, every attribute of InputVertex: an
// attribute added there must be added to ListAttribs, set_vertex_attrib, set_attrib_values and
// apply_attribs too.
static_assert(sizeof(InputVertex) == (15 + 4 * kMaxTexUnits) * sizeof(float) + sizeof(uint32_t),
              "InputVertex changed: display lists must carry the new attribute (dlist.cpp)");

namespace {

constexpr size_t kWord = sizeof(uint64_t);

// GenLists creates an empty list per name; a larger range than this is OUT_OF_MEMORY rather
// than a map of billions of names.
constexpr GLsizei kMaxGenLists = 1 << 24;

// Each record: the replay function, the payload size in words, the payload.
void execute_list(const DisplayList& list) {
  const uint64_t* p = list.code.data();
  const uint64_t* const end = p + list.code.size();
  while (p < end) {
    ReplayFn fn;
    std::memcpy(&fn, p, sizeof fn);
    const uint64_t words = p[1];
    fn(p + 2);
    p += 2 + words;
  }
}

PrimBlock* open_block(Context* ctx) {
  return static_cast<PrimBlock*>(ctx->dlist.block.get());
}

// Makes the attributes in `mask` current as the commands that set them would (GL 2.1 §2.7;
// Color also updates tracked materials, §2.14.3).
void apply_attribs(uint32_t mask, const ListAttribs& a) {
  if (mask & kListColor) exec::Color4fv(a.color);
  if (mask & kListColor2) exec::SecondaryColor3fv(a.color2);
  if (mask & kListNormal) exec::Normal3fv(a.normal);
  if (mask & kListTex) exec::TexCoord4fv(a.tex[0]);
  for (int u = 1; u < kMaxTexUnits; ++u)
    if (mask & list_tex_bit(u))
      exec::MultiTexCoord4fv(GL_TEXTURE0 + static_cast<GLenum>(u), a.tex[u]);
  if (mask & kListFog) exec::FogCoordf(a.fog);
  if (mask & kListEdge) exec::EdgeFlag(a.edge ? GL_TRUE : GL_FALSE);
}

void attribs_of(const InputVertex& v, ListAttribs& a) {
  std::copy(v.color, v.color + 4, a.color);
  std::copy(v.color2, v.color2 + 3, a.color2);
  std::copy(v.normal, v.normal + 3, a.normal);
  for (int u = 0; u < kMaxTexUnits; ++u)
    std::copy(v.tex[u], v.tex[u] + 4, a.tex[u]);
  a.edge = v.edge != 0;
  a.fog = v.fog;
}

ListAttribs current_attribs(const Context* ctx) {
  ListAttribs a;
  std::copy(ctx->current.color, ctx->current.color + 4, a.color);
  std::copy(ctx->current.color2, ctx->current.color2 + 3, a.color2);
  std::copy(ctx->current.normal, ctx->current.normal + 3, a.normal);
  for (int u = 0; u < kMaxTexUnits; ++u)
    std::copy(ctx->current.tex[u], ctx->current.tex[u] + 4, a.tex[u]);
  a.edge = ctx->current.edge;
  a.fog = ctx->current.fog_coord;
  return a;
}

// Attribute `bit` of `a` into vertex `v`.
void set_vertex_attrib(InputVertex& v, uint32_t bit, const ListAttribs& a) {
  switch (bit) {
  case kListColor:
    std::copy(a.color, a.color + 4, v.color);
    break;
  case kListColor2:
    std::copy(a.color2, a.color2 + 3, v.color2);
    break;
  case kListNormal:
    std::copy(a.normal, a.normal + 3, v.normal);
    break;
  case kListEdge:
    v.edge = a.edge ? 1u : 0u;
    break;
  case kListFog:
    v.fog = a.fog;
    break;
  default:
    for (int u = 0; u < kMaxTexUnits; ++u)
      if (bit == list_tex_bit(u)) std::copy(a.tex[u], a.tex[u] + 4, v.tex[u]);
    break;
  }
}

bool same_tex(const ListAttribs& x, const ListAttribs& y, uint32_t mask) {
  for (int u = 0; u < kMaxTexUnits; ++u)
    if ((mask & list_tex_bit(u)) && std::memcmp(x.tex[u], y.tex[u], sizeof x.tex[u]) != 0)
      return false;
  return true;
}

bool same_attribs(const ListAttribs& x, const ListAttribs& y, uint32_t mask) {
  return (!(mask & kListColor) || std::memcmp(x.color, y.color, sizeof x.color) == 0) &&
         (!(mask & kListColor2) || std::memcmp(x.color2, y.color2, sizeof x.color2) == 0) &&
         (!(mask & kListNormal) || std::memcmp(x.normal, y.normal, sizeof x.normal) == 0) &&
         (!(mask & kListEdge) || x.edge == y.edge) &&
         (!(mask & kListFog) || std::memcmp(&x.fog, &y.fog, sizeof x.fog) == 0) &&
         same_tex(x, y, mask);
}

// The current value of each inherited attribute into the leading vertices that inherit it,
// unless they hold it already. The caller holds b.patch_mutex.
void inherit_current(const Context* ctx, PrimBlock& b) {
  const ListAttribs cur = current_attribs(ctx);
  if (b.patched && same_attribs(cur, b.patched_values, b.inherit_mask)) return;
  for (int k = 0; k < kListAttribCount; ++k)
    for (uint32_t i = 0; i < b.inherit_count[k]; ++i)
      set_vertex_attrib(b.verts[i], 1u << k, cur);
  b.patched_values = cur;
  b.patched = true;
}

// Draws the block's vertices with the current values where they inherit them.
void draw_block(Context* ctx, PrimBlock& b) {
  std::unique_lock<std::mutex> lock(b.patch_mutex, std::defer_lock);
  if (b.inherit_mask != 0) {
    lock.lock();
    inherit_current(ctx, b);
  }
  const size_t n = b.verts.size();
  if (b.indices.empty())
    draw_vertices(ctx, b.mode, b.verts.data(), n, nullptr, n);
  else
    draw_vertices(ctx, b.mode, b.verts.data(), n, b.indices.data(), b.indices.size());
}

// A Begin/End block executed call by call: when it is called between Begin and End (its
// Begin is then an error and its vertices join the enclosing primitive, §2.6.3) or when the
// list does not contain its End.
void replay_block_calls(const PrimBlock& b) {
  exec::Begin(b.mode);
  ListAttribs a;
  for (size_t i = 0; i < b.verts.size(); ++i) {
    uint32_t mask = 0;
    for (int k = 0; k < kListAttribCount; ++k)
      if (i >= b.inherit_count[k]) mask |= 1u << k;
    attribs_of(b.verts[i], a);
    apply_attribs(mask, a);
    exec::Vertex4fv(b.verts[i].pos);
  }
  apply_attribs(b.final_mask, b.final_values);
  if (b.has_end) exec::End();
}

void replay_block(const void* args) {
  PrimBlock* b;
  std::memcpy(&b, args, sizeof b);
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  if (b->arrays) {
    // GL 2.1 §2.6.3: array draws are illegal between Begin and End.
    if (ctx->imm.mode != kOutsideBeginEnd)
      return record_error(ctx, GL_INVALID_OPERATION,
                          b->indices.empty() ? "glDrawArrays" : "glDrawElements");
    if (b->verts.empty()) return;
    return draw_block(ctx, *b);
  }
  // §2.6.3: Rect between Begin and End is INVALID_OPERATION and draws nothing.
  if (b->rect && ctx->imm.mode != kOutsideBeginEnd)
    return record_error(ctx, GL_INVALID_OPERATION, "glRect");
  if (ctx->imm.mode != kOutsideBeginEnd || !b->has_end) return replay_block_calls(*b);
  // What Begin, the vertices and End do (§2.6.1), without the calls.
  if (!b->verts.empty()) draw_block(ctx, *b);
  apply_attribs(b->final_mask, b->final_values);
}

struct SetCurrentArgs {
  uint32_t mask;
  ListAttribs values;
};

void replay_set_current(const void* args) {
  SetCurrentArgs a;
  std::memcpy(&a, args, sizeof a);
  apply_attribs(a.mask, a.values);
}

struct ErrorArgs {
  GLenum error;
  const char* func;
};

void replay_error(const void* args) {
  ErrorArgs a;
  std::memcpy(&a, args, sizeof a);
  if (Context* ctx = current_context()) record_error(ctx, a.error, a.func);
}

void replay_vertex(const void* args) {
  float v[4];
  std::memcpy(v, args, sizeof v);
  exec::Vertex4fv(v);
}

// Records the attributes set outside Begin/End since the last command.
void flush_pending(Context* ctx) {
  DisplayListState& d = ctx->dlist;
  if (d.pending == 0) return;
  SetCurrentArgs a{d.pending, d.attribs};
  append_record(ctx, &replay_set_current, &a, sizeof a);
  d.pending = 0;
}

// Stores the open block (with or without its End) in the list.
void close_block(Context* ctx, bool has_end) {
  DisplayListState& d = ctx->dlist;
  PrimBlock* b = open_block(ctx);
  b->has_end = has_end;
  b->final_values = d.attribs;
  append_record(ctx, &replay_block, &b, sizeof b);
  d.list->objects.push_back(std::move(d.block));
}

void set_attrib_values(ListAttribs& a, uint32_t bit, const float* v) {
  switch (bit) {
  case kListColor:
    std::copy(v, v + 4, a.color);
    break;
  case kListColor2:
    std::copy(v, v + 3, a.color2);
    break;
  case kListNormal:
    std::copy(v, v + 3, a.normal);
    break;
  case kListEdge:
    a.edge = v[0] != 0.0f;
    break;
  case kListFog:
    a.fog = v[0];
    break;
  default:
    for (int u = 0; u < kMaxTexUnits; ++u)
      if (bit == list_tex_bit(u)) std::copy(v, v + 4, a.tex[u]);
    break;
  }
}

bool valid_list_mode(GLenum mode) {
  return mode == GL_COMPILE || mode == GL_COMPILE_AND_EXECUTE;
}

size_t call_lists_type_size(GLenum type) {
  switch (type) {
  case GL_BYTE:
  case GL_UNSIGNED_BYTE:
    return 1;
  case GL_SHORT:
  case GL_UNSIGNED_SHORT:
  case GL_2_BYTES:
    return 2;
  case GL_3_BYTES:
    return 3;
  default:
    return 4;
  }
}

// §5.4: floating-point offsets are truncated to integers. Values no GLint holds (and NaN)
// name no list Pineda can have made: they become 0, which is never a list.
GLuint float_offset(float f) {
  const double t = std::trunc(static_cast<double>(f));
  if (!(t > -2147483649.0 && t < 4294967296.0)) return 0;
  return t < 0 ? static_cast<GLuint>(static_cast<GLint>(t)) : static_cast<GLuint>(t);
}

} // namespace

// ---- compilation ------------------------------------------------------------------------

void append_record(Context* ctx, ReplayFn fn, const void* args, size_t size) {
  std::vector<uint64_t>& code = ctx->dlist.list->code;
  const size_t words = (size + kWord - 1) / kWord;
  const size_t at = code.size();
  code.resize(at + 2 + words, 0);
  std::memcpy(&code[at], &fn, sizeof fn);
  code[at + 1] = words;
  if (size != 0) std::memcpy(&code[at + 2], args, size);
}

void prepare_command(Context* ctx) {
  if (ctx->dlist.block) close_block(ctx, false);
  flush_pending(ctx);
}

bool dlist_record(void (*replay)(const void* args), const void* args, size_t size) {
  Context* ctx = current_context();
  if (ctx == nullptr) return false;
  if (ctx->dlist.list == nullptr) return true; // not compiling: just execute
  prepare_command(ctx);
  append_record(ctx, replay, args, size);
  return list_executes(ctx);
}

void record_error_at_execution(Context* ctx, GLenum error, const char* func) {
  prepare_command(ctx);
  ErrorArgs a{error, func};
  append_record(ctx, &replay_error, &a, sizeof a);
}

void compile_attrib(Context* ctx, uint32_t bit, const float* values) {
  DisplayListState& d = ctx->dlist;
  set_attrib_values(d.attribs, bit, values);
  d.known |= bit;
  if (PrimBlock* b = open_block(ctx))
    b->final_mask |= bit;
  else
    d.pending |= bit;
}

void compile_vertex(Context* ctx, float x, float y, float z, float w) {
  DisplayListState& d = ctx->dlist;
  PrimBlock* b = open_block(ctx);
  if (b == nullptr) {
    // A vertex outside Begin/End in the list: it joins whatever primitive is open when the
    // list executes (lists may be called between Begin and End, §2.6.3).
    flush_pending(ctx);
    const float v[4] = {x, y, z, w};
    append_record(ctx, &replay_vertex, v, sizeof v);
    return;
  }
  InputVertex& v = b->verts.emplace_back();
  v.pos[0] = x, v.pos[1] = y, v.pos[2] = z, v.pos[3] = w;
  for (int k = 0; k < kListAttribCount; ++k)
    set_vertex_attrib(v, 1u << k, d.attribs);
  const auto n = static_cast<uint32_t>(b->verts.size());
  for (int k = 0; k < kListAttribCount; ++k) {
    if (!(d.known & (1u << k))) {
      b->inherit_count[k] = n;
      b->inherit_mask |= 1u << k;
    }
  }
}

void compile_begin(Context* ctx, GLenum mode) {
  prepare_command(ctx);
  auto b = std::make_unique<PrimBlock>();
  b->mode = mode;
  ctx->dlist.block = std::move(b);
}

void compile_end(Context* ctx) {
  close_block(ctx, true);
}

void compile_array_block(Context* ctx, GLenum mode, std::vector<InputVertex>&& verts,
                         std::vector<uint32_t>&& indices) {
  prepare_command(ctx);
  const DisplayListState& d = ctx->dlist;
  const VertexArrayGroup& arrays = ctx->arrays;
  auto b = std::make_unique<PrimBlock>();
  b->mode = mode;
  b->arrays = true;
  b->verts = std::move(verts);
  b->indices = std::move(indices);
  // GL 2.1 §2.8: attributes without an enabled array take the current values; those the list
  // has set are known now, the others are the current values when the list executes.
  const bool enabled[kListAttribCount] = {
      arrays.color.enabled,       arrays.secondary.enabled,   arrays.normal.enabled,
      arrays.texcoord[0].enabled, arrays.edgeflag.enabled,    arrays.texcoord[1].enabled,
      arrays.texcoord[2].enabled, arrays.texcoord[3].enabled, arrays.fog.enabled};
  const auto n = static_cast<uint32_t>(b->verts.size());
  for (int k = 0; k < kListAttribCount; ++k) {
    if (enabled[k]) continue;
    if (!(d.known & (1u << k))) {
      b->inherit_count[k] = n;
      b->inherit_mask |= 1u << k;
      continue;
    }
    for (InputVertex& v : b->verts)
      set_vertex_attrib(v, 1u << k, d.attribs);
  }
  PrimBlock* raw = b.get();
  append_record(ctx, &replay_block, &raw, sizeof raw);
  ctx->dlist.list->objects.push_back(std::move(b));
}

// ---- execution --------------------------------------------------------------------------

bool valid_call_lists_type(GLenum type) {
  switch (type) {
  case GL_BYTE:
  case GL_UNSIGNED_BYTE:
  case GL_SHORT:
  case GL_UNSIGNED_SHORT:
  case GL_INT:
  case GL_UNSIGNED_INT:
  case GL_FLOAT:
  case GL_2_BYTES:
  case GL_3_BYTES:
  case GL_4_BYTES:
    return true;
  default:
    return false;
  }
}

GLuint call_lists_offset(GLenum type, const void* lists, size_t i) {
  const auto* p = static_cast<const uint8_t*>(lists) + i * call_lists_type_size(type);
  switch (type) {
  case GL_BYTE:
    return static_cast<GLuint>(static_cast<GLint>(static_cast<GLbyte>(p[0])));
  case GL_UNSIGNED_BYTE:
    return p[0];
  case GL_SHORT: {
    GLshort v;
    std::memcpy(&v, p, sizeof v);
    return static_cast<GLuint>(static_cast<GLint>(v));
  }
  case GL_UNSIGNED_SHORT: {
    GLushort v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  case GL_INT:
  case GL_UNSIGNED_INT: {
    GLuint v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  case GL_FLOAT: {
    GLfloat v;
    std::memcpy(&v, p, sizeof v);
    return float_offset(v);
  }
  default: {
    // 2_BYTES, 3_BYTES, 4_BYTES: big-endian unsigned bytes (§5.4).
    GLuint offset = 0;
    for (size_t b = 0; b < call_lists_type_size(type); ++b)
      offset = (offset << 8) + p[b];
    return offset;
  }
  }
}

void call_list(Context* ctx, GLuint name) {
  DisplayListState& d = ctx->dlist;
  // §5.4: lists nested deeper than MAX_LIST_NESTING are not executed.
  if (d.depth >= kMaxListNesting) return;
  const auto it = ctx->shared->lists.find(name);
  // §5.4: no list, no effect; empty lists (from GenLists) are null.
  if (it == ctx->shared->lists.end() || it->second == nullptr) return;
  ++d.depth;
  execute_list(*it->second);
  --d.depth;
}

namespace {

// Table 6.31 (LIST_BASE, LIST_INDEX, LIST_MODE) and MAX_LIST_NESTING (Table 6.36).
bool get_list(Context& ctx, GLenum pname, QueryValues& out) {
  switch (pname) {
  case GL_LIST_BASE:
    out.ints({double(ctx.list.base)});
    return true;
  case GL_LIST_INDEX:
    out.ints({double(ctx.dlist.index)});
    return true;
  case GL_LIST_MODE:
    out.ints({double(ctx.dlist.mode)});
    return true;
  case GL_MAX_LIST_NESTING:
    out.ints({kMaxListNesting});
    return true;
  default:
    return false;
  }
}

constexpr AttribGroup kListGroups[] = {
    member_group<&Context::list>(GL_LIST_BIT, 0),
};

} // namespace

const StateArea kListArea = {
    .name = "display lists (GL 2.1 §5.4, Table 6.31)",
    .get = get_list,
    .groups = kListGroups,
};

namespace exec {

void GLAPIENTRY NewList(GLuint list, GLenum mode) {
  PINEDA_CTX_OUTSIDE("glNewList");
  if (list == 0) return record_error(ctx, GL_INVALID_VALUE, "glNewList");
  if (!valid_list_mode(mode)) return record_error(ctx, GL_INVALID_ENUM, "glNewList", mode);
  DisplayListState& d = ctx->dlist;
  if (d.list != nullptr) return record_error(ctx, GL_INVALID_OPERATION, "glNewList");
  d.list = std::make_unique<DisplayList>();
  d.index = list;
  d.mode = mode;
  d.known = 0;
  d.pending = 0;
  d.block.reset();
  t_dispatch = &kSaveDispatch;
}

void GLAPIENTRY EndList() {
  PINEDA_CTX_OUTSIDE("glEndList");
  DisplayListState& d = ctx->dlist;
  if (d.list == nullptr) return record_error(ctx, GL_INVALID_OPERATION, "glEndList");
  prepare_command(ctx);
  // §5.4: only now is the list associated with its name, replacing any previous one.
  ctx->shared->lists[d.index] = std::move(d.list);
  d.index = 0;
  d.mode = 0;
  t_dispatch = &kExecDispatch;
}

// CallList and CallLists are legal between Begin and End (§2.6.3).
void GLAPIENTRY CallList(GLuint list) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  if (list == 0) return record_error(ctx, GL_INVALID_VALUE, "glCallList");
  call_list(ctx, list);
}

void GLAPIENTRY CallLists(GLsizei n, GLenum type, const void* lists) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  if (!valid_call_lists_type(type)) return record_error(ctx, GL_INVALID_ENUM, "glCallLists", type);
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE, "glCallLists");
  if (lists == nullptr) return;
  const GLuint base = ctx->list.base;
  for (GLsizei i = 0; i < n; ++i)
    call_list(ctx, base + call_lists_offset(type, lists, static_cast<size_t>(i)));
}

void GLAPIENTRY ListBase(GLuint base) {
  PINEDA_CTX_OUTSIDE("glListBase");
  ctx->list.base = base;
}

GLuint GLAPIENTRY GenLists(GLsizei range) {
  Context* ctx = outside_begin_end("glGenLists");
  if (ctx == nullptr) return 0;
  if (range < 0) {
    record_error(ctx, GL_INVALID_VALUE, "glGenLists");
    return 0;
  }
  if (range == 0) return 0;
  if (range > kMaxGenLists) {
    record_error(ctx, GL_OUT_OF_MEMORY, "glGenLists");
    return 0;
  }
  // The lowest n with n..n+range-1 unused: walk the gaps between the names in use.
  DisplayLists& lists = ctx->shared->lists;
  const auto count = static_cast<uint64_t>(range);
  uint64_t first = 1;
  for (const auto& entry : lists) {
    if (entry.first >= first + count) break;
    if (entry.first >= first) first = uint64_t{entry.first} + 1;
  }
  if (first + count - 1 > 0xffffffffu) return 0; // §5.4: no such group, 0
  // §5.4: each name gets an empty list; empty lists are stored as null.
  for (uint64_t name = first; name < first + count; ++name)
    lists.emplace(static_cast<GLuint>(name), nullptr);
  return static_cast<GLuint>(first);
}

void GLAPIENTRY DeleteLists(GLuint list, GLsizei range) {
  PINEDA_CTX_OUTSIDE("glDeleteLists");
  if (range < 0) return record_error(ctx, GL_INVALID_VALUE, "glDeleteLists");
  DisplayLists& lists = ctx->shared->lists;
  const uint64_t last =
      std::min<uint64_t>(uint64_t{list} + static_cast<uint64_t>(range), uint64_t{0xffffffffu} + 1);
  auto it = lists.lower_bound(list);
  while (it != lists.end() && it->first < last)
    it = lists.erase(it);
}

GLboolean GLAPIENTRY IsList(GLuint list) {
  Context* ctx = outside_begin_end("glIsList");
  if (ctx == nullptr) return GL_FALSE;
  return ctx->shared->lists.count(list) != 0 ? GL_TRUE : GL_FALSE;
}

} // namespace exec
} // namespace pineda
