// Display lists against immediate mode on random command sequences (GL 2.1 §5.4: "executed,
// in order, just as if they were issued without using a display list"). Each program of
// Begin/End blocks, vertices, current attributes, materials, matrices, enables, calls of
// other lists, and misplaced or invalid commands runs three ways from the same state:
// immediately, compiled (COMPILE) and then called, and in COMPILE_AND_EXECUTE mode. The
// images, the current attributes, the model-view matrix and the first error must be
// identical. Fixed seeds make every run the same.
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "api_fixture.h"

namespace {

class Rng {
public:
  explicit Rng(uint32_t seed) : s_(seed * 2654435761u + 12345u) {}
  uint32_t next() {
    s_ ^= s_ << 13;
    s_ ^= s_ >> 17;
    s_ ^= s_ << 5;
    return s_;
  }
  int below(int n) { return static_cast<int>(next() % static_cast<uint32_t>(n)); }
  // Multiples of 1/16 in [lo, hi): the same positions for every way of running.
  float range(float lo, float hi) {
    return lo + (hi - lo) * static_cast<float>(next() % 256) / 256.0f;
  }

private:
  uint32_t s_;
};

// One command with its arguments, so that a program can be issued several times.
struct Op {
  int kind;
  float a, b, c, d;
  int e;
};

constexpr int kOpKinds = 29;    // kind 24 is unused: see client_arrays_
constexpr GLuint kSubLists = 3; // lists 1..3 exist in every run; programs compile list 10

Op random_op(Rng& r) {
  Op op{r.below(kOpKinds), r.range(-1, 1), r.range(-1, 1),
        r.range(-1, 1),    r.range(0, 1),  r.below(16)};
  return op;
}

void issue(const Op& op) {
  static const GLenum kModes[] = {GL_POINTS,     GL_LINES,          GL_LINE_LOOP,    GL_LINE_STRIP,
                                  GL_TRIANGLES,  GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS,
                                  GL_QUAD_STRIP, GL_POLYGON};
  switch (op.kind) {
  case 0:
  case 1:
    glBegin(op.e < 15 ? kModes[op.e % 10] : 0x99);
    break;
  case 2:
    glEnd();
    break;
  case 3:
  case 4:
  case 5:
    glVertex3f(op.a, op.b, op.c * 0.5f);
    break;
  case 6:
    glVertex2f(op.a, op.b);
    break;
  case 7:
    glColor3f(op.d, op.a * 0.5f + 0.5f, op.b * 0.5f + 0.5f);
    break;
  case 8:
    glColor4ub(static_cast<GLubyte>(op.e * 16), 200, static_cast<GLubyte>(op.d * 255), 255);
    break;
  case 9:
    glNormal3f(op.a, op.b, op.c + 1.5f);
    break;
  case 10:
    glTexCoord2f(op.a, op.b);
    break;
  case 11:
    glEdgeFlag(op.e & 1 ? GL_TRUE : GL_FALSE);
    break;
  case 12:
    glSecondaryColor3f(op.d, op.d, op.a);
    break;
  case 13: {
    const GLfloat m[4] = {op.d, op.a * 0.5f + 0.5f, 0.3f, 1};
    glMaterialfv(op.e & 1 ? GL_FRONT : GL_FRONT_AND_BACK,
                 op.e & 2 ? GL_DIFFUSE : GL_AMBIENT_AND_DIFFUSE, m);
    break;
  }
  case 14:
    glRotatef(op.a * 30, 0, 0, 1);
    break;
  case 15:
    glTranslatef(op.a * 0.2f, op.b * 0.2f, 0);
    break;
  case 16:
    op.e & 1 ? glPushMatrix() : glPopMatrix();
    break;
  case 17: {
    static const GLenum kCaps[] = {GL_LIGHTING,  GL_COLOR_MATERIAL, GL_LIGHT0, GL_COLOR_SUM,
                                   GL_CULL_FACE, GL_LIGHT1,         0x1234};
    const GLenum cap = kCaps[op.e % 7];
    op.d < 0.5f ? glEnable(cap) : glDisable(cap);
    break;
  }
  case 18:
    glShadeModel(op.e & 1 ? GL_FLAT : GL_SMOOTH);
    break;
  case 19:
    glPolygonMode(GL_FRONT_AND_BACK, op.e & 1 ? GL_LINE : GL_FILL);
    break;
  case 20:
    glRectf(op.a, op.b, op.c, op.d);
    break;
  case 21:
    glCallList(1 + static_cast<GLuint>(op.e) % kSubLists);
    break;
  case 22: {
    const GLubyte lists[3] = {static_cast<GLubyte>(op.e % 4), 2, 1};
    glCallLists(3, GL_UNSIGNED_BYTE, lists);
    break;
  }
  case 23:
    glColorMaterial(GL_FRONT_AND_BACK, op.e & 1 ? GL_DIFFUSE : GL_AMBIENT);
    break;
  case 25:
    glDrawArrays(kModes[op.e % 10], op.e / 4, 3 + (op.e % 4));
    break;
  case 26: {
    static const GLushort kIndices[11] = {3, 0, 5, 1, 7, 2, 6, 4, 8, 0, 2};
    glDrawElements(kModes[op.e % 10], 3 + op.e % 6, GL_UNSIGNED_SHORT, kIndices + op.e % 3);
    break;
  }
  case 27:
    glArrayElement(op.e % 9);
    break;
  case 28:
    if (op.e & 1)
      glPushAttrib(op.e & 2 ? GL_CURRENT_BIT : GL_LIGHTING_BIT | GL_CURRENT_BIT);
    else
      glPopAttrib();
    break;
  }
}

// The client arrays the array commands read: 9 elements (ArrayElement's index may be 8).
struct Arrays {
  GLfloat vertex[9][3];
  GLubyte color[9][4];
  GLfloat normal[9][3];
};

Arrays make_arrays() {
  Arrays a{};
  Rng r(77);
  for (int i = 0; i < 9; ++i) {
    for (int c = 0; c < 3; ++c) {
      a.vertex[i][c] = r.range(-1, 1);
      a.normal[i][c] = r.range(-1, 1);
    }
    for (int c = 0; c < 4; ++c)
      a.color[i][c] = static_cast<GLubyte>(r.below(256));
  }
  return a;
}

struct Outcome {
  std::vector<uint8_t> image;
  std::vector<float> state;
  GLenum error;
};

class DListRandom : public GLTest {
protected:
  // The state every way of running starts from; lists 1..3 are small programs themselves.
  void reset() {
    glGetError();
    // Pushed groups first: popping them afterwards would undo the resets below.
    GLint attribs = 0;
    glGetIntegerv(GL_ATTRIB_STACK_DEPTH, &attribs);
    for (; attribs > 0; --attribs)
      glPopAttrib();

    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_MODELVIEW);
    GLint depth = 1;
    glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &depth);
    for (; depth > 1; --depth)
      glPopMatrix();
    glLoadIdentity();
    glColor4f(0.5f, 0.5f, 0.5f, 1);
    glNormal3f(0, 0, 1);
    glTexCoord4f(0, 0, 0, 1);
    glSecondaryColor3f(0, 0, 0);
    glEdgeFlag(GL_TRUE);
    glDisable(GL_LIGHTING);
    glDisable(GL_COLOR_MATERIAL);
    glDisable(GL_COLOR_SUM);
    glDisable(GL_CULL_FACE);
    glEnable(GL_LIGHT0);
    glDisable(GL_LIGHT1);
    glShadeModel(GL_SMOOTH);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    const GLfloat amb[4] = {0.2f, 0.2f, 0.2f, 1}, dif[4] = {0.8f, 0.8f, 0.8f, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
    glListBase(0);
    static const Arrays arrays = make_arrays();
    // Client state executes immediately even while compiling (§5.4), also where the list
    // has an open Begin, so a program that changed it would legitimately differ between
    // immediate mode and a list: each seed picks its enables up front instead.
    const GLenum kArrays[3] = {GL_VERTEX_ARRAY, GL_COLOR_ARRAY, GL_NORMAL_ARRAY};
    for (int i = 0; i < 3; ++i)
      client_arrays_&(1 << i) ? glEnableClientState(kArrays[i]) : glDisableClientState(kArrays[i]);
    glVertexPointer(3, GL_FLOAT, 0, arrays.vertex);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, arrays.color);
    glNormalPointer(GL_FLOAT, 0, arrays.normal);
  }

  Outcome capture() {
    Outcome o;
    o.error = glGetError();
    o.image = buf_;
    GLfloat v[16];
    for (GLenum pname : {GL_CURRENT_COLOR, GL_CURRENT_NORMAL, GL_CURRENT_TEXTURE_COORDS,
                         GL_CURRENT_SECONDARY_COLOR, GL_MODELVIEW_MATRIX}) {
      const int n = pname == GL_MODELVIEW_MATRIX ? 16 : pname == GL_CURRENT_NORMAL ? 3 : 4;
      glGetFloatv(pname, v);
      o.state.insert(o.state.end(), v, v + n);
    }
    GLboolean edge = GL_FALSE;
    glGetBooleanv(GL_EDGE_FLAG, &edge);
    o.state.push_back(edge ? 1.0f : 0.0f);
    GLfloat mat[4];
    glGetMaterialfv(GL_FRONT, GL_DIFFUSE, mat);
    o.state.insert(o.state.end(), mat, mat + 4);
    return o;
  }

  int client_arrays_ = 0; // bits: vertex, colour, normal arrays enabled

  // Ends any Begin the program left open, so that the captures are legal.
  static void close() {
    glEnd();
    glGetError();
  }

  // Runs a program three ways; true when they agree. `why` says how they differ.
  bool agree(const std::vector<std::vector<Op>>& sub, const std::vector<Op>& program,
             std::string* why) {
    reset(); // the client state the sub-lists' arrays are read with
    for (GLuint l = 0; l < kSubLists; ++l) {
      glNewList(l + 1, GL_COMPILE);
      for (const Op& op : sub[l])
        issue(op);
      glEndList();
    }
    reset();
    for (const Op& op : program)
      issue(op);
    const GLenum first_error = glGetError();
    close();
    Outcome immediate = capture();
    immediate.error = first_error;

    reset();
    glNewList(10, GL_COMPILE);
    for (const Op& op : program)
      issue(op);
    glEndList();
    const GLenum compile_error = glGetError();
    reset();
    glCallList(10);
    const GLenum list_error = glGetError();
    close();
    Outcome compiled = capture();
    compiled.error = list_error;

    reset();
    glNewList(10, GL_COMPILE_AND_EXECUTE);
    for (const Op& op : program)
      issue(op);
    const GLenum both_error = glGetError();
    close();
    glEndList();
    Outcome both = capture();
    both.error = both_error;

    std::ostringstream w;
    if (compile_error != GL_NO_ERROR) w << " compiling generated an error;";
    for (const auto& [name, o] :
         {std::pair{"COMPILE", &compiled}, std::pair{"COMPILE_AND_EXECUTE", &both}}) {
      if (o->error != immediate.error) w << ' ' << name << ": first error;";
      if (o->state != immediate.state) w << ' ' << name << ": state;";
      if (o->image != immediate.image) w << ' ' << name << ": image;";
    }
    *why = w.str();
    return why->empty();
  }
};

std::string describe(const std::vector<Op>& ops) {
  std::ostringstream out;
  for (const Op& op : ops)
    out << ' ' << op.kind << '/' << op.e;
  return out.str();
}

TEST_F(DListRandom, ListsRunAsImmediateMode) {
  for (uint32_t seed = 0; seed < 2000; ++seed) {
    Rng r(seed);
    std::vector<std::vector<Op>> sub(kSubLists);
    for (auto& ops : sub)
      for (int i = r.below(8); i > 0; --i) {
        Op op = random_op(r);
        if (op.kind == 21 || op.kind == 22) op.kind = 3; // sub-lists call no lists
        ops.push_back(op);
      }
    std::vector<Op> program;
    for (int i = 8 + r.below(40); i > 0; --i)
      program.push_back(random_op(r));
    client_arrays_ = r.below(8) | 1;
    std::string why;
    if (agree(sub, program, &why)) continue;
    // Shrink the failing program (commands removed one at a time while it still fails) so
    // that the report is short: kind/e pairs, see issue().
    std::string shrunk_why = why;
    for (bool again = true; again;) {
      again = false;
      for (auto* ops : {&program, &sub[0], &sub[1], &sub[2]}) {
        for (size_t i = 0; i < ops->size(); ++i) {
          std::vector<Op> fewer = *ops;
          fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(i));
          std::swap(*ops, fewer);
          std::string w;
          if (!agree(sub, program, &w)) {
            shrunk_why = w;
            again = true;
            --i;
          } else {
            std::swap(*ops, fewer);
          }
        }
      }
    }
    ADD_FAILURE() << "seed " << seed << ":" << why << "\nshrunk:" << shrunk_why
                  << "\n program:" << describe(program) << "\n list 1:" << describe(sub[0])
                  << "\n list 2:" << describe(sub[1]) << "\n list 3:" << describe(sub[2]);
    break;
  }
}

} // namespace
