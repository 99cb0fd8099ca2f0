// The body of a specimen: the material inside its outline and outside its holes, each a closed
// boundary curve of straight segments and circular arcs (DESIGN.md, "The scene and the methods").
// Everything that asks "is this point in the body, how far is the boundary, does this bond or
// crack segment leave the material, where does this ray meet the boundary" asks a Body: the PD
// lattice and its bonds, the box clipping, the arrival of a crack at a hole or the outline, the
// crack's mouths and tips.
//
// A body comes from the boundary edges of a mesh (body_from_edges): the mesh of a curved boundary
// is a polygon whose vertices lie on the curve, and runs of vertices on one circle become that
// circle's arc again, so that a drilled hole is a circle, not the polygon inscribed in it.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "geometry.h"

namespace pumpd::geometry
{
  /// A piece of a boundary curve, from a to b: a straight segment, or the arc about `centre` of
  /// `radius` from the polar angle `start` over `sweep` (counter-clockwise when > 0; a full circle
  /// has |sweep| = 2 pi and a = b).
  struct Piece
  {
    Point  a, b;
    bool   arc = false;
    Point  centre;
    double radius = 0., start = 0., sweep = 0.;

    static Piece segment(Point a, Point b);
    static Piece circular(Point centre, double radius, double start, double sweep);

    double distance(Point p) const;
    Box    bounding_box() const;
    /// True if the polar angle of p about the centre lies within the arc's sweep.
    bool spans(Point p) const;
  };

  /// A closed boundary curve: its pieces end to end.
  struct Loop
  {
    std::vector<Piece> pieces;

    /// Strictly inside the curve.
    bool   encloses(Point p) const;
    double distance(Point p) const;
    double area() const;
    Box    bounding_box() const;
    /// True if the loop is one circle; then c is that circle.
    bool circle(Circle &c) const;
    /// The centre of a circle, else the centroid of the enclosed area.
    Point centre() const;
    /// Points along the curve, arcs sampled at least every `step` radians (for plots).
    Polyline sampled(double step = 0.1) const;
  };

  class Body
  {
  public:
    Body() = default;
    /// A rectangle minus circular holes.
    Body(const Box &outline, const std::vector<Circle> &holes = {});
    Body(Loop outline, std::vector<Loop> holes);

    const Loop              &outline() const { return outer; }
    const std::vector<Loop> &holes() const { return inner; }

    /// True where there is material: inside the outline or on it, outside every hole.
    bool contains(Point p) const;
    /// Distance from p to the nearest boundary curve (outline or hole).
    double clearance(Point p) const;
    /// Distance from p to the nearest hole (infinity without holes).
    double hole_clearance(Point p) const;
    /// Whether the segment [a, b], both ends in the material, leaves it: some stretch of it lies
    /// outside the outline or inside a hole by more than `tolerance` (touching does not count).
    enum class Crossing
    {
      none,
      outline,
      hole
    };
    Crossing crossing(Point a, Point b, double tolerance = 0.) const;
    bool     crosses_boundary(Point a, Point b, double tolerance = 0.) const
    {
      return crossing(a, b, tolerance) != Crossing::none;
    }
    /// For x in the body and a unit e: the first t >= 0 at which x + t e leaves the body through
    /// the outline (infinity if it does not).
    double ray_to_outline(Point x, Point e) const;
    /// The first t >= 0 at which x + t e comes within `margin` of a hole (0 if x is that close
    /// already), and which hole; t = infinity if none.
    struct HoleHit
    {
      double      t    = 0.;
      std::size_t hole = 0;
    };
    HoleHit ray_to_holes(Point x, Point e, double margin) const;

    const Box &bounding_box() const { return box; }
    double     area() const;
    /// "the hole at (x, y)" (its centre), for messages.
    std::string hole_name(std::size_t hole) const;

  private:
    Loop              outer;
    std::vector<Loop> inner;
    Box               box;         ///< of the outline
    double            tolerance;   ///< "on the boundary": 1e-12 of the larger side of the box
  };

  /// The body bounded by the given edges (pairs of indices into `vertices`), which must form
  /// closed curves: the one with the largest area is the outline, the others are holes. Runs of
  /// at least three edges whose vertices lie on one circle and turn by less than 50 degrees at
  /// each become arcs, collinear runs become one segment. Throws InvalidParameter ("Mesh
  /// boundary") if an edge end does not close up or the edges bound more than one piece (a curve
  /// outside the outline, or one inside a hole).
  Body body_from_edges(const std::vector<Point> &vertices, const std::vector<std::array<std::size_t, 2>> &edges);
} // namespace pumpd::geometry
