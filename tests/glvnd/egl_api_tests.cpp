// The EGL API on Pineda (EGL 1.5): every call's errors, config choice and sorting (§3.4.1),
// surfaces of each kind, contexts (EGL_KHR_create_context) and contexts current on two
// threads. Built twice: against glvnd's libEGL with Pineda as its vendor (the way programs
// reach it; run under Xvfb, the X11 tests included), and linked to Pineda's EGL directly (the
// sanitizer build; the surfaceless platform only when DISPLAY is unset).
// GoogleTest first: Xlib defines None and Bool as macros.
#include <gtest/gtest.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace {

bool have_x() {
  const char* d = std::getenv("DISPLAY");
  return d != nullptr && d[0] != '\0';
}

bool has_word(const char* list, const char* word) {
  if (list == nullptr) return false;
  const std::string s = std::string(" ") + list + " ";
  return s.find(std::string(" ") + word + " ") != std::string::npos;
}

EGLint attrib(EGLDisplay d, EGLConfig c, EGLint a) {
  EGLint v = -12345;
  EXPECT_TRUE(eglGetConfigAttrib(d, c, a, &v)) << std::hex << a;
  return v;
}

// Every configuration a display chooses for `attribs`.
std::vector<EGLConfig> choose(EGLDisplay d, const EGLint* attribs) {
  EGLint n = 0;
  EXPECT_TRUE(eglChooseConfig(d, attribs, nullptr, 0, &n));
  std::vector<EGLConfig> list(static_cast<size_t>(n));
  if (n > 0) {
    EXPECT_TRUE(eglChooseConfig(d, attribs, list.data(), n, &n));
  }
  list.resize(static_cast<size_t>(n));
  return list;
}

// A config of `d` with exactly these buffers that can render to `surface_type`.
EGLConfig exact_config(EGLDisplay d, EGLint surface_type, EGLint alpha, EGLint depth,
                       EGLint stencil) {
  const EGLint want[] = {EGL_SURFACE_TYPE, surface_type, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                         EGL_NONE};
  for (EGLConfig c : choose(d, want))
    if (attrib(d, c, EGL_ALPHA_SIZE) == alpha && attrib(d, c, EGL_DEPTH_SIZE) == depth &&
        attrib(d, c, EGL_STENCIL_SIZE) == stencil)
      return c;
  return nullptr;
}

// The pixel at (x, y) of the current read buffer as 0xRRGGBBAA.
uint32_t read_pixel(int x, int y) {
  uint8_t p[4] = {};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  return static_cast<uint32_t>(p[0]) << 24 | static_cast<uint32_t>(p[1]) << 16 |
         static_cast<uint32_t>(p[2]) << 8 | p[3];
}

class Surfaceless : public ::testing::Test {
protected:
  void SetUp() override {
    dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    ASSERT_NE(dpy, EGL_NO_DISPLAY);
    EGLint major = 0, minor = 0;
    ASSERT_TRUE(eglInitialize(dpy, &major, &minor));
    EXPECT_EQ(major, 1);
    EXPECT_EQ(minor, 5);
    ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
    config = exact_config(dpy, EGL_PBUFFER_BIT, 8, 24, 8);
    ASSERT_NE(config, nullptr);
  }
  void TearDown() override {
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglTerminate(dpy);
  }
  EGLSurface pbuffer(EGLConfig c, int w, int h) {
    const EGLint a[] = {EGL_WIDTH, w, EGL_HEIGHT, h, EGL_NONE};
    return eglCreatePbufferSurface(dpy, c, a);
  }
  EGLDisplay dpy = EGL_NO_DISPLAY;
  EGLConfig config = nullptr;
};

TEST(EglClient, ExtensionsAndVersion) {
  const char* ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  ASSERT_NE(ext, nullptr);
  EXPECT_TRUE(has_word(ext, "EGL_MESA_platform_surfaceless")) << ext;
  EXPECT_TRUE(has_word(ext, "EGL_EXT_platform_base")) << ext;
  EXPECT_TRUE(has_word(ext, "EGL_KHR_platform_x11")) << ext;
  EXPECT_TRUE(has_word(ext, "EGL_EXT_platform_x11")) << ext;
}

TEST(EglClient, ProcAddresses) {
  for (const char* name : {"glClear", "glDrawArrays", "glBindBufferARB", "glXSwapBuffers",
                           "eglCreateContext", "eglCreatePlatformWindowSurface", "eglCreateSync"}) {
    if (std::strncmp(name, "glX", 3) == 0) continue; // not an EGL or GL function
    EXPECT_NE(eglGetProcAddress(name), nullptr) << name;
  }
  EXPECT_EQ(eglGetProcAddress("eglNoSuchFunction"), nullptr);
}

TEST(EglDisplay, Errors) {
  EGLint major = 0, minor = 0;
  const auto bogus = reinterpret_cast<EGLDisplay>(static_cast<uintptr_t>(0x1234));
  EXPECT_FALSE(eglInitialize(bogus, &major, &minor));
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_SUCCESS); // reading the error resets it
  EXPECT_EQ(
      eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, reinterpret_cast<void*>(1), nullptr),
      EGL_NO_DISPLAY);
  EXPECT_NE(eglGetError(), EGL_SUCCESS);
  EGLDisplay d = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  ASSERT_NE(d, EGL_NO_DISPLAY);
  // The same platform and native display give the same handle.
  EXPECT_EQ(d, eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
  EGLint n = 0;
  EXPECT_FALSE(eglGetConfigs(d, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_NOT_INITIALIZED);
  EXPECT_EQ(eglQueryString(d, EGL_VENDOR), nullptr);
  EXPECT_EQ(eglGetError(), EGL_NOT_INITIALIZED);
  ASSERT_TRUE(eglInitialize(d, &major, &minor));
  EXPECT_TRUE(eglInitialize(d, nullptr, nullptr)); // again: no effect
  EXPECT_STREQ(eglQueryString(d, EGL_VENDOR), "Pineda");
  EXPECT_EQ(std::strncmp(eglQueryString(d, EGL_VERSION), "1.5", 3), 0);
  EXPECT_STREQ(eglQueryString(d, EGL_CLIENT_APIS), "OpenGL");
  EXPECT_TRUE(has_word(eglQueryString(d, EGL_EXTENSIONS), "EGL_KHR_create_context"));
  EXPECT_TRUE(has_word(eglQueryString(d, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"));
  EXPECT_EQ(eglQueryString(d, 0x1234), nullptr);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_FALSE(eglGetConfigs(d, nullptr, 0, nullptr));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_TRUE(eglTerminate(d));
  EXPECT_TRUE(eglTerminate(d)); // terminating twice is allowed
  EXPECT_FALSE(eglGetConfigs(d, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_NOT_INITIALIZED);
}

TEST_F(Surfaceless, ConfigAttributes) {
  EGLint n = 0;
  ASSERT_TRUE(eglGetConfigs(dpy, nullptr, 0, &n));
  ASSERT_GT(n, 0);
  std::vector<EGLConfig> all(static_cast<size_t>(n));
  ASSERT_TRUE(eglGetConfigs(dpy, all.data(), n, &n));
  std::vector<EGLint> ids;
  for (EGLConfig c : all) {
    EXPECT_EQ(attrib(dpy, c, EGL_RED_SIZE), 8);
    EXPECT_EQ(attrib(dpy, c, EGL_COLOR_BUFFER_TYPE), EGL_RGB_BUFFER);
    EXPECT_EQ(attrib(dpy, c, EGL_RENDERABLE_TYPE), EGL_OPENGL_BIT);
    EXPECT_EQ(attrib(dpy, c, EGL_CONFORMANT), EGL_OPENGL_BIT);
    EXPECT_EQ(attrib(dpy, c, EGL_SURFACE_TYPE) & EGL_PBUFFER_BIT, EGL_PBUFFER_BIT);
    // No multisampling yet (Pineda has no sample buffers).
    EXPECT_EQ(attrib(dpy, c, EGL_SAMPLE_BUFFERS), 0);
    EXPECT_EQ(attrib(dpy, c, EGL_SAMPLES), 0);
    EXPECT_EQ(attrib(dpy, c, EGL_BUFFER_SIZE), 24 + attrib(dpy, c, EGL_ALPHA_SIZE));
    ids.push_back(attrib(dpy, c, EGL_CONFIG_ID));
  }
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(std::adjacent_find(ids.begin(), ids.end()), ids.end()) << "config ids repeat";
  // Fewer slots than configs: only that many are returned.
  EGLConfig two[2];
  ASSERT_TRUE(eglGetConfigs(dpy, two, 2, &n));
  EXPECT_EQ(n, 2);
  EGLint v = 0;
  EXPECT_FALSE(eglGetConfigAttrib(dpy, all[0], 0x1234, &v));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_FALSE(eglGetConfigAttrib(dpy, reinterpret_cast<EGLConfig>(&v), EGL_RED_SIZE, &v));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONFIG);
}

TEST_F(Surfaceless, ChooseConfigErrors) {
  EGLint n = 0;
  const EGLint unknown[] = {0x1234, 1, EGL_NONE};
  EXPECT_FALSE(eglChooseConfig(dpy, unknown, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  const EGLint level[] = {EGL_LEVEL, EGL_DONT_CARE, EGL_NONE};
  EXPECT_FALSE(eglChooseConfig(dpy, level, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  const EGLint buffer_type[] = {EGL_COLOR_BUFFER_TYPE, 0x1234, EGL_NONE};
  EXPECT_FALSE(eglChooseConfig(dpy, buffer_type, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_FALSE(eglChooseConfig(dpy, nullptr, nullptr, 0, nullptr));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  // The default EGL_RENDERABLE_TYPE is EGL_OPENGL_ES_BIT (Table 3.4) and the default surface
  // type EGL_WINDOW_BIT: a surfaceless OpenGL-only display has no such config.
  EXPECT_TRUE(eglChooseConfig(dpy, nullptr, nullptr, 0, &n));
  EXPECT_EQ(n, 0);
}

// §3.4.1.2: the sort order, checked pair by pair on the attributes of the configs returned.
void expect_sorted(EGLDisplay d, const std::vector<EGLConfig>& list, bool count_alpha) {
  auto key = [&](EGLConfig c) {
    const long long color = 3 * 8 + (count_alpha ? attrib(d, c, EGL_ALPHA_SIZE) : 0);
    return std::vector<long long>{attrib(d, c, EGL_CONFIG_CAVEAT) == EGL_NONE ? 0 : 1,
                                  0,
                                  -color,
                                  attrib(d, c, EGL_BUFFER_SIZE),
                                  attrib(d, c, EGL_SAMPLE_BUFFERS),
                                  attrib(d, c, EGL_SAMPLES),
                                  attrib(d, c, EGL_DEPTH_SIZE),
                                  attrib(d, c, EGL_STENCIL_SIZE),
                                  attrib(d, c, EGL_ALPHA_MASK_SIZE),
                                  attrib(d, c, EGL_CONFIG_ID)};
  };
  for (size_t i = 1; i < list.size(); ++i)
    EXPECT_LT(key(list[i - 1]), key(list[i])) << "configs " << i - 1 << " and " << i;
}

TEST_F(Surfaceless, ChooseConfigSelectsAndSorts) {
  const EGLint base[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                         EGL_NONE};
  const auto all = choose(dpy, base);
  ASSERT_FALSE(all.empty());
  expect_sorted(dpy, all, false);
  // Without a colour size asked for, the smallest buffer (no alpha) and the smallest depth and
  // stencil buffers come first.
  EXPECT_EQ(attrib(dpy, all.front(), EGL_ALPHA_SIZE), 0);
  EXPECT_EQ(attrib(dpy, all.front(), EGL_DEPTH_SIZE), 0);
  EXPECT_EQ(attrib(dpy, all.front(), EGL_STENCIL_SIZE), 0);
  // Asking for alpha counts it among the colour bits: the larger totals sort first.
  const EGLint alpha[] = {EGL_SURFACE_TYPE,
                          EGL_PBUFFER_BIT,
                          EGL_RENDERABLE_TYPE,
                          EGL_OPENGL_BIT,
                          EGL_ALPHA_SIZE,
                          1,
                          EGL_DEPTH_SIZE,
                          1,
                          EGL_NONE};
  const auto with_alpha = choose(dpy, alpha);
  ASSERT_FALSE(with_alpha.empty());
  expect_sorted(dpy, with_alpha, true);
  for (EGLConfig c : with_alpha) {
    EXPECT_EQ(attrib(dpy, c, EGL_ALPHA_SIZE), 8);
    EXPECT_GE(attrib(dpy, c, EGL_DEPTH_SIZE), 1);
  }
  EXPECT_EQ(attrib(dpy, with_alpha.front(), EGL_DEPTH_SIZE), 16);
  // At-least sizes, exact caveat.
  const EGLint deep[] = {EGL_SURFACE_TYPE,
                         EGL_PBUFFER_BIT,
                         EGL_RENDERABLE_TYPE,
                         EGL_OPENGL_BIT,
                         EGL_DEPTH_SIZE,
                         24,
                         EGL_STENCIL_SIZE,
                         8,
                         EGL_CONFIG_CAVEAT,
                         EGL_NONE,
                         EGL_NONE};
  for (EGLConfig c : choose(dpy, deep)) {
    EXPECT_GE(attrib(dpy, c, EGL_DEPTH_SIZE), 24);
    EXPECT_EQ(attrib(dpy, c, EGL_STENCIL_SIZE), 8);
  }
  // Multisampled configs do not exist yet.
  const EGLint samples[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,    EGL_RENDERABLE_TYPE,
                            EGL_OPENGL_BIT,   EGL_SAMPLE_BUFFERS, 1,
                            EGL_NONE};
  EXPECT_TRUE(choose(dpy, samples).empty());
  // EGL_CONFIG_ID selects one config and every other attribute is ignored.
  const EGLint id = attrib(dpy, all[2], EGL_CONFIG_ID);
  const EGLint by_id[] = {EGL_CONFIG_ID, id, EGL_DEPTH_SIZE, 99, EGL_NONE};
  const auto one = choose(dpy, by_id);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0], all[2]);
  // Only the colour components asked for count: DONT_CARE does not.
  const EGLint dont_care[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                              EGL_OPENGL_BIT,   EGL_ALPHA_SIZE,  EGL_DONT_CARE,
                              EGL_NONE};
  EXPECT_EQ(attrib(dpy, choose(dpy, dont_care).front(), EGL_ALPHA_SIZE), 0);
}

TEST_F(Surfaceless, PbufferSurface) {
  EGLSurface s = pbuffer(config, 64, 32);
  ASSERT_NE(s, EGL_NO_SURFACE);
  EGLint v = 0;
  EXPECT_TRUE(eglQuerySurface(dpy, s, EGL_WIDTH, &v));
  EXPECT_EQ(v, 64);
  EXPECT_TRUE(eglQuerySurface(dpy, s, EGL_HEIGHT, &v));
  EXPECT_EQ(v, 32);
  EXPECT_TRUE(eglQuerySurface(dpy, s, EGL_CONFIG_ID, &v));
  EXPECT_EQ(v, attrib(dpy, config, EGL_CONFIG_ID));
  EXPECT_TRUE(eglQuerySurface(dpy, s, EGL_LARGEST_PBUFFER, &v));
  EXPECT_EQ(v, EGL_FALSE);
  EXPECT_TRUE(eglQuerySurface(dpy, s, EGL_RENDER_BUFFER, &v));
  EXPECT_EQ(v, EGL_BACK_BUFFER);
  EXPECT_TRUE(eglQuerySurface(dpy, s, EGL_TEXTURE_FORMAT, &v));
  EXPECT_EQ(v, EGL_NO_TEXTURE);
  EXPECT_FALSE(eglQuerySurface(dpy, s, 0x1234, &v));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_TRUE(eglSurfaceAttrib(dpy, s, EGL_SWAP_BEHAVIOR, EGL_BUFFER_DESTROYED));
  EXPECT_FALSE(eglSurfaceAttrib(dpy, s, EGL_MULTISAMPLE_RESOLVE, EGL_MULTISAMPLE_RESOLVE_BOX));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_FALSE(eglSurfaceAttrib(dpy, s, 0x1234, 0));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_FALSE(eglBindTexImage(dpy, s, EGL_BACK_BUFFER));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);

  const EGLint negative[] = {EGL_WIDTH, -1, EGL_NONE};
  EXPECT_EQ(eglCreatePbufferSurface(dpy, config, negative), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  const EGLint texture[] = {EGL_TEXTURE_FORMAT, EGL_TEXTURE_RGB, EGL_TEXTURE_TARGET, EGL_TEXTURE_2D,
                            EGL_NONE};
  EXPECT_EQ(eglCreatePbufferSurface(dpy, config, texture), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  const EGLint unknown[] = {0x1234, 1, EGL_NONE};
  EXPECT_EQ(eglCreatePbufferSurface(dpy, config, unknown), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  const EGLint srgb[] = {EGL_GL_COLORSPACE, EGL_GL_COLORSPACE_SRGB, EGL_NONE};
  EXPECT_EQ(eglCreatePbufferSurface(dpy, config, srgb), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_EQ(eglCreatePbufferSurface(dpy, reinterpret_cast<EGLConfig>(&v), nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_CONFIG);
  const EGLint huge[] = {EGL_WIDTH,           1 << 20,  EGL_HEIGHT, 4,
                         EGL_LARGEST_PBUFFER, EGL_TRUE, EGL_NONE};
  EGLSurface largest = eglCreatePbufferSurface(dpy, config, huge);
  ASSERT_NE(largest, EGL_NO_SURFACE);
  EXPECT_TRUE(eglQuerySurface(dpy, largest, EGL_WIDTH, &v));
  EXPECT_EQ(v, attrib(dpy, config, EGL_MAX_PBUFFER_WIDTH));
  EXPECT_TRUE(eglDestroySurface(dpy, largest));
  EXPECT_FALSE(eglDestroySurface(dpy, largest));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  // Pixmaps and windows do not exist on the surfaceless platform.
  EXPECT_EQ(eglCreatePixmapSurface(dpy, config, 0, nullptr), EGL_NO_SURFACE);
  EXPECT_NE(eglGetError(), EGL_SUCCESS);
  EXPECT_TRUE(eglDestroySurface(dpy, s));
}

TEST_F(Surfaceless, ContextsAndVersions) {
  EGLContext c = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_NE(c, EGL_NO_CONTEXT);
  EGLint v = 0;
  EXPECT_TRUE(eglQueryContext(dpy, c, EGL_CONTEXT_CLIENT_TYPE, &v));
  EXPECT_EQ(v, EGL_OPENGL_API);
  EXPECT_TRUE(eglQueryContext(dpy, c, EGL_CONFIG_ID, &v));
  EXPECT_EQ(v, attrib(dpy, config, EGL_CONFIG_ID));
  EXPECT_TRUE(eglQueryContext(dpy, c, EGL_RENDER_BUFFER, &v));
  EXPECT_EQ(v, EGL_NONE);
  EXPECT_FALSE(eglQueryContext(dpy, c, 0x1234, &v));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  // The version the context reports is the most that can be asked for.
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, c));
  int major = 0, minor = 0;
  ASSERT_EQ(
      std::sscanf(reinterpret_cast<const char*>(glGetString(GL_VERSION)), "%d.%d", &major, &minor),
      2);
  for (int m = 0; m <= minor; ++m) {
    const EGLint a[] = {EGL_CONTEXT_MAJOR_VERSION, major, EGL_CONTEXT_MINOR_VERSION, m, EGL_NONE};
    EGLContext ok = eglCreateContext(dpy, config, EGL_NO_CONTEXT, a);
    EXPECT_NE(ok, EGL_NO_CONTEXT) << major << "." << m;
    eglDestroyContext(dpy, ok);
  }
  const EGLint above[] = {EGL_CONTEXT_MAJOR_VERSION, major, EGL_CONTEXT_MINOR_VERSION, minor + 1,
                          EGL_NONE};
  // 1.6 does not exist and 2.2 neither: both are a mismatch.
  EXPECT_EQ(eglCreateContext(dpy, config, EGL_NO_CONTEXT, above), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  const EGLint gl45[] = {EGL_CONTEXT_MAJOR_VERSION,
                         4,
                         EGL_CONTEXT_MINOR_VERSION,
                         5,
                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                         EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                         EGL_NONE};
  EXPECT_EQ(eglCreateContext(dpy, config, EGL_NO_CONTEXT, gl45), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  const EGLint robust[] = {EGL_CONTEXT_OPENGL_ROBUST_ACCESS, EGL_TRUE, EGL_NONE};
  EXPECT_EQ(eglCreateContext(dpy, config, EGL_NO_CONTEXT, robust), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  const EGLint debug[] = {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE, EGL_NONE};
  EGLContext dbg = eglCreateContext(dpy, config, EGL_NO_CONTEXT, debug);
  EXPECT_NE(dbg, EGL_NO_CONTEXT);
  eglDestroyContext(dpy, dbg);
  const EGLint unknown[] = {0x1234, 1, EGL_NONE};
  EXPECT_EQ(eglCreateContext(dpy, config, EGL_NO_CONTEXT, unknown), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_EQ(eglCreateContext(dpy, nullptr, EGL_NO_CONTEXT, nullptr), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_CONFIG);
  EXPECT_EQ(eglCreateContext(dpy, config, reinterpret_cast<EGLContext>(&v), nullptr),
            EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  // OpenGL ES is refused until Pineda has ES contexts.
  EXPECT_FALSE(eglBindAPI(EGL_OPENGL_ES_API));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_FALSE(eglBindAPI(EGL_OPENVG_API));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_EQ(eglQueryAPI(), static_cast<EGLenum>(EGL_OPENGL_API));
  // A shared context sees the share group's objects.
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glEndList();
  EGLContext shared = eglCreateContext(dpy, config, c, nullptr);
  ASSERT_NE(shared, EGL_NO_CONTEXT);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, shared));
  EXPECT_TRUE(glIsList(list));
  EXPECT_EQ(eglGetCurrentContext(), shared);
  EXPECT_TRUE(eglDestroyContext(dpy, shared)); // current: lives until released
  EXPECT_TRUE(glIsList(list));
  EXPECT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
  EXPECT_TRUE(eglDestroyContext(dpy, c));
  EXPECT_FALSE(eglDestroyContext(dpy, c));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
}

TEST_F(Surfaceless, MakeCurrentErrorsAndRendering) {
  EGLContext c = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_NE(c, EGL_NO_CONTEXT);
  EGLSurface s = pbuffer(config, 40, 30);
  ASSERT_NE(s, EGL_NO_SURFACE);
  EXPECT_FALSE(eglMakeCurrent(dpy, s, s, EGL_NO_CONTEXT));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_FALSE(eglMakeCurrent(dpy, s, EGL_NO_SURFACE, c));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_FALSE(eglMakeCurrent(dpy, s, s, reinterpret_cast<EGLContext>(&c)));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  EXPECT_FALSE(eglMakeCurrent(dpy, reinterpret_cast<EGLSurface>(&c), s, c));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  EGLSurface other = pbuffer(config, 8, 8);
  EXPECT_FALSE(eglMakeCurrent(dpy, s, other, c)); // separate read surfaces are not offered
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  // A surface of a config with other ancillary buffers is a mismatch.
  EGLConfig no_depth = exact_config(dpy, EGL_PBUFFER_BIT, 8, 0, 0);
  ASSERT_NE(no_depth, nullptr);
  EGLSurface shallow = pbuffer(no_depth, 8, 8);
  EXPECT_FALSE(eglMakeCurrent(dpy, shallow, shallow, c));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);

  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, c));
  EXPECT_EQ(eglGetCurrentSurface(EGL_DRAW), s);
  EXPECT_EQ(eglGetCurrentSurface(EGL_READ), s);
  EXPECT_EQ(eglGetCurrentDisplay(), dpy);
  GLint vp[4] = {};
  glGetIntegerv(GL_VIEWPORT, vp);
  EXPECT_EQ(vp[2], 40);
  EXPECT_EQ(vp[3], 30);
  GLint box[4] = {};
  glGetIntegerv(GL_SCISSOR_BOX, box);
  EXPECT_EQ(box[2], 40);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(10, 10, 5, 5);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  EXPECT_EQ(read_pixel(0, 0), 0xff0000ffu);
  EXPECT_EQ(read_pixel(12, 12), 0x0000ffffu);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EGLint v = 0;
  EXPECT_TRUE(eglQueryContext(dpy, c, EGL_RENDER_BUFFER, &v));
  EXPECT_EQ(v, EGL_BACK_BUFFER);
  // Swapping a pbuffer has no effect; a surface not current on this thread is an error.
  EXPECT_TRUE(eglSwapBuffers(dpy, s));
  EXPECT_FALSE(eglSwapBuffers(dpy, other));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  EXPECT_TRUE(eglSwapInterval(dpy, 0));
  // Surfaceless (EGL_KHR_surfaceless_context): GL works, drawing has no effect.
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, c));
  EXPECT_NE(glGetString(GL_RENDERER), nullptr);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glVertex2f(1, 0);
  glVertex2f(0, 1);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_FALSE(eglSwapInterval(dpy, 1));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  EXPECT_FALSE(eglSwapBuffers(dpy, s));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  // Back on the pbuffer its contents are still there.
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, c));
  EXPECT_EQ(read_pixel(12, 12), 0x0000ffffu);
  // A surface destroyed while current stays usable until released.
  EXPECT_TRUE(eglDestroySurface(dpy, s));
  EXPECT_EQ(read_pixel(12, 12), 0x0000ffffu);
  EXPECT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_FALSE(eglSwapInterval(dpy, 1));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  EXPECT_FALSE(eglMakeCurrent(dpy, s, s, c));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  eglDestroySurface(dpy, other);
  eglDestroySurface(dpy, shallow);
  eglDestroyContext(dpy, c);
}

TEST_F(Surfaceless, TwoThreads) {
  // Each thread renders its own colour into its own pbuffer with its own context, many times
  // over, and must read back only its own colour.
  std::atomic<int> failures{0};
  auto worker = [&](float r, float g, uint32_t expect) {
    eglBindAPI(EGL_OPENGL_API); // the bound API is per thread (§3.7)
    EGLContext c = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
    EGLSurface s = pbuffer(config, 64, 64);
    if (c == EGL_NO_CONTEXT || s == EGL_NO_SURFACE || !eglMakeCurrent(dpy, s, s, c)) {
      ++failures;
      return;
    }
    for (int i = 0; i < 200; ++i) {
      glClearColor(r, g, 0, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      glColor3f(r, g, 0);
      glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
      if (read_pixel(32, 32) != expect || read_pixel(1, 1) != expect) ++failures;
      if (eglGetCurrentContext() != c) ++failures;
    }
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroySurface(dpy, s);
    eglDestroyContext(dpy, c);
    eglReleaseThread();
  };
  std::thread a(worker, 1.0f, 0.0f, 0xff0000ffu);
  std::thread b(worker, 0.0f, 1.0f, 0x00ff00ffu);
  a.join();
  b.join();
  EXPECT_EQ(failures.load(), 0);

  // A context current on one thread cannot be made current on another (§3.7.3).
  EGLContext c = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  EGLSurface s = pbuffer(config, 8, 8);
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, c));
  EGLint error = EGL_SUCCESS;
  std::thread other([&] {
    eglBindAPI(EGL_OPENGL_API);
    if (!eglMakeCurrent(dpy, s, s, c)) error = eglGetError();
  });
  other.join();
  EXPECT_EQ(error, EGL_BAD_ACCESS);
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroySurface(dpy, s);
  eglDestroyContext(dpy, c);
}

TEST_F(Surfaceless, SyncsAndImages) {
  EXPECT_EQ(eglCreateSync(dpy, EGL_SYNC_FENCE, nullptr), EGL_NO_SYNC);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH); // no current context
  EGLContext c = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, c));
  EXPECT_EQ(eglCreateSync(dpy, EGL_SYNC_CL_EVENT, nullptr), EGL_NO_SYNC);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EGLSync sync = eglCreateSync(dpy, EGL_SYNC_FENCE, nullptr);
  ASSERT_NE(sync, EGL_NO_SYNC);
  EGLAttrib v = 0;
  EXPECT_TRUE(eglGetSyncAttrib(dpy, sync, EGL_SYNC_TYPE, &v));
  EXPECT_EQ(v, EGL_SYNC_FENCE);
  EXPECT_TRUE(eglGetSyncAttrib(dpy, sync, EGL_SYNC_STATUS, &v));
  EXPECT_EQ(v, EGL_SIGNALED);
  EXPECT_TRUE(eglGetSyncAttrib(dpy, sync, EGL_SYNC_CONDITION, &v));
  EXPECT_EQ(v, EGL_SYNC_PRIOR_COMMANDS_COMPLETE);
  EXPECT_FALSE(eglGetSyncAttrib(dpy, sync, 0x1234, &v));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_EQ(eglClientWaitSync(dpy, sync, EGL_SYNC_FLUSH_COMMANDS_BIT, EGL_FOREVER),
            EGL_CONDITION_SATISFIED);
  EXPECT_TRUE(eglWaitSync(dpy, sync, 0));
  EXPECT_FALSE(eglWaitSync(dpy, sync, 1));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_TRUE(eglDestroySync(dpy, sync));
  EXPECT_FALSE(eglDestroySync(dpy, sync));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  // No client buffer can be an EGLImage yet.
  EXPECT_EQ(
      eglCreateImage(dpy, c, EGL_GL_TEXTURE_2D, reinterpret_cast<EGLClientBuffer>(1), nullptr),
      EGL_NO_IMAGE);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(dpy, c);
}

TEST_F(Surfaceless, TerminateWhileCurrent) {
  EGLContext c = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  EGLSurface s = pbuffer(config, 16, 16);
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, c));
  ASSERT_TRUE(eglTerminate(dpy));
  // The context and surface live on while current.
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(read_pixel(3, 3), 0x00ff00ffu);
  EGLint v = 0;
  EXPECT_FALSE(eglQueryContext(dpy, c, EGL_CONFIG_ID, &v));
  EXPECT_EQ(eglGetError(), EGL_NOT_INITIALIZED);
  // Releasing works on a terminated display and frees them.
  EXPECT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  ASSERT_TRUE(eglInitialize(dpy, nullptr, nullptr));
  EXPECT_FALSE(eglQueryContext(dpy, c, EGL_CONFIG_ID, &v));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
}

// ---- the X11 platform ----

class X11 : public ::testing::Test {
protected:
  void SetUp() override {
    if (!have_x()) GTEST_SKIP() << "no X server (DISPLAY unset)";
    x = XOpenDisplay(nullptr);
    ASSERT_NE(x, nullptr);
    dpy = eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR, x, nullptr);
    ASSERT_NE(dpy, EGL_NO_DISPLAY);
    ASSERT_TRUE(eglInitialize(dpy, nullptr, nullptr));
    ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
    config = exact_config(dpy, EGL_WINDOW_BIT | EGL_PIXMAP_BIT, 0, 24, 8);
    ASSERT_NE(config, nullptr);
    ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
    ASSERT_NE(ctx, EGL_NO_CONTEXT);
  }
  void TearDown() override {
    if (x == nullptr) return;
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglTerminate(dpy);
    for (Window w : windows)
      XDestroyWindow(x, w);
    XCloseDisplay(x);
  }
  // A window of the config's visual.
  Window window(EGLConfig c, int w, int h) {
    XVisualInfo tmpl{};
    tmpl.visualid = static_cast<VisualID>(attrib(dpy, c, EGL_NATIVE_VISUAL_ID));
    int n = 0;
    XVisualInfo* vi = XGetVisualInfo(x, VisualIDMask, &tmpl, &n);
    EXPECT_NE(vi, nullptr);
    if (vi == nullptr) return 0;
    XSetWindowAttributes swa{};
    swa.colormap = XCreateColormap(x, DefaultRootWindow(x), vi->visual, AllocNone);
    swa.border_pixel = 0;
    Window win = XCreateWindow(x, DefaultRootWindow(x), 0, 0, static_cast<unsigned>(w),
                               static_cast<unsigned>(h), 0, vi->depth, InputOutput, vi->visual,
                               CWColormap | CWBorderPixel, &swa);
    XFree(vi);
    XMapWindow(x, win);
    XSync(x, False);
    windows.push_back(win);
    return win;
  }
  // The pixel at (px, py), counted from the top, of an X drawable as 0xRRGGBB.
  uint32_t x_pixel(Drawable d, int px, int py) {
    XImage* img = XGetImage(x, d, px, py, 1, 1, AllPlanes, ZPixmap);
    if (img == nullptr) return 0xdeadbeef;
    const auto p = static_cast<uint32_t>(XGetPixel(img, 0, 0)) & 0xffffffu;
    XDestroyImage(img);
    return p;
  }
  Display* x = nullptr;
  EGLDisplay dpy = EGL_NO_DISPLAY;
  EGLConfig config = nullptr;
  EGLContext ctx = EGL_NO_CONTEXT;
  std::vector<Window> windows;
};

TEST_F(X11, DisplayAndConfigs) {
  EXPECT_STREQ(eglQueryString(dpy, EGL_VENDOR), "Pineda");
  // Every window config names a visual of the screen with its depth.
  const EGLint win[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                        EGL_NONE};
  const auto list = choose(dpy, win);
  ASSERT_FALSE(list.empty());
  expect_sorted(dpy, list, false);
  for (EGLConfig c : list) {
    EXPECT_NE(attrib(dpy, c, EGL_NATIVE_VISUAL_ID), 0);
    EXPECT_EQ(attrib(dpy, c, EGL_NATIVE_VISUAL_TYPE), TrueColor);
    EXPECT_EQ(attrib(dpy, c, EGL_NATIVE_RENDERABLE), EGL_TRUE);
  }
  // EGL_MATCH_NATIVE_PIXMAP: the configs of the pixmap's depth.
  Pixmap pm = XCreatePixmap(x, DefaultRootWindow(x), 8, 8, 24);
  const EGLint match[] = {EGL_MATCH_NATIVE_PIXMAP,
                          static_cast<EGLint>(pm),
                          EGL_RENDERABLE_TYPE,
                          EGL_OPENGL_BIT,
                          EGL_SURFACE_TYPE,
                          EGL_PIXMAP_BIT,
                          EGL_NONE};
  const auto for_pixmap = choose(dpy, match);
  EXPECT_FALSE(for_pixmap.empty());
  for (EGLConfig c : for_pixmap)
    EXPECT_EQ(attrib(dpy, c, EGL_BUFFER_SIZE), 24 + attrib(dpy, c, EGL_ALPHA_SIZE));
  XFreePixmap(x, pm);
  const EGLint bad_pixmap[] = {EGL_MATCH_NATIVE_PIXMAP, 0x7fffff, EGL_NONE};
  EGLint n = 0;
  EXPECT_FALSE(eglChooseConfig(dpy, bad_pixmap, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_BAD_NATIVE_PIXMAP);
}

TEST_F(X11, WindowSurface) {
  Window win = window(config, 64, 48);
  EGLSurface s =
      eglCreateWindowSurface(dpy, config, static_cast<EGLNativeWindowType>(win), nullptr);
  ASSERT_NE(s, EGL_NO_SURFACE);
  // One surface per window.
  EXPECT_EQ(eglCreateWindowSurface(dpy, config, static_cast<EGLNativeWindowType>(win), nullptr),
            EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_ALLOC);
  EXPECT_EQ(eglCreateWindowSurface(dpy, config, 0x7fffff, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_NATIVE_WINDOW);
  const EGLint unknown[] = {0x1234, 1, EGL_NONE};
  EXPECT_EQ(eglCreateWindowSurface(dpy, config, static_cast<EGLNativeWindowType>(win), unknown),
            EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  // A config of another visual does not match the window.
  const EGLint windows_only[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE,
                                 EGL_OPENGL_BIT, EGL_NONE};
  for (EGLConfig other : choose(dpy, windows_only)) {
    if (attrib(dpy, other, EGL_NATIVE_VISUAL_ID) == attrib(dpy, config, EGL_NATIVE_VISUAL_ID))
      continue;
    Window w2 = window(config, 8, 8);
    EXPECT_EQ(eglCreateWindowSurface(dpy, other, static_cast<EGLNativeWindowType>(w2), nullptr),
              EGL_NO_SURFACE);
    EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
    break;
  }
  EGLint v = 0;
  EXPECT_TRUE(eglQuerySurface(dpy, s, EGL_WIDTH, &v));
  EXPECT_EQ(v, 64);
  EXPECT_TRUE(eglQuerySurface(dpy, s, EGL_RENDER_BUFFER, &v));
  EXPECT_EQ(v, EGL_BACK_BUFFER);
  EXPECT_TRUE(eglSurfaceAttrib(dpy, s, EGL_SWAP_BEHAVIOR, EGL_BUFFER_PRESERVED));
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, ctx));
  EXPECT_TRUE(eglSwapInterval(dpy, 0));
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 0, 0);
  glRectf(-1, 0, 0, 1); // the top-left quarter
  ASSERT_TRUE(eglSwapBuffers(dpy, s));
  XSync(x, False);
  EXPECT_EQ(x_pixel(win, 10, 10), 0xff0000u);
  EXPECT_EQ(x_pixel(win, 50, 40), 0x00ff00u);
  // The window grows: the surface follows at the next swap.
  XResizeWindow(x, win, 80, 60);
  XSync(x, False);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(eglSwapBuffers(dpy, s));
  glViewport(0, 0, 80, 60);
  glClear(GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(eglSwapBuffers(dpy, s));
  XSync(x, False);
  EXPECT_TRUE(eglQuerySurface(dpy, s, EGL_WIDTH, &v));
  EXPECT_EQ(v, 80);
  EXPECT_EQ(x_pixel(win, 75, 55), 0x0000ffu);
  // The platform entry point takes a pointer to the Window.
  Window w3 = window(config, 16, 16);
  EGLSurface p = eglCreatePlatformWindowSurface(dpy, config, &w3, nullptr);
  EXPECT_NE(p, EGL_NO_SURFACE);
  EXPECT_TRUE(eglDestroySurface(dpy, p));
  // A single-buffered window shows what was rendered at glFlush.
  Window w4 = window(config, 16, 16);
  const EGLint single[] = {EGL_RENDER_BUFFER, EGL_SINGLE_BUFFER, EGL_NONE};
  EGLSurface one =
      eglCreateWindowSurface(dpy, config, static_cast<EGLNativeWindowType>(w4), single);
  ASSERT_NE(one, EGL_NO_SURFACE);
  ASSERT_TRUE(eglMakeCurrent(dpy, one, one, ctx));
  glViewport(0, 0, 16, 16);
  glClearColor(1, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFlush();
  XSync(x, False);
  EXPECT_EQ(x_pixel(w4, 3, 3), 0xffff00u);
  EXPECT_TRUE(eglQueryContext(dpy, ctx, EGL_RENDER_BUFFER, &v));
  EXPECT_EQ(v, EGL_SINGLE_BUFFER);
}

TEST_F(X11, PixmapSurfaceAndCopyBuffers) {
  Pixmap pm = XCreatePixmap(x, DefaultRootWindow(x), 32, 32, 24);
  EGLSurface s = eglCreatePixmapSurface(dpy, config, static_cast<EGLNativePixmapType>(pm), nullptr);
  ASSERT_NE(s, EGL_NO_SURFACE);
  EGLint v = 0;
  EXPECT_TRUE(eglQuerySurface(dpy, s, EGL_RENDER_BUFFER, &v));
  EXPECT_EQ(v, EGL_SINGLE_BUFFER);
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, ctx));
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  EXPECT_EQ(x_pixel(pm, 5, 5), 0x0000ffu);
  // X rendering shows in GL after eglWaitNative.
  GC gc = XCreateGC(x, pm, 0, nullptr);
  XSetForeground(x, gc, 0xff0000);
  XFillRectangle(x, pm, gc, 0, 0, 32, 16); // the top half
  EXPECT_TRUE(eglWaitNative(EGL_CORE_NATIVE_ENGINE));
  EXPECT_EQ(read_pixel(5, 28), 0xff0000ffu);
  EXPECT_EQ(read_pixel(5, 4), 0x0000ffffu);
  EXPECT_FALSE(eglWaitNative(0x1234));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  // eglCopyBuffers from a pbuffer into another pixmap.
  const EGLint pb_attribs[] = {EGL_WIDTH, 32, EGL_HEIGHT, 32, EGL_NONE};
  EGLSurface pb = eglCreatePbufferSurface(dpy, config, pb_attribs);
  ASSERT_NE(pb, EGL_NO_SURFACE);
  ASSERT_TRUE(eglMakeCurrent(dpy, pb, pb, ctx));
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(0, 1, 0);
  glRectf(-1, -1, 1, 0); // the bottom half
  Pixmap target = XCreatePixmap(x, DefaultRootWindow(x), 32, 32, 24);
  ASSERT_TRUE(eglCopyBuffers(dpy, pb, static_cast<EGLNativePixmapType>(target)));
  EXPECT_EQ(x_pixel(target, 5, 28), 0x00ff00u);
  EXPECT_EQ(x_pixel(target, 5, 3), 0xffffffu);
  EXPECT_FALSE(eglCopyBuffers(dpy, pb, 0x7fffff));
  EXPECT_EQ(eglGetError(), EGL_BAD_NATIVE_PIXMAP);
  Pixmap deep = XCreatePixmap(x, DefaultRootWindow(x), 32, 32, 1);
  EXPECT_FALSE(eglCopyBuffers(dpy, pb, static_cast<EGLNativePixmapType>(deep)));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_EQ(eglCreatePixmapSurface(dpy, config, static_cast<EGLNativePixmapType>(deep), nullptr),
            EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  XFreeGC(x, gc);
  XFreePixmap(x, deep);
  XFreePixmap(x, target);
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroySurface(dpy, s);
  eglDestroySurface(dpy, pb);
  XFreePixmap(x, pm);
}

TEST_F(X11, CloseDisplayWhileCurrent) {
  // The application closes its X connection with a context current on a window surface: the
  // display is terminated with it, GL renders nowhere, and nothing crashes.
  Window win = window(config, 32, 32);
  EGLSurface s =
      eglCreateWindowSurface(dpy, config, static_cast<EGLNativeWindowType>(win), nullptr);
  ASSERT_NE(s, EGL_NO_SURFACE);
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, ctx));
  glClear(GL_COLOR_BUFFER_BIT);
  windows.clear();
  XCloseDisplay(x);
  x = nullptr;
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glRectf(-1, -1, 1, 1);
  glFinish();
  EGLint v = 0;
  EXPECT_FALSE(eglQuerySurface(dpy, s, EGL_WIDTH, &v));
  EXPECT_EQ(eglGetError(), EGL_NOT_INITIALIZED);
  EXPECT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_TRUE(eglTerminate(dpy));
}

TEST_F(X11, DefaultDisplay) {
  // eglGetDisplay(EGL_DEFAULT_DISPLAY) with DISPLAY set is an X11 display Pineda opens.
  EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  ASSERT_NE(d, EGL_NO_DISPLAY);
  ASSERT_TRUE(eglInitialize(d, nullptr, nullptr));
  const EGLint win[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                        EGL_NONE};
  EXPECT_FALSE(choose(d, win).empty());
  EXPECT_TRUE(eglTerminate(d));
}

} // namespace
