// Swap intervals without a real vertical retrace (GLX_EXT_swap_control, eglSwapInterval):
// swaps are paced to a virtual 60 Hz display.
#pragma once

#include <chrono>

namespace pineda::winsys {

// When a swap with `interval` may happen: no sooner than `interval` periods after the previous
// one (`last`, which is updated). An interval of 0 never waits. The caller sleeps until then
// outside its locks.
inline std::chrono::steady_clock::time_point swap_due(int interval,
                                                      std::chrono::steady_clock::time_point& last) {
  using clock = std::chrono::steady_clock;
  const auto now = clock::now();
  auto due = now;
  if (interval > 0 && last != clock::time_point{}) {
    const auto next = last + std::chrono::microseconds(16667) * interval;
    if (next > now) due = next;
  }
  last = due;
  return due;
}

} // namespace pineda::winsys
