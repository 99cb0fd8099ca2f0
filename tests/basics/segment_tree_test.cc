// The segment tree (basics/segment_tree.h) against a scan of every segment in order: the same
// nearest segment and distance, ties to the first segment, on random and on symmetric polylines;
// and how many segments a query looks at on a long polyline.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <random>

#include "segment_tree.h"

using namespace pumpd::geometry;

namespace
{
  /// The first segment of [first, last) nearest x and its distance, by a scan in order.
  std::pair<std::size_t, double> scan(const Polyline &line, std::size_t first, std::size_t last, Point x)
  {
    std::pair<std::size_t, double> best{0, std::numeric_limits<double>::infinity()};
    for (std::size_t s = first; s < last; ++s)
      if (const double d = distance_to_segment(x, line[s], line[s + 1]); d < best.second)
        best = {s, d};
    return best;
  }

  std::pair<std::size_t, double> query(const SegmentTree &tree, const Polyline &line, Point x)
  {
    return tree.nearest(x, [&](std::size_t s) { return distance_to_segment(x, line[s], line[s + 1]); });
  }
} // namespace

TEST(SegmentTree, FindsWhatAScanInOrderFinds)
{
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> step(-1., 1.), where(-3., 3.);
  for (const std::size_t n : {1, 2, 3, 5, 17, 100, 1000})
    {
      Polyline line{{0., 0.}};
      for (std::size_t k = 0; k < n; ++k)
        line.push_back(line.back() + Point{0.05 + 0.01 * step(random), 0.02 * step(random)});
      for (const auto &[first, last] : {std::pair<std::size_t, std::size_t>{0, n}, {n / 3, n - n / 4}})
        {
          const SegmentTree tree(line, first, last);
          for (int q = 0; q < 200; ++q)
            {
              const Point x{where(random), where(random)};
              const auto  expected = first < last ? scan(line, first, last, x)
                                                  : std::pair<std::size_t, double>{0, std::numeric_limits<double>::infinity()};
              const auto  found    = query(tree, line, x);
              EXPECT_EQ(found.first, expected.first) << "n = " << n << ", x = " << to_text(x);
              EXPECT_EQ(found.second, expected.second) << "n = " << n << ", x = " << to_text(x);
            }
        }
    }
}

TEST(SegmentTree, TiesGoToTheFirstSegment)
{
  // A zigzag: a point below or above one of its vertices lies equally near the segments that meet
  // there (their nearest point is that vertex, or the two vertices beside it).
  Polyline zigzag;
  for (int k = 0; k <= 40; ++k)
    zigzag.push_back({0.05 * k, k % 2 == 0 ? 0. : 0.05});
  const SegmentTree tree(zigzag, 0, zigzag.size() - 1);
  for (int k = 0; k <= 40; ++k)
    for (const double y : {-1., -0.01, 1.})
      {
        const Point x{0.05 * k, y};
        EXPECT_EQ(query(tree, zigzag, x), scan(zigzag, 0, zigzag.size() - 1, x)) << to_text(x);
      }
  // A best found elsewhere takes part in ties by its index: (0.1, -1) lies 1 from the vertex where
  // segments 1 and 2 meet.
  const Point       below{0.1, -1.};
  const auto        to = [&](std::size_t s) { return distance_to_segment(below, zigzag[s], zigzag[s + 1]); };
  const SegmentTree from_2(zigzag, 2, zigzag.size() - 1);
  EXPECT_EQ(from_2.nearest(below, to, {1, to(1)}).first, 1u);
  EXPECT_EQ(from_2.nearest(below, to, {3, to(1)}).first, 2u);
}

TEST(SegmentTree, LooksAtFewSegmentsOfALongPolyline)
{
  // 10^4 segments along a gently curved line (a crack digitised finely) and queries on a grid
  // over the box around it, near and far: a query looks at a few leaves, not at the line.
  const std::size_t n = 10000;
  Polyline          line;
  for (std::size_t k = 0; k <= n; ++k)
    line.push_back({0.05 * double(k) / n, 0.001 * std::sin(3.14159 * double(k) / n)});
  const SegmentTree tree(line, 0, n);
  std::size_t       evaluated = 0, queries = 0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j, ++queries)
      {
        const Point x{-0.05 + 0.15 * i / 40., -0.05 + 0.1 * j / 40.};
        const auto  found = tree.nearest(x, [&](std::size_t s) {
          ++evaluated;
          return distance_to_segment(x, line[s], line[s + 1]);
        });
        EXPECT_EQ(found, scan(line, 0, n, x));
      }
  const double per_query = double(evaluated) / double(queries);
  std::cout << "segments evaluated per query: " << per_query << " of " << n << "\n";
  EXPECT_LT(per_query, 100.);
}
