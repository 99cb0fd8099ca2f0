// The scene reader (coupling/scene.h) and the global adapter (global/global_conditions.h) on
// scenes with exact answers: the Ingraffea beam read from its scene file (named places, the point
// force per unit load, the body); a plate in uniaxial tension, whose Q1 solution is exact (the
// mean displacement of the loaded edge and the reaction of the supported one, as the report
// reads them); expressions of x, y and lambda, checked between the vertices too; a named region
// held by its cells.
#include <gtest/gtest.h>

#include <deal.II/grid/tria.h>

#include <cmath>

#include "elasticity.h"
#include "error.h"
#include "global_conditions.h"
#include "scene.h"
#include "scene_file.h"

using namespace pumpd;
using namespace pumpd::coupling;

namespace
{
  SceneSettings plate(const std::string &displacement, const std::string &traction)
  {
    SceneSettings s;
    s.mesh_file    = "tests/coupling/plate.geo";
    s.displacement = displacement;
    s.traction     = traction;
    s.material     = {1e3, 0.25, 1., 1., true};
    return s;
  }

  /// The plate's problem under the scene's conditions at lambda, solved without a crack.
  struct Solved
  {
    dealii::Triangulation<2>                    tria;
    std::unique_ptr<global::EnrichedElasticity> problem;
    Solved(const Scene &scene, double lambda)
    {
      tria.copy_triangulation(*scene.mesh);
      problem = std::make_unique<global::EnrichedElasticity>(
        tria, global::ElasticMaterial{scene.material.youngs_modulus, scene.material.poisson_ratio, true},
        global::EnrichmentSettings{});
      global::apply(scene.conditions, *problem, lambda);
      problem->setup();
      problem->assemble();
      problem->solve();
    }
  };
} // namespace

TEST(Scene, ReadsTheIngraffeaBeam)
{
  const Scene scene = build_scene(test::scene_file("prm/ingraffea-case2.prm", "").scene);
  ASSERT_EQ(scene.conditions.displacements.size(), 2u);
  const auto &pin = scene.conditions.displacements[0], &roller = scene.conditions.displacements[1];
  EXPECT_EQ(pin.place.name, "pin");
  EXPECT_EQ(pin.place.kind, conditions::Place::Kind::point);
  EXPECT_TRUE(pin.ux && pin.uy);
  EXPECT_TRUE(!roller.ux && roller.uy);
  ASSERT_EQ(scene.conditions.forces.size(), 1u);
  EXPECT_EQ(scene.conditions.forces[0].force.x, 0.);
  EXPECT_EQ(scene.conditions.forces[0].force.y, -1.); // fy = -lambda: per unit load factor
  ASSERT_EQ(scene.conditions.forces[0].place.points.size(), 1u);
  EXPECT_EQ(scene.conditions.forces[0].place.points[0].x, 0.254);
  EXPECT_EQ(scene.body.holes().size(), 3u);
  ASSERT_EQ(scene.cracks.size(), 1u);
  EXPECT_EQ(scene.crack().size(), 2u);
  EXPECT_FALSE(scene.report.work_conjugate);
  EXPECT_EQ(scene.report.displacement_place.name, "load");
  EXPECT_EQ(scene.report.displacement_sign, -1.);
}

// sigma_yy = lambda on the top edge, bottom on rollers, the left edge on rollers: uniform stress,
// u_y(top) = lambda H (1 - nu^2) / E in plane strain, the bottom's reaction -lambda W.
TEST(Scene, PlateInUniaxialTension)
{
  auto settings                = plate("bottom: uy = 0; left: ux = 0", "top: ty = lambda");
  settings.report_load         = "bottom: fy";
  settings.report_displacement = "top: uy";
  const Scene  scene           = build_scene(settings);
  const double lambda = 3., E = 1e3, nu = 0.25, H = 0.5, W = 1.;
  const Solved s(scene, lambda);
  const auto   u = s.problem->mean_displacement(scene.report.displacement_place.id);
  const auto   f = s.problem->reaction(scene.report.load_place.id);
  EXPECT_NEAR(u.y, lambda * H * (1. - nu * nu) / E, 1e-12);
  EXPECT_NEAR(f.y, -lambda * W, 1e-10);
  EXPECT_NEAR(f.x, 0., 1e-10);
  // The strain energy: U = 1/2 sigma eps W H, and 2 U / lambda the work-conjugate displacement.
  EXPECT_NEAR(2. * s.problem->strain_energy() / lambda, lambda * W * H * (1. - nu * nu) / E, 1e-12);
}

// The same tension from a pressure on the top edge (t = -p n, n = +y there): p = -lambda.
TEST(Scene, PressureIsATractionAgainstTheNormal)
{
  const Scene  scene = build_scene(plate("bottom: uy = 0; left: ux = 0", "top: p = -lambda"));
  const Solved s(scene, 2.);
  EXPECT_NEAR(s.problem->displacement({0.5, 0.5}).y, 2. * 0.5 * (1. - 0.0625) / 1e3, 1e-12);
}

// Expressions of x, y and lambda, per unit lambda; a region of cells held by its nodes.
TEST(Scene, ExpressionsAndRegions)
{
  const Scene scene = build_scene(plate("plate: ux = lambda * 1e-3 * (1 + y), uy = -2e-3 * lambda * x", ""));
  ASSERT_EQ(scene.conditions.displacements.size(), 1u);
  const auto &d = scene.conditions.displacements[0];
  EXPECT_EQ(d.place.kind, conditions::Place::Kind::region);
  EXPECT_DOUBLE_EQ((*d.ux)({0.3, 0.5}), 1.5e-3);
  EXPECT_DOUBLE_EQ((*d.uy)({0.3, 0.5}), -6e-4);
  EXPECT_TRUE(d.place.inside({0.3, 0.2}));
  EXPECT_FALSE(d.place.inside({1.3, 0.2}));
  const Solved s(scene, 2.);
  EXPECT_NEAR(s.problem->displacement({0.55, 0.25}).x, 2e-3 * 1.25, 1e-14);
  EXPECT_NEAR(s.problem->displacement({0.55, 0.25}).y, -4e-3 * 0.55, 1e-14);
}

// A field is checked where the methods take it, not only at the vertices: a lambda^2 term that
// vanishes at every vertex and edge of the plate's 0.1 m cells shows inside a region's cells; one
// that vanishes on a boundary but not beside it shows in the cells along it for a displacement (full
// PD's nodes in a band there), not for a traction (the global problem takes it on the faces only).
TEST(Scene, ExpressionsAreCheckedBetweenTheVertices)
{
  const auto refusal = [](const SceneSettings &s) -> std::string {
    try
      {
        build_scene(s);
      }
    catch (const InvalidParameter &e)
      {
        return e.what();
      }
    return "(accepted)";
  };
  const std::string periodic = "1e-3 * lambda + 1e-3 * lambda^2 * sin(10 * pi * x) * sin(10 * pi * y)";
  EXPECT_NE(refusal(plate("plate: ux = " + periodic, "")).find(
              "ux must be proportional to the load factor lambda (the methods scale the whole loading with it): at "),
            std::string::npos);
  EXPECT_NE(refusal(plate("plate: ux = " + periodic, "")).find("the centre of a cell of plate"), std::string::npos);

  const std::string beside_top = "lambda * (1 + lambda * (0.5 - y))";
  const std::string displaced  = refusal(plate("bottom: uy = 0; left: ux = 0; top: uy = 1e-3 * " + beside_top, ""));
  EXPECT_NE(displaced.find("Displacement = top: uy = 1e-3 * " + beside_top + ": uy must be proportional"), std::string::npos)
    << displaced;
  EXPECT_NE(displaced.find("cell"), std::string::npos) << displaced;
  EXPECT_EQ(refusal(plate("bottom: uy = 0; left: ux = 0", "top: ty = " + beside_top)), "(accepted)");

  // Not finite between the vertices at x = 0.3 and 0.4 of the top edge (8 Gauss points per face).
  const std::string gap = refusal(plate("bottom: uy = 0; left: ux = 0", "top: ty = lambda * sqrt(abs(x - 0.35) - 0.04)"));
  EXPECT_NE(gap.find("Traction = top: ty = lambda * sqrt(abs(x - 0.35) - 0.04): ty must be finite wherever the methods "
                     "take it (on and about its place): at (0.3"),
            std::string::npos)
    << gap;
  EXPECT_NE(gap.find("of a face of top, it is -nan"), std::string::npos) << gap;
}
