// Drawing with GL_FRONT_AND_BACK (GL 2.1 §4.2.1, draw/draw_buffers.h): each colour buffer must
// end up exactly as if the same commands had drawn into it alone, from the same depth and
// stencil values, and the depth and stencil buffers as after one such pass. The scene mixes
// depth and stencil writes, blending (so the two buffers' different contents matter), wide
// points and lines, outlined polygons, large shared draws, pixel rectangles and bitmaps.
#include <GL/gl.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "api_fixture.h"
#include "state/context.h"
#include "state/draw_read_buffer.h"
#include "state/framebuffer_object.h"

namespace {

class FrontAndBackTest : public GLTest {
protected:
  static constexpr int kN = kW * kH;
  void SetUp() override {
    GLTest::SetUp();
    ctx = pineda::current_context();
    ASSERT_NE(ctx, nullptr);
    ASSERT_NE(ctx->fb.depth, nullptr);
    ASSERT_NE(ctx->fb.stencil, nullptr);
    // The OSMesa buffer becomes the back buffer of a double-buffered drawable, as GLX makes
    // one (winsys/glx/glx_drawable.cpp).
    front.assign(kN * 4, 0);
    ctx->color_buffers = pineda::kColorBufferFrontLeft | pineda::kColorBufferBackLeft;
    ctx->window.back_color = ctx->window.color;
    ctx->window.front_color = front.data();
    pineda::framebuffers_changed(ctx);
    for (int i = 0; i < kN * 4; ++i) {
      front_start.push_back(static_cast<uint8_t>(i * 37 + 11));
      back_start.push_back(static_cast<uint8_t>(i * 53 + 200));
    }
    for (int i = 0; i < kN; ++i) {
      depth_start.push_back(static_cast<uint32_t>(i) * 2654435761u >> 8);
      stencil_start.push_back(static_cast<uint8_t>(i * 7));
    }
  }

  void reset() {
    std::memcpy(front.data(), front_start.data(), front.size());
    std::memcpy(ctx->window.back_color, back_start.data(), back_start.size());
    std::memcpy(ctx->fb.depth, depth_start.data(), depth_start.size() * 4);
    std::memcpy(ctx->fb.stencil, stencil_start.data(), stencil_start.size());
  }

  struct Result {
    std::vector<uint8_t> front, back, stencil;
    std::vector<uint32_t> depth;
  };
  Result result() const {
    Result r;
    r.front = front;
    r.back.assign(ctx->window.back_color, ctx->window.back_color + kN * 4);
    r.depth.assign(ctx->fb.depth, ctx->fb.depth + kN);
    r.stencil.assign(ctx->fb.stencil, ctx->fb.stencil + kN);
    return r;
  }

  static void tri(float x0, float y0, float x1, float y1, float x2, float y2, float z) {
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x2, y2, z);
  }

  // The scene, drawn into whatever glDrawBuffer selects.
  void scene(GLenum buffer) {
    glDrawBuffer(buffer);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_GEQUAL, 100, 0xff);
    glStencilOp(GL_INCR, GL_DECR, GL_INVERT);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    // One draw of overlapping triangles at several depths: later ones meet the depth and
    // stencil values the earlier ones wrote.
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 12; ++i) {
      const float t = static_cast<float>(i) / 12.0f;
      glColor4f(t, 1.0f - t, 0.5f, 0.3f + 0.05f * static_cast<float>(i));
      tri(-0.9f + t, -0.8f, 0.7f, -0.5f + t, -0.2f, 0.9f - t, 0.8f - 1.5f * t);
    }
    glEnd();
    // Wide points and lines, and outlined polygons, near the window's edges.
    glPointSize(7.0f);
    glBegin(GL_POINTS);
    glColor4f(1, 0, 0, 0.6f);
    glVertex3f(-0.97f, -0.97f, -0.5f);
    glVertex3f(0.97f, 0.1f, -0.5f);
    glEnd();
    glLineWidth(5.0f);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x3f0f);
    glBegin(GL_LINE_STRIP);
    glColor4f(0, 0, 1, 0.7f);
    glVertex3f(-1.2f, 0.9f, -0.7f);
    glVertex3f(0.2f, -0.3f, 0.2f);
    glVertex3f(1.1f, 0.95f, -0.1f);
    glEnd();
    glDisable(GL_LINE_STIPPLE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glBegin(GL_QUADS);
    glColor4f(0.2f, 0.9f, 0.1f, 0.8f);
    glVertex3f(-0.6f, -0.6f, -0.9f);
    glVertex3f(0.6f, -0.6f, -0.9f);
    glVertex3f(0.6f, 0.6f, -0.9f);
    glVertex3f(-0.6f, 0.6f, -0.9f);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    // A draw large enough to be shared among the worker threads, and a clipped one.
    std::vector<float> v;
    for (int i = 0; i < 3000; ++i) {
      const float a = static_cast<float>(i) * 0.37f;
      v.insert(v.end(),
               {0.9f * std::sin(a), 0.9f * std::cos(a * 1.3f), std::sin(a * 0.7f),
                0.9f * std::sin(a + 1.0f), 0.9f * std::cos(a * 1.1f + 2.0f), std::cos(a * 0.3f),
                1.5f * std::sin(a * 2.0f), 1.5f * std::cos(a * 0.5f), 0.0f});
    }
    glColor4f(0.9f, 0.4f, 0.1f, 0.25f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v.data());
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(v.size() / 3));
    glDisableClientState(GL_VERTEX_ARRAY);
    // A pixel rectangle, zoomed and flipped, and a bitmap.
    std::vector<GLubyte> image(6 * 5 * 4);
    for (size_t i = 0; i < image.size(); ++i)
      image[i] = static_cast<GLubyte>(i * 29);
    glRasterPos3f(0.1f, 0.2f, -0.3f);
    glPixelZoom(2.5f, -1.5f);
    glDrawPixels(6, 5, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
    glPixelZoom(1.0f, 1.0f);
    const GLubyte bits[8] = {0xff, 0x81, 0xa5, 0x99, 0x99, 0xa5, 0x81, 0xff};
    glRasterPos3f(-0.5f, -0.1f, 0.4f);
    // One byte per row: rows padded to the default alignment of 4 would read past `bits`.
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBitmap(8, 8, 0, 0, 0, 0, bits);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glFinish();
  }

  pineda::Context* ctx = nullptr;
  std::vector<uint8_t> front, front_start, back_start, stencil_start;
  std::vector<uint32_t> depth_start;
};

TEST_F(FrontAndBackTest, EachBufferAsIfDrawnAlone) {
  {
    reset();
    scene(GL_FRONT_AND_BACK);
    const Result both = result();
    reset();
    scene(GL_FRONT);
    const Result front_only = result();
    reset();
    scene(GL_BACK);
    const Result back_only = result();
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    // The passes drew something, differently into the two buffers.
    EXPECT_NE(front_only.front, front_start);
    EXPECT_NE(back_only.back, back_start);
    EXPECT_EQ(both.front, front_only.front);
    EXPECT_EQ(both.back, back_only.back);
    EXPECT_EQ(both.depth, back_only.depth);
    EXPECT_EQ(both.stencil, back_only.stencil);
    EXPECT_EQ(front_only.depth, back_only.depth);
  }
}

} // namespace
