// Validation of the global solver with several cracks: stress intensity factors by the interaction
// integral against handbook values. Plane strain, E = 1, nu = 0.3, sigma = 1 in y on the top and
// bottom edges, rigid motions removed by three vertex constraints.
// (a) Two equal collinear cracks of half-length a = 0.5, centres at x = -+b (centre distance 2b),
//     on y = 0 in the plate [-20, 20]^2. With the crack faces at d < |x| < c (d = b - a the inner
//     tips, c = b + a the outer ones), k = d / c, k' = sqrt(1 - k^2) and K, E the complete elliptic
//     integrals of modulus k' (Tada, Paris & Irwin, The Stress Analysis of Cracks Handbook, 3rd
//     ed. 2000, Part II "two collinear cracks of equal length in an infinite sheet", exact; the
//     potential sigma (z^2 - l^2) / sqrt((z^2 - d^2)(z^2 - c^2)), l^2 = c^2 E / K from single-valued
//     displacements):
//       K_inner = sigma sqrt(pi c) (E / K - k^2) / (k' sqrt(k)),
//       K_outer = sigma sqrt(pi c) (1 - E / K) / k'.
//     Both tend to sigma sqrt(pi a) as b / a grows, to sigma sqrt(pi c) (one crack) as d -> 0.
//     Tolerance 3 % on K_I at all four tips and |K_II| < 1 % of K_ref, for b / a = 1.5 and 3. The
//     finite plate is ignored (width W = 20 >= 8 c: the secant correction sqrt(sec(pi c / 2 W))
//     would raise the reference by at most 0.6 %).
// (b) Two far-apart cracks of half-length a = 0.5 in [-10, 10]^2: one along x centred at
//     (-4, -4), one at beta = 30 degrees to x centred at (4, 4), 11 a apart. Each in the infinite
//     plate alone: K_I = sigma sqrt(pi a) cos^2 beta, K_II = sigma sqrt(pi a) sin beta cos beta
//     (as the single inclined crack of sif_test.cc); tolerance 2 % on K_I, and on K_II of the
//     inclined crack (|K_II| < 1 % of K_I for the straight one), at the four tips.
// (c) Cells cut by two cracks: two parallel edge cracks from the left edge of [-1, 1]^2, 0.04 apart
//     (y = 0.03 and 0.07, tips at x = 0.13), on the 20 x 20 mesh (cells of 0.1: every cell of the
//     row 0 < y < 0.1 along the cracks is cut by both) and on the same mesh refined 3 more times along the cracks (cells of 0.0125:
//     none is cut by both); both with cells of 0.1 / 16 within 0.1 of the tips. The strain energy and
//     K_I at both tips agree within 2 % (a cell integrated on the pieces of one crack only would
//     close the other crack along it).
// The meshes are stretched by a smooth map (tips at generic positions relative to the mesh lines)
// and refined near the cracks and 3 more times within 0.15 of each tip (cells of a / 32 there).
// Prints pumpd-metric global.many_cracks_max_rel_err: the worst relative K_I error of (a) and (b).
#include <gtest/gtest.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

#include "elasticity.h"
#include "metric.h"
#include "refinement.h"

using namespace pumpd;
using namespace pumpd::global;

namespace
{
  const double          pi = std::acos(-1.);
  const ElasticMaterial material{1., 0.3, true};

  double worst_collinear = -1., worst_far = -1.;

  class MetricEnvironment : public ::testing::Environment
  {
  public:
    void TearDown() override
    {
      if (worst_collinear >= 0. && worst_far >= 0.)
        test::metric("global.many_cracks_max_rel_err", std::max(worst_collinear, worst_far));
    }
  };
  [[maybe_unused]] ::testing::Environment *const metric_environment =
    ::testing::AddGlobalTestEnvironment(new MetricEnvironment);

  struct Result
  {
    std::vector<StressIntensity> sif;
    unsigned int                 dofs = 0, heaviside_nodes = 0, tip_nodes = 0;
  };

  /// The square [-half, half]^2 on n x n cells stretched by x' = x + 0.31 cos(pi x / 2 half),
  /// y' = y + 0.17 cos(pi y / 2 half), refined 3 times within `radius` of each centre and 3 times
  /// within 0.15 of each tip; sigma = 1 in y on the top (id 3) and bottom (id 2) edges.
  Result solve(double half, unsigned int n, const std::vector<geometry::Point> &centres, double radius,
               const std::vector<geometry::Polyline> &polylines, const std::string &vtu = "")
  {
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {n, n}, dealii::Point<2>(-half, -half),
                                                      dealii::Point<2>(half, half), true);
    dealii::GridTools::transform(
      [&](const dealii::Point<2> &p) {
        return dealii::Point<2>(p[0] + 0.31 * std::cos(pi * p[0] / (2. * half)),
                                p[1] + 0.17 * std::cos(pi * p[1] / (2. * half)));
      },
      tria);
    std::vector<geometry::Point> tips;
    for (const auto &line : polylines)
      tips.insert(tips.end(), {line.front(), line.back()});
    refine_near(tria, centres, radius, 3);
    refine_near(tria, tips, 0.15, 3);

    const geometry::Body body{{-half, -half, half, half}, {}};
    EnrichmentSettings   settings;
    settings.tip_radius = 0.2;
    EnrichedElasticity problem(tria, material, settings);
    std::vector<Crack> cracks;
    for (const auto &line : polylines)
      cracks.emplace_back(line, body, 1e-12);
    problem.set_cracks(cracks);
    problem.add_traction(3, [](geometry::Point) { return geometry::Point{0., 1.}; });
    problem.add_traction(2, [](geometry::Point) { return geometry::Point{0., -1.}; });
    problem.add_dirichlet_vertex({-half, -half}, {0., 0.});
    problem.add_dirichlet_vertex({half, -half}, {0., 0.}, false, true);
    problem.setup();
    problem.assemble();
    problem.solve();
    if (!vtu.empty())
      problem.write_vtu(vtu);
    return {problem.stress_intensity_factors(), problem.n_dofs(), problem.n_heaviside_nodes(), problem.n_tip_nodes()};
  }

  /// Case (c): {strain energy, K_I tip 1, K_I tip 2, number of cells cut by both cracks} of the
  /// two parallel edge cracks, the band along them refined `band_levels` (at most 4) times.
  std::array<double, 4> parallel_edge_cracks(unsigned int band_levels)
  {
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {20, 20}, dealii::Point<2>(-1., -1.),
                                                      dealii::Point<2>(1., 1.), true);
    const std::vector<geometry::Polyline> lines = {{{-1., 0.03}, {0.13, 0.03}}, {{-1., 0.07}, {0.13, 0.07}}};
    std::vector<geometry::Point>          band;
    for (int k = 0; k <= 110; ++k)
      band.push_back({-1. + 0.01 * k, 0.05});
    refine_near(tria, band, 0.05, band_levels);
    refine_near(tria, {{0.13, 0.03}, {0.13, 0.07}}, 0.1, 4 - band_levels);
    unsigned int both = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        const double x = cell->center()[0], h = 0.5 * cell->extent_in_direction(1);
        both += x < 0.13 && cell->center()[1] - h < 0.03 && cell->center()[1] + h > 0.07;
      }
    const geometry::Body body{{-1., -1., 1., 1.}, {}};
    EnrichmentSettings   settings;
    settings.tip_radius = 0.1;
    EnrichedElasticity problem(tria, material, settings);
    problem.set_cracks({Crack(lines[0], body, 1e-12), Crack(lines[1], body, 1e-12)});
    problem.add_traction(3, [](geometry::Point) { return geometry::Point{0., 1.}; });
    problem.add_traction(2, [](geometry::Point) { return geometry::Point{0., -1.}; });
    problem.add_dirichlet_vertex({1., -1.}, {0., 0.});
    problem.add_dirichlet_vertex({1., 1.}, {0., 0.}, true, false);
    problem.setup();
    problem.assemble();
    problem.solve();
    const auto sif = problem.stress_intensity_factors();
    return {{problem.strain_energy(), sif.at(0).k1, sif.at(1).k1, double(both)}};
  }

  /// Tada, Paris & Irwin's two equal collinear cracks, faces at d < |x| < c: {K_inner, K_outer} / sigma.
  std::array<double, 2> collinear_reference(double d, double c)
  {
    const double k = d / c, kp = std::sqrt(1. - k * k);
    const double ratio = std::comp_ellint_2(kp) / std::comp_ellint_1(kp);
    return {{std::sqrt(pi * c) * (ratio - k * k) / (kp * std::sqrt(k)), std::sqrt(pi * c) * (1. - ratio) / kp}};
  }
} // namespace

// The closed form against its potential: l^2 = int_d^c t^2 / w dt / int_d^c 1 / w dt, w = sqrt((t^2 -
// d^2)(c^2 - t^2)), by t^2 = c^2 - (c^2 - d^2) sin^2 phi (dt / w = -dphi / t, smooth), and
// K_outer = sqrt(pi / c) (c^2 - l^2) / sqrt(c^2 - d^2), K_inner = sqrt(pi / d) (l^2 - d^2) / sqrt(c^2 - d^2);
// far apart, each crack alone.
TEST(GlobalManyCracks, HandbookReferenceMatchesItsPotential)
{
  for (double b_over_a : {1.5, 3.})
    {
      const double d = (b_over_a - 1.) * 0.5, c = (b_over_a + 1.) * 0.5;
      const int    n = 2000;
      double       num = 0., den = 0.;
      for (int i = 0; i <= n; ++i)
        {
          const double phi = 0.5 * pi * i / n, w = i == 0 || i == n ? 1. : (i % 2 ? 4. : 2.);
          const double t   = std::sqrt(c * c - (c * c - d * d) * std::pow(std::sin(phi), 2));
          num += w * t;
          den += w / t;
        }
      const double l2  = num / den;
      const auto   ref = collinear_reference(d, c);
      EXPECT_NEAR(ref[0], std::sqrt(pi / d) * (l2 - d * d) / std::sqrt(c * c - d * d), 1e-9);
      EXPECT_NEAR(ref[1], std::sqrt(pi / c) * (c * c - l2) / std::sqrt(c * c - d * d), 1e-9);
    }
  const auto far = collinear_reference(1000., 1001.);
  EXPECT_NEAR(far[0] / std::sqrt(pi * 0.5), 1., 1e-3);
  EXPECT_NEAR(far[1] / std::sqrt(pi * 0.5), 1., 1e-3);
}

TEST(GlobalManyCracks, CollinearCracksMatchHandbook)
{
  const double a     = 0.5;
  double       worst = 0.;
  for (double b_over_a : {1.5, 3.})
    {
      const double b = b_over_a * a, d = b - a, c = b + a;
      const auto   k_ref = collinear_reference(d, c);
      std::cout << "collinear cracks b/a = " << b_over_a << ": K_inner " << k_ref[0] << ", K_outer " << k_ref[1]
                << " (one crack alone " << std::sqrt(pi * a) << ")\n";
      const auto r = solve(20., 40, {{0., 0.}}, c + 0.5, {{{-c, 0.}, {-d, 0.}}, {{d, 0.}, {c, 0.}}});
      std::cout << "  " << r.dofs << " dofs, " << r.heaviside_nodes << " Heaviside nodes, " << r.tip_nodes
                << " tip nodes\n";
      ASSERT_EQ(r.sif.size(), 4u);
      // Cracks in order, tips in each crack's order: (-c, 0), (-d, 0), (d, 0), (c, 0).
      const std::array<double, 4> x = {{-c, -d, d, c}};
      for (std::size_t t = 0; t < 4; ++t)
        {
          const auto  &tip   = r.sif[t];
          const double ref   = k_ref[t == 1 || t == 2 ? 0 : 1];
          const double error = tip.k1 / ref - 1.;
          std::cout << "    tip (" << tip.tip.x << ", " << tip.tip.y << "): K_I " << tip.k1 << " (rel. err " << error
                    << "), K_II " << tip.k2 << "\n";
          EXPECT_NEAR(tip.tip.x, x[t], 1e-12);
          EXPECT_LT(std::abs(error), 0.03) << "b/a " << b_over_a << ", tip " << t;
          EXPECT_LT(std::abs(tip.k2), 0.01 * ref) << "b/a " << b_over_a << ", tip " << t;
          worst = std::max(worst, std::abs(error));
        }
      // The inner tips feel the other crack more than the outer ones.
      EXPECT_GT(r.sif[1].k1, r.sif[0].k1);
      EXPECT_GT(r.sif[2].k1, r.sif[3].k1);
    }
  worst_collinear = worst;
}

TEST(GlobalManyCracks, FarApartCracksEachMatchTheInfinitePlate)
{
  const double          a = 0.5, beta = pi / 6.;
  const geometry::Point e{std::cos(beta), std::sin(beta)};
  const geometry::Point left{-4., -4.}, right{4., 4.};
  const auto r = solve(10., 20, {left, right}, 1.5, {{left - geometry::Point{a, 0.}, left + geometry::Point{a, 0.}},
                                                     {right - a * e, right + a * e}},
                       "many_cracks_far_apart.vtu");
  std::ifstream vtu("many_cracks_far_apart.vtu");
  const std::string text((std::istreambuf_iterator<char>(vtu)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("</VTKFile>"), std::string::npos);
  std::cout << "far-apart cracks: " << r.dofs << " dofs, " << r.tip_nodes << " tip nodes\n";
  ASSERT_EQ(r.sif.size(), 4u);
  const double k0 = std::sqrt(pi * a);
  double       worst = 0.;
  for (std::size_t t = 0; t < 4; ++t)
    {
      const bool   inclined = t >= 2;
      const double k1_ref = inclined ? k0 * std::pow(std::cos(beta), 2) : k0;
      const double k2_ref = inclined ? k0 * std::sin(beta) * std::cos(beta) : 0.;
      const auto  &tip = r.sif[t];
      const double e1 = tip.k1 / k1_ref - 1.;
      std::cout << "  tip (" << tip.tip.x << ", " << tip.tip.y << "): K_I " << tip.k1 << " (ref " << k1_ref
                << ", rel. err " << e1 << "), K_II " << tip.k2 << " (ref " << k2_ref << ")\n";
      EXPECT_LT(std::abs(e1), 0.02) << "tip " << t;
      if (inclined)
        EXPECT_LT(std::abs(tip.k2 / k2_ref - 1.), 0.02) << "tip " << t;
      else
        EXPECT_LT(std::abs(tip.k2), 0.01 * k1_ref) << "tip " << t;
      worst = std::max(worst, std::abs(e1));
    }
  worst_far = worst;
}

TEST(GlobalManyCracks, CellsCutByTwoCracksIntegrateAsFinerCells)
{
  const auto coarse = parallel_edge_cracks(0), fine = parallel_edge_cracks(3);
  std::cout << "parallel edge cracks 0.04 apart: cells cut by both " << coarse[3] << " (coarse), " << fine[3]
            << " (fine)\n";
  const char *name[] = {"strain energy", "K_I lower tip", "K_I upper tip"};
  for (int i = 0; i < 3; ++i)
    {
      std::cout << "  " << name[i] << ": " << coarse[i] << " on cells cut by both, " << fine[i] << " on finer cells\n";
      EXPECT_LT(std::abs(coarse[i] / fine[i] - 1.), 0.02) << name[i];
    }
  EXPECT_GT(coarse[3], 5.);
  EXPECT_EQ(fine[3], 0.);
}
