// A bounding-box hierarchy over the segments of a polyline, so that the nearest segment to a
// point is found in O(log n) instead of O(n) for a polyline of n segments. Its nodes are runs of
// consecutive segments: a polyline's neighbouring segments lie near each other, so a run's box is
// tight without any sorting.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "geometry.h"

namespace pumpd::geometry
{
  class SegmentTree
  {
  public:
    SegmentTree() = default;
    /// The segments first, ..., last - 1 of `line` (segment s joins line[s] and line[s + 1]).
    SegmentTree(const Polyline &line, std::size_t first, std::size_t last);

    /// The segment s that minimises distance(s), and that value: the first such segment where
    /// several share the minimum, as a scan in order finds. `best` is a candidate found
    /// otherwise (a segment outside the tree, its index taking part in ties). `distance(s)` must
    /// never lie below the distance from x to the segment: the subtrees whose box lies farther
    /// than the best so far are skipped, with a margin of a few rounding errors so that a
    /// segment whose computed distance ties the best is always looked at.
    template <class Distance>
    std::pair<std::size_t, double> nearest(Point x, Distance distance,
                                           std::pair<std::size_t, double> best = {
                                             0, std::numeric_limits<double>::infinity()}) const
    {
      if (!nodes.empty() && distance_to(nodes[0].box, x) * (1. - 1e-12) <= best.second)
        nearest_in(0, x, distance, best);
      return best;
    }

  private:
    /// Segments [first, last); a node with children has them at index + 1 and `second`.
    struct Node
    {
      Box         box;
      std::size_t first = 0, last = 0, second = 0;
    };
    static constexpr std::size_t leaf_size = 4;

    std::size_t build(const Polyline &line, std::size_t first, std::size_t last);
    /// Distance from x to the box (0 inside).
    static double distance_to(const Box &b, Point x);

    template <class Distance>
    void nearest_in(std::size_t n, Point x, Distance &distance, std::pair<std::size_t, double> &best) const
    {
      const Node &node = nodes[n];
      if (node.second == 0)
        {
          for (std::size_t s = node.first; s < node.last; ++s)
            if (const double d = distance(s); d < best.second || (d == best.second && s < best.first))
              best = {s, d};
          return;
        }
      // The nearer child first: the best so far then skips most of the farther one.
      std::array<std::pair<double, std::size_t>, 2> children = {
        {{distance_to(nodes[n + 1].box, x), n + 1}, {distance_to(nodes[node.second].box, x), node.second}}};
      if (children[1].first < children[0].first)
        std::swap(children[0], children[1]);
      for (const auto &[bound, child] : children)
        if (bound * (1. - 1e-12) <= best.second)
          nearest_in(child, x, distance, best);
    }

    std::vector<Node> nodes;
  };

  /// The smallest box that holds the segment [a, b].
  Box box_of(Point a, Point b);
} // namespace pumpd::geometry
