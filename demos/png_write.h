// Writes glReadPixels output as a PNG (libpng); shared by the demos and the test programs.
#pragma once

#include <png.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace demo {

// Writes an RGBA image whose rows are bottom-up (glReadPixels order) as an 8-bit RGB PNG.
inline bool write_png(const std::string& path, int width, int height,
                      const std::vector<std::uint8_t>& rgba) {
  FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) {
    std::fprintf(stderr, "cannot open %s for writing: %s\n", path.c_str(), std::strerror(errno));
    return false;
  }
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png != nullptr ? png_create_info_struct(png) : nullptr;
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    std::fprintf(stderr, "cannot write %s\n", path.c_str());
    return false;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  std::vector<std::uint8_t> row(static_cast<size_t>(width) * 3);
  for (int y = height - 1; y >= 0; --y) {
    const std::uint8_t* src = &rgba[static_cast<size_t>(y) * width * 4];
    for (int x = 0; x < width; ++x)
      std::memcpy(&row[static_cast<size_t>(x) * 3], src + x * 4, 3);
    png_write_row(png, row.data());
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return std::fclose(file) == 0;
}

} // namespace demo
