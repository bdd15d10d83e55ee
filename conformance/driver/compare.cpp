#include "compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace conformance {

DiffStats compare_images(const RgbaImage& test, const RgbaImage& reference, int tolerance,
                         RgbaImage* diff) {
  DiffStats stats;
  if (test.width != reference.width || test.height != reference.height || test.width <= 0 ||
      test.pixels.size() != reference.pixels.size())
    return stats;
  stats.comparable = true;
  if (diff) {
    diff->width = test.width;
    diff->height = test.height;
    diff->pixels.assign(test.pixels.size(), 0);
  }
  double squared_error = 0.0;
  const std::size_t count = static_cast<std::size_t>(test.width) * test.height;
  for (std::size_t i = 0; i < count; ++i) {
    const unsigned char* a = &test.pixels[i * 4];
    const unsigned char* b = &reference.pixels[i * 4];
    int worst = 0;
    for (int c = 0; c < 4; ++c) {
      const int d = std::abs(static_cast<int>(a[c]) - static_cast<int>(b[c]));
      worst = std::max(worst, d);
      squared_error += static_cast<double>(d) * d;
    }
    stats.max_diff = std::max(stats.max_diff, worst);
    const bool bad = worst > tolerance;
    if (bad) ++stats.bad_pixels;
    if (!diff) continue;
    unsigned char* out = &diff->pixels[i * 4];
    out[3] = 255;
    if (worst == 0) {
      for (int c = 0; c < 3; ++c) out[c] = static_cast<unsigned char>(b[c] / 4);
    } else if (!bad) {
      out[1] = static_cast<unsigned char>(std::min(255, 96 + worst * 32));
    } else {
      out[0] = static_cast<unsigned char>(std::min(255, 128 + worst));
      out[2] = static_cast<unsigned char>(worst > 64 ? 96 : 0); // large errors turn pink
    }
  }
  stats.bad_percent = 100.0 * static_cast<double>(stats.bad_pixels) / static_cast<double>(count);
  const double mse = squared_error / static_cast<double>(count * 4);
  stats.psnr = mse == 0.0 ? std::numeric_limits<double>::infinity()
                          : 10.0 * std::log10(255.0 * 255.0 / mse);
  return stats;
}

} // namespace conformance
