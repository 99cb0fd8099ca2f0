// The resolution rule (coupling/resolution.h): the clearance of the path ahead of a tip, the
// number of halvings or doublings it asks for, and the box of a halved or doubled horizon
// (box_policy.h).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "box_policy.h"
#include "resolution.h"

using namespace pumpd;
using geometry::Body;
using geometry::Point;

namespace
{
  // The beam of Ingraffea's Case III, with its lower hole only: radius 6.35 mm at (152.4, 69.85) mm.
  const Body beam{{0., 0., 0.508, 0.2032}, {{{0.1524, 0.06985}, 0.00635}}};
} // namespace

TEST(Resolution, ClearanceAheadIsTheDistanceOfTheSegmentFromTheHole)
{
  // A tip 30 mm left of the hole's centre heading right: the segment's end, 12 mm on, is
  // 18 mm from the centre, 11.65 mm from the rim; the tip itself is 23.65 mm from the rim and
  // 69.85 mm from the bottom edge.
  const Point tip{0.1224, 0.06985};
  EXPECT_NEAR(coupling::clearance_ahead(beam, tip, {1., 0.}, 0.012, 0.0005), 0.018 - 0.00635, 1e-9);
  // Heading up, away from the hole: the tip's own clearance (the hole, 23.65 mm) is the least.
  EXPECT_NEAR(coupling::clearance_ahead(beam, tip, {0., 1.}, 0.012, 0.0005), 0.030 - 0.00635, 1e-9);
}

TEST(Resolution, HalvesTheHorizonUntilTheClearanceHoldsThreeHorizons)
{
  coupling::ResolutionSettings s; // clearance rule, 3 horizons, at most one halving, no doubling
  const double                 delta = 0.004;
  const auto                   at    = [](double c) { return [c](double) { return c; }; };
  EXPECT_EQ(coupling::horizon_halvings(s, delta, at(0.0121)), 0); // >= 12 mm: the section's 4 mm
  EXPECT_EQ(coupling::horizon_halvings(s, delta, at(0.0119)), 1); // 2 mm
  EXPECT_EQ(coupling::horizon_halvings(s, delta, at(0.001)), 1);  // at most one halving
  s.max_halvings = 3;
  EXPECT_EQ(coupling::horizon_halvings(s, delta, at(0.0059)), 2); // 1 mm: 3 mm <= 5.9 mm < 6 mm
  EXPECT_EQ(coupling::horizon_halvings(s, delta, at(0.)), 3);
  s.rule = "fixed";
  EXPECT_EQ(coupling::horizon_halvings(s, delta, at(0.)), 0);
}

TEST(Resolution, DoublesTheHorizonWhereTheDoubledBoxAndPathKeepThreeDoubledHorizons)
{
  coupling::ResolutionSettings s;
  s.max_doublings    = 2;
  const double delta = 0.004;
  // The clearance grows with the reach of the path and the box: here it is c_1 = 30 mm at the
  // section's scale and below, 25 mm at twice it, 10 mm at four times it.
  std::vector<double> asked;
  const auto clearance = [&](double scale) {
    asked.push_back(scale);
    return scale <= 1. ? 0.030 : scale == 2. ? 0.025 : 0.010;
  };
  // 16 mm needs 48 mm (c_4 = 10 mm), 8 mm needs 24 mm (c_2 = 25 mm): one doubling.
  EXPECT_EQ(coupling::horizon_halvings(s, delta, clearance), -1);
  EXPECT_EQ(asked, (std::vector<double>{1., 4., 2.}));
  // Where the doubled box's clearance is short of 24 mm, the section's horizon: the finer
  // scales are judged by the clearance at the section's scale, as without doublings.
  EXPECT_EQ(coupling::horizon_halvings(s, delta, [](double scale) { return scale <= 1. ? 0.013 : 0.02; }), 0);
  EXPECT_EQ(coupling::horizon_halvings(s, delta, [](double scale) { return scale <= 1. ? 0.011 : 0.1; }), -2);
  // A box that does not fit has no clearance (Cycle::resolve): no doubling.
  EXPECT_EQ(coupling::horizon_halvings(s, delta, [](double scale) { return scale <= 1. ? 0.011 : 0.; }), 1);
  // Without doublings only the section's scale is asked, whatever the finer boxes would see.
  s.max_doublings = 0;
  s.max_halvings  = 2;
  asked.clear();
  EXPECT_EQ(coupling::horizon_halvings(s, delta, [&](double scale) {
              asked.push_back(scale);
              return scale == 1. ? 0.013 : 0.;
            }),
            0);
  EXPECT_EQ(asked, std::vector<double>{1.});
}

TEST(Resolution, ClearanceAheadOfOtherCracksFaces)
{
  // A face 10 mm to the right of a tip heading up, from 5 mm to 30 mm above it: the segment's
  // points from 5 mm on are 10 mm from it, the tip itself 11.2 mm.
  const std::vector<geometry::Polyline> faces{{{0.01, 0.005}, {0.01, 0.03}}};
  EXPECT_NEAR(coupling::clearance_ahead(faces, {0., 0.}, {0., 1.}, 0.024, 0.0005), 0.01, 1e-12);
  EXPECT_NEAR(coupling::clearance_ahead(faces, {0., 0.}, {0., 1.}, 0.002, 0.0005), std::hypot(0.01, 0.003), 1e-12);
  EXPECT_TRUE(std::isinf(coupling::clearance_ahead(std::vector<geometry::Polyline>{}, {0., 0.}, {0., 1.}, 0.024, 0.0005)));
}

TEST(Resolution, AHalvedBoxHasHalfTheSideAndIsNeverKeptAcrossScales)
{
  coupling::BoxSettings b;
  b.horizon = 0.004, b.spacing = 0.0005, b.size = 0.032, b.margin = 0.008, b.max_size = 0.064;
  coupling::BoxPolicy policy(beam, b);
  const Point         tip{0.1016, 0.04}, up{0., 1.};
  const auto          coarse = policy.place(tip, up);
  EXPECT_NEAR(coarse.width(), 0.032, 0.0005 + 1e-12);
  const auto fine = policy.place(tip, up, 0.5);
  EXPECT_TRUE(policy.moved());
  EXPECT_NEAR(fine.width(), 0.016, 0.00025 + 1e-12);
  EXPECT_NEAR(fine.height(), 0.016, 0.00025 + 1e-12);
  policy.place(tip, up, 0.5);
  EXPECT_FALSE(policy.moved()); // same scale, the tip has room: kept
  policy.place(tip, up);
  EXPECT_TRUE(policy.moved());
}

TEST(Resolution, AHoleTheBoxReachesCountsWithItsRadius)
{
  coupling::BoxSettings b;
  b.horizon = 0.004, b.spacing = 0.0005, b.size = 0.032, b.margin = 0.008, b.max_size = 0.064;
  const coupling::BoxPolicy policy(beam, b);
  // The box around a tip 20 mm left of the hole's centre, heading up, reaches the hole (its side
  // 16 mm to the right plus 2 horizons): the hole's radius. Far below it, nothing.
  EXPECT_NEAR(policy.smallest_hole_within_reach({0.1324, 0.06}, {0., 1.}), 0.00635, 1e-12);
  EXPECT_TRUE(std::isinf(policy.smallest_hole_within_reach({0.1324, 0.01}, {0., 1.})));
}

TEST(Resolution, ADoubledBoxReachesTheHolesOfTwiceTheSideAndMustFitTheBody)
{
  coupling::BoxSettings b;
  b.horizon = 0.004, b.spacing = 0.0005, b.size = 0.032, b.margin = 0.008, b.max_size = 0.064;
  // A tip whose horizontal distance to the hole's rim is 44 mm, heading up: the right side of its
  // 32 mm box, 16 mm from the tip, stays outside the hole's reach of 2 horizons; the doubled box
  // (32 mm to the tip's right) takes it in only with its doubled reach (16 mm, not 8 mm).
  const coupling::BoxPolicy policy(beam, b);
  const Point               tip{0.10205, 0.06};
  EXPECT_TRUE(std::isinf(policy.smallest_hole_within_reach(tip, {0., 1.})));
  EXPECT_NEAR(policy.smallest_hole_within_reach(tip, {0., 1.}, 2.), 0.00635, 1e-12);
  // The beam is 203.2 mm high: a box of 4 x 32 mm fits, one of 8 x 32 mm does not.
  EXPECT_TRUE(policy.fits(4.));
  EXPECT_FALSE(policy.fits(8.));
}

// The kink's horizon (resolution.h): delta_k <= eps a / |theta_c|, eps = 3 degrees.
TEST(Resolution, AKinkingTipHalvesTheHorizonUntilTheFirstChordHoldsTheKink)
{
  coupling::ResolutionSettings s; // kink tolerance 3 degrees, at most 3 kink halvings
  const double                 degree = std::acos(-1.) / 180.;
  // The inclined crack: a = 10 mm, theta_c = -53 degrees: 3 / 53 x 10 mm = 0.57 mm, so 4 mm / 8.
  EXPECT_EQ(coupling::kink_halvings(s, 0.004, -53. * degree, 0.010), 3);
  // Ingraffea's Case II: a = 25.4 mm, theta_c = -12.7 degrees: 6.0 mm, the section's 4 mm holds.
  EXPECT_EQ(coupling::kink_halvings(s, 0.004, -12.7 * degree, 0.0254), 0);
  // Just beyond a bound: delta |theta_c| / a = 2 x 1.01 eps asks for two halvings.
  EXPECT_EQ(coupling::kink_halvings(s, 0.004, 2.02 * 3. * degree, 0.004), 2);
  EXPECT_EQ(coupling::kink_halvings(s, 0.004, 2. * 3. * degree, 0.004), 1);
  // A straight crack, no tolerance, the fixed rule: none; and never more than the maximum.
  EXPECT_EQ(coupling::kink_halvings(s, 0.004, 0., 0.01), 0);
  EXPECT_EQ(coupling::kink_halvings(s, 0.004, -1.2, 0.0001), 3);
  s.kink_tolerance = 0.;
  EXPECT_EQ(coupling::kink_halvings(s, 0.004, -53. * degree, 0.010), 0);
  s.kink_tolerance = 3.;
  s.rule           = "fixed";
  EXPECT_EQ(coupling::kink_halvings(s, 0.004, -53. * degree, 0.010), 0);
}
