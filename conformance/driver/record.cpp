#include "record.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <sstream>

namespace conformance {
namespace {

std::string one_line(const std::string& s) {
  std::string out = s;
  for (char& c : out)
    if (c == '\t' || c == '\n' || c == '\r') c = ' ';
  return out;
}

std::string number(double v) {
  if (std::isinf(v)) return "inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

double to_number(const std::string& s) {
  if (s == "inf") return std::numeric_limits<double>::infinity();
  return std::strtod(s.c_str(), nullptr);
}

void put_impl(std::ostringstream& out, const std::string& prefix, const ImplResult& r) {
  out << prefix << ".attempted\t" << (r.attempted ? 1 : 0) << "\n"
      << prefix << ".ok\t" << (r.ok ? 1 : 0) << "\n"
      << prefix << ".status\t" << one_line(r.status) << "\n"
      << prefix << ".message\t" << one_line(r.message) << "\n"
      << prefix << ".renderer\t" << one_line(r.renderer) << "\n"
      << prefix << ".version\t" << one_line(r.version) << "\n"
      << prefix << ".median_ms\t" << number(r.median_ms) << "\n"
      << prefix << ".gl_error\t" << r.gl_error << "\n"
      << prefix << ".frames_identical\t" << (r.frames_identical ? 1 : 0) << "\n";
}

void put_diff(std::ostringstream& out, const std::string& prefix, const DiffStats& d) {
  out << prefix << ".comparable\t" << (d.comparable ? 1 : 0) << "\n"
      << prefix << ".bad_pixels\t" << d.bad_pixels << "\n"
      << prefix << ".bad_percent\t" << number(d.bad_percent) << "\n"
      << prefix << ".max_diff\t" << d.max_diff << "\n"
      << prefix << ".psnr\t" << number(d.psnr) << "\n";
}

using Fields = std::map<std::string, std::string>;

std::string get(const Fields& f, const std::string& key) {
  auto it = f.find(key);
  return it == f.end() ? std::string() : it->second;
}

void get_impl(const Fields& f, const std::string& prefix, ImplResult& r) {
  r.attempted = get(f, prefix + ".attempted") == "1";
  r.ok = get(f, prefix + ".ok") == "1";
  r.status = get(f, prefix + ".status");
  r.message = get(f, prefix + ".message");
  r.renderer = get(f, prefix + ".renderer");
  r.version = get(f, prefix + ".version");
  r.median_ms = to_number(get(f, prefix + ".median_ms"));
  r.gl_error = static_cast<unsigned>(std::strtoul(get(f, prefix + ".gl_error").c_str(), nullptr, 10));
  r.frames_identical = get(f, prefix + ".frames_identical") != "0";
}

void get_diff(const Fields& f, const std::string& prefix, DiffStats& d) {
  d.comparable = get(f, prefix + ".comparable") == "1";
  d.bad_pixels = std::strtol(get(f, prefix + ".bad_pixels").c_str(), nullptr, 10);
  d.bad_percent = to_number(get(f, prefix + ".bad_percent"));
  d.max_diff = std::atoi(get(f, prefix + ".max_diff").c_str());
  d.psnr = to_number(get(f, prefix + ".psnr"));
}

double ratio(const ImplResult& a, const ImplResult& b) {
  return a.ok && b.ok && a.median_ms > 0.0 && b.median_ms > 0.0 ? a.median_ms / b.median_ms : 0.0;
}

} // namespace

double SceneRecord::ratio_llvmpipe() const { return ratio(pineda, llvmpipe); }
double SceneRecord::ratio_softpipe() const { return ratio(pineda, softpipe); }

std::string serialize_record(const SceneRecord& r) {
  std::ostringstream out;
  out << "format\tpineda-conformance-record-1\n"
      << "name\t" << one_line(r.name) << "\n"
      << "description\t" << one_line(r.description) << "\n"
      << "why\t" << one_line(r.why) << "\n"
      << "allowance\t" << number(r.allowance) << "\n"
      << "tolerance\t" << r.tolerance << "\n"
      << "oracle\t" << one_line(r.oracle) << "\n"
      << "passed\t" << (r.passed ? 1 : 0) << "\n"
      << "verdict\t" << one_line(r.verdict) << "\n"
      << "when\t" << one_line(r.when) << "\n";
  put_impl(out, "pineda", r.pineda);
  put_impl(out, "llvmpipe", r.llvmpipe);
  put_impl(out, "softpipe", r.softpipe);
  put_diff(out, "vs_llvmpipe", r.vs_llvmpipe);
  put_diff(out, "vs_softpipe", r.vs_softpipe);
  put_diff(out, "llvmpipe_vs_softpipe", r.llvmpipe_vs_softpipe);
  return out.str();
}

bool parse_record(const std::string& text, SceneRecord& r) {
  Fields f;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto tab = line.find('\t');
    if (tab != std::string::npos) f[line.substr(0, tab)] = line.substr(tab + 1);
  }
  if (get(f, "format") != "pineda-conformance-record-1" || get(f, "name").empty()) return false;
  r.name = get(f, "name");
  r.description = get(f, "description");
  r.why = get(f, "why");
  r.allowance = to_number(get(f, "allowance"));
  r.tolerance = std::atoi(get(f, "tolerance").c_str());
  r.oracle = get(f, "oracle") == "softpipe" ? "softpipe" : "llvmpipe";
  r.passed = get(f, "passed") == "1";
  r.verdict = get(f, "verdict");
  r.when = get(f, "when");
  get_impl(f, "pineda", r.pineda);
  get_impl(f, "llvmpipe", r.llvmpipe);
  get_impl(f, "softpipe", r.softpipe);
  get_diff(f, "vs_llvmpipe", r.vs_llvmpipe);
  get_diff(f, "vs_softpipe", r.vs_softpipe);
  get_diff(f, "llvmpipe_vs_softpipe", r.llvmpipe_vs_softpipe);
  return true;
}

double geometric_mean(const std::vector<double>& values) {
  double log_sum = 0.0;
  int n = 0;
  for (double v : values) {
    if (v > 0.0 && std::isfinite(v)) {
      log_sum += std::log(v);
      ++n;
    }
  }
  return n ? std::exp(log_sum / n) : 0.0;
}

} // namespace conformance
