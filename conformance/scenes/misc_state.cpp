// State without rendering effect in an RGBA GL with no multisample buffer: colour-index state
// (GL 2.1 §2.7, §4.2.2-§4.2.3: glIndex*, glIndexMask, glClearIndex, an enabled INDEX_ARRAY) and
// multisample state (§3.2.1, §4.1.3: SAMPLE_ALPHA_TO_COVERAGE, SAMPLE_ALPHA_TO_ONE,
// SAMPLE_COVERAGE with a zero coverage value). Both scenes must look exactly as if the state
// had never been touched. Each scene puts the state back to the GL defaults at the end.
#include "scene_util.h"

using namespace scenes;

namespace {

// Smooth-shaded translucent triangles over a strip, drawn immediately and from arrays.
void translucent_fan(const Frame& frame) {
  window_projection(frame);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  const float w = float(frame.width), h = float(frame.height);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 12; ++i) {
    const float x = w * (0.05f + 0.075f * float(i));
    palette_color(i, 0.3f + 0.05f * float(i));
    glVertex2f(x, h * 0.1f);
    palette_color(i + 3, 0.9f);
    glVertex2f(x + w * 0.2f, h * 0.2f + h * 0.05f * float(i % 4));
    palette_color(i + 5, 0.1f);
    glVertex2f(x + w * 0.05f, h * 0.9f);
  }
  glEnd();
  const float quad[8] = {w * 0.2f,  h * 0.4f, w * 0.8f,  h * 0.45f,
                         w * 0.75f, h * 0.7f, w * 0.25f, h * 0.65f};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, quad);
  glColor4f(0.2f, 0.9f, 0.4f, 0.5f);
  glDrawArrays(GL_QUADS, 0, 4);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ZERO);
}

} // namespace

PINEDA_SCENE(
    misc_color_index_state,
    "Colour-index state (Index, IndexMask, ClearIndex, INDEX_ARRAY) changes nothing in RGBA") {
  glIndexMask(0);
  glClearIndex(3.0f);
  glIndexi(7);
  static const GLint indices[4] = {1, 2, 3, 4};
  glIndexPointer(GL_INT, 0, indices);
  glEnableClientState(GL_INDEX_ARRAY);
  clear_frame(0.25f, 0.25f, 0.3f);
  glBegin(GL_POINTS);
  glIndexf(2.5f);
  glEnd();
  translucent_fan(frame);
  glDisableClientState(GL_INDEX_ARRAY);
  glIndexPointer(GL_FLOAT, 0, nullptr);
  glIndexMask(~0u);
  glClearIndex(0.0f);
  glIndexi(1);
}

PINEDA_SCENE(misc_multisample_state,
             "Multisample enables and zero sample coverage change nothing without sample buffers") {
  const auto sample_coverage = proc<PFNGLSAMPLECOVERAGEPROC>("glSampleCoverage");
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  glEnable(GL_SAMPLE_COVERAGE);
  sample_coverage(0.0f, GL_FALSE);
  clear_frame(0.1f, 0.15f, 0.2f);
  translucent_fan(frame);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glDisable(GL_SAMPLE_ALPHA_TO_ONE);
  glDisable(GL_SAMPLE_COVERAGE);
  sample_coverage(1.0f, GL_FALSE);
}
