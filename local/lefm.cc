#include "lefm.h"

#include <cmath>

namespace pumpd::lefm
{
  double kolosov(double nu, bool plane_strain)
  {
    return plane_strain ? 3. - 4. * nu : (3. - nu) / (1. + nu);
  }

  geometry::Point williams_displacement(geometry::Point x, geometry::Point tip, geometry::Point d,
                                        double k1, double k2, double mu, double kappa)
  {
    const geometry::Point rel = x - tip;
    // Local frame: x' along the propagation direction, y' normal to it.
    const double xl = rel.x * d.x + rel.y * d.y, yl = -rel.x * d.y + rel.y * d.x;
    const double r = std::hypot(xl, yl), t = std::atan2(yl, xl);
    const double a = std::sqrt(r / (2. * M_PI)) / (2. * mu);
    const double c = std::cos(0.5 * t), s = std::sin(0.5 * t);
    const double ux = a * (k1 * c * (kappa - 1. + 2. * s * s) + k2 * s * (kappa + 1. + 2. * c * c));
    const double uy = a * (k1 * s * (kappa + 1. - 2. * c * c) - k2 * c * (kappa - 1. - 2. * s * s));
    return {ux * d.x - uy * d.y, ux * d.y + uy * d.x};
  }
} // namespace pumpd::lefm
