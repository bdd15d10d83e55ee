// Small helpers shared by the scenes: a deterministic random generator, panels (sub-viewports
// with their own pixel-unit projection) and a colour palette. Only GL 1.1 calls.
#pragma once

#include "scene.h"

#include <cstdint>

namespace scenes {

// xorshift32: the same seed gives the same sequence on every run and every machine, so scenes
// are deterministic without any time-based input.
class Rng {
public:
  explicit Rng(std::uint32_t seed) : state_(seed ? seed : 0x9e3779b9u) {}
  std::uint32_t next() {
    state_ ^= state_ << 13;
    state_ ^= state_ >> 17;
    state_ ^= state_ << 5;
    return state_;
  }
  // Uniform in [0, 1): 24 random bits, exactly representable as float.
  float unit() { return static_cast<float>(next() >> 8) * (1.0f / 16777216.0f); }
  float range(float lo, float hi) { return lo + (hi - lo) * unit(); }
  int below(int n) { return static_cast<int>(next() % static_cast<std::uint32_t>(n)); }

private:
  std::uint32_t state_;
};

struct Panel {
  int x, y, w, h; // in window pixels
};

// Cell `index` of a cols x rows grid (index 0 top-left, row-major), separated by `gap` pixels of
// background. Sets the viewport to the cell and the projection to glOrtho(0, w, 0, h, -1, 1), so
// the scene draws in the cell's own pixel units and the viewport clips what leaves the cell
// (GL 2.1 §2.11.1, §2.12).
Panel panel(const Frame& frame, int index, int cols, int rows, int gap = 2);

// Whole-window pixel projection, as reset_state() leaves it: viewport on the whole window,
// glOrtho(0, w, 0, h, -1, 1), identity modelview.
void window_projection(const Frame& frame);

// Clears colour and depth (GL 2.1 §4.2.3) to the given colour and depth 1.
void clear_frame(float r, float g, float b, float a = 1.0f);

// 16 well-separated saturated colours; index taken modulo 16.
const float* palette(int index);
void palette_color(int index, float alpha = 1.0f);

// Rounds v to a multiple of 1/steps. Scenes snap positions to a 1/16-pixel grid where they want
// every rasterizer with at least 4 sub-pixel bits (the GL minimum, GL_SUBPIXEL_BITS) to see the
// very same vertex positions.
float snap(float v, float steps = 16.0f);

constexpr float kPi = 3.14159265358979323846f;

// Justification shared by the scenes that draw lines (or polygons in GL_LINE mode) and so carry
// a looser allowance. llvmpipe follows the diamond-exit rule almost exactly (16 differing pixels
// over 400 random segments in a probe), so a careful implementation stays far below it.
constexpr const char* kLineWhy =
    "GL 2.1 §3.4.1 allows line rasterization to deviate from the diamond-exit rule by one pixel "
    "and by one fragment per segment, so segment ends may legitimately differ";
constexpr double kLineAllowance = 0.5; // Pineda follows the same diamond-exit rule as llvmpipe

} // namespace scenes
