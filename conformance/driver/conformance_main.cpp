// pineda_conformance: renders every conformance scene with Pineda, Mesa llvmpipe and Mesa
// softpipe (each in its own process running pineda_scene_runner) and compares the images.
// Pineda against llvmpipe decides pass or fail; softpipe is shown for perspective: where the two
// Mesa drivers disagree, GL leaves the result open. Run with --help for the options.
#include "compare.h"
#include "png_write.h"
#include "process.h"
#include "record.h"
#include "report.h"
#include "rgba_image.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace conformance;

namespace {

constexpr int kExitPass = 0, kExitFail = 1, kExitSetup = 2;

struct Options {
  std::vector<std::string> scenes, filters;
  std::string out = "conformance-out";
  std::string pineda_lib = PINEDA_CONFORMANCE_LIB_DIR;
  std::string runner;
  bool softpipe = true, allow_any_renderer = false, list = false;
  int tolerance = 2, reps = 5, threads = 0;
  int rounds = 1;  // runs of each implementation, alternating; times are their median
  std::string csv; // also write one line per scene to this CSV file
  double timeout = 50.0;
  std::string command_line;
};

void usage(std::FILE* to) {
  std::fprintf(to,
      "usage: pineda_conformance [options]\n"
      "  --scene NAME          run this scene (repeatable; default: all)\n"
      "  --filter SUBSTR       run scenes whose name contains SUBSTR (repeatable)\n"
      "  --list                list the scenes and exit\n"
      "  --out DIR             output directory (default ./conformance-out)\n"
      "  --pineda-lib DIR      directory holding Pineda's libOSMesa.so.8\n"
      "                        (default " PINEDA_CONFORMANCE_LIB_DIR ")\n"
      "  --no-softpipe         skip the softpipe runs\n"
      "  --tolerance N         per-channel difference still counted as equal (default 2)\n"
      "  --reps N              timed repetitions per scene (default 5)\n"
      "  --rounds N            run each implementation N times, alternating, and report the\n"
      "                        median of the runs' medians (benchmarks; default 1)\n"
      "  --csv FILE            also write the table as CSV (times, ratios, error)\n"
      "  --threads N           LP_NUM_THREADS for llvmpipe (default: Mesa's choice)\n"
      "  --timeout SEC         limit per runner process (default 50)\n"
      "  --runner PATH         pineda_scene_runner to use\n"
      "  --allow-any-renderer  do not insist that GL_RENDERER names the expected library\n"
      "                        (self-test of the harness with Mesa in place of Pineda)\n");
}

struct ManifestEntry {
  std::string name, format, oracle, why, description;
  std::string gl_version; // Mesa runs with MESA_GL_VERSION_OVERRIDE=gl_version when not empty
  int width = 0, height = 0, depth_bits = 0;
  bool y_up = true;
  double allowance = 0.5;
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::string::size_type start = 0;
  for (;;) {
    const auto at = s.find(sep, start);
    parts.push_back(s.substr(start, at - start));
    if (at == std::string::npos) return parts;
    start = at + 1;
  }
}

std::string last_line(const std::string& text) {
  std::string last;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  if (last.size() > 300) last = last.substr(0, 300) + "...";
  return last;
}

EnvChanges mesa_env(const Options& o, const char* driver, const std::string& gl_version = "") {
  EnvChanges env{{"LD_LIBRARY_PATH", std::nullopt}, {"LD_PRELOAD", std::nullopt},
                 {"GALLIUM_DRIVER", std::string(driver)}};
  if (o.threads > 0) env.push_back({"LP_NUM_THREADS", std::to_string(o.threads)});
  // A scene of a newer GL version is drawn by Mesa as a context of that version.
  if (!gl_version.empty()) env.push_back({"MESA_GL_VERSION_OVERRIDE", gl_version});
  return env;
}

bool read_manifest(const Options& o, std::vector<ManifestEntry>& manifest) {
  const RunOutcome run = run_process(o.runner, {"--manifest"}, mesa_env(o, "llvmpipe"), o.timeout);
  if (!run.exited_normally() || run.exit_code != 0) {
    std::fprintf(stderr, "pineda_conformance: '%s --manifest' failed (%s): %s\n",
                 o.runner.c_str(), run.describe().c_str(), last_line(run.err).c_str());
    return false;
  }
  std::istringstream in(run.out);
  for (std::string line; std::getline(in, line);) {
    const auto f = split(line, '\t');
    if (f.size() != 11) continue;
    ManifestEntry e;
    e.name = f[0];
    e.width = std::atoi(f[1].c_str());
    e.height = std::atoi(f[2].c_str());
    e.allowance = std::strtod(f[3].c_str(), nullptr);
    e.format = f[4];
    e.depth_bits = std::atoi(f[5].c_str());
    e.y_up = f[6] == "1";
    e.oracle = f[7];
    e.why = f[8];
    e.description = f[9];
    e.gl_version = f[10];
    manifest.push_back(e);
  }
  if (manifest.empty()) {
    std::fprintf(stderr, "pineda_conformance: the runner lists no scenes\n");
    return false;
  }
  return true;
}

struct Impl {
  const char* name;     // file prefix and column name
  const char* expected; // substring GL_RENDERER must contain
  EnvChanges env;
};

// Runs the scene on one implementation; fills `result` and, when it worked, `image`.
void run_impl(const Options& o, const ManifestEntry& scene, const Impl& impl,
              const std::string& dir, ImplResult& result, RgbaImage& image) {
  result.attempted = true;
  const std::string rgba_path = dir + "/" + impl.name + ".rgba";
  const std::vector<std::string> args{"--scene", scene.name, "--out", rgba_path, "--reps",
                                      std::to_string(o.reps)};
  const RunOutcome run = run_process(o.runner, args, impl.env, o.timeout);

  std::ofstream log(dir + "/" + impl.name + ".log");
  log << "command: " << o.runner;
  for (const auto& a : args) log << " " << a;
  log << "\nenvironment changes:";
  for (const auto& [k, v] : impl.env) log << " " << k << "=" << (v ? *v : "(unset)");
  log << "\nended: " << run.describe() << "\n--- stdout ---\n" << run.out << "--- stderr ---\n"
      << run.err;

  std::vector<std::string> fields;
  {
    std::istringstream in(run.out);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("RESULT\t", 0) == 0) fields = split(line, '\t');
  }
  auto field = [&](const std::string& key) {
    for (const auto& f : fields)
      if (f.rfind(key + "=", 0) == 0) return f.substr(key.size() + 1);
    return std::string();
  };
  result.renderer = field("renderer");
  result.version = field("version");
  result.median_ms = std::strtod(field("median_ms").c_str(), nullptr);
  result.gl_error = static_cast<unsigned>(std::strtoul(field("gl_error").c_str(), nullptr, 16));
  result.frames_identical = field("frames_identical") != "0";
  const std::string tail = last_line(run.err);

  if (!run.started) {
    result.status = "not started";
    result.message = run.describe();
  } else if (run.timed_out) {
    result.status = "timeout";
    result.message = "runner did not finish within " + std::to_string(int(o.timeout)) + " s";
  } else if (run.signal != 0) {
    result.status = "crashed";
    result.message = "runner " + run.describe() + (tail.empty() ? "" : ": " + tail);
  } else if (fields.empty()) {
    result.status = "crashed";
    result.message = "runner printed no RESULT line (" + run.describe() + ")" +
                     (tail.empty() ? "" : ": " + tail);
  } else if (field("status") != "ok") {
    result.status = field("status");
    result.message = result.status + ": " + field("detail");
  } else if (!o.allow_any_renderer && result.renderer.find(impl.expected) == std::string::npos) {
    result.status = "wrong renderer";
    result.message = "GL_RENDERER is '" + result.renderer + "', expected it to contain '" +
                     impl.expected + "': the environment did not select the intended library";
  } else if (std::string err = read_rgba_file(rgba_path, image); !err.empty()) {
    result.status = "no image";
    result.message = err;
  } else if (image.width != scene.width || image.height != scene.height) {
    result.status = "bad image";
    result.message = "image size differs from the scene's";
  } else {
    result.status = "ok";
    result.ok = true;
  }
  std::error_code ignored;
  fs::remove(rgba_path, ignored);
  if (result.ok) {
    if (std::string err = write_png(dir + "/" + impl.name + ".png", image); !err.empty())
      std::fprintf(stderr, "warning: %s\n", err.c_str());
  }
}

std::string now_string() {
  const std::time_t t = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S", std::localtime(&t));
  return buf;
}

std::string hex(unsigned v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%04x", v);
  return buf;
}

SceneRecord run_scene(const Options& o, const ManifestEntry& scene) {
  SceneRecord r;
  r.name = scene.name;
  r.description = scene.description;
  r.why = scene.why;
  r.allowance = scene.allowance;
  r.tolerance = o.tolerance;
  r.oracle = scene.oracle == "softpipe" ? "softpipe" : "llvmpipe";
  r.when = now_string();
  const std::string dir = o.out + "/" + scene.name;
  std::error_code ec;
  fs::create_directories(dir, ec);
  for (const char* stale : {"pineda.png", "llvmpipe.png", "softpipe.png", "diff.png",
                            "diff_mesa.png", "result.tsv"})
    fs::remove(fs::path(dir) / stale, ec);

  const std::string lib = fs::absolute(o.pineda_lib).lexically_normal().string();
  const Impl pineda{"pineda", "Pineda",
                    {{"LD_LIBRARY_PATH", lib}, {"LD_PRELOAD", std::nullopt},
                     {"GALLIUM_DRIVER", std::nullopt}}};
  RgbaImage pineda_image, llvmpipe_image, softpipe_image;
  if (!fs::exists(fs::path(lib) / "libOSMesa.so.8")) {
    r.pineda.attempted = true;
    r.pineda.status = "missing library";
    r.pineda.message = lib + "/libOSMesa.so.8 does not exist (build the 'pineda' target or pass "
                       "--pineda-lib DIR)";
  } else {
    run_impl(o, scene, pineda, dir, r.pineda, pineda_image);
  }
  run_impl(o, scene, Impl{"llvmpipe", "llvmpipe", mesa_env(o, "llvmpipe", scene.gl_version)}, dir, r.llvmpipe,
           llvmpipe_image);
  // A scene whose oracle is softpipe needs softpipe even under --no-softpipe.
  if (o.softpipe || r.softpipe_oracle())
    run_impl(o, scene, Impl{"softpipe", "softpipe", mesa_env(o, "softpipe", scene.gl_version)}, dir, r.softpipe,
             softpipe_image);

  // Further rounds, alternating the implementations so that machine noise hits them alike;
  // each one's time becomes the median of its runs' medians (the images of round one count).
  if (o.rounds > 1) {
    struct Timed {
      ImplResult* result;
      Impl impl;
      std::vector<double> ms;
    };
    std::vector<Timed> timed;
    fs::create_directories(dir + "/round", ec);
    if (r.pineda.ok) timed.push_back({&r.pineda, pineda, {r.pineda.median_ms}});
    if (r.llvmpipe.ok)
      timed.push_back({&r.llvmpipe, Impl{"llvmpipe", "llvmpipe", mesa_env(o, "llvmpipe", scene.gl_version)},
                       {r.llvmpipe.median_ms}});
    if (r.softpipe.ok)
      timed.push_back({&r.softpipe, Impl{"softpipe", "softpipe", mesa_env(o, "softpipe", scene.gl_version)},
                       {r.softpipe.median_ms}});
    for (int round = 1; round < o.rounds; ++round) {
      for (Timed& t : timed) {
        ImplResult again;
        RgbaImage ignored_image;
        run_impl(o, scene, t.impl, dir + "/round", again, ignored_image);
        if (again.ok) t.ms.push_back(again.median_ms);
      }
    }
    for (Timed& t : timed) {
      std::sort(t.ms.begin(), t.ms.end());
      const size_t n = t.ms.size();
      t.result->median_ms = n % 2 ? t.ms[n / 2] : 0.5 * (t.ms[n / 2 - 1] + t.ms[n / 2]);
    }
    fs::remove_all(dir + "/round", ec);
  }

  // diff.png shows Pineda against the scene's oracle.
  RgbaImage diff;
  if (r.pineda.ok && r.llvmpipe.ok)
    r.vs_llvmpipe = compare_images(pineda_image, llvmpipe_image, o.tolerance,
                                   r.softpipe_oracle() ? nullptr : &diff);
  if (r.pineda.ok && r.softpipe.ok)
    r.vs_softpipe = compare_images(pineda_image, softpipe_image, o.tolerance,
                                   r.softpipe_oracle() ? &diff : nullptr);
  if (diff.width > 0) write_png(dir + "/diff.png", diff);
  if (r.llvmpipe.ok && r.softpipe.ok) {
    RgbaImage mesa_diff;
    r.llvmpipe_vs_softpipe = compare_images(softpipe_image, llvmpipe_image, o.tolerance, &mesa_diff);
    if (mesa_diff.width > 0) write_png(dir + "/diff_mesa.png", mesa_diff);
  }

  char buf[200];
  const ImplResult& oracle = r.softpipe_oracle() ? r.softpipe : r.llvmpipe;
  const DiffStats& vs = r.vs_oracle();
  if (!oracle.ok) {
    r.verdict = "oracle " + r.oracle + " failed: " + oracle.message;
  } else if (!r.pineda.ok) {
    r.verdict = "Pineda failed: " + r.pineda.message;
  } else if (!vs.comparable) {
    r.verdict = "images differ in size";
  } else if (vs.bad_percent > r.allowance) {
    std::snprintf(buf, sizeof buf, "%.3f%% bad pixels against %s (max difference %d) exceeds "
                  "the %.2f%% allowance", vs.bad_percent, r.oracle.c_str(), vs.max_diff,
                  r.allowance);
    r.verdict = buf;
  } else if (r.pineda.gl_error != oracle.gl_error) {
    r.verdict = "glGetError reported " + hex(r.pineda.gl_error) + ", " + r.oracle + " " +
                hex(oracle.gl_error);
  } else if (!r.pineda.frames_identical) {
    r.verdict = "repeated frames differ from the first one (non-deterministic rendering)";
  } else {
    r.passed = true;
    r.verdict = "pass";
  }
  if (oracle.ok && !oracle.frames_identical)
    r.verdict += " [note: " + r.oracle + "'s repeated frames differ: the scene leaks state]";

  // Written under a temporary name and renamed: a parallel ctest process building report.html
  // must never read a half-written record.
  const std::string tmp = dir + "/result.tsv.tmp";
  std::ofstream(tmp) << serialize_record(r);
  fs::rename(tmp, dir + "/result.tsv", ec);
  return r;
}

std::string pct(const DiffStats& d) {
  if (!d.comparable) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", d.bad_percent);
  return buf;
}

std::string num(double v, const char* fmt) {
  if (v <= 0.0) return "-";
  if (std::isinf(v)) return "inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

void print_header() {
  std::printf("%-28s %-4s %7s %4s %6s %5s | %8s %7s | %7s %7s | %8s %4s\n", "scene", "res",
              "bad%", "max", "PSNR", "allow", "pineda", "xllvm", "bad%sp", "xsoft",
              "llvm~sp%", "max");
  std::printf("%s\n", std::string(112, '-').c_str());
}

void print_row(const SceneRecord& r) {
  const DiffStats& vs = r.vs_oracle();
  std::printf("%-28s %-4s %7s %4s %6s %5.2f | %8s %7s | %7s %7s | %8s %4s\n",
              (r.name + (r.softpipe_oracle() ? "*" : "")).c_str(), r.passed ? "ok" : "FAIL",
              pct(vs).c_str(), vs.comparable ? std::to_string(vs.max_diff).c_str() : "-",
              vs.comparable ? (std::isinf(vs.psnr) ? "inf" : num(vs.psnr, "%.1f")).c_str() : "-",
              r.allowance, num(r.pineda.median_ms, "%.2fms").c_str(),
              num(r.ratio_llvmpipe(), "%.2f").c_str(), pct(r.vs_softpipe).c_str(),
              num(r.ratio_softpipe(), "%.2f").c_str(), pct(r.llvmpipe_vs_softpipe).c_str(),
              r.llvmpipe_vs_softpipe.comparable
                  ? std::to_string(r.llvmpipe_vs_softpipe.max_diff).c_str() : "-");
  if (!r.passed) std::printf("    -> %s\n", r.verdict.c_str());
  std::fflush(stdout);
}

std::string default_runner() {
  std::error_code ec;
  if (fs::exists(PINEDA_CONFORMANCE_RUNNER, ec)) return PINEDA_CONFORMANCE_RUNNER;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return (self.parent_path() / "pineda_scene_runner").string();
}

bool parse_args(int argc, char** argv, Options& o) {
  for (int i = 0; i < argc; ++i) {
    if (i) o.command_line += ' ';
    o.command_line += argv[i];
  }
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--scene") o.scenes.push_back(value());
    else if (arg == "--filter") o.filters.push_back(value());
    else if (arg == "--list") o.list = true;
    else if (arg == "--out") o.out = value();
    else if (arg == "--pineda-lib") o.pineda_lib = value();
    else if (arg == "--no-softpipe") o.softpipe = false;
    else if (arg == "--tolerance") o.tolerance = std::atoi(value().c_str());
    else if (arg == "--reps") o.reps = std::max(1, std::atoi(value().c_str()));
    else if (arg == "--rounds") o.rounds = std::max(1, std::atoi(value().c_str()));
    else if (arg == "--csv") o.csv = value();
    else if (arg == "--threads") o.threads = std::atoi(value().c_str());
    else if (arg == "--timeout") o.timeout = std::max(1.0, std::strtod(value().c_str(), nullptr));
    else if (arg == "--runner") o.runner = value();
    else if (arg == "--allow-any-renderer") o.allow_any_renderer = true;
    else if (arg == "--help" || arg == "-h") {
      usage(stdout);
      std::exit(kExitPass);
    } else throw std::runtime_error("unknown option " + arg);
  }
  if (o.runner.empty()) o.runner = default_runner();
  return true;
}

} // namespace

int main(int argc, char** argv) {
  Options o;
  try {
    parse_args(argc, argv, o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pineda_conformance: %s\n", e.what());
    usage(stderr);
    return kExitSetup;
  }
  if (!fs::exists(o.runner)) {
    std::fprintf(stderr, "pineda_conformance: runner %s not found (--runner PATH)\n",
                 o.runner.c_str());
    return kExitSetup;
  }
  std::vector<ManifestEntry> manifest;
  if (!read_manifest(o, manifest)) return kExitSetup;
  if (o.list) {
    for (const auto& e : manifest) std::printf("%-28s %s\n", e.name.c_str(), e.description.c_str());
    return kExitPass;
  }

  std::vector<ManifestEntry> selected;
  for (const auto& name : o.scenes) {
    bool found = false;
    for (const auto& e : manifest) found = found || e.name == name;
    if (!found) {
      std::fprintf(stderr, "pineda_conformance: unknown scene '%s' (see --list)\n", name.c_str());
      return kExitSetup;
    }
  }
  for (const auto& e : manifest) {
    bool want = o.scenes.empty() && o.filters.empty();
    for (const auto& name : o.scenes) want = want || e.name == name;
    for (const auto& f : o.filters) want = want || e.name.find(f) != std::string::npos;
    if (want) selected.push_back(e);
  }
  if (selected.empty()) {
    std::fprintf(stderr, "pineda_conformance: no scene matches the filters\n");
    return kExitSetup;
  }
  std::error_code ec;
  fs::create_directories(o.out, ec);
  if (ec) {
    std::fprintf(stderr, "pineda_conformance: cannot create %s: %s\n", o.out.c_str(),
                 ec.message().c_str());
    return kExitSetup;
  }
  if (o.allow_any_renderer)
    std::printf("note: --allow-any-renderer: GL_RENDERER is not checked (harness self-test)\n");

  print_header();
  std::vector<SceneRecord> records;
  for (const auto& scene : selected) {
    records.push_back(run_scene(o, scene));
    print_row(records.back());
  }

  int passed = 0;
  std::vector<double> ratios_llvm, ratios_soft;
  for (const auto& r : records) {
    passed += r.passed ? 1 : 0;
    ratios_llvm.push_back(r.ratio_llvmpipe());
    ratios_soft.push_back(r.ratio_softpipe());
  }
  std::printf("%s\n", std::string(112, '-').c_str());
  std::printf("(* = scene compared against softpipe, see its justification)\n");
  std::printf("passed %d/%zu against the oracle; geometric mean time ratio Pineda/llvmpipe %s, "
              "Pineda/softpipe %s\n", passed, records.size(),
              num(geometric_mean(ratios_llvm), "%.2f").c_str(),
              num(geometric_mean(ratios_soft), "%.2f").c_str());
  if (!records.empty()) {
    const auto& renderer = records.front();
    std::printf("renderers: Pineda '%s', llvmpipe '%s'%s%s%s\n", renderer.pineda.renderer.c_str(),
                renderer.llvmpipe.renderer.c_str(), o.softpipe ? ", softpipe '" : "",
                o.softpipe ? renderer.softpipe.renderer.c_str() : "", o.softpipe ? "'" : "");
  }

  if (!o.csv.empty()) {
    std::ofstream csv(o.csv);
    csv << "scene,width,height,pineda_ms,llvmpipe_ms,softpipe_ms,pineda_over_llvmpipe,"
           "pineda_over_softpipe,bad_percent,max_diff,psnr,passed\n";
    for (const auto& r : records) {
      const ManifestEntry* m = nullptr;
      for (const auto& e : selected) m = e.name == r.name ? &e : m;
      const DiffStats& vs = r.vs_oracle();
      csv << r.name << ',' << (m ? m->width : 0) << ',' << (m ? m->height : 0) << ','
          << r.pineda.median_ms << ',' << r.llvmpipe.median_ms << ',' << r.softpipe.median_ms
          << ',' << r.ratio_llvmpipe() << ',' << r.ratio_softpipe() << ','
          << (vs.comparable ? vs.bad_percent : -1.0) << ',' << (vs.comparable ? vs.max_diff : -1)
          << ',' << (vs.comparable ? vs.psnr : 0.0) << ',' << (r.passed ? 1 : 0) << '\n';
    }
    if (!csv) std::fprintf(stderr, "pineda_conformance: cannot write %s\n", o.csv.c_str());
    else std::printf("csv: %s\n", o.csv.c_str());
  }

  // The report covers every scene with a result in the output directory, not only this run's.
  std::vector<SceneRecord> all;
  for (const auto& e : manifest) {
    std::ifstream in(o.out + "/" + e.name + "/result.tsv");
    if (!in) continue;
    std::stringstream text;
    text << in.rdbuf();
    SceneRecord r;
    if (parse_record(text.str(), r)) all.push_back(r);
  }
  if (std::string err = write_report(o.out, all, o.command_line); !err.empty())
    std::fprintf(stderr, "pineda_conformance: %s\n", err.c_str());
  else
    std::printf("report: %s/report.html\n", o.out.c_str());
  return passed == static_cast<int>(records.size()) ? kExitPass : kExitFail;
}
