// Run-time choice of the hot loops' instruction set (simd_level.h).
#include "core/simd_level.h"

#include <atomic>
#include <cstdlib>
#include <cstring>

#if PINEDA_HAVE_AVX512
#include <cpuid.h>
#endif

namespace pineda {

namespace {

// -1 until first use; then a SimdLevel. Relaxed: every thread computes the same value.
std::atomic<int> g_level{-1};

#if PINEDA_HAVE_AVX512
// Whether the OS saves the state AVX-512 code changes on a context switch: XCR0 bits 1 and 2
// (SSE, AVX), 5 (opmask), 6 and 7 (the upper halves of ZMM0-15 and ZMM16-31). The compilers'
// feature checks look at this too; it is checked here explicitly since running 512-bit code on
// an OS that does not save it would corrupt registers silently.
bool os_saves_zmm() {
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  if (__get_cpuid(1, &eax, &ebx, &ecx, &edx) == 0 || (ecx & bit_OSXSAVE) == 0) return false;
  unsigned lo = 0, hi = 0;
  __asm__ volatile("xgetbv" : "=a"(lo), "=d"(hi) : "c"(0));
  constexpr unsigned kNeeded = (1u << 1) | (1u << 2) | (1u << 5) | (1u << 6) | (1u << 7);
  return (lo & kNeeded) == kNeeded;
}
#endif

SimdLevel detect() {
#if PINEDA_HAVE_AVX2
  __builtin_cpu_init();
  // GCC's and Clang's checks include the OS support for the YMM state (XGETBV).
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("bmi") ||
      !__builtin_cpu_supports("bmi2"))
    return SimdLevel::Baseline;
#if PINEDA_HAVE_AVX512
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl") && os_saves_zmm())
    return SimdLevel::Avx512;
#endif
  return SimdLevel::Avx2;
#else
  return SimdLevel::Baseline;
#endif
}

SimdLevel clamp_level(SimdLevel level, SimdLevel supported) {
  return static_cast<int>(level) < static_cast<int>(supported) ? level : supported;
}

} // namespace

SimdLevel simd_level_supported() {
  static const SimdLevel supported = detect();
  return supported;
}

SimdLevel simd_level_from_env(const char* env, SimdLevel supported) {
  if (env == nullptr) return supported;
  if (std::strcmp(env, "sse2") == 0 || std::strcmp(env, "baseline") == 0)
    return SimdLevel::Baseline;
  if (std::strcmp(env, "avx2") == 0) return clamp_level(SimdLevel::Avx2, supported);
  return supported; // "avx512" or anything else: no cap below what the processor has
}

SimdLevel simd_level() {
  int v = g_level.load(std::memory_order_relaxed);
  if (v < 0) {
    v = static_cast<int>(simd_level_from_env(std::getenv("PINEDA_SIMD"), simd_level_supported()));
    g_level.store(v, std::memory_order_relaxed);
  }
  return static_cast<SimdLevel>(v);
}

void set_simd_level(SimdLevel level) {
  g_level.store(static_cast<int>(clamp_level(level, simd_level_supported())),
                std::memory_order_relaxed);
}

} // namespace pineda
