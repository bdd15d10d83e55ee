// Fixed-function lighting state (GL 2.1 §2.14.1-§2.14.4, Table 2.10 defaults, state tables
// 6.11-6.13) and the per-draw constants validate.cpp derives from it for the per-vertex
// evaluation in geometry/light_eval.cpp.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <vector>
#include "core/limits.h"

namespace pineda {

// Material parameters of one face (GL 2.1 Table 2.10).
struct Material {
  float ambient[4] = {0.2f, 0.2f, 0.2f, 1.0f};
  float diffuse[4] = {0.8f, 0.8f, 0.8f, 1.0f};
  float specular[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  float emission[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  float shininess = 0.0f;
  float color_indexes[3] = {0.0f, 1.0f, 1.0f}; // am, dm, sm: stored for queries only
};

// One light source. Position and spot direction are kept in eye coordinates: GL 2.1 §2.14.2
// transforms them by the model-view matrix current when they are specified.
struct Light {
  float ambient[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  float diffuse[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  float specular[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  float position[4] = {0.0f, 0.0f, 1.0f, 0.0f};
  float spot_direction[3] = {0.0f, 0.0f, -1.0f};
  float spot_exponent = 0.0f;
  float spot_cutoff = 180.0f;
  float attenuation[3] = {1.0f, 0.0f, 0.0f}; // constant, linear, quadratic
  bool enabled = false;
};

// A Material call between Begin and End (GL 2.1 §2.14.2): from vertex `vertex` of the
// primitive on, both faces' materials are `material`.
struct MaterialChange {
  size_t vertex = 0;
  Material material[2];
};

// Per-draw constants of one enabled light, in eye coordinates.
struct LightConstants {
  float ambient[3] = {}, diffuse[3] = {}, specular[3] = {};
  bool positional = false;
  float position[3] = {};       // positional: the light's eye position
  float direction[3] = {};      // directional: VPpli, the unit vector towards the light
  float half[3] = {};           // directional with an infinite viewer: the unit half vector
  bool spot = false;            // cutoff != 180
  float spot_direction[3] = {}; // unit spot direction
  float spot_cos = 0.0f;        // cos(cutoff)
  float spot_exponent = 0.0f;
  float spot_factor = 1.0f; // directional spot lights: the spot term is constant
  bool attenuated = false;  // positional with attenuation other than (1, 0, 0)
  float k[3] = {1.0f, 0.0f, 0.0f};
};

// Everything the per-vertex evaluation reads, derived once per draw.
struct LightSetup {
  int count = 0;
  LightConstants light[kMaxLights];
  float scene_ambient[4] = {};
  bool local_viewer = false;
  bool two_side = false;
  bool separate_specular = false;
  // COLOR_MATERIAL: which properties of which faces take the vertex colour.
  bool track[2] = {false, false}; // front, back
  bool track_ambient = false, track_diffuse = false, track_specular = false, track_emission = false;
  // Normal transformation (GL 2.1 §2.11.3): inverse transpose of the model-view's upper 3x3,
  // column-major, with the rescale factor folded in.
  float normal_matrix[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  bool normalize = false;
  float modelview[16] = {}; // column-major, for eye-space vertex positions
  bool need_eye_position = false;
};

struct LightingState {
  bool enabled = false; // GL_LIGHTING
  Light light[kMaxLights];
  Material material[2]; // [0] front, [1] back
  float model_ambient[4] = {0.2f, 0.2f, 0.2f, 1.0f};
  bool local_viewer = false;
  bool two_side = false;
  GLenum color_control = GL_SINGLE_COLOR;
  bool color_material = false;
  GLenum color_material_face = GL_FRONT_AND_BACK;
  GLenum color_material_mode = GL_AMBIENT_AND_DIFFUSE;
  // COLOR_SUM (GL 2.1 §3.9). Kept with lighting because transform.cpp folds the colour sum
  // into the vertex colours together with the lit secondary colour.
  bool color_sum = false;

  // Material calls between Begin and End: the materials at Begin and every change since,
  // applied per vertex by the draw that End issues.
  Material begin_material[2];
  std::vector<MaterialChange> imm_changes;

  LightSetup setup; // derived (validate.cpp)

  LightingState() {
    // Table 2.10: light 0 has white diffuse and specular intensities, the others black.
    for (int c = 0; c < 4; ++c)
      light[0].diffuse[c] = light[0].specular[c] = 1.0f;
  }
};

struct Context;

// GL 2.1 §2.14.3: with COLOR_MATERIAL enabled, copy the current colour into the tracked
// material properties (lighting.cpp). Called on Color, ColorMaterial and Enable.
void update_color_material(Context* ctx);

} // namespace pineda
