// pineda_scene_runner: renders one conformance scene through whatever libOSMesa.so.8 the dynamic
// loader finds (Mesa's by default, Pineda's when LD_LIBRARY_PATH points at Pineda's build/lib).
//
//   pineda_scene_runner --list
//   pineda_scene_runner --manifest
//   pineda_scene_runner --scene NAME --out FILE.rgba [--reps N]
//
// The last form renders the scene once, writes the image (see common/rgba_image.h), renders it
// once more untimed, then N more times (default 5) timing each full frame (clear + draw +
// glFinish), and prints one line
//
//   RESULT<TAB>status=ok<TAB>renderer=...<TAB>version=...<TAB>median_ms=...<TAB>gl_error=0x0...
//
// that pineda_conformance parses. The program is deliberately an ordinary OSMesa client compiled
// against the system's <GL/osmesa.h>: running it on Pineda proves that an unmodified -lOSMesa
// program runs there.
//
// Built with PINEDA_RUNNER_EGL (pineda_scene_runner_egl), the same scenes render through EGL
// instead: a pbuffer of the surfaceless platform (EGL_MESA_platform_surfaceless) with the
// scene's depth and stencil sizes, read back with glReadPixels. The program is then an ordinary
// glvnd program (libEGL, libOpenGL); which vendor runs it is the environment's choice.
#include "../common/rgba_image.h"
#include "scene.h"

#ifdef PINEDA_RUNNER_EGL
#include <EGL/egl.h>
#include <EGL/eglext.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

// Exit codes; pineda_conformance reports them by name.
constexpr int kExitOk = 0;
constexpr int kExitUsage = 2;
constexpr int kExitUnsupported = 3;
constexpr int kExitContext = 4;
constexpr int kExitOutput = 5;
constexpr int kExitOverrun = 6;

// Bytes around the colour buffer that the library must never write.
constexpr std::size_t kGuardBytes = 4096;
constexpr unsigned char kGuardByte = 0xA5;

void usage() {
  std::fprintf(stderr,
               "usage: pineda_scene_runner --list | --manifest |\n"
               "       pineda_scene_runner --scene NAME --out FILE.rgba [--reps N]\n");
}

// Values printed in the RESULT line must not contain tabs or newlines.
std::string clean(const char* s) {
  std::string out = s ? s : "(null)";
  for (char& c : out)
    if (c == '\t' || c == '\n' || c == '\r') c = ' ';
  return out;
}

#ifndef PINEDA_RUNNER_EGL
int bytes_per_pixel(GLenum format) { return format == OSMESA_RGB ? 3 : 4; }

// Converts the OSMesa colour buffer to bottom-up RGBA8. OSMESA_ARGB and OSMESA_BGRA name the
// byte order in memory; OSMESA_RGB has no alpha, reported as 255. With OSMESA_Y_UP = 0 the first
// row in memory is the top of the image.
conformance::RgbaImage to_rgba(const unsigned char* buffer, const scenes::SceneOptions& o) {
  conformance::RgbaImage image;
  image.width = o.width;
  image.height = o.height;
  image.pixels.resize(static_cast<std::size_t>(o.width) * o.height * 4);
  const int bpp = bytes_per_pixel(o.format);
  for (int y = 0; y < o.height; ++y) {
    const int memory_row = o.y_up ? y : o.height - 1 - y;
    const unsigned char* src = buffer + static_cast<std::size_t>(memory_row) * o.width * bpp;
    unsigned char* dst = image.pixels.data() + static_cast<std::size_t>(y) * o.width * 4;
    for (int x = 0; x < o.width; ++x, src += bpp, dst += 4) {
      switch (o.format) {
      case OSMESA_BGRA: dst[0] = src[2]; dst[1] = src[1]; dst[2] = src[0]; dst[3] = src[3]; break;
      case OSMESA_ARGB: dst[0] = src[1]; dst[1] = src[2]; dst[2] = src[3]; dst[3] = src[0]; break;
      case OSMESA_RGB: dst[0] = src[0]; dst[1] = src[1]; dst[2] = src[2]; dst[3] = 255; break;
      default: std::memcpy(dst, src, 4); break;
      }
    }
  }
  return image;
}

#endif

const char* format_name(GLenum format) {
  switch (format) {
  case OSMESA_RGBA: return "OSMESA_RGBA";
  case OSMESA_BGRA: return "OSMESA_BGRA";
  case OSMESA_ARGB: return "OSMESA_ARGB";
  case OSMESA_RGB: return "OSMESA_RGB";
  default: return "?";
  }
}

void print_manifest() {
  // One scene a line: name, width, height, allowance, format, depth bits, y_up, oracle,
  // justification, description, GL version; tab-separated (the strings contain no tabs).
  for (const scenes::Scene& s : scenes::all_scenes()) {
    const auto& o = s.options;
    std::printf("%s\t%d\t%d\t%.4f\t%s\t%d\t%d\t%s\t%s\t%s\t%s\n", s.name.c_str(), o.width,
                o.height, o.allowance, format_name(o.format), o.depth_bits, o.y_up ? 1 : 0,
                o.softpipe_oracle ? "softpipe" : "llvmpipe", clean(o.why ? o.why : "").c_str(),
                clean(s.description.c_str()).c_str(), clean(o.gl_version ? o.gl_version : "").c_str());
  }
}

struct Result {
  std::string status = "ok";
  std::string detail;
  std::string renderer, version;
  double median_ms = 0.0, min_ms = 0.0;
  GLenum first_error = GL_NO_ERROR;
  bool frames_identical = true;
  int reps = 0;
};

void print_result(const Result& r) {
  std::printf("RESULT\tstatus=%s\tdetail=%s\trenderer=%s\tversion=%s\tmedian_ms=%.4f\tmin_ms=%.4f"
              "\treps=%d\tgl_error=0x%04x\tframes_identical=%d\n",
              r.status.c_str(), clean(r.detail.c_str()).c_str(), r.renderer.c_str(),
              r.version.c_str(), r.median_ms, r.min_ms, r.reps,
              static_cast<unsigned>(r.first_error), r.frames_identical ? 1 : 0);
  std::fflush(stdout);
}

void note_error(Result& r) {
  const GLenum e = glGetError();
  if (e != GL_NO_ERROR && r.first_error == GL_NO_ERROR) r.first_error = e;
}

#ifndef PINEDA_RUNNER_EGL
int run_scene(const scenes::Scene& scene, const std::string& out_path, int reps) {
  const scenes::SceneOptions& o = scene.options;
  Result result;
  OSMesaContext ctx =
      OSMesaCreateContextExt(o.format, o.depth_bits, o.stencil_bits, o.accum_bits, nullptr);
  if (!ctx) {
    result.status = "context_failed";
    result.detail = std::string("OSMesaCreateContextExt(") + format_name(o.format) + ", depth " +
                    std::to_string(o.depth_bits) + ") returned NULL";
    print_result(result);
    return kExitContext;
  }
  const std::size_t bytes =
      static_cast<std::size_t>(o.width) * static_cast<std::size_t>(o.height) * bytes_per_pixel(o.format);
  std::vector<unsigned char> storage(bytes + 2 * kGuardBytes, kGuardByte);
  unsigned char* buffer = storage.data() + kGuardBytes;
  std::memset(buffer, 0, bytes);
  if (!OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, o.width, o.height)) {
    result.status = "context_failed";
    result.detail = "OSMesaMakeCurrent failed";
    print_result(result);
    OSMesaDestroyContext(ctx);
    return kExitContext;
  }
  if (!o.y_up) OSMesaPixelStore(OSMESA_Y_UP, 0);
  result.renderer = clean(reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  result.version = clean(reinterpret_cast<const char*>(glGetString(GL_VERSION)));
  const scenes::Frame frame{o.width, o.height};

  int exit_code = kExitOk;
  try {
    scenes::reset_state(frame);
    scene.draw(frame);
    glFinish();
    note_error(result);
    const conformance::RgbaImage image = to_rgba(buffer, o);
    const std::vector<unsigned char> first(buffer, buffer + bytes);
    if (std::string err = conformance::write_rgba_file(out_path, image); !err.empty()) {
      result.status = "output_failed";
      result.detail = err;
      exit_code = kExitOutput;
    }
    std::vector<double> times;
    // One untimed warm-up repetition: llvmpipe's second frame still pays for caches filled
    // lazily, which would otherwise dominate the median of a few repetitions.
    for (int i = -1; i < reps && exit_code == kExitOk; ++i) {
      scenes::reset_state(frame);
      const auto t0 = std::chrono::steady_clock::now();
      scene.draw(frame);
      glFinish();
      const auto t1 = std::chrono::steady_clock::now();
      if (i >= 0) times.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      note_error(result);
      // Every repetition must reproduce the first frame exactly; otherwise the scene leaks state
      // between frames or the library is not deterministic.
      if (std::memcmp(first.data(), buffer, bytes) != 0) result.frames_identical = false;
    }
    if (!times.empty()) {
      std::sort(times.begin(), times.end());
      result.median_ms = times.size() % 2 ? times[times.size() / 2]
                                          : 0.5 * (times[times.size() / 2 - 1] + times[times.size() / 2]);
      result.min_ms = times.front();
      result.reps = static_cast<int>(times.size());
    }
  } catch (const scenes::Unsupported& missing) {
    result.status = "unsupported";
    result.detail = std::string("library lacks ") + missing.what();
    exit_code = kExitUnsupported;
  }
  note_error(result);
  for (std::size_t i = 0; i < kGuardBytes; ++i) {
    if (storage[i] != kGuardByte || storage[kGuardBytes + bytes + i] != kGuardByte) {
      result.status = "buffer_overrun";
      result.detail = "the library wrote outside the colour buffer";
      exit_code = kExitOverrun;
      break;
    }
  }
  print_result(result);
  OSMesaDestroyContext(ctx);
  return exit_code;
}

#endif

#ifdef PINEDA_RUNNER_EGL
// The scene through EGL: a surfaceless display, a pbuffer of the scene's size whose config has
// exactly the scene's alpha, depth and stencil sizes. Scenes that need an accumulation buffer
// (EGL configs have none) are reported unsupported.
int run_scene_egl(const scenes::Scene& scene, const std::string& out_path, int reps) {
  const scenes::SceneOptions& o = scene.options;
  Result result;
  auto fail = [&](const std::string& status, const std::string& detail, int code) {
    result.status = status;
    result.detail = detail + " (EGL error " + std::to_string(eglGetError()) + ")";
    print_result(result);
    return code;
  };
  if (o.accum_bits > 0)
    return fail("unsupported", "EGL configs have no accumulation buffer", kExitUnsupported);
  EGLDisplay dpy =
      eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, nullptr, nullptr) || !eglBindAPI(EGL_OPENGL_API))
    return fail("context_failed", "no surfaceless EGL display", kExitContext);
  const EGLint want[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                         EGL_NONE};
  EGLint n = 0;
  eglChooseConfig(dpy, want, nullptr, 0, &n);
  std::vector<EGLConfig> configs(static_cast<std::size_t>(std::max(n, 0)));
  if (n > 0) eglChooseConfig(dpy, want, configs.data(), n, &n);
  const int alpha = o.format == OSMESA_RGB ? 0 : 8;
  EGLConfig config = nullptr;
  for (EGLConfig c : configs) {
    EGLint a = 0, d = 0, st = 0;
    eglGetConfigAttrib(dpy, c, EGL_ALPHA_SIZE, &a);
    eglGetConfigAttrib(dpy, c, EGL_DEPTH_SIZE, &d);
    eglGetConfigAttrib(dpy, c, EGL_STENCIL_SIZE, &st);
    if (a == alpha && d == o.depth_bits && st == o.stencil_bits) {
      config = c;
      break;
    }
  }
  if (config == nullptr)
    return fail("context_failed",
                "no config with alpha " + std::to_string(alpha) + ", depth " +
                    std::to_string(o.depth_bits) + ", stencil " + std::to_string(o.stencil_bits),
                kExitContext);
  const EGLint size[] = {EGL_WIDTH, o.width, EGL_HEIGHT, o.height, EGL_NONE};
  EGLSurface surface = eglCreatePbufferSurface(dpy, config, size);
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  if (surface == EGL_NO_SURFACE || ctx == EGL_NO_CONTEXT ||
      !eglMakeCurrent(dpy, surface, surface, ctx))
    return fail("context_failed", "pbuffer, context or eglMakeCurrent failed", kExitContext);
  result.renderer = clean(reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  result.version = clean(reinterpret_cast<const char*>(glGetString(GL_VERSION)));
  const scenes::Frame frame{o.width, o.height};
  auto read = [&] {
    conformance::RgbaImage image;
    image.width = o.width;
    image.height = o.height;
    image.pixels.resize(static_cast<std::size_t>(o.width) * o.height * 4);
    // The scene's own pixel store state must not change the read-back.
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
    glPixelStorei(GL_PACK_LSB_FIRST, GL_FALSE);
    glReadPixels(0, 0, o.width, o.height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
    glPopClientAttrib();
    return image;
  };
  int exit_code = kExitOk;
  try {
    scenes::reset_state(frame);
    scene.draw(frame);
    glFinish();
    note_error(result);
    // The read itself must not be counted against the scene: the error state is read first.
    const conformance::RgbaImage first = read();
    if (std::string err = conformance::write_rgba_file(out_path, first); !err.empty()) {
      result.status = "output_failed";
      result.detail = err;
      exit_code = kExitOutput;
    }
    for (int i = 0; i < reps && exit_code == kExitOk; ++i) {
      scenes::reset_state(frame);
      scene.draw(frame);
      glFinish();
      note_error(result);
      if (read().pixels != first.pixels) result.frames_identical = false;
    }
  } catch (const scenes::Unsupported& missing) {
    result.status = "unsupported";
    result.detail = std::string("library lacks ") + missing.what();
    exit_code = kExitUnsupported;
  }
  note_error(result);
  print_result(result);
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroySurface(dpy, surface);
  eglDestroyContext(dpy, ctx);
  eglTerminate(dpy);
  return exit_code;
}
#endif

} // namespace

int main(int argc, char** argv) {
  std::string scene_name, out_path;
  int reps = 5;
  bool list = false, manifest = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", arg.c_str());
        std::exit(kExitUsage);
      }
      return argv[++i];
    };
    if (arg == "--list") list = true;
    else if (arg == "--manifest") manifest = true;
    else if (arg == "--scene") scene_name = value();
    else if (arg == "--out") out_path = value();
    else if (arg == "--reps") reps = std::max(0, std::atoi(value()));
    else {
      usage();
      return kExitUsage;
    }
  }
  if (list) {
    for (const scenes::Scene& s : scenes::all_scenes())
      std::printf("%-28s %s\n", s.name.c_str(), s.description.c_str());
    return kExitOk;
  }
  if (manifest) {
    print_manifest();
    return kExitOk;
  }
  if (scene_name.empty() || out_path.empty()) {
    usage();
    return kExitUsage;
  }
  for (const scenes::Scene& s : scenes::all_scenes())
#ifdef PINEDA_RUNNER_EGL
    if (s.name == scene_name) return run_scene_egl(s, out_path, reps);
#else
    if (s.name == scene_name) return run_scene(s, out_path, reps);
#endif
  std::fprintf(stderr, "unknown scene '%s' (see --list)\n", scene_name.c_str());
  return kExitUsage;
}
