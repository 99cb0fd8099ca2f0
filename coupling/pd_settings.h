// The section `Peridynamics`, shared by the methods with a PD body (global-local, full PD, the PD
// edge-crack scene): the horizon and spacing, the bond law's choices, the quasi-static solver, and
// what counts as crack.
#pragma once

#include <cstddef>
#include <string>

#include "material.h"
#include "scene.h"

namespace dealii
{
  class ParameterHandler;
}

namespace pumpd::coupling
{
  struct PeridynamicsSettings
  {
    double       horizon              = 0.004; ///< delta [m]
    int          horizon_over_spacing = 8;     ///< m = delta / h
    std::string  influence            = "linear";
    double       break_factor         = 10.;
    std::string  compression          = "softening";
    double       tolerance            = 1e-5;   ///< dynamic relaxation residual
    unsigned int max_iterations       = 200000; ///< dynamic relaxation iterations per state
    double       crack_damage         = 0.3;    ///< nodes above this damage lie on the crack

    double spacing() const { return horizon / horizon_over_spacing; }
    /// The PD material of the scene's: bond-based PD has nu = 1/4 (plane strain) or 1/3 (plane
    /// stress), so the scene's Poisson's ratio must be that one (InvalidParameter otherwise).
    local::MaterialParameters material(const Material &scene_material) const;

    void add_parameters(dealii::ParameterHandler &prm);
  };
} // namespace pumpd::coupling
