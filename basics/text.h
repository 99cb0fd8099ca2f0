// Text of files: a file's bytes, and entries and their parts without surrounding white space.
#pragma once

#include <optional>
#include <string>

namespace pumpd
{
  /// `s` without leading and trailing blanks, tabs and line ends.
  std::string trim(const std::string &s);

  /// The bytes of a regular file (none if it is not one or cannot be read; a FIFO or a device is
  /// not opened).
  std::optional<std::string> file_contents(const std::string &file);

  /// What a path that is there names when it is not a regular file (symbolic links followed):
  /// "a directory", "a FIFO", "a character device", "a block device", "a socket"; "" for a regular
  /// file or a path that is not there.
  std::string special_file_kind(const std::string &path);
} // namespace pumpd
