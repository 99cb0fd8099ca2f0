// A dynamic PD run: velocity Verlet steps with the boundary layer ramped over the run, a copy of
// the last good state kept, and on a NaN or infinity the run stopped with that state saved.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "boundary_layer.h"
#include "integrators.h"
#include "model.h"

namespace pumpd::local
{
  struct ExplicitRun
  {
    std::size_t steps = 0;
    /// Layer ramp after step n of `steps` (default: linear, n / steps).
    std::function<double(std::size_t n)> ramp;
    /// Where the last good state goes if the run fails ("" = not saved).
    std::string failure_checkpoint;
    /// How often (in steps) the last good state is copied.
    std::size_t keep_every = 100;
    /// Called after every step (progress, output); may be empty.
    std::function<void(const State &, std::size_t n)> observer;
  };

  /// Runs `run.steps` steps from s. On a non-finite state throws NonFiniteState whose message
  /// names the step, and (if failure_checkpoint is set) where the last good state was saved.
  void run_explicit(const VelocityVerlet &integrator, State &s, const BoundaryLayer &layer,
                    const ExplicitRun &run);
} // namespace pumpd::local
