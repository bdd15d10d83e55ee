// Multisample state with no multisample buffer (GL 2.1 §3.2.1, §4.1.3): glSampleCoverage and
// the MULTISAMPLE, SAMPLE_ALPHA_TO_COVERAGE, SAMPLE_ALPHA_TO_ONE and SAMPLE_COVERAGE enables.
// SAMPLE_BUFFERS is 0 for every Pineda framebuffer, so "multisample rasterization cannot be
// enabled" (§3.2.1) and the fragment operations of §4.1.3 are skipped: the state is kept,
// queried and saved, and changes nothing drawn. Also the glGet and glPushAttrib hooks of the
// colour-index state (src/state/color_index.cpp), declared in state/misc_state.h.
#include "core/api_util.h"
#include "dispatch.h"
#include "state/misc_state.h"

namespace pineda {

bool* multisample_capability(Context* ctx, GLenum cap) {
  MiscState& m = ctx->misc;
  switch (cap) {
  case GL_MULTISAMPLE:
    return &m.multisample;
  case GL_SAMPLE_ALPHA_TO_COVERAGE:
    return &m.sample_alpha_to_coverage;
  case GL_SAMPLE_ALPHA_TO_ONE:
    return &m.sample_alpha_to_one;
  case GL_SAMPLE_COVERAGE:
    return &m.sample_coverage;
  default:
    return nullptr;
  }
}

int misc_query(Context* ctx, GLenum pname, double* v, int* kind) {
  const MiscState& m = ctx->misc;
  constexpr int kInt = 0, kBool = 1, kFloat = 2;
  switch (pname) {
  // Table 6.5; a float like the current colour (GetIntegerv rounds it, §6.1.2).
  case GL_CURRENT_INDEX:
    *kind = kFloat, v[0] = m.current_index;
    return 1;
  // Table 6.30: the mask's 32 bits read as a signed integer (all ones read -1, as in Mesa).
  case GL_INDEX_WRITEMASK:
    *kind = kInt, v[0] = double(int32_t(m.index_writemask));
    return 1;
  case GL_INDEX_CLEAR_VALUE:
    *kind = kInt, v[0] = m.index_clear;
    return 1;
  // Table 6.8: the index array.
  case GL_INDEX_ARRAY_TYPE:
    *kind = kInt, v[0] = ctx->arrays.index.type;
    return 1;
  case GL_INDEX_ARRAY_STRIDE:
    *kind = kInt, v[0] = ctx->arrays.index.stride;
    return 1;
  case GL_INDEX_ARRAY_BUFFER_BINDING:
    *kind = kInt, v[0] = ctx->arrays.index.buffer;
    return 1;
  // Table 6.15 (a float: GetIntegerv rounds it, as Mesa does) and Table 6.35.
  case GL_SAMPLE_COVERAGE_VALUE:
    *kind = kFloat, v[0] = m.sample_coverage_value;
    return 1;
  case GL_SAMPLE_COVERAGE_INVERT:
    *kind = kBool, v[0] = m.sample_coverage_invert;
    return 1;
  case GL_SAMPLE_BUFFERS:
  case GL_SAMPLES:
    *kind = kInt, v[0] = 0;
    return 1;
  default:
    return 0;
  }
}

void misc_save_attrib(const Context* ctx, GLbitfield mask, MiscState& out) {
  const MiscState& m = ctx->misc;
  if (mask & GL_CURRENT_BIT) out.current_index = m.current_index;
  if (mask & GL_COLOR_BUFFER_BIT) {
    out.index_writemask = m.index_writemask;
    out.index_clear = m.index_clear;
  }
  // §6.1.14: the enables belong to both ENABLE_BIT and MULTISAMPLE_BIT (Table 6.15).
  if (mask & (GL_ENABLE_BIT | GL_MULTISAMPLE_BIT)) {
    out.multisample = m.multisample;
    out.sample_alpha_to_coverage = m.sample_alpha_to_coverage;
    out.sample_alpha_to_one = m.sample_alpha_to_one;
    out.sample_coverage = m.sample_coverage;
  }
  if (mask & GL_MULTISAMPLE_BIT) {
    out.sample_coverage_value = m.sample_coverage_value;
    out.sample_coverage_invert = m.sample_coverage_invert;
  }
}

void misc_restore_attrib(Context* ctx, GLbitfield mask, const MiscState& in) {
  MiscState& m = ctx->misc;
  if (mask & GL_CURRENT_BIT) m.current_index = in.current_index;
  if (mask & GL_COLOR_BUFFER_BIT) {
    m.index_writemask = in.index_writemask;
    m.index_clear = in.index_clear;
  }
  if (mask & (GL_ENABLE_BIT | GL_MULTISAMPLE_BIT)) {
    m.multisample = in.multisample;
    m.sample_alpha_to_coverage = in.sample_alpha_to_coverage;
    m.sample_alpha_to_one = in.sample_alpha_to_one;
    m.sample_coverage = in.sample_coverage;
  }
  if (mask & GL_MULTISAMPLE_BIT) {
    m.sample_coverage_value = in.sample_coverage_value;
    m.sample_coverage_invert = in.sample_coverage_invert;
  }
}

namespace exec {

// §4.1.3: value is clamped to [0,1]; invert is a boolean (stored as TRUE or FALSE).
void GLAPIENTRY SampleCoverage(GLfloat value, GLboolean invert) {
  PINEDA_CTX_OUTSIDE("glSampleCoverage");
  ctx->misc.sample_coverage_value = clampf01(value);
  ctx->misc.sample_coverage_invert = invert != GL_FALSE;
}

} // namespace exec
} // namespace pineda
