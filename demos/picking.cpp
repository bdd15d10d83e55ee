// Picking: twelve spinning solids on a grid; a click picks the one under the cursor with the
// selection buffer (glRenderMode(GL_SELECT), glSelectBuffer, a pick matrix, glPushName /
// glLoadName with two levels of names: the row, then the object) and draws it highlighted (larger,
// glowing, outlined). Headless, the program picks on its own in the last frame: first an empty
// corner, then the centre of one object (--pick-object K, default 6) or a given pixel (--pick X,Y),
// and prints the hit records and the object picked.
#include "demo_common.h"

#include <algorithm>

namespace {

constexpr int kColumns = 4, kRows = 3, kObjects = kColumns * kRows;
constexpr int kShapes = 4;
const char* const kShapeNames[kShapes] = {"cube", "octahedron", "pyramid", "prism"};
const char* const kColourNames[kObjects] = {"red",  "orange", "yellow", "lime",   "green",  "teal",
                                            "cyan", "azure",  "blue",   "violet", "purple", "pink"};

// One flat-shaded face: the normal from the first three corners (counter-clockwise outside).
void face(std::initializer_list<demo::Vec3> corners) {
  const demo::Vec3* c = corners.begin();
  const demo::Vec3 n = demo::normalize(cross(c[1] - c[0], c[2] - c[0]));
  glNormal3f(n.x, n.y, n.z);
  glBegin(GL_POLYGON);
  for (const demo::Vec3& v : corners)
    glVertex3f(v.x, v.y, v.z);
  glEnd();
}

void shape(int kind) {
  switch (kind) {
  case 0: { // cube
    const float s = 0.55f;
    const demo::Vec3 v[8] = {{-s, -s, -s}, {s, -s, -s}, {s, s, -s}, {-s, s, -s},
                             {-s, -s, s},  {s, -s, s},  {s, s, s},  {-s, s, s}};
    face({v[4], v[5], v[6], v[7]});
    face({v[1], v[0], v[3], v[2]});
    face({v[5], v[1], v[2], v[6]});
    face({v[0], v[4], v[7], v[3]});
    face({v[7], v[6], v[2], v[3]});
    face({v[0], v[1], v[5], v[4]});
    break;
  }
  case 1: { // octahedron
    const float s = 0.8f;
    const demo::Vec3 top{0, s, 0}, bottom{0, -s, 0};
    const demo::Vec3 ring[4] = {{s, 0, 0}, {0, 0, -s}, {-s, 0, 0}, {0, 0, s}};
    for (int i = 0; i < 4; ++i) {
      face({ring[(i + 1) % 4], ring[i], top});
      face({ring[i], ring[(i + 1) % 4], bottom});
    }
    break;
  }
  case 2: { // square pyramid
    const float s = 0.6f;
    const demo::Vec3 apex{0, 0.7f, 0};
    const demo::Vec3 base[4] = {{-s, -0.5f, -s}, {s, -0.5f, -s}, {s, -0.5f, s}, {-s, -0.5f, s}};
    face({base[0], base[1], base[2], base[3]});
    for (int i = 0; i < 4; ++i)
      face({base[(i + 1) % 4], base[i], apex});
    break;
  }
  default: { // triangular prism
    const float h = 0.6f;
    demo::Vec3 a[3], b[3];
    for (int i = 0; i < 3; ++i) {
      const float ang = static_cast<float>(i) * 2.0f * static_cast<float>(demo::kPi) / 3.0f;
      a[i] = {0.65f * std::cos(ang), 0.65f * std::sin(ang), h};
      b[i] = {0.65f * std::cos(ang), 0.65f * std::sin(ang), -h};
    }
    face({a[0], a[1], a[2]});
    face({b[2], b[1], b[0]});
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      face({a[i], b[i], b[j], a[j]});
    }
    break;
  }
  }
}

struct Hit {
  std::vector<GLuint> names;
  double zmin = 0, zmax = 0;
};

class Picking : public demo::App {
public:
  std::vector<demo::ExtraOption> options() {
    return {{"--pick", "X,Y", "headless: pick at window pixel X,Y (origin top left)",
             [this](const char* v) {
               return std::sscanf(v, "%lf,%lf", &pick_x_, &pick_y_) == 2 && pick_x_ >= 0 &&
                      pick_y_ >= 0 && (pick_given_ = true);
             }},
            {"--pick-object", "K", "headless: pick the centre of object K (0-11, default 6)",
             [this](const char* v) {
               char* end = nullptr;
               const long k = std::strtol(v, &end, 10);
               if (end == v || *end != '\0' || k < 0 || k >= kObjects) return false;
               pick_object_ = static_cast<int>(k);
               return true;
             }}};
  }

  void init() override {
    lists_ = glGenLists(kShapes);
    for (int i = 0; i < kShapes; ++i) {
      glNewList(lists_ + static_cast<GLuint>(i), GL_COMPILE);
      shape(i);
      glEndList();
    }
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glShadeModel(GL_FLAT);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    const GLfloat specular[4] = {0.4f, 0.4f, 0.4f, 1.0f};
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT, GL_SHININESS, 32.0f);
  }

  void draw(const demo::Frame& f) override {
    width_ = f.width;
    height_ = f.height;
    time_ = f.time;
    if (f.headless && f.index == f.frames - 1) scripted_picks();
    glViewport(0, 0, f.width, f.height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    projection();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    const GLfloat light_dir[4] = {0.3f, 0.5f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, light_dir);
    glClearColor(0.18f, 0.2f, 0.24f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_LIGHTING);
    scene(false);
  }

  void mouse_button(int button, bool pressed, double x, double y) override {
    if (button != GLFW_MOUSE_BUTTON_LEFT || !pressed) return;
    picked_ = pick(x, y);
  }

private:
  void projection() const {
    demo::perspective(40.0, static_cast<double>(width_) / height_, 1.0, 30.0);
  }

  // Object k's place and spin; the camera looks down the -z axis at the grid.
  void object_transform(int k) const {
    const int row = k / kColumns, col = k % kColumns;
    glTranslatef((static_cast<float>(col) - 1.5f) * 2.0f, (1.0f - static_cast<float>(row)) * 2.0f,
                 -11.0f);
    const float a = static_cast<float>(time_) * (30.0f + 7.0f * static_cast<float>(k));
    glRotatef(a, 0.3f + 0.1f * static_cast<float>(k % 3), 1.0f, 0.2f);
  }

  // Draws every object; in selection mode each carries the names {row, object}.
  void scene(bool select) const {
    if (select) glInitNames();
    for (int row = 0; row < kRows; ++row) {
      if (select) glPushName(static_cast<GLuint>(100 + row));
      if (select) glPushName(0);
      for (int col = 0; col < kColumns; ++col) {
        const int k = row * kColumns + col;
        if (select) glLoadName(static_cast<GLuint>(k));
        glPushMatrix();
        object_transform(k);
        if (k == picked_ && !select) {
          // The picked object: larger, and glowing.
          glScalef(1.25f, 1.25f, 1.25f);
          const GLfloat glow[4] = {0.45f, 0.4f, 0.1f, 1.0f};
          glMaterialfv(GL_FRONT, GL_EMISSION, glow);
        }
        const float hue = static_cast<float>(k) / kObjects;
        glColor3f(0.5f + 0.5f * std::cos(6.2832f * hue),
                  0.5f + 0.5f * std::cos(6.2832f * (hue - 0.333f)),
                  0.5f + 0.5f * std::cos(6.2832f * (hue - 0.667f)));
        glCallList(lists_ + static_cast<GLuint>(k % kShapes));
        if (k == picked_ && !select) {
          const GLfloat none[4] = {0, 0, 0, 1};
          glMaterialfv(GL_FRONT, GL_EMISSION, none);
          // A yellow outline: the edges of the front faces. The solids are convex, so with back
          // faces culled these are exactly the visible edges, and no depth test is needed.
          glDisable(GL_LIGHTING);
          glDisable(GL_DEPTH_TEST);
          glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
          glColor3f(1.0f, 0.95f, 0.3f);
          glCallList(lists_ + static_cast<GLuint>(k % kShapes));
          glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
          glEnable(GL_DEPTH_TEST);
          glEnable(GL_LIGHTING);
        }
        glPopMatrix();
      }
      if (select) glPopName();
      if (select) glPopName();
    }
  }

  // Renders the scene in selection mode through a 5x5-pixel pick region around (x, y) (window
  // pixels, origin top left) and returns the nearest object hit, or -1.
  int pick(double x, double y) {
    GLuint buffer[512];
    glSelectBuffer(512, buffer);
    glRenderMode(GL_SELECT);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    // gluPickMatrix: map the pick region onto the whole clip volume.
    const double region = 5.0;
    const double wx = x, wy = height_ - y; // GL window coordinates, origin bottom left
    glTranslated((width_ - 2.0 * wx) / region, (height_ - 2.0 * wy) / region, 0.0);
    glScaled(width_ / region, height_ / region, 1.0);
    projection();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    scene(true);
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    const GLint count = glRenderMode(GL_RENDER);

    // Hit records: name count, min and max window z scaled to 2^32 - 1, the names.
    std::vector<Hit> hits;
    size_t at = 0;
    for (GLint i = 0; i < count && at + 3 <= 512; ++i) {
      Hit h;
      const GLuint n = buffer[at];
      h.zmin = buffer[at + 1] / 4294967295.0;
      h.zmax = buffer[at + 2] / 4294967295.0;
      at += 3;
      for (GLuint j = 0; j < n && at < 512; ++j)
        h.names.push_back(buffer[at++]);
      hits.push_back(h);
    }
    std::printf("pick at (%.0f, %.0f): %d hit%s\n", x, y, count, count == 1 ? "" : "s");
    int best = -1;
    double best_z = 2.0;
    for (const Hit& h : hits) {
      std::printf("  hit: names {");
      for (size_t j = 0; j < h.names.size(); ++j)
        std::printf("%s%u", j > 0 ? ", " : "", h.names[j]);
      std::printf("} z %.3f..%.3f\n", h.zmin, h.zmax);
      if (h.names.size() == 2 && h.zmin < best_z) {
        best_z = h.zmin;
        best = static_cast<int>(h.names[1]);
      }
    }
    if (best >= 0)
      std::printf("picked: object %d (%s %s, row %d)\n", best, kColourNames[best],
                  kShapeNames[best % kShapes], best / kColumns);
    else
      std::printf("picked: nothing\n");
    std::fflush(stdout);
    return best;
  }

  // Where object k's centre lands, in window pixels with the origin top left.
  void project_centre(int k, double& x, double& y) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    projection();
    GLdouble p[16];
    glGetDoublev(GL_PROJECTION_MATRIX, p);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    const int row = k / kColumns, col = k % kColumns;
    const double c[4] = {(col - 1.5) * 2.0, (1.0 - row) * 2.0, -11.0, 1.0};
    double clip[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        clip[i] += p[j * 4 + i] * c[j];
    x = (clip[0] / clip[3] * 0.5 + 0.5) * width_;
    y = height_ - (clip[1] / clip[3] * 0.5 + 0.5) * height_;
  }

  void scripted_picks() {
    pick(2.0, 2.0); // a corner: nothing there
    double x = pick_x_, y = pick_y_;
    if (!pick_given_) project_centre(pick_object_, x, y);
    picked_ = pick(std::floor(x), std::floor(y));
  }

  GLuint lists_ = 0;
  int width_ = 1, height_ = 1;
  double time_ = 0.0;
  int picked_ = -1;
  int pick_object_ = 6;
  bool pick_given_ = false;
  double pick_x_ = 0, pick_y_ = 0;
};

} // namespace

int main(int argc, char** argv) {
  Picking app;
  return demo::run("picking", argc, argv, app, app.options());
}
