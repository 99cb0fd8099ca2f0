#include "geometry.h"

#include <algorithm>
#include <cmath>

#include "error.h"

namespace pumpd::geometry
{
  double norm(Point a) { return std::hypot(a.x, a.y); }

  std::string to_text(Point p, int precision)
  {
    return "(" + pumpd::to_text(p.x, precision) + ", " + pumpd::to_text(p.y, precision) + ")";
  }

  std::string to_text(const Box &box)
  {
    return "[" + pumpd::to_text(box.x_min) + ", " + pumpd::to_text(box.x_max) + "] x [" + pumpd::to_text(box.y_min) +
           ", " + pumpd::to_text(box.y_max) + "]";
  }

  std::string to_text(const Polyline &line)
  {
    std::string s;
    for (std::size_t k = 0; k < line.size(); ++k)
      s += (k == 0 ? "" : "; ") + pumpd::to_text(line[k].x) + "," + pumpd::to_text(line[k].y);
    return s;
  }

  bool Box::contains(Point p, double tolerance) const
  {
    return p.x >= x_min - tolerance && p.x <= x_max + tolerance &&
           p.y >= y_min - tolerance && p.y <= y_max + tolerance;
  }

  bool Box::contains(const Box &other, double tolerance) const
  {
    return contains(Point{other.x_min, other.y_min}, tolerance) &&
           contains(Point{other.x_max, other.y_max}, tolerance);
  }

  Point nearest_on_segment(Point p, Point a, Point b)
  {
    const Point  ab = b - a;
    const double l2 = dot(ab, ab);
    return a + (l2 > 0. ? std::clamp(dot(p - a, ab) / l2, 0., 1.) : 0.) * ab;
  }

  double distance_to_segment(Point p, Point a, Point b) { return norm(p - nearest_on_segment(p, a, b)); }

  namespace
  {
    // Sign of the orientation of (a, b, c): +1 counter-clockwise, -1 clockwise, 0 collinear.
    int orientation(Point a, Point b, Point c)
    {
      const double v = cross(b - a, c - a);
      const double scale =
        std::max({std::abs(b.x - a.x), std::abs(b.y - a.y), std::abs(c.x - a.x), std::abs(c.y - a.y)});
      if (std::abs(v) <= 1e-14 * scale * scale)
        return 0;
      return v > 0 ? 1 : -1;
    }

    bool on_segment(Point a, Point b, Point p)
    {
      return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
             std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
    }
  } // namespace

  bool segments_intersect(Point p1, Point p2, Point q1, Point q2)
  {
    const int o1 = orientation(p1, p2, q1), o2 = orientation(p1, p2, q2);
    const int o3 = orientation(q1, q2, p1), o4 = orientation(q1, q2, p2);
    if (o1 != o2 && o3 != o4)
      return true;
    return (o1 == 0 && on_segment(p1, p2, q1)) || (o2 == 0 && on_segment(p1, p2, q2)) ||
           (o3 == 0 && on_segment(q1, q2, p1)) || (o4 == 0 && on_segment(q1, q2, p2));
  }

  bool segment_meets_disk(Point a, Point b, const Circle &c)
  {
    return distance_to_segment(c.centre, a, b) < c.radius;
  }

  bool segment_crosses_polyline(Point a, Point b, const Polyline &line)
  {
    for (std::size_t s = 0; s + 1 < line.size(); ++s)
      if (segments_intersect(a, b, line[s], line[s + 1]))
        return true;
    return false;
  }

  bool self_intersects(const Polyline &line)
  {
    for (std::size_t s = 0; s + 1 < line.size(); ++s)
      for (std::size_t t = s + 2; t + 1 < line.size(); ++t)
        if (segments_intersect(line[s], line[s + 1], line[t], line[t + 1]))
          return true;
    return false;
  }

  double length(const Polyline &line)
  {
    double l = 0.;
    for (std::size_t s = 0; s + 1 < line.size(); ++s)
      l += norm(line[s + 1] - line[s]);
    return l;
  }
} // namespace pumpd::geometry
