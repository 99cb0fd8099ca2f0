// Where a growing crack path ends its growth (every method): at a hole or at the outline.
#pragma once

#include <cstddef>
#include <string>

#include "body.h"

namespace pumpd::coupling
{
  struct Arrival
  {
    geometry::Polyline path;
    std::string        reason; ///< "" while the tip goes on
  };

  /// The path cut where it first comes within `margin` of a hole (segments from first_new - 1 on:
  /// the new ones), or extended to the outline when its last segment, continued, meets it within
  /// `reach`, or to a hole's margin within `hole_reach`: in a PD box a ligament shorter than a
  /// horizon is spanned by every bond, so it is not resolved and a tip heading into a hole that
  /// close has reached it.
  Arrival arrive(geometry::Polyline path, const geometry::Body &body, double margin, double reach,
                 std::size_t first_new = 0, double hole_reach = 0.);
} // namespace pumpd::coupling
