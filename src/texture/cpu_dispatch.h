// Run-time choice of the AVX2 variants of the texturing code (texture/sampler_quad.cpp,
// fragment/shade.cpp): the default build targets any x86-64, and the AVX2 forms run only where
// the CPU has AVX2. PINEDA_NO_AVX2 set to a non-empty value keeps the SSE2 forms (to test or
// compare them on an AVX2 machine); both give the same results.
#pragma once

#include <cstdlib>

namespace pineda {

inline bool use_avx2() {
#if defined(__x86_64__)
  static const bool ok = [] {
    const char* off = std::getenv("PINEDA_NO_AVX2");
    if (off != nullptr && *off != '\0') return false;
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return ok;
#else
  return false;
#endif
}

} // namespace pineda
