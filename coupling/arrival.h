// Where a growing crack path ends its growth (every method): at a hole or at the outline, or on
// another crack's face (it joins that crack there).
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "body.h"

namespace pumpd::coupling
{
  /// Why a tip stopped, one wording for every method: "the tip at (x, y) <what>".
  std::string tip_stop(geometry::Point tip, const std::string &what);

  /// What the run's end line says of its cracks: each crack that grew (every crack when none did)
  /// with its number (with several), its length and where each of its grown ends is (of one that
  /// did not grow: its tips, the ends more than `tolerance` from the boundary), e.g. "crack 2
  /// 0.052 m, tip at (0.1, 0.05)". `initial` are the scene's cracks, `cracks` the run's, in order
  /// (a crack past the initial ones formed in the run: every end of it grew); an end grew if it
  /// lies more than `tolerance` from both ends of its initial crack.
  std::string grown_cracks_text(const std::vector<geometry::Polyline> &initial,
                                const std::vector<geometry::Polyline> &cracks, const geometry::Body &body,
                                double tolerance);

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

  /// Where a growing tip meets another crack: that crack's index, the point on its face, and the
  /// index of the path segment that reaches it.
  struct CrackMeeting
  {
    std::size_t     crack = 0, segment = 0;
    geometry::Point at;
  };

  /// The first point where from + t e (0 <= t <= t_max) meets a crack other than `skip`: (t, crack),
  /// or (infinity, skip).
  std::pair<double, std::size_t> ray_to_cracks(geometry::Point from, geometry::Point e, double t_max,
                                               const std::vector<geometry::Polyline> &cracks, std::size_t skip);

  /// Where the path first crosses a crack other than `own`, if it does.
  std::optional<CrackMeeting> first_crossing(const geometry::Polyline &path,
                                             const std::vector<geometry::Polyline> &cracks, std::size_t own);

  /// The nearest point of a crack other than `own` within `reach` of the path's end and ahead of
  /// its last segment (segment: the last), if there is one.
  std::optional<CrackMeeting> face_ahead(const geometry::Polyline &path, const std::vector<geometry::Polyline> &cracks,
                                         std::size_t own, double reach);
} // namespace pumpd::coupling
