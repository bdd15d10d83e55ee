// Occlusion queries (GL 2.1 §4.1.7): the count of samples that pass the depth and stencil
// tests, made visible. Objects are drawn behind, in front of and half behind an occluder
// inside SAMPLES_PASSED queries; a marker next to each then shows the count as its grey level
// (count / area), green when the object was visible at all and red when it was hidden, so a
// wrong count changes the image.
#include "scene_util.h"

using namespace scenes;

namespace {

struct QueryFns {
  PFNGLGENQUERIESPROC gen = proc<PFNGLGENQUERIESPROC>("glGenQueries");
  PFNGLDELETEQUERIESPROC del = proc<PFNGLDELETEQUERIESPROC>("glDeleteQueries");
  PFNGLBEGINQUERYPROC begin = proc<PFNGLBEGINQUERYPROC>("glBeginQuery");
  PFNGLENDQUERYPROC end = proc<PFNGLENDQUERYPROC>("glEndQuery");
  PFNGLGETQUERYOBJECTUIVPROC result = proc<PFNGLGETQUERYOBJECTUIVPROC>("glGetQueryObjectuiv");
};

// Window depth of object z under glOrtho(..., -1, 1) is (1 - z) / 2: z = 0.5 is near (0.25).
void rect(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y1, z);
  glEnd();
}

// The marker for a count out of `area`: grey level count / area in the red or green channel.
void marker(float x, float y, GLuint count, float area) {
  const float level = static_cast<float>(count) / area;
  if (count > 0)
    glColor3f(0.2f * level, 0.3f + 0.7f * level, 0.2f * level);
  else
    glColor3f(0.9f, 0.1f, 0.1f);
  rect(x, y, x + 20.0f, y + 20.0f, 0.9f);
}

} // namespace

PINEDA_SCENE(query_occlusion, "SAMPLES_PASSED counts of objects behind, beside and in front of "
                              "an occluder, shown as marker colours") {
  const QueryFns q;
  window_projection(frame);
  clear_frame(0.1f, 0.1f, 0.15f);
  glEnable(GL_DEPTH_TEST);
  // The occluder: a wall over the middle band at window depth 0.4.
  glColor3f(0.5f, 0.5f, 0.55f);
  rect(70.0f, 0.0f, 170.0f, 256.0f, 0.2f);
  GLuint ids[6];
  q.gen(6, ids);
  // Objects at x offsets relative to the wall, some nearer (z 0.5), some farther (z -0.5).
  struct Obj {
    float x0, y0, w, h, z;
    int colour;
  };
  // Corners a quarter pixel off the pixel grid: no edge passes through a pixel centre.
  const Obj objs[6] = {
      {80.25f, 10.25f, 40.0f, 30.0f, -0.5f, 1},   // fully behind the wall
      {40.25f, 50.25f, 60.0f, 30.0f, -0.5f, 2},   // half behind
      {90.25f, 90.25f, 50.0f, 25.0f, 0.5f, 3},    // in front
      {150.25f, 130.25f, 40.0f, 35.0f, -0.5f, 4}, // partly behind on the right edge
      {10.25f, 180.25f, 30.0f, 30.0f, -0.5f, 5},  // beside the wall
      {100.25f, 200.75f, 7.5f, 9.25f, 0.1f, 6},   // small, behind
  };
  for (int i = 0; i < 6; ++i) {
    const Obj& o = objs[i];
    q.begin(GL_SAMPLES_PASSED, ids[i]);
    palette_color(o.colour);
    rect(o.x0, o.y0, o.x0 + o.w, o.y0 + o.h, o.z);
    q.end(GL_SAMPLES_PASSED);
  }
  glDisable(GL_DEPTH_TEST);
  for (int i = 0; i < 6; ++i) {
    GLuint count = 0;
    q.result(ids[i], GL_QUERY_RESULT, &count);
    marker(220.0f, 10.0f + 40.0f * static_cast<float>(i), count, objs[i].w * objs[i].h);
  }
  q.del(6, ids);
}

PINEDA_SCENE(query_conditional_draw,
             "Draw only what a query saw: stencil-masked and colour-masked query passes",
             .stencil_bits = 8) {
  const QueryFns q;
  window_projection(frame);
  clear_frame(0.0f, 0.0f, 0.0f);
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  // Stencil 1 inside a diagonal band.
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glBegin(GL_TRIANGLES);
  glVertex2f(0.1f, 40.3f);
  glVertex2f(216.2f, 256.4f);
  glVertex2f(0.1f, 120.6f);
  glEnd();
  // Query, without writing colour, which of a grid of cells touch the band.
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  GLuint ids[64];
  q.gen(64, ids);
  for (int i = 0; i < 64; ++i) {
    const float x = 8.0f + 30.0f * static_cast<float>(i % 8);
    const float y = 8.0f + 30.0f * static_cast<float>(i / 8);
    q.begin(GL_SAMPLES_PASSED, ids[i]);
    rect(x, y, x + 26.0f, y + 26.0f, 0.0f);
    q.end(GL_SAMPLES_PASSED);
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_STENCIL_TEST);
  // Draw the cells with their coverage as brightness; untouched cells stay dark blue.
  for (int i = 0; i < 64; ++i) {
    GLuint count = 0;
    q.result(ids[i], GL_QUERY_RESULT, &count);
    const float x = 8.0f + 30.0f * static_cast<float>(i % 8);
    const float y = 8.0f + 30.0f * static_cast<float>(i / 8);
    const float level = static_cast<float>(count) / (26.0f * 26.0f);
    if (count > 0)
      glColor3f(level, 0.5f + 0.5f * level, 1.0f - level);
    else
      glColor3f(0.0f, 0.0f, 0.3f);
    rect(x, y, x + 26.0f, y + 26.0f, 0.0f);
  }
  q.del(64, ids);
  glStencilFunc(GL_ALWAYS, 0, 0xffffffffu);
}
