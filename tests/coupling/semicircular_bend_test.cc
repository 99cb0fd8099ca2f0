// Semicircular bend specimen with an inclined edge crack (prm/semicircular-bend.prm,
// meshes/semicircular-bend.geo): a half disc of radius 0.1 m on supports at x = -+0.06 on its
// diameter, a point force on the top of its arc; the crack leaves the middle of the diameter 30
// degrees from the vertical, 30 mm long.
// - The body is the disc's own: its outline an arc and the diameter (basics/body.h recovers the
//   arc from the mesh's polygon), its area that of the half disc.
// - Mixed mode (K_I and K_II): the crack kinks back towards the load (theta_c > 0 for the crack
//   leaning to the right) and grows in both methods: LEFM growth (three increments) and the
//   global-local cycle (two exchanges), inside the body.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "growing_specimen.h"
#include "metric.h"

using namespace pumpd;
using geometry::Point;

namespace
{
  const std::string scene_file = "prm/semicircular-bend.prm";
  const double      radius     = 0.1;
} // namespace

TEST(SemicircularBend, BodyIsAnArcAndADiameter)
{
  const auto  scene   = coupling::build_scene(test::scene_file(scene_file, "").scene);
  const auto &outline = scene.body.outline();
  std::size_t arcs = 0, segments = 0;
  for (const auto &piece : outline.pieces)
    if (piece.arc)
      {
        ++arcs;
        EXPECT_NEAR(piece.radius, radius, 1e-9);
        EXPECT_NEAR(geometry::norm(piece.centre), 0., 1e-9);
      }
    else
      ++segments;
  std::cout << outline.pieces.size() << " pieces: " << arcs << " arcs, " << segments << " segments; area "
            << scene.body.area() << " m^2, half disc " << 0.5 * std::acos(-1.) * radius * radius << "\n";
  EXPECT_GE(arcs, 1u);
  EXPECT_NEAR(scene.body.area(), 0.5 * std::acos(-1.) * radius * radius, 1e-9);
  EXPECT_TRUE(scene.body.contains({0., 0.0999}));
  EXPECT_FALSE(scene.body.contains({0.08, 0.08})); // outside the arc, inside its bounding box
}

TEST(SemicircularBend, GrowsInBothMethods)
{
  const auto  r     = test::grow_in_both_methods(scene_file, "semicircular_bend", "scene.scb", 0.004);
  ASSERT_FALSE(r.lefm.steps.empty());
  const auto &first = r.lefm.steps.front();
  test::metric("scene.scb.first_kink_deg", test::degrees(first.kink_angle));
  // Mixed mode at the inclined tip, the first kink back towards the vertical through the load.
  EXPECT_GT(first.k1, 0.);
  EXPECT_GT(std::abs(first.k2), 0.2 * first.k1);
  EXPECT_GT(first.kink_angle, 0.);
  for (const auto *path : {&r.lefm.path, &r.gl.path})
    {
      EXPECT_EQ(path->front().x, 0.); // the mouth stays on the diameter
      EXPECT_EQ(path->front().y, 0.);
      EXPECT_GT(path->back().y, r.scene.crack().back().y + 0.003);     // up, towards the load
      EXPECT_GT(test::chord_angle(r.scene.crack(), *path), 0.);        // turned back from the inclination
    }
}
