#include "lefm.h"

#include <cmath>

namespace pumpd::lefm
{
  double kolosov(double nu, bool plane_strain)
  {
    return plane_strain ? 3. - 4. * nu : (3. - nu) / (1. + nu);
  }

  TipField williams(int mode, double r, double t, double mu, double kappa)
  {
    const double s = std::sin(0.5 * t), c = std::cos(0.5 * t);
    const double s3 = std::sin(1.5 * t), c3 = std::cos(1.5 * t);
    // u_i = a sqrt(r) g_i(theta); dg = dg/dtheta.
    double g[2], dg[2];
    if (mode == 1)
      {
        g[0]  = c * (kappa - 1. + 2. * s * s);
        g[1]  = s * (kappa + 1. - 2. * c * c);
        dg[0] = -0.5 * s * (kappa - 1. + 2. * s * s) + 2. * s * c * c;
        dg[1] = 0.5 * c * (kappa + 1. - 2. * c * c) + 2. * s * s * c;
      }
    else
      {
        g[0]  = s * (kappa + 1. + 2. * c * c);
        g[1]  = -c * (kappa - 1. - 2. * s * s);
        dg[0] = 0.5 * c * (kappa + 1. + 2. * c * c) - 2. * s * s * c;
        dg[1] = 0.5 * s * (kappa - 1. - 2. * s * s) + 2. * s * c * c;
      }
    TipField     f{};
    const double a = 1. / (2. * mu * std::sqrt(2. * M_PI));
    const double ct = std::cos(t), st = std::sin(t);
    for (int i = 0; i < 2; ++i)
      {
        f.u[i]             = a * std::sqrt(r) * g[i];
        const double du_dr = a * g[i] / (2. * std::sqrt(r)), du_dt = a * std::sqrt(r) * dg[i];
        f.grad[i][0]       = ct * du_dr - st / r * du_dt;
        f.grad[i][1]       = st * du_dr + ct / r * du_dt;
      }
    const double k = 1. / std::sqrt(2. * M_PI * r);
    if (mode == 1)
      {
        f.stress[0][0] = k * c * (1. - s * s3);
        f.stress[1][1] = k * c * (1. + s * s3);
        f.stress[0][1] = f.stress[1][0] = k * c * s * c3;
      }
    else
      {
        f.stress[0][0] = -k * s * (2. + c * c3);
        f.stress[1][1] = k * s * c * c3;
        f.stress[0][1] = f.stress[1][0] = k * c * (1. - s * s3);
      }
    return f;
  }

  geometry::Point williams_displacement(geometry::Point x, geometry::Point tip, geometry::Point d,
                                        double k1, double k2, double mu, double kappa)
  {
    const geometry::Point rel = x - tip;
    // Local frame: x' along the propagation direction, y' normal to it.
    const double xl = rel.x * d.x + rel.y * d.y, yl = -rel.x * d.y + rel.y * d.x;
    const double r = std::hypot(xl, yl), t = std::atan2(yl, xl);
    const TipField f1 = williams(1, r, t, mu, kappa), f2 = williams(2, r, t, mu, kappa);
    const double   ux = k1 * f1.u[0] + k2 * f2.u[0], uy = k1 * f1.u[1] + k2 * f2.u[1];
    return {ux * d.x - uy * d.y, ux * d.y + uy * d.x};
  }
} // namespace pumpd::lefm
