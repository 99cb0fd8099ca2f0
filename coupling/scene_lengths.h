// The length defaults of a scene, derived from its own lengths (README, "Lengths"): the PD
// horizon, and from it the box, the exchange's advances and the global problem's tip region; the
// LEFM growth increment. A scene file that sets an entry keeps it; `Scene/Length defaults =
// absolute` keeps every entry's own default (the published Ingraffea decks' lengths).
//
// The lengths measured (at the initial cracks, before any growth):
//   L  the body's smaller side (of its bounding box),
//   a  the crack's length at its tips, the least over the tips: an edge crack's whole length, half
//      an interior crack's (K ~ sqrt(pi a) in both),
//   R  the smallest hole's radius.
// The rule:
//   delta = min(L / 32, a / 4): a box of 8 delta covers at most a quarter of the body's smaller
//           side, and holds no more of the crack behind the tip (2.4 delta, Box tip position 0.3)
//           than 0.6 a, so that the crack it carries is the scene's, not the box's outline;
//   da    = min(a / 10, R / 2, L / 50): K ~ sqrt(a) changes by da / (2a) <= 5 % over an increment;
//           a hole's field, which varies over its radius, is crossed in two increments at least,
//           and no increment steps past a hole (2 R across); an explicit increment's path error, of
//           the order of da / 2 where the path turns, stays within 1 % of the body's side;
// each rounded down to a preferred number (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8 x 10^k). The box
// and the exchange keep the decks' proportions to the horizon (box 8 delta, margin 2 delta, a box
// grown for a hole 16 delta, advance delta to 2 delta, near distance 2 delta), and the global
// problem resolves the tip on the scale l of what grows the crack (l = delta, or da in LEFM
// growth): branch functions within 1.5 l (less than half the tip's clearance, at least the
// refined cell at the tip, which the branch functions need), cells refined
// within 2 l, and kept refined over 8 l of the path behind the tip. At delta = 4 mm these are the
// decks' values. Near holes and edges, and at a tip that must kink, each box refines its horizon
// further (resolution.h).
#pragma once

#include <limits>
#include <string>

namespace pumpd::coupling
{
  struct Scene;

  struct SceneLengths
  {
    double body_side     = 0.; ///< L [m]
    double crack_length  = std::numeric_limits<double>::infinity(); ///< a [m]; infinity without a crack
    double hole_radius   = std::numeric_limits<double>::infinity(); ///< R [m]; infinity without a hole
    double tip_clearance = std::numeric_limits<double>::infinity(); ///< least distance of a tip from the outline, a hole or another crack [m]
    double tip_cell      = 0.; ///< the largest diameter of the mesh's cell at a tip, before refinement [m]
  };

  SceneLengths measure_lengths(const Scene &scene);

  /// The largest preferred number (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8 x 10^k) at most x > 0.
  double preferred_below(double x);

  /// delta of the rule, and which length bounds it ("L / 32" or "a / 4").
  struct RuleLength
  {
    double      value = 0.;
    std::string bound;
  };
  RuleLength scene_horizon(const SceneLengths &lengths);
  /// da of the rule, and which length bounds it ("a / 10", "R / 2" or "L / 50").
  RuleLength scene_growth_increment(const SceneLengths &lengths);

  /// The proportions of the box, the exchange and the tip region to their length scale.
  namespace proportion
  {
    constexpr double box_size          = 8.;
    constexpr double box_margin        = 2.;
    constexpr double max_box_size      = 16.;
    constexpr double max_advance       = 2.;
    constexpr double min_advance       = 1.;
    constexpr double near_distance     = 2.;
    constexpr double tip_radius        = 1.5;
    constexpr double refinement_radius = 2.;
    constexpr double refinement_trail  = 8.;
  } // namespace proportion

  /// True for the entries ("Section/entry") whose default the rule derives.
  bool is_scene_length(const std::string &path);
} // namespace pumpd::coupling
