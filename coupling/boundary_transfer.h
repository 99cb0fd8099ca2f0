// The mapping of the global-local exchange (preCICE's Mapping: computed once, applied often):
// the global displacement per unit load factor at every node of a PD box, from one batched point
// evaluation (each node on its own side of the crack), built once per box; applied per load
// factor to the box's boundary layer, and to the whole box as the start of its first PD state.
#pragma once

#include <string>
#include <vector>

#include "boundary_layer.h"
#include "conditions.h"
#include "global_problem.h"
#include "model.h"

namespace pumpd::coupling
{
  /// The names, comma-separated ("" if none), of the places of `conditions` that the PD body
  /// `model` leaves free: a free node (neither in the boundary layer nor prescribed) lies within a
  /// lattice spacing of the place. The body holds only its layer to the global displacement; a
  /// load point, support, grip or loaded edge among its free nodes would not carry its condition.
  std::string conditions_left_free(const conditions::Conditions &conditions, const local::PdModel &model);

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
