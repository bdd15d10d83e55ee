// The accumulation buffer (GL 2.1 §4.2.4): glAccum with ACCUM, LOAD, RETURN, MULT and ADD,
// glClearAccum and glClear(GL_ACCUM_BUFFER_BIT), with the scissor test (§4.2.3) and the
// colour mask (§4.2.2) applying. Every scene loads or clears the accumulation buffer before
// using it, so each repetition starts from the same contents.
#include "scene_util.h"

#include <cmath>

using namespace scenes;

namespace {

// The state this file touches, at its GL defaults (reset_state() does not know it).
void accum_defaults() {
  glDisable(GL_SCISSOR_TEST);
  glClearAccum(0.0f, 0.0f, 0.0f, 0.0f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

// A smooth-shaded star-like fan centred at (cx, cy), rotated by `angle`.
void fan(float cx, float cy, float radius, float angle, int colour) {
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1.0f, 1.0f, 1.0f);
  glVertex2f(cx, cy);
  for (int i = 0; i <= 10; ++i) {
    const float a = angle + static_cast<float>(i) * 2.0f * kPi / 10.0f;
    const float r = (i & 1) ? radius * 0.45f : radius;
    palette_color(colour + i);
    glVertex2f(snap(cx + r * std::cos(a)), snap(cy + r * std::sin(a)));
  }
  glEnd();
}

// A diagonal gradient over the whole window.
void gradient(const Frame& frame) {
  const float w = static_cast<float>(frame.width), h = static_cast<float>(frame.height);
  glBegin(GL_QUADS);
  glColor4f(0.9f, 0.1f, 0.2f, 1.0f);
  glVertex2f(0, 0);
  glColor4f(0.2f, 0.8f, 0.1f, 0.5f);
  glVertex2f(w, 0);
  glColor4f(0.1f, 0.3f, 0.9f, 0.25f);
  glVertex2f(w, h);
  glColor4f(0.7f, 0.7f, 0.6f, 0.75f);
  glVertex2f(0, h);
  glEnd();
}

} // namespace

PINEDA_SCENE(accum_motion_blur,
             "Motion blur: 6 frames of a moving fan, LOAD then ACCUM 1/6, RETURN",
             .accum_bits = 16) {
  accum_defaults();
  window_projection(frame);
  const int frames = 6;
  for (int i = 0; i < frames; ++i) {
    clear_frame(0.05f, 0.05f, 0.1f);
    const float t = static_cast<float>(i) / frames;
    fan(60.0f + 130.0f * t, 80.0f + 90.0f * t * t, 50.0f, 1.2f * t, 3);
    fan(200.0f - 40.0f * t, 200.0f - 150.0f * t, 30.0f, -2.0f * t, 9);
    glAccum(i == 0 ? GL_LOAD : GL_ACCUM, 1.0f / frames);
  }
  glAccum(GL_RETURN, 1.0f);
}

PINEDA_SCENE(accum_mult_add_return,
             "ACCUM, MULT, ADD (also negative) and RETURN with scales above and below 1",
             .accum_bits = 16) {
  accum_defaults();
  window_projection(frame);
  clear_frame(0, 0, 0);
  gradient(frame);
  glAccum(GL_LOAD, 0.8f);
  clear_frame(0.2f, 0.1f, 0.4f, 0.6f);
  fan(128.0f, 128.0f, 110.0f, 0.3f, 0);
  glAccum(GL_ACCUM, 0.5f);
  glAccum(GL_MULT, 0.75f);
  glAccum(GL_ADD, 0.05f);
  // Four vertical bands: different RETURN scales, a negative ADD in between.
  glEnable(GL_SCISSOR_TEST);
  const int band = frame.width / 4;
  const float scales[4] = {0.5f, 1.0f, 1.5f, 3.0f};
  for (int b = 0; b < 4; ++b) {
    glScissor(b * band, 0, band, frame.height);
    if (b == 2) glAccum(GL_ADD, -0.1f);
    glAccum(GL_RETURN, scales[b]);
  }
  accum_defaults();
}

PINEDA_SCENE(accum_clear_scissor_mask,
             "glClearAccum values inside scissor boxes, ACCUM of negative weight, RETURN through "
             "colour masks",
             .accum_bits = 16) {
  accum_defaults();
  window_projection(frame);
  glClearAccum(0.25f, 0.5f, 0.75f, 1.0f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  const float values[4] = {-0.5f, 0.1f, 0.3f, 0.9f};
  for (int i = 0; i < 4; ++i) {
    glScissor(20 + 50 * i, 30 + 20 * i, 60, 120);
    glClearAccum(values[i], values[3 - i], 0.6f, 0.5f);
    glClear(GL_ACCUM_BUFFER_BIT);
  }
  glDisable(GL_SCISSOR_TEST);
  clear_frame(0, 0, 0);
  fan(128.0f, 128.0f, 90.0f, 0.0f, 5);
  glAccum(GL_ACCUM, -0.3f);
  clear_frame(0.1f, 0.1f, 0.1f);
  // Left half writes red and blue only, right half everything.
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, frame.width / 2, frame.height);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glAccum(GL_RETURN, 1.0f);
  glScissor(frame.width / 2, 0, frame.width - frame.width / 2, frame.height);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glAccum(GL_RETURN, 1.25f);
  accum_defaults();
}
