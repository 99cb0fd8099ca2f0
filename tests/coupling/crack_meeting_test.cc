// Where a growing tip meets another crack (coupling/arrival.h): the first crossing of a path with
// another crack, and the nearest face within reach ahead of the path's end; one's own crack is
// never met. Exact values from the geometry of straight segments.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

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

// A ray through the vertex two segments of the other crack share. These coordinates round u to
// just above 1 on the first segment and just below 0 on the second, so exact bounds on u missed
// the crack altogether.
TEST(CrackMeeting, RayThroughASharedVertexMeetsTheCrack)
{
  const Point                           v{0.049328384584120616, 0.10557851026174232};
  const std::vector<geometry::Polyline> other = {
    {{0.016012536104192017, 0.018732760751607243}, v, {0.030618903049641228, 0.10436494731629831}}};
  const Point from{0.18693648160765955, 0.1835767020715694};
  const Point e = 1.7 * (v - from);
  const auto [t, c] = coupling::ray_to_cracks(from, e, 1., other, 1);
  EXPECT_EQ(c, 0u);
  EXPECT_NEAR(t, 1. / 1.7, 1e-12);
}

// Rays aimed at the vertex two segments of a crack share, the crack crossing the ray's line
// there, from random places and at angles down to 1e-6 rad between the ray and a segment: every
// ray meets the crack, at the vertex (to the rounding of a crossing at that angle). The same ray
// moved 1e-7 m to the right misses the incoming segment alone, which ends at the vertex on its
// left: the segment's line crosses the ray, the segment does not.
TEST(CrackMeeting, EveryRayThroughASharedVertexMeetsTheCrack)
{
  std::mt19937                           random(2026);
  std::uniform_real_distribution<double> unit(0., 1.);
  const auto                             direction = [](double angle) { return Point{std::cos(angle), std::sin(angle)}; };
  int                                    missed = 0, met_beside = 0;
  for (int n = 0; n < 100000; ++n)
    {
      const Point  v{0.2 * unit(random), 0.2 * unit(random)};
      const double ray_angle = 2. * M_PI * unit(random);
      // the crack comes in from the left of the ray's line and leaves to its right, each
      // segment 1e-6 to 1 rad from it (log-uniform)
      const double a_in  = std::pow(10., -6. + 6. * unit(random));
      const double a_out = std::pow(10., -6. + 6. * unit(random));
      const Point  in    = v - (0.05 * (0.1 + unit(random))) * direction(ray_angle - a_in);
      const Point  out   = v + (0.05 * (0.1 + unit(random))) * direction(ray_angle - a_out);
      const Point  from  = v - (0.1 * (0.1 + unit(random))) * direction(ray_angle);
      const Point  e     = 1.7 * (v - from);
      const auto [t, c]  = coupling::ray_to_cracks(from, e, 1., {{in, v, out}}, 1);
      if (c != 0u || std::abs(t - 1. / 1.7) > 1e-6)
        ++missed;
      const Point right = direction(ray_angle - 0.5 * M_PI);
      if (std::isfinite(coupling::ray_to_cracks(from + 1e-7 * right, e, 1., {{in, v}}, 1).first))
        ++met_beside;
    }
  EXPECT_EQ(missed, 0);
  EXPECT_EQ(met_beside, 0);
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
