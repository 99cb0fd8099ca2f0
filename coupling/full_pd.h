// Full-domain PD: the whole Ingraffea beam as one PD body (what a user would otherwise run
// instead of the global-local cycle; issue 5, "The trade, measured").
//
// The PD box is the beam's outline, so there is no boundary layer: every box edge is a free
// surface. Holes and the initial crack (pre-broken bonds) as in the other scenes. Supports and
// load are prescribed regions (local::PrescribedRegion): the pin fixes ux = uy = 0 on the nodes
// within `support radius` of its point, the roller uy = 0, the load pad prescribes uy = -d on the
// nodes within that radius of the load point (ux free); bonds within `no-fail radius` of these
// points stay linear elastic (the pads would crush otherwise). Quasi-static states by dynamic
// relaxation at each displacement d; after each state the crack is traced from the initial tip
// (coupling::extract_crack) through the damage field, per node the largest damage of the accepted
// states (the softening is elastic up to the break stretch, so bonds behind the tip relax when
// the load falls after the peak; the crack they marked stays). The run stops where the crack
// reaches a hole (within the hole margin) or the outline, stops growing for good, or d reaches
// its maximum.
//
// Displacement steps (the rule the scene follows):
//  1. elastic: while no bond has passed its inflection stretch (max stretch ratio Z < 1) the
//     state is linear in d, so d jumps to the value where Z reaches `onset stretch ratio` (the
//     relaxed state scaled: exact, one DR state);
//  2. softening, no growth yet: dd = `first increment` d;
//  3. growth g in the last step: dd <- dd clamp(a_t / g, 1/2, 2), a_t = `target advance`; no
//     growth: dd <- 2 dd; always clamped to [`minimum increment` d, `maximum increment` d];
//  4. a step that grew the crack by more than `maximum advance` is undone (state restored) and
//     repeated with dd / 2 while dd is above the minimum and halving shortened the advance (by a
//     quarter at least); otherwise the growth is unstable (snap-back: under load-point
//     displacement the crack runs at any increment) and the step is accepted as it is.
// The predictor of each state: the elastic state scaled to the new d (phase 1), later the last
// state plus the last step's increment extrapolated to dd.
//
// Control. Under load-point displacement the beam snaps back once the crack grows: the
// equilibrium path turns back in d, and dynamic relaxation jumps to a far state (the crack runs
// into a hole). With `control = crack mouth opening` the steps above are taken in the
// crack-mouth opening w instead (phase 1 stays under d; w is proportional to it there), which
// grows monotonically along the whole path. The opening is read between two gauge nodes one
// `gauge distance` either side of the crack mouth (normal to the initial crack). A servo inside
// the relaxation (local::Servo) moves the pad whenever |w - w*| exceeds a tenth of the step: by
// gain (d/w)_0 (w* - w), and the whole body with it along the secant mode u_0 / d_0 ((d, u)_0
// the last accepted state), so that the beam's bending follows the pad at once instead of over
// the relaxation's slowest period; the relaxation settles the rest. A state is relaxed when the
// force residual is below the tolerance and w is within that tenth of w*.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "geometry.h"
#include "material.h"

namespace pumpd::coupling
{
  struct FullPdParameters
  {
    geometry::Box                 outline{0., 0., 0.508, 0.2032};
    std::vector<geometry::Circle> holes{{{0.1524, 0.06985}, 0.00635},
                                        {{0.1524, 0.12065}, 0.00635},
                                        {{0.1524, 0.17145}, 0.00635}};
    geometry::Polyline            initial_crack{{0.1016, 0.}, {0.1016, 0.0254}};
    geometry::Point               pin{0.0254, 0.}, roller{0.4826, 0.}, load_point{0.254, 0.2032};
    double                        support_radius = 0.; ///< [m]; 0: one horizon
    /// Bonds within this distance [m] of a support or load point stay linear elastic (a no-fail
    /// zone, local::PrescribedRegion::elastic_margin); 0: none, else >= the support radius. A
    /// point load P gives the Flamant stress 2 P / (pi r), above the PD strength
    /// (~K_c / sqrt(pi delta)) within a few cm at the beam's failure load: without the zone the
    /// pads crush before the notch cracks.
    double no_fail_radius = 0.04;

    local::MaterialParameters material;
    double                    horizon        = 0.004;
    int                       horizon_ratio  = 4;
    double                    tolerance      = 1e-5;
    std::size_t               max_iterations = 200000;
    double                    crack_damage   = 0.3;

    double      onset_stretch_ratio = 0.9;   ///< Z the elastic jump aims at, in [0.001, 1]
    double      first_increment     = 0.02;  ///< dd / d once bonds soften
    double      min_increment       = 0.002; ///< smallest dd / d
    double      max_increment       = 0.05;  ///< largest dd / d
    double      target_advance      = 0.;    ///< a_t [m]; 0: one horizon
    double      max_advance         = 0.;    ///< [m]; 0: four horizons (then the step is repeated)
    double      max_displacement    = 0.005; ///< [m], load-point displacement
    enum class Control
    {
      load_point,
      crack_mouth_opening
    } control                = Control::crack_mouth_opening;
    double      servo_gain     = 1.;    ///< in (0, 1]: the fraction of the opening error one correction removes
    double      gauge_distance = 0.;    ///< [m]; 0: one horizon
    std::size_t max_steps           = 400;
    std::size_t stall_steps         = 15;    ///< no growth for this many steps after it began: stop
    double      hole_margin         = 0.001; ///< [m]

    std::string output_directory;
    std::string published_path;
    std::size_t output_interval = 10; ///< pd_*.vtu every n steps (and the last)
  };

  struct FullPdStep
  {
    std::size_t     step = 0;
    double          displacement = 0.; ///< load-point displacement, downwards [m]
    double          mouth_opening = 0.; ///< crack-mouth opening between the gauges [m]
    double          load         = 0.; ///< reaction of the load pad, upwards on the loader [N/m]
    double          crack_length = 0.; ///< [m], the initial crack included
    geometry::Point tip;
    std::size_t     iterations = 0, repeats = 0;
    bool            converged  = true;
    double          seconds    = 0.;
  };

  struct FullPdResult
  {
    geometry::Polyline      path;
    std::vector<FullPdStep> steps;
    std::string             stop_reason;
    std::size_t             nodes      = 0;
    double                  node_steps = 0.; ///< sum over DR states of nodes x iterations
    double                  seconds    = 0., seconds_relaxation = 0.;
    double                  peak_rss_mb = 0.;
    /// Against the published path (our path up to its point nearest the published tip): symmetric
    /// mean and Hausdorff distance [m]; -1 without one.
    double published_mean = -1., published_hausdorff = -1.;
  };

  /// Throws InvalidParameter naming the parameter for bad input.
  FullPdResult run_full_pd(const FullPdParameters &parameters, std::ostream &progress);
} // namespace pumpd::coupling
