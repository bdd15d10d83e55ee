// An ordinary GLFW program on Pineda's libGL.so.1: GLFW loads GLX with dlopen("libGL.so.1")
// and goes through glXGetFBConfigs/glXGetFBConfigAttrib, glXCreateWindow,
// glXCreateContextAttribsARB or glXCreateNewContext, glXSwapIntervalEXT and glXSwapBuffers.
// Exit status 0 when the swapped frame reaches the window (read back with XGetImage).
#include <GL/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#define GLFW_EXPOSE_NATIVE_X11
#include <GLFW/glfw3native.h>
#include <X11/Xutil.h>

#include <cstdio>
#include <cstring>

int main() {
  if (glfwInit() != GLFW_TRUE) {
    std::fprintf(stderr, "glfwInit failed\n");
    return 1;
  }
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  GLFWwindow* window = glfwCreateWindow(64, 48, "pineda", nullptr, nullptr);
  if (window == nullptr) {
    std::fprintf(stderr, "glfwCreateWindow failed\n");
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(0);
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  std::printf("GL_RENDERER: %s\n", renderer != nullptr ? renderer : "(null)");
  int status = renderer != nullptr && std::strncmp(renderer, "Pineda", 6) == 0 ? 0 : 1;
  int fb_w = 0, fb_h = 0;
  glfwGetFramebufferSize(window, &fb_w, &fb_h);
  glViewport(0, 0, fb_w, fb_h);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glfwSwapBuffers(window);
  Display* dpy = glfwGetX11Display();
  XImage* img = XGetImage(dpy, glfwGetX11Window(window), fb_w / 2, fb_h / 2, 1, 1, AllPlanes,
                          ZPixmap);
  const unsigned long pixel = img != nullptr ? (XGetPixel(img, 0, 0) & 0xffffff) : 0;
  if (img != nullptr) XDestroyImage(img);
  std::printf("window centre: %06lx\n", pixel);
  if (pixel != 0x00ff00) status = 1;
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}
