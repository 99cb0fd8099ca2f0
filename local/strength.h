// Strength of Lipton's bond-based model under a homogeneous strain (docs/peridynamics.md,
// "Strength of the bond-based model").
//
// The strain eps = epsilon diag(p_x, 1) stretches the bond along e = (cos t, sin t) by
// S = epsilon s(t), s = p_x cos^2 t + sin^2 t. The stress is sigma = dW / deps, W = int psi, so
// with rho = |xi| / delta and a = beta delta epsilon^2
//   sigma_yy = (2 C beta / pi) epsilon Phi_y(a),   sigma_xx = (2 C beta / pi) epsilon Phi_x(a),
//   Phi_y(a) = int_0^1 J(rho) rho^2 int_0^{2 pi} s sin^2 t exp(-a rho s^2) dt drho  (cos^2 t: Phi_x),
// the bonds past the break stretch (a rho s^2 > break_factor^2 / 2) left out; under the linear
// law in compression (material.h) a shortened bond (s < 0, epsilon > 0) has exp(0) = 1 and never
// breaks. The paths:
// uniaxial strain p_x = 0, equibiaxial strain p_x = 1, uniaxial stress p_x = -q(a) with q the
// root of Phi_x = 0 (1/3 while the bonds are linear: lambda = mu). With the calibration of
// material.h sigma_yy = sqrt(2 / pi) sqrt(lambda G_c / delta) sqrt(a) Phi_y(a) / M: the peak over the
// path is sigma_max = k sqrt(lambda G_c / delta), k depending only on J, the path, the law in
// compression (for a path that shortens bonds) and, for break_factor below about 1.7, on the
// break stretch.
#pragma once

#include "material.h"

namespace pumpd::local
{
  enum class StrainPath
  {
    uniaxial_strain, ///< eps_yy = epsilon, eps_xx = eps_xy = 0
    uniaxial_stress, ///< eps_yy = epsilon, eps_xx such that sigma_xx = 0, eps_xy = 0 (a free surface)
    equibiaxial      ///< eps_xx = eps_yy = epsilon, eps_xy = 0
  };

  /// sigma_yy [Pa] of the continuum model at the strain epsilon along the path (bonds failed on a
  /// monotone path to it carry nothing).
  double homogeneous_stress(const LiptonMaterial &material, StrainPath path, double epsilon);

  /// eps_xx of the path at eps_yy = epsilon.
  double lateral_strain(const LiptonMaterial &material, StrainPath path, double epsilon);

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
