// LEFM crack growth, the fast end of the speed/accuracy trade: the global XFEM solution alone
// decides where the crack goes (no PD). At each step: solve the scene at lambda = 1, K_I and K_II
// at every tip by the interaction integral, the maximum hoop stress kink angle theta_c
// (kink_angle, global_problem.h), and a straight increment da in that direction:
//   tip_new = tip + da (cos theta_c d + sin theta_c n),   n = d rotated by +90 degrees,
// with d the tip direction. The load of the step is the critical load factor lambda_c of the tip
// that reaches G = G_c first. Sign convention (checked in tests/coupling/lefm_growth_test.cc):
// stress_intensity_factors() returns K_II in the frame (d, n) at every tip, the first or the last
// polyline vertex: K_II > 0 when the material on the n side slides along +d relative to the other
// side (Anderson's Williams field), and then theta_c < 0, i.e. the crack turns away from n.
//
// A tip stops cleanly when it reaches the outline (the crack is clipped to it and the tip
// disappears), when it would enter a hole (it stops `hole margin` before it), when it is at rest
// (closed, or no driving force: at_rest, global_problem.h); the run stops when no tip is left,
// after `max_steps` increments or at the maximum crack length (with several cracks: their total
// length).
//
// Several cracks: every tip of every crack has its state. The step's load factor is the smallest
// lambda_c over the tips still growing; every tip whose lambda_c <= lambda_min (1 + tolerance)
// (`Simultaneous growth tolerance`) grows by its da along its maximum hoop stress direction, the
// others wait (quasi-static: they are not yet critical at that load). A tip whose increment would
// reach another crack's face (within look_ahead da, or crossing a segment grown earlier in the step)
// joins it: the new segment is clipped to the face and ends there, the end becomes a junction and
// the tip disappears (global::Crack::join; the junction is enriched by the junction function). The
// other tips go on; the run ends when no tip grows or the cracks cut a piece off the body
// (global/crack_network.h).
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "global_problem.h"
#include "growth_settings.h"
#include "scene.h"

namespace dealii
{
  class ParameterHandler;
}

namespace pumpd::coupling
{
  /// The section `LEFM growth`.
  struct LefmSettings
  {
    double       growth_increment = 0.004; ///< da [m]
    double       halving_angle    = 0.;    ///< [deg]: da / (1 + |theta_c| / this); 0: fixed da
    unsigned int max_steps        = 100;   ///< growth increments
    unsigned int output_interval  = 5;     ///< global_NNN.vtu every n steps
    double       simultaneous_tolerance = 1e-3; ///< relative, on lambda_c: tips that grow together

    void add_parameters(dealii::ParameterHandler &prm);
  };

  struct LefmGrowthSettings
  {
    GlobalSettings global;
    GrowthSettings growth;
    LefmSettings   lefm;
  };

  /// One tip at one solved step.
  struct LefmGrowthStep
  {
    std::size_t     step = 0;
    std::size_t     tip  = 0; ///< over all tips, cracks in order, tips in each crack's order
    geometry::Point position;
    double          crack_length = 0.; ///< of the whole polyline at the solve [m]
    double          k1 = 0., k2 = 0.;  ///< [Pa m^1/2] at lambda = 1
    double          critical_load_factor = 0.;
    double          kink_angle   = 0.; ///< theta_c [rad]
    double          increment    = 0.; ///< length of the segment added to this tip [m] (0: none)
    unsigned int    dofs         = 0;
    double          solve_seconds = 0.;
    std::size_t     crack        = 0; ///< index of the tip's crack
  };

  struct LefmGrowthResult
  {
    geometry::Polyline              path;  ///< the final first crack
    std::vector<geometry::Polyline> paths; ///< every final crack, in order
    bool                            joined = false; ///< a tip joined another crack
    std::vector<LefmGrowthStep> steps;
    std::size_t                 increments = 0; ///< growth steps done
    std::string                 stop_reason;
    double                      seconds = 0.;
    /// Largest distance of a vertex of the reference path from our path [m]; -1 without one.
    double                      reference_deviation = -1.;
  };

  /// Throws InvalidParameter (naming the parameter) for bad input.
  LefmGrowthResult run_lefm_growth(const Scene &scene, const LefmGrowthSettings &settings, std::ostream &progress);
} // namespace pumpd::coupling
