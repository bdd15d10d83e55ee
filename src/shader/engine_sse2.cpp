// The engine's kernels for the baseline target: four lanes per vector (SSE2 on x86-64).
#include <cstring>
#include <utility>

#include "shader/engine_internal.h"
#include "shader/engine_kernels.h"

namespace pineda::shader {

KernelTable kernels_baseline(bool block) {
  return block ? make_kernel_table<4, true>() : make_kernel_table<4, false>();
}

} // namespace pineda::shader
