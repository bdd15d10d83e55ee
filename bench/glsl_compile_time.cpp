// GLSL compile and link time, Pineda against Mesa: every program of a directory in the framing
// tools/piglit_glsl_pairs.py writes (tests/fuzz/glsl_framing.h) is compiled and linked on both
// implementations, timing glCompileShader + glLinkProgram, and compile to first draw (the same
// plus glUseProgram, a one-pixel draw and glFinish, where llvmpipe generates its code).
//
//   tools/piglit_glsl_pairs.py --kind shader --out build/glsl_pairs
//   build/conformance/pineda_glsl_compile_time [--reps N] [--rounds N] [--every N]
//       [--pineda-lib DIR] [--tsv FILE] build/glsl_pairs
//
// It works as the conformance harness does: this program is an ordinary OSMesa program built
// against the system's headers and linked with the system's libOSMesa; it runs itself as a
// child once with LD_LIBRARY_PATH=<Pineda's lib dir> (Pineda's libOSMesa.so.8) and once without
// (Mesa llvmpipe, MESA_GL_VERSION_OVERRIDE=2.1, its shader cache off so that every compile is
// a compile), each child checking GL_RENDERER. A program's time is the median of --reps
// compilations (fresh shader and program objects each), the minimum over --rounds alternating
// Pineda/Mesa runs. A program that takes more than 30 s or crashes the child is reported and
// skipped. The summary gives the median and maximum per program on both and the ratios.
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "glsl_framing.h"
#include "process.h"

namespace {

namespace fs = std::filesystem;
namespace framing = pineda::glsl_framing;

struct GL2 {
  PFNGLCREATESHADERPROC CreateShader;
  PFNGLSHADERSOURCEPROC ShaderSource;
  PFNGLCOMPILESHADERPROC CompileShader;
  PFNGLGETSHADERIVPROC GetShaderiv;
  PFNGLCREATEPROGRAMPROC CreateProgram;
  PFNGLATTACHSHADERPROC AttachShader;
  PFNGLLINKPROGRAMPROC LinkProgram;
  PFNGLGETPROGRAMIVPROC GetProgramiv;
  PFNGLUSEPROGRAMPROC UseProgram;
  PFNGLDELETEPROGRAMPROC DeleteProgram;
  PFNGLDELETESHADERPROC DeleteShader;
};

template <typename Fn> Fn proc(const char* name) {
  OSMESAproc p = OSMesaGetProcAddress(name);
  if (p == nullptr) {
    std::fprintf(stderr, "%s is missing\n", name);
    std::exit(2);
  }
  return reinterpret_cast<Fn>(p);
}

std::string read_file(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

std::vector<fs::path> program_files(const std::string& dir, int every) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<fs::path> out;
  for (size_t i = 0; i < files.size(); i += static_cast<size_t>(every))
    out.push_back(files[i]);
  return out;
}

double ms_between(std::chrono::steady_clock::time_point a,
                  std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())))];
}

// ---- child: one implementation ----

struct Measure {
  const char* status = "linked";
  double compile_link_ms = 0, first_draw_ms = 0;
};

Measure measure_once(const GL2& gl, const framing::Program& prog) {
  Measure m;
  const auto t0 = std::chrono::steady_clock::now();
  const GLuint p = gl.CreateProgram();
  std::vector<GLuint> shaders;
  bool compiled = true;
  for (const auto& [stage, src] : prog.shaders) {
    const GLuint s =
        gl.CreateShader(stage == framing::Stage::Vertex ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER);
    const GLchar* str = src.data();
    const GLint len = static_cast<GLint>(src.size());
    gl.ShaderSource(s, 1, &str, &len);
    gl.CompileShader(s);
    GLint ok = 0;
    gl.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    compiled = compiled && ok;
    gl.AttachShader(p, s);
    shaders.push_back(s);
  }
  GLint linked = 0;
  if (compiled) {
    gl.LinkProgram(p);
    gl.GetProgramiv(p, GL_LINK_STATUS, &linked);
  }
  const auto t1 = std::chrono::steady_clock::now();
  m.compile_link_ms = ms_between(t0, t1);
  if (!compiled) {
    m.status = "compile-error";
  } else if (!linked) {
    m.status = "link-error";
  } else {
    // A one-pixel triangle pair in the 1x1 viewport.
    gl.UseProgram(p);
    glBegin(GL_TRIANGLE_STRIP);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(-1, 1);
    glVertex2f(1, 1);
    glEnd();
    glFinish();
    m.first_draw_ms = ms_between(t0, std::chrono::steady_clock::now());
    gl.UseProgram(0);
  }
  for (GLuint s : shaders)
    gl.DeleteShader(s);
  gl.DeleteProgram(p);
  return m;
}

int run_child(const std::string& expect, const std::string& dir, int reps, int every,
              const std::string& start_after) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  static uint8_t buffer[4 * 4 * 4];
  if (ctx == nullptr || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 4, 4)) {
    std::fprintf(stderr, "no OSMesa context\n");
    return 2;
  }
  const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  std::string lower = renderer;
  for (char& c : lower)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower.find(expect) == std::string::npos) {
    std::fprintf(stderr, "GL_RENDERER is \"%s\", expected %s\n", renderer.c_str(), expect.c_str());
    return 3;
  }
  std::printf("renderer\t%s\t%s\n", renderer.c_str(),
              reinterpret_cast<const char*>(glGetString(GL_VERSION)));
  GL2 gl{proc<PFNGLCREATESHADERPROC>("glCreateShader"),
         proc<PFNGLSHADERSOURCEPROC>("glShaderSource"),
         proc<PFNGLCOMPILESHADERPROC>("glCompileShader"),
         proc<PFNGLGETSHADERIVPROC>("glGetShaderiv"),
         proc<PFNGLCREATEPROGRAMPROC>("glCreateProgram"),
         proc<PFNGLATTACHSHADERPROC>("glAttachShader"),
         proc<PFNGLLINKPROGRAMPROC>("glLinkProgram"),
         proc<PFNGLGETPROGRAMIVPROC>("glGetProgramiv"),
         proc<PFNGLUSEPROGRAMPROC>("glUseProgram"),
         proc<PFNGLDELETEPROGRAMPROC>("glDeleteProgram"),
         proc<PFNGLDELETESHADERPROC>("glDeleteShader")};
  glViewport(0, 0, 1, 1);
  bool started = start_after.empty();
  for (const fs::path& file : program_files(dir, every)) {
    const std::string name = file.filename().string();
    if (!started) {
      started = name == start_after;
      continue;
    }
    const std::string text = read_file(file);
    const framing::Program prog = framing::parse(text);
    if (prog.shaders.empty()) continue;
    // The parent reads "begin" to know which program a crash or a hang was in.
    std::printf("begin\t%s\n", name.c_str());
    std::fflush(stdout);
    alarm(30);
    std::vector<double> cl, fd;
    Measure m;
    for (int r = 0; r < reps; ++r) {
      m = measure_once(gl, prog);
      cl.push_back(m.compile_link_ms);
      fd.push_back(m.first_draw_ms);
    }
    alarm(0);
    std::printf("result\t%s\t%s\t%.4f\t%.4f\n", name.c_str(), m.status, median(cl), median(fd));
    std::fflush(stdout);
  }
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);
  return 0;
}

// ---- parent ----

struct Row {
  std::string status; // linked, compile-error, link-error, crash, hang
  double compile_link_ms = 1e300, first_draw_ms = 1e300;
};

// Runs one implementation over the whole directory (restarting after a program that crashed or
// hung the child) and folds the rows into `rows` (minimum over rounds).
bool run_impl(const std::string& self, const std::string& impl, const conformance::EnvChanges& env,
              const std::vector<std::string>& base_args, std::map<std::string, Row>& rows,
              std::string& renderer) {
  std::string start_after;
  for (;;) {
    std::vector<std::string> args = {"--child", impl};
    args.insert(args.end(), base_args.begin(), base_args.end());
    if (!start_after.empty()) args.insert(args.begin() + 2, {"--start-after", start_after});
    const conformance::RunOutcome out = conformance::run_process(self, args, env, 4 * 3600.0);
    std::istringstream lines(out.out);
    std::string last_begun;
    for (std::string line; std::getline(lines, line);) {
      std::vector<std::string> f;
      std::istringstream fields(line);
      for (std::string x; std::getline(fields, x, '\t');)
        f.push_back(x);
      if (f.size() >= 2 && f[0] == "renderer") {
        renderer = f[1] + (f.size() > 2 ? " (GL " + f[2] + ")" : "");
      } else if (f.size() == 2 && f[0] == "begin") {
        last_begun = f[1];
      } else if (f.size() == 5 && f[0] == "result") {
        Row& r = rows[f[1]];
        r.status = f[2];
        r.compile_link_ms = std::min(r.compile_link_ms, std::atof(f[3].c_str()));
        r.first_draw_ms = std::min(r.first_draw_ms, std::atof(f[4].c_str()));
        last_begun.clear();
      }
    }
    if (out.exited_normally() && out.exit_code == 0) return true;
    if (last_begun.empty()) {
      std::fprintf(stderr, "%s: the child failed (%s): %s\n", impl.c_str(), out.describe().c_str(),
                   out.err.c_str());
      return false;
    }
    rows[last_begun].status = out.signal == SIGALRM ? "hang" : "crash";
    std::fprintf(stderr, "%s: %s on %s (%s)\n", impl.c_str(), rows[last_begun].status.c_str(),
                 last_begun.c_str(), out.describe().c_str());
    start_after = last_begun;
  }
}

void usage() {
  std::fprintf(stderr, "usage: pineda_glsl_compile_time [--reps N] [--rounds N] [--every N] "
                       "[--pineda-lib DIR] [--tsv FILE] DIR\n");
}

} // namespace

int main(int argc, char** argv) {
  std::string dir, child, start_after, tsv, lib = PINEDA_CONFORMANCE_LIB_DIR;
  int reps = 3, rounds = 1, every = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool more = i + 1 < argc;
    if (a == "--child" && more)
      child = argv[++i];
    else if (a == "--start-after" && more)
      start_after = argv[++i];
    else if (a == "--reps" && more)
      reps = std::max(1, std::atoi(argv[++i]));
    else if (a == "--rounds" && more)
      rounds = std::max(1, std::atoi(argv[++i]));
    else if (a == "--every" && more)
      every = std::max(1, std::atoi(argv[++i]));
    else if (a == "--pineda-lib" && more)
      lib = argv[++i];
    else if (a == "--tsv" && more)
      tsv = argv[++i];
    else if (!a.empty() && a[0] != '-')
      dir = a;
    else
      dir.clear(), i = argc;
  }
  if (dir.empty()) {
    usage();
    return 2;
  }
  if (!child.empty()) return run_child(child, dir, reps, every, start_after);

  const std::string self = fs::canonical("/proc/self/exe").string();
  const std::vector<std::string> args = {"--reps", std::to_string(reps), "--every",
                                         std::to_string(every), dir};
  const conformance::EnvChanges pineda_env = {
      {"LD_LIBRARY_PATH", lib}, {"LD_PRELOAD", std::nullopt}, {"GALLIUM_DRIVER", std::nullopt}};
  const conformance::EnvChanges mesa_env = {{"LD_LIBRARY_PATH", std::nullopt},
                                            {"LD_PRELOAD", std::nullopt},
                                            {"GALLIUM_DRIVER", "llvmpipe"},
                                            {"MESA_GL_VERSION_OVERRIDE", "2.1"},
                                            {"MESA_SHADER_CACHE_DISABLE", "true"}};
  std::map<std::string, Row> pineda, mesa;
  std::string pineda_renderer, mesa_renderer;
  for (int r = 0; r < rounds; ++r) {
    std::fprintf(stderr, "round %d of %d: Pineda\n", r + 1, rounds);
    if (!run_impl(self, "pineda", pineda_env, args, pineda, pineda_renderer)) return 1;
    std::fprintf(stderr, "round %d of %d: Mesa\n", r + 1, rounds);
    if (!run_impl(self, "llvmpipe", mesa_env, args, mesa, mesa_renderer)) return 1;
  }

  std::vector<double> pcl, pfd, mcl, mfd, rcl, rfd;
  std::string pcl_max, pfd_max, mcl_max, mfd_max;
  double pcl_m = 0, pfd_m = 0, mcl_m = 0, mfd_m = 0;
  std::map<std::string, int> pineda_status, mesa_status;
  int both = 0;
  FILE* out = tsv.empty() ? nullptr : std::fopen(tsv.c_str(), "w");
  if (out != nullptr)
    std::fprintf(out, "program\tpineda_status\tpineda_compile_link_ms\tpineda_first_draw_ms\t"
                      "mesa_status\tmesa_compile_link_ms\tmesa_first_draw_ms\n");
  for (const auto& [name, p] : pineda) {
    ++pineda_status[p.status];
    const auto it = mesa.find(name);
    if (it == mesa.end()) continue;
    const Row& m = it->second;
    if (out != nullptr)
      std::fprintf(out, "%s\t%s\t%.4f\t%.4f\t%s\t%.4f\t%.4f\n", name.c_str(), p.status.c_str(),
                   p.compile_link_ms, p.first_draw_ms, m.status.c_str(), m.compile_link_ms,
                   m.first_draw_ms);
    if (p.status != "linked" || m.status != "linked") continue;
    ++both;
    // The name passed in: clang 14 cannot capture a structured binding.
    const auto track = [&](std::vector<double>& v, double x, double& mx, std::string& at,
                           const std::string& program) {
      v.push_back(x);
      if (x > mx) mx = x, at = program;
    };
    track(pcl, p.compile_link_ms, pcl_m, pcl_max, name);
    track(pfd, p.first_draw_ms, pfd_m, pfd_max, name);
    track(mcl, m.compile_link_ms, mcl_m, mcl_max, name);
    track(mfd, m.first_draw_ms, mfd_m, mfd_max, name);
    rcl.push_back(p.compile_link_ms / std::max(m.compile_link_ms, 1e-6));
    rfd.push_back(p.first_draw_ms / std::max(m.first_draw_ms, 1e-6));
  }
  for (const auto& [name, m] : mesa)
    ++mesa_status[m.status];
  if (out != nullptr) std::fclose(out);

  const auto statuses = [](const std::map<std::string, int>& s) {
    std::string t;
    for (const auto& [k, v] : s)
      t += (t.empty() ? "" : ", ") + std::to_string(v) + " " + k;
    return t;
  };
  std::printf("Pineda: %s\n  %s\n", pineda_renderer.c_str(), statuses(pineda_status).c_str());
  std::printf("Mesa:   %s\n  %s\n", mesa_renderer.c_str(), statuses(mesa_status).c_str());
  std::printf("%d programs linked on both (median of %d compilations each, best of %d rounds)\n",
              both, reps, rounds);
  std::printf("%-22s %10s %10s %10s %10s %8s %14s\n", "per program (ms)", "Pineda med",
              "Pineda max", "Mesa med", "Mesa max", "med/med", "ratio p50/p90");
  std::printf("%-22s %10.3f %10.2f %10.3f %10.2f %8.2f %6.2f/%-7.2f\n", "compile+link", median(pcl),
              pcl_m, median(mcl), mcl_m, median(pcl) / std::max(median(mcl), 1e-9), median(rcl),
              percentile(rcl, 0.9));
  std::printf("%-22s %10.3f %10.2f %10.3f %10.2f %8.2f %6.2f/%-7.2f\n", "compile to 1st draw",
              median(pfd), pfd_m, median(mfd), mfd_m, median(pfd) / std::max(median(mfd), 1e-9),
              median(rfd), percentile(rfd, 0.9));
  std::printf("slowest: Pineda compile+link %s, first draw %s; Mesa compile+link %s, first draw "
              "%s\n",
              pcl_max.c_str(), pfd_max.c_str(), mcl_max.c_str(), mfd_max.c_str());
  return 0;
}
