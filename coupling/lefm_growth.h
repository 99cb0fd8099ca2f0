// LEFM crack growth, the fast end of the speed/accuracy trade: the global XFEM solution alone
// decides where the crack goes (no PD). At each step: solve, K_I and K_II at every tip by the
// interaction integral, the maximum hoop stress kink angle (Erdogan & Sih 1963)
//   theta_c = 2 atan((K_I - sqrt(K_I^2 + 8 K_II^2)) / (4 K_II))   (0 when K_II = 0),
// and a straight increment da in that direction:
//   tip_new = tip + da (cos theta_c d + sin theta_c n),   n = d rotated by +90 degrees,
// with d the tip direction. Sign convention (checked in tests/coupling/lefm_growth_test.cc):
// stress_intensity_factors() returns K_II in the frame (d, n) at every tip, the first or the last
// polyline vertex: K_II > 0 when the material on the n side slides along +d relative to the other
// side (Anderson's Williams field), and then theta_c < 0, i.e. the crack turns away from n.
//
// The scene is the Ingraffea & Grigoriu beam in three-point bending (DESIGN.md, "Units and
// conventions"): a pin and a roller on the bottom edge, a downward point load on the top edge,
// an initial edge crack; the body (outline, holes) is read from the mesh. A tip stops cleanly
// when it reaches the outline (the crack is clipped to it and the tip disappears), when it would
// enter a hole (it stops `hole_margin` before the hole's circle), when K_I <= 0 (closed crack);
// the run stops when no tip is left, after `max_steps` increments or at `max_crack_length`.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "geometry.h"

namespace pumpd::coupling
{
  struct LefmGrowthParameters
  {
    std::string        mesh_file;                  ///< gmsh .geo (meshed by gmsh) or .msh
    double             mesh_size = 0.;             ///< h of the .geo [m]; 0: the file's default
    geometry::Polyline initial_crack;              ///< vertices; an end on the outline is the mouth
    double             youngs_modulus = 2.4e9;     ///< E [Pa]
    double             poisson_ratio  = 0.35;      ///< nu
    bool               plane_strain   = true;
    geometry::Point    pin{0.0254, 0.};            ///< both displacement components fixed
    geometry::Point    roller{0.4826, 0.};         ///< vertical displacement fixed
    geometry::Point    load_point{0.254, 0.2032};  ///< the downward point load acts here
    double             load = 1e5;                 ///< [N per m of thickness]
    double             growth_increment = 0.004;   ///< da [m]
    double             halving_angle    = 0.;      ///< [deg]: da / (1 + |theta_c| / this); 0: fixed da
    std::size_t        max_steps        = 100;     ///< growth increments
    double             max_crack_length = 0.3;     ///< [m], the whole polyline
    double             tip_radius       = 0.01;    ///< branch enrichment radius [m]
    unsigned int       refinement_levels = 1;      ///< cells near a tip are refined to this level
    double             refinement_radius = 0.012;  ///< [m] around each tip
    double             hole_margin       = 0.001;  ///< a tip stops this far from a hole's circle [m]
    std::string        output_directory;           ///< "" = no files
    std::size_t        output_interval = 5;        ///< global_NNN.vtu every n steps
    std::string        published_path;             ///< CSV x,y of a reference path; "" = none
    bool               iterative_solver = false;   ///< CG + AMG instead of UMFPACK
  };

  /// One tip at one solved step.
  struct LefmGrowthStep
  {
    std::size_t     step         = 0;
    std::size_t     tip          = 0;
    geometry::Point position;
    double          crack_length = 0.; ///< of the whole polyline at the solve [m]
    double          k1 = 0., k2 = 0.;  ///< [Pa m^1/2]
    double          kink_angle   = 0.; ///< theta_c [rad]
    double          increment    = 0.; ///< length of the segment added to this tip [m] (0: none)
    unsigned int    dofs         = 0;
    double          solve_seconds = 0.;
  };

  struct LefmGrowthResult
  {
    geometry::Polyline          path;          ///< the final crack
    std::vector<LefmGrowthStep> steps;
    std::size_t                 increments = 0; ///< growth steps done
    std::string                 stop_reason;
    double                      seconds = 0.;
    /// Largest distance of a vertex of the published path from our path [m]; -1 without one.
    double                      published_deviation = -1.;
  };

  /// theta_c of the maximum hoop stress criterion [rad], in (-pi, pi); 0 when K_II = 0.
  /// Evaluated as -2 atan(2 K_II / (K_I + sqrt(K_I^2 + 8 K_II^2))), the same value without
  /// the cancellation of K_I - sqrt(...) for small K_II.
  double kink_angle(double k1, double k2);

  /// Throws InvalidParameter (naming the parameter) for bad parameters, a missing mesh or
  /// published path, an initial crack outside the body, supports or load off the mesh vertices.
  LefmGrowthResult run_lefm_growth(const LefmGrowthParameters &parameters, std::ostream &progress);
} // namespace pumpd::coupling
