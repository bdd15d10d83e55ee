// Compares two screenshots (8-bit RGB or RGBA PNGs of the same size) the way the conformance
// harness does, or by colour histogram.
//
//   png_compare A.png B.png [--tolerance T] [--max-bad P] [--histogram D] [--diff out.png]
//
// Pixel mode (default): a pixel is bad when a channel differs by more than T (default 2); the
// images match when at most P percent of the pixels are bad (default 0.5).
// Histogram mode (--histogram D): each channel is binned into 32 bins; the distance of a channel
// is the share of pixels that would have to change bins to turn one histogram into the other
// (half the L1 distance of the normalised histograms); the images match when every channel's
// distance is at most D percent. For pictures where the details may move but the overall
// colours must not (many small blended sprites).
// On a mismatch with --diff, writes an image with the bad pixels in red over a dimmed grey copy
// of A. Exit status: 0 match, 1 mismatch, 2 bad usage or unreadable file.
#include "png_write.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

namespace {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba; // top-down rows (as stored in the file)
};

bool read_png(const char* path, Image& out) {
  png_image img;
  std::memset(&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, path)) {
    std::fprintf(stderr, "png_compare: cannot read %s: %s\n", path, img.message);
    return false;
  }
  img.format = PNG_FORMAT_RGBA;
  out.width = static_cast<int>(img.width);
  out.height = static_cast<int>(img.height);
  out.rgba.resize(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, out.rgba.data(), 0, nullptr)) {
    std::fprintf(stderr, "png_compare: cannot decode %s: %s\n", path, img.message);
    png_image_free(&img);
    return false;
  }
  return true;
}

int usage() {
  std::fprintf(stderr, "usage: png_compare A.png B.png [--tolerance T] [--max-bad PERCENT] "
                       "[--histogram PERCENT] [--diff out.png]\n");
  return 2;
}

bool parse_number(const char* text, double& out) {
  char* end = nullptr;
  out = std::strtod(text, &end);
  return end != text && *end == '\0' && std::isfinite(out) && out >= 0;
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  const char* path_a = argv[1];
  const char* path_b = argv[2];
  double tolerance = 2, max_bad = 0.5, histogram = -1;
  std::string diff_path;
  for (int i = 3; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) return usage();
    const char* v = argv[++i];
    double* target = a == "--tolerance"   ? &tolerance
                     : a == "--max-bad"   ? &max_bad
                     : a == "--histogram" ? &histogram
                                          : nullptr;
    if (a == "--diff") {
      diff_path = v;
    } else if (target == nullptr || !parse_number(v, *target)) {
      std::fprintf(stderr, "png_compare: bad option %s %s\n", a.c_str(), v);
      return usage();
    }
  }
  Image a, b;
  if (!read_png(path_a, a) || !read_png(path_b, b)) return 2;
  if (a.width != b.width || a.height != b.height) {
    std::fprintf(stderr, "png_compare: sizes differ: %dx%d and %dx%d\n", a.width, a.height, b.width,
                 b.height);
    return 1;
  }
  const size_t pixels = static_cast<size_t>(a.width) * a.height;

  // Per pixel, in both modes (printed; decides in pixel mode).
  size_t bad = 0;
  int worst = 0;
  std::vector<bool> is_bad(pixels);
  for (size_t p = 0; p < pixels; ++p) {
    int d = 0;
    for (int c = 0; c < 3; ++c)
      d = std::max(d, std::abs(a.rgba[p * 4 + c] - b.rgba[p * 4 + c]));
    worst = std::max(worst, d);
    if (d > tolerance) {
      is_bad[p] = true;
      ++bad;
    }
  }
  const double bad_percent = 100.0 * static_cast<double>(bad) / static_cast<double>(pixels);
  std::printf(
      "png_compare: %dx%d, %zu bad pixels (%.3f%%, tolerance %.0f), largest difference %d\n",
      a.width, a.height, bad, bad_percent, tolerance, worst);

  bool match = bad_percent <= max_bad;
  if (histogram >= 0) {
    constexpr int kBins = 32;
    double worst_distance = 0;
    for (int c = 0; c < 3; ++c) {
      std::array<long, kBins> ha{}, hb{};
      for (size_t p = 0; p < pixels; ++p) {
        ++ha[a.rgba[p * 4 + c] * kBins / 256];
        ++hb[b.rgba[p * 4 + c] * kBins / 256];
      }
      long l1 = 0;
      for (int k = 0; k < kBins; ++k)
        l1 += std::abs(ha[k] - hb[k]);
      const double distance = 50.0 * static_cast<double>(l1) / static_cast<double>(pixels);
      std::printf("png_compare: channel %c histogram distance %.3f%%\n", "RGB"[c], distance);
      worst_distance = std::max(worst_distance, distance);
    }
    match = worst_distance <= histogram;
    std::printf("png_compare: histogram mode, limit %.3f%%: %s\n", histogram,
                match ? "match" : "MISMATCH");
  } else {
    std::printf("png_compare: pixel mode, limit %.3f%% bad: %s\n", max_bad,
                match ? "match" : "MISMATCH");
  }

  if (!match && !diff_path.empty()) {
    // write_png takes bottom-up rows: flip while composing.
    std::vector<std::uint8_t> diff(pixels * 4);
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x) {
        const size_t src = static_cast<size_t>(y) * a.width + x;
        const size_t dst = static_cast<size_t>(a.height - 1 - y) * a.width + x;
        const std::uint8_t* s = &a.rgba[src * 4];
        const auto grey = static_cast<std::uint8_t>((s[0] * 77 + s[1] * 150 + s[2] * 29) >> 10);
        std::uint8_t* d = &diff[dst * 4];
        d[0] = is_bad[src] ? 255 : grey;
        d[1] = is_bad[src] ? 0 : grey;
        d[2] = is_bad[src] ? 0 : grey;
        d[3] = 255;
      }
    if (demo::write_png(diff_path, a.width, a.height, diff))
      std::printf("png_compare: diff image %s\n", diff_path.c_str());
  }
  return match ? 0 : 1;
}
