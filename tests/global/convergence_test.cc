// Validation 1 of the global solver: the exact near-tip field (Williams, mode I and mode II,
// unit K) imposed as boundary data on a square with an edge crack (displacement on three edges,
// traction on the edge with the crack mouth); errors
// in the energy norm and in L2 on four uniform meshes. Geometric tip enrichment (fixed radius)
// restores the optimal rates of Q1: energy-norm rate >= 0.95, L2 rate >= 1.9 (least-squares
// slopes over the four meshes). The crack line and the tip lie at generic positions in all meshes.
#include <gtest/gtest.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "elasticity.h"
#include "lefm.h"
#include "metric.h"

using namespace pumpd;
using namespace pumpd::global;

namespace
{
  const geometry::Point tip{0.013, 0.};

  struct Field
  {
    int             mode;
    ElasticMaterial material;

    lefm::TipField at(geometry::Point x, int side) const
    {
      const geometry::Point rel = x - tip;
      const double          r   = std::max(geometry::norm(rel), 1e-300);
      return lefm::williams(mode, r, side * std::acos(std::clamp(rel.x / r, -1., 1.)), material.mu(),
                            material.kolosov());
    }
  };

  /// Slope of log(error) against log(h) by least squares.
  double rate(const std::vector<double> &h, const std::vector<double> &e)
  {
    double sx = 0., sy = 0., sxx = 0., sxy = 0.;
    const double n = h.size();
    for (std::size_t i = 0; i < h.size(); ++i)
      {
        const double x = std::log(h[i]), y = std::log(e[i]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
      }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
  }
} // namespace

TEST(GlobalConvergence, WilliamsFieldOptimalRates)
{
  double worst_energy = 1e9, worst_l2 = 1e9;
  for (int mode : {1, 2})
    {
      Field field{mode, {1., 0.3, true}};
      std::vector<double> h, e_energy, e_l2;
      for (unsigned int n : {20u, 40u, 80u, 160u})
        {
          dealii::Triangulation<2> tria;
          dealii::GridGenerator::subdivided_hyper_rectangle(tria, {n, n}, dealii::Point<2>(-1., -0.97),
                                                            dealii::Point<2>(1., 1.03), true);
          EnrichmentSettings settings;
          settings.tip_radius = 0.3;
          EnrichedElasticity problem(tria, field.material, settings);
          geometry::Body body{{-1., -0.97, 1., 1.03}, {}};
          problem.set_crack(Crack({{-1., 0.}, tip}, body, 1e-12));
          const SidedField exact = [&](geometry::Point x, int side) {
            const auto f = field.at(x, side);
            return geometry::Point{f.u[0], f.u[1]};
          };
          // The exact displacement on three edges, the exact traction sigma n on the edge that
          // holds the crack mouth (left, n = (-1, 0)), as at a real mouth (a loaded free surface).
          for (unsigned int id = 1; id < 4; ++id)
            problem.add_dirichlet(id, exact);
          problem.add_traction(0, [&](geometry::Point x) {
            const auto f = field.at(x, x.y >= 0. ? 1 : -1);
            return geometry::Point{-f.stress[0][0], -f.stress[1][0]};
          });
          problem.setup();
          problem.assemble();
          problem.solve();
          const auto err = problem.errors(exact, [&](geometry::Point x, int side) {
            const auto f = field.at(x, side);
            return std::array<double, 4>{{f.grad[0][0], f.grad[0][1], f.grad[1][0], f.grad[1][1]}};
          });
          const auto sif = problem.stress_intensity_factors();
          std::cout << "mode " << mode << " n = " << n << ": dofs " << problem.n_dofs() << " (enriched "
                    << problem.n_enriched_dofs() << "), relative errors energy " << err.energy / err.energy_exact
                    << " L2 " << err.l2 / err.l2_exact << ", K_I " << sif[0].k1 << " K_II " << sif[0].k2 << "\n";
          h.push_back(2. / n);
          e_energy.push_back(err.energy / err.energy_exact);
          e_l2.push_back(err.l2 / err.l2_exact);
        }
      const double r_energy = rate(h, e_energy), r_l2 = rate(h, e_l2);
      std::cout << "mode " << mode << ": energy rate " << r_energy << ", L2 rate " << r_l2 << "\n";
      EXPECT_GE(r_energy, 0.95);
      EXPECT_GE(r_l2, 1.9);
      worst_energy = std::min(worst_energy, r_energy);
      worst_l2     = std::min(worst_l2, r_l2);
    }
  test::metric("global.energy_rate", worst_energy);
  test::metric("global.l2_rate", worst_l2);
}
