// The pixel transfer operations of GL 2.1 §3.6.5 that exist in GL 1.5 without the imaging
// subset: component scale and bias, index shift and offset, and the pixel map lookups.
#include "pixel/transfer.h"

#include <cmath>

namespace pineda {

int pixel_map_id(GLenum map) {
  if (map >= GL_PIXEL_MAP_I_TO_I && map <= GL_PIXEL_MAP_A_TO_A)
    return static_cast<int>(map - GL_PIXEL_MAP_I_TO_I);
  return -1;
}

int pixel_map_size_id(GLenum pname) {
  if (pname >= GL_PIXEL_MAP_I_TO_I_SIZE && pname <= GL_PIXEL_MAP_A_TO_A_SIZE)
    return static_cast<int>(pname - GL_PIXEL_MAP_I_TO_I_SIZE);
  return -1;
}

bool rgba_transfer_active(const PixelTransferView& xfer) {
  if (xfer.mode.map_color) return true;
  for (int c = 0; c < 4; ++c)
    if (xfer.mode.scale[c] != 1.0f || xfer.mode.bias[c] != 0.0f) return true;
  return false;
}

bool depth_transfer_active(const PixelTransferView& xfer) {
  return xfer.mode.depth_scale != 1.0f || xfer.mode.depth_bias != 0.0f;
}

bool stencil_transfer_active(const PixelTransferView& xfer) {
  return xfer.mode.map_stencil || xfer.mode.index_shift != 0 || xfer.mode.index_offset != 0;
}

namespace {

// "RGBA to RGBA Lookup": clamp to [0, 1], scale by size - 1, round to the nearest address.
// NaN clamps to 0 so that the address stays inside the table.
float lookup_component(const PixelMap& map, float v) {
  const float c = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
  const int i = static_cast<int>(std::floor(c * static_cast<float>(map.size - 1) + 0.5f));
  return map.values[i];
}

// "Color Index Lookup" and "Stencil Index Lookup": the tables have 2^n entries and the index
// is ANDed with 2^n - 1.
float lookup_index(const PixelMap& map, uint32_t index) {
  return map.values[index & static_cast<uint32_t>(map.size - 1)];
}

} // namespace

void transfer_rgba(const PixelTransferView& xfer, float* rgba, size_t count) {
  bool scale_bias = false;
  for (int c = 0; c < 4; ++c)
    scale_bias |= xfer.mode.scale[c] != 1.0f || xfer.mode.bias[c] != 0.0f;
  if (scale_bias) {
    for (size_t i = 0; i < count; ++i)
      for (int c = 0; c < 4; ++c)
        rgba[i * 4 + c] = rgba[i * 4 + c] * xfer.mode.scale[c] + xfer.mode.bias[c];
  }
  if (xfer.mode.map_color) {
    const PixelMap* maps = &xfer.maps.maps[kMapRtoR];
    for (size_t i = 0; i < count; ++i)
      for (int c = 0; c < 4; ++c)
        rgba[i * 4 + c] = lookup_component(maps[c], rgba[i * 4 + c]);
  }
}

void transfer_depth(const PixelTransferView& xfer, float* depth, size_t count) {
  if (!depth_transfer_active(xfer)) return;
  for (size_t i = 0; i < count; ++i)
    depth[i] = depth[i] * xfer.mode.depth_scale + xfer.mode.depth_bias;
}

uint32_t shift_offset_index(const PixelTransferView& xfer, uint32_t index) {
  // Shifts of 32 or more bits leave nothing of a 32-bit index (zero-filled, §3.6.5).
  const int s = xfer.mode.index_shift;
  if (s > 0)
    index = s >= 32 ? 0u : index << s;
  else if (s < 0)
    index = s <= -32 ? 0u : index >> -s;
  return index + static_cast<uint32_t>(xfer.mode.index_offset);
}

void color_index_to_rgba(const PixelTransferView& xfer, const uint32_t* index, size_t count,
                         float* rgba) {
  const PixelMap* maps = &xfer.maps.maps[kMapItoR];
  for (size_t i = 0; i < count; ++i) {
    const uint32_t v = shift_offset_index(xfer, index[i]);
    for (int c = 0; c < 4; ++c)
      rgba[i * 4 + c] = lookup_index(maps[c], v);
  }
}

void transfer_stencil(const PixelTransferView& xfer, uint32_t* index, size_t count) {
  if (xfer.mode.index_shift != 0 || xfer.mode.index_offset != 0) {
    for (size_t i = 0; i < count; ++i)
      index[i] = shift_offset_index(xfer, index[i]);
  }
  if (xfer.mode.map_stencil) {
    const PixelMap& map = xfer.maps.maps[kMapStoS];
    // S_TO_S entries are integers (rounded when specified, §3.6.3); negative ones wrap like
    // any other index arithmetic.
    for (size_t i = 0; i < count; ++i)
      index[i] = static_cast<uint32_t>(static_cast<int64_t>(lookup_index(map, index[i])));
  }
}

} // namespace pineda
