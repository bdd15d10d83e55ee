// Occlusion-query counting in the fragment stage (GL 2.1 §4.1.7): with
// RasterState::count_samples, draw_primitives adds the fragments that pass the stencil and
// depth tests; the count equals the fragments an additive-counting pass lets through, whatever
// the colour path; and without the flag no counting instance is selected.
#include <gtest/gtest.h>

#include <vector>

#include "fragment/fragment_ops.h"
#include "geometry/assemble.h"
#include "raster_test_util.h"

namespace pineda {
namespace {

using test::TestFb;
using test::vtx;

// A fixed set of overlapping triangles at various depths.
std::vector<PVertex> triangles() {
  std::vector<PVertex> v;
  uint32_t s = 12345;
  const auto rnd = [&s](float lo, float hi) {
    s ^= s << 13;
    s ^= s >> 17;
    s ^= s << 5;
    return lo + (hi - lo) * static_cast<float>(s >> 8) / 16777216.0f;
  };
  for (int i = 0; i < 30; ++i)
    for (int k = 0; k < 3; ++k)
      v.push_back(vtx(rnd(-4, 44), rnd(-4, 36), rnd(0.1f, 0.9f), 1.0f, test::kCountColor));
  return v;
}

uint64_t draw(TestFb& t, RasterState rs, const std::vector<PVertex>& v) {
  uint64_t n = 0;
  rs.count_samples = true;
  DrawCall dc;
  dc.state = &rs;
  dc.fb = &t.fb;
  dc.samples_passed = &n;
  draw_primitives(dc, GL_TRIANGLES, v.data(), nullptr, v.size());
  return n;
}

// The fragments a state lets through, counted by an additive pass in the red channel over a
// copy of the same depth buffer.
uint64_t reference(RasterState rs, const std::vector<PVertex>& v, const TestFb& like) {
  TestFb t(like.fb.width, like.fb.height);
  t.depth_mem = like.depth_mem;
  RasterState c = test::counting_state();
  c.depth_test = rs.depth_test;
  c.depth_func = rs.depth_func;
  c.depth_write = rs.depth_write;
  c.scissor_test = rs.scissor_test;
  for (int k = 0; k < 4; ++k)
    c.scissor[k] = rs.scissor[k];
  DrawCall dc;
  dc.state = &c;
  dc.fb = &t.fb;
  draw_primitives(dc, GL_TRIANGLES, v.data(), nullptr, v.size());
  uint64_t sum = 0;
  for (int y = 0; y < t.fb.height; ++y)
    for (int x = 0; x < t.fb.width; ++x)
      sum += t.rgba(x, y)[0];
  return sum;
}

TEST(SampleCount, MatchesTheFragmentsThatPass) {
  const std::vector<PVertex> v = triangles();
  for (int depth = 0; depth < 2; ++depth) {
    for (int mask = 0; mask < 3; ++mask) {
      for (int scissor = 0; scissor < 2; ++scissor) {
        RasterState rs;
        rs.depth_test = depth != 0;
        rs.depth_func = GL_LESS;
        if (mask == 1)
          for (bool& w : rs.color_write)
            w = false;
        if (mask == 2) rs.color_write[1] = false;
        rs.scissor_test = scissor != 0;
        rs.scissor[0] = 5;
        rs.scissor[1] = 3;
        rs.scissor[2] = 20;
        rs.scissor[3] = 17;
        TestFb t(37, 29); // a width that is not a multiple of 8
        const uint64_t want = reference(rs, v, t);
        const uint64_t got = draw(t, rs, v);
        EXPECT_EQ(got, want) << "depth " << depth << " mask " << mask << " scissor " << scissor;
        EXPECT_GT(got, 0u);
      }
    }
  }
}

TEST(SampleCount, StencilFailuresDoNotCount) {
  const std::vector<PVertex> v = triangles();
  TestFb t(37, 29);
  RasterState rs;
  rs.stencil_test = true;
  // Both faces: the triangles include back-facing ones, which take the back state (§4.1.5).
  rs.stencil.func = GL_NEVER;
  rs.stencil_back = rs.stencil;
  EXPECT_EQ(draw(t, rs, v), 0u);
  rs.stencil.func = GL_ALWAYS;
  rs.stencil.depth_pass = GL_INCR; // makes the test "able to change anything"
  rs.stencil_back = rs.stencil;
  const uint64_t all = reference(RasterState{}, v, t);
  EXPECT_EQ(draw(t, rs, v), all);
}

TEST(SampleCount, NoCountingInstancesWithoutAQuery) {
  const TestFb t(16, 16);
  RasterState rs;
  StateKey k = make_state_key(rs, t.fb);
  EXPECT_FALSE(k.ext());
  rs.count_samples = true;
  k = make_state_key(rs, t.fb);
  EXPECT_TRUE(k.count_samples);
  EXPECT_TRUE(k.ext());
  // Counting needs the block loop to run even when nothing would be written.
  for (bool& w : rs.color_write)
    w = false;
  FragCtx ctx;
  prepare_fragments(rs, t.fb, ctx);
  EXPECT_FALSE(ctx.noop);
}

} // namespace
} // namespace pineda
