// The processed vertex: what the geometry stage hands to primitive assembly, clipping and
// rasterization. One layout for every path (immediate mode, arrays, buffers, display lists).
// Plain data at the bottom of the layers: the geometry stage writes it, the back end reads it.
#pragma once

#include <cstdint>

#include "core/limits.h"

namespace pineda {

// Attribute slots in PVertex::attr. The layout is fixed; RasterState::attr_count says how many
// leading floats are live (clipped and interpolated), so a scene that reads only colour pays
// for four floats.
constexpr int kAttrColor = 0;  // primary colour RGBA, clamped to [0,1]
constexpr int kAttrColor2 = 4; // secondary colour RGB(A) (GL 1.4 colour sum)
constexpr int kAttrTex0 = 8;   // texture unit u at kAttrTex0 + 4*u, (s,t,r,q)
constexpr int kAttrFog = kAttrTex0 + 4 * kMaxTexUnits; // 24: fog coordinate / factor
constexpr int kAttrBackColor = 28;                     // two-sided lighting: back primary colour
constexpr int kAttrBackColor2 = 32;                    // two-sided lighting: back secondary colour
// With a GLSL program, the user varyings the fragment shader reads follow, packed as the link
// packs them (state/program_draw.cpp): MAX_VARYING_FLOATS of them at most.
constexpr int kAttrVarying0 = 36;
constexpr int kMaxVaryingAttr = 64;
constexpr int kMaxAttr = kAttrVarying0 + kMaxVaryingAttr;
// With a vertex shader and user clip planes, the distance of the vertex's gl_ClipVertex to
// plane i at kAttrClipDist + i (geometry/clip.h ClipSetup::user_dist): the last floats, free
// unless the varyings fill them.
constexpr int kAttrClipDist = kMaxAttr - kMaxClipPlanes;

// Clip code bits (GL 2.1 §2.12). A bit is set when the vertex is outside that half-space.
enum ClipBit : uint32_t {
  kClipLeft = 1u << 0,   // x < -w
  kClipRight = 1u << 1,  // x >  w
  kClipBottom = 1u << 2, // y < -w
  kClipTop = 1u << 3,    // y >  w
  kClipNear = 1u << 4,   // z < -w
  kClipFar = 1u << 5,    // z >  w
  kClipUser0 = 1u << 6,  // user plane i at kClipUser0 << i (i < 6): dot(plane, clip) < 0
  kClipGuard = 1u << 12, // x or y outside the guard band (raster_state.h kGuardBand)
};
constexpr uint32_t kClipFrustumMask = 0x3f;

// The fields the primitive assembly and the triangle setup read for every primitive (window
// position, clip code, clip coordinates, primary colour) come first, inside the first 64
// bytes; with the alignment each vertex's hot fields are one cache line, and a draw touches
// only the attribute lines up to RasterState::attr_count.
struct alignas(64) PVertex {
  float win[4];      // window x, y; z after depth range in [0,1]; win[3] = 1 / clip w.
                     // Valid whenever clipmask == 0, and for every vertex the clipper emits.
  uint32_t clipmask; // ClipBit set for this vertex
  uint32_t edgeflag; // GL edge flag (1 = boundary edge starts here)
  // Derived point size (GL 2.1 §3.3 eq 3.1) when distance attenuation is on; 1 otherwise.
  float point_size;
  float clip[4]; // clip coordinates (x, y, z, w)
  float attr[kMaxAttr];
};

} // namespace pineda
