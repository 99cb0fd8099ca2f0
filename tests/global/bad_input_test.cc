// Validation 7 of the global solver: bad input is refused with a clear pumpd::InvalidParameter
// whose what() names the parameter ("<name> = <value>: <allowed>", local/error.h). Checked: the
// exception type and that what() contains the parameter's name, for a crack outside the body, a
// crack vertex outside the mesh (inside the given body), a self-intersecting crack, a missing mesh
// file, a missing boundary id (mesh check and Dirichlet condition), a tip enrichment radius smaller
// than the cell at the tip, Poisson's ratio 0.5, a negative Young's modulus, a point load and a
// Dirichlet vertex that are not mesh vertices, and an evaluation point outside the mesh.
#include <gtest/gtest.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <functional>
#include <iostream>
#include <string>

#include "elasticity.h"
#include "error.h"
#include "mesh.h"

using namespace pumpd;
using namespace pumpd::global;

namespace
{
  const geometry::Body unit_body{{0., 0., 1., 1.}, {}};

  /// what() of the InvalidParameter that f throws; "no exception" / "other exception: ...".
  std::string invalid_parameter(const std::function<void()> &f)
  {
    try
      {
        f();
      }
    catch (const InvalidParameter &e)
      {
        return e.what();
      }
    catch (const std::exception &e)
      {
        return std::string("other exception: ") + e.what();
      }
    catch (...)
      {
        return "other exception";
      }
    return "no exception";
  }

  /// Expects f to throw InvalidParameter with `name` in what(); prints the message.
  void expect_refused(const std::string &what_case, const std::function<void()> &f, const std::string &name)
  {
    const std::string message = invalid_parameter(f);
    std::cout << what_case << ": " << message << "\n";
    EXPECT_NE(message.find(name), std::string::npos) << what_case << ": expected InvalidParameter naming \"" << name
                                                     << "\", got: " << message;
    EXPECT_EQ(message.rfind("other exception", 0), std::string::npos) << what_case;
    EXPECT_NE(message, "no exception") << what_case;
  }

  /// The unit square, 10 x 10 cells (h = 0.1), boundary ids 0 left, 1 right, 2 bottom, 3 top.
  void unit_square(dealii::Triangulation<2> &tria)
  {
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {10, 10}, dealii::Point<2>(0., 0.), dealii::Point<2>(1., 1.),
                                                      true);
  }

  /// A well-posed problem on the unit square: edge crack from (0, 0.53) to (0.47, 0.53), bottom
  /// fixed, top pulled; tip radius 0.3.
  void well_posed(EnrichedElasticity &problem)
  {
    problem.set_crack(Crack({{0., 0.53}, {0.47, 0.53}}, unit_body, 1e-12));
    problem.add_dirichlet(2, [](geometry::Point, int) { return geometry::Point{0., 0.}; });
    problem.add_traction(3, [](geometry::Point) { return geometry::Point{0., 1.}; });
  }

  EnrichmentSettings tip_radius(double r)
  {
    EnrichmentSettings s;
    s.tip_radius = r;
    return s;
  }
} // namespace

TEST(GlobalBadInput, TheWellPosedProblemRuns)
{
  // The baseline the other cases perturb: no exception.
  dealii::Triangulation<2> tria;
  unit_square(tria);
  EnrichedElasticity problem(tria, {1., 0.3, true}, tip_radius(0.3));
  well_posed(problem);
  problem.add_point_load({1., 1.}, {0.1, 0.});
  problem.add_dirichlet_vertex({1., 0.}, {0., 0.});
  EXPECT_EQ(invalid_parameter([&] {
              problem.setup();
              problem.assemble();
              problem.solve();
              problem.prepare_point_evaluation({{0.5, 0.5}, {0.9, 0.1}});
            }),
            "no exception");
}

TEST(GlobalBadInput, CrackOutsideTheBody)
{
  expect_refused("crack vertex outside the body outline",
                 [] { Crack c({{0., 0.5}, {1.2, 0.5}}, unit_body, 1e-12); }, "Crack");
  // The body given to the crack is larger than the mesh: the crack is valid geometry, but its tip
  // lies outside the mesh.
  dealii::Triangulation<2> tria;
  unit_square(tria);
  EnrichedElasticity problem(tria, {1., 0.3, true}, tip_radius(0.3));
  problem.set_crack(Crack({{0., 0.5}, {1.5, 0.5}}, geometry::Body{{0., 0., 2., 1.}, {}}, 1e-12));
  problem.add_dirichlet(2, [](geometry::Point, int) { return geometry::Point{0., 0.}; });
  expect_refused("crack vertex outside the mesh", [&] { problem.setup(); }, "Crack vertex");
}

TEST(GlobalBadInput, SelfIntersectingCrack)
{
  expect_refused("self-intersecting polyline",
                 [] { Crack c({{0.2, 0.2}, {0.8, 0.8}, {0.8, 0.2}, {0.2, 0.8}}, unit_body, 1e-12); }, "Crack");
  expect_refused("polyline folding back onto itself",
                 [] { Crack c({{0.2, 0.5}, {0.8, 0.5}, {0.4, 0.5}}, unit_body, 1e-12); }, "Crack");
}

TEST(GlobalBadInput, MissingMeshFile)
{
  dealii::Triangulation<2> tria;
  expect_refused("nonexistent mesh file", [&] { read_mesh("/nonexistent/pumpd-no-such-mesh.msh", tria); },
                 "Mesh file");
}

TEST(GlobalBadInput, MissingBoundaryId)
{
  dealii::Triangulation<2> tria;
  unit_square(tria);

  EnrichedElasticity problem(tria, {1., 0.3, true}, tip_radius(0.3));
  well_posed(problem);
  problem.add_dirichlet(7, [](geometry::Point, int) { return geometry::Point{0., 0.}; });
  expect_refused("Dirichlet condition on boundary id 7", [&] { problem.setup(); }, "Dirichlet boundary id");

  EnrichedElasticity region(tria, {1., 0.3, true}, tip_radius(0.3));
  well_posed(region);
  region.add_dirichlet_region(9, [](geometry::Point) { return geometry::Point{0., 0.}; });
  expect_refused("Dirichlet condition on material id 9", [&] { region.setup(); }, "Dirichlet region");
}

TEST(GlobalBadInput, TipRadiusSmallerThanTheTipCell)
{
  // Cell diameter 0.1 sqrt(2) = 0.141 at the tip.
  dealii::Triangulation<2> tria;
  unit_square(tria);
  EnrichedElasticity problem(tria, {1., 0.3, true}, tip_radius(0.1));
  well_posed(problem);
  expect_refused("tip radius 0.1 < cell diameter 0.141", [&] { problem.setup(); }, "Tip enrichment radius");
}

TEST(GlobalBadInput, MaterialOutOfRange)
{
  dealii::Triangulation<2> tria;
  unit_square(tria);
  expect_refused("Poisson's ratio 0.5", [&] { EnrichedElasticity p(tria, {1., 0.5, true}, tip_radius(0.3)); },
                 "Poisson's ratio");
  expect_refused("Poisson's ratio 0.6", [&] { EnrichedElasticity p(tria, {1., 0.6, false}, tip_radius(0.3)); },
                 "Poisson's ratio");
  expect_refused("negative Young's modulus", [&] { EnrichedElasticity p(tria, {-1., 0.3, true}, tip_radius(0.3)); },
                 "Young's modulus");
  expect_refused("zero Young's modulus", [&] { EnrichedElasticity p(tria, {0., 0.3, true}, tip_radius(0.3)); },
                 "Young's modulus");
}

TEST(GlobalBadInput, PointLoadAndDirichletVertexNotAtAVertex)
{
  {
    dealii::Triangulation<2> tria;
    unit_square(tria);
    EnrichedElasticity problem(tria, {1., 0.3, true}, tip_radius(0.3));
    well_posed(problem);
    problem.add_point_load({0.95, 1.}, {0., 1.}); // on the top edge, between two vertices
    problem.setup();
    // Point loads are applied (and checked) in assemble().
    expect_refused("point load between vertices", [&] { problem.assemble(); }, "Point load");
  }
  {
    dealii::Triangulation<2> tria;
    unit_square(tria);
    EnrichedElasticity problem(tria, {1., 0.3, true}, tip_radius(0.3));
    well_posed(problem);
    problem.add_dirichlet_vertex({1., 0.05}, {0., 0.}); // on the right edge, between two vertices
    expect_refused("Dirichlet vertex between vertices", [&] { problem.setup(); }, "Dirichlet vertex");
  }
}

TEST(GlobalBadInput, EvaluationPointOutsideTheMesh)
{
  dealii::Triangulation<2> tria;
  unit_square(tria);
  EnrichedElasticity problem(tria, {1., 0.3, true}, tip_radius(0.3));
  well_posed(problem);
  problem.setup();
  problem.assemble();
  problem.solve();
  expect_refused("evaluation point (1.5, 0.5)",
                 [&] { problem.prepare_point_evaluation({{0.5, 0.5}, {1.5, 0.5}}); }, "Evaluation point");
}
