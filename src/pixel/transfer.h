// Pixel transfer state (GL 2.1 §3.6.3: glPixelTransfer and glPixelMap) and the pixel transfer
// operations of §3.6.5 that DrawPixels, ReadPixels, CopyPixels and the
// texture image commands apply to every group. Plain data and functions: no GL context here.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include "core/limits.h"

namespace pineda {

// The ten maps of Table 3.3, in the order of their enums (GL_PIXEL_MAP_I_TO_I .. _A_TO_A are
// consecutive).
enum PixelMapId : int {
  kMapItoI,
  kMapStoS,
  kMapItoR,
  kMapItoG,
  kMapItoB,
  kMapItoA,
  kMapRtoR,
  kMapGtoG,
  kMapBtoB,
  kMapAtoA,
  kPixelMapCount,
};

// PixelMapId of a GL_PIXEL_MAP_* enum, -1 for anything else.
int pixel_map_id(GLenum map);

// GL_PIXEL_MAP_*_SIZE enum (GL_PIXEL_MAP_I_TO_I_SIZE ..) to PixelMapId, -1 for anything else.
int pixel_map_size_id(GLenum pname);

// True for the maps addressed by an index, whose size must be a power of two (§3.6.3).
inline bool pixel_map_index_addressed(int id) {
  return id <= kMapItoA;
}

// One table. Entries are stored as floats: colour components as given or converted per
// Table 2.9, colour indices as their value, stencil indices rounded to integers (§3.6.3).
struct PixelMap {
  int size = 1;
  float values[kMaxPixelMapTable] = {};
};

// Every pixel transfer mode of Table 3.2 that GL 1.5 has: glPixelTransfer's state, part of the
// pixel attribute group (state/pixel.h, Table 6.24).
struct PixelTransfer {
  bool map_color = false;
  bool map_stencil = false;
  int index_shift = 0;
  int index_offset = 0;
  float scale[4] = {1.0f, 1.0f, 1.0f, 1.0f}; // RED_SCALE .. ALPHA_SCALE
  float bias[4] = {0.0f, 0.0f, 0.0f, 0.0f};  // RED_BIAS .. ALPHA_BIAS
  float depth_scale = 1.0f;
  float depth_bias = 0.0f;
};

// The ten maps of Table 3.3 (glPixelMap, Table 6.25; no attribute group saves them).
struct PixelMaps {
  PixelMap maps[kPixelMapCount];
};

// What the operations of §3.6.5 read: the modes and the maps.
struct PixelTransferView {
  const PixelTransfer& mode;
  const PixelMaps& maps;
};

// True when "Arithmetic on Components" or "RGBA to RGBA Lookup" can change an RGBA group.
bool rgba_transfer_active(const PixelTransferView& xfer);
// True when depth scale/bias can change a depth component.
bool depth_transfer_active(const PixelTransferView& xfer);
// True when shift/offset or MAP_STENCIL can change a stencil index.
bool stencil_transfer_active(const PixelTransferView& xfer);

// §3.6.5 "Arithmetic on Components" then "RGBA to RGBA Lookup" on `count` RGBA groups.
void transfer_rgba(const PixelTransferView& xfer, float* rgba, size_t count);

// §3.6.5 "Arithmetic on Components" on `count` depth components.
void transfer_depth(const PixelTransferView& xfer, float* depth, size_t count);

// §3.6.5 "Arithmetic on Indices": shift by |INDEX_SHIFT| (left when positive), add
// INDEX_OFFSET. Indices are integers held in 32 bits; arithmetic wraps.
uint32_t shift_offset_index(const PixelTransferView& xfer, uint32_t index);

// §3.6.5 "Arithmetic on Indices" then "Color Index Lookup" to RGBA (the groups are always
// RGBA-required in Pineda, which has no colour index mode): `count` indices to RGBA groups.
void color_index_to_rgba(const PixelTransferView& xfer, const uint32_t* index, size_t count,
                         float* rgba);

// §3.6.5 "Arithmetic on Indices" then "Stencil Index Lookup" (when MAP_STENCIL) in place.
void transfer_stencil(const PixelTransferView& xfer, uint32_t* index, size_t count);

} // namespace pineda
