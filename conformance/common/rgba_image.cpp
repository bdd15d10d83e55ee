#include "rgba_image.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace conformance {
namespace {

constexpr char kMagic[8] = {'P', 'N', 'D', 'R', 'G', 'B', 'A', '1'};
// Larger images are refused so that a corrupt header cannot make the reader allocate gigabytes.
constexpr std::uint32_t kMaxSide = 16384;

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

void put_u32(unsigned char* out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out[i] = static_cast<unsigned char>(v >> (8 * i));
}

std::uint32_t get_u32(const unsigned char* in) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(in[i]) << (8 * i);
  return v;
}

} // namespace

std::string write_rgba_file(const std::string& path, const RgbaImage& image) {
  const std::size_t expected =
      static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4;
  if (image.width <= 0 || image.height <= 0 || image.pixels.size() != expected)
    return "image has inconsistent size";
  File f(std::fopen(path.c_str(), "wb"));
  if (!f) return "cannot create " + path + ": " + std::strerror(errno);
  unsigned char header[16];
  std::memcpy(header, kMagic, 8);
  put_u32(header + 8, static_cast<std::uint32_t>(image.width));
  put_u32(header + 12, static_cast<std::uint32_t>(image.height));
  if (std::fwrite(header, 1, sizeof header, f.get()) != sizeof header ||
      std::fwrite(image.pixels.data(), 1, expected, f.get()) != expected)
    return "short write to " + path;
  if (std::fclose(f.release()) != 0) return "cannot close " + path;
  return {};
}

std::string read_rgba_file(const std::string& path, RgbaImage& image) {
  File f(std::fopen(path.c_str(), "rb"));
  if (!f) return "cannot open " + path + ": " + std::strerror(errno);
  unsigned char header[16];
  if (std::fread(header, 1, sizeof header, f.get()) != sizeof header ||
      std::memcmp(header, kMagic, 8) != 0)
    return path + " is not a runner image (bad header)";
  const std::uint32_t w = get_u32(header + 8), h = get_u32(header + 12);
  if (w == 0 || h == 0 || w > kMaxSide || h > kMaxSide)
    return path + " has an implausible size";
  image.width = static_cast<int>(w);
  image.height = static_cast<int>(h);
  const std::size_t bytes = static_cast<std::size_t>(w) * h * 4;
  image.pixels.assign(bytes, 0);
  if (std::fread(image.pixels.data(), 1, bytes, f.get()) != bytes)
    return path + " is truncated";
  return {};
}

} // namespace conformance
