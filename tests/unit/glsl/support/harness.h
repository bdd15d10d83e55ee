// A tiny drawing pipeline around a linked program, for the tests and the piglit corpus runner:
// uniforms by name, the vertex stage over vertices, the fragment stage over 2x2 quads, and a
// float framebuffer where rectangles are rasterized (two triangles, perspective-correct
// varyings, one triangle's quads at a time as a GL rasterizer does).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "glsl/glsl.h"
#include "shader/io.h"
#include "support/test_sampler.h"

namespace pineda::glsl_test {

using Vec4 = std::array<float, 4>;

// Compiles and links; on failure `log` gets the logs and the program is null.
std::unique_ptr<glsl::Program> build(const std::string& vs, const std::string& fs, std::string* log,
                                     const glsl::Limits& limits = {});

class Pipeline {
public:
  explicit Pipeline(const glsl::Program& p, int width = 250, int height = 250);

  // glUniform by name ("v", "arr[2]", "s.m"): floats for float types; ints, bools and
  // samplers take ints (or floats, converted).
  bool set_uniform(const std::string& name, const std::vector<double>& values);
  // The built-in uniform state a fixed-function GL would have: identity matrices (or the
  // projection of `ortho`), zeros elsewhere.
  void set_builtin_state();

  // Runs the vertex shader: in[v][component] (kNumVertexInputs * 4), out likewise
  // (kNumVertexOutputs * 4).
  std::vector<std::vector<float>> run_vertices(const std::vector<std::vector<float>>& in);
  // Runs the fragment shader over `quads` quads: in[lane][component] (kNumFragmentInputs * 4);
  // out[lane][component] (kNumFragmentOutputs * 4); returns the discarded lanes.
  uint64_t run_fragments(int quads, const std::vector<std::vector<float>>& in,
                         std::vector<std::vector<float>>& out, bool front_facing = true);

  void clear(const Vec4& c);
  // piglit's "draw rect": corners in normalized device coordinates.
  void draw_rect(float x, float y, float w, float h);
  Vec4 pixel(int x, int y) const;

  const glsl::Program& program;
  std::vector<uint32_t> uniforms;
  TestSampler sampler;
  bool ortho = false;
  int width, height;
  std::vector<Vec4> fb;
  // Vertex attributes other than the position for draw_rect (conventional and generic).
  std::vector<float> attrib_defaults;

private:
  void draw_triangle(const std::vector<float>* v[3]);
  std::vector<char> scratch_;
};

} // namespace pineda::glsl_test
