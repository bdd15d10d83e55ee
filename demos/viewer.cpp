// Viewer: a model viewer with a mouse orbit. The models are parametric surfaces built in code
// (a trefoil torus knot, a rounded superellipsoid, a lathed vase), smooth shaded with two
// lights and specular highlights, drawn with glDrawElements from vertex arrays over a grid of
// lines. Left drag orbits, the wheel zooms, M changes the model, W toggles wireframe, S flat /
// smooth shading. Headless, the camera orbits on its own.
#include "demo_common.h"

#include <algorithm>

namespace {

constexpr int kModels = 3;
const char* const kModelNames[kModels] = {"torus knot", "superellipsoid", "vase"};

// A point on model `m` at parameters u, v in [0, 1].
demo::Vec3 surface(int m, float u, float v) {
  const float tau = 2.0f * static_cast<float>(demo::kPi);
  switch (m) {
  case 0: {
    // A (2, 3) torus knot: a tube of radius 0.28 around the curve, framed by the curve's
    // tangent and its (numerical) second derivative.
    const auto curve = [&](float t) {
      const float a = t * tau;
      const float r = 1.0f + 0.45f * std::cos(3.0f * a);
      return demo::Vec3{r * std::cos(2.0f * a), 0.45f * std::sin(3.0f * a), r * std::sin(2.0f * a)};
    };
    const float h = 1e-3f;
    const demo::Vec3 c = curve(u), c1 = curve(u + h), c0 = curve(u - h);
    const demo::Vec3 t = demo::normalize(c1 - c0);
    const demo::Vec3 accel = c1 + c0 - c * 2.0f;
    const demo::Vec3 n = demo::normalize(accel - t * demo::dot(accel, t));
    const demo::Vec3 b = demo::cross(t, n);
    const float a = v * tau;
    return c + (n * std::cos(a) + b * std::sin(a)) * 0.28f;
  }
  case 1: {
    // A superellipsoid: a sphere with its cosines and sines raised to the power 0.4.
    const auto sp = [](float x, float e) { return std::copysign(std::pow(std::fabs(x), e), x); };
    const float lat = (v - 0.5f) * static_cast<float>(demo::kPi), lon = u * tau;
    const float cl = sp(std::cos(lat), 0.4f);
    return {1.1f * cl * sp(std::cos(lon), 0.4f), 1.1f * sp(std::sin(lat), 0.4f),
            1.1f * cl * sp(std::sin(lon), 0.4f)};
  }
  default: {
    // A vase: a profile radius(height) turned about the y axis.
    const float y = v * 2.6f - 1.3f;
    const float r = 0.55f + 0.35f * std::sin(v * 5.0f + 0.5f) * (1.0f - 0.5f * v) + 0.1f * v;
    const float a = -u * tau;
    return {r * std::cos(a), y, r * std::sin(a)};
  }
  }
}

struct Mesh {
  std::vector<GLfloat> position, normal;
  std::vector<GLuint> index;
};

// Samples the surface on a (nu + 1) x (nv + 1) grid; normals from the cross product of the
// numerical partial derivatives (du x dv points outwards for these three parametrisations, and
// the triangles wind counter-clockwise seen from outside, which two-sided lighting relies on).
Mesh build(int m, int nu, int nv) {
  Mesh mesh;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const float u = static_cast<float>(i) / nu, v = static_cast<float>(j) / nv;
      const demo::Vec3 p = surface(m, u, v);
      const float h = 1e-3f;
      // Clamp v at the poles so the difference stays inside the surface.
      const float v0 = std::max(v - h, 0.0f), v1 = std::min(v + h, 1.0f);
      const demo::Vec3 du = surface(m, u + h, v) - surface(m, u - h, v);
      const demo::Vec3 dv = surface(m, u, v1) - surface(m, u, v0);
      demo::Vec3 n = demo::normalize(demo::cross(du, dv));
      // At the poles du vanishes: the normal points along the axis.
      if (demo::dot(du, du) < 1e-12f) n = {0, v < 0.5f ? -1.0f : 1.0f, 0};
      mesh.position.insert(mesh.position.end(), {p.x, p.y, p.z});
      mesh.normal.insert(mesh.normal.end(), {n.x, n.y, n.z});
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const auto at = [&](int ii, int jj) { return static_cast<GLuint>(jj * (nu + 1) + ii); };
      mesh.index.insert(mesh.index.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j),
                                           at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

class Viewer : public demo::App {
public:
  void init() override {
    meshes_[0] = build(0, 240, 24);
    meshes_[1] = build(1, 64, 48);
    meshes_[2] = build(2, 64, 40);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    const GLfloat key[4] = {0.85f, 0.82f, 0.75f, 1.0f};
    const GLfloat fill[4] = {0.25f, 0.3f, 0.45f, 1.0f};
    glLightfv(GL_LIGHT0, GL_DIFFUSE, key);
    glLightfv(GL_LIGHT0, GL_SPECULAR, key);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, fill);
    const GLfloat diffuse[4] = {0.75f, 0.45f, 0.2f, 1.0f};
    const GLfloat specular[4] = {0.7f, 0.7f, 0.7f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
    // The vase is open at the top: its inside shows, lit as a back face.
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
  }

  void draw(const demo::Frame& f) override {
    if (f.headless) {
      yaw_ = 30.0f + static_cast<float>(f.time) * 40.0f;
      pitch_ = 25.0f;
    }
    glViewport(0, 0, f.width, f.height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    demo::perspective(45.0, static_cast<double>(f.width) / f.height, 0.5, 50.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    // Lights fixed to the camera: the key light up left, the fill light from below right.
    const GLfloat key_dir[4] = {-0.5f, 0.7f, 0.6f, 0.0f};
    const GLfloat fill_dir[4] = {0.7f, -0.4f, 0.3f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, key_dir);
    glLightfv(GL_LIGHT1, GL_POSITION, fill_dir);
    glTranslatef(0.0f, 0.0f, -distance_);
    glRotatef(pitch_, 1, 0, 0);
    glRotatef(yaw_, 0, 1, 0);

    glClearColor(0.12f, 0.12f, 0.14f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    // The floor grid.
    glDisable(GL_LIGHTING);
    glColor3f(0.35f, 0.35f, 0.4f);
    glBegin(GL_LINES);
    for (int i = -6; i <= 6; ++i) {
      const auto c = static_cast<float>(i) * 0.5f;
      glVertex3f(c, -1.6f, -3.0f);
      glVertex3f(c, -1.6f, 3.0f);
      glVertex3f(-3.0f, -1.6f, c);
      glVertex3f(3.0f, -1.6f, c);
    }
    glEnd();

    glEnable(GL_LIGHTING);
    glShadeModel(flat_ ? GL_FLAT : GL_SMOOTH);
    glPolygonMode(GL_FRONT_AND_BACK, wireframe_ ? GL_LINE : GL_FILL);
    const Mesh& mesh = meshes_[model_];
    glVertexPointer(3, GL_FLOAT, 0, mesh.position.data());
    glNormalPointer(GL_FLOAT, 0, mesh.normal.data());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.index.size()), GL_UNSIGNED_INT,
                   mesh.index.data());
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  }

  void key(int k) override {
    switch (k) {
    case GLFW_KEY_M:
      model_ = (model_ + 1) % kModels;
      std::printf("model: %s\n", kModelNames[model_]);
      break;
    case GLFW_KEY_W:
      wireframe_ = !wireframe_;
      break;
    case GLFW_KEY_S:
      flat_ = !flat_;
      break;
    default:
      break;
    }
  }

  void mouse_button(int button, bool pressed, double x, double y) override {
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    dragging_ = pressed;
    last_x_ = x;
    last_y_ = y;
  }

  void cursor(double x, double y) override {
    if (!dragging_) return;
    yaw_ += static_cast<float>(x - last_x_) * 0.5f;
    pitch_ = std::clamp(pitch_ + static_cast<float>(y - last_y_) * 0.5f, -89.0f, 89.0f);
    last_x_ = x;
    last_y_ = y;
  }

  void scroll(double dy) override {
    distance_ = std::clamp(distance_ * std::pow(0.9f, static_cast<float>(dy)), 2.0f, 30.0f);
  }

  std::vector<demo::ExtraOption> options() {
    return {{"--model", "K", "the model: 0 torus knot (default), 1 superellipsoid, 2 vase",
             [this](const char* v) {
               if (std::strlen(v) != 1 || v[0] < '0' || v[0] >= '0' + kModels) return false;
               model_ = v[0] - '0';
               return true;
             }}};
  }

private:
  Mesh meshes_[kModels];
  int model_ = 0;
  bool wireframe_ = false, flat_ = false, dragging_ = false;
  float yaw_ = 30.0f, pitch_ = 25.0f, distance_ = 6.0f;
  double last_x_ = 0, last_y_ = 0;
};

} // namespace

int main(int argc, char** argv) {
  Viewer app;
  return demo::run("viewer", argc, argv, app, app.options());
}
