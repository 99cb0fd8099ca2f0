// Plain geometry: intersections the PD set-up relies on, with exact answers.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry.h"

using namespace pumpd::geometry;

TEST(Geometry, SegmentIntersection)
{
  EXPECT_TRUE(segments_intersect({0, 0}, {1, 1}, {0, 1}, {1, 0}));
  EXPECT_FALSE(segments_intersect({0, 0}, {1, 0}, {0, 1}, {1, 1}));
  EXPECT_TRUE(segments_intersect({0, 0}, {1, 0}, {1, 0}, {2, 5}));   // shared end point
  EXPECT_TRUE(segments_intersect({0, 0}, {2, 0}, {1, 0}, {3, 0}));   // collinear overlap
  EXPECT_FALSE(segments_intersect({0, 0}, {1, 0}, {2, 0}, {3, 0}));  // collinear apart
}

TEST(Geometry, DiskAndPolyline)
{
  const Circle hole{{0., 0.}, 1.};
  EXPECT_TRUE(segment_meets_disk({-2, 0.5}, {2, 0.5}, hole));
  EXPECT_FALSE(segment_meets_disk({-2, 1.5}, {2, 1.5}, hole));
  EXPECT_NEAR(distance_to_segment({0, 0}, {-2, 1.5}, {2, 1.5}), 1.5, 1e-15);

  const Polyline crack{{0, 0}, {1, 0}, {2, 1}};
  EXPECT_NEAR(length(crack), 1. + std::sqrt(2.), 1e-15);
  EXPECT_TRUE(segment_crosses_polyline({0.5, -1}, {0.5, 1}, crack));
  EXPECT_FALSE(segment_crosses_polyline({3, -1}, {3, 1}, crack));
  EXPECT_FALSE(self_intersects(crack));
  EXPECT_TRUE(self_intersects({{0, 0}, {2, 0}, {2, 1}, {1, -1}}));
}
