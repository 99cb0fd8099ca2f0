// The two linear solvers give the same enriched solution: CG + AMG (Trilinos ML, rigid-body
// near-null space) against UMFPACK on the edge-crack problem of the convergence test, with
// iterations and time reported. Tolerance: displacements and K_I agree to 1e-6 relative.
#include <gtest/gtest.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "elasticity.h"
#include "lefm.h"

using namespace pumpd;
using namespace pumpd::global;

TEST(Solvers, AmgMatchesDirect)
{
  int                                             argc = 1;
  char                                            name[] = "solver_test";
  char                                           *args[] = {name, nullptr};
  char                                          **argv   = args;
  static dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const ElasticMaterial material{1., 0.3, true};
  const geometry::Point tip{0.013, 0.};
  const SidedField      exact = [&](geometry::Point x, int side) {
    const geometry::Point rel = x - tip;
    const double          r   = std::max(geometry::norm(rel), 1e-300);
    const auto f = lefm::williams(1, r, side * std::acos(std::clamp(rel.x / r, -1., 1.)), material.mu(), material.kolosov());
    return geometry::Point{f.u[0], f.u[1]};
  };
  dealii::Triangulation<2> tria;
  dealii::GridGenerator::subdivided_hyper_rectangle(tria, {60, 60}, dealii::Point<2>(-1., -0.97),
                                                    dealii::Point<2>(1., 1.03), true);
  EnrichmentSettings settings;
  settings.tip_radius = 0.3;
  EnrichedElasticity problem(tria, material, settings);
  problem.set_crack(Crack({{-1., 0.}, tip}, geometry::Body{{-1., -0.97, 1., 1.03}, {}}, 1e-12));
  for (unsigned int id = 0; id < 4; ++id)
    problem.add_dirichlet(id, exact);
  problem.setup();
  problem.assemble();

  const std::vector<geometry::Point> probes = {{-0.5, 0.3}, {0.5, -0.2}, {-0.2, 1e-3}, {-0.2, -1e-3}, {0.9, 0.9}};
  const auto direct = problem.solve();
  std::vector<geometry::Point> u_direct;
  for (const auto &p : probes)
    u_direct.push_back(problem.displacement(p));
  const double k_direct = problem.stress_intensity_factors()[0].k1;

  SolverSettings amg;
  amg.type      = SolverSettings::Type::cg_amg;
  amg.tolerance = 1e-12;
  const auto iterative = problem.solve(amg);
  std::cout << problem.n_dofs() << " dofs (" << problem.n_enriched_dofs() << " enriched): " << direct.solver << " "
            << direct.seconds << " s; " << iterative.solver << " " << iterative.iterations << " iterations, "
            << iterative.seconds << " s\n";
  EXPECT_GT(iterative.iterations, 0u);
  double scale = 0.;
  for (const auto &u : u_direct)
    scale = std::max(scale, geometry::norm(u));
  for (std::size_t i = 0; i < probes.size(); ++i)
    EXPECT_LT(geometry::norm(problem.displacement(probes[i]) - u_direct[i]), 1e-6 * scale);
  EXPECT_NEAR(problem.stress_intensity_factors()[0].k1, k_direct, 1e-6 * std::abs(k_direct));
}
