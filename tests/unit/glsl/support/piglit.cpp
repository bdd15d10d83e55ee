// piglit corpus runner (piglit.h).
#include "support/piglit.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "support/harness.h"

namespace pineda::glsl_test {

namespace fs = std::filesystem;

namespace {

std::string read_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

std::string trim(std::string s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> words(const std::string& s) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == ' ' || c == '\t' || c == '(' || c == ')' || c == ',') {
      if (!cur.empty()) out.push_back(cur), cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

CaseResult skip(const std::string& why) {
  return {Outcome::Skip, why, 0};
}
CaseResult fail(const std::string& why) {
  return {Outcome::Fail, why, 0};
}

// ---- glslparsertest ----

CaseResult run_parse(const std::string& path) {
  const std::string src = read_file(path);
  const size_t b = src.find("[config]"), e = src.find("[end config]");
  if (b == std::string::npos || e == std::string::npos) return skip("no [config]");
  std::map<std::string, std::string> cfg;
  std::istringstream lines(src.substr(b, e - b));
  for (std::string line; std::getline(lines, line);) {
    line = trim(line);
    while (!line.empty() && (line[0] == '*' || line[0] == '/'))
      line = trim(line.substr(1));
    const size_t colon = line.find(':');
    if (colon != std::string::npos) cfg[trim(line.substr(0, colon))] = trim(line.substr(colon + 1));
  }
  const std::string version = cfg["glsl_version"];
  if (version != "1.10" && version != "1.20") return skip("GLSL " + version);
  for (const std::string& ext : words(cfg["require_extensions"]))
    if (ext[0] != '!') return skip("requires " + ext);
  const bool expect_pass = cfg["expect_result"] == "pass";
  const bool check_link = cfg["check_link"] == "true";
  glsl::ShaderStage stage;
  if (path.ends_with(".vert"))
    stage = glsl::ShaderStage::Vertex;
  else if (path.ends_with(".frag"))
    stage = glsl::ShaderStage::Fragment;
  else
    return skip("stage");
  const auto t0 = std::chrono::steady_clock::now();
  auto sh = glsl::Shader::compile(stage, {src});
  bool ok = sh->compiled();
  std::string log = sh->info_log();
  if (ok && check_link) {
    auto p = glsl::Program::link({sh}, {});
    ok = p->linked();
    log += p->info_log();
  }
  CaseResult r;
  r.compile_link_ms = ms_since(t0);
  if (ok == expect_pass) {
    r.outcome = Outcome::Pass;
  } else {
    r.outcome = Outcome::Fail;
    r.why = expect_pass ? "rejected: " + log : "accepted, expected an error";
  }
  return r;
}

// ---- shader_runner ----

struct ShaderTest {
  std::vector<std::pair<glsl::ShaderStage, std::string>> shaders;
  int glsl = 110; // the [require] section's GLSL version
  std::vector<std::string> commands;
  int width = 250, height = 250;
};

const char* kPassthroughVs = "#version 110\nvoid main() { gl_Position = gl_Vertex; }\n";

std::string parse_shader_test(const std::string& src, ShaderTest& t) {
  std::istringstream in(src);
  std::string section, body;
  const auto flush = [&]() -> std::string {
    if (section == "vertex shader") t.shaders.emplace_back(glsl::ShaderStage::Vertex, body);
    if (section == "fragment shader") t.shaders.emplace_back(glsl::ShaderStage::Fragment, body);
    body.clear();
    return "";
  };
  for (std::string line; std::getline(in, line);) {
    const std::string tl = trim(line);
    if (!tl.empty() && tl[0] == '[' && tl.back() == ']') {
      flush();
      section = tl.substr(1, tl.size() - 2);
      if (section == "vertex shader passthrough")
        t.shaders.emplace_back(glsl::ShaderStage::Vertex, kPassthroughVs);
      else if (section != "require" && section != "vertex shader" && section != "fragment shader" &&
               section != "test")
        return "section [" + section + "]";
      continue;
    }
    if (section == "require") {
      const auto w = words(tl);
      if (w.empty() || w[0][0] == '#') continue;
      if (w[0] == "GLSL" && w.size() >= 3) {
        if (w[1] == "ES") return "GLSL ES";
        const double v = std::atof(w[2].c_str());
        if ((w[1] == ">=" && v > 1.201) || (w[1] == ">" && v >= 1.2)) return "GLSL " + w[2];
        if (w[1] == ">=" && v > 1.101) t.glsl = 120;
      } else if (w[0] == "GL" && w.size() >= 3) {
        if (w[1] == "ES") return "GL ES";
        if ((w[1] == ">=" || w[1] == ">") && std::atof(w[2].c_str()) > 2.101) return "GL " + w[2];
      } else if (w[0] == "SIZE" && w.size() >= 3) {
        t.width = std::atoi(w[1].c_str());
        t.height = std::atoi(w[2].c_str());
      } else if (w[0].rfind("GL_MAX", 0) == 0 && w.size() >= 3) {
        // Limits beyond Pineda's (glsl.h Limits) skip the test.
        const glsl::Limits lim;
        const int want = std::atoi(w[2].c_str());
        const int have =
            w[0] == "GL_MAX_FRAGMENT_UNIFORM_COMPONENTS" ? lim.max_fragment_uniform_components
            : w[0] == "GL_MAX_VERTEX_UNIFORM_COMPONENTS" ? lim.max_vertex_uniform_components
            : w[0] == "GL_MAX_VARYING_FLOATS" || w[0] == "GL_MAX_VARYING_COMPONENTS"
                ? lim.max_varying_floats
                : 1 << 30;
        if (want > have) return w[0] + " " + w[2];
        continue;
      } else if (w[0] == "rlimit") {
        continue;
      } else if (w[0].rfind("GL_", 0) == 0) {
        return "requires " + w[0];
      }
      continue;
    }
    if (section == "vertex shader" || section == "fragment shader")
      body += line + "\n";
    else if (section == "test" && !tl.empty() && tl[0] != '#')
      t.commands.push_back(tl);
  }
  flush();
  // shader_runner puts the required version in front of shaders without one.
  for (auto& sh : t.shaders)
    if (t.glsl == 120 && sh.second.find("#version") == std::string::npos)
      sh.second = "#version 120\n" + sh.second;
  return "";
}

bool near(float a, double b) {
  return std::fabs(static_cast<double>(a) - b) <= 0.01 + 1.0 / 255;
}

CaseResult run_shader_test(const std::string& path) {
  ShaderTest t;
  const std::string why = parse_shader_test(read_file(path), t);
  if (!why.empty()) return skip(why);
  if (t.shaders.empty()) return skip("no shaders");
  bool expect_link_error = false;
  for (const std::string& c : t.commands)
    if (c == "link error") expect_link_error = true;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::shared_ptr<const glsl::Shader>> shaders;
  std::string log;
  bool ok = true;
  for (const auto& [stage, src] : t.shaders) {
    auto s = glsl::Shader::compile(stage, {src});
    log += s->info_log();
    ok = ok && s->compiled();
    shaders.push_back(s);
  }
  std::unique_ptr<glsl::Program> prog;
  if (ok) {
    prog = glsl::Program::link(shaders, {});
    ok = prog->linked();
    log += prog->info_log();
  }
  const double elapsed = ms_since(t0);
  if (expect_link_error) {
    CaseResult r{ok ? Outcome::Fail : Outcome::Pass, ok ? "linked, expected a link error" : "",
                 elapsed};
    return r;
  }
  if (!ok) return fail("did not link: " + log);
  CaseResult r;
  r.compile_link_ms = elapsed;
  Pipeline pipe(*prog, t.width, t.height);
  bool cmd_is_rgb = false;
  const auto probe = [&](int x, int y, const std::vector<double>& want) -> std::string {
    const Vec4 got = pipe.pixel(x, y);
    // "rgb" probes look at three channels (a few tests give a fourth value anyway).
    const bool rgb = cmd_is_rgb;
    for (size_t c = 0; c < want.size() && c < (rgb ? 3u : 4u); ++c)
      if (!near(got[c], want[c])) {
        char buf[200];
        std::snprintf(buf, sizeof buf, "probe (%d, %d): got %g %g %g %g, expected %g %g %g %s", x,
                      y, got[0], got[1], got[2], got[3], want[0], want[1], want[2],
                      want.size() > 3 ? std::to_string(want[3]).c_str() : "");
        return buf;
      }
    return "";
  };
  for (const std::string& cmd : t.commands) {
    const auto w = words(cmd);
    if (w.empty()) continue;
    cmd_is_rgb = std::find(w.begin(), w.end(), "rgb") != w.end();
    // Numbers; "0x..." is a float's bit pattern for float uniforms (as piglit's parser).
    const bool float_type =
        w.size() > 1 &&
        (w[1].find("vec") != std::string::npos || w[1] == "float" || w[1].rfind("mat", 0) == 0) &&
        w[1][0] != 'i' && w[1][0] != 'b';
    const auto nums = [&](size_t from) {
      std::vector<double> v;
      for (size_t i = from; i < w.size(); ++i) {
        if (w[i].rfind("0x", 0) == 0) {
          const auto bits = static_cast<uint32_t>(std::strtoul(w[i].c_str(), nullptr, 16));
          v.push_back(float_type ? static_cast<double>(std::bit_cast<float>(bits))
                                 : static_cast<double>(static_cast<int32_t>(bits)));
        } else {
          v.push_back(std::atof(w[i].c_str()));
        }
      }
      return v;
    };
    std::string err;
    if (cmd == "link success" || cmd == "link error") {
      continue;
    } else if (w[0] == "clear" && w.size() == 1) {
      continue;
    } else if (w[0] == "clear" && w.size() >= 6 && w[1] == "color") {
      const auto v = nums(2);
      pipe.clear({static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]),
                  static_cast<float>(v[3])});
    } else if (w[0] == "ortho") {
      pipe.ortho = true;
    } else if (w[0] == "uniform" && w.size() >= 4) {
      if (!pipe.set_uniform(w[2], nums(3))) return skip("uniform " + w[2] + " has no location");
    } else if (w[0] == "draw" && w.size() >= 6 && w[1] == "rect") {
      const bool ortho = w[2] == "ortho";
      if (!ortho && (w[2] == "tex" || w.size() > 6)) return skip(cmd);
      auto v = nums(ortho ? 3 : 2);
      if (ortho) {
        v[0] = v[0] * 2 / t.width - 1, v[1] = v[1] * 2 / t.height - 1;
        v[2] = v[2] * 2 / t.width, v[3] = v[3] * 2 / t.height;
      }
      pipe.draw_rect(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]),
                     static_cast<float>(v[3]));
    } else if (w[0] == "probe" && w.size() >= 2 && w[1] == "all") {
      const auto v = nums(3);
      for (int y = 0; y < t.height && err.empty(); y += 3)
        for (int x = 0; x < t.width && err.empty(); x += 3)
          err = probe(x, y, v);
    } else if (w[0] == "probe" && w.size() >= 3 && w[1] == "rect") {
      const auto v = nums(3);
      const std::vector<double> want(v.begin() + 4, v.end());
      for (int y = static_cast<int>(v[1]); y < v[1] + v[3] && err.empty(); ++y)
        for (int x = static_cast<int>(v[0]); x < v[0] + v[2] && err.empty(); ++x)
          err = probe(x, y, want);
    } else if (w[0] == "probe" && w.size() >= 5) {
      const auto v = nums(2);
      err = probe(static_cast<int>(v[0]), static_cast<int>(v[1]), {v.begin() + 2, v.end()});
    } else if (w[0] == "relative" && w.size() >= 6 && w[1] == "probe") {
      const auto v = nums(3);
      // piglit: the fraction of the window, the last pixel for 1.0.
      err = probe(std::min(static_cast<int>(v[0] * t.width), t.width - 1),
                  std::min(static_cast<int>(v[1] * t.height), t.height - 1),
                  {v.begin() + 2, v.end()});
    } else if (w[0] == "texture" && w.size() >= 5 && w[1] == "rgbw") {
      const int unit = std::atoi(w[2].c_str()), tw = std::atoi(w[3].c_str()),
                th = std::atoi(w[4].c_str());
      if (unit < 0 || unit > 31 || tw <= 0 || th <= 0 || tw > 4096 || th > 4096) return skip(cmd);
      if (static_cast<int>(pipe.sampler.units.size()) <= unit)
        pipe.sampler.units.resize(static_cast<size_t>(unit) + 1);
      // piglit_rgbw_image: red, green (bottom row), blue, white (top row).
      pipe.sampler.units[static_cast<size_t>(unit)] = TestTexture::make(
          shader::TexTarget::Tex2D, tw, th, 1, [&](int, int x, int y, int) -> std::array<float, 4> {
            const bool right = x >= tw / 2, top = y >= th / 2;
            if (!top)
              return right ? std::array<float, 4>{0, 1, 0, 1} : std::array<float, 4>{1, 0, 0, 1};
            return right ? std::array<float, 4>{1, 1, 1, 1} : std::array<float, 4>{0, 0, 1, 1};
          });
      pipe.sampler.units[static_cast<size_t>(unit)].repeat = false;
    } else {
      return skip("command: " + cmd);
    }
    if (!err.empty()) {
      r.outcome = Outcome::Fail;
      r.why = err;
      return r;
    }
  }
  r.outcome = Outcome::Pass;
  return r;
}

} // namespace

std::vector<std::string> corpus_files(const std::string& dir) {
  std::vector<std::string> out;
  for (const char* sub : {"tests/spec/glsl-1.10", "tests/spec/glsl-1.20",
                          "generated_tests/spec/glsl-1.10", "generated_tests/spec/glsl-1.20"}) {
    const fs::path root = fs::path(dir) / sub;
    std::error_code ec;
    if (!fs::is_directory(root, ec)) continue;
    for (const auto& e : fs::recursive_directory_iterator(root, ec)) {
      if (!e.is_regular_file()) continue;
      const std::string p = e.path().string();
      if (p.ends_with(".vert") || p.ends_with(".frag") || p.ends_with(".shader_test"))
        out.push_back(p);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

CaseResult run_case(const std::string& path) {
  if (path.ends_with(".shader_test")) return run_shader_test(path);
  return run_parse(path);
}

} // namespace pineda::glsl_test
