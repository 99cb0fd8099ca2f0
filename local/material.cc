#include "material.h"

#include <cmath>

#include "error.h"

namespace pumpd::local
{
  Influence influence_from_string(const std::string &name)
  {
    if (name == "constant")
      return Influence::constant;
    if (name == "linear")
      return Influence::linear;
    throw InvalidParameter("Influence function", name, "one of constant|linear");
  }

  std::string to_string(Influence influence)
  {
    return influence == Influence::constant ? "constant" : "linear";
  }

  Compression compression_from_string(const std::string &name)
  {
    if (name == "softening")
      return Compression::softening;
    if (name == "linear")
      return Compression::linear;
    throw InvalidParameter("Bond law in compression", name, "one of softening|linear");
  }

  LiptonMaterial::LiptonMaterial(const MaterialParameters &parameters, double horizon)
    : p(parameters)
    , delta(horizon)
  {
    require_positive("Young's modulus", p.youngs_modulus);
    require_positive("Fracture energy", p.fracture_energy);
    require_positive("Density", p.density);
    require_positive("Horizon", delta);
    require_range("Bond break factor", p.break_factor, 1., 1e6,
                  "must be in [1, 1e6] (a multiple of the inflection stretch)");

    const double E  = p.youngs_modulus;
    const double nu = poisson_ratio();
    // In-plane Lame constant: plane strain E nu / ((1+nu)(1-2nu)), plane stress E nu / (1-nu^2).
    lambda = p.plane_strain ? E * nu / ((1. + nu) * (1. - 2. * nu)) : E * nu / (1. - nu * nu);
    M      = p.influence == Influence::constant ? 1. / 3. : 1.;
    c      = M_PI * p.fracture_energy / (4. * M);
    b      = 2. * lambda / (c * M);
    norm   = 1. / (M_PI * delta * delta * delta);
  }

  double LiptonMaterial::effective_modulus() const
  {
    const double nu = poisson_ratio();
    return p.plane_strain ? p.youngs_modulus / (1. - nu * nu) : p.youngs_modulus;
  }

  double LiptonMaterial::critical_sif() const
  {
    return std::sqrt(effective_modulus() * p.fracture_energy);
  }

  double LiptonMaterial::influence(double r) const
  {
    if (r < 0. || r >= 1.)
      return 0.;
    return p.influence == Influence::constant ? 1. : 12. * (1. - r);
  }

  double LiptonMaterial::inflection_stretch(double r) const { return 1. / std::sqrt(2. * b * r); }

  double LiptonMaterial::elastic_energy_density(double exx, double eyy, double exy) const
  {
    const double tr = exx + eyy;
    return 0.5 * lambda * tr * tr + lambda * (exx * exx + eyy * eyy + 2. * exy * exy);
  }
} // namespace pumpd::local
