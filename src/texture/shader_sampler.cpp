// GLSL texture lookups through the sampler (shader_sampler.h).
#include "texture/shader_sampler.h"

#include <algorithm>
#include <cmath>

namespace pineda {

namespace {

// lambda of each quad (§3.8.8 eq 3.18-3.19) from its fragments' coordinates, as the fixed
// path takes it: d/dx along the upper row, d/dy along the left column, rho the longer scaled
// derivative vector. Cube maps: the derivatives of the face coordinates along the major axis
// of the quad's lower-left fragment.
void quad_lambdas(const SamplerView& v, shader::TexTarget target, int lanes, const float* s,
                  const float* t, const float* r, float* lambda) {
  const float width = static_cast<float>(v.width), height = static_cast<float>(v.height);
  const float depth = static_cast<float>(v.depth);
  for (int q = 0; q < lanes / 4; ++q) {
    const int ll = 4 * q, ul = ll + 2, ur = ll + 3;
    float dx[3] = {0, 0, 0}, dy[3] = {0, 0, 0};
    if (target == shader::TexTarget::Cube) {
      const float ax = std::fabs(s[ll]), ay = std::fabs(t[ll]), az = std::fabs(r[ll]);
      const int major = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
      const auto face = [&](int p, float& u, float& w) {
        const float d[3] = {s[p], t[p], r[p]};
        const float ma = std::fabs(d[major]);
        const float inv = ma > 0.0f ? 0.5f / ma : 0.0f;
        u = d[major == 0 ? 2 : 0] * inv;
        w = d[major == 1 ? 2 : 1] * inv;
      };
      float u0, v0, u1, v1, u2, v2;
      face(ul, u0, v0);
      face(ur, u1, v1);
      face(ll, u2, v2);
      dx[0] = (u1 - u0) * width, dx[1] = (v1 - v0) * width;
      dy[0] = (u0 - u2) * width, dy[1] = (v0 - v2) * width;
    } else {
      dx[0] = (s[ur] - s[ul]) * width, dy[0] = (s[ul] - s[ll]) * width;
      if (target != shader::TexTarget::Tex1D)
        dx[1] = (t[ur] - t[ul]) * height, dy[1] = (t[ul] - t[ll]) * height;
      if (target == shader::TexTarget::Tex3D)
        dx[2] = (r[ur] - r[ul]) * depth, dy[2] = (r[ul] - r[ll]) * depth;
    }
    const float rho2 = std::max(dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2],
                                dy[0] * dy[0] + dy[1] * dy[1] + dy[2] * dy[2]);
    // NaN coordinates (lanes outside the primitive may carry any value) stay finite here.
    const float lam = rho2 > 0.0f && rho2 < INFINITY ? std::max(0.5f * lod_log2(rho2), -64.0f)
                                                     : (rho2 > 0.0f ? 64.0f : -64.0f);
    for (int l = 0; l < 4; ++l)
      lambda[ll + l] = lam;
  }
}

} // namespace

void ShaderSampler::sample(const shader::TexRequest& req) {
  const int n = std::min(req.lanes, kMaxSampleBatch);
  const int target = static_cast<int>(req.target);
  const bool ok = req.unit >= 0 && req.unit < kMaxCombinedTextureImageUnits && target >= 0 &&
                  target < 4 && complete[req.unit][target];
  if (!ok) {
    // An incomplete texture (or a unit with none) returns (0, 0, 0, 1) (§3.8.10 as GL 3.x
    // states it; what llvmpipe does).
    for (int l = 0; l < n; ++l) {
      req.rgba[0][l] = req.rgba[1][l] = req.rgba[2][l] = 0.0f;
      req.rgba[3][l] = 1.0f;
    }
    return;
  }
  const SamplerView& v = views[req.unit][target];
  // Coordinates the engine leaves out for lower dimensions read as zero.
  alignas(16) float zeros[kMaxSampleBatch] = {};
  const float* s = req.coord[0] != nullptr ? req.coord[0] : zeros;
  const float* t = req.coord[1] != nullptr ? req.coord[1] : zeros;
  const float* r = req.coord[2] != nullptr ? req.coord[2] : zeros;
  alignas(16) float lambda[kMaxSampleBatch];
  float bias = 0.0f;
  switch (req.lod) {
  case shader::LodMode::Implicit:
    quad_lambdas(v, req.target, n, s, t, r, lambda);
    bias = unit_bias[req.unit];
    break;
  case shader::LodMode::Bias:
    quad_lambdas(v, req.target, n, s, t, r, lambda);
    for (int l = 0; l < n; ++l)
      lambda[l] += req.lod_or_bias[l];
    bias = unit_bias[req.unit];
    break;
  default:
    for (int l = 0; l < n; ++l)
      lambda[l] = req.lod_or_bias != nullptr ? req.lod_or_bias[l] : 0.0f;
    break;
  }
  // The sampler wants finite levels and coordinates it can wrap; NaN lanes become zero.
  alignas(16) float cs[kMaxSampleBatch], ct[kMaxSampleBatch], cr[kMaxSampleBatch];
  for (int l = 0; l < n; ++l) {
    cs[l] = std::isnan(s[l]) ? 0.0f : s[l];
    ct[l] = std::isnan(t[l]) ? 0.0f : t[l];
    cr[l] = std::isnan(r[l]) ? 0.0f : r[l];
    if (!(lambda[l] > -64.0f)) lambda[l] = -64.0f;
    if (!(lambda[l] < 64.0f)) lambda[l] = 64.0f;
  }
  float out[kMaxSampleBatch][4];
  sample_texture(v, n, cs, ct, cr, lambda, bias, out);
  for (int l = 0; l < n; ++l)
    for (int c = 0; c < 4; ++c)
      req.rgba[c][l] = out[l][c];
}

} // namespace pineda
