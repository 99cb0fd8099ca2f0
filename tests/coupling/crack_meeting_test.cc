// Where a growing tip meets another crack (coupling/arrival.h): the first crossing of a path with
// another crack, and the nearest face within reach ahead of the path's end; one's own crack is
// never met. Exact values from the geometry of straight segments.
#include <gtest/gtest.h>

#include <cmath>

#include "arrival.h"

using namespace pumpd;
using geometry::Point;

namespace
{
  // Crack 0 grows along y = 0 towards +x; crack 1 is a vertical face at x = 0.05, y in [-0.02, 0.02].
  const std::vector<geometry::Polyline> cracks = {{{0., 0.}, {0.03, 0.}}, {{0.05, -0.02}, {0.05, 0.02}}};
} // namespace

TEST(CrackMeeting, RayMeetsTheOtherCrackOnly)
{
  const auto [t, c] = coupling::ray_to_cracks({0.03, 0.}, {1., 0.}, 1., cracks, 0);
  EXPECT_EQ(c, 1u);
  EXPECT_NEAR(t, 0.02, 1e-15);
  EXPECT_TRUE(std::isinf(coupling::ray_to_cracks({0.03, 0.}, {1., 0.}, 0.01, cracks, 0).first)); // beyond t_max
  EXPECT_TRUE(std::isinf(coupling::ray_to_cracks({0.03, 0.}, {-1., 0.}, 1., cracks, 0).first));  // its own crack
}

TEST(CrackMeeting, FirstCrossingOfAPath)
{
  const geometry::Polyline path = {{0.03, 0.}, {0.04, 0.005}, {0.06, 0.01}};
  const auto               m    = coupling::first_crossing(path, cracks, 0);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->crack, 1u);
  EXPECT_EQ(m->segment, 1u);
  EXPECT_NEAR(m->at.x, 0.05, 1e-15);
  EXPECT_NEAR(m->at.y, 0.0075, 1e-15);
  EXPECT_FALSE(coupling::first_crossing({{0.03, 0.}, {0.045, 0.}}, cracks, 0));
}

TEST(CrackMeeting, FaceAheadWithinReach)
{
  const geometry::Polyline path = {{0.03, 0.}, {0.047, 0.001}};
  const auto               m    = coupling::face_ahead(path, cracks, 0, 0.004);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->crack, 1u);
  EXPECT_EQ(m->segment, 1u);
  EXPECT_NEAR(m->at.x, 0.05, 1e-15);
  EXPECT_NEAR(m->at.y, 0.001, 1e-15);
  EXPECT_FALSE(coupling::face_ahead(path, cracks, 0, 0.002));                          // out of reach
  EXPECT_FALSE(coupling::face_ahead({{0.051, 0.}, {0.053, 0.}}, cracks, 0, 0.004)); // behind: moving away
}
