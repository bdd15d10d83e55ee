// glHint (GL 2.1 §5.6) and the hint area (Table 6.32, hints.h): the hint queries and HINT_BIT.
#include "dispatch.h"
#include "state/api_util.h"
#include "state/area.h"

namespace pineda {

namespace {

GLenum* hint_slot(Context& ctx, GLenum target) {
  HintGroup& h = ctx.hint;
  switch (target) {
  case GL_PERSPECTIVE_CORRECTION_HINT:
    return &h.perspective;
  case GL_POINT_SMOOTH_HINT:
    return &h.point_smooth;
  case GL_LINE_SMOOTH_HINT:
    return &h.line_smooth;
  case GL_POLYGON_SMOOTH_HINT:
    return &h.polygon_smooth;
  case GL_FOG_HINT:
    return &h.fog;
  case GL_GENERATE_MIPMAP_HINT:
    return &h.generate_mipmap;
  case GL_TEXTURE_COMPRESSION_HINT:
    return &h.texture_compression;
  default:
    return nullptr;
  }
}

bool get_hint(Context& ctx, GLenum pname, QueryValues& out) {
  const GLenum* slot = hint_slot(ctx, pname);
  if (slot == nullptr) return false;
  out.ints({double(*slot)});
  return true;
}

// The fog hint picks per-vertex or per-fragment fog (validate_texpipe.cpp).
constexpr AttribGroup kHintGroups[] = {
    member_group<&Context::hint>(GL_HINT_BIT, kDirtyFog),
};

} // namespace

const StateArea kHintArea = {
    .name = "hints (GL 2.1 §5.6, Table 6.32)",
    .get = get_hint,
    .groups = kHintGroups,
};

namespace exec {

void GLAPIENTRY Hint(GLenum target, GLenum mode) {
  PINEDA_CTX_OUTSIDE("glHint");
  if (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE)
    return record_error(ctx, GL_INVALID_ENUM, "glHint", mode);
  GLenum* slot = hint_slot(*ctx, target);
  if (slot == nullptr) return record_error(ctx, GL_INVALID_ENUM, "glHint", target);
  if (*slot == mode) return;
  *slot = mode;
  // The fog hint chooses per-vertex or per-fragment fog (state/validate_texpipe.cpp).
  if (target == GL_FOG_HINT) mark_dirty(ctx, kDirtyFog);
}

} // namespace exec
} // namespace pineda
