// The junction function in the global problem (Daux et al. 2000). On the unit square, crack M runs
// from the left edge along y = 0.515 to a tip at x = 0.615; crack S comes down from the top edge
// along x = 0.315 and joins M's face at J = (0.315, 0.515). The two cut the block
// P = [0, 0.315] x [0.515, 1] off the body. The bottom edge is clamped and the top edge moved by
// (0, delta): P, held by its top edge only, translates rigidly by (0, delta), and below M nothing
// is cut along x = 0.315, so the displacement there is continuous.
// In the cell holding J, {1, H_M, J_S} span the three pieces' constants (P, right of S above M,
// below M), so P decouples from the rest exactly: tolerance 1e-8 delta on P's displacement. With
// S's Heaviside extended through M instead, the cell has four pieces for three functions and P is
// dragged by the rest. Below M, the displacement 2e-6 apart across x = 0.315 agrees within
// 1e-4 delta (a gradient of order delta / 0.5 gives 4e-6 delta).
// The mesh is the 20 x 20 square stretched by a smooth map, so that no crack runs along a mesh line.
// Prints pumpd-metric global.junction_block_rigid_err (the largest |u - (0, delta)| / delta in P)
// and global.junction_jump_below_over_delta.
#include <gtest/gtest.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>

#include "crack.h"
#include "elasticity.h"
#include "metric.h"

using namespace pumpd;
using namespace pumpd::global;

TEST(GlobalJunction, ACrackJoinedToAnotherCutsOffTheBlockBetweenThem)
{
  const double             pi = std::acos(-1.), delta = 1e-3;
  dealii::Triangulation<2> tria;
  dealii::GridGenerator::subdivided_hyper_rectangle(tria, {20, 20}, dealii::Point<2>(0., 0.), dealii::Point<2>(1., 1.),
                                                    true);
  dealii::GridTools::transform(
    [&](const dealii::Point<2> &p) {
      return dealii::Point<2>(p[0] + 0.013 * std::sin(pi * p[0]), p[1] + 0.011 * std::sin(pi * p[1]));
    },
    tria);

  const geometry::Body body{{0., 0., 1., 1.}, {}};
  const Crack          m({{0., 0.515}, {0.615, 0.515}}, body, 1e-12);
  Crack                s({{0.315, 1.}, {0.315, 0.7}}, body, 1e-12);
  s.join(0, {0.315, 0.515}, m);
  ASSERT_TRUE(s.tips().empty());

  EnrichmentSettings settings;
  settings.tip_radius = 0.12;
  EnrichedElasticity problem(tria, ElasticMaterial{1., 0.3, true}, settings);
  problem.set_cracks({m, s});
  problem.add_dirichlet(2, [](geometry::Point, int) { return geometry::Point{0., 0.}; });
  problem.add_dirichlet(3, [&](geometry::Point, int) { return geometry::Point{0., delta}; });
  problem.setup();
  problem.assemble();
  problem.solve();

  double rigid_err = 0., jump = 0.;
  for (const geometry::Point x : {geometry::Point{0.05, 0.55}, geometry::Point{0.31, 0.52}, geometry::Point{0.2, 0.9},
                                  geometry::Point{0.1, 0.99}})
    {
      const auto u = problem.displacement(x);
      rigid_err    = std::max(rigid_err, geometry::norm(u - geometry::Point{0., delta}) / delta);
      EXPECT_NEAR(u.x, 0., 1e-8 * delta) << "P at " << to_text(x);
      EXPECT_NEAR(u.y, delta, 1e-8 * delta) << "P at " << to_text(x);
    }
  const auto right = problem.displacement({0.32, 0.52});
  EXPECT_GT(geometry::norm(right - geometry::Point{0., delta}), 1e-3 * delta) << "right of S the body is strained";

  for (const double below : {0.002, 0.01, 0.03})
    {
      const auto left = problem.displacement({0.315 - 1e-6, 0.515 - below});
      const auto right_of_s = problem.displacement({0.315 + 1e-6, 0.515 - below});
      EXPECT_LT(geometry::norm(left - right_of_s), 1e-4 * delta) << below << " below M";
      jump = std::max(jump, geometry::norm(left - right_of_s) / delta);
    }
  test::metric("global.junction_block_rigid_err", rigid_err);
  test::metric("global.junction_jump_below_over_delta", jump);
}
