// The structure of a scene file, checked before deal.II's ParameterHandler reads it: what the
// handler does not refuse on its own.
#pragma once

#include <set>
#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace pumpd::coupling
{
  /// Throws InvalidParameter when `file` is not a readable regular file (a FIFO or a device is
  /// refused, not opened), when an included file starts with a UTF-8 byte order mark (deal.II
  /// would take it for part of the first line's text), when it includes itself
  /// (directly or through other files; `include` names a file relative to the working directory,
  /// as deal.II reads it), or when one file sets the same entry of the same section twice (the
  /// later value would win silently). A file may set again an entry that a file it includes has
  /// set: that is how a variant overrides a scene (tests/coupling/study/sent-coarse.prm).
  /// Returns the entries the file and the files it includes set ("Section/Sub/entry").
  std::set<std::string> check_parameter_file(const std::string &file);

  /// The entries the text of a scene file and the files it includes set, with the checks of
  /// check_parameter_file.
  std::set<std::string> entries_set_in(const std::string &text);

  /// check_parameter_file, then the file parsed into `prm` (ParameterHandler::parse_input): a byte
  /// order mark at the start of `file`, which editors may write, is dropped. Returns the entries
  /// set, as check_parameter_file.
  std::set<std::string> parse_parameter_file(dealii::ParameterHandler &prm, const std::string &file);
} // namespace pumpd::coupling
