// The same GL scenes rendered with the baseline block loops and with the AVX2 and AVX-512 ones
// (simd_level.h) give the same bytes: full-screen depth-tested layers (the overdraw bench, with
// the depth writers around it: clears, scissored clears, DrawPixels of depth, depth mask off,
// polygon offset, stencil), blended quads, one-pixel triangles, textured and fogged
// triangles, lines and points.
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "core/simd_level.h"

namespace {

using pineda::SimdLevel;

constexpr int kW = 203, kH = 157; // not multiples of 8

// Renders `draw` in a new context (so that its draws set up their block loops at `level`).
std::vector<uint8_t> render(SimdLevel level, const std::function<void()>& draw) {
  const SimdLevel saved = pineda::simd_level();
  pineda::set_simd_level(level);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  std::vector<uint8_t> buf(static_cast<size_t>(kW) * kH * 4, 0);
  EXPECT_NE(ctx, nullptr);
  if (ctx == nullptr) return buf;
  EXPECT_EQ(OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, kW, kH), GL_TRUE);
  glViewport(0, 0, kW, kH);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kW, 0, kH, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  draw();
  glFinish();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // The depth buffer too, as 32-bit values.
  std::vector<uint32_t> depth(static_cast<size_t>(kW) * kH);
  glReadPixels(0, 0, kW, kH, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth.data());
  const auto* bytes = reinterpret_cast<const uint8_t*>(depth.data());
  buf.insert(buf.end(), bytes, bytes + depth.size() * 4);
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);
  pineda::set_simd_level(saved);
  return buf;
}

// Every level above the baseline that the processor has against the baseline.
void expect_same(const std::function<void()>& draw) {
  if (pineda::simd_level_supported() < SimdLevel::Avx2) GTEST_SKIP() << "no AVX2";
  const std::vector<uint8_t> base = render(SimdLevel::Baseline, draw);
  for (SimdLevel level : {SimdLevel::Avx2, SimdLevel::Avx512}) {
    if (level > pineda::simd_level_supported()) continue;
    SCOPED_TRACE(level == SimdLevel::Avx512 ? "AVX-512" : "AVX2");
    const std::vector<uint8_t> wide = render(level, draw);
    ASSERT_EQ(base.size(), wide.size());
    size_t differ = 0;
    for (size_t i = 0; i < base.size(); ++i)
      differ += base[i] != wide[i];
    EXPECT_EQ(differ, 0u);
  }
}

void quad(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y1, z);
  glEnd();
}

// Layers front to back and back to front (bench_overdraw_depth), z in glOrtho's [-1, 1].
void layers(int pass) {
  for (int i = 0; i < 6; ++i) {
    const int layer = pass == 0 ? i : 5 - i;
    const float z = 0.8f - 0.3f * static_cast<float>(layer) - 0.1f * static_cast<float>(pass);
    glBegin(GL_QUADS);
    glColor3f(0.15f * static_cast<float>(layer), 0.3f, 0.9f);
    glVertex3f(0, 0, -z);
    glVertex3f(kW, 0, -z);
    glColor3f(0.1f, 0.5f, 1.0f - 0.1f * static_cast<float>(layer));
    glVertex3f(kW, kH, -z);
    glVertex3f(0, kH, -z);
    glEnd();
  }
}

TEST(SimdLevel, OverdrawWithEveryDepthWriter) {
  expect_same([] {
    glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    layers(0);
    layers(1);
    // A scissored depth clear, then depth written by DrawPixels.
    glEnable(GL_SCISSOR_TEST);
    glScissor(20, 10, 90, 70);
    glClearDepth(0.3);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    std::vector<float> zs(64 * 40);
    for (size_t i = 0; i < zs.size(); ++i)
      zs[i] = static_cast<float>(i % 97) / 96.0f;
    glRasterPos2i(100, 60);
    glDrawPixels(64, 40, GL_DEPTH_COMPONENT, GL_FLOAT, zs.data());
    layers(1);
    // Depth mask off, LEQUAL, GREATER, polygon offset.
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_LEQUAL);
    layers(0);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_GREATER);
    layers(1);
    glDepthFunc(GL_LESS);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 64.0f);
    layers(0);
    glDisable(GL_POLYGON_OFFSET_FILL);
    // Stencil: depth-fail updates must see every fragment of a hidden block.
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_INCR, GL_REPLACE);
    layers(0);
    glStencilFunc(GL_EQUAL, 2, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glDisable(GL_DEPTH_TEST);
    glColor3f(1, 1, 1);
    quad(0, 0, kW, kH, 0);
    glDisable(GL_STENCIL_TEST);
  });
}

TEST(SimdLevel, BlendedQuads) {
  expect_same([] {
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_BLEND);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const GLenum src[] = {GL_SRC_ALPHA, GL_ONE, GL_DST_COLOR, GL_CONSTANT_ALPHA};
    const GLenum dst[] = {GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_COLOR};
    for (int k = 0; k < 4; ++k) {
      glBlendFunc(src[k], dst[k]);
      glBegin(GL_QUADS);
      for (int i = 0; i < 60; ++i) {
        const float x = u(rng) * 250 - 30, y = u(rng) * 200 - 30, s = 10 + u(rng) * 90;
        glColor4f(u(rng), u(rng), u(rng), u(rng));
        glVertex2f(x, y);
        glVertex2f(x + s, y);
        glColor4f(u(rng) * 1.2f, u(rng), u(rng), u(rng));
        glVertex2f(x + s, y + s);
        glVertex2f(x, y + s);
      }
      glEnd();
    }
    glDisable(GL_BLEND);
  });
}

TEST(SimdLevel, TinyTrianglesLinesAndPoints) {
  expect_same([] {
    glClear(GL_COLOR_BUFFER_BIT);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 3000; ++i) {
      const float x = 1 + u(rng) * (kW - 2), y = 1 + u(rng) * (kH - 2);
      glColor3f(u(rng), u(rng), u(rng));
      glVertex2f(x, y);
      glVertex2f(x + 0.5f + u(rng), y + u(rng) * 0.6f - 0.3f);
      glVertex2f(x + u(rng) * 0.6f - 0.3f, y + 0.5f + u(rng));
    }
    glEnd();
    glLineWidth(3.0f);
    glBegin(GL_LINES);
    for (int i = 0; i < 100; ++i) {
      glColor4f(u(rng), u(rng), u(rng), 1);
      glVertex2f(u(rng) * kW, u(rng) * kH);
      glColor4f(u(rng), u(rng), u(rng), 1);
      glVertex2f(u(rng) * kW, u(rng) * kH);
    }
    glEnd();
    glPointSize(5.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 100; ++i) {
      glColor3f(u(rng), u(rng), u(rng));
      glVertex2f(u(rng) * kW, u(rng) * kH);
    }
    glEnd();
  });
}

TEST(SimdLevel, TexturedAndFogged) {
  expect_same([] {
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    std::vector<uint8_t> tex(16 * 16 * 4);
    for (size_t i = 0; i < tex.size(); ++i)
      tex[i] = static_cast<uint8_t>(i * 37);
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex.data());
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, -1.0f);
    glFogf(GL_FOG_END, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0.5f, 0.2f);
    glTexCoord2f(0, 0);
    glVertex3f(5, 5, 0.5f);
    glColor3f(0.2f, 1, 0.5f);
    glTexCoord2f(3, 0);
    glVertex3f(190, 20, -0.5f);
    glTexCoord2f(1, 2);
    glVertex3f(60, 150, 0.0f);
    glEnd();
    glDisable(GL_FOG);
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &name);
  });
}

} // namespace
