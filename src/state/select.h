// Selection and feedback (GL 2.1 §5.2, §5.3; Table 6.31) and occlusion queries (§4.1.7,
// §6.1.12): the context state, and the functions other parts of Pineda call (the draw path,
// the pixel paths, glClear).
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <unordered_map>

#include "core/vertex.h"
#include "draw/draw.h"
#include "core/limits.h"

namespace pineda {

struct Context;

// RENDER_MODE and the selection and feedback state of GL 2.1 Table 6.31 (§5.2, §5.3).
struct RenderModeState {
  GLenum mode = GL_RENDER;

  // ---- selection (§5.2) ----
  GLuint* select_buffer = nullptr;
  GLsizei select_size = 0;
  bool select_buffer_set = false; // glSelectBuffer has been called
  GLuint names[kMaxNameStackDepth] = {};
  int name_depth = 0;
  GLsizei select_count = 0; // values written into the selection array
  GLint hits = 0;           // hit records written
  bool select_overflow = false;
  bool hit = false; // a hit since the last name stack change or RenderMode
  float hit_min_z = 1.0f, hit_max_z = 0.0f;

  // ---- feedback (§5.3) ----
  GLfloat* feedback_buffer = nullptr;
  GLsizei feedback_size = 0;
  GLenum feedback_type = GL_2D;
  bool feedback_buffer_set = false; // glFeedbackBuffer has been called
  GLsizei feedback_count = 0;       // values written into the feedback array
  bool feedback_overflow = false;
};

// One occlusion query object (GL 2.1 §4.1.7).
struct QueryObject {
  bool created = false; // a BeginQuery has made the name a query object (GenQueries only
                        // reserves it)
  uint64_t result = 0;
};

// Occlusion queries: the context's query names and the active SAMPLES_PASSED query.
struct QueryState {
  std::unordered_map<GLuint, QueryObject> objects; // every name in use
  GLuint active = 0;           // CURRENT_QUERY of SAMPLES_PASSED; 0 when none is active
  uint64_t samples_passed = 0; // samples counted since BeginQuery (the fragment stage adds)
};

// ---- for the rest of Pineda ----

// True in RENDER mode; in SELECT and FEEDBACK mode nothing reaches the framebuffer (GL 2.1
// §5.2, §5.3): draws, clears, accumulation and pixel rectangles update no pixel.
bool render_mode_is_render(const Context* ctx);

// The selection or feedback state as the draw home writes into it (draw/draw.h): what the
// state layer hands down with a draw in SELECT or FEEDBACK mode.
class RenderModeRecords final : public RenderRecords {
public:
  explicit RenderModeRecords(RenderModeState& rm) : rm_(rm) {}
  bool selecting() const override { return rm_.mode == GL_SELECT; }
  bool textured() const override {
    return rm_.feedback_type == GL_3D_COLOR_TEXTURE || rm_.feedback_type == GL_4D_COLOR_TEXTURE;
  }
  void hit(float zmin, float zmax) override;
  void value(float v) override;
  void vertex(const float win[3], float clip_w, const float color[4], const float tex[4]) override;

private:
  RenderModeState& rm_;
};

// GL 2.1 §5.3: glBitmap, glDrawPixels and glCopyPixels in FEEDBACK mode with a valid raster
// position write `token` (GL_BITMAP_TOKEN, GL_DRAW_PIXEL_TOKEN or GL_COPY_PIXEL_TOKEN) and the
// current raster position as one vertex of the feedback type: window x, y, z, the raster
// position's clip w, its colour and its unit 0 texture coordinates. Does nothing in other
// modes. The caller checks that the raster position is valid.
void feedback_raster_token(Context* ctx, GLenum token, const float win[4], const float color[4],
                           const float tex[4]);

// GL 2.1 §5.2: a RasterPos (or WindowPos) whose position is valid causes a selection hit at
// window depth `win_z`. Does nothing outside SELECT mode.
void select_raster_hit(Context* ctx, float win_z);

struct StateArea;
extern const StateArea kSelectArea; // select.cpp

// glClear(GL_ACCUM_BUFFER_BIT) (accum.cpp): fill the accumulation buffer, within the scissor
// box when the scissor test is on, with the clear value. No-op without an accumulation buffer.
void accum_clear(Context* ctx);

} // namespace pineda
