// Polygon rasterization ties (GL 2.1 §3.5.1): fragment centres exactly on shared edges must be
// produced by exactly one of the two polygons. These scenes put edges through pixel centres on
// purpose and draw with additive blending in four dim colours, so a centre hit twice shows as a
// mixed brighter colour, a centre hit by neither as black, and the owner's colour shows which
// side won. GL lets the implementation pick the owner; llvmpipe, the reference, includes centres
// on left edges and on bottom edges (GL window coordinates, y up), i.e. the "top-left" rule of a
// y-down framebuffer. softpipe uses the opposite convention, so it disagrees on every tie.
//
// All coordinates are in the full 256x256 window with the default pixel projection, where
// half-integers land exactly on pixel centres.
#include "scene_util.h"

#include <cmath>
#include <vector>

using namespace scenes;

namespace {

const char* const kTieWhy =
    "ties are the point of the scene and llvmpipe is the reference for them; softpipe breaks "
    "ties the other way (right/top edges), so llvmpipe vs softpipe differs by design";

// Additive blending of quarter-intensity colours (exact in 8 bits: 0.25 -> 64).
void additive() {
  clear_frame(0.0f, 0.0f, 0.0f, 0.0f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
}

void quarter_color(int i) {
  static const float colours[4][3] = {{0.25f, 0.0f, 0.0f}, {0.0f, 0.25f, 0.0f},
                                      {0.0f, 0.0f, 0.25f}, {0.25f, 0.25f, 0.0f}};
  const float* c = colours[i & 3];
  glColor4f(c[0], c[1], c[2], 0.25f);
}

void tri(float ax, float ay, float bx, float by, float cx, float cy, int colour) {
  quarter_color(colour);
  glVertex2f(ax, ay);
  glVertex2f(bx, by);
  glVertex2f(cx, cy);
}

// A fan around (cx, cy) with `n` rim vertices on a square of half-size r (so rim vertices stay on
// the same lattice as the centre when r and the centre are lattice values).
void square_fan(float cx, float cy, float r, int n, int colour) {
  std::vector<float> rim;
  for (int i = 0; i < n; ++i) {
    const float t = 8.0f * static_cast<float>(i) / static_cast<float>(n); // 0..8 around the square
    float x, y;
    if (t < 2.0f) { x = -r + r * t; y = -r; }
    else if (t < 4.0f) { x = r; y = -r + r * (t - 2.0f); }
    else if (t < 6.0f) { x = r - r * (t - 4.0f); y = r; }
    else { x = -r; y = r - r * (t - 6.0f); }
    rim.push_back(cx + x);
    rim.push_back(cy + y);
  }
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    tri(cx, cy, rim[2 * i], rim[2 * i + 1], rim[2 * j], rim[2 * j + 1], colour + i);
  }
  glEnd();
}

} // namespace

PINEDA_SCENE(fill_ties, "Shared edges through pixel centres: horizontal, vertical, diagonal, steep, shallow",
             .why = kTieWhy) {
  additive();
  // A 4 x 4 grid of 64-pixel cells: the column picks the pattern, the row the lattice its
  // vertices sit on: pixel centres, pixel corners, or centres in x or y only.
  for (int cell = 0; cell < 16; ++cell) {
    const int row = cell / 4;
    const float x0 = 64.0f * (cell % 4) + 8.0f + (row == 0 || row == 2 ? 0.5f : 0.0f);
    const float y0 = 64.0f * row + 8.0f + (row == 0 || row == 3 ? 0.5f : 0.0f), s = 46.0f;
    glBegin(GL_TRIANGLES);
    switch (cell % 4) {
    case 0: // a square cut by both diagonals into four triangles
      tri(x0, y0, x0 + s, y0, x0 + s / 2, y0 + s / 2, cell);
      tri(x0 + s, y0, x0 + s, y0 + s, x0 + s / 2, y0 + s / 2, cell + 1);
      tri(x0 + s, y0 + s, x0, y0 + s, x0 + s / 2, y0 + s / 2, cell + 2);
      tri(x0, y0 + s, x0, y0, x0 + s / 2, y0 + s / 2, cell + 3);
      break;
    case 1: // vertical and horizontal shared edges: a 3 x 3 grid of split squares
      for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
          const float a = x0 + 15.0f * i, b = y0 + 15.0f * j, d = 15.0f;
          tri(a, b, a + d, b, a, b + d, i + j);
          tri(a + d, b, a + d, b + d, a, b + d, i + j + 1);
        }
      }
      break;
    case 2: // steep (slope 3) and shallow (slope 1/3) shared edges
      tri(x0, y0, x0 + 15.0f, y0 + s - 1.0f, x0, y0 + s - 1.0f, cell);
      tri(x0, y0, x0 + 15.0f, y0, x0 + 15.0f, y0 + s - 1.0f, cell + 1);
      tri(x0 + 15.0f, y0, x0 + s, y0, x0 + s, y0 + 10.0f, cell + 2);
      tri(x0 + 15.0f, y0, x0 + s, y0 + 10.0f, x0 + 15.0f, y0 + s - 1.0f, cell + 3);
      tri(x0 + s, y0 + 10.0f, x0 + s, y0 + s - 1.0f, x0 + 15.0f, y0 + s - 1.0f, cell);
      break;
    default: // both windings: the same split square, second pair clockwise
      tri(x0, y0, x0 + s, y0 + s / 3, x0 + s / 3, y0 + s, cell);
      tri(x0 + s, y0 + s / 3, x0 + s, y0 + s, x0 + s / 3, y0 + s, cell + 1);
      tri(x0, y0, x0 + s / 3, y0 + s, x0, y0 + s, cell + 2);
      tri(x0, y0, x0 + s, y0, x0 + s, y0 + s / 3, cell + 3);
      break;
    }
    glEnd();
  }
  glDisable(GL_BLEND);
}

PINEDA_SCENE(fill_fans, "Fans whose centres sit on pixel centres, pixel corners and edge midpoints",
             .why = kTieWhy) {
  additive();
  // Three rows: centres at (k + 0.5, k + 0.5), at integers (a pixel corner: four pixels share
  // it), and at (k + 0.5, k): each row with 4, 8, 12, 16 and 24 slices.
  const int slices[5] = {4, 8, 12, 16, 24};
  for (int row = 0; row < 3; ++row) {
    for (int k = 0; k < 5; ++k) {
      const float cx = 26.0f + 50.0f * k + (row != 1 ? 0.5f : 0.0f);
      const float cy = 40.0f + 80.0f * row + (row == 0 ? 0.5f : 0.0f);
      square_fan(cx, cy, 20.0f, slices[k], row + k);
      // A tiny fan in the corner of each: every slice is smaller than a pixel.
      square_fan(cx + 21.5f, cy + 28.0f, 2.0f, slices[k], row);
    }
  }
  glDisable(GL_BLEND);
}

PINEDA_SCENE(fill_subpixel_steps, "The same triangles shifted by n/16 pixel, n = 0..15, one cell each",
             .why = kTieWhy) {
  additive();
  for (int n = 0; n < 16; ++n) {
    glLoadIdentity();
    // Translations are multiples of 1/16 plus whole pixels: exact in float.
    glTranslatef(64.0f * (n % 4) + static_cast<float>(n) / 16.0f,
                 64.0f * (n / 4) + static_cast<float>((n * 5) % 16) / 16.0f, 0.0f);
    glBegin(GL_TRIANGLES);
    // A pair sharing a diagonal, plus a thin pair sharing a long near-horizontal edge.
    tri(4.5f, 4.5f, 40.5f, 10.5f, 10.5f, 40.5f, 0);
    tri(40.5f, 10.5f, 44.5f, 44.5f, 10.5f, 40.5f, 1);
    tri(4.0f, 50.0f, 60.0f, 51.5f, 30.25f, 57.0f, 2);
    tri(4.0f, 50.0f, 30.25f, 46.0f, 60.0f, 51.5f, 3);
    tri(50.0f, 4.0f, 59.5f, 4.0f, 55.0f, 44.0f, 0);
    glEnd();
  }
  glLoadIdentity();
  glDisable(GL_BLEND);
}
