#include "trade_table.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "csv.h"
#include "scene.h"

namespace pumpd::coupling
{
  namespace
  {
    std::optional<std::size_t> finest_of(const std::vector<TradeRow> &rows, const std::string &method)
    {
      std::optional<std::size_t> best;
      for (std::size_t i = 0; i < rows.size(); ++i)
        {
          const auto &r = rows[i];
          if (r.record.method != method || !r.record.ok() || r.path.size() < 2)
            continue;
          if (!best || r.pd_spacing < rows[*best].pd_spacing ||
              (r.pd_spacing == rows[*best].pd_spacing && r.record.pd_node_steps > rows[*best].record.pd_node_steps))
            best = i;
        }
      return best;
    }

    std::string fixed(double v, int digits)
    {
      if (!std::isfinite(v))
        return "";
      std::ostringstream s;
      s << std::fixed << std::setprecision(digits) << v;
      return s.str();
    }

    std::string general(double v)
    {
      std::ostringstream s;
      s << std::setprecision(3) << v;
      return s.str();
    }

    /// The cells of a row, in the order of `columns`.
    const char *columns[] = {"run", "method", "setting", "status", "reused", "wall_s", "peak_mib", "pd_node_steps",
                             "global_dofs", "crack_end_x_mm", "crack_end_y_mm", "mean_vs_finest_mm",
                             "hausdorff_vs_finest_mm", "mean_vs_fullpd_mm", "hausdorff_vs_fullpd_mm",
                             "first_growth_load", "peak_load", "recommended"};

    std::vector<std::string> cells(const TradeRow &r, bool recommended)
    {
      const auto   nan   = std::numeric_limits<double>::quiet_NaN();
      const bool   path  = r.path.size() >= 2;
      const auto   mm    = [](const std::optional<PathDistance> &d, bool mean) {
        return d ? fixed(1e3 * (mean ? d->mean : d->hausdorff), 2) : std::string();
      };
      return {r.record.run,
              r.record.method,
              r.setting,
              r.record.status,
              r.reused ? "yes" : "no",
              fixed(r.record.wall_seconds, 1),
              fixed(r.record.peak_memory, 0),
              general(r.record.pd_node_steps),
              fixed(r.record.global_dofs, 0),
              fixed(path ? 1e3 * r.path.back().x : nan, 1),
              fixed(path ? 1e3 * r.path.back().y : nan, 1),
              mm(r.from_finest, true),
              mm(r.from_finest, false),
              mm(r.from_full_pd, true),
              mm(r.from_full_pd, false),
              std::isfinite(r.first_growth_load) ? general(r.first_growth_load) : "",
              std::isfinite(r.peak_load) ? general(r.peak_load) : "",
              recommended ? "yes" : ""};
    }
  } // namespace

  void read_run_output(const std::string &directory, TradeRow &row)
  {
    if (std::filesystem::exists(directory + "/crack_path.csv"))
      row.path = read_path(directory + "/crack_path.csv");
    double first_length = std::numeric_limits<double>::quiet_NaN();
    for (auto &r : read_csv_rows(directory + "/load_displacement.csv"))
      {
        const double load = csv_number(r["load"]), length = csv_number(r["crack_length_m"]);
        if (std::isnan(first_length))
          first_length = length;
        const bool grown = row.record.method != "full-pd" || length > first_length + 1e-9;
        if (grown && std::isnan(row.first_growth_load))
          row.first_growth_load = load;
        if (!(load <= row.peak_load))
          row.peak_load = load;
      }
  }

  TradeTable judge(std::vector<TradeRow> rows, double tolerance)
  {
    TradeTable t;
    t.rows      = std::move(rows);
    t.tolerance = tolerance;
    t.finest    = finest_of(t.rows, "global-local");
    t.full_pd   = finest_of(t.rows, "full-pd");
    for (auto &r : t.rows)
      {
        if (!r.record.ok() || r.path.size() < 2)
          continue;
        if (t.finest)
          r.from_finest = trade_distance(r.path, t.rows[*t.finest].path);
        if (t.full_pd)
          r.from_full_pd = trade_distance(r.path, t.rows[*t.full_pd].path);
      }
    for (std::size_t i = 0; i < t.rows.size(); ++i)
      {
        const auto &r = t.rows[i];
        if (r.from_finest && r.from_finest->mean <= tolerance &&
            (!t.recommended || r.record.wall_seconds < t.rows[*t.recommended].record.wall_seconds))
          t.recommended = i;
      }
    return t;
  }

  void write_csv(const TradeTable &table, const std::string &file)
  {
    std::string header;
    for (const auto *c : columns)
      header += (header.empty() ? "" : ",") + std::string(c);
    CsvFile csv(file, header);
    for (std::size_t i = 0; i < table.rows.size(); ++i)
      {
        auto row = cells(table.rows[i], table.recommended == i);
        row[2]   = "\"" + row[2] + "\""; // the setting may hold commas
        csv.row(row);
      }
  }

  void write_markdown(const TradeTable &table, const std::string &scene, const std::string &file)
  {
    std::ofstream out(file);
    out << "# The speed/accuracy trade of " << scene << "\n\n"
        << "Written by `pumpd --study " << scene << "`. Distances are the symmetric mean and the Hausdorff "
        << "distance of the crack paths over the shorter one's extent; the finest run is "
        << (table.finest ? "`" + table.rows[*table.finest].record.run + "`" : "none") << ", full PD "
        << (table.full_pd ? "`" + table.rows[*table.full_pd].record.run + "`" : "not run") << ". Times are wall "
        << "times of one process each, memory its peak resident set.\n\n"
        << "Recommended: " << recommendation(table) << "\n\n|";
    for (const auto *c : columns)
      out << " " << c << " |";
    out << "\n|";
    for (std::size_t c = 0; c < std::size(columns); ++c)
      out << " --- |";
    out << "\n";
    for (std::size_t i = 0; i < table.rows.size(); ++i)
      {
        out << "|";
        for (const auto &cell : cells(table.rows[i], table.recommended == i))
          out << " " << cell << " |";
        out << "\n";
      }
  }

  std::string recommendation(const TradeTable &table)
  {
    if (!table.finest)
      return "none: no global-local run succeeded, so there is no finest run to judge by";
    if (!table.recommended)
      return "none within " + fixed(1e3 * table.tolerance, 2) + " mm of the finest run";
    const auto &r = table.rows[*table.recommended];
    return r.record.run + " (" + (r.setting.empty() ? "the scene's settings" : r.setting) + "): " + fixed(r.record.wall_seconds, 1) + " s, " + fixed(1e3 * r.from_finest->mean, 2) + " mm mean from " +
           table.rows[*table.finest].record.run + " (tolerance " + fixed(1e3 * table.tolerance, 2) + " mm)";
  }
} // namespace pumpd::coupling
