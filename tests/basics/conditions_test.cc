// Where a condition's place lies against a box (conditions.h): a boundary that crosses the box with
// no vertex in it, a point on the box's edge, a region whose bounding box overlaps it; exact answers.
#include <gtest/gtest.h>

#include "conditions.h"

using namespace pumpd;
using namespace pumpd::conditions;

namespace
{
  Place boundary(const std::string &name, geometry::Point a, geometry::Point b)
  {
    Place p;
    p.kind  = Place::Kind::boundary;
    p.name  = name;
    p.edges = {{a, b}};
    return p;
  }

  Place point(const std::string &name, geometry::Point x)
  {
    Place p;
    p.kind   = Place::Kind::point;
    p.name   = name;
    p.points = {x};
    return p;
  }
} // namespace

TEST(Conditions, APlaceReachesIntoABox)
{
  const geometry::Box box{0., 0., 1., 1.};
  EXPECT_TRUE(reaches_into(boundary("across", {-1., 0.5}, {2., 0.5}), box)) << "no vertex inside, the face crosses";
  EXPECT_FALSE(reaches_into(boundary("beside", {-1., 1.5}, {2., 1.5}), box));
  EXPECT_TRUE(reaches_into(point("on the edge", {1., 0.3}), box));
  EXPECT_FALSE(reaches_into(point("outside", {1. + 1e-12, 0.3}), box));

  Place region;
  region.kind = Place::Kind::region;
  region.box  = {0.9, 0.9, 3., 3.};
  EXPECT_TRUE(reaches_into(region, box));
  region.box = {1.1, 0., 3., 3.};
  EXPECT_FALSE(reaches_into(region, box));
}

TEST(Conditions, PlacesInABoxKeepTheConditionsOrder)
{
  Conditions c;
  c.displacements.push_back({point("support", {5., 5.}), std::nullopt, Field([](geometry::Point) { return 0.; })});
  c.displacements.push_back({boundary("grip", {0., 0.2}, {0.5, 0.2}), std::nullopt, std::nullopt});
  c.tractions.push_back({boundary("arc", {0.4, 0.9}, {0.6, 0.9}), {}, {}, {}});
  c.forces.push_back({point("pad", {0.5, 0.5}), {0., -1.}});
  EXPECT_EQ(places_in(c, {0., 0., 1., 1.}), (std::vector<std::string>{"grip", "arc", "pad"}));
  EXPECT_TRUE(places_in(c, {2., 2., 3., 3.}).empty());
}
