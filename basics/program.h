// Another program run as a child process (posix_spawn: no fork of this process's memory, safe
// after MPI start-up), its output to a log file, measured as the operating system sees it: wall
// time and the peak resident memory (wait4's ru_maxrss of the child and its waited-for children).
#pragma once

#include <string>
#include <vector>

namespace pumpd
{
  struct ProgramRun
  {
    int    start_error = 0;  ///< errno of a failed start (0: it started)
    int    exit_code   = -1; ///< -1: not started, or killed by a signal
    int    signal      = 0;  ///< the signal that killed it (0: none)
    double seconds     = 0.;
    double peak_memory = 0.; ///< [MiB]
    bool   timed_out   = false; ///< killed at the time limit
  };

  /// Runs argv[0] (searched on the PATH unless it holds a '/') with the arguments argv[1...], stdin
  /// from /dev/null, stdout and stderr to `log` (created anew), and waits for it. Throws
  /// std::runtime_error if `log` cannot be written or waiting fails. A program still running after
  /// `time_limit` seconds (> 0) is killed (SIGKILL) and reported as timed out.
  ProgramRun run_program(const std::vector<std::string> &argv, const std::string &log, double time_limit = 0.);

  /// The last line of a file that is not blank ("" if none).
  std::string last_line(const std::string &file);

  /// The path of the running executable (/proc/self/exe resolved).
  std::string this_executable();

  /// What tells two builds of a program apart: the GNU build ID of an ELF executable (the
  /// linker's hash of its content, read from its notes without reading the whole file), else
  /// FNV-1a (basics/hash.h) of its bytes; in hex, "" if it cannot be read.
  std::string program_version(const std::string &executable);
} // namespace pumpd
