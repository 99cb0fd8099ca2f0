// The one CSV writer of pumpd's results (crack paths, load steps, load-displacement): a header,
// then one row per call, flushed at once so that a long run's progress is on disk line by line.
#pragma once

#include <fstream>
#include <iomanip>
#include <string>

namespace pumpd
{
  class CsvFile
  {
  public:
    /// No file: rows are dropped (a run without an output directory).
    CsvFile() = default;
    /// Creates `path` with the comma-separated `header`, or appends to it if `append` (and it exists).
    CsvFile(const std::string &path, const std::string &header, bool append = false);

    /// One row of values, 10 significant digits.
    template <class... T>
    void row(const T &...values)
    {
      if (!out.is_open())
        return;
      bool first = true;
      ((out << (first ? "" : ",") << std::setprecision(10) << values, first = false), ...);
      out << "\n";
      out.flush();
    }

    explicit operator bool() const { return out.is_open(); }

  private:
    std::ofstream out;
  };
} // namespace pumpd
