// A crack in the global problem: a polyline that grows at its tips (DESIGN.md, global/).
// Plain geometry, no deal.II: level sets, tip frames and the enrichment functions' values.
//
// Ends: an end on the body's boundary (outline or a hole's rim) is a mouth, an end joined to another
// crack's face (join()) a junction, any other end a tip. A crack given to the constructor needs a
// tip (with both ends on the boundary it has nothing to grow); growth may leave none (a tip that
// reaches the outline or joins another crack). Level sets:
//   phi(x): signed distance to the crack extended by the rays tangent to its end segments;
//           + on the left of the polyline (walking from the first to the last vertex). At a point
//           whose nearest crack point is an interior vertex the sign comes from the
//           pseudo-normal (the mean of the two adjacent segment normals).
//   tip frame: position, unit direction of propagation (along the end segment, outward).
//   (r, theta) about a tip: r = |x - tip|, theta = side(x) acos((x - tip).d / r) in [-pi, pi],
//           so theta = +-pi on the crack faces even when the crack behind the tip is kinked.
//   H(x): the Heaviside function, sign(phi). Beyond a junction (across the crack it joined, by that
//           crack's level set, and ahead of the junction along the joined end) it is the constant
//           H has next to that face on the far side, so that the joined crack does not run on
//           through the crack it joined (Daux et al. 2000, the junction function).
// Branch functions (Fleming et al. 1997; Moes et al. 1999):
//   F1 = sqrt(r) sin(t/2), F2 = sqrt(r) cos(t/2), F3 = sqrt(r) sin(t/2) sin t, F4 = sqrt(r) cos(t/2) sin t
// with grad theta = side(x) sign(y') grad(polar angle), y' the coordinate normal to the tip direction.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "body.h"
#include "segment_tree.h"

namespace pumpd::global
{
  using geometry::Point;

  struct Tip
  {
    Point       position;
    Point       direction;  ///< unit vector, pointing away from the crack
    std::size_t vertex = 0; ///< index of the tip vertex in vertices() (0 or last)
  };

  /// Values and gradients of the four branch functions at a point.
  struct BranchValues
  {
    std::array<double, 4> value{};
    std::array<Point, 4>  gradient{};
  };

  class Crack
  {
  public:
    /// Throws InvalidParameter ("Crack", with the reason) if there are fewer than 2 vertices, two
    /// consecutive vertices coincide, the polyline intersects itself, a vertex lies outside the
    /// body outline or inside a hole, a segment crosses the outline or a hole, or no end is a
    /// tip. tolerance decides "on the boundary".
    Crack(geometry::Polyline vertices, const geometry::Body &body, double tolerance);

    const geometry::Polyline &vertices() const { return points; }
    const std::vector<Tip>   &tips() const { return tip_list; }
    double                    length() const;

    double signed_distance(Point x) const;
    /// +1 where signed_distance >= 0, -1 elsewhere, and constant beyond a junction: the Heaviside
    /// (junction) function.
    int side(Point x) const;
    /// True where side() is a junction's constant (see the level sets above).
    bool beyond_junction(Point x) const;
    /// (r, theta) of x about tip t.
    std::array<double, 2> polar(Point x, std::size_t t) const;
    BranchValues          branch_functions(Point x, std::size_t t) const;
    /// Index of the tip nearest to x.
    std::size_t nearest_tip(Point x) const;
    /// Distance from x to the polyline (its segments, not their extensions).
    double distance(Point x) const;

    /// Extends tip t to new_position (a new segment). Throws InvalidParameter if the new segment
    /// crosses the crack or leaves the body; the tip frame follows the new segment.
    void grow(std::size_t t, Point new_position);
    /// Extends tip t to `at` (as grow; not if the tip lies there already) on the face of `other`
    /// and ends it there: that end becomes a junction and the tip disappears. Throws
    /// InvalidParameter if `at` lies farther than the tolerance from `other`.
    void join(std::size_t t, Point at, const Crack &other);
    /// Whether the first / the last vertex is a junction.
    std::array<bool, 2> junctions() const { return {{junction[0].has_value(), junction[1].has_value()}}; }

  private:
    /// Where an end joined another crack: H is `beyond` where (x - at).d > 0 and x lies on the
    /// other side of the other crack (its level set, as it was at the join) than this crack.
    struct Junction
    {
      Point              at;
      Point              d; ///< the direction of the joined end, out of the crack (into the other crack)
      geometry::Polyline    face;          ///< the other crack's polyline
      geometry::SegmentTree face_interior; ///< of `face`, for its signed distance
      int                near = 1;  ///< the sign of the other crack's level set on this crack's side
      int                beyond = 1;
    };

    /// The segment tree and the tips after the vertices changed.
    void update();
    /// The junction whose constant H takes at x, if any.
    const Junction *junction_beyond(Point x) const;

    geometry::Polyline                     points;
    geometry::Body                         body;
    double                                 tol;
    geometry::SegmentTree                  interior; ///< of the segments between the end segments
    std::vector<Tip>                       tip_list;
    std::array<std::optional<Junction>, 2> junction{}; ///< at the first / the last vertex
  };
} // namespace pumpd::global
