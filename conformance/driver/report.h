// report.html: every scene of an output directory side by side (Pineda, llvmpipe, softpipe,
// diff) with its numbers.
#pragma once

#include "record.h"

#include <string>
#include <vector>

namespace conformance {

// Writes <out_dir>/report.html for `records` (already sorted). The file is written under a
// temporary name and renamed, so parallel ctest processes never leave a half-written report.
// Returns an empty string on success.
std::string write_report(const std::string& out_dir, const std::vector<SceneRecord>& records,
                         const std::string& command_line);

} // namespace conformance
