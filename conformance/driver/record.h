// The outcome of one scene: what each implementation produced and how they compare. Saved as
// <out>/<scene>/result.tsv so that report.html can show every scene run into the same output
// directory, including scenes run by separate (possibly parallel) ctest processes.
#pragma once

#include "compare.h"

#include <string>
#include <vector>

namespace conformance {

struct ImplResult {
  bool attempted = false;
  bool ok = false;           // produced an image from the expected renderer, status ok
  std::string status = "not run";
  std::string message;       // why it is not ok, for people
  std::string renderer, version;
  double median_ms = 0.0;    // 0 when unknown
  unsigned gl_error = 0;     // first glGetError() value seen by the runner
  bool frames_identical = true;
};

struct SceneRecord {
  std::string name, description, why;
  double allowance = 0.5;
  int tolerance = 2;
  std::string oracle = "llvmpipe"; // the implementation that decides pass or fail
  bool passed = false;
  std::string verdict;       // "pass" or the reason for failing
  std::string when;          // local time of the run
  ImplResult pineda, llvmpipe, softpipe;
  DiffStats vs_llvmpipe, vs_softpipe, llvmpipe_vs_softpipe;

  bool softpipe_oracle() const { return oracle == "softpipe"; }
  const DiffStats& vs_oracle() const { return softpipe_oracle() ? vs_softpipe : vs_llvmpipe; }

  // Pineda time over the other's median time; 0 when either is unknown.
  double ratio_llvmpipe() const;
  double ratio_softpipe() const;
};

std::string serialize_record(const SceneRecord& record);
bool parse_record(const std::string& text, SceneRecord& record);

// Geometric mean of the positive values; 0 when there are none.
double geometric_mean(const std::vector<double>& values);

} // namespace conformance
