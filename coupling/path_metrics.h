// Distances between two crack paths (polylines), for comparing a computed path with a published
// one. Both curves are sampled at a fixed arc-length step; d(p, C) is the distance from the point
// p to the polyline C.
//   directed max:     max_{a in A} d(a, B)
//   Hausdorff:        max(directed max A->B, directed max B->A)
//   symmetric mean:   (mean_{a in A} d(a, B) + mean_{b in B} d(b, A)) / 2, means over arc length
#pragma once

#include "geometry.h"

namespace pumpd::coupling
{
  struct PathDistance
  {
    double mean      = 0.; ///< symmetric mean distance [m]
    double hausdorff = 0.; ///< [m]
  };

  /// Distance from p to the polyline (infinity for an empty one, |p - q| for a single point q).
  double distance_to_polyline(geometry::Point p, const geometry::Polyline &line);
  /// Largest distance of the vertices of `from` from the polyline `to`.
  double directed_max_distance(const geometry::Polyline &from, const geometry::Polyline &to);
  /// The first `length` [m] of the polyline (all of it if shorter).
  geometry::Polyline truncate(const geometry::Polyline &line, double length);
  /// The polyline up to its point nearest to x (the part of a computed path that a shorter
  /// reference path covers: arc lengths differ when the reference is a lattice staircase).
  geometry::Polyline up_to_nearest(const geometry::Polyline &line, geometry::Point x);
  /// Symmetric mean and Hausdorff distance, both curves sampled every `step` [m] (> 0).
  PathDistance path_distance(const geometry::Polyline &a, const geometry::Polyline &b, double step);
  /// A computed path against a published one over the published extent: path_distance of our
  /// path up to its point nearest the published tip, and the published path.
  PathDistance published_distance(const geometry::Polyline &path, const geometry::Polyline &published, double step);
  /// Two computed paths over the shorter one's extent: published_distance of the longer against
  /// the shorter, sampled every thousandth of the longer of the two (the longer cut as there).
  PathDistance trade_distance(const geometry::Polyline &a, const geometry::Polyline &b);
} // namespace pumpd::coupling
