// A small, ordinary freeglut program: a lit teapot and a torus, turning frame by frame. It runs
// on whatever libGL.so.1 the loader finds (Pineda with LD_LIBRARY_PATH, Mesa without).
//   freeglut_teapot [--frames N] [--screenshot out.png] [--verbose]
// Draws N frames (default 10; frame i turns 6 degrees per step), writes the last one as a PNG,
// then leaves the main loop.
#include "png_write.h"

#include <GL/freeglut.h>

#include <cstdlib>

namespace {

int frames = 10;
int frame = 0;
std::string screenshot_path;
bool verbose = false;
int status = 0;
constexpr int kWidth = 320, kHeight = 240;

void display() {
  glViewport(0, 0, kWidth, kHeight);
  glClearColor(0.1f, 0.15f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.8, 0.8, -0.6, 0.6, 2.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const GLfloat light[4] = {0.4f, 0.8f, 1.0f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glTranslatef(0.0f, 0.0f, -7.0f);
  glRotatef(20.0f, 1.0f, 0.0f, 0.0f);

  const GLfloat teapot_colour[4] = {0.8f, 0.6f, 0.2f, 1.0f};
  const GLfloat torus_colour[4] = {0.2f, 0.5f, 0.9f, 1.0f};
  glPushMatrix();
  glTranslatef(-0.9f, 0.0f, 0.0f);
  glRotatef(static_cast<float>(frame) * 6.0f, 0.0f, 1.0f, 0.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, teapot_colour);
  glutSolidTeapot(0.9);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(1.5f, 0.0f, 0.0f);
  glRotatef(static_cast<float>(frame) * 6.0f, 1.0f, 0.0f, 0.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, torus_colour);
  glutSolidTorus(0.25, 0.7, 16, 32);
  glPopMatrix();

  if (frame == frames - 1) {
    if (!screenshot_path.empty()) {
      std::vector<std::uint8_t> rgba(static_cast<size_t>(kWidth) * kHeight * 4);
      glFinish();
      glReadBuffer(GL_BACK);
      glPixelStorei(GL_PACK_ALIGNMENT, 1);
      glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
      if (!demo::write_png(screenshot_path, kWidth, kHeight, rgba)) status = 1;
    }
    if (glGetError() != GL_NO_ERROR) status = 1;
    glutLeaveMainLoop();
  }
  glutSwapBuffers();
  ++frame;
}

} // namespace

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--frames" && i + 1 < argc) {
      frames = std::atoi(argv[++i]);
      if (frames < 1) {
        std::fprintf(stderr, "freeglut_teapot: --frames needs a positive integer\n");
        return 2;
      }
    } else if (a == "--screenshot" && i + 1 < argc) {
      screenshot_path = argv[++i];
    } else if (a == "--verbose") {
      verbose = true;
    } else {
      std::fprintf(stderr,
                   "usage: freeglut_teapot [--frames N] [--screenshot out.png] [--verbose]\n");
      return 2;
    }
  }
  glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE | GLUT_DEPTH);
  glutInitWindowSize(kWidth, kHeight);
  glutCreateWindow("freeglut teapot");
  glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_CONTINUE_EXECUTION);
  if (verbose)
    std::printf("GL_RENDERER: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glutDisplayFunc(display);
  glutIdleFunc(glutPostRedisplay);
  glutMainLoop();
  std::printf("freeglut_teapot: %d frames\n", frame);
  return status;
}
