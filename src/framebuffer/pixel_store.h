// The glPixelStore parameters of one direction (pack or unpack). The context keeps two of
// these; the pixel paths (ReadPixels, DrawPixels, TexImage, GetTexImage) take the one they need.
#pragma once

namespace pineda {

// GL 2.1 §3.6.1 Table 3.1 (unpack) and §4.3.2 Table 4.5 (pack): same fields, same defaults.
struct PixelStore {
  bool swap_bytes = false;
  bool lsb_first = false;
  int row_length = 0;  // 0: a row holds `width` groups (§3.6.4)
  int skip_rows = 0;
  int skip_pixels = 0;
  int alignment = 4;   // 1, 2, 4 or 8
  int image_height = 0; // 3D images (§3.8.1); not used by 2D paths
  int skip_images = 0;
};

} // namespace pineda
