// The OSMesa API: context creation variants, buffer binding, pixel store, queries, proc
// lookup, per-thread current context, and rendering into each colour byte order.
#include <thread>

#include "api_fixture.h"

namespace {

std::vector<uint8_t> clear_and_get(GLenum format, int bpp, bool y_up = true) {
  OSMesaContext c = OSMesaCreateContextExt(format, 16, 0, 0, nullptr);
  EXPECT_NE(c, nullptr);
  std::vector<uint8_t> buf(4 * 2 * bpp, 0);
  EXPECT_EQ(OSMesaMakeCurrent(c, buf.data(), GL_UNSIGNED_BYTE, 4, 2), GL_TRUE);
  if (!y_up) OSMesaPixelStore(OSMESA_Y_UP, 0);
  glClearColor(1.0f, 0.5f, 0.0f, 0.25f);
  glClear(GL_COLOR_BUFFER_BIT);
  // Paint the bottom row blue with a rectangle so row order is visible.
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, 4, 0, 2, -1, 1);
  glColor4f(0, 0, 1, 1);
  glRectf(0, 0, 4, 1);
  glFinish();
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(c);
  return buf;
}

TEST(OSMesa, ColorByteOrders) {
  auto rgba = clear_and_get(OSMESA_RGBA, 4);
  // Row 0 (first in memory with Y_UP) is the bottom, blue.
  EXPECT_EQ(rgba[0], 0);
  EXPECT_EQ(rgba[2], 255);
  const uint8_t* top = &rgba[4 * 4];
  EXPECT_EQ(top[0], 255);
  EXPECT_NEAR(top[1], 128, 1);
  EXPECT_EQ(top[2], 0);
  EXPECT_NEAR(top[3], 64, 1);
  auto bgra = clear_and_get(OSMESA_BGRA, 4);
  EXPECT_EQ(bgra[16 + 0], 0);
  EXPECT_EQ(bgra[16 + 2], 255);
  EXPECT_NEAR(bgra[16 + 3], 64, 1);
  auto argb = clear_and_get(OSMESA_ARGB, 4);
  EXPECT_NEAR(argb[16 + 0], 64, 1);
  EXPECT_EQ(argb[16 + 1], 255);
  EXPECT_EQ(argb[16 + 3], 0);
  auto rgb = clear_and_get(OSMESA_RGB, 3);
  EXPECT_EQ(rgb[12 + 0], 255);
  EXPECT_EQ(rgb[12 + 2], 0);
  EXPECT_EQ(rgb[2], 255); // bottom row blue
}

TEST(OSMesa, YDownPutsBottomRowLast) {
  auto buf = clear_and_get(OSMESA_RGBA, 4, false);
  EXPECT_EQ(buf[0], 255);      // first row in memory is the top: orange
  EXPECT_EQ(buf[16 + 2], 255); // second is the bottom: blue
}

TEST(OSMesa, CreationVariants) {
  EXPECT_EQ(OSMesaCreateContextExt(OSMESA_RGB_565, 16, 0, 0, nullptr), nullptr);
  EXPECT_EQ(OSMesaCreateContextExt(OSMESA_COLOR_INDEX, 16, 0, 0, nullptr), nullptr);
  const int core[] = {OSMESA_PROFILE, OSMESA_CORE_PROFILE, 0};
  EXPECT_EQ(OSMesaCreateContextAttribs(core, nullptr), nullptr);
  // Up to the version glGetString(GL_VERSION) reports, 2.1, and no further.
  for (const int minor : {0, 1}) {
    const int v2[] = {OSMESA_CONTEXT_MAJOR_VERSION, 2, OSMESA_CONTEXT_MINOR_VERSION, minor, 0};
    OSMesaContext ok = OSMesaCreateContextAttribs(v2, nullptr);
    EXPECT_NE(ok, nullptr) << "2." << minor;
    OSMesaDestroyContext(ok);
  }
  const int v30[] = {OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 0, 0};
  EXPECT_EQ(OSMesaCreateContextAttribs(v30, nullptr), nullptr);
  const int attribs[] = {
      OSMESA_FORMAT, OSMESA_BGRA, OSMESA_DEPTH_BITS, 32, OSMESA_STENCIL_BITS, 8, 0};
  OSMesaContext c = OSMesaCreateContextAttribs(attribs, nullptr);
  ASSERT_NE(c, nullptr);
  std::vector<uint8_t> buf(8 * 8 * 4);
  EXPECT_EQ(OSMesaMakeCurrent(c, buf.data(), GL_FLOAT, 8, 8), GL_FALSE);
  EXPECT_EQ(OSMesaMakeCurrent(c, buf.data(), GL_UNSIGNED_BYTE, 0, 8), GL_FALSE);
  EXPECT_EQ(OSMesaMakeCurrent(c, nullptr, GL_UNSIGNED_BYTE, 8, 8), GL_FALSE);
  ASSERT_EQ(OSMesaMakeCurrent(c, buf.data(), GL_UNSIGNED_BYTE, 8, 8), GL_TRUE);
  EXPECT_EQ(OSMesaGetCurrentContext(), c);
  GLint v = 0;
  glGetIntegerv(GL_DEPTH_BITS, &v);
  EXPECT_EQ(v, 32);
  OSMesaGetIntegerv(OSMESA_FORMAT, &v);
  EXPECT_EQ(v, OSMESA_BGRA);
  OSMesaGetIntegerv(OSMESA_WIDTH, &v);
  EXPECT_EQ(v, 8);
  GLint w, h, fmt, bpv;
  void* p;
  EXPECT_EQ(OSMesaGetColorBuffer(c, &w, &h, &fmt, &p), GL_TRUE);
  EXPECT_EQ(p, buf.data());
  EXPECT_EQ(OSMesaGetDepthBuffer(c, &w, &h, &bpv, &p), GL_TRUE);
  EXPECT_EQ(w, 8);
  EXPECT_NE(p, nullptr);
  // Rebinding to a bigger buffer resizes the drawable; the viewport is kept (GL 2.1 §2.11.1).
  std::vector<uint8_t> big(16 * 16 * 4);
  ASSERT_EQ(OSMesaMakeCurrent(c, big.data(), GL_UNSIGNED_BYTE, 16, 16), GL_TRUE);
  OSMesaGetIntegerv(OSMESA_HEIGHT, &v);
  EXPECT_EQ(v, 16);
  GLint vp[4];
  glGetIntegerv(GL_VIEWPORT, vp);
  EXPECT_EQ(vp[2], 8);
  OSMesaDestroyContext(c);
  EXPECT_EQ(OSMesaGetCurrentContext(), nullptr);
}

TEST(OSMesa, ProcAddress) {
  EXPECT_EQ(reinterpret_cast<void*>(OSMesaGetProcAddress("glVertex3f")),
            reinterpret_cast<void*>(&glVertex3f));
  EXPECT_EQ(reinterpret_cast<void*>(OSMesaGetProcAddress("OSMesaMakeCurrent")),
            reinterpret_cast<void*>(&OSMesaMakeCurrent));
  EXPECT_EQ(OSMesaGetProcAddress("glNotAFunction"), nullptr);
  EXPECT_EQ(OSMesaGetProcAddress(nullptr), nullptr);
  EXPECT_EQ(reinterpret_cast<void*>(OSMesaGetProcAddress("glEvalMesh2")),
            reinterpret_cast<void*>(&glEvalMesh2));
}

TEST(OSMesa, CurrentContextIsPerThread) {
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
  std::vector<uint8_t> buf(4 * 4 * 4);
  ASSERT_EQ(OSMesaMakeCurrent(c, buf.data(), GL_UNSIGNED_BYTE, 4, 4), GL_TRUE);
  OSMesaContext seen = c;
  std::thread t([&] { seen = OSMesaGetCurrentContext(); });
  t.join();
  EXPECT_EQ(seen, nullptr);
  EXPECT_EQ(OSMesaGetCurrentContext(), c);
  OSMesaDestroyContext(c);
}

TEST(OSMesa, RowLength) {
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
  std::vector<uint8_t> buf(8 * 4 * 4, 0);
  ASSERT_EQ(OSMesaMakeCurrent(c, buf.data(), GL_UNSIGNED_BYTE, 4, 4), GL_TRUE);
  OSMesaPixelStore(OSMESA_ROW_LENGTH, 8);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  // Pixels 4..7 of each 8-pixel row are outside the drawable and stay untouched.
  EXPECT_EQ(buf[3 * 4], 255);
  EXPECT_EQ(buf[4 * 4], 0);
  EXPECT_EQ(buf[8 * 4], 255);
  OSMesaDestroyContext(c);
}

class Render : public GLTest {};

TEST_F(Render, FullWindowTriangleAndReadPixels) {
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(0, 1, 0);
  glBegin(GL_TRIANGLES);
  glVertex2f(-1, -1);
  glVertex2f(3, -1);
  glVertex2f(-1, 3);
  glEnd();
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      ASSERT_EQ(pixel(x, y), 0xff00ff00u) << x << "," << y;
  uint8_t rgba[4];
  glReadPixels(5, 6, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  EXPECT_EQ(rgba[1], 255);
  float z = -1;
  glClearDepth(0.25);
  glClear(GL_DEPTH_BUFFER_BIT);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z);
  EXPECT_NEAR(z, 0.25f, 1e-6f);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Render, DepthTestKeepsNearer) {
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glColor3f(1, 0, 0);
  glRectf(-1, -1, 1, 1); // z = 0 → window 0.5
  glColor3f(0, 0, 1);
  glBegin(GL_QUADS);
  glVertex3f(-1, -1, 0.5f);
  glVertex3f(1, -1, 0.5f);
  glVertex3f(1, 1, 0.5f);
  glVertex3f(-1, 1, 0.5f);
  glEnd();
  EXPECT_EQ(pixel(10, 10), 0xff0000ffu); // red stays: blue is farther
  glDepthFunc(GL_GREATER);
  glBegin(GL_QUADS);
  glVertex3f(-1, -1, 0.5f);
  glVertex3f(1, -1, 0.5f);
  glVertex3f(1, 1, 0.5f);
  glVertex3f(-1, 1, 0.5f);
  glEnd();
  EXPECT_EQ(pixel(10, 10), 0xffff0000u);
}

TEST_F(Render, ArraysAndBuffersDrawTheSame) {
  const float verts[] = {-1, -1, 1, -1, 1, 1, -1, 1};
  const uint8_t colors[] = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
  const GLushort idx[] = {0, 1, 2, 0, 2, 3};
  glVertexPointer(2, GL_FLOAT, 0, verts);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, idx);
  EXPECT_EQ(pixel(0, 0), 0xff0000ffu);
  EXPECT_EQ(pixel(31, 31), 0xff0000ffu);
  glClear(GL_COLOR_BUFFER_BIT);
  GLuint b[2];
  glGenBuffers(2, b);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof(verts), verts, GL_STATIC_DRAW);
  glVertexPointer(2, GL_FLOAT, 0, nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof(idx), idx, GL_STATIC_DRAW);
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, nullptr);
  EXPECT_EQ(pixel(16, 16), 0xff0000ffu);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glDeleteBuffers(2, b);
}

} // namespace
