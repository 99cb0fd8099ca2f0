// The one ParaView series writer: <name>.pvd indexes the VTU files of a run (global solutions,
// PD states), rewritten at every add so that an interrupted run leaves a valid index.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace pumpd
{
  class PvdSeries
  {
  public:
    PvdSeries(std::string directory, std::string name);
    /// The file name of the next VTU (<name>_NNN.vtu, in the directory).
    std::string next_file() const;
    /// The path of a file of the series: <directory>/<file>.
    std::string path_of(const std::string &file) const { return directory + "/" + file; }
    /// Records that file at `time` and rewrites the index.
    void add(double time, const std::string &file);

  private:
    std::string                                 directory, name;
    std::vector<std::pair<double, std::string>> entries;
  };
} // namespace pumpd
