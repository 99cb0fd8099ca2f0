// HDF5 checkpoint of a PD state: displacements, velocities, forces, bond bits, time, step and
// energy totals, plus named scalars of the driver (load step, ramp, ...). Restoring it into the
// same model continues the run bit for bit.
#pragma once

#include <map>
#include <string>

#include "model.h"

namespace pumpd::local
{
  using Attributes = std::map<std::string, double>;

  /// Throws std::runtime_error if the file cannot be written.
  void write_checkpoint(const std::string &path, const PdModel &model, const State &s,
                        const Attributes &attributes = {});

  /// Throws std::runtime_error if the file is missing, unreadable, or was written for a lattice
  /// of another size or spacing.
  State read_checkpoint(const std::string &path, const PdModel &model, Attributes *attributes = nullptr);
} // namespace pumpd::local
