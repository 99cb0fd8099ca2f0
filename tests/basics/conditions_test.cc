// Whether a condition's place lies near a point (conditions.h): a boundary's face, a point's
// vertex, a region's cells; exact answers at the distance given.
#include <gtest/gtest.h>

#include "conditions.h"

using namespace pumpd;
using namespace pumpd::conditions;

TEST(Conditions, APlaceLiesNearAPoint)
{
  Place grip;
  grip.kind  = Place::Kind::boundary;
  grip.name  = "grip";
  grip.edges = {{{{0., 1.}, {1., 1.}}}, {{{1., 1.}, {2., 1.}}}};
  grip.box   = {0., 1., 2., 1.};
  EXPECT_TRUE(near(grip, {1.5, 0.75}, 0.25)) << "a quarter below the second face";
  EXPECT_FALSE(near(grip, {1.5, 0.7}, 0.25));
  EXPECT_FALSE(near(grip, {2.2, 1.}, 0.1)) << "beyond the last face's end";

  Place pad;
  pad.kind   = Place::Kind::point;
  pad.name   = "pad";
  pad.points = {{3., 4.}};
  pad.box    = {3., 4., 3., 4.};
  EXPECT_TRUE(near(pad, {0., 0.}, 5.));
  EXPECT_FALSE(near(pad, {0., 0.}, 5. - 1e-12));

  Place region;
  region.kind   = Place::Kind::region;
  region.name   = "inclusion";
  region.box    = {0., 0., 1., 1.};
  region.inside = [](geometry::Point x) { return x.x + x.y < 1.; };
  EXPECT_TRUE(near(region, {0.2, 0.2}, 0.));
  EXPECT_FALSE(near(region, {0.8, 0.8}, 0.1)) << "in the bounding box, not in the cells";
}
