// Full-domain PD: the whole body of a scene as one PD body, the expensive end of the
// speed/accuracy trade (what a user would otherwise run instead of the global-local cycle).
//
// The PD box is the body's bounding box, the lattice the body's material; every boundary is a
// free surface but where the scene prescribes (the PD adapter, local/pd_conditions.h):
//   a displacement condition on a point   -> the nodes within `support radius` of it,
//                            on a boundary -> the nodes within one horizon of it (a grip),
//                            on a region   -> the nodes in it,
//   a point force -> a loading pad: the nodes within the support radius, displaced rigidly along
//                    the force (PD specimens are loaded through pads under displacement control).
// Bonds within `no-fail radius` of a point condition stay linear elastic: a support or pad
// concentrates stress far beyond the PD strength (~K_c / sqrt(pi delta)) and would crush. The
// radius is at most a quarter of the body's smaller side, so that in a slender beam the crack
// can still run towards the pad.
// Initial cracks start as broken bonds. The control variable d is the largest prescribed
// displacement: the pad's displacement along its force (one point force), or lambda times the
// largest value of the lambda-scaled displacement conditions. Tractions, or a point force together
// with lambda-scaled displacements, cannot be driven by one displacement and are refused.
//
// Quasi-static states by dynamic relaxation at each d; after each state every crack is traced from
// its initial tips (coupling/crack_traces.h: an edge crack from its tip, an interior crack from
// both) through the damage field, per node the largest damage of the accepted states (the
// softening is elastic up to the break stretch, so bonds behind the tip relax when the load falls
// after the peak; the crack they marked stays). A scene without a crack forms its own: it is
// traced from a mouth, the boundary point nearest the most damaged node within a spacing of the
// boundary (damage at least the crack threshold, a horizon clear of the prescribed regions and
// no-fail zones), along the direction to the damage-weighted centroid of the crack nodes within
// three horizons of it; mouth and direction follow the damage until the crack is a horizon long.
// A crack that forms inside the body instead (damage at the threshold a horizon or more from the
// boundary while no node near it qualifies as a mouth) is traced both ways from its most damaged
// node (`interior_crack`), along the principal axis of the damage around it, each way until its
// ridge ends or splits; once that trace is a horizon long, the run traces it on from its two tips,
// as it traces an initial interior crack.
// Its steps are taken in d until it forms (the mouth is not known before), then, under crack-mouth
// control (below), in the opening of the mouth where it formed, if the gauges across that mouth
// opened over the step in which it formed (else, and for a crack formed inside the body, in d to
// the end). The run stops where every tip has reached a hole (within the hole margin) or the
// outline, where a tip joins another crack or comes within half a horizon of a no-fail zone, where
// the cracks stop growing for good, or where d reaches its maximum. The crack advance of a step is
// that of every crack together.
//
// Displacement steps (the rule the method follows):
//  1. elastic: while no bond has passed its inflection stretch (max stretch ratio Z < 1) the
//     state is linear in d, so d jumps to the value where Z near the tip reaches `onset stretch
//     ratio` (the relaxed state scaled: exact, one DR state);
//  2. softening, no growth yet: dd = `first increment` d;
//  3. growth g in the last step: dd <- dd clamp(a_t / g, 1/2, 2), a_t = `target advance`; no
//     growth: dd <- 2 dd; always clamped to [`minimum increment` d, `maximum increment` d];
//  4. a step that grew the crack by more than `maximum advance` is undone (state restored) and
//     repeated with dd / 2 while dd is above the minimum and halving shortened the advance (by a
//     quarter at least); otherwise the growth is unstable (snap-back) and the step is accepted.
// The predictor of each state: the elastic state scaled to the new d (phase 1), later the last
// state plus the last step's increment extrapolated to dd.
//
// Equilibrium. Dynamic relaxation stops when the residual r = |f| / (k |u - u_rigid|) (k the bond
// stiffness scale, local/integrators.h) falls below a tolerance. The slowest mode of a body L wide
// on a lattice of spacing h, its bending, is about (h / L)^2 as stiff as a bond, so a state with
// residual r can lie r (L / h)^2 from equilibrium, relative to its deformation. The tolerance that
// suits a PD box 30 to 60 spacings wide leaves a whole panel hundreds of spacings wide far from it:
// the panel stiffer than it is, its stress concentrations too high. The whole body is therefore
// relaxed to r < `equilibrium error` (h / L)^2, L the larger side of its bounding box (or to the
// Peridynamics section's tolerance where that is tighter).
//
// Control. Under displacement control a specimen snaps back once the crack grows: the
// equilibrium path turns back in d, and dynamic relaxation jumps to a far state. With `control =
// crack mouth opening` the steps above are taken in the crack-mouth opening w instead (phase 1
// stays under d; w is proportional to it there), which grows monotonically along the whole path.
// The opening is read between two gauge nodes one `gauge distance` either side of the first
// crack's mouth (normal to its first segment; by default one horizon across an initial crack,
// four across a crack that forms, whose softening zone still reaches past one or two). A servo
// inside the relaxation (local::Servo) moves the driven displacements whenever |w - w*| exceeds a
// tenth of the step: by gain (d/w)_0 (w* - w), and the whole body with them along the secant mode
// u_0 / d_0 ((d, u)_0 the last accepted state); the relaxation settles the rest. The opening also
// grows while bonds ahead of the tip soften and the crack does not, so under this control (with an
// initial crack or a formed one) a crack counts as stopped only once the drive, too, has risen by
// (1 + maximum increment)^(stall steps) since the crack last grew; a drive that keeps falling
// without growth runs to the maximum steps. A servo that needs a drive outside (0, 2 d) (d the last
// accepted drive) has no equilibrium to hold at that opening: the step is repeated in d, and the
// steps stay in d from then on.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "growth_settings.h"
#include "model.h"
#include "pd_settings.h"
#include "scene.h"

namespace dealii
{
  class ParameterHandler;
}

namespace pumpd::coupling
{
  /// The section `Full PD`.
  struct FullPdControlSettings
  {
    double       support_radius      = 0.;    ///< [m]; 0: one horizon
    double       no_fail_horizons    = 10.;   ///< no-fail radius in horizons; 0: none
    double       onset_stretch_ratio = 0.9;   ///< Z the elastic jump aims at
    double       first_increment     = 0.02;  ///< dd / d once bonds soften
    double       min_increment       = 0.002; ///< smallest dd / d
    double       max_increment       = 0.05;  ///< largest dd / d
    double       target_advance      = 0.;    ///< a_t [m]; 0: one horizon
    double       max_advance         = 0.;    ///< [m]; 0: four horizons (then the step is repeated)
    double       max_displacement    = 0.;    ///< largest d [m]; 0: no limit
    unsigned int max_steps           = 400;
    std::string  control             = "crack mouth opening";
    double       servo_gain          = 1.;    ///< the fraction of the opening error one correction removes
    double       gauge_distance      = 0.;    ///< [m]; 0: one horizon (an initial crack), four (a crack that forms)
    unsigned int stall_steps         = 15;    ///< no growth for this many steps after it began: stop (Control)
    unsigned int output_interval     = 10;    ///< pd_*.vtu every n steps (and the last)
    double       equilibrium_error   = 5e-3;  ///< relative displacement error the relaxation leaves at most

    /// The residual tolerance of dynamic relaxation on a body of larger side `size` and lattice
    /// spacing h (header comment, "Equilibrium"): the smaller of `tolerance` (the Peridynamics
    /// section's) and equilibrium_error (h / size)^2.
    double relaxation_tolerance(double tolerance, double spacing, double size) const;

    void add_parameters(dealii::ParameterHandler &prm);
  };

  struct FullPdSettings
  {
    PeridynamicsSettings  pd;
    GrowthSettings        growth;
    FullPdControlSettings full_pd;
  };

  struct FullPdStep
  {
    std::size_t     step = 0;
    double          displacement  = 0.; ///< the control displacement d [m]
    double          mouth_opening = 0.; ///< crack-mouth opening between the gauges [m]
    double          lambda        = 0.; ///< the scene's load factor the state corresponds to
    double          load = 0., reported_displacement = 0.; ///< the scene's report
    double          crack_length = 0.; ///< [m], every crack together, the initial cracks included
    geometry::Point tip;               ///< the first crack's end
    std::size_t     iterations = 0, repeats = 0;
    bool            converged  = true;
    double          seconds    = 0.;
  };

  struct FullPdResult
  {
    geometry::Polyline              path;           ///< the first crack
    std::vector<geometry::Polyline> paths;          ///< every crack, in the scene's order
    bool                            joined = false; ///< a tip joined another crack
    /// Without an initial crack: where one formed inside the body, with no mouth (its most damaged
    /// node; the crack is then traced on from its two tips).
    std::optional<geometry::Point> interior_crack;
    std::vector<FullPdStep>         steps;
    std::string                     stop_reason;
    std::size_t                     nodes      = 0;
    double                          node_steps = 0.; ///< sum over DR states of nodes x iterations
    double                          seconds    = 0., seconds_relaxation = 0.;
    double                          peak_rss_mb = 0.;
    /// Against the scene's reference path (our path up to its point nearest the reference's tip):
    /// symmetric mean and Hausdorff distance [m]; -1 without one.
    double reference_mean = -1., reference_hausdorff = -1.;
  };

  /// The memory full PD needs on `scene` with `pd` (the lattice over the body's bounding box)
  /// against this machine's, checked before run_full_pd would refuse it.
  local::ModelMemory full_pd_memory(const Scene &scene, const PeridynamicsSettings &pd);

  /// Throws InvalidParameter naming the parameter for bad input.
  FullPdResult run_full_pd(const Scene &scene, const FullPdSettings &settings, std::ostream &progress);
} // namespace pumpd::coupling
