// Fixed-function lighting state (GL 2.1 §2.14.1-§2.14.4, §2.14.7; Tables 6.9-6.11 "Lighting",
// the "lighting" attribute group; Table 2.10 the defaults). Commands in lighting.cpp and
// polygon.cpp (ShadeModel); the per-draw constants the geometry stage evaluates
// (geometry/light_eval.h) are derived from it by the lighting area's validation.
#pragma once

#include <GL/gl.h>

#include <glm/mat4x4.hpp>

#include "core/limits.h"
#include "geometry/light_eval.h"

namespace pineda {

struct Context;
struct StateArea;

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
  bool enabled = false;                      // LIGHTi ("lighting/enable")
};

// LIGHTING_BIT: Tables 6.9-6.11 (LIGHTING, COLOR_MATERIAL and the lights' enables are also
// "enable").
struct LightingGroup {
  bool enabled = false; // LIGHTING
  Light light[kMaxLights];
  Material material[2]; // [0] front, [1] back
  float model_ambient[4] = {0.2f, 0.2f, 0.2f, 1.0f};
  bool local_viewer = false;
  bool two_side = false;
  GLenum color_control = GL_SINGLE_COLOR;
  bool color_material = false;
  GLenum color_material_face = GL_FRONT_AND_BACK;
  GLenum color_material_mode = GL_AMBIENT_AND_DIFFUSE;
  GLenum shade_model = GL_SMOOTH; // §2.14.7

  LightingGroup() {
    // Table 2.10: light 0 has white diffuse and specular intensities, the others black.
    for (int c = 0; c < 4; ++c)
      light[0].diffuse[c] = light[0].specular[c] = 1.0f;
  }
};

// GL 2.1 §2.14.3: with COLOR_MATERIAL enabled, copy the current colour into the tracked
// material properties. Called on Color, ColorMaterial and Enable.
void update_color_material(Context* ctx);

// The per-draw constants of the lighting equation (geometry/light_eval.h) from the lighting
// group, the model-view matrix and the normal processing of the transform group (NORMALIZE,
// RESCALE_NORMAL): the lighting area's derived state.
void setup_lighting(LightSetup& s, const LightingGroup& ls, const glm::mat4& modelview,
                    bool normalize, bool rescale);

extern const StateArea kLightingArea; // lighting.cpp

} // namespace pineda
