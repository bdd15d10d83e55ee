// The sharing of back-end work among the worker threads (schedule.h).
#include "raster/schedule.h"

#include <algorithm>
#include <cstdint>

namespace pineda {

namespace {

// Clears of at least this many pixels are shared among the worker threads, in runs of at
// least kShareClearRows rows.
constexpr int64_t kShareClearArea = 512 * 1024;
constexpr int kShareClearRows = 16;

} // namespace

void clear_buffers_shared(RasterWorkers* workers, Framebuffer& fb, const ClearState& cs,
                          GLbitfield mask) {
  const ClearRect r = clear_rect(fb, cs);
  const int64_t area = int64_t{std::max(r.w(), 0)} * std::max(r.h(), 0);
  if (workers != nullptr && area >= kShareClearArea && r.h() >= 2 * kShareClearRows) {
    const int n = std::min(workers->threads(), r.h() / kShareClearRows);
    if (n > 1) {
      auto job = [&](int i) {
        if (i >= n) return;
        ClearRect part = r;
        part.y0 = r.y0 + static_cast<int>(int64_t{r.h()} * i / n);
        part.y1 = r.y0 + static_cast<int>(int64_t{r.h()} * (i + 1) / n);
        clear_buffers(fb, cs, mask, part);
      };
      workers->run(job);
      return;
    }
  }
  clear_buffers(fb, cs, mask, r);
}

} // namespace pineda
