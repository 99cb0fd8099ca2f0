// The resolution of each PD box, chosen by what lies ahead of the crack tip (DESIGN.md,
// coupling/). A PD box resolves the tip with its horizon delta: the tip's family (one
// horizon), and the surface layer of a hole or edge, where the families miss bonds and the
// material is softer than the continuum it is coupled to (one horizon, Le & Bobaru 2018). The
// crack's path near a free surface is modelled, not an artefact of the two overlapping, when a
// free horizon of bulk lies between them: clearance >= 3 delta. A hole's stress concentration
// decays over its radius R, which the box resolves by the same count: R >= 3 delta. So the box's
// horizon is
//   delta_k = delta / 2^k,  k in [-max_doublings, max_halvings] the least with
//   c_k >= clearance_over_horizon * delta_k,
// c_k the least of the clearance (to holes and the outline) of the path the crack may take in
// this exchange (the segment from the tip along its direction over the maximum advance plus one
// horizon) and the radius of every hole the box reaches (BoxPolicy::smallest_hole_within_reach),
// the path and the box at delta_k where it is coarser than delta, at delta where it is finer. A
// doubled box must fit into the body, and its path must keep the clearance from the other
// cracks' faces too (at the section's horizon and below, a trace that comes within a horizon of
// a face ends on it and joins it). A doubled box takes half as many exchanges for the same crack
// length; its path is that of the coarser horizon (the path converges with the horizon,
// docs/ingraffea.md), so doubling is a choice of the speed/accuracy trade, off by default.
// Each box is its own PD problem, so delta changes from one exchange to the next without the
// ghost forces of a variable horizon within one body (Silling, Littlewood, Seleson 2015). The
// box, its margin, the maximum advance per exchange and the near distance scale with delta_k, the
// minimum advance where delta_k is coarser than delta (a finer box keeps the section's, capped at
// half its allowed advance); the spacing is delta_k / m.
//
// A tip that must kink gets the horizon its first kink needs, while it has not grown. The first
// PD increment is one straight segment of s ~ 1.5-2 delta (docs/peridynamics.md, "The first kink
// of a mixed-mode crack"), the chord of a path that leaves the tip at the maximum hoop stress
// angle theta_c and then turns back towards mode I by an angle of the order of theta_c over the
// crack's own length scale a (the crack's length at an edge crack, half of it at an interior
// one): a curvature of about |theta_c| / a, whose chord over s departs from the tangent by
// s |theta_c| / (2 a) ~ delta |theta_c| / a. Within the kink tolerance eps:
//   delta_k <= eps a / |theta_c|,
// the least halving that reaches it, at most Maximum kink halvings. theta_c is the limit r -> 0
// of the direction of the largest hoop stress; the PD crack leaves the tip where its bonds fail,
// over the first increment, and follows the plate's own field there (beyond K_I and K_II: the
// T-stress, the outline), which may point elsewhere (single-edge-notch shear, tests/coupling/
// sens_test.cc). So the box's horizon is also halved until the largest hoop stress of the global
// solution on the circle of 1.5 delta_k about the tip (the middle of an accepted first increment,
// delta_k to 2 delta_k) lies within eps of theta_c. Once the tip has grown along its kink it runs
// nearly in mode I and its boxes return to the rule above.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "body.h"

namespace dealii
{
  class ParameterHandler;
}

namespace pumpd::coupling
{
  /// The subsection `Resolution` of `Global-local`.
  struct ResolutionSettings
  {
    std::string  rule                   = "clearance"; ///< clearance | fixed (the section Peridynamics' horizon)
    double       clearance_over_horizon = 3.;          ///< c / delta_k at least
    unsigned int max_halvings           = 1;
    unsigned int max_doublings          = 0;
    double       kink_tolerance         = 3.; ///< eps [deg]; 0: no kink halvings
    unsigned int max_kink_halvings      = 3;

    void add_parameters(dealii::ParameterHandler &prm);
  };

  /// Least distance from a hole or the outline along the segment tip + s d, s in [0, reach],
  /// sampled every `step` [m].
  double clearance_ahead(const geometry::Body &body, geometry::Point tip, geometry::Point direction, double reach,
                         double step);
  /// The same for the distance from the polylines `faces` (infinity if there are none).
  double clearance_ahead(const std::vector<geometry::Polyline> &faces, geometry::Point tip, geometry::Point direction,
                         double reach, double step);

  /// k, delta_k = delta / 2^k (k < 0: a doubling), where `clearance(scale)` is c_k measured with
  /// the path and the box of the horizon delta x scale (0 where that box does not fit); k = 0
  /// under the fixed rule.
  int horizon_halvings(const ResolutionSettings &settings, double horizon,
                       const std::function<double(double scale)> &clearance);

  /// The halvings of `horizon` a tip of a crack of length scale `crack_length` [m] needs to kink by
  /// `kink` [rad] (theta_c) within the kink tolerance: 0 under the fixed rule, without a tolerance,
  /// or where horizon |kink| / crack_length is within it.
  int kink_halvings(const ResolutionSettings &settings, double horizon, double kink, double crack_length);

  /// The least halving k of `horizon`, at most Maximum kink halvings, at which
  /// |hoop_direction(1.5 horizon / 2^k) - kink| <= eps (the maximum where none does): 0 under the
  /// fixed rule, without a tolerance, or where |kink| is within it.
  int field_kink_halvings(const ResolutionSettings &settings, double horizon, double kink,
                          const std::function<double(double r)> &hoop_direction);
} // namespace pumpd::coupling
