// The program's side of the draws (program_draw.cpp): what the back end reads of the current
// program. Not included by context.h (the back end's names collide with Xlib's macros in the
// GLX files); the files that read it include it.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "fragment/shade.h"
#include "geometry/vertex_program.h"
#include "pixel/raster_pos.h"
#include "state/program.h"

namespace pineda {

// What the back end reads of the current program, derived when the program or the state its stages
// depend on changed, and refreshed before each draw (uniforms, built-in state, textures).
struct ProgramDerived {
  // The program the rest was derived for (kept alive: another context of the share group may
  // relink or delete it meanwhile, and the draws notice).
  std::shared_ptr<const LinkedProgram> linked;
  bool has_vertex = false, has_fragment = false;
  uint32_t vs_tex_units = 0; // gl_MultiTexCoord0..3 the vertex shader reads
  uint32_t fs_tex_units = 0; // gl_TexCoord[0..3] the fragment shader reads
  bool fs_fog = false;       // the fragment shader reads gl_FogFragCoord
  int attr_count = 0;        // RasterState::attr_count with a fragment shader
  VertexProgram vertex;
  FragmentProgram fragment;
  std::shared_ptr<ShadeSetup> shade; // RasterState::shade with a fragment shader
  // The uniform buffer with this context's built-in state, and what the stages were prepared
  // with (prepared again only when it changes).
  std::vector<uint32_t> words;
  std::vector<uint32_t> prepared_words;
  std::shared_ptr<const LinkedProgram> prepared_for;
  uint64_t sampler_generation = ~uint64_t{0};
  uint64_t sampler_serial = ~uint64_t{0};
  std::shared_ptr<shader::Prepared> vs_prepared, fs_prepared;
  std::shared_ptr<ShaderSampler> sampler;
};

// glRasterPos with a vertex shader (GL 2.1 §2.13): the shader transforms the position; fills
// `rp` and returns whether the position is valid.
bool program_raster_pos(Context* ctx, const float obj[4], RasterPos& rp);

} // namespace pineda
