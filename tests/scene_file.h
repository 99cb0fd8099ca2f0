// Scene files in tests: a .prm of the source tree read as pumpd reads it (relative paths in it
// start at the source directory: the tests that use this run there), changed in C++ where a test
// needs it, its output in a fresh temporary directory.
#pragma once

#include <filesystem>
#include <string>

#include "parameters.h"

namespace pumpd::test
{
  /// The parameters of `relative` (a path in the source tree), their output directory the fresh
  /// temporary directory pumpd_<output> ("" for none).
  inline coupling::Parameters scene_file(const std::string &relative, const std::string &output)
  {
    auto p = coupling::read_parameters(relative);
    if (output.empty())
      p.scene.output_directory = "";
    else
      {
        const auto dir = std::filesystem::temp_directory_path() / ("pumpd_" + output);
        std::filesystem::remove_all(dir);
        p.scene.output_directory = dir.string();
      }
    return p;
  }
} // namespace pumpd::test
