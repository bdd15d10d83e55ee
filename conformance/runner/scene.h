// Scene registry of the conformance runner.
//
// A scene is a deterministic GL 1.x frame. It is declared with
//
//   PINEDA_SCENE(name, "one-line description", .option = value, ...) { ...GL calls... }
//
// The name must be on the same line as "PINEDA_SCENE(" because conformance/CMakeLists.txt reads
// the scene names from the sources with a regular expression to register one ctest per scene.
// The options are designated initialisers of SceneOptions, in declaration order.
//
// This header is compiled against the system's Mesa headers only: the runner is an ordinary,
// unmodified OSMesa program.
#pragma once

#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#ifdef PINEDA_RUNNER_EGL
#include <EGL/egl.h>
#endif

#include <stdexcept>
#include <string>
#include <vector>

namespace scenes {

struct SceneOptions {
  int width = 256;
  int height = 256;
  GLenum format = OSMESA_RGBA; // OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB or OSMESA_RGB
  int depth_bits = 24;         // context depth bits passed to OSMesaCreateContextExt
  int stencil_bits = 0;        // context stencil bits passed to OSMesaCreateContextExt
  int accum_bits = 0;          // context accumulation bits passed to OSMesaCreateContextExt
  bool y_up = true;            // OSMesaPixelStore(OSMESA_Y_UP, ...)
  double allowance = 0.5;      // percent of pixels allowed to differ from llvmpipe
  // Compare against softpipe instead of llvmpipe: only for scenes llvmpipe gets wrong.
  bool softpipe_oracle = false;
  // Required whenever allowance exceeds the default or softpipe is the oracle: why GL leaves
  // the result open, or what llvmpipe gets wrong.
  const char* why = nullptr;
  // The GL version whose core the scene uses ("2.1"), when above 1.5: Mesa is run with
  // MESA_GL_VERSION_OVERRIDE set to it, so that it draws as that version's context would.
  const char* gl_version = nullptr;
};

struct Frame {
  int width;
  int height;
};

using DrawFn = void (*)(const Frame&);

struct Scene {
  std::string name;
  std::string description;
  SceneOptions options;
  DrawFn draw;
};

// All registered scenes, sorted by name.
const std::vector<Scene>& all_scenes();

struct Registrar {
  Registrar(const char* name, const char* description, const SceneOptions& options, DrawFn draw);
};

// Thrown by proc() when the library under test does not provide a function.
struct Unsupported : std::runtime_error {
  explicit Unsupported(const std::string& function) : std::runtime_error(function) {}
};

// Functions newer than GL 1.1 are looked up through OSMesaGetProcAddress (eglGetProcAddress in
// the EGL runner), never linked directly, so that a library without them reports "unsupported"
// instead of failing to load.
template <typename Fn> Fn proc(const char* name) {
#ifdef PINEDA_RUNNER_EGL
  auto p = eglGetProcAddress(name);
#else
  OSMESAproc p = OSMesaGetProcAddress(name);
#endif
  if (!p) throw Unsupported(name);
  return reinterpret_cast<Fn>(p);
}

// Puts back the state every scene starts from: pixel-unit orthographic projection
// (glOrtho(0, w, 0, h, -1, 1), so integer and half-integer coordinates land exactly on pixel
// edges and centres), full-window viewport, identity modelview, and everything the scenes touch
// at its GL default. The runner calls it before each frame, outside the timed region, so that
// every repetition of a scene starts from the same state.
void reset_state(const Frame& frame);

} // namespace scenes

#define PINEDA_SCENE_CAT2(a, b) a##b
#define PINEDA_SCENE(NAME, DESCRIPTION, ...)                                                      \
  static void PINEDA_SCENE_CAT2(scene_draw_, NAME)(const ::scenes::Frame& frame);                 \
  static const ::scenes::Registrar PINEDA_SCENE_CAT2(scene_registrar_, NAME){                     \
      #NAME, DESCRIPTION, ::scenes::SceneOptions{__VA_ARGS__},                                    \
      &PINEDA_SCENE_CAT2(scene_draw_, NAME)};                                                     \
  static void PINEDA_SCENE_CAT2(scene_draw_, NAME)([[maybe_unused]] const ::scenes::Frame& frame)
