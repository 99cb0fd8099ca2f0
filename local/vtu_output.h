// ParaView output of the PD state: one VTU per snapshot (nodes as vertices with displacement,
// damage, stretch ratio Z, energy density), listed with its time in a PVD series (basics/pvd.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "model.h"
#include "pvd.h"

namespace pumpd::local
{
  /// Writes <path> (.vtu) for the material nodes of the model. Throws std::runtime_error if the
  /// file cannot be written.
  void write_vtu(const std::string &path, const PdModel &model, const State &s);

  /// The next VTU of a series (basics/pvd.h), indexed at the state's time.
  void write_vtu(PvdSeries &series, const PdModel &model, const State &s);
} // namespace pumpd::local
