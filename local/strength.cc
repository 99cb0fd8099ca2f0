#include "strength.h"

#include <algorithm>
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

    /// s(t) = e.P.e = p_x cos^2 t + sin^2 t for P = diag(p_x, 1).
    struct Path
    {
      double px;
      double s(double t) const
      {
        const double c = std::cos(t), n = std::sin(t);
        return px * c * c + n * n;
      }
    };

    struct Phi
    {
      double x, y; ///< Phi_x, Phi_y
    };

    /// Phi_x, Phi_y (strength.h) over the intact bonds, a rho s^2 <= x_break. The integrands are
    /// even about t = 0 and t = pi / 2, so four times the quarter; the quarter is split where the
    /// break cut-off rho < x_break / (a s^2) enters (s is monotone in t, and s = +-sqrt(x_break / a)
    /// at most once each), or, under the linear law in compression, where s = 0 (the shortened
    /// bonds' factor exp(-a rho s^2) becomes 1), so that each piece is smooth.
    Phi phi(const LiptonMaterial &material, const Path &path, double a)
    {
      const auto  &g       = rule();
      const double x_break = 0.5 * material.parameters().break_factor * material.parameters().break_factor;
      const auto piece = [&](double t0, double t1) {
        Phi sum{0., 0.};
        for (std::size_t i = 0; i < g.x.size(); ++i)
          {
            const double t = t0 + (t1 - t0) * g.x[i], s = path.s(t), cos_t = std::cos(t), sin_t = std::sin(t);
            const bool   soft  = material.softens(s); // else a linear bond: exp(0), no break
            const double reach = soft && a * s * s > x_break ? x_break / (a * s * s) : 1.;
            double       radial = 0.;
            for (std::size_t j = 0; j < g.x.size(); ++j)
              {
                const double rho = reach * g.x[j];
                radial += g.w[j] * material.influence(rho) * rho * rho * (soft ? std::exp(-a * rho * s * s) : 1.);
              }
            const double common = (t1 - t0) * g.w[i] * s * reach * radial;
            sum.x += common * cos_t * cos_t;
            sum.y += common * sin_t * sin_t;
          }
        return sum;
      };
      // sin^2 t_b = (+-sqrt(x_break / a) - p_x) / (1 - p_x): the first bond (rho = 1) breaks; under
      // the linear law in compression, the shortened bonds neither break nor soften: s = 0 instead.
      const bool          linear_below = material.parameters().compression == Compression::linear;
      std::vector<double> ends{0.};
      if (a > 0. && path.px != 1.)
        for (const double s_b : {linear_below ? 0. : -std::sqrt(x_break / a), std::sqrt(x_break / a)})
          if (const double split = (s_b - path.px) / (1. - path.px); split > 0. && split < 1.)
            ends.push_back(std::asin(std::sqrt(split)));
      std::sort(ends.begin() + 1, ends.end());
      ends.push_back(0.5 * M_PI);
      Phi total{0., 0.};
      for (std::size_t k = 0; k + 1 < ends.size(); ++k)
        {
          const Phi p = piece(ends[k], ends[k + 1]);
          total.x += 4. * p.x;
          total.y += 4. * p.y;
        }
      return total;
    }

    /// The path's P = diag(p_x, 1) at a = beta delta epsilon^2. Uniaxial stress: p_x = -q with
    /// Phi_x(a, q) = 0, q in (0, 1) (Phi_x > 0 at q = 0, where every bond is stretched, and < 0 at
    /// q = 1, where the compressed bonds along x outweigh the stretched ones), by regula falsi
    /// (Illinois): Phi_x is nearly linear in q.
    Path path_at(const LiptonMaterial &material, StrainPath path, double a)
    {
      if (path == StrainPath::uniaxial_strain)
        return {0.};
      if (path == StrainPath::equibiaxial)
        return {1.};
      double lo = 0., hi = 1., f_lo = phi(material, {-lo}, a).x, f_hi = phi(material, {-hi}, a).x, q = -1.;
      int    kept = 0; // the end the last step kept: -1 lo, 1 hi
      for (int it = 0; it < 100; ++it)
        {
          const double next = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
          if (std::abs(next - q) < 1e-14)
            break;
          q              = next;
          const double f = phi(material, {-q}, a).x;
          if (f == 0.)
            break;
          if ((f > 0.) == (f_lo > 0.))
            {
              lo   = q;
              f_lo = f;
              if (kept == 1)
                f_hi *= 0.5;
              kept = 1;
            }
          else
            {
              hi   = q;
              f_hi = f;
              if (kept == -1)
                f_lo *= 0.5;
              kept = -1;
            }
        }
      return {-q};
    }
  } // namespace

  double homogeneous_stress(const LiptonMaterial &material, StrainPath path, double epsilon)
  {
    const double a = material.beta() * material.horizon() * epsilon * epsilon;
    return 2. * material.C() * material.beta() / M_PI * epsilon * phi(material, path_at(material, path, a), a).y;
  }

  double lateral_strain(const LiptonMaterial &material, StrainPath path, double epsilon)
  {
    const double a = material.beta() * material.horizon() * epsilon * epsilon;
    return path_at(material, path, a).px * epsilon;
  }

  PeakStress peak_stress(const LiptonMaterial &material, StrainPath path)
  {
    // sigma_yy is proportional to sqrt(a) Phi_y(a): bracket its peak on a geometric grid of a,
    // then golden-section search in log a.
    const auto   f     = [&](double log_a) {
      const double a = std::exp(log_a);
      return std::sqrt(a) * phi(material, path_at(material, path, a), a).y;
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
    return peak_stress(material, StrainPath::uniaxial_strain).stress;
  }
} // namespace pumpd::local
