// Colour-index state of an RGBA-only GL (GL 2.1 §2.7, §4.2.2, §4.2.3) and multisample state
// with no multisample buffer (§3.2.1, §4.1.3): state that is set, queried and saved by
// glPushAttrib but has no effect on rendering. Commands in src/state/color_index.cpp and
// src/state/multisample.cpp.
#pragma once

#include <GL/gl.h>

#include <cstdint>

namespace pineda {

struct Context;

struct MiscState {
  // Table 6.5 CURRENT_INDEX: kept as given (Mesa keeps the float; no masking in RGBA mode).
  float current_index = 1.0f;
  // Table 6.30 INDEX_WRITEMASK (all ones) and INDEX_CLEAR_VALUE (the integer part, §4.2.3).
  GLuint index_writemask = ~0u;
  int32_t index_clear = 0;
  // Table 6.15: multisample enables and sample coverage (§3.2.1, §4.1.3).
  bool multisample = true;
  bool sample_alpha_to_coverage = false;
  bool sample_alpha_to_one = false;
  bool sample_coverage = false;
  float sample_coverage_value = 1.0f;
  bool sample_coverage_invert = false;
};

// glGet values of the state above, of SAMPLE_BUFFERS/SAMPLES and of the INDEX_ARRAY_* queries:
// the number written to v (0: not such a query) and their kind (get.cpp's Kind index: 0
// integer, 1 boolean, 2 float).
int misc_query(Context* ctx, GLenum pname, double* v, int* kind);

// The multisample enables for glEnable/glIsEnabled (nullptr for other caps).
bool* multisample_capability(Context* ctx, GLenum cap);

// glPushAttrib/glPopAttrib: CURRENT_BIT (current index), COLOR_BUFFER_BIT (index clear value
// and write mask), MULTISAMPLE_BIT (all of Table 6.15), ENABLE_BIT (the multisample enables).
void misc_save_attrib(const Context* ctx, GLbitfield mask, MiscState& out);
void misc_restore_attrib(Context* ctx, GLbitfield mask, const MiscState& in);

} // namespace pineda
