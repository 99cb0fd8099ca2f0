// The single-edge-notched tension (SENT) strip of the global tests: W = 1, [0, 1] x [-2, 2],
// an edge crack on y = 0 from x = 0, unit traction pulling the ends apart, rigid motions held at
// the right corners; and Tada's handbook K_I for it.
#pragma once

#include <cmath>

#include "elasticity.h"

namespace pumpd::sent_strip
{
  /// Brown & Srawley's fit for the SENT specimen (Tada, Paris & Irwin, to 0.5 % for a / W <= 0.6),
  /// s = a / W: K_I = sigma sqrt(pi a) F(s).
  inline double geometry_factor(double s)
  {
    return 1.12 - 0.231 * s + 10.55 * s * s - 21.72 * std::pow(s, 3) + 30.39 * std::pow(s, 4);
  }

  /// Unit traction on the top (boundary id 3) and bottom (2) ends; (1, -2) fixed, (1, 2) held in x.
  inline void load(global::EnrichedElasticity &problem)
  {
    problem.add_traction(3, [](geometry::Point) { return geometry::Point{0., 1.}; });
    problem.add_traction(2, [](geometry::Point) { return geometry::Point{0., -1.}; });
    problem.add_dirichlet_vertex({1., -2.}, {0., 0.});
    problem.add_dirichlet_vertex({1., 2.}, {0., 0.}, true, false);
  }
} // namespace pumpd::sent_strip
