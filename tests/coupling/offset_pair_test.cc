// Offset pair of edge cracks under tension (prm/offset-pair.prm, meshes/offset-pair.geo): LEFM
// growth of two cracks (the global-local cycle's test is at the end). The left crack runs from the
// left edge at y = 0.04, the right one from the right edge at y = 0.06; the top edge is pulled, the
// bottom held. Checked:
// - both cracks grow (their tips advance towards the middle of the plate);
// - each path turns towards the other crack: the end of the left path lies above y = 0.04 (the
//   right crack's side), the end of the right path below y = 0.06;
// - the rule for simultaneous tips: in every step the tips that grow have lambda_c within the
//   simultaneous growth tolerance of the step's smallest, the others wait; both cases occur (the
//   tips grow together while the scene's half-turn symmetry holds, one waits afterwards);
// - the run ends for a stated reason: a tip joins the other crack (its path then ends on the
//   other crack's face), or a tip reaches the outline;
// - crack_path.csv holds the left crack and crack_path_2.csv the right one.
// Prints pumpd-metric cracks.offset_pair.lefm_tip_gap_mm (at the end, the smallest distance from a
// remaining tip to the other crack; 0 once they joined), .left_turn_mm and .right_turn_mm (how far
// each end lies off its initial crack line towards the other crack), .joined (1 or 0), .increments.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>

#include "csv.h"
#include "geometry.h"
#include "global_local.h"
#include "lefm_growth.h"
#include "path_metrics.h"
#include "metric.h"
#include "scene_file.h"

using namespace pumpd;
using geometry::Point;

namespace
{
  /// Distance from p to the polyline.
  double distance(Point p, const geometry::Polyline &line)
  {
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t s = 0; s + 1 < line.size(); ++s)
      d = std::min(d, geometry::distance_to_segment(p, line[s], line[s + 1]));
    return d;
  }
} // namespace

TEST(OffsetPair, LefmGrowthTurnsTheTipsTowardsEachOther)
{
  const auto p      = test::scene_file("prm/offset-pair.prm", "offset_pair");
  const auto scene  = coupling::build_scene(p.scene);
  ASSERT_EQ(scene.cracks.size(), 2u);
  const auto result = coupling::run_lefm_growth(scene, p.lefm_growth_settings(), std::cout);

  ASSERT_EQ(result.paths.size(), 2u);
  const auto &left = result.paths[0], &right = result.paths[1];
  // The left crack starts at the left edge (vertex 0) and grows at its last vertex; the right one
  // likewise from the right edge.
  EXPECT_EQ(left.front().x, 0.);
  EXPECT_EQ(right.front().x, 0.2);
  EXPECT_GT(left.size(), 3u) << "the left crack grew";
  EXPECT_GT(right.size(), 3u) << "the right crack grew";
  EXPECT_GT(left.back().x, 0.07 + 0.01);
  EXPECT_LT(right.back().x, 0.13 - 0.01);

  // Simultaneous tips: grow within the tolerance of the smallest lambda_c, wait above it.
  const double tolerance = p.lefm.simultaneous_tolerance;
  bool         together = false, waited = false;
  for (std::size_t k = 0; k + 1 < result.steps.size(); k += 2)
    {
      const auto &a = result.steps[k], &b = result.steps[k + 1];
      ASSERT_EQ(a.step, b.step);
      const double smallest = std::min(a.critical_load_factor, b.critical_load_factor);
      for (const auto *tip : {&a, &b})
        {
          const bool critical = tip->critical_load_factor <= smallest * (1. + tolerance);
          if (a.step < p.lefm.max_steps) // at the last step allowed no tip grows
            EXPECT_EQ(tip->increment > 0., critical) << "step " << tip->step << ", tip " << tip->tip;
        }
      together |= a.increment > 0. && b.increment > 0.;
      waited |= (a.increment > 0.) != (b.increment > 0.);
    }
  EXPECT_TRUE(together);
  EXPECT_TRUE(waited);

  // Turned towards the other crack.
  const double left_turn = left.back().y - 0.04, right_turn = 0.06 - right.back().y;
  EXPECT_GT(left_turn, 0.002) << "left path ends at (" << left.back().x << ", " << left.back().y << ")";
  EXPECT_GT(right_turn, 0.002) << "right path ends at (" << right.back().x << ", " << right.back().y << ")";

  // The end: joined (the end lies on the other crack) or stopped at the outline.
  const bool joined = result.joined;
  std::cout << "end: " << result.stop_reason << "\n";
  if (joined)
    {
      EXPECT_NE(result.stop_reason.find("joined crack"), std::string::npos);
      const double gap = std::min(distance(left.back(), right), distance(right.back(), left));
      EXPECT_LT(gap, 1e-9) << "a joined path ends on the other crack";
    }
  else
    EXPECT_NE(result.stop_reason.find("reached the outline"), std::string::npos) << result.stop_reason;

  // The files: one per crack, the first in the one-crack format.
  const auto dir   = std::filesystem::path(scene.output_directory);
  const auto first = read_csv_rows((dir / "crack_path.csv").string());
  const auto second = read_csv_rows((dir / "crack_path_2.csv").string());
  EXPECT_EQ(first.size(), left.size());
  EXPECT_EQ(second.size(), right.size());

  // Tip gap at the end: 0 when joined, else the smallest distance from a remaining tip to the other crack.
  double gap = 0.;
  if (!joined)
    gap = std::min(distance(left.back(), right), distance(right.back(), left));
  test::metric("cracks.offset_pair.lefm_tip_gap_mm", 1e3 * gap);
  test::metric("cracks.offset_pair.left_turn_mm", 1e3 * left_turn);
  test::metric("cracks.offset_pair.right_turn_mm", 1e3 * right_turn);
  test::metric("cracks.offset_pair.joined", joined ? 1. : 0.);
  test::metric("cracks.offset_pair.increments", double(result.increments));
}

// The global-local cycle on the same scene (a PD box per tip, m = 4): both cracks grow and turn
// towards each other, and the run ends when one joins the other (a tip within a horizon of the
// other crack's face joins it there) or reaches the outline. Prints
// cracks.offset_pair.gl_left_turn_mm, .gl_right_turn_mm, .gl_joined, and the mean distance of each
// global-local path from LEFM growth's over their common extent (.gl_vs_lefm_mean_mm, the larger
// of the two cracks'): the two methods' answers on one scene.
TEST(OffsetPair, GlobalLocalTurnsTheTipsTowardsEachOther)
{
  auto lefm        = test::scene_file("prm/offset-pair.prm", "offset_pair_lefm");
  const auto scene = coupling::build_scene(lefm.scene);
  std::ostringstream lefm_log;
  const auto         l = coupling::run_lefm_growth(scene, lefm.lefm_growth_settings(), lefm_log);

  auto gl                    = test::scene_file("prm/offset-pair.prm", "offset_pair_global_local");
  gl.pd.horizon_over_spacing = 4;
  const auto r = coupling::run_global_local(coupling::build_scene(gl.scene), gl.global_local_settings(), std::cout);
  ASSERT_EQ(r.paths.size(), 2u);
  const auto &left = r.paths[0], &right = r.paths[1];
  EXPECT_GT(left.back().x, 0.07 + 0.01);
  EXPECT_LT(right.back().x, 0.13 - 0.01);
  const double h          = gl.pd.spacing();
  const double left_turn  = left.back().y - 0.04, right_turn = 0.06 - right.back().y;
  EXPECT_GT(left_turn, 2. * h);
  EXPECT_GT(right_turn, 2. * h);
  const bool joined = r.stop_reason.find("joined crack") != std::string::npos;
  if (joined)
    EXPECT_LT(std::min(distance(left.back(), right), distance(right.back(), left)), 1e-9);
  else
    EXPECT_NE(r.stop_reason.find("reached the outline"), std::string::npos) << r.stop_reason;
  double mean = 0.;
  for (std::size_t c = 0; c < 2; ++c)
    mean = std::max(mean, coupling::trade_distance(r.paths[c], l.paths[c]).mean);
  test::metric("cracks.offset_pair.gl_left_turn_mm", 1e3 * left_turn);
  test::metric("cracks.offset_pair.gl_right_turn_mm", 1e3 * right_turn);
  test::metric("cracks.offset_pair.gl_joined", joined ? 1. : 0.);
  test::metric("cracks.offset_pair.gl_vs_lefm_mean_mm", 1e3 * mean);
}
