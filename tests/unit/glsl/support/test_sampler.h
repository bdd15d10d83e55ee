// A simple texture sampler for the shader engine's tests (shader/engine.h TextureSampler):
// float RGBA textures per unit, nearest or linear filtering, repeat or clamp-to-edge wraps,
// mipmaps chosen nearest, cube faces, depth comparison. The GL integration implements the
// interface on Pineda's own sampler instead (src/texture).
#pragma once

#include <array>
#include <vector>

#include "shader/engine.h"

namespace pineda::glsl_test {

struct TestTexture {
  shader::TexTarget target = shader::TexTarget::Tex2D;
  int width = 1, height = 1, depth = 1;
  bool linear = false;
  bool repeat = true;
  bool mipmaps = false; // levels halve down to 1x1; level 0 otherwise
  // levels[l][face][texel]: RGBA
  std::vector<std::array<std::vector<std::array<float, 4>>, 6>> levels;

  // A texture of one level (six faces for cubes) filled by fn(face, x, y, z).
  template <class Fn> static TestTexture make(shader::TexTarget t, int w, int h, int d, Fn&& fn) {
    TestTexture tex;
    tex.target = t;
    tex.width = w, tex.height = h, tex.depth = d;
    tex.levels.resize(1);
    const int faces = t == shader::TexTarget::Cube ? 6 : 1;
    for (int f = 0; f < faces; ++f)
      for (int z = 0; z < d; ++z)
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x)
            tex.levels[0][static_cast<size_t>(f)].push_back(fn(f, x, y, z));
    return tex;
  }
  // Adds the mipmap chain, each level the box average of the one above.
  void build_mipmaps();
};

class TestSampler : public shader::TextureSampler {
public:
  std::vector<TestTexture> units; // by texture unit
  int calls = 0;

  void sample(const shader::TexRequest& req) override;
  // One lookup by hand (the tests' reference).
  std::array<float, 4> lookup(int unit, float s, float t, float r, float lambda, bool shadow) const;
};

} // namespace pineda::glsl_test
