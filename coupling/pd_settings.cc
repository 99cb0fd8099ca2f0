#include "pd_settings.h"

#include <deal.II/base/parameter_handler.h>

#include <cmath>

#include "error.h"

namespace pumpd::coupling
{
  namespace Patterns = dealii::Patterns;

  void PeridynamicsSettings::add_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Peridynamics");
    prm.add_parameter("Horizon", horizon, "delta [m].", Patterns::Double(1e-300));
    prm.add_parameter("Horizon over spacing", horizon_over_spacing,
                      "m = delta / h: the lattice spacing is h = delta / m.", Patterns::Integer(2, 64));
    prm.add_parameter("Influence function", influence,
                      "J(r): constant 1, or linear 12 (1 - r) (the published decks).",
                      Patterns::Selection("constant|linear"));
    prm.add_parameter("Bond break factor", break_factor,
                      "A bond fails for good beyond this multiple of its inflection stretch S_c = 1 / sqrt(2 beta "
                      "|xi|); the decks use 10.",
                      Patterns::Double(1., 1e6));
    prm.add_parameter("Bond law in compression", compression,
                      "A shortened bond softens and fails by Lipton's law, as a stretched one does (softening), or "
                      "stays linear elastic and never fails (linear): a body squeezed harder than it is pulled, "
                      "like a Brazilian disc, needs linear.",
                      Patterns::Selection("softening|linear"));
    prm.add_parameter("Relaxation tolerance", tolerance,
                      "Dynamic relaxation stops when |f| / (k |u - u_rigid|) falls below this (u_rigid: the best-fit "
                      "rigid motion of the PD body).",
                      Patterns::Double(1e-14, 0.5));
    prm.add_parameter("Relaxation max iterations", max_iterations, "Dynamic relaxation iterations per state at most.",
                      Patterns::Integer(1));
    prm.add_parameter("Crack damage threshold", crack_damage,
                      "A node with damage above this lies on the crack (the face of a straight crack has ~0.41).",
                      Patterns::Double(0.05, 0.95));
    prm.leave_subsection();
  }

  local::MaterialParameters PeridynamicsSettings::material(const Material &m) const
  {
    const double nu = m.plane_strain ? 0.25 : 1. / 3.;
    if (std::abs(m.poisson_ratio - nu) > 1e-9)
      throw InvalidParameter("Poisson's ratio", std::to_string(m.poisson_ratio),
                             std::string("bond-based peridynamics has nu = ") + (m.plane_strain ? "1/4 in plane strain" : "1/3 in plane stress") +
                               ": set it in Scene/Material so that both models describe one material (LEFM growth "
                               "takes any nu)");
    local::MaterialParameters p;
    p.youngs_modulus  = m.youngs_modulus;
    p.fracture_energy = m.fracture_energy;
    p.density         = m.density;
    p.plane_strain    = m.plane_strain;
    p.influence       = local::influence_from_string(influence);
    p.break_factor    = break_factor;
    p.compression     = local::compression_from_string(compression);
    return p;
  }
} // namespace pumpd::coupling
