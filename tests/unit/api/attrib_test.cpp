// glPushAttrib / glPopAttrib (GL 2.1 §6.1.14): stack limits and errors, every attribute group
// Pineda has state for, the groups a mask leaves out, and popped state taking effect on drawing.
#include <functional>
#include <initializer_list>
#include <utility>
#include <vector>

#include "api_fixture.h"

namespace {

using Attrib = GLTest;

GLint get_int(GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  return v;
}

// The values of (pname, component count) pairs, through glGetDoublev.
std::vector<double> get(std::initializer_list<std::pair<GLenum, int>> pnames) {
  std::vector<double> out;
  for (const auto& [pname, n] : pnames) {
    GLdouble v[16] = {};
    glGetDoublev(pname, v);
    out.insert(out.end(), v, v + n);
  }
  return out;
}

void append_enabled(std::vector<double>& out, std::initializer_list<GLenum> caps) {
  for (GLenum cap : caps)
    out.push_back(glIsEnabled(cap));
}

// One attribute group: its bit, a change of every state it covers away from the defaults, and
// a read-back of that state.
struct Group {
  const char* name;
  GLbitfield bit;
  std::function<void()> change;
  std::function<std::vector<double>()> query;
};

std::vector<Group> groups() {
  return {
      {"current", GL_CURRENT_BIT,
       [] {
         glColor4f(0.25f, 0.5f, 0.75f, 0.5f);
         glSecondaryColor3f(0.5f, 0.25f, 1.0f);
         glNormal3f(1, 0, 0);
         glTexCoord4f(1, 2, 3, 4);
         glEdgeFlag(GL_FALSE);
       },
       [] {
         return get({{GL_CURRENT_COLOR, 4},
                     {GL_CURRENT_SECONDARY_COLOR, 4},
                     {GL_CURRENT_NORMAL, 3},
                     {GL_CURRENT_TEXTURE_COORDS, 4},
                     {GL_EDGE_FLAG, 1}});
       }},
      {"polygon", GL_POLYGON_BIT,
       [] {
         glEnable(GL_CULL_FACE);
         glCullFace(GL_FRONT);
         glFrontFace(GL_CW);
         glPolygonMode(GL_FRONT, GL_LINE);
         glPolygonMode(GL_BACK, GL_POINT);
       },
       [] {
         auto v = get({{GL_CULL_FACE_MODE, 1}, {GL_FRONT_FACE, 1}, {GL_POLYGON_MODE, 2}});
         append_enabled(v, {GL_CULL_FACE});
         return v;
       }},
      {"lighting", GL_LIGHTING_BIT,
       [] {
         glEnable(GL_LIGHTING);
         glEnable(GL_LIGHT3);
         const GLfloat diffuse[4] = {0.5f, 0.25f, 0.125f, 1.0f};
         glLightfv(GL_LIGHT3, GL_DIFFUSE, diffuse);
         glLightf(GL_LIGHT3, GL_SPOT_CUTOFF, 45.0f);
         glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
         glMaterialfv(GL_BACK, GL_EMISSION, diffuse);
         glLightModelfv(GL_LIGHT_MODEL_AMBIENT, diffuse);
         glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
         glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
         glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
         glColorMaterial(GL_BACK, GL_SPECULAR);
         glEnable(GL_COLOR_MATERIAL);
         glShadeModel(GL_FLAT);
       },
       [] {
         auto v = get({{GL_LIGHT_MODEL_AMBIENT, 4},
                       {GL_LIGHT_MODEL_TWO_SIDE, 1},
                       {GL_LIGHT_MODEL_LOCAL_VIEWER, 1},
                       {GL_LIGHT_MODEL_COLOR_CONTROL, 1},
                       {GL_COLOR_MATERIAL_FACE, 1},
                       {GL_COLOR_MATERIAL_PARAMETER, 1},
                       {GL_SHADE_MODEL, 1}});
         append_enabled(v, {GL_LIGHTING, GL_LIGHT3, GL_COLOR_MATERIAL});
         GLfloat f[4] = {};
         glGetLightfv(GL_LIGHT3, GL_DIFFUSE, f);
         v.insert(v.end(), f, f + 4);
         glGetLightfv(GL_LIGHT3, GL_SPOT_CUTOFF, f);
         v.push_back(f[0]);
         glGetMaterialfv(GL_FRONT, GL_SHININESS, f);
         v.push_back(f[0]);
         glGetMaterialfv(GL_BACK, GL_EMISSION, f);
         v.insert(v.end(), f, f + 4);
         return v;
       }},
      {"depth-buffer", GL_DEPTH_BUFFER_BIT,
       [] {
         glEnable(GL_DEPTH_TEST);
         glDepthFunc(GL_GEQUAL);
         glClearDepth(0.25);
         glDepthMask(GL_FALSE);
       },
       [] {
         auto v = get({{GL_DEPTH_FUNC, 1}, {GL_DEPTH_CLEAR_VALUE, 1}, {GL_DEPTH_WRITEMASK, 1}});
         append_enabled(v, {GL_DEPTH_TEST});
         return v;
       }},
      {"color-buffer", GL_COLOR_BUFFER_BIT,
       [] {
         glEnable(GL_ALPHA_TEST);
         glAlphaFunc(GL_GREATER, 0.5f);
         glEnable(GL_BLEND);
         glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE);
         glBlendEquation(GL_FUNC_SUBTRACT);
         glBlendColor(0.5f, 0.25f, 0.125f, 1.0f);
         glDisable(GL_DITHER);
         glEnable(GL_COLOR_LOGIC_OP);
         glEnable(GL_INDEX_LOGIC_OP);
         glLogicOp(GL_XOR);
         glDrawBuffer(GL_NONE);
         glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
         glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
       },
       [] {
         auto v = get({{GL_ALPHA_TEST_FUNC, 1},
                       {GL_ALPHA_TEST_REF, 1},
                       {GL_BLEND_SRC_RGB, 1},
                       {GL_BLEND_DST_RGB, 1},
                       {GL_BLEND_SRC_ALPHA, 1},
                       {GL_BLEND_DST_ALPHA, 1},
                       {GL_BLEND_EQUATION, 1},
                       {GL_BLEND_COLOR, 4},
                       {GL_LOGIC_OP_MODE, 1},
                       {GL_DRAW_BUFFER, 1},
                       {GL_COLOR_WRITEMASK, 4},
                       {GL_COLOR_CLEAR_VALUE, 4}});
         append_enabled(v,
                        {GL_ALPHA_TEST, GL_BLEND, GL_DITHER, GL_COLOR_LOGIC_OP, GL_INDEX_LOGIC_OP});
         return v;
       }},
      {"stencil-buffer", GL_STENCIL_BUFFER_BIT,
       [] {
         glEnable(GL_STENCIL_TEST);
         glStencilFunc(GL_EQUAL, 3, 0x0f);
         glStencilOp(GL_INCR, GL_DECR, GL_INVERT);
         glClearStencil(5);
         glStencilMask(0x3c);
       },
       [] {
         auto v = get({{GL_STENCIL_FUNC, 1},
                       {GL_STENCIL_REF, 1},
                       {GL_STENCIL_VALUE_MASK, 1},
                       {GL_STENCIL_FAIL, 1},
                       {GL_STENCIL_PASS_DEPTH_FAIL, 1},
                       {GL_STENCIL_PASS_DEPTH_PASS, 1},
                       {GL_STENCIL_CLEAR_VALUE, 1},
                       {GL_STENCIL_WRITEMASK, 1}});
         append_enabled(v, {GL_STENCIL_TEST});
         return v;
       }},
      {"scissor", GL_SCISSOR_BIT,
       [] {
         glEnable(GL_SCISSOR_TEST);
         glScissor(1, 2, 3, 4);
       },
       [] {
         auto v = get({{GL_SCISSOR_BOX, 4}});
         append_enabled(v, {GL_SCISSOR_TEST});
         return v;
       }},
      {"viewport", GL_VIEWPORT_BIT,
       [] {
         glViewport(2, 3, 10, 12);
         glDepthRange(0.25, 0.75);
       },
       [] {
         return get({{GL_VIEWPORT, 4}, {GL_DEPTH_RANGE, 2}});
       }},
      {"transform", GL_TRANSFORM_BIT,
       [] {
         const GLdouble plane[4] = {1, 2, 3, 4};
         glClipPlane(GL_CLIP_PLANE2, plane);
         glEnable(GL_CLIP_PLANE2);
         glEnable(GL_NORMALIZE);
         glEnable(GL_RESCALE_NORMAL);
         glMatrixMode(GL_PROJECTION);
       },
       [] {
         auto v = get({{GL_MATRIX_MODE, 1}});
         append_enabled(v, {GL_CLIP_PLANE2, GL_NORMALIZE, GL_RESCALE_NORMAL});
         GLdouble p[4] = {};
         glGetClipPlane(GL_CLIP_PLANE2, p);
         v.insert(v.end(), p, p + 4);
         return v;
       }},
      {"hint", GL_HINT_BIT,
       [] {
         for (GLenum h : {GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_SMOOTH_HINT, GL_LINE_SMOOTH_HINT,
                          GL_POLYGON_SMOOTH_HINT, GL_FOG_HINT, GL_GENERATE_MIPMAP_HINT,
                          GL_TEXTURE_COMPRESSION_HINT})
           glHint(h, GL_NICEST);
       },
       [] {
         return get({{GL_PERSPECTIVE_CORRECTION_HINT, 1},
                     {GL_POINT_SMOOTH_HINT, 1},
                     {GL_LINE_SMOOTH_HINT, 1},
                     {GL_POLYGON_SMOOTH_HINT, 1},
                     {GL_FOG_HINT, 1},
                     {GL_GENERATE_MIPMAP_HINT, 1},
                     {GL_TEXTURE_COMPRESSION_HINT, 1}});
       }},
      {"pixel", GL_PIXEL_MODE_BIT, [] { glReadBuffer(GL_FRONT_LEFT); },
       [] {
         return get({{GL_READ_BUFFER, 1}});
       }},
      {"fog", GL_FOG_BIT, [] { glEnable(GL_COLOR_SUM); },
       [] {
         std::vector<double> v;
         append_enabled(v, {GL_COLOR_SUM});
         return v;
       }},
      {"enable", GL_ENABLE_BIT,
       [] {
         for (GLenum cap : {GL_CLIP_PLANE0, GL_CLIP_PLANE5, GL_LIGHT0, GL_LIGHT7, GL_CULL_FACE,
                            GL_LIGHTING, GL_COLOR_MATERIAL, GL_COLOR_SUM, GL_DEPTH_TEST, GL_BLEND,
                            GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_COLOR_LOGIC_OP,
                            GL_INDEX_LOGIC_OP, GL_NORMALIZE, GL_RESCALE_NORMAL})
           glEnable(cap);
         glDisable(GL_DITHER);
       },
       [] {
         std::vector<double> v;
         append_enabled(v, {GL_CLIP_PLANE0, GL_CLIP_PLANE5, GL_LIGHT0, GL_LIGHT7, GL_CULL_FACE,
                            GL_LIGHTING, GL_COLOR_MATERIAL, GL_COLOR_SUM, GL_DEPTH_TEST, GL_BLEND,
                            GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_COLOR_LOGIC_OP,
                            GL_INDEX_LOGIC_OP, GL_NORMALIZE, GL_RESCALE_NORMAL, GL_DITHER});
         return v;
       }},
  };
}

TEST_F(Attrib, Limits) {
  EXPECT_GE(get_int(GL_MAX_ATTRIB_STACK_DEPTH), 16);
  EXPECT_EQ(get_int(GL_ATTRIB_STACK_DEPTH), 0);
  glPushAttrib(GL_CURRENT_BIT);
  EXPECT_EQ(get_int(GL_ATTRIB_STACK_DEPTH), 1);
  glPopAttrib();
  EXPECT_EQ(get_int(GL_ATTRIB_STACK_DEPTH), 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Attrib, OverflowAndUnderflowChangeNothing) {
  const GLint max = get_int(GL_MAX_ATTRIB_STACK_DEPTH);
  for (GLint i = 0; i < max; ++i)
    glPushAttrib(GL_ALL_ATTRIB_BITS);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glDepthFunc(GL_EQUAL);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_STACK_OVERFLOW));
  EXPECT_EQ(get_int(GL_ATTRIB_STACK_DEPTH), max);
  // The failed push saved nothing: the first pop restores the last successful frame.
  glPopAttrib();
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_LESS);
  for (GLint i = 1; i < max; ++i)
    glPopAttrib();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glDepthFunc(GL_EQUAL);
  glPopAttrib();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_STACK_UNDERFLOW));
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_EQUAL);
  EXPECT_EQ(get_int(GL_ATTRIB_STACK_DEPTH), 0);
}

TEST_F(Attrib, IllegalInsideBeginEnd) {
  glBegin(GL_TRIANGLES);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_ATTRIB_STACK_DEPTH), 0);
  glPushAttrib(GL_DEPTH_BUFFER_BIT);
  glDepthFunc(GL_EQUAL);
  glBegin(GL_TRIANGLES);
  glPopAttrib();
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_ATTRIB_STACK_DEPTH), 1);
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_EQUAL);
}

TEST_F(Attrib, EachGroupIsRestored) {
  for (const Group& g : groups()) {
    const std::vector<double> before = g.query();
    glPushAttrib(g.bit);
    g.change();
    EXPECT_NE(g.query(), before) << g.name;
    glPopAttrib();
    EXPECT_EQ(g.query(), before) << g.name;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << g.name;
  }
}

TEST_F(Attrib, AllAttribBitsRestoresEveryGroup) {
  std::vector<std::vector<double>> before;
  for (const Group& g : groups())
    before.push_back(g.query());
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  for (const Group& g : groups())
    g.change();
  glPopAttrib();
  size_t i = 0;
  for (const Group& g : groups())
    EXPECT_EQ(g.query(), before[i++]) << g.name;
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// State outside the mask keeps the value it had at PopAttrib. The mask is every bit except
// the group's own and, because enables belong to both, ENABLE_BIT (and for the enable group,
// every group whose state includes an enable).
TEST_F(Attrib, StateOutsideTheMaskIsUntouched) {
  const GLbitfield with_enables = GL_POLYGON_BIT | GL_LIGHTING_BIT | GL_DEPTH_BUFFER_BIT |
                                  GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_SCISSOR_BIT |
                                  GL_TRANSFORM_BIT | GL_FOG_BIT;
  for (const Group& g : groups()) {
    GLbitfield mask = GL_ALL_ATTRIB_BITS & ~g.bit & ~GLbitfield(GL_ENABLE_BIT);
    if (g.bit == GL_ENABLE_BIT) mask &= ~with_enables;
    glPushAttrib(mask);
    g.change();
    const std::vector<double> changed = g.query();
    glPopAttrib();
    EXPECT_EQ(g.query(), changed) << g.name;
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Attrib, EnableBitRestoresOnlyEnables) {
  glPushAttrib(GL_ENABLE_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glEnable(GL_LIGHT2);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_LIGHT2), GL_FALSE);
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_GREATER);
}

// Groups with no state in Pineda yet are accepted and leave everything alone.
TEST_F(Attrib, GroupsWithoutStateAreAccepted) {
  for (GLbitfield bit : {GL_ACCUM_BUFFER_BIT, GL_EVAL_BIT, GL_LINE_BIT, GL_POINT_BIT,
                         GL_POLYGON_STIPPLE_BIT, GL_LIST_BIT, GL_TEXTURE_BIT, GL_MULTISAMPLE_BIT}) {
    glPushAttrib(bit);
    glDepthFunc(GL_EQUAL);
    glPopAttrib();
    EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_EQUAL) << std::hex << bit;
    glDepthFunc(GL_LESS);
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// Nested frames pop in last-in first-out order.
TEST_F(Attrib, NestedFrames) {
  glPushAttrib(GL_DEPTH_BUFFER_BIT);
  glDepthFunc(GL_EQUAL);
  glPushAttrib(GL_DEPTH_BUFFER_BIT);
  glDepthFunc(GL_NEVER);
  glPopAttrib();
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_EQUAL);
  glPopAttrib();
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_LESS);
}

void quad(float z, float r, float g, float b, float a) {
  glColor4f(r, g, b, a);
  glBegin(GL_QUADS);
  glVertex3f(-1, -1, z);
  glVertex3f(1, -1, z);
  glVertex3f(1, 1, z);
  glVertex3f(-1, 1, z);
  glEnd();
}

// Popped state reaches the rasterizer: depth test and blending saved off, turned on, and
// popped off again draw as if never enabled.
TEST_F(Attrib, PoppedStateTakesEffectOnDrawing) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  quad(0.5f, 1, 0, 0, 1); // red, far
  glPushAttrib(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  quad(0.0f, 0, 0, 1, 1); // blue, near: passes the depth test, adds to red
  EXPECT_EQ(pixel(kW / 2, kH / 2), 0xffff00ffu);
  quad(0.9f, 0, 1, 0, 1); // green, farther: fails the depth test
  EXPECT_EQ(pixel(kW / 2, kH / 2), 0xffff00ffu);
  glPopAttrib();
  quad(0.9f, 0, 1, 0, 1); // no depth test, no blending: replaces
  EXPECT_EQ(pixel(kW / 2, kH / 2), 0xff00ff00u);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

} // namespace
