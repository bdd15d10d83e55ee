// The tests' texture sampler (test_sampler.h).
#include "support/test_sampler.h"

#include <algorithm>
#include <cmath>

namespace pineda::glsl_test {

void TestTexture::build_mipmaps() {
  mipmaps = true;
  int w = width, h = height, d = depth;
  const int faces = target == shader::TexTarget::Cube ? 6 : 1;
  while (w > 1 || h > 1 || d > 1) {
    const int nw = std::max(1, w / 2), nh = std::max(1, h / 2), nd = std::max(1, d / 2);
    std::array<std::vector<std::array<float, 4>>, 6> next;
    const auto& prev = levels.back();
    for (int f = 0; f < faces; ++f)
      for (int z = 0; z < nd; ++z)
        for (int y = 0; y < nh; ++y)
          for (int x = 0; x < nw; ++x) {
            std::array<float, 4> acc{};
            int n = 0;
            for (int dz = 0; dz < (d > 1 ? 2 : 1); ++dz)
              for (int dy = 0; dy < (h > 1 ? 2 : 1); ++dy)
                for (int dx = 0; dx < (w > 1 ? 2 : 1); ++dx) {
                  const auto& t = prev[static_cast<size_t>(f)][static_cast<size_t>(
                      ((2 * z + dz) * h + (2 * y + dy)) * w + (2 * x + dx))];
                  for (int c = 0; c < 4; ++c)
                    acc[static_cast<size_t>(c)] += t[static_cast<size_t>(c)];
                  ++n;
                }
            for (float& c : acc)
              c /= static_cast<float>(n);
            next[static_cast<size_t>(f)].push_back(acc);
          }
    levels.push_back(std::move(next));
    w = nw, h = nh, d = nd;
  }
}

namespace {

int wrap(int i, int n, bool repeat) {
  if (repeat) return ((i % n) + n) % n;
  return std::clamp(i, 0, n - 1);
}

// Texel coordinate of s in [0, 1] scaled to n texels, NaN and infinities made harmless.
float scaled(float s, int n) {
  if (!std::isfinite(s)) s = 0.0f;
  return std::clamp(s, -1e6f, 1e6f) * static_cast<float>(n);
}

} // namespace

std::array<float, 4> TestSampler::lookup(int unit, float s, float t, float r, float lambda,
                                         bool shadow) const {
  if (unit < 0 || unit >= static_cast<int>(units.size()) ||
      units[static_cast<size_t>(unit)].levels.empty())
    return {0, 0, 0, 1};
  const TestTexture& tex = units[static_cast<size_t>(unit)];
  int face = 0;
  float ref = r;
  if (tex.target == shader::TexTarget::Cube) {
    // GL 2.1 §3.8.6, Table 3.19.
    const float ax = std::fabs(s), ay = std::fabs(t), az = std::fabs(r);
    float sc, tc, ma;
    if (ax >= ay && ax >= az) {
      face = s >= 0 ? 0 : 1;
      sc = s >= 0 ? -r : r, tc = -t, ma = ax;
    } else if (ay >= az) {
      face = t >= 0 ? 2 : 3;
      sc = s, tc = t >= 0 ? r : -r, ma = ay;
    } else {
      face = r >= 0 ? 4 : 5;
      sc = r >= 0 ? s : -s, tc = -t, ma = az;
    }
    if (!(ma > 0)) ma = 1;
    s = (sc / ma + 1) * 0.5f;
    t = (tc / ma + 1) * 0.5f;
    r = 0;
  }
  int level = 0;
  if (tex.mipmaps && std::isfinite(lambda) && lambda > 0.5f)
    level = std::min(static_cast<int>(lambda + 0.5f), static_cast<int>(tex.levels.size()) - 1);
  const int w = std::max(1, tex.width >> level), h = std::max(1, tex.height >> level),
            d = std::max(1, tex.depth >> level);
  const bool is1d = tex.target == shader::TexTarget::Tex1D;
  const bool is3d = tex.target == shader::TexTarget::Tex3D;
  const auto& data = tex.levels[static_cast<size_t>(level)][static_cast<size_t>(face)];
  const auto texel = [&](int x, int y, int z) {
    x = wrap(x, w, tex.repeat);
    y = is1d ? 0 : wrap(y, h, tex.repeat);
    z = is3d ? wrap(z, d, tex.repeat) : 0;
    return data[static_cast<size_t>((z * h + y) * w + x)];
  };
  std::array<float, 4> out{};
  const float u = scaled(s, w), v = scaled(t, h), q = scaled(r, d);
  if (!tex.linear) {
    out = texel(static_cast<int>(std::floor(u)), static_cast<int>(std::floor(v)),
                static_cast<int>(std::floor(q)));
  } else {
    const float fu = u - 0.5f, fv = is1d ? 0.0f : v - 0.5f, fq = is3d ? q - 0.5f : 0.0f;
    const int x0 = static_cast<int>(std::floor(fu)), y0 = static_cast<int>(std::floor(fv)),
              z0 = static_cast<int>(std::floor(fq));
    const float a = fu - static_cast<float>(x0), b = fv - static_cast<float>(y0),
                g = fq - static_cast<float>(z0);
    for (int dz = 0; dz < 2; ++dz)
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
          const float wgt = (dx ? a : 1 - a) * (dy ? b : 1 - b) * (dz ? g : 1 - g);
          if (wgt == 0) continue;
          const auto tx = texel(x0 + dx, y0 + dy, z0 + dz);
          for (int c = 0; c < 4; ++c)
            out[static_cast<size_t>(c)] += wgt * tx[static_cast<size_t>(c)];
        }
  }
  if (shadow) {
    // GL 2.1 §3.8.14: LEQUAL, the result as luminance.
    const float dref = std::clamp(std::isfinite(ref) ? ref : 0.0f, 0.0f, 1.0f);
    const float v2 = dref <= out[0] ? 1.0f : 0.0f;
    return {v2, v2, v2, 1.0f};
  }
  return out;
}

void TestSampler::sample(const shader::TexRequest& req) {
  ++calls;
  const TestTexture* tex = req.unit >= 0 && req.unit < static_cast<int>(units.size())
                               ? &units[static_cast<size_t>(req.unit)]
                               : nullptr;
  for (int l = 0; l < req.lanes; ++l) {
    const float s = req.coord[0] ? req.coord[0][l] : 0.0f;
    const float t = req.coord[1] ? req.coord[1][l] : 0.0f;
    const float r = req.coord[2] ? req.coord[2][l] : 0.0f;
    float lambda = 0.0f;
    if (req.lod == shader::LodMode::Explicit) {
      lambda = req.lod_or_bias ? req.lod_or_bias[l] : 0.0f;
    } else if (tex) {
      // §3.8.8 from the quad's upper row (x) and left column (y), as fragment/shade.cpp.
      const int q = l & ~3;
      const auto d = [&](int k, int a, int b, int size) {
        return req.coord[k] ? (req.coord[k][q + a] - req.coord[k][q + b]) * static_cast<float>(size)
                            : 0.0f;
      };
      const float dx0 = d(0, 3, 2, tex->width), dy0 = d(0, 2, 0, tex->width);
      const float dx1 = d(1, 3, 2, tex->height), dy1 = d(1, 2, 0, tex->height);
      const float rho =
          std::max(std::sqrt(dx0 * dx0 + dx1 * dx1), std::sqrt(dy0 * dy0 + dy1 * dy1));
      lambda = rho > 0 ? std::log2(rho) : -100.0f;
      if (req.lod == shader::LodMode::Bias && req.lod_or_bias) lambda += req.lod_or_bias[l];
    }
    const auto c = lookup(req.unit, s, t, r, lambda, req.shadow);
    for (int k = 0; k < 4; ++k)
      req.rgba[k][l] = c[static_cast<size_t>(k)];
  }
}

} // namespace pineda::glsl_test
