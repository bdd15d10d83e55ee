// The floating-point environment the engine computes in: denormal inputs read as zero and
// denormal results flush to zero (MXCSR DAZ and FTZ on x86), as llvmpipe's generated code and
// GPUs do (GLSL 1.20 §4.1.4 allows it). The engine's runs and the IR's constant folder both
// use it, so that a folded constant equals what the engine computes; the texture sampler is
// called with the caller's environment.
#pragma once

#include <cstdint>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace pineda::shader {

class ShaderFpEnv {
public:
  ShaderFpEnv() {
#if defined(__SSE2__)
    saved_ = _mm_getcsr();
    _mm_setcsr(saved_ | 0x8040u); // FTZ (bit 15), DAZ (bit 6)
#endif
  }
  ~ShaderFpEnv() {
#if defined(__SSE2__)
    _mm_setcsr(saved_);
#endif
  }
  ShaderFpEnv(const ShaderFpEnv&) = delete;
  ShaderFpEnv& operator=(const ShaderFpEnv&) = delete;
  uint32_t saved() const {
    return saved_;
  }

private:
  uint32_t saved_ = 0;
};

// Runs fn with the environment `csr` (the caller's), then returns to the engine's.
template <class Fn> inline void with_fp_env(uint32_t csr, Fn&& fn) {
#if defined(__SSE2__)
  const uint32_t mine = _mm_getcsr();
  _mm_setcsr(csr);
  fn();
  _mm_setcsr(mine);
#else
  (void)csr;
  fn();
#endif
}

} // namespace pineda::shader
