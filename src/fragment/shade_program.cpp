// The fragment stage of a GLSL program (GL 2.1 §3.11): the inputs of the fragments of a block,
// perspective-correct (§3.5.1 eq 3.9), in 2x2 quads so that the engine's derivatives and the
// texture lookups' level of detail see real neighbours, one run of the engine per block, and
// gl_FragColor back to the block loop with the fragments the shader discarded removed.
#include <algorithm>
#include <cstring>
#include <memory>
#include <iterator>

#include "fragment/shade.h"
#include "shader/engine.h"
#include "shader/io.h"

namespace pineda {

namespace {

using namespace shader;

struct FragmentBuffers {
  std::unique_ptr<std::byte[]> scratch_storage;
  size_t scratch_size = 0;
  void* scratch = nullptr;
  alignas(64) float in[kNumFragmentInputs * 4][kBlockLanes];
  alignas(64) float out[kNumFragmentOutputs * 4][kBlockLanes];
  // The last run's quads (block position of each) and the outputs it wrote, for
  // shade_program_colors.
  int nq = 0;
  int qpix[16] = {};
  bool written[kNumFragmentOutputs * 4] = {};

  void* scratch_for(size_t bytes) {
    if (bytes > scratch_size) {
      scratch_storage = std::make_unique<std::byte[]>(bytes + 64);
      const auto addr = reinterpret_cast<uintptr_t>(scratch_storage.get());
      scratch = scratch_storage.get() + ((64 - addr % 64) % 64);
      scratch_size = bytes;
    }
    return scratch;
  }
};

FragmentBuffers& fragment_buffers() {
  thread_local std::unique_ptr<FragmentBuffers> buffers;
  if (!buffers) buffers = std::make_unique<FragmentBuffers>();
  return *buffers;
}

} // namespace

uint64_t shade_program_block(const FragCtx& ctx, const FragInputs& in, int bx, int by,
                             uint64_t mask, float (*out)[64], uint32_t* depth) {
  const FragmentProgram& fp = *ctx.shade->program;
  const ShadeInputs& si = *in.shade;
  FragmentBuffers& fb = fragment_buffers();
  // The 2x2 quads holding a fragment, in block order; quads without one in a row pair that has
  // one are written as zeros (the block loop reads whole rows).
  int qpix[16];
  int nq = 0;
  for (int qy = 0; qy < 4; ++qy) {
    const unsigned pair = static_cast<unsigned>(mask >> (16 * qy)) & 0xffffu;
    if (pair == 0) continue;
    for (int qx = 0; qx < 4; ++qx) {
      const int p = 16 * qy + 2 * qx;
      if (((pair >> (2 * qx)) & 0x303u) == 0) {
        for (int c = 0; c < 4; ++c)
          out[c][p] = out[c][p + 1] = out[c][p + 8] = out[c][p + 9] = 0.0f;
        if (depth != nullptr) depth[p] = depth[p + 1] = depth[p + 8] = depth[p + 9] = 0;
        continue;
      }
      qpix[nq++] = p;
    }
  }
  if (nq == 0) return 0;
  const float fi0 = static_cast<float>(bx - in.ox), fj0 = static_cast<float>(by - in.oy);
  const double di0 = bx - in.ox, dj0 = by - in.oy;
  const float* in_ptr[kNumFragmentInputs * 4] = {};
  float* out_ptr[kNumFragmentOutputs * 4] = {};
  for (int i = 0; i < fp.input_count; ++i)
    in_ptr[fp.input_comp[i]] = fb.in[fp.input_comp[i]];
  if (fp.frag_coord)
    for (int c = 0; c < 4; ++c)
      in_ptr[kFragCoord * 4 + c] = fb.in[kFragCoord * 4 + c];
  if (fp.point_coord)
    for (int c = 0; c < 2; ++c)
      in_ptr[kFragPointCoord * 4 + c] = fb.in[kFragPointCoord * 4 + c];
  std::fill(std::begin(fb.written), std::end(fb.written), false);
  fb.nq = nq;
  std::copy_n(qpix, nq, fb.qpix);
  for (int c : fp.exe->outputs_written()) {
    fb.written[c] = true;
    out_ptr[c] = fb.out[c];
    std::fill(fb.out[c], fb.out[c] + 4 * nq, 0.0f);
  }
  for (int q = 0; q < nq; ++q) {
    const int p = qpix[q];
    for (int l = 0; l < 4; ++l) {
      const int lane = 4 * q + l;
      const int px = (p & 7) + (l & 1), py = (p >> 3) + (l >> 1);
      const float fi = fi0 + static_cast<float>(px), fj = fj0 + static_cast<float>(py);
      const float inv_w = si.inv_w.v0 + fi * si.inv_w.dx + fj * si.inv_w.dy;
      const float w = 1.0f / inv_w;
      for (int i = 0; i < fp.input_count; ++i) {
        const ShadeInputs::Plane& pl = si.prog_w[i];
        fb.in[fp.input_comp[i]][lane] = (pl.v0 + fi * pl.dx + fj * pl.dy) * w;
      }
      if (fp.point_coord) {
        // §3.3.1: linear in window space (sprites have no perspective).
        for (int c = 0; c < 2; ++c) {
          const PlaneF& pl = si.point_coord[c];
          fb.in[kFragPointCoord * 4 + c][lane] = pl.v0 + fi * pl.dx + fj * pl.dy;
        }
      }
      if (fp.frag_coord) {
        // §3.11.2: window x, y of the fragment centre, window z, and 1 / w_clip.
        const double z = in.z.v0 + (di0 + px) * in.z.dx + (dj0 + py) * in.z.dy;
        fb.in[kFragCoord * 4 + 0][lane] = static_cast<float>(bx + px) + 0.5f;
        fb.in[kFragCoord * 4 + 1][lane] = static_cast<float>(by + py) + 0.5f;
        fb.in[kFragCoord * 4 + 2][lane] =
            static_cast<float>(std::clamp(z / ctx.depth_max, 0.0, 1.0));
        fb.in[kFragCoord * 4 + 3][lane] = inv_w;
      }
    }
  }
  FragmentQuads quads;
  quads.quads = nq;
  quads.in = in_ptr;
  quads.front_facing = si.front_facing;
  quads.out = out_ptr;
  quads.sampler = fp.sampler;
  const uint64_t killed =
      fp.exe->run_fragments(*fp.prepared, quads, fb.scratch_for(fp.exe->scratch_bytes()));
  // §3.11.2, §4.2.1: gl_FragColor goes to every draw buffer, gl_FragData[n] to buffer n.
  const int slot = kOutFragData0 + (fp.frag_data ? ctx.color_output : 0);
  const float* color[4];
  for (int c = 0; c < 4; ++c)
    color[c] = out_ptr[slot * 4 + c];
  // gl_FragDepth clamped to [0, 1] (NaN to 0, as llvmpipe) and converted as the block loop
  // converts the primitive's depth (round to nearest).
  const float* fz = depth != nullptr ? out_ptr[kOutFragDepth * 4] : nullptr;
  // §4.1.4: the alpha test of another colour's pass, on colour zero's alpha as the block loop
  // compares it (8-bit values).
  const float* alpha0 = ctx.alpha_test_color0 ? out_ptr[kOutFragData0 * 4 + 3] : nullptr;
  for (int q = 0; q < nq; ++q) {
    const int p = qpix[q];
    for (int l = 0; l < 4; ++l) {
      const int lane = 4 * q + l;
      const int e = p + (l & 1) + 8 * (l >> 1);
      for (int c = 0; c < 4; ++c)
        out[c][e] = color[c] != nullptr ? color[c][lane] : 0.0f;
      if (depth != nullptr) {
        const double z = fz != nullptr ? static_cast<double>(fz[lane]) : 0.0;
        const double zc = (z > 0.0 ? (z < 1.0 ? z : 1.0) : 0.0) * ctx.depth_max + 0.5;
        depth[e] = static_cast<uint32_t>(static_cast<int64_t>(zc));
      }
      bool kill = ((killed >> lane) & 1u) != 0;
      if (ctx.alpha_test_color0) {
        const int a = color_to_unorm8(alpha0 != nullptr ? alpha0[lane] : 0.0f);
        const unsigned rel = a < ctx.alpha_ref ? 1u : a == ctx.alpha_ref ? 2u : 4u;
        kill = kill || (ctx.alpha_func & rel) == 0;
      }
      if (kill) mask &= ~(uint64_t{1} << e);
    }
  }
  return mask;
}

void shade_program_colors(const FragCtx& ctx, int output, float (*out)[64]) {
  const FragmentProgram& fp = *ctx.shade->program;
  const FragmentBuffers& fb = fragment_buffers();
  const int slot = kOutFragData0 + (fp.frag_data ? output : 0);
  std::memset(out, 0, sizeof(float) * 4 * 64);
  for (int q = 0; q < fb.nq; ++q) {
    const int p = fb.qpix[q];
    for (int l = 0; l < 4; ++l) {
      const int e = p + (l & 1) + 8 * (l >> 1);
      for (int c = 0; c < 4; ++c)
        out[c][e] = fb.written[slot * 4 + c] ? fb.out[slot * 4 + c][4 * q + l] : 0.0f;
    }
  }
}

} // namespace pineda
