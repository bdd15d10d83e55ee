// The tests' drawing pipeline (harness.h).
#include "support/harness.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace pineda::glsl_test {

using namespace shader;

std::unique_ptr<glsl::Program> build(const std::string& vs, const std::string& fs, std::string* log,
                                     const glsl::Limits& limits) {
  std::vector<std::shared_ptr<const glsl::Shader>> shaders;
  std::string l;
  if (!vs.empty()) {
    auto s = glsl::Shader::compile(glsl::ShaderStage::Vertex, {vs}, limits);
    l += s->info_log();
    if (!s->compiled()) {
      if (log) *log = "vertex shader: " + l;
      return nullptr;
    }
    shaders.push_back(s);
  }
  if (!fs.empty()) {
    auto s = glsl::Shader::compile(glsl::ShaderStage::Fragment, {fs}, limits);
    l += s->info_log();
    if (!s->compiled()) {
      if (log) *log = "fragment shader: " + l;
      return nullptr;
    }
    shaders.push_back(s);
  }
  auto p = glsl::Program::link(shaders, {}, limits);
  if (!p->linked()) {
    if (log) *log = "link: " + p->info_log();
    return nullptr;
  }
  if (log) *log = l;
  return p;
}

Pipeline::Pipeline(const glsl::Program& p, int w, int h)
    : program(p), uniforms(p.initial_uniforms()), width(w), height(h),
      fb(static_cast<size_t>(w * h), Vec4{0, 0, 0, 0}),
      attrib_defaults(static_cast<size_t>(kNumVertexInputs) * 4, 0.0f) {
  size_t bytes = 1024;
  if (p.vertex()) bytes = std::max(bytes, p.vertex()->scratch_bytes());
  if (p.fragment()) bytes = std::max(bytes, p.fragment()->scratch_bytes());
  scratch_.resize(bytes);
  // GL's current attribute values: (0, 0, 0, 1), white colours, normal (0, 0, 1).
  for (int s = 0; s < kNumVertexInputs; ++s)
    attrib_defaults[static_cast<size_t>(s * 4 + 3)] = 1.0f;
  for (int c = 0; c < 4; ++c)
    attrib_defaults[static_cast<size_t>(kInColor * 4 + c)] = 1.0f;
  attrib_defaults[kInNormal * 4 + 2] = 1.0f;
  attrib_defaults[kInNormal * 4 + 3] = 0.0f;
}

bool Pipeline::set_uniform(const std::string& name, const std::vector<double>& values) {
  const int loc = program.uniform_location(name);
  if (loc < 0) return false;
  const glsl::UniformLocation& l = program.locations()[static_cast<size_t>(loc)];
  const glsl::ActiveUniform& u = program.uniforms()[static_cast<size_t>(l.uniform)];
  bool is_float = true, is_bool = false;
  switch (u.type) {
  case GL_INT:
  case GL_INT_VEC2:
  case GL_INT_VEC3:
  case GL_INT_VEC4:
  case GL_SAMPLER_1D:
  case GL_SAMPLER_2D:
  case GL_SAMPLER_3D:
  case GL_SAMPLER_CUBE:
  case GL_SAMPLER_1D_SHADOW:
  case GL_SAMPLER_2D_SHADOW:
    is_float = false;
    break;
  case GL_BOOL:
  case GL_BOOL_VEC2:
  case GL_BOOL_VEC3:
  case GL_BOOL_VEC4:
    is_float = false, is_bool = true;
    break;
  default:
    break;
  }
  const int end = u.word + u.size * u.stride;
  for (size_t k = 0; k < values.size() && l.word + static_cast<int>(k) < end; ++k) {
    uint32_t bits;
    if (is_bool)
      bits = values[k] != 0 ? 1 : 0;
    else if (is_float)
      bits = std::bit_cast<uint32_t>(static_cast<float>(values[k]));
    else
      bits = static_cast<uint32_t>(static_cast<int32_t>(values[k]));
    uniforms[static_cast<size_t>(l.word) + k] = bits;
  }
  return true;
}

void Pipeline::set_builtin_state() {
  const float W = static_cast<float>(width), H = static_cast<float>(height);
  const float ortho_m[16] = {2 / W, 0, 0, 0, 0, 2 / H, 0, 0, 0, 0, -1, 0, -1, -1, 0, 1};
  for (const glsl::BuiltinUniform& b : program.builtin_uniforms()) {
    const auto put = [&](int k, float v) {
      uniforms[static_cast<size_t>(b.word + k)] = std::bit_cast<uint32_t>(v);
    };
    const bool proj = b.name == "gl_ModelViewProjectionMatrix" || b.name == "gl_ProjectionMatrix";
    if (b.type == GL_FLOAT_MAT4) {
      for (int k = 0; k < 16; ++k)
        put(k, ortho && proj ? ortho_m[k] : (k % 5 == 0 ? 1.0f : 0.0f));
    } else if (b.type == GL_FLOAT_MAT3) {
      for (int k = 0; k < 9; ++k)
        put(k, k % 4 == 0 ? 1.0f : 0.0f);
    } else if (b.name == "gl_DepthRange.far" || b.name == "gl_DepthRange.diff" ||
               b.name == "gl_NormalScale" || b.name == "gl_Point.size") {
      put(0, 1.0f);
    } else {
      // GL 2.1 Table 6.9's initial lighting state, the rest zero.
      const auto ends = [&](const char* s) {
        return b.name.size() >= std::strlen(s) &&
               b.name.compare(b.name.size() - std::strlen(s), std::string::npos, s) == 0;
      };
      const bool light0 = b.name.rfind("gl_LightSource[0]", 0) == 0;
      if (b.name.rfind("gl_LightSource[", 0) == 0) {
        if (ends(".ambient")) put(3, 1.0f);
        if (ends(".diffuse") || ends(".specular")) {
          for (int k = 0; k < 3; ++k)
            put(k, light0 ? 1.0f : 0.0f);
          put(3, 1.0f);
        }
        if (ends(".position")) put(2, 1.0f);
        if (ends(".spotDirection")) put(2, -1.0f);
        if (ends(".spotCutoff")) put(0, 180.0f);
        if (ends(".spotCosCutoff")) put(0, -1.0f);
        if (ends(".constantAttenuation")) put(0, 1.0f);
      } else if (b.name.find("Material.") != std::string::npos) {
        const float v = ends(".ambient") ? 0.2f : ends(".diffuse") ? 0.8f : 0.0f;
        if (b.type == GL_FLOAT_VEC4) {
          for (int k = 0; k < 3; ++k)
            put(k, v);
          put(3, 1.0f);
        }
      } else if (b.name == "gl_LightModel.ambient") {
        for (int k = 0; k < 3; ++k)
          put(k, 0.2f);
        put(3, 1.0f);
      }
    }
  }
}

std::vector<std::vector<float>> Pipeline::run_vertices(const std::vector<std::vector<float>>& in) {
  const Executable* vs = program.vertex();
  const size_t n = in.size();
  std::vector<std::vector<float>> out(n, std::vector<float>(kNumVertexOutputs * 4, 0.0f));
  if (!vs || n == 0) return out;
  std::vector<std::vector<float>> soa_in(kNumVertexInputs * 4), soa_out(kNumVertexOutputs * 4);
  std::vector<const float*> ip(kNumVertexInputs * 4, nullptr);
  std::vector<float*> op(kNumVertexOutputs * 4, nullptr);
  for (int c : vs->inputs_read()) {
    auto& a = soa_in[static_cast<size_t>(c)];
    for (size_t v = 0; v < n; ++v)
      a.push_back(in[v][static_cast<size_t>(c)]);
    ip[static_cast<size_t>(c)] = a.data();
  }
  for (int c : vs->outputs_written()) {
    soa_out[static_cast<size_t>(c)].assign(n, 0.0f);
    op[static_cast<size_t>(c)] = soa_out[static_cast<size_t>(c)].data();
  }
  Prepared prep;
  vs->prepare(uniforms.data(), prep);
  VertexBatch b;
  b.count = static_cast<int>(n);
  b.in = ip.data();
  b.out = op.data();
  b.sampler = &sampler;
  vs->run_vertices(prep, b, scratch_.data());
  for (int c : vs->outputs_written())
    for (size_t v = 0; v < n; ++v)
      out[v][static_cast<size_t>(c)] = soa_out[static_cast<size_t>(c)][v];
  return out;
}

uint64_t Pipeline::run_fragments(int quads, const std::vector<std::vector<float>>& in,
                                 std::vector<std::vector<float>>& out, bool front_facing) {
  const Executable* fs = program.fragment();
  const int lanes = quads * 4;
  out.assign(static_cast<size_t>(lanes), std::vector<float>(kNumFragmentOutputs * 4, 0.0f));
  if (!fs) return 0;
  std::vector<std::vector<float>> soa_in(kNumFragmentInputs * 4), soa_out(kNumFragmentOutputs * 4);
  std::vector<const float*> ip(kNumFragmentInputs * 4, nullptr);
  std::vector<float*> op(kNumFragmentOutputs * 4, nullptr);
  for (int c : fs->inputs_read()) {
    auto& a = soa_in[static_cast<size_t>(c)];
    for (int l = 0; l < lanes; ++l)
      a.push_back(in[static_cast<size_t>(l)][static_cast<size_t>(c)]);
    ip[static_cast<size_t>(c)] = a.data();
  }
  for (int c : fs->outputs_written()) {
    soa_out[static_cast<size_t>(c)].assign(static_cast<size_t>(lanes), 0.0f);
    op[static_cast<size_t>(c)] = soa_out[static_cast<size_t>(c)].data();
  }
  Prepared prep;
  fs->prepare(uniforms.data(), prep);
  FragmentQuads q;
  q.quads = quads;
  q.in = ip.data();
  q.out = op.data();
  q.front_facing = front_facing;
  q.sampler = &sampler;
  const uint64_t kill = fs->run_fragments(prep, q, scratch_.data());
  for (int c : fs->outputs_written())
    for (int l = 0; l < lanes; ++l)
      out[static_cast<size_t>(l)][static_cast<size_t>(c)] =
          soa_out[static_cast<size_t>(c)][static_cast<size_t>(l)];
  return kill;
}

void Pipeline::clear(const Vec4& c) {
  std::fill(fb.begin(), fb.end(), c);
}

Vec4 Pipeline::pixel(int x, int y) const {
  if (x < 0 || y < 0 || x >= width || y >= height) return {0, 0, 0, 0};
  return fb[static_cast<size_t>(y * width + x)];
}

void Pipeline::draw_rect(float x, float y, float w, float h) {
  std::vector<std::vector<float>> in(4, attrib_defaults);
  const float xs[4] = {x, x + w, x, x + w}, ys[4] = {y, y, y + h, y + h};
  // The position goes to gl_Vertex and to piglit's generic attribute piglit_vertex.
  const int generic = program.attrib_location("piglit_vertex");
  for (size_t v = 0; v < 4; ++v) {
    for (int slot : {static_cast<int>(kInVertex), generic < 0 ? -1 : kInGeneric0 + generic}) {
      if (slot < 0) continue;
      in[v][static_cast<size_t>(slot * 4 + 0)] = xs[v];
      in[v][static_cast<size_t>(slot * 4 + 1)] = ys[v];
      in[v][static_cast<size_t>(slot * 4 + 2)] = 0.0f;
      in[v][static_cast<size_t>(slot * 4 + 3)] = 1.0f;
    }
  }
  std::vector<std::vector<float>> out;
  if (program.vertex()) {
    set_builtin_state();
    out = run_vertices(in);
  } else {
    // Fixed-function vertex processing, as far as these tests need it.
    out.assign(4, std::vector<float>(kNumVertexOutputs * 4, 0.0f));
    const float W = static_cast<float>(width), H = static_cast<float>(height);
    for (size_t v = 0; v < 4; ++v) {
      float px = in[v][0], py = in[v][1];
      if (ortho) px = px * 2 / W - 1, py = py * 2 / H - 1;
      out[v][kOutPosition * 4 + 0] = px;
      out[v][kOutPosition * 4 + 1] = py;
      out[v][kOutPosition * 4 + 3] = 1.0f;
      for (int c = 0; c < 4; ++c) {
        out[v][static_cast<size_t>(kOutFrontColor * 4 + c)] =
            in[v][static_cast<size_t>(kInColor * 4 + c)];
        for (int t = 0; t < kMaxTextureCoords; ++t)
          out[v][static_cast<size_t>((kOutTexCoord0 + t) * 4 + c)] =
              in[v][static_cast<size_t>((kInMultiTexCoord0 + t) * 4 + c)];
      }
    }
  }
  const std::vector<float>* t0[3] = {&out[0], &out[1], &out[2]};
  const std::vector<float>* t1[3] = {&out[2], &out[1], &out[3]};
  draw_triangle(t0);
  draw_triangle(t1);
}

void Pipeline::draw_triangle(const std::vector<float>* vin[3]) {
  const double W = width, H = height;
  const std::vector<float>* v[3] = {vin[0], vin[1], vin[2]};
  double wx[3], wy[3], wz[3], iw[3];
  for (int i = 0; i < 3; ++i) {
    const float* p = v[i]->data() + kOutPosition * 4;
    const double w = p[3] != 0 ? p[3] : 1e-30;
    iw[i] = 1.0 / w;
    wx[i] = (p[0] * iw[i] + 1) * W * 0.5;
    wy[i] = (p[1] * iw[i] + 1) * H * 0.5;
    wz[i] = (p[2] * iw[i] + 1) * 0.5;
  }
  double area = (wx[1] - wx[0]) * (wy[2] - wy[0]) - (wx[2] - wx[0]) * (wy[1] - wy[0]);
  if (area == 0 || !std::isfinite(area)) return;
  const bool front = area > 0;
  if (!front) {
    // Counter-clockwise from here on, so that the fill rule below has one orientation.
    std::swap(v[1], v[2]), std::swap(wx[1], wx[2]), std::swap(wy[1], wy[2]);
    std::swap(wz[1], wz[2]), std::swap(iw[1], iw[2]);
    area = -area;
  }
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min({wx[0], wx[1], wx[2]}))) & ~1);
  const int y0 = std::max(0, static_cast<int>(std::floor(std::min({wy[0], wy[1], wy[2]}))) & ~1);
  const int x1 = std::min(width - 1, static_cast<int>(std::ceil(std::max({wx[0], wx[1], wx[2]}))));
  const int y1 = std::min(height - 1, static_cast<int>(std::ceil(std::max({wy[0], wy[1], wy[2]}))));
  // Edge functions; a pixel centre on an edge belongs to the triangle on the edge's left or
  // top side only, so that triangles sharing an edge draw its pixels once.
  bool inside_tie[3];
  for (int i = 0; i < 3; ++i) {
    const int a = (i + 1) % 3, b = (i + 2) % 3;
    const double dx = wx[b] - wx[a], dy = wy[b] - wy[a];
    inside_tie[i] = dy < 0 || (dy == 0 && dx > 0);
  }
  const auto edges = [&](double px, double py, double e[3]) {
    for (int i = 0; i < 3; ++i) {
      const int a = (i + 1) % 3, b = (i + 2) % 3;
      e[i] = (wx[b] - wx[a]) * (py - wy[a]) - (wy[b] - wy[a]) * (px - wx[a]);
    }
  };
  // Where each fragment input comes from among the vertex outputs.
  std::vector<int> from(kNumFragmentInputs * 4, -1);
  for (int c = 0; c < 4; ++c) {
    from[static_cast<size_t>(kFragColor * 4 + c)] =
        (front ? kOutFrontColor : kOutBackColor) * 4 + c;
    from[static_cast<size_t>(kFragSecondaryColor * 4 + c)] =
        (front ? kOutFrontSecondaryColor : kOutBackSecondaryColor) * 4 + c;
    for (int t = 0; t < kMaxTextureCoords; ++t)
      from[static_cast<size_t>((kFragTexCoord0 + t) * 4 + c)] = (kOutTexCoord0 + t) * 4 + c;
    for (int s = 0; s < kMaxVaryingSlots; ++s)
      from[static_cast<size_t>((kFragVarying0 + s) * 4 + c)] = (kOutVarying0 + s) * 4 + c;
  }
  from[kFragFogFragCoord * 4] = kOutFogFragCoord * 4;
  if (!program.vertex()) {
    // Fixed-function colours come unlit from the vertex.
    for (int c = 0; c < 4; ++c)
      from[static_cast<size_t>(kFragColor * 4 + c)] = kOutFrontColor * 4 + c;
  }
  std::vector<std::array<int, 2>> quads;
  for (int qy = y0; qy <= y1; qy += 2)
    for (int qx = x0; qx <= x1; qx += 2)
      quads.push_back({qx, qy});
  std::vector<std::vector<float>> in, out;
  for (size_t first = 0; first < quads.size(); first += 16) {
    const int nq = static_cast<int>(std::min<size_t>(16, quads.size() - first));
    in.assign(static_cast<size_t>(nq * 4), std::vector<float>(kNumFragmentInputs * 4, 0.0f));
    uint64_t covered = 0;
    for (int q = 0; q < nq; ++q)
      for (int l = 0; l < 4; ++l) {
        const int px = quads[first + static_cast<size_t>(q)][0] + (l & 1);
        const int py = quads[first + static_cast<size_t>(q)][1] + (l >> 1);
        double e[3];
        edges(px + 0.5, py + 0.5, e);
        const int lane = q * 4 + l;
        bool hit = px < width && py < height;
        for (int i = 0; i < 3; ++i)
          hit = hit && (e[i] > 0 || (e[i] == 0 && inside_tie[i]));
        if (hit) covered |= uint64_t{1} << lane;
        double b[3], pw[3], sum = 0;
        for (int i = 0; i < 3; ++i)
          b[i] = e[i] / area, pw[i] = b[i] * iw[i], sum += pw[i];
        auto& li = in[static_cast<size_t>(lane)];
        for (size_t c = 0; c < from.size(); ++c) {
          if (from[c] < 0) continue;
          double a = 0;
          for (int i = 0; i < 3; ++i)
            a += pw[i] * (*v[i])[static_cast<size_t>(from[c])];
          li[c] = sum != 0 ? static_cast<float>(a / sum) : 0.0f;
        }
        li[kFragCoord * 4 + 0] = static_cast<float>(px) + 0.5f;
        li[kFragCoord * 4 + 1] = static_cast<float>(py) + 0.5f;
        li[kFragCoord * 4 + 2] = static_cast<float>(b[0] * wz[0] + b[1] * wz[1] + b[2] * wz[2]);
        li[kFragCoord * 4 + 3] = static_cast<float>(sum);
      }
    if (!covered) continue;
    uint64_t kill = 0;
    if (program.fragment()) {
      kill = run_fragments(nq, in, out, front);
    } else {
      out.assign(in.size(), std::vector<float>(kNumFragmentOutputs * 4, 0.0f));
      for (size_t l = 0; l < in.size(); ++l)
        for (int c = 0; c < 4; ++c)
          out[l][static_cast<size_t>(c)] = in[l][static_cast<size_t>(kFragColor * 4 + c)];
    }
    for (int lane = 0; lane < nq * 4; ++lane) {
      if (!((covered >> lane) & 1) || ((kill >> lane) & 1)) continue;
      const int px = quads[first + static_cast<size_t>(lane / 4)][0] + (lane & 1);
      const int py = quads[first + static_cast<size_t>(lane / 4)][1] + ((lane >> 1) & 1);
      Vec4& d = fb[static_cast<size_t>(py * width + px)];
      for (int c = 0; c < 4; ++c) {
        const float x = out[static_cast<size_t>(lane)][static_cast<size_t>(c)];
        d[static_cast<size_t>(c)] = std::isnan(x) ? 0.0f : std::clamp(x, 0.0f, 1.0f);
      }
    }
  }
}

} // namespace pineda::glsl_test
