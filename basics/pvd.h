// The one ParaView series writer: <name>.pvd indexes the VTU files of a run (global solutions,
// PD states), rewritten at every add (aside and renamed, output.h) so that an interrupted run
// leaves a valid index.
#pragma once

#include <cstddef>
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
    /// Records that file at `time` and rewrites the index. Throws as write_failed (output.h).
    void add(double time, const std::string &file);

    /// The files recorded.
    std::size_t size() const { return entries.size(); }
    /// The index file: <directory>/<name>.pvd.
    std::string index() const { return path_of(name + ".pvd"); }
    /// Continues the series an interrupted run wrote: takes the first `n` entries of its index on
    /// disk, the later ones dropped (their files are written again). Returns how many it found, at
    /// most n.
    std::size_t restore(std::size_t n);

  private:
    std::string                                 directory, name;
    std::vector<std::pair<double, std::string>> entries;
  };
} // namespace pumpd
