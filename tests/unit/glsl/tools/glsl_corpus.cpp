// glsl_corpus: runs piglit's GLSL 1.10/1.20 tests through the front end and the engine
// (support/piglit.h) and prints the pass rate, the failures and the compile+link times.
//   glsl_corpus [--piglit DIR] [--filter SUBSTRING] [--quiet]
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "support/piglit.h"

using namespace pineda::glsl_test;

int main(int argc, char** argv) {
  std::string dir = PINEDA_PIGLIT_DIR, filter;
  bool quiet = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--piglit") && i + 1 < argc)
      dir = argv[++i];
    else if (!std::strcmp(argv[i], "--filter") && i + 1 < argc)
      filter = argv[++i];
    else if (!std::strcmp(argv[i], "--quiet"))
      quiet = true;
  }
  const auto files = corpus_files(dir);
  if (files.empty()) {
    std::fprintf(stderr, "glsl_corpus: no piglit GLSL tests under %s\n", dir.c_str());
    return 2;
  }
  struct Count {
    int pass = 0, fail = 0, skip = 0;
  };
  std::map<std::string, Count> by_kind;
  std::map<std::string, int> skip_reasons;
  std::vector<double> times;
  std::vector<std::pair<double, std::string>> slowest;
  for (const std::string& f : files) {
    if (!filter.empty() && f.find(filter) == std::string::npos) continue;
    const CaseResult r = run_case(f);
    const std::string kind =
        f.ends_with(".shader_test")
            ? (f.find("/execution/") != std::string::npos ? "execution" : "link")
            : "parse";
    Count& c = by_kind[kind];
    if (r.outcome == Outcome::Pass) ++c.pass;
    if (r.outcome == Outcome::Fail) {
      ++c.fail;
      if (!quiet) {
        std::string why = r.why.substr(0, r.why.find('\n', 200));
        std::printf("FAIL %s\n     %s\n", f.c_str() + dir.size() + 1, why.substr(0, 300).c_str());
      }
    }
    if (r.outcome == Outcome::Skip) {
      ++c.skip;
      ++skip_reasons[r.why.substr(0, 40)];
    }
    if (r.compile_link_ms > 0) {
      times.push_back(r.compile_link_ms);
      slowest.emplace_back(r.compile_link_ms, f.substr(dir.size() + 1));
    }
  }
  int pass = 0, fail = 0, skip = 0;
  for (const auto& [k, c] : by_kind) {
    std::printf("%-10s pass %5d  fail %4d  skip %4d  (%.1f%% of the run)\n", k.c_str(), c.pass,
                c.fail, c.skip, 100.0 * c.pass / std::max(1, c.pass + c.fail));
    pass += c.pass, fail += c.fail, skip += c.skip;
  }
  std::printf("all        pass %5d  fail %4d  skip %4d  (%.1f%% of the run)\n", pass, fail, skip,
              100.0 * pass / std::max(1, pass + fail));
  if (!times.empty()) {
    std::sort(times.begin(), times.end());
    std::printf("compile+link per program: median %.2f ms, 90th percentile %.2f ms, max %.1f ms "
                "(%zu programs)\n",
                times[times.size() / 2], times[times.size() * 9 / 10], times.back(), times.size());
  }
  std::sort(slowest.rbegin(), slowest.rend());
  for (size_t i = 0; i < slowest.size() && i < 5; ++i)
    std::printf("  slow: %8.1f ms  %s\n", slowest[i].first, slowest[i].second.c_str());
  if (!quiet) {
    std::vector<std::pair<int, std::string>> reasons;
    for (const auto& [r, n] : skip_reasons)
      reasons.emplace_back(n, r);
    std::sort(reasons.rbegin(), reasons.rend());
    std::printf("skipped because:\n");
    for (size_t i = 0; i < reasons.size() && i < 25; ++i)
      std::printf("  %5d  %s\n", reasons[i].first, reasons[i].second.c_str());
  }
  return 0;
}
