// The rows of a CSV file with a header line, each a map from column name to field; a field in
// double quotes may hold commas (trade.csv's settings).
#pragma once

#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace pumpd::test
{
  using CsvRow = std::map<std::string, std::string>;

  inline std::vector<CsvRow> read_csv_rows(const std::string &file)
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
        else
          {
            CsvRow row;
            for (std::size_t i = 0; i < header.size() && i < fields.size(); ++i)
              row[header[i]] = fields[i];
            rows.push_back(row);
          }
      }
    return rows;
  }
} // namespace pumpd::test
