// Pixel comparison of two runner images.
#pragma once

#include "rgba_image.h"

namespace conformance {

struct DiffStats {
  bool comparable = false;  // both images present and of the same size
  long bad_pixels = 0;      // pixels where some channel differs by more than the tolerance
  double bad_percent = 0.0; // bad_pixels as a percentage of all pixels
  int max_diff = 0;         // largest absolute channel difference (0..255)
  double psnr = 0.0;        // over all four channels; infinity when identical
};

// Compares `test` against `reference`. When `diff` is not null it receives a visualisation: the
// reference dimmed to a quarter where the images agree exactly, differences within the
// tolerance in green amplified 32x, and bad pixels in red (brightness grows with the difference).
DiffStats compare_images(const RgbaImage& test, const RgbaImage& reference, int tolerance,
                         RgbaImage* diff);

} // namespace conformance
