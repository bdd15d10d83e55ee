// The image file the scene runner writes and the conformance driver reads.
//
// Layout: the 8-byte magic "PNDRGBA1", width and height as little-endian uint32, then
// width * height RGBA8 pixels, rows bottom-up (the GL window-coordinate order, GL 2.1 §2.11.1),
// so row 0 is window y = 0 whatever colour format or OSMESA_Y_UP setting the scene used.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace conformance {

struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels; // width * height * 4 bytes, bottom-up rows

  const std::uint8_t* pixel(int x, int y) const {
    return pixels.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                            static_cast<std::size_t>(x)) * 4;
  }
};

// Both return an empty string on success, else a message saying what went wrong.
std::string write_rgba_file(const std::string& path, const RgbaImage& image);
std::string read_rgba_file(const std::string& path, RgbaImage& image);

} // namespace conformance
