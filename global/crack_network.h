// The cracks of a body as a network: which ends are junctions on which crack, and whether the
// cracks cut a piece off the body. Plain geometry, no deal.II.
//
// The network is a graph whose nodes are the boundary's components (the outline, each hole's
// rim) and the cracks, with an edge for every mouth (crack - the component it opens on) and every
// junction (crack - the crack it joined). A cycle of this graph is a closed loop of crack faces and
// boundary arcs: it cuts a piece off the body. A crack from the outline to a hole closes none (it
// joins two components); a second one between them, an edge crack with both ends on the outline
// or one joined to a crack that opens on the outline does.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "body.h"
#include "crack.h"

namespace pumpd::global
{
  /// The boundary curve an end of a crack opens on: 0 the outline (within `tolerance` of it),
  /// 1 + h hole h (within `hole_margin` + `tolerance` of its rim); none for an end off the boundary.
  std::optional<std::size_t> boundary_curve(const geometry::Body &body, Point end, double tolerance,
                                            double hole_margin = 0.);

  /// True if the cracks, through their mouths and junctions, cut a piece off the body; ends
  /// within `tolerance` of the outline, or within `hole_margin` + `tolerance` of a hole's rim (where
  /// growth stops a tip that reached the hole), open on it.
  bool cuts_off_a_piece(const std::vector<Crack> &cracks, const geometry::Body &body, double tolerance,
                        double hole_margin = 0.);

  /// Why growth stops when cuts_off_a_piece: "the crack cut the body through" (or "the cracks").
  std::string cut_through_message(const std::vector<Crack> &cracks);

  /// Joins every tip that lies within `tolerance` of another crack's face to that crack (Crack::join):
  /// the junctions of cracks rebuilt from their polylines.
  void join_touching(std::vector<Crack> &cracks, double tolerance);
} // namespace pumpd::global
