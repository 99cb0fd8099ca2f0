// A crack leaving a hole's rim (prm/hole-rim-crack.prm, meshes/hole-rim-crack.geo): a 0.2 m square
// plate with a hole of radius 0.02 m at its centre, pulled apart by its top edge; the crack's
// mouth lies on the rim at 0 degrees, its tip 10 mm out.
// - The scene takes the end on the rim for the mouth: one tip, at the other end.
// - The crack grows from the rim in both methods: LEFM growth (three increments) and the
//   global-local cycle (two exchanges), straight to the right (the scene is symmetric about the
//   crack's line), its mouth staying on the rim.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "crack.h"
#include "growing_specimen.h"
#include "metric.h"

using namespace pumpd;
using geometry::Point;

namespace
{
  const std::string scene_file = "prm/hole-rim-crack.prm";
  const Point       centre{0.1, 0.1};
  const double      radius = 0.02;
} // namespace

TEST(HoleRimCrack, TheEndOnTheRimIsTheMouth)
{
  const auto scene = coupling::build_scene(test::scene_file(scene_file, "").scene);
  ASSERT_EQ(scene.body.holes().size(), 1u);
  geometry::Circle hole;
  ASSERT_TRUE(scene.body.holes().front().circle(hole)); // the rim's polygon is the circle again
  EXPECT_NEAR(geometry::norm(hole.centre - centre), 0., 1e-9);
  EXPECT_NEAR(hole.radius, radius, 1e-9);
  EXPECT_LT(scene.body.hole_clearance(scene.crack().front()), 1e-9);
  const global::Crack crack(scene.crack(), scene.body, 1e-8 * scene.body.bounding_box().width());
  ASSERT_EQ(crack.tips().size(), 1u);
  EXPECT_EQ(crack.tips().front().position.x, 0.13);
  EXPECT_EQ(crack.tips().front().direction.x, 1.);
}

TEST(HoleRimCrack, GrowsFromTheRimInBothMethods)
{
  const auto r = test::grow_in_both_methods(scene_file, "hole_rim_crack", "scene.hole_rim", 0.01);
  for (const auto *path : {&r.lefm.path, &r.gl.path})
    {
      EXPECT_NEAR(geometry::norm(path->front() - centre), radius, 1e-12); // the mouth stays on the rim
      for (std::size_t k = 2; k < path->size(); ++k)
        {
          EXPECT_GT((*path)[k].x, (*path)[k - 1].x);  // away from the hole
          EXPECT_NEAR((*path)[k].y, centre.y, 0.002); // along the symmetry line, within half a PD horizon
        }
    }
}
