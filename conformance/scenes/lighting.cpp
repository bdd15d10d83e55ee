// Fixed-function lighting (GL 2.1 §2.14): directional, positional, spot and attenuated lights,
// eight lights at once, two-sided lighting, COLOR_MATERIAL, the local viewer with a separate
// specular colour, RESCALE_NORMAL / NORMALIZE under a scaled model-view, and Material calls
// between Begin and End. Lighting is evaluated per vertex, so the surfaces are tessellated
// densely enough that the interpolated colours stay smooth.
#include "scene_util.h"

#include <array>
#include <cmath>

using namespace scenes;

namespace {

// Every draw of a scene must reproduce the first, so each scene starts from the GL 2.1
// Table 2.10 defaults rather than from what the previous repetition left behind.
void reset_lighting() {
  const GLfloat black[4] = {0, 0, 0, 1}, white[4] = {1, 1, 1, 1};
  const GLfloat pos[4] = {0, 0, 1, 0}, dir[3] = {0, 0, -1};
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  for (int i = 0; i < 8; ++i) {
    const GLenum l = GL_LIGHT0 + i;
    glLightfv(l, GL_AMBIENT, black);
    glLightfv(l, GL_DIFFUSE, i == 0 ? white : black);
    glLightfv(l, GL_SPECULAR, i == 0 ? white : black);
    glLightfv(l, GL_POSITION, pos);
    glLightfv(l, GL_SPOT_DIRECTION, dir);
    glLightf(l, GL_SPOT_EXPONENT, 0);
    glLightf(l, GL_SPOT_CUTOFF, 180);
    glLightf(l, GL_CONSTANT_ATTENUATION, 1);
    glLightf(l, GL_LINEAR_ATTENUATION, 0);
    glLightf(l, GL_QUADRATIC_ATTENUATION, 0);
    glDisable(l);
  }
  const GLfloat amb[4] = {0.2f, 0.2f, 0.2f, 1}, dif[4] = {0.8f, 0.8f, 0.8f, 1};
  glDisable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, black);
  glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, black);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 0);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_FALSE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  glDisable(GL_NORMALIZE);
  glDisable(GL_RESCALE_NORMAL);
  glShadeModel(GL_SMOOTH);
}

// A perspective view of the whole frame with depth testing; eye at the origin looking down -z.
void perspective_frame(const Frame& f, double near = 1.0, double far = 30.0) {
  glViewport(0, 0, f.width, f.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double aspect = static_cast<double>(f.width) / f.height;
  glFrustum(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, near, far);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
}

void light4(GLenum light, GLenum pname, float a, float b, float c, float d) {
  const GLfloat v[4] = {a, b, c, d};
  glLightfv(light, pname, v);
}

void material4(GLenum face, GLenum pname, float a, float b, float c, float d) {
  const GLfloat v[4] = {a, b, c, d};
  glMaterialfv(face, pname, v);
}

void vertex_on_sphere(float r, float theta, float phi) {
  const float x = std::sin(theta) * std::cos(phi), y = std::cos(theta),
              z = std::sin(theta) * std::sin(phi);
  glNormal3f(x, y, z);
  glVertex3f(r * x, r * y, r * z);
}

// A sphere of radius r around the origin: `stacks` triangle strips from pole to pole, unit
// normals. With `color_fn` set, each vertex also gets a colour from its position.
void sphere(float r, int slices, int stacks, void (*color_fn)(float, float, float) = nullptr) {
  for (int i = 0; i < stacks; ++i) {
    const float t0 = kPi * i / stacks, t1 = kPi * (i + 1) / stacks;
    glBegin(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= slices; ++j) {
      const float p = 2.0f * kPi * j / slices;
      if (color_fn) color_fn(t1, p, r);
      vertex_on_sphere(r, t1, p);
      if (color_fn) color_fn(t0, p, r);
      vertex_on_sphere(r, t0, p);
    }
    glEnd();
  }
}

// A torus around the z axis: ring radius R, tube radius r.
void torus(float big_r, float r, int rings, int sides) {
  for (int i = 0; i < rings; ++i) {
    glBegin(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= sides; ++j) {
      const float v = 2.0f * kPi * j / sides;
      for (int k = 1; k >= 0; --k) {
        const float u = 2.0f * kPi * (i + k) / rings;
        const float nx = std::cos(v) * std::cos(u), ny = std::cos(v) * std::sin(u),
                    nz = std::sin(v);
        glNormal3f(nx, ny, nz);
        glVertex3f((big_r + r * std::cos(v)) * std::cos(u), (big_r + r * std::cos(v)) * std::sin(u),
                   r * nz);
      }
    }
    glEnd();
  }
}

// A square floor in the y = 0 plane, normal +y, n x n cells.
void floor_grid(float half, int n) {
  glNormal3f(0, 1, 0);
  for (int i = 0; i < n; ++i) {
    const float z0 = -half + 2 * half * i / n, z1 = -half + 2 * half * (i + 1) / n;
    glBegin(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= n; ++j) {
      const float x = -half + 2 * half * j / n;
      glVertex3f(x, 0, z1);
      glVertex3f(x, 0, z0);
    }
    glEnd();
  }
}

} // namespace

PINEDA_SCENE(light_directional, "Nine spheres with different materials under one directional light") {
  clear_frame(0.05f, 0.05f, 0.1f);
  reset_lighting();
  perspective_frame(frame);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  light4(GL_LIGHT0, GL_POSITION, -0.4f, 0.7f, 0.6f, 0.0f);
  light4(GL_LIGHT0, GL_AMBIENT, 0.1f, 0.1f, 0.1f, 1);
  for (int i = 0; i < 9; ++i) {
    const float* c = palette(i * 5 + 1);
    material4(GL_FRONT, GL_DIFFUSE, c[0] * 0.8f, c[1] * 0.8f, c[2] * 0.8f, 1);
    material4(GL_FRONT, GL_AMBIENT, c[0] * 0.3f, c[1] * 0.3f, c[2] * 0.3f, 1);
    const float s = 0.15f * static_cast<float>(i % 3) + 0.2f;
    material4(GL_FRONT, GL_SPECULAR, s, s, s, 1);
    glMaterialf(GL_FRONT, GL_SHININESS, 4.0f + 20.0f * static_cast<float>(i / 3));
    glPushMatrix();
    glTranslatef(-1.1f + 1.1f * static_cast<float>(i % 3), -1.1f + 1.1f * static_cast<float>(i / 3),
                 -4.5f);
    sphere(0.5f, 40, 24);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);
}

PINEDA_SCENE(light_positional, "A torus and spheres around a positional light, local viewer off") {
  clear_frame(0.0f, 0.0f, 0.0f);
  reset_lighting();
  perspective_frame(frame);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  light4(GL_LIGHT0, GL_POSITION, 0.3f, 0.4f, -3.5f, 1.0f);
  light4(GL_LIGHT0, GL_DIFFUSE, 1.0f, 0.9f, 0.7f, 1);
  light4(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1);
  material4(GL_FRONT, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 24.0f);
  material4(GL_FRONT, GL_DIFFUSE, 0.3f, 0.6f, 0.9f, 1);
  glPushMatrix();
  glTranslatef(0, 0, -5);
  glRotatef(60, 1, 0, 0);
  torus(1.3f, 0.35f, 64, 32);
  glPopMatrix();
  material4(GL_FRONT, GL_DIFFUSE, 0.9f, 0.5f, 0.2f, 1);
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    const float a = kPi * 0.5f * static_cast<float>(i) + 0.4f;
    glTranslatef(1.6f * std::cos(a), 1.2f * std::sin(a), -4.0f - 0.5f * static_cast<float>(i));
    sphere(0.35f, 32, 20);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);
}

PINEDA_SCENE(light_spot, "A spot light on a finely tessellated floor and a sphere") {
  clear_frame(0.0f, 0.0f, 0.05f);
  reset_lighting();
  perspective_frame(frame);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT1);
  glPushMatrix();
  glTranslatef(0, -1.0f, -5.0f);
  glRotatef(25, 1, 0, 0);
  // The light is specified under the floor's model-view: position and direction follow it.
  light4(GL_LIGHT1, GL_POSITION, 0.5f, 2.5f, 0.5f, 1.0f);
  const GLfloat dir[3] = {-0.3f, -1.0f, -0.2f};
  glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, dir);
  glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 35.0f);
  glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 12.0f);
  light4(GL_LIGHT1, GL_DIFFUSE, 1.0f, 1.0f, 0.8f, 1);
  light4(GL_LIGHT1, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1);
  light4(GL_LIGHT1, GL_AMBIENT, 0.05f, 0.05f, 0.05f, 1);
  material4(GL_FRONT, GL_DIFFUSE, 0.7f, 0.7f, 0.7f, 1);
  floor_grid(3.0f, 96);
  material4(GL_FRONT, GL_DIFFUSE, 0.9f, 0.2f, 0.2f, 1);
  material4(GL_FRONT, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 16.0f);
  glTranslatef(-0.3f, 0.6f, -0.2f);
  sphere(0.6f, 48, 32);
  glPopMatrix();
  glDisable(GL_LIGHTING);
}

PINEDA_SCENE(light_attenuation, "Constant, linear and quadratic attenuation of two positional lights") {
  clear_frame(0.0f, 0.0f, 0.0f);
  reset_lighting();
  perspective_frame(frame);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT2);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, std::array<GLfloat, 4>{0.05f, 0.05f, 0.05f, 1}.data());
  glPushMatrix();
  glTranslatef(0, -1.2f, -5.0f);
  glRotatef(30, 1, 0, 0);
  light4(GL_LIGHT0, GL_POSITION, -1.2f, 0.6f, 0.0f, 1.0f);
  light4(GL_LIGHT0, GL_DIFFUSE, 1.0f, 0.5f, 0.2f, 1);
  glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0.3f);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.6f);
  light4(GL_LIGHT2, GL_POSITION, 1.2f, 0.4f, -0.5f, 1.0f);
  light4(GL_LIGHT2, GL_DIFFUSE, 0.2f, 0.6f, 1.0f, 1);
  light4(GL_LIGHT2, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);
  glLightf(GL_LIGHT2, GL_CONSTANT_ATTENUATION, 0.2f);
  glLightf(GL_LIGHT2, GL_QUADRATIC_ATTENUATION, 1.5f);
  floor_grid(3.0f, 80);
  material4(GL_FRONT, GL_SPECULAR, 0.4f, 0.4f, 0.4f, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 10.0f);
  glTranslatef(0, 0.5f, -0.3f);
  glRotatef(90, 1, 0, 0);
  torus(0.9f, 0.25f, 64, 24);
  glPopMatrix();
  glDisable(GL_LIGHTING);
}

PINEDA_SCENE(light_eight, "Eight coloured lights (directional and positional) on a sphere and a torus") {
  clear_frame(0.0f, 0.0f, 0.0f);
  reset_lighting();
  perspective_frame(frame);
  glEnable(GL_LIGHTING);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, std::array<GLfloat, 4>{0, 0, 0, 1}.data());
  for (int i = 0; i < 8; ++i) {
    const GLenum l = GL_LIGHT0 + i;
    const float a = 2.0f * kPi * static_cast<float>(i) / 8.0f;
    const float* c = palette(i * 2);
    light4(l, GL_DIFFUSE, c[0] * 0.45f, c[1] * 0.45f, c[2] * 0.45f, 1);
    light4(l, GL_SPECULAR, c[0] * 0.3f, c[1] * 0.3f, c[2] * 0.3f, 1);
    light4(l, GL_AMBIENT, 0.02f, 0.02f, 0.02f, 1);
    if (i % 2 == 0)
      light4(l, GL_POSITION, 3.0f * std::cos(a), 3.0f * std::sin(a), -2.0f, 1.0f);
    else
      light4(l, GL_POSITION, std::cos(a), std::sin(a), 0.8f, 0.0f);
    glEnable(l);
  }
  material4(GL_FRONT, GL_DIFFUSE, 0.9f, 0.9f, 0.9f, 1);
  material4(GL_FRONT, GL_SPECULAR, 0.7f, 0.7f, 0.7f, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
  glPushMatrix();
  glTranslatef(-0.9f, 0.2f, -5.0f);
  sphere(0.9f, 56, 36);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(1.1f, -0.3f, -5.5f);
  glRotatef(50, 1, 1, 0);
  torus(0.8f, 0.3f, 64, 28);
  glPopMatrix();
  glDisable(GL_LIGHTING);
}

PINEDA_SCENE(light_two_sided, "Two-sided lighting: open half-spheres and a ribbon show back faces with the back material") {
  clear_frame(0.1f, 0.1f, 0.1f);
  reset_lighting();
  perspective_frame(frame);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  light4(GL_LIGHT0, GL_POSITION, 0.3f, 0.5f, 1.0f, 0.0f);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  material4(GL_FRONT, GL_DIFFUSE, 0.9f, 0.6f, 0.1f, 1);
  material4(GL_BACK, GL_DIFFUSE, 0.2f, 0.5f, 0.9f, 1);
  material4(GL_BACK, GL_AMBIENT, 0.1f, 0.3f, 0.1f, 1);
  material4(GL_BACK, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1);
  glMaterialf(GL_BACK, GL_SHININESS, 12.0f);
  // Half-spheres open towards the viewer at different tilts: the inside is back facing.
  for (int k = 0; k < 3; ++k) {
    glPushMatrix();
    glTranslatef(-1.3f + 1.3f * static_cast<float>(k), 0.7f, -5.0f);
    glRotatef(-90.0f + 35.0f * static_cast<float>(k), 1, 0, 0);
    for (int i = 0; i < 12; ++i) {
      const float t0 = 0.5f * kPi * i / 12, t1 = 0.5f * kPi * (i + 1) / 12;
      glBegin(GL_TRIANGLE_STRIP);
      for (int j = 0; j <= 40; ++j) {
        const float p = 2.0f * kPi * j / 40;
        vertex_on_sphere(0.55f, t1, p);
        vertex_on_sphere(0.55f, t0, p);
      }
      glEnd();
    }
    glPopMatrix();
  }
  // A twisted ribbon: its faces alternate between front and back facing along its length.
  glPushMatrix();
  glTranslatef(0, -0.9f, -5.0f);
  glBegin(GL_QUAD_STRIP);
  for (int j = 0; j <= 80; ++j) {
    const float x = -2.2f + 4.4f * j / 80, a = 2.0f * kPi * j / 80;
    const float ny = -std::sin(a), nz = std::cos(a);
    glNormal3f(0, ny, nz);
    glVertex3f(x, 0.4f * std::cos(a), 0.4f * std::sin(a));
    glVertex3f(x, -0.4f * std::cos(a), -0.4f * std::sin(a));
  }
  glEnd();
  glPopMatrix();
  glDisable(GL_LIGHTING);
}

namespace {
void rainbow(float theta, float phi, float) {
  glColor4f(0.5f + 0.5f * std::cos(phi), 0.5f + 0.5f * std::sin(theta * 2.0f),
            0.5f + 0.5f * std::sin(phi), 1.0f);
}
} // namespace

PINEDA_SCENE(light_color_material, "COLOR_MATERIAL: per-vertex colours drive ambient+diffuse, diffuse, specular, emission") {
  clear_frame(0.0f, 0.0f, 0.0f);
  reset_lighting();
  perspective_frame(frame);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  light4(GL_LIGHT0, GL_POSITION, -0.3f, 0.6f, 1.0f, 0.0f);
  light4(GL_LIGHT0, GL_AMBIENT, 0.2f, 0.2f, 0.2f, 1);
  material4(GL_FRONT, GL_SPECULAR, 0.4f, 0.4f, 0.4f, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
  const GLenum modes[4] = {GL_AMBIENT_AND_DIFFUSE, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION};
  glEnable(GL_COLOR_MATERIAL);
  for (int i = 0; i < 4; ++i) {
    glColorMaterial(GL_FRONT, modes[i]);
    glPushMatrix();
    glTranslatef(i % 2 == 0 ? -0.75f : 0.75f, i < 2 ? 0.75f : -0.75f, -4.5f);
    glRotatef(30.0f * static_cast<float>(i), 0, 1, 0);
    sphere(0.65f, 40, 28, rainbow);
    glPopMatrix();
  }
  glDisable(GL_COLOR_MATERIAL);
  // The material keeps what the last colour wrote (§2.14.3: the replacements are permanent).
  material4(GL_FRONT, GL_EMISSION, 0, 0, 0, 1);
  glDisable(GL_LIGHTING);
}

PINEDA_SCENE(light_local_viewer_specular, "Local viewer and SEPARATE_SPECULAR_COLOR against the infinite viewer and SINGLE_COLOR") {
  clear_frame(0.0f, 0.0f, 0.0f);
  reset_lighting();
  perspective_frame(frame);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  light4(GL_LIGHT0, GL_POSITION, 0.5f, 1.0f, -2.0f, 1.0f);
  light4(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1);
  material4(GL_FRONT, GL_DIFFUSE, 0.6f, 0.1f, 0.1f, 1);
  material4(GL_FRONT, GL_SPECULAR, 0.9f, 0.9f, 0.9f, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
  for (int i = 0; i < 4; ++i) {
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, i % 2 == 0 ? GL_TRUE : GL_FALSE);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL,
                  i < 2 ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
    glPushMatrix();
    glTranslatef(i % 2 == 0 ? -0.8f : 0.8f, i < 2 ? 0.8f : -0.8f, -4.5f);
    sphere(0.7f, 48, 32);
    glPopMatrix();
  }
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  glDisable(GL_LIGHTING);
}

PINEDA_SCENE(light_normals, "Scaled model-view: unnormalized, RESCALE_NORMAL, NORMALIZE, and NORMALIZE under a non-uniform scale") {
  clear_frame(0.05f, 0.05f, 0.05f);
  reset_lighting();
  perspective_frame(frame);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  light4(GL_LIGHT0, GL_POSITION, -0.5f, 0.5f, 1.0f, 0.0f);
  material4(GL_FRONT, GL_DIFFUSE, 0.3f, 0.8f, 0.5f, 1);
  material4(GL_FRONT, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 15.0f);
  for (int i = 0; i < 4; ++i) {
    if (i == 1) glEnable(GL_RESCALE_NORMAL);
    if (i == 2) {
      glDisable(GL_RESCALE_NORMAL);
      glEnable(GL_NORMALIZE);
    }
    glPushMatrix();
    glTranslatef(i % 2 == 0 ? -0.8f : 0.8f, i < 2 ? 0.8f : -0.8f, -4.5f);
    if (i == 3)
      glScalef(0.7f, 0.35f, 0.5f);
    else
      glScalef(0.35f, 0.35f, 0.35f);
    sphere(1.8f, 44, 30);
    glPopMatrix();
  }
  glDisable(GL_NORMALIZE);
  glDisable(GL_LIGHTING);
}

PINEDA_SCENE(light_material_begin_end, "glMaterial between glBegin and glEnd changes diffuse, specular and shininess per vertex") {
  clear_frame(0.0f, 0.0f, 0.0f);
  reset_lighting();
  perspective_frame(frame);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  light4(GL_LIGHT0, GL_POSITION, 0.2f, 0.4f, 1.0f, 0.0f);
  glPushMatrix();
  glTranslatef(0, 0, -5);
  // A band of quads around a cylinder: the front diffuse colour, specular colour and
  // shininess change with every column of vertices. One-sided: Mesa's per-vertex back
  // materials under two-sided lighting differ between llvmpipe and softpipe, so they are no
  // oracle for that case (unit-tested in lighting_test.cpp instead).
  glRotatef(70, 1, 0, 0);
  glRotatef(20, 0, 0, 1);
  glBegin(GL_QUAD_STRIP);
  for (int j = 0; j <= 64; ++j) {
    const float a = 2.0f * kPi * j / 64;
    const float* c = palette(j / 4);
    material4(GL_FRONT, GL_DIFFUSE, c[0], c[1], c[2], 1);
    glMaterialf(GL_FRONT, GL_SHININESS, 2.0f + static_cast<float>(j % 5) * 10.0f);
    material4(GL_FRONT, GL_SPECULAR, 0.3f, 0.3f, 0.3f, 1);
    glNormal3f(std::cos(a), std::sin(a), 0);
    glVertex3f(1.4f * std::cos(a), 1.4f * std::sin(a), -0.8f);
    glVertex3f(1.4f * std::cos(a), 1.4f * std::sin(a), 0.8f);
  }
  glEnd();
  glPopMatrix();
  glDisable(GL_LIGHTING);
}

PINEDA_SCENE(light_flat_arrays, "Flat-shaded lit polygons and a lit sphere from vertex and normal arrays") {
  clear_frame(0.0f, 0.05f, 0.05f);
  reset_lighting();
  perspective_frame(frame);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  light4(GL_LIGHT0, GL_POSITION, -1.0f, 1.0f, 0.5f, 1.0f);
  material4(GL_FRONT, GL_DIFFUSE, 0.8f, 0.7f, 0.3f, 1);
  material4(GL_FRONT, GL_SPECULAR, 0.4f, 0.4f, 0.4f, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 8.0f);
  glShadeModel(GL_FLAT);
  glPushMatrix();
  glTranslatef(-0.9f, 0, -4.5f);
  glRotatef(20, 1, 1, 0);
  sphere(0.8f, 16, 10);
  glPopMatrix();
  glShadeModel(GL_SMOOTH);

  // The same kind of sphere through glDrawElements.
  constexpr int kSlices = 40, kStacks = 26;
  static GLfloat pos[(kSlices + 1) * (kStacks + 1) * 3], nrm[(kSlices + 1) * (kStacks + 1) * 3];
  static GLuint idx[kStacks * (kSlices + 1) * 2];
  for (int i = 0; i <= kStacks; ++i)
    for (int j = 0; j <= kSlices; ++j) {
      const float t = kPi * i / kStacks, p = 2.0f * kPi * j / kSlices;
      const int k = (i * (kSlices + 1) + j) * 3;
      nrm[k] = std::sin(t) * std::cos(p);
      nrm[k + 1] = std::cos(t);
      nrm[k + 2] = std::sin(t) * std::sin(p);
      for (int c = 0; c < 3; ++c) pos[k + c] = 0.8f * nrm[k + c];
    }
  glVertexPointer(3, GL_FLOAT, 0, pos);
  glNormalPointer(GL_FLOAT, 0, nrm);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  material4(GL_FRONT, GL_DIFFUSE, 0.3f, 0.5f, 0.9f, 1);
  glPushMatrix();
  glTranslatef(0.9f, 0, -4.5f);
  for (int i = 0; i < kStacks; ++i) {
    GLuint* strip = idx + i * (kSlices + 1) * 2;
    for (int j = 0; j <= kSlices; ++j) {
      strip[2 * j] = static_cast<GLuint>((i + 1) * (kSlices + 1) + j);
      strip[2 * j + 1] = static_cast<GLuint>(i * (kSlices + 1) + j);
    }
    glDrawElements(GL_TRIANGLE_STRIP, (kSlices + 1) * 2, GL_UNSIGNED_INT, strip);
  }
  glPopMatrix();
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisable(GL_LIGHTING);
}

PINEDA_SCENE(color_sum, "GL 1.4 secondary colour: COLOR_SUM on and off, smooth and flat, from glSecondaryColor and from arrays") {
  const auto secondary3f = proc<PFNGLSECONDARYCOLOR3FPROC>("glSecondaryColor3f");
  const auto secondary_pointer = proc<PFNGLSECONDARYCOLORPOINTERPROC>("glSecondaryColorPointer");
  clear_frame(0.0f, 0.0f, 0.0f);
  reset_lighting();
  glDisable(GL_DEPTH_TEST);
  // Four panels: COLOR_SUM off / on with immediate-mode colours, flat shading, and arrays.
  for (int k = 0; k < 3; ++k) {
    const Panel p = panel(frame, k, 2, 2);
    if (k == 0)
      glDisable(GL_COLOR_SUM);
    else
      glEnable(GL_COLOR_SUM);
    glShadeModel(k == 2 ? GL_FLAT : GL_SMOOTH);
    const float w = static_cast<float>(p.w), h = static_cast<float>(p.h);
    glBegin(GL_TRIANGLES);
    for (int t = 0; t < 6; ++t) {
      const float x0 = w * static_cast<float>(t % 3) / 3.0f;
      const float y0 = h * static_cast<float>(t / 3) / 2.0f;
      for (int v = 0; v < 3; ++v) {
        const float* c = palette(t * 3 + v);
        const float* s = palette(t * 5 + v * 7 + 2);
        glColor4f(c[0] * 0.6f, c[1] * 0.6f, c[2] * 0.6f, 1);
        secondary3f(s[0] * 0.7f, s[1] * 0.7f, s[2] * 0.7f);
        const float vx = x0 + (v == 1 ? w / 3.0f - 4.0f : 4.0f);
        const float vy = y0 + (v == 2 ? h / 2.0f - 4.0f : 4.0f);
        glVertex2f(snap(vx), snap(vy));
      }
    }
    glEnd();
  }
  glShadeModel(GL_SMOOTH);

  const Panel p = panel(frame, 3, 2, 2);
  constexpr int kN = 12;
  static GLfloat pos[(kN + 1) * 2 * 2];
  static GLubyte sec[(kN + 1) * 2 * 3];
  for (int i = 0; i <= kN; ++i)
    for (int j = 0; j < 2; ++j) {
      const int k = i * 2 + j;
      pos[k * 2] = snap(static_cast<float>(p.w) * static_cast<float>(i) / kN);
      pos[k * 2 + 1] = j == 0 ? 8.0f : static_cast<float>(p.h) - 8.0f;
      sec[k * 3] = static_cast<GLubyte>(i * 20);
      sec[k * 3 + 1] = static_cast<GLubyte>(j * 200);
      sec[k * 3 + 2] = static_cast<GLubyte>(255 - i * 20);
    }
  glColor4f(0.3f, 0.2f, 0.1f, 1);
  glVertexPointer(2, GL_FLOAT, 0, pos);
  secondary_pointer(3, GL_UNSIGNED_BYTE, 0, sec);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, (kN + 1) * 2);
  glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisable(GL_COLOR_SUM);
  secondary3f(0, 0, 0);
}
