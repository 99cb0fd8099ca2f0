// The one CSV writer of pumpd's results (crack paths, load steps, load-displacement, the study's
// tables): a header, then one row per call, flushed at once so that a long run's progress is on
// disk line by line (a row that cannot be written stops the run: output.h); and the reader of
// such files.
#pragma once

#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace pumpd
{
  class CsvFile
  {
  public:
    /// No file: rows are dropped (a run without an output directory).
    CsvFile() = default;
    /// Creates `path` with the comma-separated `header`, or appends to it if `append` (and it exists).
    CsvFile(const std::string &path, const std::string &header, bool append = false);

    /// One row of values, 10 significant digits; a number that is not finite (a closed tip's
    /// critical load factor) is an empty field.
    template <class... T>
    void row(const T &...values)
    {
      if (!out.is_open())
        return;
      bool first = true;
      ((out << (first ? "" : ","), field(values), first = false), ...);
      end_row();
    }
    /// One row of cells, as they are.
    void row(const std::vector<std::string> &cells);

    explicit operator bool() const { return out.is_open(); }

  private:
    template <class T>
    void field(const T &value)
    {
      if constexpr (std::is_floating_point_v<T>)
        if (!std::isfinite(value))
          return;
      out << std::setprecision(10) << value;
    }

    /// Ends the row and flushes it; throws as write_failed (output.h) if it did not reach the file.
    void end_row();

    std::string   path;
    std::ofstream out;
  };

  /// A row of a CSV file: its fields by the header's column names.
  using CsvRow = std::map<std::string, std::string>;

  /// The rows of a CSV file under its header line (none if it cannot be read). A field in double
  /// quotes may hold commas; a row with another number of fields than the header (cut short by an
  /// interruption) is dropped.
  std::vector<CsvRow> read_csv_rows(const std::string &file);

  /// The number in a field; an empty field (CsvFile's for a number that is not finite) is NaN.
  double csv_number(const std::string &field);
} // namespace pumpd
