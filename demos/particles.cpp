// Particles: a fountain of sparks over a checkered floor. Each spark is a textured billboard
// (a soft round sprite made in code) blended additively, so overlapping sparks glow; the floor
// is depth-tested and the sparks test against it without writing depth. Every spark's state
// is a closed-form function of time (launched at a fixed rate with a velocity drawn from its
// index, one bounce off the floor), so a frame depends only on its time.
// Keys: B toggles additive / alpha blending, P draws points instead of sprites, SPACE pauses,
// left drag turns the view.
#include "demo_common.h"

#include <algorithm>

namespace {

constexpr int kRate = 400;        // sparks launched per second
constexpr float kLifetime = 3.0f; // seconds
constexpr float kGravity = -9.8f;
constexpr float kBounce = 0.45f; // vertical speed kept at the bounce
constexpr int kSpriteSize = 32;

struct Spark {
  demo::Vec3 position;
  float age; // 0 at launch, 1 at the end of its life
  float hue; // 0: gold, 1: red
};

// The spark launched as number `index`, at time `t` (no value when not alive then).
bool spark_at(std::uint32_t index, double t, Spark& out) {
  const double launch = static_cast<double>(index) / kRate;
  const auto age = static_cast<float>(t - launch);
  if (age < 0.0f || age >= kLifetime) return false;
  // Seeded by the index alone: the same spark whenever it is evaluated.
  demo::Rng rng(index * 2654435761u + 12345u);
  const float angle = rng.range(0.0f, 2.0f * static_cast<float>(demo::kPi));
  const float spread = rng.range(0.4f, 2.4f);
  const float up = rng.range(7.0f, 10.0f);
  demo::Vec3 v{spread * std::cos(angle), up, spread * std::sin(angle)};
  demo::Vec3 p{0.0f, 0.5f, 0.0f};
  // Time of impact with the floor: p.y + v.y t + g t^2 / 2 = 0.
  const float t_hit = (-v.y - std::sqrt(v.y * v.y - 2.0f * kGravity * p.y)) / kGravity;
  float tt = age;
  if (age > t_hit) {
    p = p + v * t_hit;
    p.y = 0.0f;
    v.y = -(v.y + kGravity * t_hit) * kBounce;
    tt = age - t_hit;
  }
  out.position = {p.x + v.x * tt, p.y + v.y * tt + 0.5f * kGravity * tt * tt, p.z + v.z * tt};
  out.position.y = std::max(out.position.y, 0.0f);
  out.age = age / kLifetime;
  out.hue = rng.uniform();
  return true;
}

class Particles : public demo::App {
public:
  void init() override {
    // The sprite: white, with an alpha that falls off like a Gaussian from the centre.
    std::vector<std::uint8_t> rgba(static_cast<size_t>(kSpriteSize) * kSpriteSize * 4);
    for (int y = 0; y < kSpriteSize; ++y)
      for (int x = 0; x < kSpriteSize; ++x) {
        const float dx = (x + 0.5f) / kSpriteSize * 2.0f - 1.0f;
        const float dy = (y + 0.5f) / kSpriteSize * 2.0f - 1.0f;
        const float a = std::exp(-4.0f * (dx * dx + dy * dy));
        std::uint8_t* p = &rgba[(static_cast<size_t>(y) * kSpriteSize + x) * 4];
        p[0] = p[1] = p[2] = 255;
        p[3] = static_cast<std::uint8_t>(std::clamp(a * 255.0f, 0.0f, 255.0f));
      }
    glGenTextures(1, &sprite_);
    glBindTexture(GL_TEXTURE_2D, sprite_);
    demo::upload_mipmapped_rgba(kSpriteSize, std::move(rgba));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_DEPTH_TEST);
  }

  void draw(const demo::Frame& f) override {
    if (!paused_) time_ += f.time - last_time_;
    last_time_ = f.time;
    glViewport(0, 0, f.width, f.height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    demo::perspective(50.0, static_cast<double>(f.width) / f.height, 0.5, 60.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, -2.5f, -13.0f);
    glRotatef(pitch_, 1, 0, 0);
    glRotatef(yaw_ + static_cast<float>(time_) * 10.0f, 0, 1, 0);

    glClearColor(0.02f, 0.02f, 0.05f, 1.0f);
    // The depth write mask also masks the depth clear (GL 2.1 §4.2.3).
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    // The floor: a checker of dark tiles, writing depth.
    glDisable(GL_BLEND);
    glDisable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    for (int z = -8; z < 8; ++z)
      for (int x = -8; x < 8; ++x) {
        const float c = ((x + z) & 1) != 0 ? 0.30f : 0.18f;
        glColor3f(c, c, c * 1.3f);
        glVertex3f(static_cast<float>(x), 0.0f, static_cast<float>(z));
        glVertex3f(static_cast<float>(x), 0.0f, static_cast<float>(z + 1));
        glVertex3f(static_cast<float>(x + 1), 0.0f, static_cast<float>(z + 1));
        glVertex3f(static_cast<float>(x + 1), 0.0f, static_cast<float>(z));
      }
    glEnd();

    // The sparks: depth-tested against the floor, not writing depth, blended.
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    if (additive_)
      glBlendFunc(GL_SRC_ALPHA, GL_ONE);
    else
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    // Billboard axes: the rows of the modelview's rotation are the eye's right and up in
    // object coordinates.
    GLfloat mv[16];
    glGetFloatv(GL_MODELVIEW_MATRIX, mv);
    const demo::Vec3 right{mv[0], mv[4], mv[8]};
    const demo::Vec3 up{mv[1], mv[5], mv[9]};
    const auto newest = static_cast<std::int64_t>(time_ * kRate);
    const auto oldest =
        std::max<std::int64_t>(0, newest - static_cast<std::int64_t>(kLifetime * kRate));
    if (points_) {
      glPointSize(3.0f);
      glBegin(GL_POINTS);
    } else {
      glEnable(GL_TEXTURE_2D);
      glBindTexture(GL_TEXTURE_2D, sprite_);
      glBegin(GL_QUADS);
    }
    for (std::int64_t i = oldest; i <= newest; ++i) {
      Spark s;
      if (!spark_at(static_cast<std::uint32_t>(i), time_, s)) continue;
      // From white-gold through orange to a dim red as it ages.
      const float life = 1.0f - s.age;
      glColor4f(1.0f, 0.35f + 0.6f * life * (1.0f - 0.5f * s.hue), 0.1f + 0.5f * life * life,
                0.25f + 0.75f * life);
      if (points_) {
        glVertex3f(s.position.x, s.position.y, s.position.z);
        continue;
      }
      const float size = 0.12f + 0.12f * s.age;
      const demo::Vec3 r = right * size, u = up * size;
      const demo::Vec3 corners[4] = {s.position - r - u, s.position + r - u, s.position + r + u,
                                     s.position - r + u};
      const float st[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (int k = 0; k < 4; ++k) {
        glTexCoord2fv(st[k]);
        glVertex3f(corners[k].x, corners[k].y, corners[k].z);
      }
    }
    glEnd();
    glDisable(GL_TEXTURE_2D);
  }

  void key(int k) override {
    switch (k) {
    case GLFW_KEY_B:
      additive_ = !additive_;
      break;
    case GLFW_KEY_P:
      points_ = !points_;
      break;
    case GLFW_KEY_SPACE:
      paused_ = !paused_;
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
    yaw_ += static_cast<float>(x - last_x_) * 0.4f;
    pitch_ = std::clamp(pitch_ + static_cast<float>(y - last_y_) * 0.4f, -10.0f, 80.0f);
    last_x_ = x;
    last_y_ = y;
  }

private:
  GLuint sprite_ = 0;
  bool additive_ = true, points_ = false, paused_ = false, dragging_ = false;
  float yaw_ = 0.0f, pitch_ = 15.0f;
  double last_x_ = 0, last_y_ = 0;
  double time_ = 0.0, last_time_ = 0.0;
};

} // namespace

int main(int argc, char** argv) {
  Particles app;
  return demo::run("particles", argc, argv, app);
}
