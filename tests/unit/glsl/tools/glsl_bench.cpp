// glsl_bench: the shader engine's speed on a ~100-instruction ALU fragment kernel, in ns per
// pixel at each SIMD level, for blocks of 16 quads (64 pixels) and of 4 quads (16 pixels),
// and a texture-free lighting-style kernel with transcendentals.
//   glsl_bench [--seconds S] [--quads 16,4,...] [--blocks N]
// Times are the thread's CPU time (the machine is shared).
#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/simd_level.h"
#include "glsl/glsl.h"
#include "shader/io.h"

using namespace pineda;

namespace {

const char* kAlu = "varying vec4 v0, v1;\n"
                   "uniform vec4 u0, u1, u2;\n"
                   "void main() {\n"
                   "  vec4 a = v0, b = v1;\n"
                   "  for (int i = 0; i < 5; i++) {\n"
                   "    a = a * u0 + b;\n"
                   "    b = max(b * u1, a - u2);\n"
                   "    a = clamp(a, -10.0, 10.0);\n"
                   "  }\n"
                   "  gl_FragColor = a + b;\n"
                   "}\n";

const char* kLighting = "varying vec3 n, l, e;\n"
                        "uniform vec4 diffuse, specular, ambient;\n"
                        "uniform float shininess;\n"
                        "void main() {\n"
                        "  vec3 N = normalize(n), L = normalize(l), E = normalize(e);\n"
                        "  vec3 H = normalize(L + E);\n"
                        "  float d = max(dot(N, L), 0.0);\n"
                        "  float s = pow(max(dot(N, H), 0.0), shininess);\n"
                        "  gl_FragColor = ambient + diffuse * d + specular * s;\n"
                        "}\n";

struct Result {
  double ns_per_pixel;
  int instructions;
};

long g_fixed_blocks = 0;            // --blocks: run exactly this many (for instruction counting)
std::vector<int> g_quads = {16, 4}; // --quads N,N,...: quads per block

Result run(const char* src, int quads, SimdLevel level, double seconds) {
  auto fs = glsl::Shader::compile(glsl::ShaderStage::Fragment, {src});
  auto p = glsl::Program::link({fs}, {});
  if (!p->linked()) {
    std::fprintf(stderr, "%s\n", p->info_log().c_str());
    std::exit(1);
  }
  const shader::Executable& exe = *p->fragment();
  std::vector<uint32_t> uniforms = p->initial_uniforms();
  for (size_t i = 0; i < uniforms.size(); ++i) {
    const float f = 0.5f + 0.01f * static_cast<float>(i);
    std::memcpy(&uniforms[i], &f, 4);
  }
  shader::Prepared prep;
  exe.prepare(uniforms.data(), prep);
  std::vector<std::vector<float>> in(shader::kNumFragmentInputs * 4);
  std::vector<const float*> ip(in.size(), nullptr);
  for (int c : exe.inputs_read()) {
    in[static_cast<size_t>(c)].resize(64);
    for (int l = 0; l < 64; ++l)
      in[static_cast<size_t>(c)][static_cast<size_t>(l)] =
          0.1f * static_cast<float>(l % 7) - 0.2f * static_cast<float>(c % 3);
    ip[static_cast<size_t>(c)] = in[static_cast<size_t>(c)].data();
  }
  std::vector<std::vector<float>> out(shader::kNumFragmentOutputs * 4, std::vector<float>(64));
  std::vector<float*> op;
  for (auto& o : out)
    op.push_back(o.data());
  std::vector<char> scratch(exe.scratch_bytes());
  shader::FragmentQuads q;
  q.quads = quads;
  q.in = ip.data();
  q.out = op.data();
  set_simd_level(level);
  // The thread's CPU time: the machine is shared, wall time would count other processes.
  const auto cpu = [] {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  };
  long blocks = 0;
  const double t0 = cpu();
  double elapsed = 0;
  if (g_fixed_blocks > 0) {
    for (long i = 0; i < g_fixed_blocks; ++i)
      exe.run_fragments(prep, q, scratch.data());
    blocks = g_fixed_blocks;
    elapsed = cpu() - t0;
  }
  while (g_fixed_blocks == 0 && elapsed < seconds) {
    for (int i = 0; i < 1000; ++i)
      exe.run_fragments(prep, q, scratch.data());
    blocks += 1000;
    elapsed = cpu() - t0;
  }
  set_simd_level(simd_level_supported());
  return {elapsed * 1e9 / (static_cast<double>(blocks) * quads * 4), exe.instruction_count()};
}

} // namespace

int main(int argc, char** argv) {
  double seconds = 1.0;
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "--seconds") && i + 1 < argc)
      seconds = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--blocks") && i + 1 < argc)
      g_fixed_blocks = std::atol(argv[++i]);
    else if (!std::strcmp(argv[i], "--quads") && i + 1 < argc) {
      g_quads.clear();
      for (const char* q = argv[++i]; *q;) {
        char* end = nullptr;
        g_quads.push_back(std::clamp(static_cast<int>(std::strtol(q, &end, 10)), 1, 16));
        q = *end ? end + 1 : end;
      }
    }
  const SimdLevel levels[] = {SimdLevel::Baseline, SimdLevel::Avx2, SimdLevel::Avx512};
  const char* names[] = {"baseline (SSE2, 4 lanes)", "AVX2 (8 lanes)", "AVX-512 (16 lanes)"};
  for (const auto& [name, src] :
       {std::pair{"ALU kernel", kAlu}, std::pair{"lighting kernel", kLighting}}) {
    for (int quads : g_quads) {
      for (int l = 0; l < 3; ++l) {
        if (static_cast<int>(levels[l]) > static_cast<int>(simd_level_supported())) continue;
        const Result r = run(src, quads, levels[l], seconds);
        std::printf("%-16s %2d quads  %-26s %3d instructions  %6.3f ns/pixel\n", name, quads,
                    names[l], r.instructions, r.ns_per_pixel);
      }
    }
  }
  return 0;
}
