#include "scene.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace scenes {
namespace {

std::vector<Scene>& registry() {
  static std::vector<Scene> scenes;
  return scenes;
}

} // namespace

Registrar::Registrar(const char* name, const char* description, const SceneOptions& options,
                     DrawFn draw) {
  // A looser allowance must say why: the report shows the justification next to the numbers.
  if ((options.allowance > SceneOptions{}.allowance || options.softpipe_oracle) &&
      (!options.why || !*options.why)) {
    std::fprintf(stderr, "scene %s: allowance %.2f%% or softpipe oracle without a justification\n",
                 name, options.allowance);
    std::abort();
  }
  auto& scenes = registry();
  for (const Scene& s : scenes) {
    if (s.name == name) {
      std::fprintf(stderr, "scene %s is declared twice\n", name);
      std::abort();
    }
  }
  scenes.push_back(Scene{name, description, options, draw});
}

const std::vector<Scene>& all_scenes() {
  auto& scenes = registry();
  std::sort(scenes.begin(), scenes.end(),
            [](const Scene& a, const Scene& b) { return a.name < b.name; });
  return scenes;
}

void reset_state(const Frame& frame) {
  // Every value below is the GL default (GL 2.1 §6.2, state tables) except the projection and
  // the clear colour/depth, which each scene sets itself anyway.
  glViewport(0, 0, frame.width, frame.height);
  glDepthRange(0.0, 1.0);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, frame.width, 0.0, frame.height, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  for (GLenum cap : {GL_DEPTH_TEST, GL_CULL_FACE, GL_BLEND, GL_CLIP_PLANE0, GL_CLIP_PLANE1,
                     GL_CLIP_PLANE2, GL_CLIP_PLANE3, GL_CLIP_PLANE4, GL_CLIP_PLANE5})
    glDisable(cap);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glBlendFunc(GL_ONE, GL_ZERO);
  glShadeModel(GL_SMOOTH);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glFrontFace(GL_CCW);
  glCullFace(GL_BACK);
  glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
  glEdgeFlag(GL_TRUE);
  for (GLenum array : {GL_VERTEX_ARRAY, GL_COLOR_ARRAY, GL_NORMAL_ARRAY, GL_TEXTURE_COORD_ARRAY,
                       GL_EDGE_FLAG_ARRAY})
    glDisableClientState(array);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClearDepth(1.0);
}

} // namespace scenes
