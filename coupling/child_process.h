// A program run as a child process, its output to a file, measured as the operating system sees
// it: wall time and the peak resident memory (wait4's ru_maxrss of the child and its waited-for
// children).
#pragma once

#include <string>
#include <vector>

namespace pumpd::coupling
{
  struct ChildRun
  {
    int    exit_code   = -1; ///< -1: killed by a signal or not started
    double seconds     = 0.;
    double peak_memory = 0.; ///< [MiB]
  };

  /// Runs `program` with `arguments` in the current directory, its stdout and stderr to `log`
  /// (created anew), and waits for it.
  ChildRun run_child(const std::string &program, const std::vector<std::string> &arguments, const std::string &log);

  /// The path of the running executable (/proc/self/exe resolved).
  std::string this_executable();
} // namespace pumpd::coupling
