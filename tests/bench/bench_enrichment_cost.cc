// Validation 6 of the global solver: what the enrichment costs. The same uniform mesh (160 x 160
// cells on the square of the convergence test; 80 x 80 as well, for the trend) solved with the
// edge crack (mode I Williams field as boundary data) and without it (set_crack(std::nullopt), a
// linear field of constant stress as boundary data, the same Dirichlet edges and traction edge).
// setup, assemble and solve are timed separately, median of a few repetitions, on one thread
// (deal.II's thread limit; the BLAS under CHOLMOD is whatever the system provides).
// Timings are never pass/fail; the only checks are that both problems are solved correctly
// (the plain one reproduces the linear field, the cracked one gets K_I).
#include <gtest/gtest.h>

#include <deal.II/base/multithread_info.h>

#include <cmath>
#include <iostream>
#include <string>

#include "metric.h"
#include "williams_problem.h"

using namespace pumpd;
using namespace pumpd::bench;

namespace
{
  struct Timing
  {
    double       setup = 0., assemble = 0., solve = 0.;
    double       total() const { return setup + assemble + solve; }
    unsigned int dofs = 0;
    double       check = 0.; ///< |K_I - 1| (cracked) or the relative energy error (plain)
  };

  /// u = A x: constant strain, constant stress (an equilibrium field without body force).
  geometry::Point linear_field(geometry::Point x)
  {
    return {0.01 * x.x + 0.002 * x.y, -0.003 * x.x + 0.005 * x.y};
  }

  Timing run_once(dealii::Triangulation<2> &tria, bool cracked)
  {
    const Williams     field{1, {1., 0.3, true}};
    EnrichmentSettings settings;
    settings.tip_radius = 0.3;
    EnrichedElasticity problem(tria, field.material, settings);
    if (cracked)
      {
        problem.set_crack(edge_crack());
        add_williams_boundary_data(problem, field);
      }
    else
      {
        problem.set_crack(std::nullopt);
        const SidedField u = [](geometry::Point x, int) { return linear_field(x); };
        for (unsigned int id = 1; id < 4; ++id)
          problem.add_dirichlet(id, u);
        // sigma = lambda tr(eps) I + 2 mu eps, n = (-1, 0) on the left edge.
        const double lambda = field.material.lambda(), mu = field.material.mu();
        const double exx = 0.01, eyy = 0.005, exy = 0.5 * (0.002 - 0.003);
        const double sxx = lambda * (exx + eyy) + 2. * mu * exx, sxy = 2. * mu * exy;
        problem.add_traction(0, [=](geometry::Point) { return geometry::Point{-sxx, -sxy}; });
      }
    Timing t;
    auto   start = std::chrono::steady_clock::now();
    problem.setup();
    t.setup = seconds_since(start);
    start   = std::chrono::steady_clock::now();
    problem.assemble();
    t.assemble = seconds_since(start);
    start      = std::chrono::steady_clock::now();
    problem.solve();
    t.solve = seconds_since(start);
    t.dofs  = problem.n_dofs();
    if (cracked)
      t.check = std::abs(problem.stress_intensity_factors().at(0).k1 - 1.);
    else
      {
        const auto err = problem.errors([](geometry::Point x, int) { return linear_field(x); },
                                        [](geometry::Point, int) { return std::array<double, 4>{{0.01, 0.002, -0.003, 0.005}}; });
        t.check = err.energy / err.energy_exact;
      }
    return t;
  }

  Timing run_median(unsigned int n, bool cracked, int repetitions)
  {
    dealii::Triangulation<2> tria;
    make_square(tria, n);
    std::vector<double> setup, assemble, solve, total;
    Timing              last;
    for (int rep = 0; rep < repetitions; ++rep)
      {
        last = run_once(tria, cracked);
        setup.push_back(last.setup);
        assemble.push_back(last.assemble);
        solve.push_back(last.solve);
        total.push_back(last.total());
      }
    Timing t = last;
    t.setup    = median(setup);
    t.assemble = median(assemble);
    t.solve    = median(solve);
    std::cout << n << " x " << n << (cracked ? " cracked: " : " plain:   ") << t.dofs << " dofs, setup " << t.setup
              << " s, assemble " << t.assemble << " s, solve " << t.solve << " s, total " << t.total()
              << " s (median total " << median(total) << " s over " << repetitions << ")"
              << (cracked ? ", |K_I - 1| " : ", energy error ") << t.check << std::endl;
    return t;
  }
} // namespace

TEST(GlobalEnrichmentCost, CrackedAgainstPlainOnTheSameMesh)
{
  dealii::MultithreadInfo::set_thread_limit(1);
  // The smaller mesh first: the trend with the mesh size.
  {
    const Timing plain = run_median(80, false, 5), cracked = run_median(80, true, 5);
    test::metric("global.enriched_over_plain_time_80", cracked.total() / plain.total());
    EXPECT_LT(plain.check, 1e-10);
    EXPECT_LT(cracked.check, 2e-3);
  }
  const Timing plain = run_median(160, false, 3), cracked = run_median(160, true, 3);
  test::metric("global.plain_dofs", plain.dofs);
  test::metric("global.enriched_dofs", cracked.dofs);
  test::metric("global.plain_time_s", plain.total());
  test::metric("global.enriched_time_s", cracked.total());
  test::metric("global.enriched_over_plain_time", cracked.total() / plain.total());
  test::metric("global.enriched_over_plain_setup", cracked.setup / plain.setup);
  test::metric("global.enriched_over_plain_assemble", cracked.assemble / plain.assemble);
  test::metric("global.enriched_over_plain_solve", cracked.solve / plain.solve);
  EXPECT_LT(plain.check, 1e-10);
  EXPECT_LT(cracked.check, 1e-3);
}
