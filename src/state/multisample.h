// Multisample state with no multisample buffer (GL 2.1 §3.2.1, §4.1.3; Table 6.15
// "Multisampling", the "multisample" attribute group): set, queried and saved, and without
// effect on rendering since SAMPLE_BUFFERS is 0. Commands in multisample.cpp.
#pragma once

#include <GL/gl.h>

namespace pineda {

struct StateArea;

// MULTISAMPLE_BIT: Table 6.15 (the four enables are also "enable").
struct MultisampleGroup {
  bool multisample = true;
  bool sample_alpha_to_coverage = false;
  bool sample_alpha_to_one = false;
  bool sample_coverage = false;
  float sample_coverage_value = 1.0f;
  bool sample_coverage_invert = false;
};

extern const StateArea kMultisampleArea; // multisample.cpp

} // namespace pineda
