#include "csv.h"

#include <filesystem>

#include "error.h"

namespace pumpd
{
  CsvFile::CsvFile(const std::string &path, const std::string &header, bool append)
  {
    const bool exists = append && std::filesystem::exists(path);
    out.open(path, exists ? std::ios::app : std::ios::trunc);
    if (!out)
      throw InvalidParameter("Output directory", path, "cannot be written");
    if (!exists)
      out << header << "\n";
  }
} // namespace pumpd
