// What every writer of a run's files shares (the CSV, VTU and PVD writers, the checkpoints):
//   - the lock of the output directory: one pumpd writes into a directory at a time. The run
//     reserves its directory before any work; the first file a writer puts into it locks it
//     (flock on <directory>/.pumpd.lock, which holds the locking process's id) until the process
//     ends, however it ends. A run that fails its checks before it writes a file takes no lock,
//     so bad input never waits for or blocks another run;
//   - a write that fails (a full disk, a removed folder) stops the run with the file and the cause;
//   - a file written aside and renamed onto its name when complete, so that an interruption
//     never leaves half a file under the name.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

namespace pumpd
{
  /// Marks `directory` as the output directory that the entry `entry` (e.g. "Scene / Output
  /// directory") names: the first claim_output_directory of it locks it.
  void reserve_output_directory(const std::string &entry, const std::string &directory);

  /// Called before a file is written into `directory`: locks it if it is reserved and not yet
  /// locked by this process (its sub-directories are other directories: a study's runs lock their
  /// own). Throws InvalidParameter naming the entry if another process holds the lock ("another
  /// pumpd (pid <n>) writes there"), or if the lock file cannot be made.
  void claim_output_directory(const std::string &directory);

  /// Throws std::runtime_error "cannot write <path>: <cause>", the cause from `error` (an errno
  /// value; 0: unknown).
  [[noreturn]] void write_failed(const std::string &path, int error);

  /// Where a file is written before replace_with moves it onto `path`: <path>.partial.
  std::string partial_of(const std::string &path);

  /// Moves the complete file partial_of(path) onto `path` (rename: one step on one file system).
  /// Throws as write_failed if it cannot.
  void replace_with_partial(const std::string &path);

  /// Writes the file `path` as `text` puts it on the stream: aside, then replace_with_partial. A
  /// write that fails, or an exception from `text`, removes the partial file; the first throws as
  /// write_failed.
  void write_aside(const std::string &path, const std::function<void(std::ostream &)> &text);
} // namespace pumpd
