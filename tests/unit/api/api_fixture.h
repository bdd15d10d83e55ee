// A GoogleTest fixture with a current OSMesa context on a small RGBA buffer.
#pragma once

#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <vector>

class GLTest : public ::testing::Test {
protected:
  static constexpr int kW = 32, kH = 32;
  void SetUp() override {
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    ASSERT_NE(ctx_, nullptr);
    buf_.assign(kW * kH * 4, 0);
    ASSERT_EQ(OSMesaMakeCurrent(ctx_, buf_.data(), GL_UNSIGNED_BYTE, kW, kH), GL_TRUE);
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  }
  void TearDown() override {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(ctx_);
  }
  // Pixel (x, y) of the buffer, bottom-up rows, as 0xAABBGGRR.
  uint32_t pixel(int x, int y) const {
    const uint8_t* p = &buf_[(y * kW + x) * 4];
    return p[0] | (p[1] << 8) | (p[2] << 16) | (static_cast<uint32_t>(p[3]) << 24);
  }
  OSMesaContext ctx_ = nullptr;
  std::vector<uint8_t> buf_;
};
