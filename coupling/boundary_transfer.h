// The mapping of the global-local exchange (preCICE's Mapping: computed once, applied often):
// the global displacement per unit load factor at every node of a PD box, from one batched point
// evaluation (each node on its own side of the crack), built once per box; applied per load
// factor to the box's boundary layer, and to the whole box as the start of its first PD state.
#pragma once

#include <vector>

#include "boundary_layer.h"
#include "global_problem.h"
#include "model.h"

namespace pumpd::coupling
{
  class BoundaryTransfer
  {
  public:
    BoundaryTransfer(GlobalProblem &global, const local::PdModel &model);

    /// The layer's target at load factor lambda: lambda u_1 at its nodes.
    void apply(double lambda, local::BoundaryLayer &layer) const;
    /// lambda u_1 at every node of s.
    void start(double lambda, local::State &s) const;

  private:
    const local::PdModel &model;
    std::vector<double>   ux, uy; ///< u_1, by storage index
  };
} // namespace pumpd::coupling
