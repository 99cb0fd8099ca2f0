// Validation 2 of the global solver: stress intensity factors by the interaction integral against
// handbook and exact values. Plane strain, E = 1, nu = 0.3, sigma = 1.
// (a) Single-edge-notch tension (SENT): strip [0, 1] x [-2, 2] (W = 1, half-height 2 >= W), edge
//     crack of length a from the left edge at mid-height, uniform traction sigma on the top and
//     bottom edges, rigid motions removed by three vertex constraints on the right edge (the load
//     is self-equilibrated, so their reactions vanish). Reference: Tada, Paris & Irwin (Brown &
//     Srawley's fit), quoted accurate to 0.5 % for s <= 0.6:
//       K_I = sigma sqrt(pi a) F(s), F = 1.12 - 0.231 s + 10.55 s^2 - 21.72 s^3 + 30.39 s^4, s = a / W.
//     Tolerance: |K_I / K_ref - 1| < 1 % and |K_II| < 0.1 % of K_ref, for s = 0.3 and 0.5, on the
//     40 x 160 mesh refined twice near the tip and on the uniform 40 x 160 and 80 x 320 meshes
//     (the 20 x 80 mesh is printed only, to show the convergence).
// (b) Inclined centre crack of half-length a = 0.5 through the origin at beta = 30 and 60 degrees
//     to x, plate [-10, 10]^2, uniaxial traction sigma in y on the top and bottom edges. Reference:
//     the infinite plate, at both tips in the tip's own frame (x1 ahead of the tip, x2 its left
//     normal; the frame the solver reports in):
//       K_I = sigma sqrt(pi a) cos^2 beta, K_II = +sigma sqrt(pi a) sin beta cos beta,
//     i.e. K_II has the same (positive) sign at both tips. The finite width is ignored (the secant
//     correction sqrt(sec(pi a / 2b)) would raise the reference by 0.15 % at a / b = 0.05).
//     Tolerance: 2 % on K_I and on K_II (relative to the exact K_II) at both tips, on the 20 x 20
//     mesh refined near the crack (hanging nodes) to cells of h / 64 = a / 32 at the tips.
// The crack lines and tips lie at generic positions relative to the mesh lines: the uniform meshes
// are stretched by a smooth map of x alone and y alone (cells stay rectangles, the outline stays).
// Prints pumpd-metric global.sif_max_rel_err: the worst relative error of the asserted cases
// (SENT: K_I; inclined: K_I and K_II).
#include <gtest/gtest.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

#include "elasticity.h"
#include "metric.h"
#include "refinement.h"
#include "sent_strip.h"

using namespace pumpd;
using namespace pumpd::global;

namespace
{
  const double          pi = std::acos(-1.);
  const ElasticMaterial material{1., 0.3, true};

  /// Worst relative error of the asserted cases, per part; the metric is printed once both ran.
  double worst_sent = -1., worst_inclined = -1.;

  class MetricEnvironment : public ::testing::Environment
  {
  public:
    void TearDown() override
    {
      if (worst_sent >= 0. && worst_inclined >= 0.)
        test::metric("global.sif_max_rel_err", std::max(worst_sent, worst_inclined));
    }
  };
  [[maybe_unused]] ::testing::Environment *const metric_environment =
    ::testing::AddGlobalTestEnvironment(new MetricEnvironment);

  double seconds_since(std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  struct Result
  {
    std::vector<StressIntensity> sif;
    unsigned int                 dofs = 0, tip_nodes = 0;
    double                       seconds = 0.;
  };

  /// Solves with sigma = 1 in y on the top (id 3) and bottom (id 2) edges; `fixed` gets both
  /// components fixed, `roller` the component named by roller_x / !roller_x.
  Result solve(dealii::Triangulation<2> &tria, const geometry::Body &body, const geometry::Polyline &crack,
               geometry::Point fixed, geometry::Point roller, bool roller_x, double tip_radius, double sif_factor)
  {
    const auto         start = std::chrono::steady_clock::now();
    EnrichmentSettings settings;
    settings.tip_radius = tip_radius;
    EnrichedElasticity problem(tria, material, settings);
    problem.set_crack(Crack(crack, body, 1e-12));
    problem.add_traction(3, [](geometry::Point) { return geometry::Point{0., 1.}; });
    problem.add_traction(2, [](geometry::Point) { return geometry::Point{0., -1.}; });
    problem.add_dirichlet_vertex(fixed, {0., 0.});
    problem.add_dirichlet_vertex(roller, {0., 0.}, roller_x, !roller_x);
    problem.setup();
    problem.assemble();
    problem.solve();
    Result r;
    r.sif       = problem.stress_intensity_factors(sif_factor);
    r.dofs      = problem.n_dofs();
    r.tip_nodes = problem.n_tip_nodes();
    r.seconds   = seconds_since(start);
    return r;
  }

  /// SENT with crack length a on the nx x ny mesh of [0, 1] x [-2, 2], stretched by
  /// x' = x + 0.37 h_x sin(pi x), y' = y + 0.41 h_y cos(pi y / 4) (before refinement the crack line
  /// y = 0 lies 0.41 h_y below the nearest mesh line, the tip 0.30 h_x (a = 0.3) or 0.37 h_x
  /// (a = 0.5) left of the nearest vertical one), refined `levels` times within 0.1 of the tip.
  /// Tip enrichment radius 0.15, q-function radius 0.15.
  Result sent(double a, unsigned int nx, unsigned int ny, unsigned int levels)
  {
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {nx, ny}, dealii::Point<2>(0., -2.),
                                                      dealii::Point<2>(1., 2.), true);
    const double hx = 1. / nx, hy = 4. / ny;
    dealii::GridTools::transform(
      [&](const dealii::Point<2> &p) {
        return dealii::Point<2>(p[0] + 0.37 * hx * std::sin(pi * p[0]), p[1] + 0.41 * hy * std::cos(pi * p[1] / 4.));
      },
      tria);
    refine_near(tria, {{a, 0.}}, 0.1, levels);
    return solve(tria, {{0., -2., 1., 2.}, {}}, {{0., 0.}, {a, 0.}}, {1., -2.}, {1., 2.}, true, 0.15, 1.);
  }

  /// SENT with a = 0.5 on the 40 x 160 mesh (h = 1 / 40) whose row of cells that holds the crack
  /// line is h / aspect high, the crack at the fraction `at` of its height; the tip 0.37 h right
  /// of a vertical mesh line, the other rows and columns of about h (study_sliver_cells' rows).
  Result sent_with_sliver_row(double aspect, double at)
  {
    const double a = 0.5, h = 1. / 40., thin = h / aspect;
    // Steps of about h over [from, to] with one step `step` whose lower end lies `below` under `at`.
    const auto steps = [&](double from, double to, double where, double step, double below) {
      std::vector<double> out;
      const auto          fill = [&](double lower, double upper) {
        const unsigned int k = std::max(1., std::round((upper - lower) / h));
        out.insert(out.end(), k, (upper - lower) / k);
      };
      fill(from, where - below);
      out.push_back(step);
      fill(where - below + step, to);
      return out;
    };
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {steps(0., 1., a, h, 0.37 * h), steps(-2., 2., 0., thin, at * thin)},
                                                      dealii::Point<2>(0., -2.), dealii::Point<2>(1., 2.), true);
    return solve(tria, {{0., -2., 1., 2.}, {}}, {{0., 0.}, {a, 0.}}, {1., -2.}, {1., 2.}, true, 0.15, 1.);
  }

  /// Inclined crack of half-length 0.5 at angle beta through the origin of [-10, 10]^2 on the
  /// 20 x 20 mesh stretched by x' = x + 0.31 cos(pi x / 20), y' = y + 0.17 cos(pi y / 20), refined
  /// `levels` times within `radius` of the origin and then 3 times within 0.15 of each tip (the
  /// origin lies at (-0.31, -0.17) h from the nearest vertex of the unrefined mesh). Tip
  /// enrichment radius 0.2, q-function radius 0.2 (the other tip is 1 away).
  Result inclined(double beta, unsigned int levels, double radius)
  {
    const double             a = 0.5;
    const geometry::Point    e{std::cos(beta), std::sin(beta)};
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {20, 20}, dealii::Point<2>(-10., -10.),
                                                      dealii::Point<2>(10., 10.), true);
    dealii::GridTools::transform(
      [&](const dealii::Point<2> &p) {
        return dealii::Point<2>(p[0] + 0.31 * std::cos(pi * p[0] / 20.), p[1] + 0.17 * std::cos(pi * p[1] / 20.));
      },
      tria);
    refine_near(tria, {{0., 0.}}, radius, levels);
    refine_near(tria, {(-a) * e, a * e}, 0.15, 3);
    return solve(tria, {{-10., -10., 10., 10.}, {}}, {(-a) * e, a * e}, {-10., -10.}, {10., -10.}, false, 0.2, 1.);
  }
} // namespace

TEST(GlobalSif, SingleEdgeNotchTensionMatchesHandbook)
{
  struct Mesh
  {
    unsigned int nx, ny, levels;
    bool         asserted;
  };
  double worst = 0.;
  for (double s : {0.3, 0.5})
    {
      const double k_ref = std::sqrt(pi * s) * sent_strip::geometry_factor(s);
      std::cout << "SENT a/W = " << s << ": K_ref = " << k_ref << "\n";
      for (const Mesh &m : {Mesh{20, 80, 0, false}, Mesh{40, 160, 0, true}, Mesh{80, 320, 0, true}, Mesh{40, 160, 1, false},
                            Mesh{40, 160, 2, true}})
        {
          const auto   r   = sent(s, m.nx, m.ny, m.levels);
          const double k1  = r.sif.at(0).k1, k2 = r.sif.at(0).k2;
          const double err = k1 / k_ref - 1.;
          std::cout << "  " << m.nx << " x " << m.ny << ", refined " << m.levels << "x near the tip: K_I " << k1
                    << " (rel. err " << err << "), K_II " << k2 << ", " << r.dofs << " dofs, " << r.tip_nodes
                    << " tip nodes, " << r.seconds << " s\n";
          if (!m.asserted)
            continue;
          EXPECT_LT(std::abs(err), 0.01) << "a/W = " << s << ", mesh " << m.nx << " x " << m.ny << " L" << m.levels;
          EXPECT_LT(std::abs(k2), 1e-3 * k_ref) << "a/W = " << s << ", mesh " << m.nx << " x " << m.ny << " L" << m.levels;
          worst = std::max(worst, std::abs(err));
        }
    }
  worst_sent = worst;
}

TEST(GlobalSif, InclinedCentreCrackMatchesInfinitePlate)
{
  double worst = 0.;
  for (double degrees : {30., 60.})
    {
      const double beta = degrees * pi / 180.;
      const double k0 = std::sqrt(pi * 0.5), k1_exact = k0 * std::pow(std::cos(beta), 2),
                   k2_exact = k0 * std::sin(beta) * std::cos(beta);
      std::cout << "inclined crack beta = " << degrees << " deg: exact K_I " << k1_exact << ", K_II " << k2_exact << "\n";
      // (levels, radius) of the refinement around the crack: a coarser one (printed) and the one
      // asserted.
      for (const auto &[levels, radius] : {std::pair<unsigned int, double>{2, 1.}, {3, 1.5}})
        {
          const bool asserted = levels == 3;
          const auto r        = inclined(beta, levels, radius);
          std::cout << "  refined " << levels << "x within " << radius << " of the origin, 3x near the tips: "
                    << r.dofs << " dofs, " << r.tip_nodes << " tip nodes, " << r.seconds << " s\n";
          ASSERT_EQ(r.sif.size(), 2u);
          for (const auto &tip : r.sif)
            {
              const double e1 = tip.k1 / k1_exact - 1., e2 = tip.k2 / k2_exact - 1.;
              std::cout << "    tip (" << tip.tip.x << ", " << tip.tip.y << "): K_I " << tip.k1 << " (rel. err " << e1
                        << "), K_II " << tip.k2 << " (rel. err " << e2 << ")\n";
              if (!asserted)
                continue;
              EXPECT_LT(std::abs(e1), 0.02) << "beta " << degrees << ", tip (" << tip.tip.x << ", " << tip.tip.y << ")";
              EXPECT_LT(std::abs(e2), 0.02) << "beta " << degrees << ", tip (" << tip.tip.x << ", " << tip.tip.y << ")";
              worst = std::max({worst, std::abs(e1), std::abs(e2)});
            }
          if (asserted) // the same sign at both tips, each in its own frame
            {
              EXPECT_GT(r.sif[0].k2 * r.sif[1].k2, 0.);
            }
        }
    }
  worst_inclined = worst;
}

// Issue 45 point 6: a row of sliver cells along the crack (aspect ratio 1e3 with the crack just
// where its upper nodes' supports are cut below min_cut_fraction of their area; 1e4, where both
// rows' are) keeps K_I: within the 1 % of the SENT cases above of Tada's value, and within 0.5 % of
// the same mesh without the sliver (aspect ratio 1). Heaviside blocks dropped by area alone left
// these cells to hold the crack shut (K_I 86 % low).
TEST(GlobalSif, SliverRowAlongTheCrackKeepsK)
{
  const double s = 0.5, k_ref = std::sqrt(pi * s) * sent_strip::geometry_factor(s);
  const double k_square = sent_with_sliver_row(1., 0.3).sif.at(0).k1;
  const double barely   = 0.9 * EnrichmentSettings().min_cut_fraction;
  for (const auto &[aspect, at] : {std::pair<double, double>{1e3, barely * (1e3 + 1.)}, {1e4, 0.3}})
    {
      const double k1 = sent_with_sliver_row(aspect, at).sif.at(0).k1;
      std::cout << "SENT a/W = 0.5, crack row of aspect ratio " << aspect << ", crack at " << at
                << " of its height: K_I " << k1 << " (rel. err " << k1 / k_ref - 1. << ", against square cells "
                << k1 / k_square - 1. << ")\n";
      EXPECT_LT(std::abs(k1 / k_ref - 1.), 0.01) << "aspect ratio " << aspect;
      EXPECT_LT(std::abs(k1 / k_square - 1.), 0.005) << "aspect ratio " << aspect;
    }
}
