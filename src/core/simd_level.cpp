// Run-time choice of the hot loops' instruction set (simd_level.h).
#include "core/simd_level.h"

#include <atomic>
#include <cstdlib>
#include <cstring>

namespace pineda {

namespace {

// -1 until first use; then a SimdLevel. Relaxed: every thread computes the same value.
std::atomic<int> g_level{-1};

SimdLevel detect() {
#if PINEDA_HAVE_AVX2
  __builtin_cpu_init();
  // GCC's and Clang's checks include the OS support for the YMM state (XGETBV).
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("bmi") &&
      __builtin_cpu_supports("bmi2"))
    return SimdLevel::Avx2;
#endif
  return SimdLevel::Baseline;
}

} // namespace

SimdLevel simd_level_supported() {
  static const SimdLevel supported = detect();
  return supported;
}

SimdLevel simd_level() {
  int v = g_level.load(std::memory_order_relaxed);
  if (v < 0) {
    SimdLevel l = simd_level_supported();
    const char* env = std::getenv("PINEDA_SIMD");
    if (env != nullptr && (std::strcmp(env, "sse2") == 0 || std::strcmp(env, "baseline") == 0))
      l = SimdLevel::Baseline;
    v = static_cast<int>(l);
    g_level.store(v, std::memory_order_relaxed);
  }
  return static_cast<SimdLevel>(v);
}

void set_simd_level(SimdLevel level) {
  if (level == SimdLevel::Avx2 && simd_level_supported() != SimdLevel::Avx2)
    level = SimdLevel::Baseline;
  g_level.store(static_cast<int>(level), std::memory_order_relaxed);
}

} // namespace pineda
