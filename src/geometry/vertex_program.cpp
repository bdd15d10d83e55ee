// The vertex stage of a GLSL program (vertex_program.h).
#include "geometry/vertex_program.h"

#include "shader/engine.h"

#include <algorithm>
#include <cstring>
#include <memory>
#include <vector>

namespace pineda {

namespace {

using namespace shader;

// Vertices per run of the engine: one register of lanes.
constexpr int kBatch = kBlockLanes;

// Each thread's scratch registers and input and output arrays, grown as programs need.
struct ThreadBuffers {
  std::unique_ptr<std::byte[]> scratch_storage;
  size_t scratch_size = 0;
  void* scratch = nullptr;
  alignas(64) float in[kNumVertexInputs * 4][kBatch];
  alignas(64) float out[kNumVertexOutputs * 4][kBatch];

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

ThreadBuffers& thread_buffers() {
  thread_local std::unique_ptr<ThreadBuffers> buffers;
  if (!buffers) buffers = std::make_unique<ThreadBuffers>();
  return *buffers;
}

inline float clamp01(float v) {
  return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
}

// Component k of input slot `slot` of vertex v (shader/io.h VertexInput).
inline float input(const VertexProgram& vp, const InputVertex& v, size_t index, int slot, int k) {
  switch (slot) {
  case kInVertex:
    return v.pos[k];
  case kInNormal:
    return k < 3 ? v.normal[k] : 1.0f;
  case kInColor:
    return v.color[k];
  case kInSecondaryColor:
    return k < 3 ? v.color2[k] : 1.0f;
  case kInFogCoord:
    return k == 0 ? v.fog : (k == 3 ? 1.0f : 0.0f);
  default:
    break;
  }
  if (slot >= kInMultiTexCoord0 && slot < kInMultiTexCoord0 + kMaxTextureCoords) {
    const int u = slot - kInMultiTexCoord0;
    if (u < kMaxTexUnits) return v.tex[u][k];
    return k == 3 ? 1.0f : 0.0f;
  }
  const int i = slot - kInGeneric0;
  if (i == 0) return v.pos[k]; // §2.7: generic attribute 0 is the vertex
  if (i > 0 && i < kMaxVertexAttribs) {
    const int col = vp.generic_column[i];
    if (col >= 0) return vp.generic[index * static_cast<size_t>(vp.generic_stride) + col + k];
    return vp.generic_current[i][k];
  }
  return 0.0f;
}

} // namespace

void run_vertex_program(const VertexProgram& vp, const ClipSetup& cs, const Viewport& view,
                        const InputVertex* in, size_t first, PVertex* out, size_t n) {
  const Executable& exe = *vp.exe;
  ThreadBuffers& tb = thread_buffers();
  void* scratch = tb.scratch_for(exe.scratch_bytes());
  const std::vector<int>& reads = exe.inputs_read();
  const std::vector<int>& writes = exe.outputs_written();
  const float* in_ptr[kNumVertexInputs * 4] = {};
  float* out_ptr[kNumVertexOutputs * 4] = {};
  for (int c : reads)
    in_ptr[c] = tb.in[c];
  for (int c : writes)
    out_ptr[c] = tb.out[c];
  const bool writes_position =
      std::find(writes.begin(), writes.end(), kOutPosition * 4) != writes.end();
  // GL 2.1 §2.20.3 (§2.12): the user planes clip against gl_ClipVertex in eye space; a
  // shader that does not write it clips against gl_Position, as Mesa does.
  const bool user_planes = cs.user_dist >= 0 && cs.user_mask != 0;
  const int clip_vertex =
      std::find(writes.begin(), writes.end(), kOutClipVertex * 4) != writes.end()
          ? kOutClipVertex * 4
          : kOutPosition * 4;
  for (size_t b0 = 0; b0 < n; b0 += kBatch) {
    const int count = static_cast<int>(std::min<size_t>(kBatch, n - b0));
    for (int c : reads) {
      const int slot = c / 4, k = c % 4;
      float* dst = tb.in[c];
      for (int l = 0; l < count; ++l)
        dst[l] = input(vp, in[b0 + l], first + b0 + l, slot, k);
    }
    VertexBatch batch;
    batch.count = count;
    batch.in = in_ptr;
    batch.out = out_ptr;
    batch.sampler = vp.sampler;
    // Outputs the shader leaves unwritten on some path read as zero.
    for (int c : writes)
      std::fill(tb.out[c], tb.out[c] + count, 0.0f);
    exe.run_vertices(*vp.prepared, batch, scratch);
    for (int l = 0; l < count; ++l) {
      PVertex& p = out[b0 + l];
      std::fill(p.attr, p.attr + vp.attr_count, 0.0f);
      for (int c : writes) {
        const int a = vp.out_attr[c];
        if (a < 0) continue;
        const float x = tb.out[c][l];
        // §2.14.6: the colours a vertex shader writes are clamped to [0, 1].
        const bool color = a < kAttrTex0 || (a >= kAttrBackColor && a < kAttrVarying0);
        p.attr[a] = color ? clamp01(x) : x;
      }
      if (vp.fold_sum)
        for (int k = 0; k < 3; ++k) {
          p.attr[kAttrColor + k] += p.attr[kAttrColor2 + k];
          p.attr[kAttrBackColor + k] += p.attr[kAttrBackColor2 + k];
        }
      for (int k = 0; k < 4; ++k)
        p.clip[k] = writes_position ? tb.out[kOutPosition * 4 + k][l] : 0.0f;
      p.clipmask = clip_code(cs, p.clip);
      if (user_planes) {
        float cv[4];
        for (int k = 0; k < 4; ++k)
          cv[k] = writes_position || clip_vertex != kOutPosition * 4 ? tb.out[clip_vertex + k][l]
                                                                     : 0.0f;
        for (uint32_t planes = cs.user_mask; planes != 0; planes &= planes - 1) {
          const int i = __builtin_ctz(planes);
          const float* q = cs.user[i];
          const float d = q[0] * cv[0] + q[1] * cv[1] + q[2] * cv[2] + q[3] * cv[3];
          p.attr[cs.user_dist + i] = d;
          if (!(d >= 0.0f)) p.clipmask |= kClipUser0 << i;
        }
      }
      if (p.clipmask == 0) to_window(p, view);
      p.edgeflag = in[b0 + l].edge;
      p.point_size = 1.0f;
      if (vp.point_size) {
        // §3.3: gl_PointSize clamped to the implementation's range (and POINT_SIZE_MIN/MAX,
        // as llvmpipe does); NaN becomes the minimum.
        const float s = out_ptr[kOutPointSize * 4] != nullptr ? tb.out[kOutPointSize * 4][l] : 1.0f;
        p.point_size = s >= vp.point_size_min ? (s < vp.point_size_max ? s : vp.point_size_max)
                                              : vp.point_size_min;
      }
    }
  }
}

} // namespace pineda
