#include "strength.h"

#include <cmath>
#include <vector>

namespace pumpd::local
{
  namespace
  {
    /// Gauss-Legendre nodes and weights on [0, 1] (Newton on P_n from the Chebyshev guesses).
    struct GaussLegendre
    {
      std::vector<double> x, w;
      explicit GaussLegendre(int n)
      {
        for (int i = 0; i < n; ++i)
          {
            double t = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 1.;
            for (int it = 0; it < 100; ++it)
              {
                double p0 = 1., p1 = t;
                for (int k = 2; k <= n; ++k)
                  {
                    const double p2 = ((2. * k - 1.) * t * p1 - (k - 1.) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                  }
                dp = n * (t * p1 - p0) / (t * t - 1.);
                const double step = p1 / dp;
                t -= step;
                if (std::abs(step) < 1e-15)
                  break;
              }
            x.push_back(0.5 * (1. - t));
            w.push_back(1. / ((1. - t * t) * dp * dp));
          }
      }
    };

    const GaussLegendre &rule()
    {
      static const GaussLegendre g(48);
      return g;
    }

    /// s(t) = e.P.e = p_x cos^2 t + p_y sin^2 t.
    struct Path
    {
      double px, py;
      explicit Path(StrainPath path)
        : px(path == StrainPath::equibiaxial ? 1. : 0.)
        , py(1.)
      {}
      double s(double t) const
      {
        const double c = std::cos(t), n = std::sin(t);
        return px * c * c + py * n * n;
      }
    };

    /// Phi(a) = int_0^1 J rho^2 int_0^{2 pi} s sin^2 t exp(-a rho s^2) dt drho over the intact
    /// bonds, a rho s^2 <= x_break. The integrand is even about t = 0 and t = pi / 2, so four
    /// times the quarter; the quarter is split where the break cut-off rho < x_break / (a s^2)
    /// enters (s is monotone in t), so that each piece is smooth.
    double phi(const LiptonMaterial &material, const Path &path, double a)
    {
      const auto  &g       = rule();
      const double x_break = 0.5 * material.parameters().break_factor * material.parameters().break_factor;
      const auto piece = [&](double t0, double t1) {
        double sum = 0.;
        for (std::size_t i = 0; i < g.x.size(); ++i)
          {
            const double t = t0 + (t1 - t0) * g.x[i], s = path.s(t), sin_t = std::sin(t);
            const double reach = a * s * s > x_break ? x_break / (a * s * s) : 1.;
            double       radial = 0.;
            for (std::size_t j = 0; j < g.x.size(); ++j)
              {
                const double rho = reach * g.x[j];
                radial += g.w[j] * material.influence(rho) * rho * rho * std::exp(-a * rho * s * s);
              }
            sum += g.w[i] * s * sin_t * sin_t * reach * radial;
          }
        return (t1 - t0) * sum;
      };
      // sin^2 t_b = (sqrt(x_break / a) - p_x) / (p_y - p_x): the first bond (rho = 1) breaks.
      double split = -1.;
      if (path.py != path.px && a > 0.)
        split = (std::sqrt(x_break / a) - path.px) / (path.py - path.px);
      if (split > 0. && split < 1.)
        {
          const double tb = std::asin(std::sqrt(split));
          return 4. * (piece(0., tb) + piece(tb, 0.5 * M_PI));
        }
      return 4. * piece(0., 0.5 * M_PI);
    }
  } // namespace

  double homogeneous_stress(const LiptonMaterial &material, StrainPath path, double epsilon)
  {
    const double a = material.beta() * material.horizon() * epsilon * epsilon;
    return 2. * material.C() * material.beta() / M_PI * epsilon * phi(material, Path(path), a);
  }

  PeakStress peak_stress(const LiptonMaterial &material, StrainPath path)
  {
    // sigma_yy is proportional to sqrt(a) Phi(a): bracket its peak on a geometric grid of a, then
    // golden-section search in log a.
    const Path   p(path);
    const auto   f     = [&](double log_a) {
      const double a = std::exp(log_a);
      return std::sqrt(a) * phi(material, p, a);
    };
    const double first = std::log(1e-3), step = std::log(1.1);
    int          best  = 0;
    double       top   = 0.;
    for (int i = 0; i <= 160; ++i)
      if (const double v = f(first + i * step); v > top)
        {
          top  = v;
          best = i;
        }
    double       lo = first + (best - 1) * step, hi = first + (best + 1) * step;
    const double r  = 0.5 * (std::sqrt(5.) - 1.);
    double       c = hi - r * (hi - lo), d = lo + r * (hi - lo), fc = f(c), fd = f(d);
    while (hi - lo > 1e-10)
      if (fc > fd)
        {
          hi = d;
          d  = c;
          fd = fc;
          c  = hi - r * (hi - lo);
          fc = f(c);
        }
      else
        {
          lo = c;
          c  = d;
          fc = fd;
          d  = lo + r * (hi - lo);
          fd = f(d);
        }
    const double a      = std::exp(0.5 * (lo + hi));
    const double strain = std::sqrt(a / (material.beta() * material.horizon()));
    return {homogeneous_stress(material, path, strain), strain};
  }

  double tensile_strength(const LiptonMaterial &material)
  {
    return peak_stress(material, StrainPath::uniaxial).stress;
  }
} // namespace pumpd::local
