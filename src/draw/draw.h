// The draw home: everything between a draw call of the API and the back end. The state layer
// validates its state and hands down one DrawInput per draw (state/draw_call.cpp); the draw
// home keeps the per-draw setup across draws (the draw cache), transforms the vertices a slice
// at a time on the worker threads (geometry/transform.h), draws them once per draw buffer
// (GL 2.1 §4.2.1, draw_buffers.h), chooses how the back end shares the primitives among the
// threads (raster/schedule.h), and in SELECT and FEEDBACK mode turns them into selection hits
// or feedback values (feedback.cpp). It never sees the Context.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/raster_state.h"
#include "core/vertex.h"
#include "framebuffer/framebuffer.h"
#include "geometry/input_vertex.h"
#include "geometry/light_eval.h"
#include "geometry/texcoord.h"
#include "geometry/vertex_program.h"
#include "raster/workers.h"

namespace pineda {

// Where the primitives of a draw go in SELECT or FEEDBACK mode (GL 2.1 §5.2, §5.3) instead of
// the framebuffer: the state layer's selection and feedback state (state/select.cpp), handed
// down with the draw. The draw home reports what survived clipping and culling.
class RenderRecords {
public:
  virtual ~RenderRecords() = default;
  // SELECT mode (hit), else FEEDBACK mode (value, vertex).
  virtual bool selecting() const = 0;
  // Feedback of the types with texture coordinates (3D_COLOR_TEXTURE, 4D_COLOR_TEXTURE).
  virtual bool textured() const = 0;
  // Selection: one primitive hit, with these window z extremes (§5.2).
  virtual void hit(float zmin, float zmax) = 0;
  // Feedback: one value (a token or a count).
  virtual void value(float v) = 0;
  // Feedback: one vertex of the feedback type (Table 5.2).
  virtual void vertex(const float win[3], float clip_w, const float color[4],
                      const float tex[4]) = 0;
};

// The derived state the draws read and where they go, as the state layer keeps them: their
// addresses do not change for the life of the context, so the state layer sets them once.
struct DrawSources {
  const RasterState* raster = nullptr;
  const uint64_t* raster_serial = nullptr; // advanced with every change of *raster
  const glm::mat4* mvp = nullptr;
  const glm::mat4* modelview = nullptr; // distance attenuation of points
  const LightSetup* light = nullptr;
  const TexVertexSetup* tex = nullptr;
  Framebuffer* fb = nullptr;
  RasterWorkers* workers = nullptr;
  // Where an active occlusion query counts (RasterState::count_samples, §4.1.7).
  uint64_t* samples_passed = nullptr;
};

// One draw as the state layer hands it down: the vertices and what changes from one draw to
// the next (the state it reads is validated).
struct DrawInput {
  GLenum mode = GL_POINTS;
  const InputVertex* in = nullptr;
  size_t n = 0;                      // vertices in `in`
  const uint32_t* indices = nullptr; // optional: `count` indices into `in`
  size_t count = 0;
  bool lit = false;                   // lighting on (§2.14.1)
  bool color_sum = false;             // the colour sum applies (§3.9)
  const Material* material = nullptr; // the current materials, [0] front, [1] back
  // Material calls between Begin and End (§2.14.2): from vertex changes[i].vertex on.
  const MaterialChange* changes = nullptr;
  size_t change_count = 0;
  // SELECT or FEEDBACK mode: the records instead of the framebuffer.
  RenderRecords* records = nullptr;
  // Feedback of texture coordinates reports unit 0's through its texture matrix (§2.11.4).
  const glm::mat4* texture0 = nullptr;
  // A vertex shader runs in place of the fixed-function transform and lighting (§2.20).
  const VertexProgram* vertex_program = nullptr;
  // Feedback with a vertex shader reports gl_FrontColor and gl_TexCoord[0]; where the shader
  // does not write them, these values (the current colour and coordinates, as Mesa reports).
  const float* feedback_color = nullptr;
  const float* feedback_tex = nullptr;
};

struct DrawCache; // draw_cache.h

// What the draw home keeps across the draws of one context.
struct DrawContext {
  DrawContext();
  ~DrawContext();
  DrawContext(const DrawContext&) = delete;
  DrawContext& operator=(const DrawContext&) = delete;
  DrawSources src;
  std::unique_ptr<DrawCache> cache;
  std::vector<PVertex> verts; // the processed vertices, reused so the hot path does not allocate
};

// Transforms the vertices of `in` and draws them in in.mode (into every draw buffer of
// dc.src.fb, or into in.records).
void draw_vertices(DrawContext& dc, const DrawInput& in);

} // namespace pineda
