// Pineda's implementation limits (GL 2.1 §6.2 Tables 6.36-6.37 "Implementation Dependent
// Values", and the minimums the sections cite): one header at the bottom of the layers, so that
// the back end's plain types, the GL state and glGet all read the same numbers.
#pragma once

#include <cstddef>
#include <cstdint>

namespace pineda {

// ---- vertex processing (Tables 6.36, 6.37) ----
// GL 2.1 §2.7 separates the conventional texture units of fixed-function texturing (their
// environments and target enables) from the texture coordinate sets (matrices, generation,
// current coordinates, arrays) and the texture image units (bindings, which samplers name).
constexpr int kMaxTexUnits = 4;                 // MAX_TEXTURE_UNITS (GL 2.1 §2.7)
constexpr int kMaxTexCoordSets = 4;             // MAX_TEXTURE_COORDS (GL 2.1 §2.7)
constexpr int kMaxTextureImageUnits = 16;       // MAX_TEXTURE_IMAGE_UNITS (fragment, §3.11.2)
constexpr int kMaxVertexTextureImageUnits = 16; // MAX_VERTEX_TEXTURE_IMAGE_UNITS (§2.15.4)
// MAX_COMBINED_TEXTURE_IMAGE_UNITS (§2.15.4): a program may use all of both stages' units.
constexpr int kMaxCombinedTextureImageUnits = 32;
// ActiveTexture's range (§2.7): the larger of the coordinate sets and the image units.
constexpr int kMaxActiveTexture = kMaxTexCoordSets > kMaxCombinedTextureImageUnits
                                      ? kMaxTexCoordSets
                                      : kMaxCombinedTextureImageUnits;
// Every coordinate set has a conventional unit's state today (current.h, texcoord.h).
static_assert(kMaxTexCoordSets == kMaxTexUnits);
constexpr int kMaxLights = 8;                // MAX_LIGHTS (§2.14.1: at least 8)
constexpr int kMaxClipPlanes = 6;            // MAX_CLIP_PLANES (§2.12: at least 6)
constexpr size_t kModelviewStackDepth = 32;  // MAX_MODELVIEW_STACK_DEPTH (§2.11.2: at least 32)
constexpr size_t kProjectionStackDepth = 32; // MAX_PROJECTION_STACK_DEPTH (at least 2)
constexpr size_t kTextureStackDepth = 10;    // MAX_TEXTURE_STACK_DEPTH (at least 2)
constexpr int kMaxViewportDim = 16384;       // MAX_VIEWPORT_DIMS (§2.11.1)
constexpr int kMaxEvalOrder = 30;            // MAX_EVAL_ORDER (§5.1: at least 8; Mesa's 30)
// GL 1.2 DrawRangeElements recommendations (MAX_ELEMENTS_VERTICES, MAX_ELEMENTS_INDICES):
// Pineda has no such limit and reports large values.
constexpr int kMaxElementsVertices = 1 << 20;

// ---- stacks of state (Table 6.37) ----
constexpr size_t kAttribStackDepth = 16;       // MAX_ATTRIB_STACK_DEPTH (§6.1.14: at least 16)
constexpr size_t kClientAttribStackDepth = 16; // MAX_CLIENT_ATTRIB_STACK_DEPTH
constexpr int kMaxNameStackDepth = 64;         // MAX_NAME_STACK_DEPTH (§5.2: at least 64)
constexpr int kMaxListNesting = 64;            // MAX_LIST_NESTING (§5.4: at least 64)

// ---- rasterization (Table 6.36), the values llvmpipe reports ----
constexpr int kSubpixelBits = 8; // SUBPIXEL_BITS
// ALIASED_/POINT_SIZE_RANGE and ALIASED_/LINE_WIDTH_RANGE end here; the granularities.
constexpr float kMaxPointSize = 255.0f;
constexpr float kMaxLineWidth = 255.0f;
constexpr float kSizeGranularity = 0.1f;

// ---- pixels and textures (Tables 6.36, 6.37) ----
constexpr int kMaxPixelMapTable = 256; // MAX_PIXEL_MAP_TABLE (§3.6.3: at least 32; Mesa's 256)
constexpr int kMaxTexLevels = 12;      // 2048 = 2^11: levels 0..11
constexpr int kMax3DTexLevels = 12;    // 2048, as llvmpipe
constexpr int kMaxTextureSize = 1 << (kMaxTexLevels - 1);     // MAX_TEXTURE_SIZE
constexpr int kMax3DTextureSize = 1 << (kMax3DTexLevels - 1); // MAX_3D_TEXTURE_SIZE
constexpr int kMaxCubeTextureSize = kMaxTextureSize;          // MAX_CUBE_MAP_TEXTURE_SIZE
constexpr float kMaxLodBias = 16.0f;                          // MAX_TEXTURE_LOD_BIAS, as llvmpipe
// The largest texel store of one image (4 bytes per texel); larger images are OUT_OF_MEMORY.
constexpr uint64_t kMaxTextureImageBytes = uint64_t(1) << 30;

// ---- framebuffer objects (ARB_framebuffer_object, Table 6.X "Framebuffer Dependent Values") ----
constexpr int kMaxDrawBuffers = 8;          // MAX_DRAW_BUFFERS (GL 2.0 §4.2.1)
constexpr int kMaxColorAttachments = 8;     // MAX_COLOR_ATTACHMENTS
constexpr int kMaxRenderbufferSize = 16384; // MAX_RENDERBUFFER_SIZE, as MAX_VIEWPORT_DIMS
// The largest storage of one renderbuffer; larger ones are OUT_OF_MEMORY (§4.4.2.1).
constexpr uint64_t kMaxRenderbufferBytes = uint64_t(1) << 28;

} // namespace pineda
