// The mapping of the global-local exchange (preCICE's Mapping: computed once, applied often):
// the global displacement per unit load factor at every node of a PD box, from one batched point
// evaluation (each node on its own side of the crack), built once per box; applied per load
// factor to the box's boundary layer and its held places, and to the whole box as the start of
// its first PD state.
#pragma once

#include <string>
#include <vector>

#include "boundary_layer.h"
#include "conditions.h"
#include "global_problem.h"
#include "model.h"

namespace pumpd::coupling
{
  /// The places of `conditions` that the PD body `probe` takes in (a free node lies within a
  /// lattice spacing of the place: a load point, support, grip or loaded edge inside the box), as
  /// held places: prescribed regions of the nodes within a horizon of the place (a region's
  /// cells), both components held to the global displacement as the boundary layer is. About a
  /// point (a point force, a support) the bonds of those nodes and those within a horizon of them
  /// stay linear elastic: the point concentrates stress far beyond the PD strength. The global
  /// solution carries the condition; the box takes its displacement there as it does along its
  /// layer.
  std::vector<local::PrescribedRegion> held_places(const conditions::Conditions &conditions,
                                                   const local::PdModel         &probe);

  class BoundaryTransfer
  {
  public:
    BoundaryTransfer(GlobalProblem &global, const local::PdModel &model);

    /// The layer's target at load factor lambda: lambda u_1 at its nodes.
    void apply(double lambda, local::BoundaryLayer &layer) const;
    /// lambda u_1 at the nodes of the model's prescribed regions (its held places), on the
    /// components each region fixes.
    void hold(double lambda, local::State &s) const;
    /// lambda u_1 at every node of s.
    void start(double lambda, local::State &s) const;

  private:
    const local::PdModel &model;
    std::vector<double>   ux, uy; ///< u_1, by storage index
  };
} // namespace pumpd::coupling
