// A freeglut program that ends by calling exit() inside its display callback, as many old
// GLUT programs do. freeglut's exit handler (fgDeinitialize -> fgDestroyWindow ->
// fgSetWindow) then binds the window's context again after destroying it; on Mesa that is no
// error and the program exits with status 0, and so it must on Pineda.
//   freeglut_exit [--screenshot out.png] [--verbose]
// Draws one frame, writes it as a PNG, flushes stdout and calls exit(0) from the callback.
#include "png_write.h"

#include <GL/freeglut.h>

#include <cstdlib>

namespace {

std::string screenshot_path;
constexpr int kWidth = 200, kHeight = 150;

void display() {
  glViewport(0, 0, kWidth, kHeight);
  glClearColor(0.2f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.5, 1.5, -1.125, 1.125, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(30, 1, 1, 0);
  glutSolidCube(1.0);
  glFinish();
  int status = 0;
  if (!screenshot_path.empty()) {
    std::vector<std::uint8_t> rgba(static_cast<size_t>(kWidth) * kHeight * 4);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    if (!demo::write_png(screenshot_path, kWidth, kHeight, rgba)) status = 1;
  }
  if (glGetError() != GL_NO_ERROR) status = 1;
  glutSwapBuffers();
  std::printf("freeglut_exit: exit(%d) from the display callback\n", status);
  std::fflush(stdout);
  std::exit(status);
}

} // namespace

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  bool verbose = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--screenshot" && i + 1 < argc) {
      screenshot_path = argv[++i];
    } else if (a == "--verbose") {
      verbose = true;
    } else {
      std::fprintf(stderr, "usage: freeglut_exit [--screenshot out.png] [--verbose]\n");
      return 2;
    }
  }
  glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE | GLUT_DEPTH);
  glutInitWindowSize(kWidth, kHeight);
  glutCreateWindow("freeglut exit");
  if (verbose)
    std::printf("GL_RENDERER: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glutDisplayFunc(display);
  glutMainLoop();
  return 1; // not reached: the display callback exits
}
