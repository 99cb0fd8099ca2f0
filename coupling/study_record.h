// The record of a study's finished runs (runs.csv in its output directory, a row appended as soon
// as a run ends), and what makes a run the same as a recorded one: its key, a hash of the program
// version, the run's scene file and the sources of the mesh file it names. The program version
// is the pumpd executable's build ID (basics/program.h): any rebuild that changes the program
// runs everything again.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace pumpd::coupling
{
  struct RunRecord
  {
    std::string run, key, method;
    std::string status; ///< ok | exit <code> | killed
    double      wall_seconds = 0., peak_memory = 0.; ///< [s], [MiB]
    double      pd_node_steps = 0., global_dofs = 0., pd_seconds = 0.;

    bool ok() const { return status == "ok"; }
  };

  /// The key of a run: FNV-1a of the program version, its scene file text and its mesh file's
  /// sources (global::mesh_sources_hash; the file's own bytes where those are unknown).
  std::string run_key(const std::string &program_version, const std::string &scene_text, const std::string &mesh_file);

  /// The `pumpd-metric <name> <value>` lines of a run's log.
  std::map<std::string, double> read_metrics(const std::string &log);

  /// The rows of runs.csv (none if it does not exist), in the order written.
  std::vector<RunRecord> read_records(const std::string &file);
  /// Appends a row (the header first if the file is new), flushed.
  void append_record(const std::string &file, const RunRecord &record);
} // namespace pumpd::coupling
