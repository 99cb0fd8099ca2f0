// LEFM crack growth (coupling/lefm_growth.h):
// - the maximum hoop stress kink angle against closed values (pure mode I: 0; pure mode II:
//   -+2 atan(1/sqrt 2) = -+70.53 degrees for K_II >< 0) and against the textbook form;
// - the sign convention of the K_II that EnrichedElasticity::stress_intensity_factors returns:
//   the exact Williams field of (K_I, K_II) = (1, 0.5) about a slanted tip, imposed on a square,
//   gives K back in the frame (d, n = d rotated +90 degrees) whether the tip is the last or the
//   first polyline vertex; and a slanted edge crack under uniaxial tension (known loading) has
//   K_II > 0 and kinks back towards the plane normal to the load (theta_c < 0);
// - coarse Ingraffea Case I growth: the path stays in the body, grows by the increments, kinks
//   towards the load point (x increasing) first, and is clipped to the outline where it leaves;
// - a crack aimed straight at a hole stops `hole_margin` before the hole's circle;
// - a tip that joins another crack ends there (a junction) and the other crack's tips go on.
#include <gtest/gtest.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <iostream>

#include "elasticity.h"
#include "lefm.h"
#include "lefm_growth.h"
#include "scene_file.h"

using namespace pumpd;
using geometry::Point;

namespace
{
  const double pi      = std::acos(-1.);
  const double mode_ii = 2. * std::atan(1. / std::sqrt(2.)); // 70.53 degrees

  const std::string beam  = "meshes/ingraffea-beam.geo";
  const std::string holes = "meshes/ingraffea-beam-holes.geo";

  /// Coarse Ingraffea beam (cells of 16 mm, 8 mm in the crack band), no refinement, da = 8 mm.
  coupling::Parameters coarse(const std::string &mesh)
  {
    auto p                     = test::scene_file("tests/regression/ingraffea-case1-lefm-coarse.prm", "");
    p.scene.mesh_file          = mesh;
    p.lefm.halving_angle       = 0.;
    p.growth.max_crack_length  = 0.;
    return p;
  }

  coupling::LefmGrowthResult run(const coupling::Parameters &p)
  {
    return coupling::run_lefm_growth(coupling::build_scene(p.scene), p.lefm_growth_settings(), std::cout);
  }

  /// The square [-1, 1]^2, 40 x 40 cells, boundary ids 0 left, 1 right, 2 bottom, 3 top.
  void square(dealii::Triangulation<2> &tria)
  {
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {40, 40}, dealii::Point<2>(-1., -1.),
                                                      dealii::Point<2>(1., 1.), true);
  }
} // namespace

TEST(LefmGrowth, KinkAngleClosedValues)
{
  EXPECT_EQ(coupling::kink_angle(1., 0.), 0.);
  EXPECT_NEAR(coupling::kink_angle(0., 1.), -mode_ii, 1e-14);
  EXPECT_NEAR(coupling::kink_angle(0., -1.), mode_ii, 1e-14);
  EXPECT_NEAR(mode_ii * 180. / pi, 70.5288, 1e-4);
  for (const auto &[k1, k2] : {std::pair{1., 0.3}, {2., -0.7}, {0.4, 1.5}, {1e6, 3e4}})
    {
      const double textbook = 2. * std::atan((k1 - std::sqrt(k1 * k1 + 8. * k2 * k2)) / (4. * k2));
      EXPECT_NEAR(coupling::kink_angle(k1, k2), textbook, 1e-13) << k1 << ", " << k2;
      EXPECT_EQ(coupling::kink_angle(k1, -k2), -coupling::kink_angle(k1, k2));
    }
  // Small K_II: theta_c = -2 K_II / K_I + O((K_II / K_I)^3), without cancellation.
  EXPECT_NEAR(coupling::kink_angle(1., 1e-9), -2e-9, 1e-20);
}

TEST(LefmGrowth, SifSignConventionFromWilliamsField)
{
  const double k1 = 1., k2 = 0.5, beta = pi / 6.;
  const Point  d{std::cos(beta), std::sin(beta)}, n{-d.y, d.x};
  const Point  tip{0.013, 0.27};
  const Point  mouth = tip - ((tip.x + 1.) / d.x) * d; // on the left edge
  const global::ElasticMaterial material{1., 0.3, true};

  // The exact field in global components: (R^T u', R^T sigma' R) with the rows of R = (d, n);
  // theta from the crack side, as the solver's auxiliary fields.
  const auto field = [&](Point x, int side, std::array<double, 2> &u, std::array<double, 3> &s) {
    const Point  rel = x - tip;
    const double r   = std::max(geometry::norm(rel), 1e-300);
    const double th  = side * std::acos(std::clamp(geometry::dot(rel, d) / r, -1., 1.));
    const auto   f1  = lefm::williams(1, r, th, material.mu(), material.kolosov());
    const auto   f2  = lefm::williams(2, r, th, material.mu(), material.kolosov());
    const double ux = k1 * f1.u[0] + k2 * f2.u[0], uy = k1 * f1.u[1] + k2 * f2.u[1];
    u = {{ux * d.x + uy * n.x, ux * d.y + uy * n.y}};
    double sl[2][2];
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        sl[i][j] = k1 * f1.stress[i][j] + k2 * f2.stress[i][j];
    const double e[2][2] = {{d.x, n.x}, {d.y, n.y}}; // columns: d, n
    double       sg[2][2] = {};
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b)
        for (int i = 0; i < 2; ++i)
          for (int j = 0; j < 2; ++j)
            sg[a][b] += e[a][i] * sl[i][j] * e[b][j];
    s = {{sg[0][0], sg[1][1], sg[0][1]}};
  };

  for (const bool tip_last : {true, false})
    {
      dealii::Triangulation<2> tria;
      square(tria);
      global::EnrichmentSettings settings;
      settings.tip_radius = 0.3;
      global::EnrichedElasticity problem(tria, material, settings);
      const geometry::Body body{{-1., -1., 1., 1.}, {}};
      problem.set_crack(global::Crack(tip_last ? geometry::Polyline{mouth, tip} : geometry::Polyline{tip, mouth},
                                      body, 1e-12));
      for (unsigned int id = 1; id < 4; ++id)
        problem.add_dirichlet(id, [&](Point x, int) { // the crack does not reach these edges
          std::array<double, 2> u;
          std::array<double, 3> s;
          field(x, geometry::dot(x - tip, n) >= 0. ? 1 : -1, u, s);
          return Point{u[0], u[1]};
        });
      // The edge with the mouth carries the exact traction sigma (-1, 0).
      problem.add_traction(0, [&](Point x) {
        std::array<double, 2> u;
        std::array<double, 3> s;
        field(x, geometry::dot(x - tip, n) >= 0. ? 1 : -1, u, s);
        return Point{-s[0], -s[2]};
      });
      problem.setup();
      problem.assemble();
      problem.solve();
      const auto sif = problem.stress_intensity_factors();
      ASSERT_EQ(sif.size(), 1u);
      std::cout << "tip at the " << (tip_last ? "last" : "first") << " vertex: K_I " << sif[0].k1 << ", K_II "
                << sif[0].k2 << " (imposed 1, 0.5)\n";
      EXPECT_NEAR(sif[0].k1, k1, 0.03);
      EXPECT_NEAR(sif[0].k2, k2, 0.03);
    }
}

TEST(LefmGrowth, SlantedEdgeCrackUnderTensionKinksTowardsTheNormalPlane)
{
  // Edge crack from the left edge at 30 degrees above the x axis; sigma_yy = 1 on top and bottom.
  const double beta = pi / 6.;
  const Point  mouth{-1., -0.3}, d{std::cos(beta), std::sin(beta)};
  dealii::Triangulation<2> tria;
  square(tria);
  global::EnrichmentSettings settings;
  settings.tip_radius = 0.15;
  global::EnrichedElasticity problem(tria, {1., 0.3, true}, settings);
  problem.set_crack(global::Crack({mouth, mouth + 0.6 * d}, {{-1., -1., 1., 1.}, {}}, 1e-12));
  problem.add_traction(3, [](Point) { return Point{0., 1.}; });
  problem.add_traction(2, [](Point) { return Point{0., -1.}; });
  problem.add_dirichlet_vertex({1., -1.}, {0., 0.}, true, true);
  problem.add_dirichlet_vertex({1., 1.}, {0., 0.}, true, false);
  problem.setup();
  problem.assemble();
  problem.solve();
  const auto sif = problem.stress_intensity_factors();
  ASSERT_EQ(sif.size(), 1u);
  const double theta = coupling::kink_angle(sif[0].k1, sif[0].k2);
  std::cout << "slanted edge crack: K_I " << sif[0].k1 << ", K_II " << sif[0].k2 << ", theta_c "
            << theta * 180. / pi << " deg\n";
  EXPECT_GT(sif[0].k1, 0.);
  EXPECT_GT(sif[0].k2, 0.1 * sif[0].k1);
  // Towards -n: the new direction beta + theta_c lies between 0 and beta.
  EXPECT_LT(theta, 0.);
  EXPECT_GT(beta + theta, 0.);
}

TEST(LefmGrowth, CoarseCaseIPathGrowsByIncrementsTowardsTheLoad)
{
  auto p           = coarse(beam);
  p.lefm.max_steps = 4;
  const auto r     = run(p);
  EXPECT_EQ(r.increments, 4u);
  EXPECT_EQ(r.steps.size(), 5u); // 4 growth steps and the solve of the final crack
  EXPECT_EQ(r.stop_reason, "maximum steps");
  ASSERT_EQ(r.path.size(), 6u);
  EXPECT_NEAR(geometry::length(r.path), 0.0254 + 4 * 0.008, 1e-12);
  for (std::size_t k = 2; k < r.path.size(); ++k)
    EXPECT_NEAR(geometry::norm(r.path[k] - r.path[k - 1]), 0.008, 1e-12);
  for (const auto &x : r.path)
    {
      EXPECT_TRUE(x.x >= 0. && x.x <= 0.508 && x.y >= 0. && x.y <= 0.2032) << x.x << ", " << x.y;
    }
  // The first kink turns the vertical crack towards the load point at x = 0.254: K_II > 0 in
  // the frame (d, n) = ((0, 1), (-1, 0)), theta_c < 0, x increases.
  EXPECT_GT(r.steps[0].k1, 0.);
  EXPECT_GT(r.steps[0].k2, 0.);
  EXPECT_LT(r.steps[0].kink_angle, -5. * pi / 180.);
  EXPECT_GT(r.path[2].x, r.path[1].x + 0.001);
  for (std::size_t k = 3; k < r.path.size(); ++k)
    EXPECT_GT(r.path[k].x, r.path[k - 1].x);
}

TEST(LefmGrowth, CoarseCaseIIsClippedToTheOutline)
{
  auto p                  = coarse(beam);
  p.lefm.growth_increment = 0.016;
  const auto r            = run(p);
  EXPECT_NE(r.stop_reason.find("reached the outline"), std::string::npos) << r.stop_reason;
  EXPECT_NE(r.stop_reason.find("cut the body through"), std::string::npos) << r.stop_reason;
  EXPECT_NEAR(r.path.back().y, 0.2032, 1e-12); // on the top edge
  EXPECT_GT(r.path.back().x, 0.1016);
  EXPECT_LT(r.path.back().x, 0.254);
}

TEST(LefmGrowth, CrackAimedAtAHoleStopsBeforeIt)
{
  // Vertical crack below the lowest hole (centre (0.1524, 0.06985), radius 0.00635).
  auto p                    = coarse(holes);
  p.scene.initial_cracks    = "0.1524,0; 0.1524,0.045";
  p.lefm.growth_increment   = 0.006;
  p.growth.hole_margin      = 0.001;
  const auto r              = run(p);
  const Point  centre{0.1524, 0.06985};
  const double radius = 0.00635;
  EXPECT_NE(r.stop_reason.find("before a hole"), std::string::npos) << r.stop_reason;
  EXPECT_NE(r.stop_reason.find("no tip grows"), std::string::npos) << r.stop_reason;
  EXPECT_LT(r.increments, 5u);
  // The tip stops on the circle of radius r + margin (the mesh's hole, a polygon inscribed in
  // the circle of radius r, is further away), and no segment enters the hole.
  EXPECT_NEAR(geometry::norm(r.path.back() - centre), radius + p.growth.hole_margin, 2e-5);
  for (std::size_t k = 1; k < r.path.size(); ++k)
    EXPECT_GT(geometry::distance_to_segment(centre, r.path[k - 1], r.path[k]), radius + 0.5 * p.growth.hole_margin);
}

// The coarse Case I beam's notch below a horizontal interior crack 21 mm above its tip (beyond the
// tip enrichment radius), along the bending stress and so hardly opened by it. With da = 16 mm the
// face lies within the look-ahead of the notch's first increment: the notch joins it; the body
// stays whole, and the notch, opening, now wedges the interior crack open, so its tips go on
// growing from the junction-enriched solution until the step limit.
TEST(LefmGrowth, TheOtherTipsGoOnAfterAJoin)
{
  auto p                  = coarse(beam);
  p.scene.initial_cracks  = "0.1016,0; 0.1016,0.0254 | 0.07,0.0464; 0.13,0.0464";
  p.lefm.growth_increment = 0.016;
  p.lefm.max_steps        = 8;
  const auto r            = run(p);
  ASSERT_EQ(r.paths.size(), 2u);
  EXPECT_TRUE(r.joined);
  EXPECT_NE(r.stop_reason.find("joined crack 2"), std::string::npos) << r.stop_reason;
  EXPECT_EQ(r.stop_reason.find("cut the body through"), std::string::npos) << r.stop_reason;
  const geometry::Polyline &notch = r.paths[0], &interior = r.paths[1];
  double gap = 1.;
  for (std::size_t k = 1; k < interior.size(); ++k)
    gap = std::min(gap, geometry::distance_to_segment(notch.back(), interior[k - 1], interior[k]));
  EXPECT_LT(gap, 1e-9) << "the notch ends on the interior crack's face";
  std::size_t joined_at = 0, interior_growth_after = 0;
  for (const auto &st : r.steps)
    if (st.crack == 0 && st.increment > 0.)
      joined_at = st.step;
  for (const auto &st : r.steps)
    interior_growth_after += st.crack == 1 && st.step > joined_at && st.increment > 0.;
  EXPECT_GE(interior_growth_after, 2u) << "the interior crack grows after the join";
  EXPECT_GT(geometry::length(interior), 0.06 + 2 * 0.004);
}

// The same T given at set-up (the notch ends on the interior crack's face): the end is a junction,
// not a tip, so the first solve has the interior crack's two tips only, and the body is whole.
TEST(LefmGrowth, ATGivenAtSetUpIsAJunction)
{
  auto p                 = coarse(beam);
  p.scene.initial_cracks = "0.1016,0; 0.1016,0.0464 | 0.07,0.0464; 0.13,0.0464";
  p.lefm.max_steps       = 2;
  const auto r           = run(p);
  std::size_t first = 0;
  for (const auto &st : r.steps)
    if (st.step == 0)
      {
        ++first;
        EXPECT_EQ(st.crack, 1u);
      }
  EXPECT_EQ(first, 2u);
  EXPECT_EQ(r.stop_reason.find("cut the body through"), std::string::npos) << r.stop_reason;
  EXPECT_GT(r.increments, 0u);
}
