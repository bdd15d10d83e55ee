// Helpers for the property tests that go through the GL API: an OSMesa context on a colour
// buffer with guard bytes on both sides, and additive counting of fragments.
#pragma once

#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

namespace pineda::test {

// A current context whose RGBA colour buffer sits between two guard areas filled with a
// pattern, so that any write outside the w x h pixels is seen.
class GuardedContext {
public:
  static constexpr size_t kGuard = 4096;
  static constexpr uint8_t kPattern = 0x5A;

  GuardedContext(int w, int h, GLint depth_bits = 24) : w_(w), h_(h) {
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, depth_bits, 8, 0, nullptr);
    mem_.assign(2 * kGuard + static_cast<size_t>(w) * h * 4, kPattern);
    std::memset(mem_.data() + kGuard, 0, static_cast<size_t>(w) * h * 4);
    ok_ = ctx_ != nullptr &&
          OSMesaMakeCurrent(ctx_, mem_.data() + kGuard, GL_UNSIGNED_BYTE, w, h) == GL_TRUE;
  }
  ~GuardedContext() {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    if (ctx_ != nullptr) OSMesaDestroyContext(ctx_);
  }
  GuardedContext(const GuardedContext&) = delete;
  GuardedContext& operator=(const GuardedContext&) = delete;

  bool ok() const { return ok_; }
  int width() const { return w_; }
  int height() const { return h_; }

  // True when both guard areas still hold the pattern.
  bool guards_intact() const {
    const size_t tail = kGuard + static_cast<size_t>(w_) * h_ * 4;
    for (size_t i = 0; i < kGuard; ++i)
      if (mem_[i] != kPattern || mem_[tail + i] != kPattern) return false;
    return true;
  }
  const uint8_t* px(int x, int y) const {
    return mem_.data() + kGuard + (static_cast<size_t>(y) * w_ + x) * 4;
  }
  void clear_pixels() { std::memset(mem_.data() + kGuard, 0, static_cast<size_t>(w_) * h_ * 4); }

private:
  OSMesaContext ctx_ = nullptr;
  int w_, h_;
  bool ok_ = false;
  std::vector<uint8_t> mem_;
};

// Each fragment adds 1 to red: blending ONE, ONE with colour 1/255 (exactly 1 after the
// conversion to 8 bits, GL 2.1 §2.14.9).
inline void enable_counting() {
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glColor4f(1.0f / 255.0f, 0.0f, 0.0f, 0.0f);
}

} // namespace pineda::test
