// Plain 2D geometry shared by local/, global/ and coupling/: points, boxes, circles,
// polylines and the intersection tests the PD set-up and the crack logic need (the body of a
// specimen, its outline and holes, is body.h). No peridynamics and no deal.II here.
#pragma once

#include <string>
#include <vector>

namespace pumpd::geometry
{
  struct Point
  {
    double x = 0.;
    double y = 0.;
  };

  inline Point operator+(Point a, Point b) { return {a.x + b.x, a.y + b.y}; }
  inline Point operator-(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }
  inline Point operator*(double s, Point a) { return {s * a.x, s * a.y}; }
  inline double dot(Point a, Point b) { return a.x * b.x + a.y * b.y; }
  inline double cross(Point a, Point b) { return a.x * b.y - a.y * b.x; }
  double norm(Point a);

  /// A polyline crack: vertices in order, the last one is the (growing) tip.
  using Polyline = std::vector<Point>;

  /// "(x, y)" for a message, `precision` significant digits.
  std::string to_text(Point p, int precision = 6);
  /// "x0,y0; x1,y1; ...", as a crack is written in a .prm.
  std::string to_text(const Polyline &line);

  struct Circle
  {
    Point  centre;
    double radius = 0.;
  };

  /// Axis-parallel rectangle [x_min, x_max] x [y_min, y_max].
  struct Box
  {
    double x_min = 0., y_min = 0., x_max = 0., y_max = 0.;

    double width() const { return x_max - x_min; }
    double height() const { return y_max - y_min; }
    bool   contains(Point p, double tolerance = 0.) const;
    bool   contains(const Box &other, double tolerance = 0.) const;
  };

  /// "[x_min, x_max] x [y_min, y_max]" for a message.
  std::string to_text(const Box &box);

  /// The point of the segment [a, b] nearest p (a for a segment of zero length).
  Point nearest_on_segment(Point p, Point a, Point b);

  /// Distance from p to the segment [a, b].
  double distance_to_segment(Point p, Point a, Point b);

  /// True if the closed segments [p1, p2] and [q1, q2] have a point in common.
  bool segments_intersect(Point p1, Point p2, Point q1, Point q2);

  /// True if the segment [a, b] passes through the open disk of c.
  bool segment_meets_disk(Point a, Point b, const Circle &c);

  /// True if the segment [a, b] crosses any segment of the polyline.
  bool segment_crosses_polyline(Point a, Point b, const Polyline &line);

  /// True if two non-adjacent segments of the polyline intersect.
  bool self_intersects(const Polyline &line);

  /// Sum of segment lengths.
  double length(const Polyline &line);
} // namespace pumpd::geometry
