// A spinning, depth-tested colour cube rendered off screen through OSMesa: the smallest
// complete program using Pineda as a library. Headless: --frames N renders N frames of the
// animation, --screenshot FILE writes the last one as a binary PPM, --check exits non-zero
// unless the picture shows the cube (several colours over the background). egl_cube.cpp draws
// the same through EGL.
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "cube_scene.h"

int main(int argc, char** argv) {
  using namespace cube;
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
  setup();
  const auto t0 = std::chrono::steady_clock::now();
  for (int frame = 0; frame < frames; ++frame)
    draw_frame(frame);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%d frames in %.3f s (%.1f FPS)\n", frames, secs, frames / secs);
  // OSMesa rows are bottom-up, as write_ppm expects.
  if (!screenshot.empty() && !write_ppm(screenshot, buffer)) {
    std::fprintf(stderr, "osmesa_cube: cannot write %s\n", screenshot.c_str());
    return 1;
  }
  int status = 0;
  if (check && !shows_cube(buffer)) {
    std::fprintf(stderr, "osmesa_cube: the picture does not show the cube\n");
    status = 1;
  }
  OSMesaDestroyContext(ctx);
  return status;
}
