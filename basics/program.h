// Another program run as a child process (posix_spawn: no fork of this process's memory, safe
// after MPI start-up), its output to a log file, measured as the operating system sees it: wall
// time and the peak resident memory (wait4's ru_maxrss of the child and its waited-for children).
// A signal that would stop this process while it waits (SIGINT, SIGTERM, SIGHUP) is passed on to
// the program, and the run ends with Interrupted once the program is gone, so that nothing it
// started outlives this process and the callers' destructors clean up.
#pragma once

#include <functional>
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

  /// A wait for a program that a signal ended: the signal was passed on to the program and the
  /// program has ended. Not a std::exception, so that the handlers that turn errors into messages
  /// (catch std::exception) let it through to main, which ends the process as the signal would.
  struct Interrupted
  {
    int         signal;  ///< SIGINT, SIGTERM or SIGHUP
    std::string program; ///< what was running (argv[0])

    /// "SIGTERM while waiting for <program> (passed on to it; it has ended)".
    std::string what() const;
  };

  /// What a caller is told while a program runs: tick(seconds since it started) every `interval`
  /// seconds (none if interval <= 0).
  struct Heartbeat
  {
    double                      interval = 0.;
    std::function<void(double)> tick;
  };

  /// Runs argv[0] (searched on the PATH unless it holds a '/') with the arguments argv[1...], stdin
  /// from /dev/null, stdout and stderr to `log` (created anew), and waits for it. Throws
  /// std::runtime_error if `log` cannot be written or waiting fails. A program still running after
  /// `time_limit` seconds (> 0) is killed (SIGKILL, with what it started: it runs in a process group
  /// of its own) and reported as timed out. SIGINT, SIGTERM and SIGHUP that reach this process while
  /// it waits are passed on to the program (to its process group under a time limit), and once it
  /// has ended, Interrupted is thrown; a signal this process ignores stays ignored. Programs run
  /// one at a time.
  ProgramRun run_program(const std::vector<std::string> &argv, const std::string &log, double time_limit = 0.,
                         const Heartbeat &heartbeat = {});

  /// The last line of a file that is not blank ("" if none).
  std::string last_line(const std::string &file);

  /// The path of the running executable (/proc/self/exe resolved).
  std::string this_executable();

  /// What tells two builds of a program apart: the GNU build ID of an ELF executable (the
  /// linker's hash of its content, read from its notes without reading the whole file), else
  /// FNV-1a (basics/hash.h) of its bytes; in hex, "" if it cannot be read.
  std::string program_version(const std::string &executable);
} // namespace pumpd
