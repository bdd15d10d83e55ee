// Multisample state with no multisample buffer (GL 2.1 §3.2.1, §4.1.3): glSampleCoverage and
// the MULTISAMPLE, SAMPLE_ALPHA_TO_COVERAGE, SAMPLE_ALPHA_TO_ONE and SAMPLE_COVERAGE enables.
// SAMPLE_BUFFERS is 0 for every Pineda framebuffer, so "multisample rasterization cannot be
// enabled" (§3.2.1) and the fragment operations of §4.1.3 are skipped: the state is kept,
// queried and saved, and changes nothing drawn. The multisample area (Table 6.15,
// multisample.h).
#include "dispatch.h"
#include "state/api_util.h"
#include "state/area.h"

namespace pineda {

namespace {

// Table 6.15 (the coverage value is a float: GetIntegerv rounds it, as Mesa does) and
// Table 6.35.
bool get_multisample(Context& ctx, GLenum pname, QueryValues& out) {
  const MultisampleGroup& m = ctx.multisample;
  switch (pname) {
  case GL_SAMPLE_COVERAGE_VALUE:
    out.floats({m.sample_coverage_value});
    return true;
  case GL_SAMPLE_COVERAGE_INVERT:
    out.boolean(m.sample_coverage_invert);
    return true;
  case GL_SAMPLE_BUFFERS:
  case GL_SAMPLES:
    out.ints({0});
    return true;
  default:
    return false;
  }
}

// No derived state depends on them.
constexpr Capability kMultisampleCaps[] = {
    {GL_MULTISAMPLE, 1, CapabilityKind::kServer, 0,
     [](Context& c, unsigned, unsigned) { return &c.multisample.multisample; }},
    {GL_SAMPLE_ALPHA_TO_COVERAGE, 1, CapabilityKind::kServer, 0,
     [](Context& c, unsigned, unsigned) { return &c.multisample.sample_alpha_to_coverage; }},
    {GL_SAMPLE_ALPHA_TO_ONE, 1, CapabilityKind::kServer, 0,
     [](Context& c, unsigned, unsigned) { return &c.multisample.sample_alpha_to_one; }},
    {GL_SAMPLE_COVERAGE, 1, CapabilityKind::kServer, 0,
     [](Context& c, unsigned, unsigned) { return &c.multisample.sample_coverage; }},
};

constexpr AttribGroup kMultisampleGroups[] = {
    member_group<&Context::multisample>(GL_MULTISAMPLE_BIT, 0),
};

} // namespace

const StateArea kMultisampleArea = {
    .name = "multisample (GL 2.1 §3.2.1, §4.1.3, Table 6.15)",
    .capabilities = kMultisampleCaps,
    .get = get_multisample,
    .groups = kMultisampleGroups,
};

namespace exec {

// §4.1.3: value is clamped to [0,1]; invert is a boolean (stored as TRUE or FALSE).
void GLAPIENTRY SampleCoverage(GLfloat value, GLboolean invert) {
  PINEDA_CTX_OUTSIDE("glSampleCoverage");
  ctx->multisample.sample_coverage_value = clampf01(value);
  ctx->multisample.sample_coverage_invert = invert != GL_FALSE;
}

} // namespace exec
} // namespace pineda
