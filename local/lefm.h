// Linear elastic fracture mechanics reference fields (no PD, no deal.II): the Williams near-tip
// displacement for modes I and II, used to drive a PD box by a known K and to check solvers.
#pragma once

#include "geometry.h"

namespace pumpd::lefm
{
  /// Kolosov constant: 3 - 4 nu (plane strain), (3 - nu) / (1 + nu) (plane stress).
  double kolosov(double nu, bool plane_strain);

  /// Near-tip displacement for stress intensity factors K_I, K_II (Anderson, Fracture Mechanics,
  /// Table 2.2) at a point x, for a tip at `tip` whose crack runs behind it along -direction
  /// (direction = unit vector of propagation). theta in (-pi, pi], the crack faces at +-pi.
  ///   u_x' = K_I/(2 mu) sqrt(r/2pi) cos(t/2) (kappa - 1 + 2 sin^2(t/2))
  ///        + K_II/(2 mu) sqrt(r/2pi) sin(t/2) (kappa + 1 + 2 cos^2(t/2))
  ///   u_y' = K_I/(2 mu) sqrt(r/2pi) sin(t/2) (kappa + 1 - 2 cos^2(t/2))
  ///        - K_II/(2 mu) sqrt(r/2pi) cos(t/2) (kappa - 1 - 2 sin^2(t/2))
  geometry::Point williams_displacement(geometry::Point x, geometry::Point tip, geometry::Point direction,
                                        double k1, double k2, double shear_modulus, double kappa);
} // namespace pumpd::lefm
