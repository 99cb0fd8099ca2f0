// Path distances against closed-form values (coupling/path_metrics.h).
#include <gtest/gtest.h>

#include <cmath>

#include "error.h"
#include "path_metrics.h"

using namespace pumpd;
using geometry::Point;
using geometry::Polyline;

namespace
{
  constexpr double step = 1e-4; // sampling step [m]; the closed forms below are exact for any step
}

TEST(PathMetrics, ParallelSegmentsAreTheirOffsetApart)
{
  const Polyline a = {{0., 0.}, {0.1, 0.}};
  const Polyline b = {{0., 0.003}, {0.1, 0.003}};
  const auto     d = coupling::path_distance(a, b, step);
  EXPECT_NEAR(d.mean, 0.003, 1e-12);
  EXPECT_NEAR(d.hausdorff, 0.003, 1e-12);
}

TEST(PathMetrics, IdenticalPathsWithDifferentVerticesAreZeroApart)
{
  const Polyline a = {{0., 0.}, {0.05, 0.05}, {0.1, 0.1}};
  const Polyline b = {{0., 0.}, {0.02, 0.02}, {0.07, 0.07}, {0.1, 0.1}};
  const auto     d = coupling::path_distance(a, b, step);
  EXPECT_LT(d.mean, 1e-15);
  EXPECT_LT(d.hausdorff, 1e-15);
}

TEST(PathMetrics, ALongerPathCountsItsExtraLength)
{
  // b = a plus 0.05 straight on: from b to a the extra part is 0..0.05 away (mean 0.025 over
  // 0.05 of b's 0.15), from a to b nothing. Symmetric mean = (0 + 0.025 * 0.05 / 0.15) / 2.
  const Polyline a = {{0., 0.}, {0.1, 0.}};
  const Polyline b = {{0., 0.}, {0.15, 0.}};
  const auto     d = coupling::path_distance(a, b, step);
  EXPECT_NEAR(d.hausdorff, 0.05, 1e-12);
  EXPECT_NEAR(d.mean, 0.5 * 0.025 * 0.05 / 0.15, 1e-9);
}

TEST(PathMetrics, KinkedPathAgainstStraightOne)
{
  // a: straight up 0.1; b: straight up 0.05, then 45 degrees for 0.05 sqrt(2).
  // From b's kinked part to a: distance t along it grows as t / sqrt(2), max 0.05.
  const Polyline a = {{0., 0.}, {0., 0.1}};
  const Polyline b = {{0., 0.}, {0., 0.05}, {0.05, 0.1}};
  const auto     d = coupling::path_distance(a, b, step);
  EXPECT_NEAR(d.hausdorff, 0.05, 1e-12);
  EXPECT_NEAR(coupling::directed_max_distance(b, a), 0.05, 1e-12);
}

TEST(PathMetrics, TruncateAndNearestPrefix)
{
  const Polyline line = {{0., 0.}, {0., 0.1}, {0.1, 0.1}};
  const auto     t    = coupling::truncate(line, 0.15);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_NEAR(t.back().x, 0.05, 1e-15);
  EXPECT_NEAR(geometry::length(t), 0.15, 1e-15);
  const auto u = coupling::up_to_nearest(line, {0.03, 0.2});
  ASSERT_EQ(u.size(), 3u);
  EXPECT_NEAR(u.back().x, 0.03, 1e-15);
  EXPECT_NEAR(u.back().y, 0.1, 1e-15);
}

TEST(PathMetrics, RefusesBadInput)
{
  EXPECT_THROW(coupling::path_distance({{0., 0.}, {1., 0.}}, {{0., 0.}, {1., 0.}}, 0.), InvalidParameter);
  EXPECT_THROW(coupling::path_distance({{0., 0.}}, {{0., 0.}, {1., 0.}}, step), InvalidParameter);
}
