// The vertex stage of a GLSL program (GL 2.1 §2.20): the vertex shader runs in place of the
// fixed-function transform and lighting, over batches of vertices (shader/engine.h), and its
// outputs become processed vertices: gl_Position the clip coordinates, the colours (clamped,
// §2.14.6), texture coordinates, fog coordinate and varyings the attribute slots the fragment
// stage reads, gl_PointSize the point size under VERTEX_PROGRAM_POINT_SIZE (§3.3).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/raster_state.h"
#include "core/vertex.h"
#include "geometry/clip.h"
#include "geometry/input_vertex.h"
#include "shader/io.h"

// The engine's types by name only (vertex_program.cpp includes shader/engine.h): this header
// reaches files that include Xlib, whose macros collide with the engine's IR names.
namespace pineda::shader {
class Executable;
class TextureSampler;
struct Prepared;
} // namespace pineda::shader

namespace pineda {

// Everything the vertex stage of a program reads that is constant over a draw: plain data made
// by the state layer (state/program_draw.cpp).
struct VertexProgram {
  const shader::Executable* exe = nullptr;
  const shader::Prepared* prepared = nullptr;
  shader::TextureSampler* sampler = nullptr;
  // Generic attributes (§2.7): per vertex of the draw, generic_stride floats, attribute i at
  // column generic_column[i] (-1: the attribute's current value for every vertex). Attribute 0
  // is the vertex position.
  const float* generic = nullptr;
  int generic_stride = 0;
  int8_t generic_column[shader::kMaxVertexAttribs] = {};
  float generic_current[shader::kMaxVertexAttribs][4] = {};
  // Where output component c (shader/io.h) goes in PVertex::attr, or -1.
  int16_t out_attr[shader::kNumVertexOutputs * 4] = {};
  int attr_count = 0;      // attribute floats the draw clips and interpolates (zeroed first)
  bool point_size = false; // VERTEX_PROGRAM_POINT_SIZE: gl_PointSize, clamped to the range
  float point_size_min = 0.0f, point_size_max = kMaxPointSize;
  bool fold_sum = false; // fixed-function fragments with the colour sum folded in per vertex
};

// Runs the program over in[0..n) (vertex `first + k` of the draw for the generic values) into
// out[0..n): clip coordinates and code, window coordinates when unclipped, attributes, edge
// flag and point size. Safe to call from several threads at once on separate ranges.
void run_vertex_program(const VertexProgram& vp, const ClipSetup& cs, const Viewport& view,
                        const InputVertex* in, size_t first, PVertex* out, size_t n);

} // namespace pineda
