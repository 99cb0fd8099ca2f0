#include "body.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "error.h"

namespace pumpd::geometry
{
  namespace
  {
    constexpr double pi       = 3.14159265358979323846;
    constexpr double infinity = std::numeric_limits<double>::infinity();

    Point  unit(Point a) { return (1. / norm(a)) * a; }
    Point  left_normal(Point a) { return {-a.y, a.x}; }
    double angle_of(Point v) { return std::atan2(v.y, v.x); }

    /// The angle in [0, 2 pi) that one turns counter-clockwise from `from` to `to`.
    double ccw_angle(double from, double to)
    {
      double d = std::fmod(to - from, 2. * pi);
      return d < 0. ? d + 2. * pi : d;
    }

    /// Both t (ascending) with |x + t d - c| = R, d not necessarily unit; none if the line misses
    /// or touches the circle (a tangent does not cross it).
    int circle_roots(Point x, Point d, Point c, double R, double t[2])
    {
      const double A = dot(d, d), B = dot(x - c, d), C = dot(x - c, x - c) - R * R;
      const double disc = B * B - A * C;
      if (!(disc > 0.) || A == 0.)
        return 0;
      const double s = std::sqrt(disc);
      t[0] = (-B - s) / A;
      t[1] = (-B + s) / A;
      return 2;
    }

    /// Parameters t in [0, 1] at which [a, b] meets the piece.
    void intersections(Point a, Point b, const Piece &piece, std::vector<double> &out)
    {
      if (!piece.arc && (std::max(a.x, b.x) < std::min(piece.a.x, piece.b.x) ||
                         std::min(a.x, b.x) > std::max(piece.a.x, piece.b.x) ||
                         std::max(a.y, b.y) < std::min(piece.a.y, piece.b.y) ||
                         std::min(a.y, b.y) > std::max(piece.a.y, piece.b.y)))
        return;
      const Point d = b - a;
      if (!piece.arc)
        {
          const Point  e   = piece.b - piece.a;
          const double den = cross(d, e);
          if (std::abs(den) <= 1e-14 * norm(d) * norm(e))
            return; // parallel: a segment along the boundary stays on it
          const double t = cross(piece.a - a, e) / den, s = cross(piece.a - a, d) / den;
          if (t >= 0. && t <= 1. && s >= 0. && s <= 1.)
            out.push_back(t);
          return;
        }
      double t[2];
      for (int k = 0, n = circle_roots(a, d, piece.centre, piece.radius, t); k < n; ++k)
        if (t[k] >= 0. && t[k] <= 1. && piece.spans(a + t[k] * d))
          out.push_back(t[k]);
    }

    /// Crossing-number test of p against the closed polygon v.
    bool in_polygon(const std::vector<Point> &v, Point p)
    {
      bool inside = false;
      for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++)
        if ((v[i].y > p.y) != (v[j].y > p.y) &&
            p.x < (v[j].x - v[i].x) * (p.y - v[i].y) / (v[j].y - v[i].y) + v[i].x)
          inside = !inside;
      return inside;
    }

    std::string text(Point p)
    {
      std::ostringstream s;
      s << "(" << p.x << ", " << p.y << ")";
      return s.str();
    }

    /// The circle through three points (its centre; R via the caller).
    bool circumcentre(Point p, Point q, Point r, Point &c)
    {
      const Point  b = q - p, d = r - p;
      const double den = 2. * cross(b, d);
      if (!(std::abs(den) > 2e-12 * norm(b) * norm(d)))
        return false;
      const double bb = dot(b, b), dd = dot(d, d);
      c = p + (1. / den) * Point{d.y * bb - b.y * dd, b.x * dd - d.x * bb};
      return true;
    }
  } // namespace

  Piece Piece::segment(Point a, Point b)
  {
    Piece p;
    p.a = a;
    p.b = b;
    return p;
  }

  Piece Piece::circular(Point centre, double radius, double start, double sweep)
  {
    Piece p;
    p.arc    = true;
    p.centre = centre;
    p.radius = radius;
    p.start  = start;
    p.sweep  = sweep;
    p.a      = centre + radius * Point{std::cos(start), std::sin(start)};
    p.b      = std::abs(sweep) >= 2. * pi ? p.a : centre + radius * Point{std::cos(start + sweep), std::sin(start + sweep)};
    return p;
  }

  bool Piece::spans(Point p) const
  {
    if (std::abs(sweep) >= 2. * pi)
      return true;
    const double phi = angle_of(p - centre);
    const double rel = sweep > 0. ? ccw_angle(start, phi) : ccw_angle(phi, start);
    return rel <= std::abs(sweep) * (1. + 1e-12) || rel >= 2. * pi * (1. - 1e-12);
  }

  double Piece::distance(Point p) const
  {
    if (!arc)
      return distance_to_segment(p, a, b);
    if (spans(p))
      return std::abs(norm(p - centre) - radius);
    return std::min(norm(p - a), norm(p - b));
  }

  Box Piece::bounding_box() const
  {
    Box box{std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
    if (arc)
      for (int k = 0; k < 4; ++k)
        {
          const Point extreme = centre + radius * Point{std::cos(k * pi / 2.), std::sin(k * pi / 2.)};
          if (spans(extreme))
            box = {std::min(box.x_min, extreme.x), std::min(box.y_min, extreme.y), std::max(box.x_max, extreme.x),
                   std::max(box.y_max, extreme.y)};
        }
    return box;
  }

  bool Loop::circle(Circle &c) const
  {
    if (pieces.size() != 1 || !pieces[0].arc || std::abs(pieces[0].sweep) < 2. * pi)
      return false;
    c = {pieces[0].centre, pieces[0].radius};
    return true;
  }

  // The region inside the curve is the polygon of the piece ends, with the circular segment
  // between each arc and its chord added where the arc bulges out and removed where it bulges in:
  // inside = in_polygon XOR (in the circular segment of any arc), the segments being disjoint.
  bool Loop::encloses(Point p) const
  {
    Circle c;
    if (circle(c))
      return norm(p - c.centre) < c.radius;
    std::vector<Point> ends;
    for (const auto &piece : pieces)
      ends.push_back(piece.a);
    bool inside = in_polygon(ends, p);
    for (const auto &piece : pieces)
      if (piece.arc && norm(p - piece.centre) < piece.radius)
        {
          const Point  mid  = piece.centre + piece.radius * Point{std::cos(piece.start + 0.5 * piece.sweep),
                                                                  std::sin(piece.start + 0.5 * piece.sweep)};
          const double side = cross(piece.b - piece.a, p - piece.a), arc_side = cross(piece.b - piece.a, mid - piece.a);
          if (side * arc_side > 0.)
            inside = !inside;
        }
    return inside;
  }

  double Loop::distance(Point p) const
  {
    double d = infinity;
    for (const auto &piece : pieces)
      d = std::min(d, piece.distance(p));
    return d;
  }

  // Signed area by Green's theorem, 1/2 oint (x dy - y dx): a x b / 2 for a segment,
  // (c x (b - a) + R^2 sweep) / 2 for an arc.
  double Loop::area() const
  {
    double twice = 0.;
    for (const auto &piece : pieces)
      twice += piece.arc ? cross(piece.centre, piece.b - piece.a) + piece.radius * piece.radius * piece.sweep
                         : cross(piece.a, piece.b);
    return 0.5 * std::abs(twice);
  }

  Box Loop::bounding_box() const
  {
    Box box{infinity, infinity, -infinity, -infinity};
    for (const auto &piece : pieces)
      {
        const Box b = piece.bounding_box();
        box         = {std::min(box.x_min, b.x_min), std::min(box.y_min, b.y_min), std::max(box.x_max, b.x_max),
                       std::max(box.y_max, b.y_max)};
      }
    return box;
  }

  Polyline Loop::sampled(double step) const
  {
    Polyline out;
    for (const auto &piece : pieces)
      {
        out.push_back(piece.a);
        if (piece.arc)
          {
            const int n = std::max(1, int(std::ceil(std::abs(piece.sweep) / step)));
            for (int k = 1; k < n; ++k)
              {
                const double phi = piece.start + piece.sweep * k / n;
                out.push_back(piece.centre + piece.radius * Point{std::cos(phi), std::sin(phi)});
              }
          }
      }
    out.push_back(pieces.front().a);
    return out;
  }

  Point Loop::centre() const
  {
    Circle c;
    if (circle(c))
      return c.centre;
    const Polyline v = sampled(0.01);
    double         a = 0.;
    Point          m;
    for (std::size_t k = 0; k + 1 < v.size(); ++k)
      {
        const double w = cross(v[k], v[k + 1]);
        a += w;
        m = m + (w / 3.) * (v[k] + v[k + 1]);
      }
    return (1. / a) * m;
  }

  namespace
  {
    Loop rectangle(const Box &b)
    {
      const Point corners[4] = {{b.x_min, b.y_min}, {b.x_max, b.y_min}, {b.x_max, b.y_max}, {b.x_min, b.y_max}};
      Loop        loop;
      for (int k = 0; k < 4; ++k)
        loop.pieces.push_back(Piece::segment(corners[k], corners[(k + 1) % 4]));
      return loop;
    }

    std::vector<Loop> circles(const std::vector<Circle> &holes)
    {
      std::vector<Loop> loops;
      for (const auto &c : holes)
        loops.push_back({{Piece::circular(c.centre, c.radius, 0., 2. * pi)}});
      return loops;
    }
  } // namespace

  Body::Body(const Box &outline, const std::vector<Circle> &holes)
    : Body(rectangle(outline), circles(holes))
  {}

  Body::Body(Loop o, std::vector<Loop> h)
    : outer(std::move(o))
    , inner(std::move(h))
    , box(outer.bounding_box())
    , tolerance(1e-12 * std::max(box.width(), box.height()))
  {}

  bool Body::contains(Point p) const
  {
    if (!outer.encloses(p) && outer.distance(p) > tolerance)
      return false;
    return std::none_of(inner.begin(), inner.end(),
                        [&](const Loop &hole) { return hole.encloses(p) && hole.distance(p) > tolerance; });
  }

  double Body::clearance(Point p) const { return std::min(outer.distance(p), hole_clearance(p)); }

  double Body::hole_clearance(Point p) const
  {
    double d = infinity;
    for (const auto &hole : inner)
      d = std::min(d, hole.distance(p));
    return d;
  }

  Body::Crossing Body::crossing(Point a, Point b, double allowed) const
  {
    // A segment between two points outside a circle enters it where it comes closer to the
    // centre than the radius.
    Circle c;
    for (const auto &hole : inner)
      if (hole.circle(c) && distance_to_segment(c.centre, a, b) < c.radius - allowed)
        return Crossing::hole;
    std::vector<double> t;
    for (const auto &piece : outer.pieces)
      intersections(a, b, piece, t);
    for (const auto &hole : inner)
      if (!hole.circle(c))
        for (const auto &piece : hole.pieces)
          intersections(a, b, piece, t);
    if (t.empty())
      return Crossing::none;
    t.push_back(0.);
    t.push_back(1.);
    std::sort(t.begin(), t.end());
    for (std::size_t k = 0; k + 1 < t.size(); ++k)
      {
        if (t[k + 1] - t[k] <= 1e-12)
          continue;
        const Point m = a + (0.5 * (t[k] + t[k + 1])) * (b - a);
        if (!outer.encloses(m) && outer.distance(m) > allowed)
          return Crossing::outline;
        for (const auto &hole : inner)
          if (hole.encloses(m) && hole.distance(m) > allowed)
            return Crossing::hole;
      }
    return Crossing::none;
  }

  double Body::ray_to_outline(Point x, Point e) const
  {
    const double step = 1e3 * tolerance;
    double       best = infinity;
    const auto   consider = [&](double t) {
      if (t < -step || t >= best)
        return;
      if (!outer.encloses(x + (t + step) * e)) // leaving, not entering
        best = std::max(t, 0.);
    };
    for (const auto &piece : outer.pieces)
      if (!piece.arc)
        {
          const Point  d   = piece.b - piece.a;
          const double den = cross(e, d);
          if (den == 0.)
            continue;
          const double t = cross(piece.a - x, d) / den, s = cross(piece.a - x, e) / den;
          if (s >= 0. && s <= 1.)
            consider(t);
        }
      else
        {
          double t[2];
          for (int k = 0, n = circle_roots(x, e, piece.centre, piece.radius, t); k < n; ++k)
            if (piece.spans(x + t[k] * e))
              consider(t[k]);
        }
    return best;
  }

  // The points within `margin` of a piece form a capsule (segment) or a thick arc; the ray enters
  // it first through one of its offset curves (lines or circles R +- margin within the span) or
  // one of the disks of radius `margin` about the piece's ends.
  Body::HoleHit Body::ray_to_holes(Point x, Point e, double margin) const
  {
    HoleHit    best{infinity, 0};
    const auto consider = [&](double t, std::size_t hole) {
      if (t >= 0. && t < best.t)
        best = {t, hole};
    };
    const auto disk = [&](Point c, double R, std::size_t hole) {
      double t[2];
      if (margin > 0. && circle_roots(x, e, c, R, t) == 2)
        consider(t[0], hole);
    };
    for (std::size_t h = 0; h < inner.size(); ++h)
      for (const auto &piece : inner[h].pieces)
        {
          if (piece.distance(x) <= margin)
            {
              consider(0., h);
              continue;
            }
          if (!piece.arc)
            {
              const Point  u = unit(piece.b - piece.a), n = left_normal(u);
              const double length = norm(piece.b - piece.a), en = dot(e, n);
              if (en != 0.)
                for (double side : {-1., 1.})
                  {
                    const double t = (side * margin - dot(x - piece.a, n)) / en;
                    const double s = dot(x + t * e - piece.a, u);
                    if (s >= 0. && s <= length)
                      consider(t, h);
                  }
              disk(piece.a, margin, h);
              disk(piece.b, margin, h);
              continue;
            }
          for (double R : {piece.radius + margin, piece.radius - margin})
            {
              double t[2];
              if (R > 0.)
                for (int k = 0, n = circle_roots(x, e, piece.centre, R, t); k < n; ++k)
                  if (piece.spans(x + t[k] * e))
                    consider(t[k], h);
            }
          if (std::abs(piece.sweep) < 2. * pi)
            {
              disk(piece.a, margin, h);
              disk(piece.b, margin, h);
            }
        }
    return best;
  }

  double Body::area() const
  {
    double a = outer.area();
    for (const auto &hole : inner)
      a -= hole.area();
    return a;
  }

  std::string Body::hole_name(std::size_t hole) const { return "the hole at " + text(inner.at(hole).centre()); }

  namespace
  {
    constexpr double sharp_turn = 50. * pi / 180.; ///< a turn at least this sharp is a corner
    constexpr double collinear  = 1e-10;           ///< sin of the turn below which edges are collinear

    /// Signed turn from edge (p, q) to edge (q, r).
    double turn(Point p, Point q, Point r) { return std::atan2(cross(q - p, r - q), dot(q - p, r - q)); }

    /// The arc through the run v[0..n-1] (at least 4 points on one circle). A whole circle's
    /// centre is the mean of its vertices (the centroid of the inscribed polygon), summed in the
    /// order of `by_index` (the mesh's vertex order: the same bits whatever vertex a loop starts at).
    Piece arc_through(const std::vector<Point> &v, bool closed, const std::vector<Point> &by_index = {})
    {
      const std::size_t n = v.size();
      Point             c;
      if (closed)
        {
          for (const auto &p : by_index)
            c = c + p;
          c = (1. / by_index.size()) * c;
        }
      else
        circumcentre(v[0], v[n / 3], v[(2 * n) / 3], c);
      double R = 0., sweep = 0.;
      for (std::size_t k = 0; k < n; ++k)
        R = std::max(R, norm(v[k] - c));
      for (std::size_t k = 0; k + 1 < n; ++k)
        sweep += std::atan2(cross(v[k] - c, v[k + 1] - c), dot(v[k] - c, v[k + 1] - c));
      if (closed)
        sweep = sweep > 0. ? 2. * pi : -2. * pi;
      Piece p = Piece::circular(c, R, angle_of(v[0] - c), sweep);
      p.a     = v[0];
      if (!closed)
        p.b = v[n - 1];
      return p;
    }

    /// The pieces of the closed polygon v (no repeated last vertex): runs of collinear edges
    /// become segments, runs of at least three edges on one circle turning the same way become
    /// arcs, a polygon on one circle without corners becomes the circle.
    Loop fit_loop(const std::vector<Point> &v, const std::vector<Point> &by_index)
    {
      const std::size_t   n  = v.size();
      const auto          at = [&](std::size_t k) { return v[k % n]; };
      std::vector<double> alpha(n); // turn at each vertex
      for (std::size_t k = 0; k < n; ++k)
        alpha[k] = turn(at(k + n - 1), at(k), at(k + 1));
      const auto flat = [](double a) { return std::abs(std::sin(a)) <= collinear && std::cos(a) > 0.; };

      // Without corners, a circle?
      const auto corner = std::find_if(alpha.begin(), alpha.end(), [](double a) { return std::abs(a) >= sharp_turn; });
      if (corner == alpha.end() && n >= 4)
        {
          Point c;
          if (circumcentre(v[0], v[n / 3], v[(2 * n) / 3], c) &&
              std::all_of(v.begin(), v.end(),
                          [&](Point p) { return std::abs(norm(p - c) - norm(v[0] - c)) <= 1e-6 * norm(v[0] - c); }) &&
              std::all_of(alpha.begin(), alpha.end(), [&](double a) { return !flat(a) && a * alpha[0] > 0.; }))
            return Loop{{arc_through(v, true, by_index)}};
        }

      // Runs from a corner (or vertex 0), so that no run but a smooth one wraps around the start.
      const std::size_t  s = corner == alpha.end() ? 0 : std::size_t(corner - alpha.begin());
      Loop               loop;
      std::vector<Point> run = {at(s)};
      enum class Kind { edge, straight, curved } kind = Kind::edge;
      Point              c;
      double             R = 0., first_turn = 0.;
      const auto         extends = [&](Point w, double a) {
        switch (kind)
          {
            case Kind::edge:
              if (flat(a))
                kind = Kind::straight;
              else if (std::abs(a) < sharp_turn && circumcentre(run[0], run[1], w, c))
                kind = Kind::curved, R = norm(run[0] - c), first_turn = a;
              return kind != Kind::edge;
            case Kind::straight:
              return flat(a);
            case Kind::curved:
              return !flat(a) && std::abs(a) < sharp_turn && a * first_turn > 0. && std::abs(norm(w - c) - R) <= 1e-6 * R;
          }
        return false;
      };
      const auto close_run = [&] {
        if (kind == Kind::curved && run.size() >= 4)
          loop.pieces.push_back(arc_through(run, false));
        else if (kind == Kind::straight)
          loop.pieces.push_back(Piece::segment(run.front(), run.back()));
        else
          for (std::size_t k = 0; k + 1 < run.size(); ++k)
            loop.pieces.push_back(Piece::segment(run[k], run[k + 1]));
        run  = {run.back()};
        kind = Kind::edge;
      };
      for (std::size_t j = 1; j <= n; ++j)
        {
          const Point w = at(s + j);
          if (run.size() >= 2 && !extends(w, alpha[(s + j - 1) % n]))
            close_run();
          run.push_back(w);
        }
      close_run();
      // Without a corner the last run may continue the first one.
      if (corner == alpha.end() && loop.pieces.size() > 1)
        {
          const Piece &first = loop.pieces.front(), &last = loop.pieces.back();
          const bool   one_line = !first.arc && !last.arc && flat(turn(last.a, first.a, first.b));
          const bool   one_arc  = first.arc && last.arc && norm(first.centre - last.centre) <= 1e-6 * first.radius &&
                               std::abs(first.radius - last.radius) <= 1e-6 * first.radius && first.sweep * last.sweep > 0.;
          if (one_line || one_arc)
            {
              Piece merged = one_line ? Piece::segment(last.a, first.b)
                                      : Piece::circular(last.centre, std::max(first.radius, last.radius), last.start,
                                                        last.sweep + first.sweep);
              merged.a            = last.a;
              merged.b            = first.b;
              loop.pieces.front() = merged;
              loop.pieces.pop_back();
            }
        }
      return loop;
    }
  } // namespace

  Body body_from_edges(const std::vector<Point> &vertices, const std::vector<std::array<std::size_t, 2>> &edges)
  {
    std::map<std::size_t, std::vector<std::size_t>> next;
    for (const auto &e : edges)
      {
        next[e[0]].push_back(e[1]);
        next[e[1]].push_back(e[0]);
      }
    for (const auto &[v, n] : next)
      if (n.size() != 2)
        throw InvalidParameter("Mesh boundary", text(vertices.at(v)),
                               "the boundary must be closed curves, but " + std::to_string(n.size()) +
                                 " boundary edges meet at this vertex");
    std::map<std::size_t, bool> used;
    std::vector<Loop>           loops;
    for (const auto &[first, unused] : next)
      {
        if (used[first])
          continue;
        std::vector<Point>       ring;
        std::vector<std::size_t> indices;
        std::size_t              previous = first, current = first;
        do
          {
            used[current] = true;
            ring.push_back(vertices.at(current));
            indices.push_back(current);
            const auto &n    = next[current];
            const std::size_t step = n[0] == previous && current != first ? n[1] : n[0];
            previous               = current;
            current                = step;
          }
        while (current != first);
        if (ring.size() < 3)
          throw InvalidParameter("Mesh boundary", text(ring.front()), "a boundary curve needs at least 3 edges");
        std::sort(indices.begin(), indices.end());
        std::vector<Point> by_index;
        for (const auto i : indices)
          by_index.push_back(vertices[i]);
        loops.push_back(fit_loop(ring, by_index));
      }
    if (loops.empty())
      throw InvalidParameter("Mesh boundary", "no boundary edges", "the mesh has no boundary");
    const auto outer = std::max_element(loops.begin(), loops.end(),
                                        [](const Loop &a, const Loop &b) { return a.area() < b.area(); });
    Loop              outline = *outer;
    loops.erase(outer);
    for (const auto &loop : loops)
      if (const Point p = loop.pieces.front().a; !outline.encloses(p))
        throw InvalidParameter("Mesh boundary", text(p),
                               "this boundary curve lies outside the largest one: the mesh has more than one piece, "
                               "and a scene is one connected body");
    for (const auto &hole : loops)
      for (const auto &loop : loops)
        if (const Point p = loop.pieces.front().a; &loop != &hole && hole.encloses(p))
          throw InvalidParameter("Mesh boundary", text(p),
                                 "this boundary curve lies inside the hole bounded by the curve through " +
                                   text(hole.pieces.front().a) +
                                   ": the mesh has a piece inside a hole, and a scene is one connected body");
    return Body(std::move(outline), std::move(loops));
  }
} // namespace pumpd::geometry
