// What a run writes for people (DESIGN.md, "Output of a run"), the same for every method:
//   body.csv               the body's curves and the named points of its conditions (for plots)
//   reference_path.csv     the scene's reference path, if any
//   crack_path.csv         the crack, rewritten at every step; crack_path_2.csv, ... the further
//                          cracks of a run with several (the same x_m,y_m columns)
//   load_displacement.csv  the scene's reported load and displacement per accepted step
//   global.pvd + global_NNN.vtu, pd.pvd + pd_NNN.vtu   ParaView series
//   <table>.csv            the method's own table (load_steps.csv), row by row
// Without an output directory nothing is written. A resumed run (the global-local cycle) appends
// to the tables and series of the interrupted one, each cut back first to its length when the
// checkpoint was written (lengths()): what the interrupted run wrote after its checkpoint is
// computed and written again, so the files and the checkpoint agree however the run ended.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "csv.h"
#include "model.h"
#include "pvd.h"
#include "scene.h"

namespace pumpd::coupling
{
  class GlobalProblem;

  /// The length of each file a run appends to, by its name in the output directory: the bytes of
  /// a table, the entries of a series' index (<name>.pvd).
  using OutputLengths = std::map<std::string, std::uint64_t>;

  class Recorder
  {
  public:
    /// Creates the scene's output directory and writes body.csv and reference_path.csv. With
    /// `resumed` (the lengths an interrupted run's checkpoint recorded) it appends to that run's
    /// tables and series, each cut back to its length; InvalidParameter naming Resume if one is
    /// missing or shorter.
    explicit Recorder(const Scene &scene, std::optional<OutputLengths> resumed = std::nullopt);

    bool        writes() const { return !directory.empty(); }
    std::string path(const std::string &file) const { return directory + "/" + file; }
    /// A table of the method's own, appended to when resuming.
    CsvFile table(const std::string &file, const std::string &header);
    /// The lengths of the tables and series written so far (for a checkpoint).
    OutputLengths lengths() const;

    void crack_path(const geometry::Polyline &crack) const;
    /// crack_path.csv for the first crack, crack_path_<k>.csv for the k-th (k >= 2).
    void crack_paths(const std::vector<geometry::Polyline> &cracks) const;
    void load_displacement(std::size_t step, double lambda, double load, double displacement, double crack_length,
                           geometry::Point tip);
    void global_state(const GlobalProblem &global, double time);
    void pd_state(const local::PdModel &model, const local::State &s);

  private:
    /// Cuts the table `file` back to its resumed length.
    void cut_back(const std::string &file) const;
    /// Continues the series of the interrupted run.
    void restore(PvdSeries &series) const;

    std::string                  directory;
    std::optional<OutputLengths> resumed;
    std::vector<std::string>     tables; ///< the files appended to, by name
    CsvFile                      loads;
    std::unique_ptr<PvdSeries> global_series, pd_series;
  };
} // namespace pumpd::coupling
