// Strength of Lipton's bond-based model under a homogeneous strain (docs/peridynamics.md,
// "Strength of the bond-based model").
//
// The strain eps = epsilon P stretches the bond along e = (cos t, sin t) by S = epsilon s(t),
// s = e.P.e (P = diag(0, 1): uniaxial strain, eps_xx = 0; P = I: equibiaxial strain). The stress
// is sigma = dW / deps, W = int psi, so with rho = |xi| / delta and a = beta delta epsilon^2
//   sigma_yy = (2 C beta / pi) epsilon Phi(a),
//   Phi(a)   = int_0^1 J(rho) rho^2 int_0^{2 pi} s sin^2 t exp(-a rho s^2) dt drho,
// the bonds past the break stretch (a rho s^2 > break_factor^2 / 2) left out. With the
// calibration of material.h this is sqrt(2 / pi) sqrt(lambda G_c / delta) sqrt(a) Phi(a) / M: the
// peak over the path is sigma_max = k sqrt(lambda G_c / delta), k depending only on J, the path
// and, for break_factor below about 1.7, on the break stretch.
#pragma once

#include "material.h"

namespace pumpd::local
{
  enum class StrainPath
  {
    uniaxial,   ///< eps_yy = epsilon, eps_xx = eps_xy = 0
    equibiaxial ///< eps_xx = eps_yy = epsilon, eps_xy = 0
  };

  /// sigma_yy [Pa] of the continuum model at the strain epsilon along the path (bonds failed on a
  /// monotone path to it carry nothing).
  double homogeneous_stress(const LiptonMaterial &material, StrainPath path, double epsilon);

  struct PeakStress
  {
    double stress; ///< max over epsilon of sigma_yy [Pa]
    double strain; ///< the epsilon where it is reached
  };

  /// The peak of sigma_yy along the path.
  PeakStress peak_stress(const LiptonMaterial &material, StrainPath path);

  /// Tensile strength: the peak of sigma_yy in uniaxial strain.
  double tensile_strength(const LiptonMaterial &material);
} // namespace pumpd::local
