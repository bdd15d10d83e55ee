// Texture units (GL 2.1 §2.7 ActiveTexture; Tables 6.15-6.19 "Texturing", the "texture"
// attribute group): per unit the target enables (§3.8.15), coordinate generation (§2.11.4) and
// the texture environment (§3.8.13). Commands in texenv.cpp. Texture objects and their
// bindings, which TEXTURE_BIT also saves, are the texture objects' (texture_object.h).
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <memory>

#include "core/limits.h"
#include "geometry/texcoord.h"

namespace pineda {

struct StateArea;
struct ShadeSetup; // fragment/shade.h

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
};

struct TexUnit {
  // TEXTURE_1D, TEXTURE_2D, TEXTURE_3D, TEXTURE_CUBE_MAP enables (§3.8.15; "texture/enable").
  bool enable_1d = false, enable_2d = false, enable_3d = false, enable_cube = false;
  bool gen_enabled[4] = {false, false, false, false}; // TEXTURE_GEN_S, T, R, Q
  TexGenCoord gen[4];
  TexEnv env;
  TexUnit() {
    // §2.11.4: the S plane defaults to (1,0,0,0), T to (0,1,0,0), R and Q to zero.
    gen[0].object_plane[0] = gen[0].eye_plane[0] = 1.0f;
    gen[1].object_plane[1] = gen[1].eye_plane[1] = 1.0f;
  }
};

// TEXTURE_BIT: Tables 6.15-6.19 but the bindings and the objects' state.
struct TextureGroup {
  GLuint active = 0; // ACTIVE_TEXTURE - TEXTURE0, below kMaxActiveTexture
  TexUnit unit[kMaxTexUnits];
  // TEXTURE_FILTER_CONTROL's TEXTURE_LOD_BIAS (§3.8.8) of each texture image unit.
  float lod_bias[kMaxCombinedTextureImageUnits] = {};
};

// Derived at draw time from the texture units, the objects they use, fog and lighting (the
// texture area's validation, validate_texpipe.cpp).
struct TexPipeDerived {
  TexVertexSetup vertex;             // what the geometry stage computes per vertex
  std::shared_ptr<ShadeSetup> shade; // the fragment stage's setup; allocated on first use
  bool shading = false;              // texturing or fog on: RasterState::shade is set
  int attr_count = 4;                // RasterState::attr_count
  uint64_t seen_generation = 0;      // SharedObjects::texture_generation at the last setup
  bool any_target_enabled = false;   // some unit has a texture target enabled
};

struct Context;

// The texture area's derived state (TexPipeDerived) from the units, the objects they use, fog
// and lighting (validate_texpipe.cpp); the `dirty` bits say what changed.
void validate_texpipe(Context& ctx, uint32_t dirty);

extern const StateArea kTextureEnvArea; // texenv.cpp

} // namespace pineda
