// Terrain: a fly-over of a fractal landscape fading into fog. The height field is value noise
// summed over five octaves, coloured by height (water, sand, grass, rock, snow), lit with a sun,
// modulated by a mipmapped detail texture and drawn as indexed triangle strips from vertex
// arrays. Keys: F cycles the fog mode (linear, exp, exp2, off), T toggles the detail texture,
// SPACE pauses.
#include "demo_common.h"

#include <algorithm>

namespace {

constexpr int kGrid = 160;       // vertices per side
constexpr float kCell = 1.5f;    // distance between vertices
constexpr float kWater = 0.0f;   // the water level
constexpr int kDetailSize = 64;  // detail texture side
constexpr float kFogEnd = 90.0f; // the far end of the linear fog and of the view

// Periodic value noise: a lattice of random values with `period` cells per side, smoothly
// interpolated.
class ValueNoise {
public:
  ValueNoise(int period, std::uint32_t seed)
      : period_(period), values_(static_cast<size_t>(period) * period) {
    demo::Rng rng(seed);
    for (float& v : values_)
      v = rng.range(-1.0f, 1.0f);
  }
  float at(float x, float y) const {
    const float fx = std::floor(x), fy = std::floor(y);
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
    const float tx = smooth(x - fx), ty = smooth(y - fy);
    const float a = lattice(ix, iy), b = lattice(ix + 1, iy);
    const float c = lattice(ix, iy + 1), d = lattice(ix + 1, iy + 1);
    return (a + (b - a) * tx) * (1 - ty) + (c + (d - c) * tx) * ty;
  }

private:
  static float smooth(float t) { return t * t * (3.0f - 2.0f * t); }
  float lattice(int x, int y) const {
    x = ((x % period_) + period_) % period_;
    y = ((y % period_) + period_) % period_;
    return values_[static_cast<size_t>(y) * period_ + x];
  }
  int period_;
  std::vector<float> values_;
};

struct Vertex {
  GLfloat position[3];
  GLfloat normal[3];
  GLubyte colour[4];
  GLfloat texcoord[2];
};

class Terrain : public demo::App {
public:
  void init() override {
    build_mesh();
    build_detail_texture();

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    const GLfloat sun[4] = {1.0f, 0.95f, 0.85f, 1.0f};
    const GLfloat ambient[4] = {0.35f, 0.38f, 0.45f, 1.0f};
    glLightfv(GL_LIGHT0, GL_DIFFUSE, sun);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    // The vertex colours are the material's ambient and diffuse colour.
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);

    glFogfv(GL_FOG_COLOR, kSky);
    glFogf(GL_FOG_START, 20.0f);
    glFogf(GL_FOG_END, kFogEnd);
    glFogf(GL_FOG_DENSITY, 0.025f);
    set_fog();

    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    const auto stride = static_cast<GLsizei>(sizeof(Vertex));
    glVertexPointer(3, GL_FLOAT, stride, vertices_[0].position);
    glNormalPointer(GL_FLOAT, stride, vertices_[0].normal);
    glColorPointer(4, GL_UNSIGNED_BYTE, stride, vertices_[0].colour);
    glTexCoordPointer(2, GL_FLOAT, stride, vertices_[0].texcoord);
  }

  void draw(const demo::Frame& f) override {
    if (!paused_) flight_ += f.time - last_time_;
    last_time_ = f.time;
    glViewport(0, 0, f.width, f.height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    demo::perspective(60.0, static_cast<double>(f.width) / f.height, 0.5, kFogEnd + 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    // The flight: a loop around the middle of the map, above the ground ahead, looking where
    // the path goes a little later.
    const float centre = (kGrid - 1) * kCell * 0.5f;
    const auto path = [&](double t) {
      const auto a = static_cast<float>(t * 0.12);
      demo::Vec3 p{centre + 60.0f * std::cos(a), 0.0f, centre + 45.0f * std::sin(a * 2.0f) * 0.8f};
      float ground = kWater;
      for (float ahead = 0.0f; ahead <= 12.0f; ahead += 3.0f) {
        const float b = a + ahead * 0.01f;
        ground = std::max(ground, height_at(centre + 60.0f * std::cos(b),
                                            centre + 45.0f * std::sin(b * 2.0f) * 0.8f));
      }
      p.y = ground + 6.0f;
      return p;
    };
    const demo::Vec3 eye = path(flight_);
    demo::Vec3 target = path(flight_ + 1.5);
    target.y -= 2.5f;
    demo::look_at(eye, target, {0, 1, 0});
    const GLfloat sun_dir[4] = {0.5f, 0.8f, 0.3f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, sun_dir);

    glClearColor(kSky[0], kSky[1], kSky[2], kSky[3]);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (texturing_)
      glEnable(GL_TEXTURE_2D);
    else
      glDisable(GL_TEXTURE_2D);
    for (size_t row = 0; row + 1 < kGrid; ++row)
      glDrawElements(GL_TRIANGLE_STRIP, 2 * kGrid, GL_UNSIGNED_INT, &strips_[row * 2 * kGrid]);
  }

  void key(int k) override {
    switch (k) {
    case GLFW_KEY_F:
      fog_mode_ = (fog_mode_ + 1) % 4;
      set_fog();
      break;
    case GLFW_KEY_T:
      texturing_ = !texturing_;
      break;
    case GLFW_KEY_SPACE:
      paused_ = !paused_;
      break;
    default:
      break;
    }
  }

private:
  static constexpr GLfloat kSky[4] = {0.62f, 0.70f, 0.80f, 1.0f};

  float height_at(float x, float z) const {
    // Bilinear in the grid, clamped to it.
    const float gx = std::clamp(x / kCell, 0.0f, kGrid - 1.001f);
    const float gz = std::clamp(z / kCell, 0.0f, kGrid - 1.001f);
    const int ix = static_cast<int>(gx), iz = static_cast<int>(gz);
    const float tx = gx - ix, tz = gz - iz;
    const auto h = [&](int xx, int zz) { return heights_[static_cast<size_t>(zz) * kGrid + xx]; };
    return (h(ix, iz) * (1 - tx) + h(ix + 1, iz) * tx) * (1 - tz) +
           (h(ix, iz + 1) * (1 - tx) + h(ix + 1, iz + 1) * tx) * tz;
  }

  void build_mesh() {
    const ValueNoise noise(32, 20240611);
    heights_.resize(static_cast<size_t>(kGrid) * kGrid);
    for (int z = 0; z < kGrid; ++z)
      for (int x = 0; x < kGrid; ++x) {
        float h = 0.0f, amplitude = 14.0f, freq = 1.0f / 24.0f;
        for (int octave = 0; octave < 5; ++octave) {
          h += amplitude * noise.at(x * freq + octave * 7.3f, z * freq + octave * 3.1f);
          amplitude *= 0.45f;
          freq *= 2.0f;
        }
        // Valleys flatten into lakes.
        heights_[static_cast<size_t>(z) * kGrid + x] = std::max(h + 5.0f, kWater);
      }
    vertices_.resize(heights_.size());
    for (int z = 0; z < kGrid; ++z)
      for (int x = 0; x < kGrid; ++x) {
        const auto h = [&](int xx, int zz) {
          xx = std::clamp(xx, 0, kGrid - 1);
          zz = std::clamp(zz, 0, kGrid - 1);
          return heights_[static_cast<size_t>(zz) * kGrid + xx];
        };
        const float y = h(x, z);
        Vertex& v = vertices_[static_cast<size_t>(z) * kGrid + x];
        v.position[0] = x * kCell;
        v.position[1] = y;
        v.position[2] = z * kCell;
        // Central differences.
        const demo::Vec3 n =
            demo::normalize({h(x - 1, z) - h(x + 1, z), 2.0f * kCell, h(x, z - 1) - h(x, z + 1)});
        v.normal[0] = n.x;
        v.normal[1] = n.y;
        v.normal[2] = n.z;
        const float steep = 1.0f - n.y;
        float c[3];
        if (y <= kWater)
          set(c, 0.15f, 0.35f, 0.55f);
        else if (y < 1.0f)
          set(c, 0.76f, 0.70f, 0.50f);
        else if (y > 13.0f)
          set(c, 0.95f, 0.95f, 0.97f);
        else if (steep > 0.25f || y > 9.0f)
          set(c, 0.45f, 0.42f, 0.38f);
        else
          set(c, 0.25f + 0.01f * y, 0.55f - 0.015f * y, 0.18f);
        for (int k = 0; k < 3; ++k)
          v.colour[k] = static_cast<GLubyte>(c[k] * 255.0f + 0.5f);
        v.colour[3] = 255;
        // The detail texture repeats every 4 cells.
        v.texcoord[0] = x * 0.25f;
        v.texcoord[1] = z * 0.25f;
      }
    // One strip per row of cells, winding counter-clockwise seen from above.
    for (int z = 0; z + 1 < kGrid; ++z)
      for (int x = 0; x < kGrid; ++x) {
        strips_.push_back(static_cast<GLuint>(z * kGrid + x));
        strips_.push_back(static_cast<GLuint>((z + 1) * kGrid + x));
      }
  }

  static void set(float* c, float r, float g, float b) {
    c[0] = r;
    c[1] = g;
    c[2] = b;
  }

  void build_detail_texture() {
    const ValueNoise noise(16, 77);
    std::vector<std::uint8_t> rgba(static_cast<size_t>(kDetailSize) * kDetailSize * 4);
    for (int y = 0; y < kDetailSize; ++y)
      for (int x = 0; x < kDetailSize; ++x) {
        const float n = 0.5f * noise.at(x / 4.0f, y / 4.0f) + 0.25f * noise.at(x / 2.0f, y / 2.0f);
        const auto g = static_cast<std::uint8_t>(std::clamp(215.0f + 40.0f * n, 0.0f, 255.0f));
        std::uint8_t* p = &rgba[(static_cast<size_t>(y) * kDetailSize + x) * 4];
        p[0] = g;
        p[1] = g;
        p[2] = g;
        p[3] = 255;
      }
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    demo::upload_mipmapped_rgba(kDetailSize, std::move(rgba));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  }

  void set_fog() {
    static const GLint modes[3] = {GL_LINEAR, GL_EXP, GL_EXP2};
    if (fog_mode_ == 3) {
      glDisable(GL_FOG);
      return;
    }
    glFogi(GL_FOG_MODE, modes[fog_mode_]);
    glEnable(GL_FOG);
  }

  std::vector<float> heights_;
  std::vector<Vertex> vertices_;
  std::vector<GLuint> strips_;
  GLuint texture_ = 0;
  int fog_mode_ = 0;
  bool texturing_ = true, paused_ = false;
  double flight_ = 0.0, last_time_ = 0.0;
};

} // namespace

int main(int argc, char** argv) {
  Terrain app;
  return demo::run("terrain", argc, argv, app);
}
