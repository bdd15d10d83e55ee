// Display lists (GL 2.1 §5.4): lit gears compiled once and drawn from lists as glxgears does,
// lists calling lists with matrix and state changes, CallLists with ListBase, lists compiled in
// COMPILE_AND_EXECUTE mode, lists whose vertices inherit the current colour, vertex arrays
// dereferenced at compile time, and Material between Begin and End inside a list. Every
// scene compiles its lists again in each repetition and deletes them at the end.
#include "scene_util.h" // first: gear_geometry.h needs the GL header it includes

#include "gear_geometry.h"

#include <cmath>

using namespace scenes;

namespace {

// A perspective view of the whole frame with depth testing.
void perspective(const Frame& f) {
  glViewport(0, 0, f.width, f.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double aspect = static_cast<double>(f.width) / f.height;
  glFrustum(-aspect, aspect, -1.0, 1.0, 5.0, 60.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
}

void material(GLenum pname, float r, float g, float b) {
  const GLfloat v[4] = {r, g, b, 1.0f};
  glMaterialfv(GL_FRONT, pname, v);
}

void lights_on() {
  const GLfloat pos[4] = {5, 5, 10, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_CULL_FACE);
}

void lights_off() {
  glDisable(GL_LIGHTING);
  glDisable(GL_LIGHT0);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  material(GL_AMBIENT, 0.2f, 0.2f, 0.2f);
  material(GL_DIFFUSE, 0.8f, 0.8f, 0.8f);
  glShadeModel(GL_SMOOTH);
}

} // namespace

PINEDA_SCENE(dlist_gears, "Three lit gears drawn from display lists, as glxgears does") {
  clear_frame(0.0f, 0.0f, 0.0f);
  perspective(frame);
  lights_on();
  const GLuint first = glGenLists(3);
  glNewList(first, GL_COMPILE);
  material(GL_AMBIENT_AND_DIFFUSE, 0.8f, 0.1f, 0.0f);
  gear_geometry(1.0f, 4.0f, 1.0f, 20, 0.7f);
  glEndList();
  glNewList(first + 1, GL_COMPILE);
  material(GL_AMBIENT_AND_DIFFUSE, 0.0f, 0.8f, 0.2f);
  gear_geometry(0.5f, 2.0f, 2.0f, 10, 0.7f);
  glEndList();
  glNewList(first + 2, GL_COMPILE);
  material(GL_AMBIENT_AND_DIFFUSE, 0.2f, 0.2f, 1.0f);
  gear_geometry(1.3f, 2.0f, 0.5f, 10, 0.7f);
  glEndList();
  const float angle = 17.0f;
  glTranslatef(0, 0, -40);
  glRotatef(20, 1, 0, 0);
  glRotatef(30, 0, 1, 0);
  glPushMatrix();
  glTranslatef(-3, -2, 0);
  glRotatef(angle, 0, 0, 1);
  glCallList(first);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(3.1f, -2, 0);
  glRotatef(-2 * angle - 9, 0, 0, 1);
  glCallList(first + 1);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(-3.1f, 4.2f, 0);
  glRotatef(-2 * angle - 25, 0, 0, 1);
  glCallList(first + 2);
  glPopMatrix();
  glDeleteLists(first, 3);
  lights_off();
}

PINEDA_SCENE(dlist_nested, "Lists calling lists, CallLists of every type with ListBase") {
  clear_frame(0.1f, 0.1f, 0.1f);
  window_projection(frame);
  const GLuint tiles = glGenLists(8);
  // Eight tiles: a coloured square with a differently coloured triangle, drawn at the origin.
  for (GLuint i = 0; i < 8; ++i) {
    glNewList(tiles + i, GL_COMPILE);
    palette_color(static_cast<int>(i));
    glRectf(1, 1, 27, 27);
    glBegin(GL_TRIANGLES);
    palette_color(static_cast<int>(i) + 5);
    glVertex2f(4, 4);
    glVertex2f(24, 6);
    palette_color(static_cast<int>(i) + 9);
    glVertex2f(10, 22);
    glEnd();
    glTranslatef(29, 0, 0); // each tile moves the pen, as a font's glyph lists do
    glEndList();
  }
  // A row list calls tiles through CallLists with the current ListBase; a page list calls rows.
  const GLuint row = glGenLists(2);
  const GLubyte order[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  glNewList(row, GL_COMPILE);
  glPushMatrix();
  glCallLists(8, GL_UNSIGNED_BYTE, order);
  glPopMatrix();
  glTranslatef(0, 30, 0);
  glEndList();
  glNewList(row + 1, GL_COMPILE);
  glListBase(tiles);
  glCallList(row);
  glShadeModel(GL_FLAT);
  glCallList(row);
  glShadeModel(GL_SMOOTH);
  glEndList();
  glTranslatef(6, 6, 0);
  glCallList(row + 1);
  // Every CallLists type, each naming three tiles relative to a base.
  glListBase(tiles + 4);
  const GLbyte b[3] = {-4, -1, 3};
  const GLshort s[3] = {-3, 0, 2};
  const GLint i32[3] = {-2, 1, 0};
  const GLfloat f[3] = {-1.5f, 2.9f, 1.2f};
  const GLubyte ub[3] = {0, 1, 2};
  const GLushort us[3] = {3, 2, 1};
  const GLuint ui[3] = {1, 3, 0};
  const GLubyte two[6] = {0, 1, 0, 2, 0, 3};
  const GLubyte three[9] = {0, 0, 0, 0, 0, 1, 0, 0, 2};
  const GLubyte four[12] = {0, 0, 0, 3, 0, 0, 0, 2, 0, 0, 0, 1};
  const struct {
    GLenum type;
    const void* data;
    GLuint base;
  } calls[] = {{GL_BYTE, b, tiles + 4},        {GL_SHORT, s, tiles + 4},
               {GL_INT, i32, tiles + 4},       {GL_FLOAT, f, tiles + 4},
               {GL_UNSIGNED_BYTE, ub, tiles},  {GL_UNSIGNED_SHORT, us, tiles + 4},
               {GL_UNSIGNED_INT, ui, tiles},   {GL_2_BYTES, two, tiles + 1},
               {GL_3_BYTES, three, tiles + 2}, {GL_4_BYTES, four, tiles}};
  int k = 0;
  for (const auto& c : calls) {
    glPushMatrix();
    glTranslatef(static_cast<float>(6 + (k % 2) * 90), static_cast<float>(70 + (k / 2) * 30), 0);
    glListBase(c.base);
    glCallLists(3, c.type, c.data);
    glPopMatrix();
    ++k;
  }
  glListBase(0);
  glDeleteLists(tiles, 8);
  glDeleteLists(row, 2);
}

PINEDA_SCENE(dlist_compile_and_execute, "COMPILE_AND_EXECUTE, inherited colours, compiled arrays") {
  clear_frame(0.0f, 0.0f, 0.2f);
  window_projection(frame);
  const GLuint l = glGenLists(4);
  // Drawn while compiled, and twice more from the list.
  glNewList(l, GL_COMPILE_AND_EXECUTE);
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1, 1, 1);
  glVertex2f(40, 40);
  for (int i = 0; i <= 12; ++i) {
    const float a = static_cast<float>(i) * kPi / 6;
    palette_color(i);
    glVertex2f(40 + 30 * std::cos(a), 40 + 30 * std::sin(a));
  }
  glEnd();
  glEndList();
  glPushMatrix();
  glTranslatef(80, 0, 0);
  glCallList(l);
  glTranslatef(80, 0, 0);
  glScalef(1.5f, 0.75f, 1);
  glCallList(l);
  glPopMatrix();
  // No colour in the list before the second vertex: the first two vertices take the current
  // colour of each call; the colour set in the list stays current after it.
  glNewList(l + 1, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glVertex2f(50, 0);
  glColor3f(1, 1, 0);
  glVertex2f(25, 40);
  glEnd();
  glRectf(55, 0, 75, 40); // after the block: yellow
  glEndList();
  for (int i = 0; i < 3; ++i) {
    glPushMatrix();
    glTranslatef(static_cast<float>(10 + 80 * i), 90, 0);
    palette_color(2 + 3 * i);
    glCallList(l + 1);
    glPopMatrix();
  }
  // Arrays read when the list is compiled: the list keeps the first contents.
  GLfloat verts[8] = {0, 0, 60, 0, 60, 50, 0, 50};
  GLubyte colors[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  const GLushort idx[6] = {0, 1, 2, 2, 3, 0};
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, verts);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
  glNewList(l + 2, GL_COMPILE);
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, idx);
  glTranslatef(70, 0, 0);
  glDrawArrays(GL_LINE_LOOP, 0, 4);
  glBegin(GL_TRIANGLES);
  glArrayElement(0);
  glArrayElement(1);
  glArrayElement(3);
  glEnd();
  glEndList();
  for (float& v : verts)
    v *= 0.25f;
  colors[0] = 0;
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glPushMatrix();
  glTranslatef(20, 160, 0);
  glCallList(l + 2);
  glPopMatrix();
  glDeleteLists(l, 4);
}

PINEDA_SCENE(dlist_state_changes, "Lists with matrices, lighting, Material inside Begin/End") {
  clear_frame(0.05f, 0.05f, 0.05f);
  perspective(frame);
  const GLuint l = glGenLists(3);
  // A lit strip whose material changes between Begin and End.
  glNewList(l, GL_COMPILE);
  glPushAttrib(GL_LIGHTING_BIT | GL_ENABLE_BIT);
  lights_on();
  glDisable(GL_CULL_FACE);
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= 16; ++i) {
    const float a = static_cast<float>(i) * kPi / 16;
    if (i % 4 == 0) {
      const float* c = palette(i / 4);
      const GLfloat m[4] = {c[0], c[1], c[2], 1};
      glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, m);
    }
    glNormal3f(std::cos(a), 0, std::sin(a));
    glVertex3f(3 * std::cos(a), -1.5f, 3 * std::sin(a));
    glVertex3f(3 * std::cos(a), 1.5f, 3 * std::sin(a));
  }
  glEnd();
  glPopAttrib();
  glEndList();
  // A list that places the strip with the matrix stack and calls it twice.
  glNewList(l + 1, GL_COMPILE);
  glPushMatrix();
  glTranslatef(-4, 2.5f, -30);
  glRotatef(200, 0, 1, 0);
  glCallList(l);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(4, -2.5f, -30);
  glRotatef(30, 1, 0, 0);
  glRotatef(160, 0, 1, 0);
  glScalef(0.8f, 0.8f, 0.8f);
  glEnable(GL_NORMALIZE);
  glCallList(l);
  glDisable(GL_NORMALIZE);
  glPopMatrix();
  glEndList();
  glCallList(l + 1);
  // Unlit, colour-material-free geometry after the pops: lighting is off again.
  glNewList(l + 2, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glColor3f(0.9f, 0.9f, 0.2f);
  glVertex3f(-6, -6, -35);
  glVertex3f(-2, -6, -35);
  glVertex3f(-4, -3, -35);
  glEnd();
  glEndList();
  glCallList(l + 2);
  glDeleteLists(l, 3);
  lights_off();
}
