// Runs a child process (fork/exec) with a controlled environment and a time limit, capturing its
// standard output and error. Never throws and never lets a child's crash reach the caller: every
// outcome is described in RunOutcome.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace conformance {

// name -> value to set, or std::nullopt to remove the variable.
using EnvChanges = std::vector<std::pair<std::string, std::optional<std::string>>>;

struct RunOutcome {
  bool started = false;     // fork and exec succeeded
  bool timed_out = false;   // killed after the time limit
  int exit_code = -1;       // valid when the child exited normally
  int signal = 0;           // non-zero when the child was killed by a signal
  std::string out, err;     // captured stdout and stderr
  std::string failure;      // why the child could not be started

  bool exited_normally() const { return started && !timed_out && signal == 0; }
  // One line describing how the process ended, e.g. "exit code 3", "killed by SIGSEGV".
  std::string describe() const;
};

RunOutcome run_process(const std::string& executable, const std::vector<std::string>& args,
                       const EnvChanges& env, double timeout_seconds);

} // namespace conformance
