// Time integration of rho u'' = f(u): velocity Verlet for dynamics, adaptive dynamic relaxation
// (Kilic & Madenci 2010) for quasi-static states. The boundary layer and the fixed components of
// prescribed regions are prescribed (PdModel::free_mask_x / free_mask_y), every other component of
// a material node moves. Both check the state after each force evaluation and throw
// NonFiniteState on a NaN or infinity.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "boundary_layer.h"
#include "model.h"

namespace pumpd::local
{
  class VelocityVerlet
  {
  public:
    /// Throws InvalidParameter if dt <= 0 or dt exceeds the Silling-Askari bound (named in the
    /// message with its value).
    VelocityVerlet(const PdModel &model, double time_step);

    double time_step() const { return dt; }
    const PdModel &model() const { return pd; }
    /// Forces at the current state; call once before the first step (and after a restart
    /// only if the checkpoint did not carry them).
    void initialise(State &s) const;
    /// Advances one step; the layer and the given prescribed regions move to their values at
    /// ramp_end (a region not given keeps its displacement), and the work all prescribed
    /// components do on the body (trapezoidal rule on their reaction forces) is added to
    /// s.external_work.
    void step(State &s, const BoundaryLayer &layer, double ramp_end,
              const std::vector<const RegionDisplacement *> &regions = {}) const;

  private:
    const PdModel &pd;
    double         dt;
  };

  struct RelaxationResult
  {
    std::size_t iterations = 0;   ///< displacement updates made (max_iterations if not converged)
    double      residual   = 0.; ///< |f_free| / (stiffness scale |u - u_rigid|), u_rigid: best-fit rigid motion
    double      servo_error = 0.; ///< the servo's last relative error (0 without one)
    bool        converged  = false;
  };

  /// A controller acting inside dynamic relaxation: indirect displacement control, e.g. a servo
  /// that moves a loading pad until a crack-mouth opening reaches its target. `correct` is called
  /// after every update of the free components; it may change prescribed components of the state
  /// and returns its relative error. A state counts as relaxed only when that error is below
  /// `tolerance` as well.
  struct Servo
  {
    std::function<double(State &)> correct;
    double                         tolerance = 1e-6;
  };

  class DynamicRelaxation
  {
  public:
    /// tolerance in [1e-14, 0.5], max_iterations >= 1.
    DynamicRelaxation(const PdModel &model, double tolerance, std::size_t max_iterations);

    /// Relaxes the free components to equilibrium with the prescribed ones (layer, regions) as
    /// they are in s, or as the servo moves them. Velocities are fictitious and left at zero on
    /// return.
    RelaxationResult solve(State &s, const Servo &servo = {}) const;

  private:
    const PdModel &model;
    double         tol;
    std::size_t    max_it;
  };

  /// Throws NonFiniteState naming the step if a displacement or force of s is not finite.
  void check_finite(const PdModel &model, const State &s);
} // namespace pumpd::local
