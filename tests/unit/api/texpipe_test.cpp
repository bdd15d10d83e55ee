// Texture units, texture environment, coordinate generation and fog through the GL API: errors,
// defaults, queries, the attribute stack (GL 2.1 §2.7, §2.11.4, §3.8.13, §3.10, §6.1.14).
#include <GL/glext.h>

#include <cmath>

#include "api_fixture.h"

namespace {

using TexPipeTest = GLTest;

GLenum err() {
  return glGetError();
}

TEST_F(TexPipeTest, ActiveTextureUnitsAndLimits) {
  GLint v = 0;
  glGetIntegerv(GL_MAX_TEXTURE_UNITS, &v);
  EXPECT_GE(v, 4);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &v);
  EXPECT_EQ(v, GL_TEXTURE0);
  glActiveTexture(GL_TEXTURE2);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &v);
  EXPECT_EQ(v, GL_TEXTURE2);
  // GL 2.1 §2.7: up to the larger of MAX_TEXTURE_COORDS and MAX_COMBINED_TEXTURE_IMAGE_UNITS.
  glActiveTexture(GL_TEXTURE0 + 32);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glClientActiveTexture(GL_TEXTURE3);
  glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &v);
  EXPECT_EQ(v, GL_TEXTURE3);
  glClientActiveTexture(GL_TEXTURE1 - 1 + 9);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glBegin(GL_POINTS);
  glActiveTexture(GL_TEXTURE1);
  glEnd();
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(TexPipeTest, MultiTexCoordPerUnit) {
  glMultiTexCoord2f(GL_TEXTURE1, 0.5f, 0.25f);
  glMultiTexCoord4i(GL_TEXTURE3, 1, 2, 3, 4);
  glMultiTexCoord1d(GL_TEXTURE0, 7.0);
  GLfloat t[4];
  glActiveTexture(GL_TEXTURE1);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
  EXPECT_EQ(t[0], 0.5f);
  EXPECT_EQ(t[1], 0.25f);
  EXPECT_EQ(t[2], 0.0f);
  EXPECT_EQ(t[3], 1.0f);
  glActiveTexture(GL_TEXTURE3);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
  EXPECT_EQ(t[3], 4.0f);
  glActiveTexture(GL_TEXTURE0);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
  EXPECT_EQ(t[0], 7.0f);
  glMultiTexCoord2f(GL_TEXTURE0 + 4, 1, 1);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
}

TEST_F(TexPipeTest, TextureEnablesPerUnit) {
  glActiveTexture(GL_TEXTURE1);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_GEN_S);
  EXPECT_TRUE(glIsEnabled(GL_TEXTURE_2D));
  EXPECT_TRUE(glIsEnabled(GL_TEXTURE_GEN_S));
  glActiveTexture(GL_TEXTURE0);
  EXPECT_FALSE(glIsEnabled(GL_TEXTURE_2D));
  EXPECT_FALSE(glIsEnabled(GL_TEXTURE_GEN_S));
  for (GLenum cap : {GL_TEXTURE_1D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_GEN_T,
                     GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q, GL_FOG}) {
    glEnable(cap);
    EXPECT_TRUE(glIsEnabled(cap));
    glDisable(cap);
    EXPECT_FALSE(glIsEnabled(cap));
  }
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

TEST_F(TexPipeTest, TexEnvDefaultsAndValues) {
  GLint v = 0;
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
  EXPECT_EQ(v, GL_MODULATE);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_COMBINE_RGB, &v);
  EXPECT_EQ(v, GL_MODULATE);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_SRC2_RGB, &v);
  EXPECT_EQ(v, GL_CONSTANT);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_OPERAND2_RGB, &v);
  EXPECT_EQ(v, GL_SRC_ALPHA);
  GLfloat f = 0;
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_RGB_SCALE, &f);
  EXPECT_EQ(f, 1.0f);
  for (GLenum m : {GL_REPLACE, GL_DECAL, GL_BLEND, GL_ADD, GL_COMBINE, GL_MODULATE}) {
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, m);
    glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
    EXPECT_EQ(v, GLint(m));
  }
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGBA);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_ALPHA, GL_TEXTURE3);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_ONE_MINUS_SRC_COLOR);
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 4.0f);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -1.5f);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  glGetTexEnviv(GL_TEXTURE_ENV, GL_COMBINE_RGB, &v);
  EXPECT_EQ(v, GL_DOT3_RGBA);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_SRC1_ALPHA, &v);
  EXPECT_EQ(v, GL_TEXTURE3);
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_ALPHA_SCALE, &f);
  EXPECT_EQ(f, 4.0f);
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &f);
  EXPECT_EQ(f, -1.5f);
  const GLfloat color[4] = {0.25f, 2.0f, -1.0f, 0.5f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, color);
  GLfloat got[4];
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, got);
  EXPECT_EQ(got[0], 0.25f);
  EXPECT_EQ(got[1], 1.0f); // clamped
  EXPECT_EQ(got[2], 0.0f);
  GLint igot[4];
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, igot);
  EXPECT_EQ(igot[1], 2147483647);
  // Per unit: unit 1 still has the defaults.
  glActiveTexture(GL_TEXTURE1);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_COMBINE_RGB, &v);
  EXPECT_EQ(v, GL_MODULATE);
}

TEST_F(TexPipeTest, TexEnvErrors) {
  glTexEnvi(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_SUBTRACT);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGB);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_COLOR);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB, GL_TEXTURE0 + 4);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 3.0f);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, 1.0f);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_ENV_MODE, 1.0f);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  GLint v = 0;
  glGetTexEnviv(GL_TEXTURE_ENV, GL_FOG_MODE, &v);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glBegin(GL_POINTS);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnd();
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
  EXPECT_EQ(v, GL_MODULATE);
}

TEST_F(TexPipeTest, TexGenModesPlanesAndErrors) {
  GLint v = 0;
  glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &v);
  EXPECT_EQ(v, GL_EYE_LINEAR);
  GLdouble p[4];
  glGetTexGendv(GL_S, GL_OBJECT_PLANE, p);
  EXPECT_EQ(p[0], 1.0);
  glGetTexGendv(GL_T, GL_EYE_PLANE, p);
  EXPECT_EQ(p[1], 1.0);
  glGetTexGendv(GL_R, GL_OBJECT_PLANE, p);
  EXPECT_EQ(p[0] + p[1] + p[2] + p[3], 0.0);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexGeni(GL_S + 7, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glTexGenf(GL_S, GL_OBJECT_PLANE, 1.0f);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  // §2.11.4: the eye plane is transformed by the inverse model-view at specification.
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glScalef(2.0f, 4.0f, 1.0f);
  const GLfloat plane[4] = {1.0f, 1.0f, 1.0f, 0.5f};
  glTexGenfv(GL_T, GL_EYE_PLANE, plane);
  GLfloat got[4];
  glGetTexGenfv(GL_T, GL_EYE_PLANE, got);
  EXPECT_FLOAT_EQ(got[0], 0.5f);
  EXPECT_FLOAT_EQ(got[1], 0.25f);
  EXPECT_FLOAT_EQ(got[2], 1.0f);
  EXPECT_FLOAT_EQ(got[3], 0.5f);
  glTexGenfv(GL_T, GL_OBJECT_PLANE, plane);
  glGetTexGenfv(GL_T, GL_OBJECT_PLANE, got);
  EXPECT_EQ(got[1], 1.0f);
  glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &v);
  EXPECT_EQ(v, GL_SPHERE_MAP);
}

TEST_F(TexPipeTest, FogStateQueriesAndErrors) {
  GLint v = 0;
  glGetIntegerv(GL_FOG_MODE, &v);
  EXPECT_EQ(v, GL_EXP);
  glGetIntegerv(GL_FOG_COORD_SRC, &v);
  EXPECT_EQ(v, GL_FRAGMENT_DEPTH);
  GLfloat f = 0;
  glGetFloatv(GL_FOG_DENSITY, &f);
  EXPECT_EQ(f, 1.0f);
  glGetFloatv(GL_FOG_END, &f);
  EXPECT_EQ(f, 1.0f);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, -2.0f);
  glFogf(GL_FOG_END, 12.5f);
  glFogf(GL_FOG_DENSITY, 0.25f);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  const GLfloat color[4] = {0.5f, 1.5f, 0.25f, -1.0f};
  glFogfv(GL_FOG_COLOR, color);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  glGetIntegerv(GL_FOG_MODE, &v);
  EXPECT_EQ(v, GL_LINEAR);
  glGetFloatv(GL_FOG_START, &f);
  EXPECT_EQ(f, -2.0f);
  glGetFloatv(GL_FOG_END, &f);
  EXPECT_EQ(f, 12.5f);
  GLfloat c[4];
  glGetFloatv(GL_FOG_COLOR, c);
  EXPECT_EQ(c[1], 1.0f);
  EXPECT_EQ(c[3], 0.0f);
  glFogf(GL_FOG_DENSITY, -1.0f);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glFogi(GL_FOG_MODE, GL_REPLACE);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glFogi(GL_FOG_COORD_SRC, GL_LINEAR);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glFogf(GL_FOG_COLOR, 0.5f);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glFogf(GL_TEXTURE_ENV_MODE, 0.5f);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glBegin(GL_TRIANGLES);
  glFogf(GL_FOG_START, 1.0f);
  glEnd();
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(TexPipeTest, FogCoordCurrentAndArray) {
  glFogCoordf(2.5f);
  GLfloat f = 0;
  glGetFloatv(GL_CURRENT_FOG_COORD, &f);
  EXPECT_EQ(f, 2.5f);
  glFogCoordd(-1.0);
  glGetFloatv(GL_CURRENT_FOG_COORD, &f);
  EXPECT_EQ(f, -1.0f);
  const GLfloat coords[3] = {1, 2, 3};
  glFogCoordPointer(GL_FLOAT, 8, coords);
  GLint v = 0;
  glGetIntegerv(GL_FOG_COORD_ARRAY_TYPE, &v);
  EXPECT_EQ(v, GL_FLOAT);
  glGetIntegerv(GL_FOG_COORD_ARRAY_STRIDE, &v);
  EXPECT_EQ(v, 8);
  void* p = nullptr;
  glGetPointerv(GL_FOG_COORD_ARRAY_POINTER, &p);
  EXPECT_EQ(p, coords);
  glEnableClientState(GL_FOG_COORD_ARRAY);
  EXPECT_TRUE(glIsEnabled(GL_FOG_COORD_ARRAY));
  glFogCoordPointer(GL_INT, 0, coords);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glFogCoordPointer(GL_FLOAT, -4, coords);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
}

TEST_F(TexPipeTest, AttribStackTextureFogEnable) {
  glActiveTexture(GL_TEXTURE1);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
  glFogi(GL_FOG_MODE, GL_EXP2);
  glPushAttrib(GL_TEXTURE_BIT | GL_FOG_BIT | GL_ENABLE_BIT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glActiveTexture(GL_TEXTURE3);
  glPopAttrib();
  GLint v = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &v);
  EXPECT_EQ(v, GL_TEXTURE1);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
  EXPECT_EQ(v, GL_ADD);
  glGetTexGeniv(GL_T, GL_TEXTURE_GEN_MODE, &v);
  EXPECT_EQ(v, GL_EYE_LINEAR);
  EXPECT_FALSE(glIsEnabled(GL_TEXTURE_2D));
  EXPECT_FALSE(glIsEnabled(GL_FOG));
  glGetIntegerv(GL_FOG_MODE, &v);
  EXPECT_EQ(v, GL_EXP2);
  // ENABLE_BIT alone restores the enables but not the environment.
  glPushAttrib(GL_ENABLE_BIT);
  glEnable(GL_TEXTURE_GEN_Q);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  glPopAttrib();
  EXPECT_FALSE(glIsEnabled(GL_TEXTURE_GEN_Q));
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
  EXPECT_EQ(v, GL_DECAL);
  // CURRENT_BIT saves the fog coordinate.
  glFogCoordf(3.0f);
  glPushAttrib(GL_CURRENT_BIT);
  glFogCoordf(5.0f);
  glPopAttrib();
  GLfloat f = 0;
  glGetFloatv(GL_CURRENT_FOG_COORD, &f);
  EXPECT_EQ(f, 3.0f);
}

TEST_F(TexPipeTest, TextureMatrixPerUnit) {
  glMatrixMode(GL_TEXTURE);
  glActiveTexture(GL_TEXTURE2);
  glTranslatef(1, 2, 3);
  glPushMatrix();
  GLint depth = 0;
  glGetIntegerv(GL_TEXTURE_STACK_DEPTH, &depth);
  EXPECT_EQ(depth, 2);
  GLfloat m[16];
  glGetFloatv(GL_TEXTURE_MATRIX, m);
  EXPECT_EQ(m[12], 1.0f);
  glActiveTexture(GL_TEXTURE0);
  glGetIntegerv(GL_TEXTURE_STACK_DEPTH, &depth);
  EXPECT_EQ(depth, 1);
  glGetFloatv(GL_TEXTURE_MATRIX, m);
  EXPECT_EQ(m[12], 0.0f);
}

// Fog over a quad with the fog coordinate as source: the pixel colour follows eq. 3.27.
TEST_F(TexPipeTest, LinearFogRendersExpectedColour) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kW, 0, kH, -1, 1);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 4.0f);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  const GLfloat fog[4] = {0.0f, 0.0f, 1.0f, 1.0f};
  glFogfv(GL_FOG_COLOR, fog);
  glFogCoordf(1.0f); // f = 3/4
  glColor4f(1.0f, 0.0f, 0.0f, 1.0f);
  glRecti(0, 0, kW, kH);
  const uint32_t px = pixel(5, 5);
  EXPECT_NEAR(static_cast<int>(px & 0xff), 191, 1);        // 0.75 * 255
  EXPECT_NEAR(static_cast<int>((px >> 16) & 0xff), 64, 1); // 0.25 * 255
  EXPECT_EQ((px >> 24) & 0xff, 255u);
}

} // namespace
