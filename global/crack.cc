#include "crack.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "crack_network.h"
#include "error.h"
#include "segment_tree.h"

namespace pumpd::global
{
  using geometry::cross;
  using geometry::dot;
  using geometry::norm;

  namespace
  {
    /// t itself, or InvalidParameter if there is no tip t.
    std::size_t check_tip(std::size_t t, std::size_t tips)
    {
      if (t >= tips)
        throw InvalidParameter("Crack tip", std::to_string(t),
                               "must be an index below the number of tips (" + std::to_string(tips) + ")");
      return t;
    }

    Point unit(Point a) { return (1. / norm(a)) * a; }

    /// acos(v.d / |v|) in [0, pi] for a unit d, as atan2(|v x d|, v.d): acos loses half the digits
    /// near 0 and pi (on the faces and ahead of the tip), atan2 none.
    double unsigned_angle(Point v, Point d) { return std::atan2(std::abs(cross(d, v)), dot(v, d)); }

    /// a rotated by +90 degrees: the left normal of a direction.
    Point left_normal(Point a) { return {-a.y, a.x}; }

    /// Outside the outline by more than the tolerance.
    bool outside(Point p, const geometry::Body &body, double tolerance)
    {
      return !body.outline().encloses(p) && body.outline().distance(p) > tolerance;
    }

    /// Inside a hole by more than the tolerance: touching a hole's rim is allowed.
    bool in_hole(Point p, const geometry::Body &body, double tolerance)
    {
      return std::any_of(body.holes().begin(), body.holes().end(),
                         [&](const geometry::Loop &hole) { return hole.encloses(p) && hole.distance(p) > tolerance; });
    }

    /// True if the segments e1 (ending at a vertex) and e2 (starting there) fold back onto each other.
    bool folds_back(Point e1, Point e2)
    {
      return dot(e1, e2) < 0. && std::abs(cross(e1, e2)) <= 1e-14 * norm(e1) * norm(e2);
    }

    /// The segment tree of the interior segments 1, ..., n - 2 of a polyline of n segments: the
    /// end segments extend into rays (signed_distance_to), which no box bounds.
    geometry::SegmentTree interior_tree(const geometry::Polyline &v)
    {
      return geometry::SegmentTree(v, 1, v.size() > 2 ? v.size() - 2 : 1);
    }

    /// The distance from x to segment s of v (its end segments extended by rays), and the
    /// interior vertex it is measured to (0: none, the nearest point lies on the segment or ray).
    std::pair<double, std::size_t> to_segment(const geometry::Polyline &v, std::size_t s, Point x)
    {
      const std::size_t segments = v.size() - 1;
      const Point       a = v[s], ab = v[s + 1] - a;
      const double      t = dot(x - a, ab) / dot(ab, ab);
      std::size_t       vertex = 0;
      if (t <= 0. && s > 0)
        vertex = s;
      else if (t >= 1. && s + 1 < segments)
        vertex = s + 1;
      return {vertex > 0 ? norm(x - v[vertex]) : std::abs(cross(ab, x - a)) / norm(ab), vertex};
    }

    /// Signed distance from x to the polyline v extended by rays at both ends (the first segment
    /// backwards, the last one forwards), + on the left of v; `interior` is v's interior_tree. The
    /// nearest point lies on segment s at parameter t = (x - a).(b - a) / |b - a|^2, clamped to
    /// [0, 1] except at the open ends (the first such segment where several are as near). If it
    /// is an interior vertex k, the sign is that of (x - v_k).(n_{k-1} + n_k) with the unit left
    /// normals n of the two segments at k (the pseudo-normal).
    double signed_distance_to(const geometry::Polyline &v, const geometry::SegmentTree &interior, Point x)
    {
      const std::size_t segments = v.size() - 1;
      const auto        distance = [&](std::size_t s) { return to_segment(v, s, x).first; };
      auto              best     = interior.nearest(x, distance, {0, distance(0)});
      if (segments > 1)
        if (const double d = distance(segments - 1); d < best.second)
          best = {segments - 1, d};
      const std::size_t s = best.first, k = to_segment(v, s, x).second;

      double orientation;
      if (k > 0)
        {
          const Point pseudo_normal = left_normal(unit(v[k] - v[k - 1])) + left_normal(unit(v[k + 1] - v[k]));
          orientation = dot(x - v[k], pseudo_normal);
        }
      else
        orientation = cross(v[s + 1] - v[s], x - v[s]);
      return orientation >= 0. ? best.second : -best.second;
    }
  } // namespace

  Crack::Crack(geometry::Polyline vertices, const geometry::Body &b, double tolerance)
    : points(std::move(vertices))
    , body(b)
    , tol(tolerance)
  {
    if (!(tol >= 0.) || !std::isfinite(tol))
      throw InvalidParameter("Crack tolerance", std::to_string(tol), "must be a finite number >= 0");
    if (points.size() < 2)
      throw InvalidParameter("Crack", std::to_string(points.size()) + " vertices", "needs at least 2 vertices");
    for (std::size_t k = 0; k < points.size(); ++k)
      {
        const Point       &p    = points[k];
        const std::string  name = "Crack vertex " + std::to_string(k);
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
          throw InvalidParameter(name, to_text(p), "must be finite");
        if (outside(p, body, tol))
          throw InvalidParameter(name, to_text(p), "lies outside the body outline");
        if (in_hole(p, body, tol))
          throw InvalidParameter(name, to_text(p), "lies inside a hole");
        if (k > 0 && k + 1 < points.size() && body.clearance(p) <= tol)
          throw InvalidParameter(name, to_text(p), "only an end of the crack may lie on the body outline or a hole's rim");
        if (k > 0 && norm(p - points[k - 1]) <= tol)
          throw InvalidParameter(name, to_text(p), "repeats the previous vertex (consecutive vertices must differ)");
      }
    for (std::size_t k = 1; k + 1 < points.size(); ++k)
      if (folds_back(points[k] - points[k - 1], points[k + 1] - points[k]))
        throw InvalidParameter("Crack vertex " + std::to_string(k + 1), to_text(points[k + 1]),
                               "folds the crack back onto its previous segment (self-intersection)");
    if (geometry::self_intersects(points))
      throw InvalidParameter("Crack", "polyline of " + std::to_string(points.size()) + " vertices",
                             "must not intersect itself");
    for (std::size_t s = 0; s + 1 < points.size(); ++s)
      if (const auto c = body.crossing(points[s], points[s + 1], tol); c != geometry::Body::Crossing::none)
        throw InvalidParameter("Crack segment " + std::to_string(s), to_text(points[s]) + " - " + to_text(points[s + 1]),
                               c == geometry::Body::Crossing::hole ? "passes through a hole" : "crosses the body outline");
    update();
    if (tip_list.empty())
      throw InvalidParameter("Crack", to_text(points.front()) + " ... " + to_text(points.back()),
                             "both ends lie on the body outline or a hole's rim, so the crack has no tip to grow" +
                               std::string(boundary_curve(body, points.front(), tol) == boundary_curve(body, points.back(), tol)
                                             ? " (and it cuts a piece off the body: both ends on one boundary curve)"
                                             : " (it joins two boundary curves and leaves the body in one piece)"));
  }

  double Crack::length() const { return geometry::length(points); }

  double Crack::signed_distance(Point x) const { return signed_distance_to(points, interior, x); }

  int Crack::side(Point x) const
  {
    if (const Junction *j = junction_beyond(x))
      return j->beyond;
    return signed_distance(x) >= 0. ? 1 : -1;
  }

  bool Crack::beyond_junction(Point x) const { return junction_beyond(x) != nullptr; }

  const Crack::Junction *Crack::junction_beyond(Point x) const
  {
    for (const auto &j : junction)
      if (j && dot(x - j->at, j->d) > 0. && (signed_distance_to(j->face, j->face_interior, x) >= 0. ? 1 : -1) != j->near)
        return &*j;
    return nullptr;
  }

  std::array<double, 2> Crack::polar(Point x, std::size_t t) const
  {
    const Tip   &tip = tip_list[check_tip(t, tip_list.size())];
    const Point  v   = x - tip.position;
    const double r   = norm(v);
    if (r == 0.)
      return {0., 0.};
    return {r, side(x) * unsigned_angle(v, tip.direction)};
  }

  BranchValues Crack::branch_functions(Point x, std::size_t t) const
  {
    const Tip   &tip = tip_list[check_tip(t, tip_list.size())];
    const Point  v   = x - tip.position;
    const double r   = norm(v);
    BranchValues f;
    if (r == 0.)
      return f;

    // Tip frame: x' = (x - tip).d, y' = (x - tip).n with n = d rotated by +90 degrees.
    const Point  d = tip.direction, n = left_normal(d);
    const double xp = dot(v, d), yp = dot(v, n);
    const int    s     = side(x);
    const double theta = s * unsigned_angle(v, d);

    // theta = side |alpha| with the polar angle alpha = atan2(y', x'): grad theta = side sign(y')
    // grad alpha, grad alpha = (x' n - y' d) / r^2; grad r = (x - tip) / r. Next to the line y' = 0
    // side sign(y') = o, with o = +1 at the last vertex (n points to the + side) and o = -1 at
    // vertex 0 (d is reversed there, n points to the - side); on the line itself use that limit.
    const int o  = tip.vertex == 0 ? -1 : 1;
    const int sy = yp > 0. ? 1 : yp < 0. ? -1 : o * s;
    const Point grad_r     = (1. / r) * v;
    const Point grad_theta = (s * sy / (r * r)) * (xp * n - yp * d);

    // F = sqrt(r) g(theta): grad F = g / (2 sqrt(r)) grad r + sqrt(r) g'(theta) grad theta.
    const double sq = std::sqrt(r), sh = std::sin(theta / 2.), ch = std::cos(theta / 2.);
    const double st = std::sin(theta), ct = std::cos(theta);
    const std::array<double, 4> g       = {sh, ch, sh * st, ch * st};
    const std::array<double, 4> g_theta = {ch / 2., -sh / 2., ch / 2. * st + sh * ct, -sh / 2. * st + ch * ct};
    for (std::size_t i = 0; i < 4; ++i)
      {
        f.value[i]    = sq * g[i];
        f.gradient[i] = (g[i] / (2. * sq)) * grad_r + (sq * g_theta[i]) * grad_theta;
      }
    return f;
  }

  std::size_t Crack::nearest_tip(Point x) const
  {
    if (tip_list.empty())
      throw InvalidParameter("Crack tips", "0", "nearest_tip needs a crack with at least one tip");
    std::size_t best = 0;
    for (std::size_t t = 1; t < tip_list.size(); ++t)
      if (norm(x - tip_list[t].position) < norm(x - tip_list[best].position))
        best = t;
    return best;
  }

  void Crack::grow(std::size_t t, Point p)
  {
    const Tip        &tip       = tip_list[check_tip(t, tip_list.size())];
    const bool        front     = tip.vertex == 0;
    const std::size_t neighbour = front ? 1 : points.size() - 2;
    const std::string name      = "Crack growth";
    const std::string from      = " (from the tip at " + to_text(tip.position) + ")";
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw InvalidParameter(name, to_text(p), "must be finite");
    if (outside(p, body, tol))
      throw InvalidParameter(name, to_text(p), "leaves the body outline" + from);
    if (norm(p - tip.position) <= tol)
      throw InvalidParameter(name, to_text(p), "must differ from the tip position" + from);
    if (const auto c = body.crossing(tip.position, p, tol); c != geometry::Body::Crossing::none)
      throw InvalidParameter(name, to_text(p), (c == geometry::Body::Crossing::hole ? "enters a hole" : "leaves the body outline") + from);
    // The new segment shares the tip vertex with the end segment, so it must not fold back onto
    // it; it must not touch any other segment.
    if (folds_back(tip.position - points[neighbour], p - tip.position))
      throw InvalidParameter(name, to_text(p), "folds back onto the crack" + from);
    for (std::size_t s = 0; s + 1 < points.size(); ++s)
      {
        const bool end_segment = front ? s == 0 : s + 2 == points.size();
        if (!end_segment && geometry::segments_intersect(tip.position, p, points[s], points[s + 1]))
          throw InvalidParameter(name, to_text(p), "crosses the crack" + from);
      }
    if (front)
      points.insert(points.begin(), p);
    else
      points.push_back(p);
    update();
  }

  double Crack::distance(Point x) const
  {
    const auto        to = [&](std::size_t s) { return geometry::distance_to_segment(x, points[s], points[s + 1]); };
    const std::size_t last = points.size() - 2;
    return std::min(interior.nearest(x, to, {0, to(0)}).second, to(last));
  }

  void Crack::join(std::size_t t, Point at, const Crack &other)
  {
    const Tip  tip   = tip_list[check_tip(t, tip_list.size())];
    const bool front = tip.vertex == 0;
    const auto &o    = other.points;
    std::size_t face = 0;
    for (std::size_t s = 1; s + 1 < o.size(); ++s)
      if (geometry::distance_to_segment(at, o[s], o[s + 1]) < geometry::distance_to_segment(at, o[face], o[face + 1]))
        face = s;
    if (geometry::distance_to_segment(at, o[face], o[face + 1]) > tol)
      throw InvalidParameter("Crack junction", to_text(at), "must lie on the face of the crack it joins");
    if (norm(at - tip.position) > tol)
      grow(t, at);

    // H beyond the junction takes the value H has on the far side next to the face where the face
    // runs back against the joined end's direction d: there the level set's sign comes from the
    // end segment's line and is the same up to the face, so H stays continuous across the part
    // of the far side that the extension of the joined end does not reach.
    const std::size_t last    = points.size() - 1;
    const Point       segment = front ? points[1] - points[0] : points[last] - points[last - 1];
    Junction          j;
    j.at              = at;
    j.d               = front ? unit(points[0] - points[1]) : unit(segment);
    j.face            = o;
    j.face_interior   = interior_tree(j.face);
    j.near            = signed_distance_to(o, other.interior, at - (1e-3 * norm(segment)) * j.d) >= 0. ? 1 : -1;
    const Point along = unit(o[face + 1] - o[face]);
    const Point back  = dot(along, j.d) <= 0. ? along : -1. * along;
    j.beyond          = cross(segment, back) >= 0. ? 1 : -1;
    junction[front ? 0 : 1] = j;
    update();
  }

  void Crack::update()
  {
    interior = interior_tree(points);
    tip_list.clear();
    const std::size_t last = points.size() - 1;
    if (!junction[0] && body.clearance(points.front()) > tol)
      tip_list.push_back({points.front(), unit(points.front() - points[1]), 0});
    if (!junction[1] && body.clearance(points.back()) > tol)
      tip_list.push_back({points.back(), unit(points.back() - points[last - 1]), last});
  }
} // namespace pumpd::global
