// The state of the global-local cycle between two exchanges, in HDF5 (checkpoint.h5), so that an
// interrupted run resumes where it stopped. The PD box is rebuilt at every exchange from the crack
// polyline, so the crack, the boxes, the accepted load, the counters and the refinements of the
// global mesh (tip positions and levels: the same mesh on resume) and the last box's horizon are
// the whole state.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "geometry.h"
#include "global_problem.h"

namespace pumpd::coupling
{
  struct CycleState
  {
    std::size_t                exchanges   = 0;  ///< exchanges accepted so far
    double                     load_factor = 0.; ///< lambda of the last accepted exchange
    bool                       finished    = false;
    geometry::Polyline         crack;
    std::vector<geometry::Box> boxes;
    std::vector<Refinement>    refinements; ///< of every global solve so far
    unsigned int               halvings = 0; ///< of the last box's horizon (coupling/resolution.h)
  };

  /// Throws std::runtime_error if the file cannot be written.
  void write_cycle_checkpoint(const std::string &path, const CycleState &state);
  /// Throws std::runtime_error if the file is missing or not a cycle checkpoint.
  CycleState read_cycle_checkpoint(const std::string &path);
} // namespace pumpd::coupling
