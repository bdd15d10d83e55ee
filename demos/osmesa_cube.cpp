// A spinning, depth-tested colour cube rendered off screen through OSMesa: the smallest
// complete program using Pineda as a library. Headless: --frames N renders N frames of the
// animation, --screenshot FILE writes the last one as a binary PPM, --check exits non-zero
// unless the picture shows the cube (several colours over the background).
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace {

constexpr int kWidth = 320, kHeight = 240;

void draw_cube() {
  // Each face gets its own corner colours so smooth shading shows across it.
  static const float v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  static const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                  {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
  glBegin(GL_QUADS);
  for (const auto& f : faces)
    for (int k : f) {
      glColor3f(0.2f + 0.8f * (v[k][0] > 0), 0.2f + 0.8f * (v[k][1] > 0),
                0.2f + 0.8f * (v[k][2] > 0));
      glVertex3fv(v[k]);
    }
  glEnd();
}

bool write_ppm(const std::string& path, const std::vector<unsigned char>& rgba) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return false;
  std::fprintf(f, "P6\n%d %d\n255\n", kWidth, kHeight);
  // OSMesa rows are bottom-up; PPM rows are top-down.
  for (int y = kHeight - 1; y >= 0; --y)
    for (int x = 0; x < kWidth; ++x) std::fwrite(&rgba[(y * kWidth + x) * 4], 1, 3, f);
  return std::fclose(f) == 0;
}

} // namespace

int main(int argc, char** argv) {
  int frames = 300;
  std::string screenshot;
  bool check = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) frames = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--screenshot") && i + 1 < argc) screenshot = argv[++i];
    else if (!std::strcmp(argv[i], "--check")) check = true;
    else {
      std::fprintf(stderr, "usage: %s [--frames N] [--screenshot out.ppm] [--check]\n", argv[0]);
      return 2;
    }
  }
  if (frames < 1) frames = 1;
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  std::vector<unsigned char> buffer(kWidth * kHeight * 4);
  if (ctx == nullptr || !OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kWidth, kHeight)) {
    std::fprintf(stderr, "osmesa_cube: cannot create an OSMesa context\n");
    return 1;
  }
  std::printf("renderer: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1.0, 1.0, -0.75, 0.75, 1.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
  const auto t0 = std::chrono::steady_clock::now();
  for (int frame = 0; frame < frames; ++frame) {
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -5.0f);
    glRotatef(static_cast<float>(frame) * 3.0f, 1.0f, 0.7f, 0.2f);
    draw_cube();
    glFinish();
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%d frames in %.3f s (%.1f FPS)\n", frames, secs, frames / secs);
  if (!screenshot.empty() && !write_ppm(screenshot, buffer)) {
    std::fprintf(stderr, "osmesa_cube: cannot write %s\n", screenshot.c_str());
    return 1;
  }
  int status = 0;
  if (check) {
    std::set<unsigned> colours;
    for (size_t i = 0; i < buffer.size(); i += 4)
      colours.insert(buffer[i] | buffer[i + 1] << 8 | buffer[i + 2] << 16);
    if (colours.size() < 50 || glGetError() != GL_NO_ERROR) {
      std::fprintf(stderr, "osmesa_cube: the picture does not show the cube\n");
      status = 1;
    }
  }
  OSMesaDestroyContext(ctx);
  return status;
}
