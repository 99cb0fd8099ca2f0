// Where a crack starts in a body without one (README, "Where a crack starts"): the first place
// where the largest principal stress reaches the strength of the PD material as the load factor
// rises. One solve of the uncracked body at lambda_ref gives the stress per unit load factor at
// every mesh vertex (recovered from the Gauss points, global/elasticity.h), and
//   sigma_1 = (s_xx + s_yy) / 2 + sqrt(((s_xx - s_yy) / 2)^2 + s_xy^2),
//   ratio   = sigma_1 / sigma_s,    lambda_i = 1 / max ratio   (linear elasticity),
// sigma_s the peak stress of the bond-based model in uniaxial stress (local/strength.h), the state
// at a free surface, where a crack starts in a body loaded by its boundary; inside the body the
// criterion is Rankine's with that strength. sigma_1 acts along n = (cos t, sin t),
// t = atan2(2 s_xy, s_xx - s_yy) / 2; the crack would open against it, running perpendicular to n.
//
// Candidate sites: the local maxima of the ratio (no vertex within a horizon, or within the cells
// around the vertex where those are larger, has a larger one) whose ratio is at least
// (1 - margin) times the largest; any two lie more than a horizon apart. A point force or point
// support is no site, nor is its neighbourhood (`Point clearance` horizons, or cells of the point
// where those are larger): its field is singular, and the stress the mesh gives there belongs to
// the idealisation of a contact as a point, not to the material (full PD keeps bonds there
// unbroken for the same reason).
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "elasticity.h"
#include "geometry.h"
#include "global_problem.h"
#include "pd_settings.h"
#include "scene.h"

namespace dealii
{
  class ParameterHandler;
}

namespace pumpd::coupling
{
  /// The section `Initiation`: which sites to list (and check, nucleation.h), and where the PD
  /// states of a nucleation start.
  struct InitiationSettings
  {
    double margin            = 0.1; ///< the local maxima within this fraction of the largest ratio are sites
    double point_clearance   = 2.;  ///< no site this many horizons (or cells) around a point condition
    double first_load_factor = 0.8; ///< lambda / lambda_i of the first PD state of a nucleation

    void add_parameters(dealii::ParameterHandler &prm);
  };

  struct InitiationSite
  {
    geometry::Point position;
    double          stress      = 0.; ///< sigma_1 per unit load factor [Pa]
    double          ratio       = 0.; ///< sigma_1 / sigma_s per unit load factor
    double          load_factor = 0.; ///< lambda_i = 1 / ratio
    geometry::Point direction;        ///< of sigma_1 (unit, x >= 0); the crack runs perpendicular to it
  };

  struct Initiation
  {
    double                      strength = 0.; ///< sigma_s [Pa]
    std::vector<InitiationSite> sites;         ///< largest ratio first
  };

  /// The candidate sites of the stress field per unit load factor (header comment), of the
  /// vertices outside the disks `left_out`. Throws InvalidParameter naming "Boundary conditions" when no ratio is
  /// positive (nothing pulls the body apart), with the largest ratio and where.
  std::vector<InitiationSite> candidate_sites(const std::vector<global::NodalStress> &stress_per_unit_load,
                                              double strength, double margin, double horizon,
                                              const std::vector<geometry::Circle> &left_out = {});

  /// Solves the uncracked scene once and returns its candidate sites against the strength of the
  /// scene's PD material (section Peridynamics: horizon, influence function, break factor; the
  /// scene's E and G_c). Writes the solution to <output directory>/initiation.vtu.
  Initiation find_initiation(const Scene &scene, const GlobalSettings &global, const PeridynamicsSettings &pd,
                             const InitiationSettings &settings);

  /// What nucleation (nucleation.h) made of a site.
  struct SiteOutcome
  {
    bool        checked     = false; ///< a PD box ran at it (else it is the same site as one before it)
    bool        formed      = false; ///< a crack formed there
    double      load_factor = 0.;    ///< lambda of the state that formed it
    std::size_t crack       = 0;     ///< the initial crack it became (1, 2, ...); 0: none
  };

  /// Prints the sites and writes <output directory>/initiation_sites.csv.
  void report_initiation(const Initiation &initiation, const Scene &scene, std::ostream &out);

  /// Writes <output directory>/initiation_sites.csv: per site its position, lambda_i, sigma_1 and
  /// the ratio per unit load factor, the direction of sigma_1; with `outcomes` (one per site) also
  /// checked, formed, formed_load_factor and crack (0/1, lambda, the initial crack or 0).
  void write_initiation_sites(const Initiation &initiation, const Scene &scene,
                              const std::vector<SiteOutcome> &outcomes = {});
} // namespace pumpd::coupling
