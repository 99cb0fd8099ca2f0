// ParaView output of the PD state: one VTU per snapshot (nodes as vertices with displacement,
// damage, stretch ratio Z, energy density) and a PVD file that lists the series with times.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "model.h"

namespace pumpd::local
{
  /// Writes <path> (.vtu) for the material nodes of the model. Throws std::runtime_error if the
  /// file cannot be written.
  void write_vtu(const std::string &path, const PdModel &model, const State &s);

  /// A growing time series: add() writes the VTU and rewrites the PVD that indexes it.
  class PvdSeries
  {
  public:
    PvdSeries(std::string directory, std::string name);
    void add(const PdModel &model, const State &s);

  private:
    std::string                                directory, name;
    std::vector<std::pair<double, std::string>> entries;
  };
} // namespace pumpd::local
