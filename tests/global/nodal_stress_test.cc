// The recovered nodal stress (EnrichedElasticity::nodal_stresses): each cell's 2 x 2 Gauss point
// stresses extrapolated bilinearly to its corners, averaged at each vertex.
//
// On rectangles the bilinear field u = (x y, 0) lies in the Q1 space, so the discrete solution
// with u prescribed on the boundary and the body force that balances it is u itself:
//   eps = [[y, x/2], [x/2, 0]],  sigma_xx = (lambda + 2 mu) y,  sigma_yy = lambda y,  sigma_xy = mu x,
//   div sigma + f = 0  =>  f = (0, -(lambda + mu)).
// Its stress is linear, bilinear in each cell's reference coordinates: the extrapolation gives it
// exactly at every vertex, on the boundary and at hanging vertices (the mesh refined around a
// point) too, where the cells' centre values or plain Gauss-point averages would be off by half a
// cell's gradient. Tolerance: 1e-9 of the largest stress (round-off of the solve).
#include <gtest/gtest.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "elasticity.h"
#include "refinement.h"

using namespace pumpd;
using namespace pumpd::global;

TEST(NodalStress, LinearFieldExactAtEveryVertex)
{
  dealii::Triangulation<2> tria;
  dealii::GridGenerator::subdivided_hyper_rectangle(tria, {8u, 4u}, dealii::Point<2>(0., 0.), dealii::Point<2>(2., 1.),
                                                    true);
  refine_near(tria, {{0.9, 0.4}}, 0.3, 2); // hanging vertices
  const ElasticMaterial material{1e3, 0.25, true};
  const double          lambda = material.lambda(), mu = material.mu();
  EnrichedElasticity    problem(tria, material, EnrichmentSettings{});
  for (unsigned int id = 0; id < 4; ++id)
    problem.add_dirichlet(id, [](geometry::Point x, int) { return geometry::Point{x.x * x.y, 0.}; });
  problem.set_body_force([&](geometry::Point) { return geometry::Point{0., -(lambda + mu)}; });
  problem.setup();
  problem.assemble();
  problem.solve();

  const auto   stress = problem.nodal_stresses();
  const double scale  = (lambda + 2. * mu) * 1.;
  double       worst  = 0.;
  for (const auto &s : stress)
    {
      worst = std::max({worst, std::abs(s.xx - (lambda + 2. * mu) * s.at.y), std::abs(s.yy - lambda * s.at.y),
                        std::abs(s.xy - mu * s.at.x)});
      EXPECT_GT(s.cell_size, 0.);
    }
  EXPECT_EQ(stress.size(), tria.n_used_vertices());
  EXPECT_LT(worst, 1e-9 * scale);

  problem.set_crack(Crack({{0., 0.5}, {0.5, 0.5}}, {{0., 0., 2., 1.}, {}}, 1e-12));
  EXPECT_THROW(problem.nodal_stresses(), std::logic_error);
}
