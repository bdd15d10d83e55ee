// The numbering of a shader program's inputs and outputs, shared by the front end (which
// lowers GLSL's built-in and user variables to them), the engine (which reads and writes them
// as plain arrays) and the GL integration (which fills and consumes those arrays). Every slot
// holds four components; component k of slot s is index 4 * s + k.
#pragma once

#include <cstdint>

namespace pineda::shader {

constexpr int kMaxTextureCoords = 8;  // gl_TexCoord[] / gl_MultiTexCoordN
constexpr int kMaxVertexAttribs = 16; // generic attributes 0..15
constexpr int kMaxVaryingSlots = 16;  // user varyings, four floats each (MAX_VARYING_FLOATS 64)
constexpr int kMaxDrawBuffers = 8;    // gl_FragData[]

// Vertex shader inputs: the conventional attributes (GL 2.1 §2.7) and the generic ones.
enum VertexInput : int {
  kInVertex = 0,         // gl_Vertex
  kInNormal = 1,         // gl_Normal (xyz)
  kInColor = 2,          // gl_Color
  kInSecondaryColor = 3, // gl_SecondaryColor
  kInFogCoord = 4,       // gl_FogCoord (x)
  kInMultiTexCoord0 = 5, // gl_MultiTexCoord0..7: 5..12
  kInGeneric0 = 16,      // generic attribute i: 16 + i
  kNumVertexInputs = kInGeneric0 + kMaxVertexAttribs,
};

// Vertex shader outputs (GL 2.1 §2.15.3 "Varying variables" and the special ones).
enum VertexOutput : int {
  kOutPosition = 0,            // gl_Position
  kOutPointSize = 1,           // gl_PointSize (x)
  kOutClipVertex = 2,          // gl_ClipVertex
  kOutFrontColor = 3,          // gl_FrontColor
  kOutBackColor = 4,           // gl_BackColor
  kOutFrontSecondaryColor = 5, // gl_FrontSecondaryColor
  kOutBackSecondaryColor = 6,  // gl_BackSecondaryColor
  kOutTexCoord0 = 7,           // gl_TexCoord[0..7]: 7..14
  kOutFogFragCoord = 15,       // gl_FogFragCoord (x)
  kOutVarying0 = 16,           // user varying slot v: 16 + v (the link assigns v)
  kNumVertexOutputs = kOutVarying0 + kMaxVaryingSlots,
};

// Fragment shader inputs. The colours are the ones the rasterizer chose (front or back,
// GL 2.1 §2.14.1 two-sided lighting) and interpolated.
enum FragmentInput : int {
  kFragColor = 0,          // gl_Color
  kFragSecondaryColor = 1, // gl_SecondaryColor
  kFragTexCoord0 = 2,      // gl_TexCoord[0..7]: 2..9
  kFragFogFragCoord = 10,  // gl_FogFragCoord (x)
  kFragCoord = 11,         // gl_FragCoord (x, y window; z depth; w 1/w_clip)
  kFragPointCoord = 12,    // gl_PointCoord (xy)
  kFragFrontFacing = 13,   // gl_FrontFacing (x; the run's front_facing, not an array)
  kFragVarying0 = 16,      // user varying slot v: 16 + v, as the vertex outputs
  kNumFragmentInputs = kFragVarying0 + kMaxVaryingSlots,
};

// Fragment shader outputs.
enum FragmentOutput : int {
  kOutFragData0 = 0, // gl_FragData[i]: i; gl_FragColor is written to slot 0
  kOutFragDepth = 8, // gl_FragDepth (x)
  kNumFragmentOutputs = 9,
};

} // namespace pineda::shader
