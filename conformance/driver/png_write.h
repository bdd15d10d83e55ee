// PNG output with libpng, for the report.
#pragma once

#include "rgba_image.h"

#include <string>

namespace conformance {

// Writes the image as an 8-bit RGB PNG, top row first (the runner image is bottom-up). Alpha is
// dropped so that the pictures show colour as it would appear on screen; alpha differences still
// count in the statistics and the diff image. Returns an empty string on success.
std::string write_png(const std::string& path, const RgbaImage& image);

} // namespace conformance
