// Linear elastic fracture mechanics reference fields (no PD, no deal.II): the Williams near-tip
// fields for modes I and II, used to drive a PD box by a known K, as auxiliary fields of the
// interaction integral, and as exact solutions in tests. Shared by local/ and global/.
#pragma once

#include "geometry.h"

namespace pumpd::lefm
{
  /// Kolosov constant: 3 - 4 nu (plane strain), (3 - nu) / (1 + nu) (plane stress).
  double kolosov(double nu, bool plane_strain);

  /// Williams field of unit K in the tip frame (x1 ahead of the tip, x2 normal) at polar
  /// coordinates (r, theta), theta in [-pi, pi] (the crack faces at +-pi): displacement u_i,
  /// gradient du_i/dx_j and stress sigma_ij (Anderson, Fracture Mechanics, Tables 2.1-2.2).
  struct TipField
  {
    double u[2];
    double grad[2][2];
    double stress[2][2];
  };
  TipField williams(int mode, double r, double theta, double shear_modulus, double kappa);

  /// Near-tip displacement for stress intensity factors K_I, K_II (Anderson, Fracture Mechanics,
  /// Table 2.2) at a point x, for a tip at `tip` whose crack runs behind it along -direction
  /// (direction = unit vector of propagation). theta in (-pi, pi], the crack faces at +-pi.
  ///   u_x' = K_I/(2 mu) sqrt(r/2pi) cos(t/2) (kappa - 1 + 2 sin^2(t/2))
  ///        + K_II/(2 mu) sqrt(r/2pi) sin(t/2) (kappa + 1 + 2 cos^2(t/2))
  ///   u_y' = K_I/(2 mu) sqrt(r/2pi) sin(t/2) (kappa + 1 - 2 cos^2(t/2))
  ///        - K_II/(2 mu) sqrt(r/2pi) cos(t/2) (kappa - 1 - 2 sin^2(t/2))
  /// with theta = atan2 in the tip frame.
  geometry::Point williams_displacement(geometry::Point x, geometry::Point tip, geometry::Point direction,
                                        double k1, double k2, double shear_modulus, double kappa);
} // namespace pumpd::lefm
