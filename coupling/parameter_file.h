// The structure of a scene file, checked before deal.II's ParameterHandler reads it: what the
// handler does not refuse on its own.
#pragma once

#include <string>

namespace pumpd::coupling
{
  /// Throws InvalidParameter when `file` is not a readable regular file, when it includes itself
  /// (directly or through other files; `include` names a file relative to the working directory,
  /// as deal.II reads it), or when one file sets the same entry of the same section twice (the
  /// later value would win silently). A file may set again an entry that a file it includes has
  /// set: that is how a variant overrides a scene (tests/coupling/study/sent-coarse.prm).
  void check_parameter_file(const std::string &file);
} // namespace pumpd::coupling
