// Scenes whose cracks grow into the places of their conditions, run at their defaults: a PD box
// that takes in a load point, a support, a held edge or a loaded arc holds the nodes within a
// horizon of it to the global displacement (held_places, boundary_transfer.h), and a tip within
// Clearance over horizon finest horizons of such a place grows by LEFM (the last ligament).
// - SENS square (prm/sens.prm): the cycle's crack runs down to the held bottom edge and cuts the
//   body through, as LEFM growth's does; the two paths within 2 mm of each other (mean distance
//   over the shorter one, scene.sens.gl_vs_lefm_mean_mm).
// - Brazilian disc (prm/brazilian-disc.prm): the interior crack that forms at the centre grows
//   at both tips along the loaded diameter towards the arcs, at least 80 % of the diameter long
//   (initiation.disc.gl_length_over_diameter), its ends within 5 horizons of the diameter.
// - Unnotched beam (prm/unnotched-beam.prm): the crack that forms at mid-span rises under the
//   load point, held in the last boxes, to at least 85 % of the depth
//   (initiation.beam.gl_depth_over_height), within a horizon of mid-span.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include "global_local.h"
#include "lefm_growth.h"
#include "metric.h"
#include "nucleation.h"
#include "path_metrics.h"
#include "scene_file.h"

using namespace pumpd;

namespace
{
  bool contains(const std::string &text, const std::string &part) { return text.find(part) != std::string::npos; }
} // namespace

TEST(HeldPlaces, SensCrackCutsThroughToTheHeldEdgeAsLefmGrowthDoes)
{
  const auto p     = test::scene_file("prm/sens.prm", "held_sens");
  const auto scene = coupling::build_scene(p.scene);
  const auto cycle = coupling::run_global_local(scene, p.global_local_settings(), std::cout);
  std::ostringstream lefm_log;
  const auto         lefm = coupling::run_lefm_growth(scene, p.lefm_growth_settings(), lefm_log);
  EXPECT_TRUE(contains(cycle.stop_reason, "reached the outline")) << cycle.stop_reason;
  EXPECT_TRUE(contains(lefm.stop_reason, "reached the outline")) << lefm.stop_reason;
  EXPECT_NEAR(cycle.path.back().y, 0., 1e-9);
  const double mean = coupling::trade_distance(cycle.path, lefm.path).mean;
  std::cout << "ends: cycle " << geometry::to_text(cycle.path.back()) << ", LEFM " << geometry::to_text(lefm.path.back())
            << "\n";
  test::metric("scene.sens.gl_vs_lefm_mean_mm", 1e3 * mean);
  test::metric("scene.sens.gl_end_x_mm", 1e3 * cycle.path.back().x);
  test::metric("scene.sens.lefm_end_x_mm", 1e3 * lefm.path.back().x);
  EXPECT_LT(mean, 0.002);
}

TEST(HeldPlaces, DiscCrackGrowsAlongTheLoadedDiameterTowardsTheArcs)
{
  const auto   p        = test::scene_file("prm/brazilian-disc.prm", "held_disc");
  const auto   scene    = coupling::build_scene(p.scene);
  const double diameter = 0.1;
  const auto   r = coupling::run_global_local_from_initiation(scene, p.global_local_settings(), p.initiation, std::cout);
  ASSERT_EQ(r.paths.size(), 1u);
  const auto &path = r.paths[0];
  std::cout << "stop: " << r.stop_reason << "\nends " << geometry::to_text(path.front()) << ", "
            << geometry::to_text(path.back()) << "\n";
  const double length = geometry::length(path);
  test::metric("initiation.disc.gl_length_over_diameter", length / diameter);
  EXPECT_GT(length, 0.8 * diameter);
  EXPECT_LT(std::abs(path.front().x), 5. * p.pd.horizon);
  EXPECT_LT(std::abs(path.back().x), 5. * p.pd.horizon);
}

TEST(HeldPlaces, BeamCrackRisesUnderTheLoadPoint)
{
  const auto   p     = test::scene_file("prm/unnotched-beam.prm", "held_beam");
  const auto   scene = coupling::build_scene(p.scene);
  const double depth = 0.05, mid_span = 0.22;
  const auto   r = coupling::run_global_local_from_initiation(scene, p.global_local_settings(), p.initiation, std::cout);
  ASSERT_EQ(r.paths.size(), 1u);
  const auto &tip = r.paths[0].back();
  std::cout << "stop: " << r.stop_reason << "\n";
  test::metric("initiation.beam.gl_depth_over_height", tip.y / depth);
  EXPECT_GT(tip.y, 0.85 * depth);
  EXPECT_LT(std::abs(tip.x - mid_span), p.pd.horizon);
}
