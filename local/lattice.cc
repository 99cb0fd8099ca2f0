#include "lattice.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <string>
#include <utility>

#include "error.h"
#include "material.h"

namespace pumpd::local
{
  namespace
  {
    Stencil integrate_half_stencil(int m, const LiptonMaterial &material)
    {
      Stencil s;
      s.reach = m;
      // Midpoint rule on n x n sub-cells of each neighbour cell: the rim error is O(1/n^2).
      const int    n   = 96;
      const double sub = 1. / n;
      for (int dy = 0; dy <= m; ++dy)
        for (int dx = -m; dx <= m; ++dx)
          {
            if (dy == 0 && dx <= 0)
              continue;
            double w = 0.;
            for (int a = 0; a < n; ++a)
              for (int c = 0; c < n; ++c)
                {
                  const double x = dx - 0.5 + (a + 0.5) * sub;
                  const double y = dy - 0.5 + (c + 0.5) * sub;
                  const double rho = std::hypot(x, y);
                  w += material.influence(rho / m) * rho;
                }
            const double r = std::hypot(double(dx), double(dy));
            w *= sub * sub / r;
            if (w <= 0.)
              continue;
            s.dx.push_back(dx);
            s.dy.push_back(dy);
            s.length.push_back(r);
            s.ex.push_back(dx / r);
            s.ey.push_back(dy / r);
            s.weight.push_back(w);
          }

      // The energy of an affine strain sums w r (e.eps e)^2; on a square lattice the 4th moment
      // sum w r e(x)e(x)e(x)e has a cos(4 theta) part that makes shear differ from tension at small
      // m. Scale w by (1 - gamma cos 4 theta) so that sum w r cos 4 theta = 0 (isotropic), then
      // restore the radial moment sum w r = int J(|xi|/delta) |xi| dxi = 2 pi m^3 M (full stencil).
      double c1 = 0., c2 = 0.;
      for (std::size_t k = 0; k < s.size(); ++k)
        {
          const double c4 = std::cos(4. * std::atan2(double(s.dy[k]), double(s.dx[k])));
          c1 += s.weight[k] * s.length[k] * c4;
          c2 += s.weight[k] * s.length[k] * c4 * c4;
        }
      const double gamma = c2 > 0. ? c1 / c2 : 0.;
      double       radial = 0.;
      for (std::size_t k = 0; k < s.size(); ++k)
        {
          s.weight[k] *= 1. - gamma * std::cos(4. * std::atan2(double(s.dy[k]), double(s.dx[k])));
          radial += 2. * s.weight[k] * s.length[k];
        }
      const double exact = 2. * M_PI * m * m * m * material.moment();
      for (auto &w : s.weight)
        w *= exact / radial;
      return s;
    }
  } // namespace

  Stencil make_half_stencil(int m, const LiptonMaterial &material)
  {
    static std::mutex                                   mutex;
    static std::map<std::pair<int, Influence>, Stencil> computed;
    const std::lock_guard<std::mutex>                   lock(mutex);
    const std::pair key   = {m, material.parameters().influence};
    auto            found = computed.find(key);
    if (found == computed.end())
      found = computed.emplace(key, integrate_half_stencil(m, material)).first;
    return found->second;
  }

  Lattice::Lattice(const geometry::Box &box, double spacing, int ratio)
    : b(box)
    , h(spacing)
    , m(ratio)
  {
    require_positive("PD spacing h", h);
    if (m < 2)
      throw InvalidParameter("Horizon over spacing (m)", std::to_string(m),
                             "must be an integer >= 2 (the horizon spans at least two spacings)");
    if (!(b.width() > 0. && b.height() > 0. && std::isfinite(b.width()) && std::isfinite(b.height())))
      throw InvalidParameter("PD box",
                             "[" + std::to_string(b.x_min) + ", " + std::to_string(b.x_max) + "] x [" +
                               std::to_string(b.y_min) + ", " + std::to_string(b.y_max) + "]",
                             "needs x_min < x_max and y_min < y_max");
    // Beyond this many nodes no machine holds the lattice; refused before its counts overflow.
    const double most_nodes = 1e12;
    if ((b.width() / h) * (b.height() / h) > most_nodes)
      throw InvalidParameter("PD box", to_text(b.width()) + " x " + to_text(b.height()),
                             "holds about " + to_text((b.width() / h) * (b.height() / h), 3) +
                               " nodes at spacing h = " + to_text(h) + ", more than any machine can hold (at most " +
                               to_text(most_nodes, 3) + "): a smaller box or a larger spacing");
    const auto count = [&](double length) { return std::size_t(std::floor(length / h + 1e-9)); };
    n_x = count(b.width());
    n_y = count(b.height());
    if (n_x < std::size_t(2 * m + 1) || n_y < std::size_t(2 * m + 1))
      throw InvalidParameter("PD box", std::to_string(b.width()) + " x " + std::to_string(b.height()),
                             "must hold at least 2 m + 1 = " + std::to_string(2 * m + 1) +
                               " spacings each way (h = " + to_text(h) + "): a smaller Horizon or a larger box");
    row_stride = (n_x + 2 * m + 63) / 64 * 64;
    x0         = b.x_min + 0.5 * (b.width() - n_x * h) + 0.5 * h;
    y0         = b.y_min + 0.5 * (b.height() - n_y * h) + 0.5 * h;
  }

  bool Lattice::is_real(std::size_t i) const
  {
    const std::size_t c = i % row_stride, r = i / row_stride;
    return c >= std::size_t(m) && c < m + n_x && r < n_y;
  }

  geometry::Point Lattice::position(std::size_t i) const
  {
    const double c = double(i % row_stride) - m;
    const double r = double(i / row_stride);
    return {x0 + c * h, y0 + r * h};
  }
} // namespace pumpd::local
