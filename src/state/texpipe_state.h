// GL state of the texturing pipeline and fog (GL 2.1 §2.11.4, §3.8.13, §3.8.15, §3.10): per
// texture unit the target enables, coordinate generation and texture environment; the fog
// parameters and the current fog coordinate. Texture objects and their bindings live with the
// texture objects (src/texture/).
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <memory>

#include "geometry/texcoord.h"
#include "core/vertex.h"

namespace pineda {

// One texture coordinate's generation function (GL 2.1 §2.11.4, Table 6.16).
struct TexGenCoord {
  GLenum mode = GL_EYE_LINEAR;
  float object_plane[4] = {0, 0, 0, 0};
  float eye_plane[4] = {0, 0, 0, 0}; // stored in eye space (transformed at specification)
};

// The texture environment of one unit (GL 2.1 §3.8.13, Table 6.19).
struct TexEnv {
  GLenum mode = GL_MODULATE;
  float color[4] = {0, 0, 0, 0}; // TEXTURE_ENV_COLOR
  GLenum combine_rgb = GL_MODULATE, combine_alpha = GL_MODULATE;
  GLenum src_rgb[3] = {GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  GLenum src_alpha[3] = {GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  GLenum op_rgb[3] = {GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA};
  GLenum op_alpha[3] = {GL_SRC_ALPHA, GL_SRC_ALPHA, GL_SRC_ALPHA};
  float rgb_scale = 1.0f, alpha_scale = 1.0f;
  float lod_bias = 0.0f; // TEXTURE_FILTER_CONTROL / TEXTURE_LOD_BIAS
};

struct TexUnitState {
  // TEXTURE_1D, TEXTURE_2D, TEXTURE_3D, TEXTURE_CUBE_MAP enables (§3.8.15).
  bool enable_1d = false, enable_2d = false, enable_3d = false, enable_cube = false;
  bool gen_enabled[4] = {false, false, false, false}; // TEXTURE_GEN_S, T, R, Q
  TexGenCoord gen[4];
  TexEnv env;
  TexUnitState() {
    // §2.11.4: the S plane defaults to (1,0,0,0), T to (0,1,0,0), R and Q to zero.
    gen[0].object_plane[0] = gen[0].eye_plane[0] = 1.0f;
    gen[1].object_plane[1] = gen[1].eye_plane[1] = 1.0f;
  }
};

// Fog (GL 2.1 §3.10, Table 6.11).
struct FogState {
  bool enabled = false;
  GLenum mode = GL_EXP;
  float color[4] = {0, 0, 0, 0};
  float density = 1.0f, start = 0.0f, end = 1.0f;
  float index = 0.0f;
  GLenum coord_src = GL_FRAGMENT_DEPTH; // FOG_COORD_SRC
};

// What glPushAttrib saves of this state: TEXTURE_BIT (per unit environment, generation and
// enables), ENABLE_BIT (the enables alone), FOG_BIT, and the fog coordinate under CURRENT_BIT.
struct TexPipeAttrib {
  TexUnitState unit[kMaxTexUnits];
  bool enables[kMaxTexUnits][8] = {}; // the four target enables and four generation enables
  FogState fog;
  bool fog_enabled = false;
  float fog_coord = 0.0f;
  unsigned active_texture = 0;
};

struct ShadeSetup; // fragment/shade.h

struct TexPipeState {
  TexUnitState unit[kMaxTexUnits];
  FogState fog;
  float cur_fog_coord = 0.0f; // CURRENT_FOG_COORD (Table 6.5)

  // ---- derived at draw time (src/state/validate_texpipe.cpp) ----
  TexVertexSetup vertex;             // what the geometry stage computes per vertex
  std::shared_ptr<ShadeSetup> shade; // the fragment stage's setup; allocated on first use
  bool shading = false;              // texturing or fog on: RasterState::shade is set
  int attr_count = 4;                // RasterState::attr_count
  uint64_t seen_generation = 0;      // SharedObjects::texture_generation at the last setup
  bool any_target_enabled = false;   // some unit has a texture target enabled
};

} // namespace pineda
