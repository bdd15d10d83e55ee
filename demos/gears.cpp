// Gears: three meshing gears, lit and flat shaded, each compiled once into a display list.
// Arrow keys turn the view, Z / Shift+Z roll it, SPACE pauses.
#include "demo_common.h"

namespace {

// One gear around the z axis, centred on z = 0. The outline (seen from +z, counter-clockwise)
// runs per tooth: root, rising flank to the tip, tip land, falling flank back to the root, root
// land. Faces: the front and back rings with their teeth, the outline's side walls with outward
// normals, and the bore.
void gear(float bore_radius, float radius, float width, int teeth, float tooth_depth) {
  const float r_bore = bore_radius;
  const float r_root = radius - tooth_depth * 0.5f;
  const float r_tip = radius + tooth_depth * 0.5f;
  const float step = 2.0f * static_cast<float>(demo::kPi) / static_cast<float>(teeth);
  const float hz = width * 0.5f;
  const auto at = [](float r, float a) { return demo::Vec3{r * std::cos(a), r * std::sin(a), 0}; };

  // The outline points: 4 per tooth.
  std::vector<demo::Vec3> outline;
  for (int i = 0; i < teeth; ++i) {
    const float a = static_cast<float>(i) * step;
    outline.push_back(at(r_root, a));
    outline.push_back(at(r_tip, a + step * 0.25f));
    outline.push_back(at(r_tip, a + step * 0.5f));
    outline.push_back(at(r_root, a + step * 0.75f));
  }

  // Front (+z) and back (-z) faces: a quad from the bore to the root for each root segment, and
  // the tooth itself.
  for (const float z : {hz, -hz}) {
    const bool front = z > 0;
    glNormal3f(0, 0, front ? 1.0f : -1.0f);
    glBegin(GL_QUADS);
    for (int i = 0; i < teeth; ++i) {
      const float a = static_cast<float>(i) * step;
      const float cuts[3] = {a, a + step * 0.75f, a + step};
      for (int s = 0; s < 2; ++s) {
        const demo::Vec3 q[4] = {at(r_bore, cuts[s]), at(r_root, cuts[s]), at(r_root, cuts[s + 1]),
                                 at(r_bore, cuts[s + 1])};
        for (int k = 0; k < 4; ++k) {
          const demo::Vec3& v = q[front ? k : 3 - k];
          glVertex3f(v.x, v.y, z);
        }
      }
      const demo::Vec3* t = &outline[static_cast<size_t>(i) * 4];
      for (int k = 0; k < 4; ++k) {
        const demo::Vec3& v = t[front ? k : 3 - k];
        glVertex3f(v.x, v.y, z);
      }
    }
    glEnd();
  }

  // Side walls along the outline: for a counter-clockwise outline the outward normal of the
  // edge (dx, dy) is (dy, -dx).
  glBegin(GL_QUADS);
  for (size_t k = 0; k < outline.size(); ++k) {
    const demo::Vec3 p = outline[k];
    const demo::Vec3 q = outline[(k + 1) % outline.size()];
    const demo::Vec3 n = demo::normalize({q.y - p.y, p.x - q.x, 0});
    glNormal3f(n.x, n.y, 0);
    glVertex3f(p.x, p.y, hz);
    glVertex3f(p.x, p.y, -hz);
    glVertex3f(q.x, q.y, -hz);
    glVertex3f(q.x, q.y, hz);
  }
  glEnd();

  // The bore, smooth shaded, normals towards the axis.
  glShadeModel(GL_SMOOTH);
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= teeth * 2; ++i) {
    const float a = -static_cast<float>(i) * step * 0.5f;
    glNormal3f(-std::cos(a), -std::sin(a), 0);
    glVertex3f(r_bore * std::cos(a), r_bore * std::sin(a), -hz);
    glVertex3f(r_bore * std::cos(a), r_bore * std::sin(a), hz);
  }
  glEnd();
  glShadeModel(GL_FLAT);
}

class Gears : public demo::App {
public:
  void init() override {
    const GLfloat light_pos[4] = {5.0f, 5.0f, 10.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_NORMALIZE);
    glShadeModel(GL_FLAT);

    const GLfloat colours[3][4] = {
        {0.8f, 0.1f, 0.0f, 1.0f}, {0.0f, 0.8f, 0.2f, 1.0f}, {0.2f, 0.2f, 1.0f, 1.0f}};
    const struct {
      float bore, radius, width;
      int teeth;
    } shapes[3] = {{1.0f, 4.0f, 1.0f, 20}, {0.5f, 2.0f, 2.0f, 10}, {1.3f, 2.0f, 0.5f, 10}};
    lists_ = glGenLists(3);
    for (int i = 0; i < 3; ++i) {
      glNewList(lists_ + static_cast<GLuint>(i), GL_COMPILE);
      glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, colours[i]);
      gear(shapes[i].bore, shapes[i].radius, shapes[i].width, shapes[i].teeth, 0.7f);
      glEndList();
    }
  }

  void draw(const demo::Frame& f) override {
    // 70 degrees a second, advanced by the frame's time step so that pausing holds the angle.
    if (!paused_) angle_ += static_cast<float>(f.time - last_time_) * 70.0f;
    last_time_ = f.time;
    glViewport(0, 0, f.width, f.height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    const double aspect = static_cast<double>(f.width) / f.height;
    glFrustum(-aspect, aspect, -1.0, 1.0, 5.0, 60.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -44.0f);

    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    glRotatef(view_x_, 1, 0, 0);
    glRotatef(view_y_, 0, 1, 0);
    glRotatef(view_z_, 0, 0, 1);
    // The 20-tooth gear drives the two 10-tooth gears at twice its speed, the other way round;
    // the phase offsets put a tooth of one into a gap of the other.
    const struct {
      float x, y, speed, phase;
    } place[3] = {
        {-3.0f, -2.0f, 1.0f, 0.0f}, {3.1f, -2.0f, -2.0f, -9.0f}, {-3.1f, 4.2f, -2.0f, -25.0f}};
    for (int i = 0; i < 3; ++i) {
      glPushMatrix();
      glTranslatef(place[i].x, place[i].y, 0.0f);
      glRotatef(place[i].speed * angle_ + place[i].phase, 0, 0, 1);
      glCallList(lists_ + static_cast<GLuint>(i));
      glPopMatrix();
    }
    glPopMatrix();
  }

  void key(int k) override {
    switch (k) {
    case GLFW_KEY_UP:
      view_x_ += 5;
      break;
    case GLFW_KEY_DOWN:
      view_x_ -= 5;
      break;
    case GLFW_KEY_LEFT:
      view_y_ += 5;
      break;
    case GLFW_KEY_RIGHT:
      view_y_ -= 5;
      break;
    case GLFW_KEY_Z:
      view_z_ += 5;
      break;
    case GLFW_KEY_SPACE:
      paused_ = !paused_;
      break;
    default:
      break;
    }
  }

private:
  GLuint lists_ = 0;
  float angle_ = 0.0f;
  double last_time_ = 0.0;
  float view_x_ = 20.0f, view_y_ = 30.0f, view_z_ = 0.0f;
  bool paused_ = false;
};

} // namespace

int main(int argc, char** argv) {
  Gears app;
  return demo::run("gears", argc, argv, app);
}
