// glPushAttrib / glPopAttrib and glPushClientAttrib / glPopClientAttrib (GL 2.1 §6.1.14
// "Saving and Restoring State"): the attribute stacks. A group is the state whose "attribute"
// column in the GL 2.1 §6.2 tables names it; each area lists its groups in its StateArea
// (area.h) and most are one struct of Context, copied whole. ENABLE_BIT is every server
// capability of every area. glXCopyContext copies groups between contexts the same way.
#include "state/attrib.h"

#include "dispatch.h"
#include "state/api_util.h"

namespace pineda {

namespace {

template <typename F> void for_each_enable(Context& ctx, F&& f) {
  for (const StateArea* area : state_areas())
    for (const Capability& c : area->capabilities) {
      if (c.kind == CapabilityKind::kClient) continue;
      const unsigned units = c.kind == CapabilityKind::kPerUnit ? kMaxTexUnits : 1;
      for (unsigned i = 0; i < c.count; ++i)
        for (unsigned u = 0; u < units; ++u)
          f(c, *c.flag(ctx, i, u));
    }
}

// The groups of `mask` (client groups for the client stack), in the areas' order.
AttribFrame save(const Context& ctx, GLbitfield mask, bool client) {
  AttribFrame f;
  f.mask = mask;
  for (const StateArea* area : state_areas())
    for (const AttribGroup& g : area->groups)
      if (g.client == client && (mask & g.bit) != 0) f.groups.push_back({&g, g.save(ctx)});
  if (!client && (mask & GL_ENABLE_BIT) != 0)
    for_each_enable(const_cast<Context&>(ctx),
                    [&](const Capability&, bool& flag) { f.enables.push_back(flag); });
  return f;
}

// Puts the groups of `f` back in the order they were saved and returns the derived state they
// invalidate; then each area's `restored` (server groups only) adjusts what depends on
// several groups.
uint32_t restore(Context& ctx, const AttribFrame& f, bool client) {
  uint32_t dirty = 0;
  for (const AttribFrame::Saved& s : f.groups) {
    s.copy->restore(ctx);
    dirty |= s.group->dirty;
  }
  if (!f.enables.empty()) {
    size_t i = 0;
    for_each_enable(ctx, [&](const Capability& c, bool& flag) {
      flag = f.enables[i++];
      dirty |= c.dirty;
    });
  }
  if (!client)
    for (const StateArea* area : state_areas())
      if (area->restored != nullptr) dirty |= area->restored(ctx, f.mask);
  return dirty;
}

bool get_stack(Context& ctx, GLenum pname, QueryValues& out) {
  switch (pname) {
  case GL_ATTRIB_STACK_DEPTH:
    out.ints({double(ctx.attrib_stack.size())});
    return true;
  case GL_CLIENT_ATTRIB_STACK_DEPTH:
    out.ints({double(ctx.client_attrib_stack.size())});
    return true;
  case GL_MAX_ATTRIB_STACK_DEPTH:
    out.ints({double(kAttribStackDepth)});
    return true;
  case GL_MAX_CLIENT_ATTRIB_STACK_DEPTH:
    out.ints({double(kClientAttribStackDepth)});
    return true;
  default:
    return false;
  }
}

void push(const char* func, GLbitfield mask, bool client) {
  PINEDA_CTX_OUTSIDE(func);
  std::vector<AttribFrame>& stack = client ? ctx->client_attrib_stack : ctx->attrib_stack;
  // §6.1.14: a full stack is STACK_OVERFLOW and the command has no other effect; bits of no
  // group are ignored.
  if (stack.size() >= (client ? kClientAttribStackDepth : kAttribStackDepth))
    return record_error(ctx, GL_STACK_OVERFLOW, func);
  stack.push_back(save(*ctx, mask, client));
}

void pop(const char* func, bool client) {
  PINEDA_CTX_OUTSIDE(func);
  std::vector<AttribFrame>& stack = client ? ctx->client_attrib_stack : ctx->attrib_stack;
  // §6.1.14: an empty stack is STACK_UNDERFLOW and the command has no other effect.
  if (stack.empty()) return record_error(ctx, GL_STACK_UNDERFLOW, func);
  mark_dirty(ctx, restore(*ctx, stack.back(), client));
  stack.pop_back();
}

} // namespace

const StateArea kAttribStackArea = {
    .name = "attribute stacks (GL 2.1 §6.1.14, Tables 6.34, 6.37)",
    .get = get_stack,
};

void copy_attrib_groups(const Context* src, Context* dst, GLbitfield mask) {
  AttribFrame f = save(*src, mask, false);
  // GLX 1.4 §3.3.7: "texture objects cannot be copied"; across share groups a name means
  // another object, so dst's own bindings and parameters are what it keeps.
  if (src->shared != dst->shared)
    for (AttribFrame::Saved& s : f.groups)
      if (s.group->shared_objects) s.copy = s.group->save(*dst);
  mark_dirty(dst, restore(*dst, f, false));
}

namespace exec {

void GLAPIENTRY PushAttrib(GLbitfield mask) {
  push("glPushAttrib", mask, false);
}
void GLAPIENTRY PopAttrib() {
  pop("glPopAttrib", false);
}
void GLAPIENTRY PushClientAttrib(GLbitfield mask) {
  push("glPushClientAttrib", mask, true);
}
void GLAPIENTRY PopClientAttrib() {
  pop("glPopClientAttrib", true);
}

} // namespace exec
} // namespace pineda
