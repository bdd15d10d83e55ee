// The vertex the immediate-mode, array and display-list paths collect and the geometry stage
// transforms: object position plus a snapshot of the current attributes (GL 2.1 §2.7).
#pragma once

#include <cstdint>

#include "core/limits.h"

namespace pineda {

// The attributes every draw reads fill the first 64 bytes (one cache line); the texture
// coordinates, read only by units that are on, follow.
struct InputVertex {
  // Deliberately leaves the members uninitialized, also where a container value-initializes
  // (imm.emplace_back()): every path that makes a vertex fills what its draw reads, and
  // zeroing 128 bytes per glVertex call is measurable.
  InputVertex() {} // NOLINT(modernize-use-equals-default): = default would zero them
  float pos[4];
  float color[4];
  float normal[3];
  float color2[3]; // secondary colour (GL 1.4, §2.7)
  float fog;       // fog coordinate (GL 1.4, §2.7)
  uint32_t edge;
  float tex[kMaxTexUnits][4]; // per texture unit
};

// Which texture units' coordinates a draw's geometry stage reads from its InputVertex array
// (bit u for unit u); the paths that build InputVertex arrays for one draw copy only those.
// Display lists and glArrayElement keep every unit (kAllTexUnits).
constexpr uint32_t kAllTexUnits = (1u << kMaxTexUnits) - 1;

} // namespace pineda
