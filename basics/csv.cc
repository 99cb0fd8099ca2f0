#include "csv.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <limits>

#include "error.h"
#include "output.h"

namespace pumpd
{
  CsvFile::CsvFile(const std::string &file, const std::string &header, bool append)
    : path(file)
  {
    claim_output_directory(std::filesystem::path(path).parent_path().string());
    const bool exists = append && std::filesystem::exists(path);
    errno             = 0;
    out.open(path, exists ? std::ios::app : std::ios::trunc);
    if (!out)
      throw InvalidParameter("Output directory", path,
                             std::string("cannot be written (") +
                               (errno != 0 ? std::strerror(errno) : "the system gave no cause") + ")");
    if (!exists)
      {
        out << header;
        end_row();
      }
  }

  void CsvFile::row(const std::vector<std::string> &cells)
  {
    if (!out.is_open())
      return;
    for (std::size_t c = 0; c < cells.size(); ++c)
      out << (c ? "," : "") << cells[c];
    end_row();
  }

  void CsvFile::end_row()
  {
    errno = 0;
    out << "\n";
    out.flush();
    if (!out)
      {
        const int error = errno;
        out.close();
        write_failed(path, error);
      }
  }

  std::vector<CsvRow> read_csv_rows(const std::string &file)
  {
    std::ifstream            in(file);
    std::vector<std::string> header;
    std::vector<CsvRow>      rows;
    for (std::string line; std::getline(in, line);)
      {
        std::vector<std::string> fields(1);
        bool                     quoted = false;
        for (char c : line)
          if (c == '"')
            quoted = !quoted;
          else if (c == ',' && !quoted)
            fields.emplace_back();
          else
            fields.back() += c;
        if (header.empty())
          header = fields;
        else if (fields.size() == header.size())
          {
            CsvRow row;
            for (std::size_t i = 0; i < header.size(); ++i)
              row[header[i]] = fields[i];
            rows.push_back(row);
          }
      }
    return rows;
  }

  double csv_number(const std::string &field)
  {
    return field.empty() ? std::numeric_limits<double>::quiet_NaN() : std::stod(field);
  }
} // namespace pumpd
