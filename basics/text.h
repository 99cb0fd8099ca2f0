// Text of files: a file's bytes, and entries and their parts without surrounding white space.
#pragma once

#include <optional>
#include <string>

namespace pumpd
{
  /// `s` without leading and trailing blanks, tabs and line ends.
  std::string trim(const std::string &s);

  /// The bytes of a regular file (none if it is not one or cannot be read).
  std::optional<std::string> file_contents(const std::string &file);
} // namespace pumpd
