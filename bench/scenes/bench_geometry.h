// Geometry and view set-up shared by the bench, sweep and scaling scenes.
#pragma once

#include "scene_util.h"

#include <cmath>
#include <vector>

namespace bench {

// A perspective projection with vertical half-angle tangent `fovy_tan`, identity model-view.
inline void perspective_view(const scenes::Frame& frame, float fovy_tan, float near_plane,
                             float far_plane) {
  glViewport(0, 0, frame.width, frame.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
  glFrustum(-fovy_tan * aspect * near_plane, fovy_tan * aspect * near_plane, -fovy_tan * near_plane,
            fovy_tan * near_plane, near_plane, far_plane);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

// A torus of rings x sides quads as an indexed triangle list: positions and normals
// interleaved (x y z nx ny nz).
struct Mesh {
  std::vector<float> vn;
  std::vector<unsigned> indices;
};

inline Mesh torus(int rings, int sides, float major, float minor) {
  Mesh m;
  m.vn.reserve(static_cast<size_t>((rings + 1) * (sides + 1) * 6));
  for (int i = 0; i <= rings; ++i) {
    const float u = 2.0f * scenes::kPi * static_cast<float>(i) / static_cast<float>(rings);
    for (int j = 0; j <= sides; ++j) {
      const float v = 2.0f * scenes::kPi * static_cast<float>(j) / static_cast<float>(sides);
      const float nx = std::cos(u) * std::cos(v), ny = std::sin(u) * std::cos(v), nz = std::sin(v);
      m.vn.insert(m.vn.end(),
                  {(major + minor * std::cos(v)) * std::cos(u),
                   (major + minor * std::cos(v)) * std::sin(u), minor * std::sin(v), nx, ny, nz});
    }
  }
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j) {
      const unsigned a = static_cast<unsigned>(i * (sides + 1) + j), b = a + 1;
      const unsigned c = a + static_cast<unsigned>(sides + 1), d = c + 1;
      m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
    }
  }
  return m;
}

} // namespace bench
