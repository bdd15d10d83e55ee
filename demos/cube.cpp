// Cube: a lit, textured, spinning cube drawn from vertex arrays. The texture (bricks over a
// checker of mortar shades) is made in code and uploaded with its whole mipmap chain; the
// lighting is a white directional light plus a warm positional one, modulated by the texture.
// Keys: T toggles texturing, L lighting, M cycles the minification filter, SPACE pauses.
#include "demo_common.h"

namespace {

constexpr int kTexSize = 128;

// Bricks: 8 rows of 4 bricks, every other row offset by half a brick, each brick with its own
// shade and a little deterministic grain, mortar lines 2 texels wide.
std::vector<std::uint8_t> brick_texture() {
  std::vector<std::uint8_t> rgba(static_cast<size_t>(kTexSize) * kTexSize * 4);
  demo::Rng rng(1234);
  float shade[8][5];
  for (auto& row : shade)
    for (float& s : row)
      s = rng.range(0.75f, 1.0f);
  const int brick_h = kTexSize / 8, brick_w = kTexSize / 4;
  for (int y = 0; y < kTexSize; ++y)
    for (int x = 0; x < kTexSize; ++x) {
      const int row = y / brick_h;
      const int xs = x + (row % 2) * brick_w / 2;
      const int col = (xs / brick_w) % 5;
      const bool mortar = y % brick_h < 2 || xs % brick_w < 2;
      const float grain = rng.range(0.9f, 1.0f);
      std::uint8_t* p = &rgba[(static_cast<size_t>(y) * kTexSize + x) * 4];
      if (mortar) {
        const auto g = static_cast<std::uint8_t>(200 * grain);
        p[0] = g;
        p[1] = g;
        p[2] = static_cast<std::uint8_t>(g * 0.95f);
      } else {
        const float s = shade[row][col] * grain;
        p[0] = static_cast<std::uint8_t>(180 * s + 40);
        p[1] = static_cast<std::uint8_t>(70 * s + 20);
        p[2] = static_cast<std::uint8_t>(50 * s + 10);
      }
      p[3] = 255;
    }
  return rgba;
}

// 24 vertices (4 per face, each face with its own normal and texture coordinates).
struct Mesh {
  std::vector<GLfloat> position, normal, texcoord;
  std::vector<GLubyte> index;
};

Mesh cube_mesh() {
  Mesh m;
  // For each face: the normal, and two axes spanning it (right, up) as seen from outside.
  const float faces[6][3][3] = {
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
      {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}};
  const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int f = 0; f < 6; ++f) {
    const auto base = static_cast<GLubyte>(m.position.size() / 3);
    for (const auto& c : corners) {
      for (int k = 0; k < 3; ++k) {
        m.position.push_back(faces[f][0][k] + c[0] * faces[f][1][k] + c[1] * faces[f][2][k]);
        m.normal.push_back(faces[f][0][k]);
      }
      // Two repeats of the texture across a face.
      m.texcoord.push_back(c[0] + 1.0f);
      m.texcoord.push_back(c[1] + 1.0f);
    }
    for (int k : {0, 1, 2, 0, 2, 3})
      m.index.push_back(static_cast<GLubyte>(base + k));
  }
  return m;
}

class Cube : public demo::App {
public:
  void init() override {
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    demo::upload_mipmapped_rgba(kTexSize, brick_texture());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    set_min_filter();

    const GLfloat white[4] = {0.9f, 0.9f, 0.9f, 1.0f};
    const GLfloat warm[4] = {0.6f, 0.4f, 0.2f, 1.0f};
    const GLfloat ambient[4] = {0.15f, 0.15f, 0.2f, 1.0f};
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, warm);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.1f);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    const GLfloat material[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    const GLfloat specular[4] = {0.3f, 0.3f, 0.3f, 1.0f};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, material);
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT, GL_SHININESS, 24.0f);

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    mesh_ = cube_mesh();
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, mesh_.position.data());
    glNormalPointer(GL_FLOAT, 0, mesh_.normal.data());
    glTexCoordPointer(2, GL_FLOAT, 0, mesh_.texcoord.data());
  }

  void draw(const demo::Frame& f) override {
    if (!paused_) spin_ += f.time - last_time_;
    last_time_ = f.time;
    glViewport(0, 0, f.width, f.height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    demo::perspective(45.0, static_cast<double>(f.width) / f.height, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    // Lights in eye space: a fixed directional key light and a warm light circling the cube.
    const GLfloat key_dir[4] = {-0.4f, 0.6f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, key_dir);
    const float a = static_cast<float>(spin_) * 0.8f;
    const GLfloat warm_pos[4] = {3.0f * std::cos(a), -1.0f, -5.0f + 3.0f * std::sin(a), 1.0f};
    glLightfv(GL_LIGHT1, GL_POSITION, warm_pos);

    glClearColor(0.08f, 0.09f, 0.12f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (lighting_)
      glEnable(GL_LIGHTING);
    else
      glDisable(GL_LIGHTING);
    if (texturing_)
      glEnable(GL_TEXTURE_2D);
    else
      glDisable(GL_TEXTURE_2D);
    glColor3f(1, 1, 1);
    glTranslatef(0.0f, 0.0f, -5.5f);
    glRotatef(static_cast<float>(spin_) * 40.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(static_cast<float>(spin_) * 55.0f, 0.0f, 1.0f, 0.0f);
    glRotatef(25.0f, 0.0f, 0.0f, 1.0f);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh_.index.size()), GL_UNSIGNED_BYTE,
                   mesh_.index.data());
  }

  void key(int k) override {
    switch (k) {
    case GLFW_KEY_T:
      texturing_ = !texturing_;
      break;
    case GLFW_KEY_L:
      lighting_ = !lighting_;
      break;
    case GLFW_KEY_M:
      filter_ = (filter_ + 1) % 6;
      set_min_filter();
      break;
    case GLFW_KEY_SPACE:
      paused_ = !paused_;
      break;
    default:
      break;
    }
  }

private:
  void set_min_filter() {
    static const GLint filters[6] = {GL_LINEAR_MIPMAP_LINEAR,
                                     GL_NEAREST,
                                     GL_LINEAR,
                                     GL_NEAREST_MIPMAP_NEAREST,
                                     GL_LINEAR_MIPMAP_NEAREST,
                                     GL_NEAREST_MIPMAP_LINEAR};
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filters[filter_]);
  }

  Mesh mesh_;
  GLuint texture_ = 0;
  int filter_ = 0;
  bool texturing_ = true, lighting_ = true, paused_ = false;
  double spin_ = 0.0, last_time_ = 0.0;
};

} // namespace

int main(int argc, char** argv) {
  Cube app;
  return demo::run("cube", argc, argv, app);
}
