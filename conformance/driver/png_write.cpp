#include "png_write.h"

#include <png.h>

#include <cstdio>
#include <vector>

namespace conformance {

std::string write_png(const std::string& path, const RgbaImage& image) {
  if (image.width <= 0 || image.height <= 0) return "empty image";
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return "cannot create " + path;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    return "libpng initialisation failed";
  }
  // Rows are built before setjmp so that no object with a destructor is live across longjmp.
  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 3;
  std::vector<png_byte> rgb(row_bytes * static_cast<std::size_t>(image.height));
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
  for (int y = 0; y < image.height; ++y) {
    png_bytep row = rgb.data() + row_bytes * static_cast<std::size_t>(y);
    rows[static_cast<std::size_t>(y)] = row;
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, image.height - 1 - y);
      row[x * 3 + 0] = p[0];
      row[x * 3 + 1] = p[1];
      row[x * 3 + 2] = p[2];
    }
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    return "libpng error while writing " + path;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  if (std::fclose(file) != 0) return "cannot close " + path;
  return {};
}

} // namespace conformance
