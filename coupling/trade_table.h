// The table of a study: per run what it cost and where its crack went, the path distances from the
// finest run and from full PD, and the setting recommended (study.h).
//   finest run:   the global-local run with the smallest PD spacing (ties: the most PD node-steps)
//   full PD:      the full-PD run with the smallest PD spacing
//   recommended:  the cheapest run (wall time) within the tolerance (mean distance) of the finest
// Two paths are compared over the shorter one's extent: the longer is cut at its point nearest the
// other's tip (path_metrics.h, trade_distance).
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "geometry.h"
#include "path_metrics.h"
#include "study_record.h"

namespace pumpd::coupling
{
  struct TradeRow
  {
    RunRecord          record;
    std::string        setting;        ///< the overrides, as written
    bool               reused = false; ///< taken from an earlier study
    double             pd_spacing = 0.; ///< h of the section Peridynamics [m] (0: no PD)
    geometry::Polyline path;           ///< empty: none written
    double first_growth_load = std::numeric_limits<double>::quiet_NaN(), peak_load = std::numeric_limits<double>::quiet_NaN();
    std::optional<PathDistance> from_finest, from_full_pd;
  };

  struct TradeTable
  {
    std::vector<TradeRow> rows;
    std::optional<std::size_t> finest, full_pd, recommended;
    double                     tolerance = 0.; ///< [m]
  };

  /// Reads a run's crack_path.csv and load_displacement.csv from its output directory into the
  /// row: the load at first growth (the first row, or for full PD the first whose crack is longer
  /// than the first row's) and the peak load.
  void read_run_output(const std::string &directory, TradeRow &row);

  /// The finest and full-PD runs, the distances from them and the recommendation.
  TradeTable judge(std::vector<TradeRow> rows, double tolerance);

  void write_csv(const TradeTable &table, const std::string &file);
  /// The table as Markdown, under a heading naming the scene, and the recommendation.
  void write_markdown(const TradeTable &table, const std::string &scene, const std::string &file);
  /// "<run> (<setting>): <s> s, <d> mm mean from <finest> (tolerance <t> mm)", or why there is none.
  std::string recommendation(const TradeTable &table);
} // namespace pumpd::coupling
