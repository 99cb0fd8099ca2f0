#include "segment_tree.h"

#include <algorithm>
#include <cmath>

namespace pumpd::geometry
{
  namespace
  {
    Box merged(const Box &a, const Box &b)
    {
      return {std::min(a.x_min, b.x_min), std::min(a.y_min, b.y_min), std::max(a.x_max, b.x_max),
              std::max(a.y_max, b.y_max)};
    }
  } // namespace

  Box box_of(Point a, Point b)
  {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
  }

  SegmentTree::SegmentTree(const Polyline &line, std::size_t first, std::size_t last)
  {
    if (first < last && last < line.size())
      build(line, first, last);
  }

  std::size_t SegmentTree::build(const Polyline &line, std::size_t first, std::size_t last)
  {
    const std::size_t n = nodes.size();
    nodes.push_back({box_of(line[first], line[first + 1]), first, last, 0});
    if (last - first <= leaf_size)
      {
        for (std::size_t s = first + 1; s < last; ++s)
          nodes[n].box = merged(nodes[n].box, box_of(line[s], line[s + 1]));
        return n;
      }
    const std::size_t middle = first + (last - first) / 2;
    build(line, first, middle);
    const std::size_t second = build(line, middle, last);
    nodes[n].box      = merged(nodes[n + 1].box, nodes[second].box);
    nodes[n].second   = second;
    return n;
  }

  double SegmentTree::distance_to(const Box &b, Point x)
  {
    const double dx = std::max({b.x_min - x.x, 0., x.x - b.x_max});
    const double dy = std::max({b.y_min - x.y, 0., x.y - b.y_max});
    return std::hypot(dx, dy);
  }
} // namespace pumpd::geometry
