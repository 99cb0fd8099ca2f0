// The global problem of every method that solves the whole body (DESIGN.md, "Data flow of one
// exchange"): enriched linear elasticity (global/) on a copy of the scene's mesh, refined at the
// crack tips, under the scene's conditions at a reference load factor lambda_ref. Linear
// elasticity gives every field per unit load factor, and the load at which a tip reaches G_c
// follows from one solve:
//   lambda_c = lambda_ref sqrt(G_c / G_ref),  G_ref = (K_I^2 + K_II^2) / E'  at lambda_ref.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "crack.h"
#include "geometry.h"
#include "scene.h"

namespace dealii
{
  class ParameterHandler;
}

namespace pumpd::global
{
  class EnrichedElasticity;
}

namespace pumpd::coupling
{
  /// The section `Global` (XFEM), shared by the methods that solve the whole body.
  struct GlobalSettings
  {
    double       tip_radius        = 0.006; ///< branch-function radius [m]
    unsigned int refinement_levels = 2;     ///< cells near a tip refined this often
    double       refinement_radius = 0.008; ///< [m] around each tip
    double       refinement_trail  = 0.032; ///< [m] earlier tips' refinement kept within it
    std::string  linear_solver     = "direct";
    double       reference_load_factor = 1.; ///< lambda of the solve


    void add_parameters(dealii::ParameterHandler &prm);
  };

  /// Two crack points closer than this count as one: 1e-8 of the body's larger side [m].
  double crack_tolerance(const Scene &scene);

  /// The cracks along `polylines` in the scene's body, cracks that touch joined (an end on
  /// another crack's face is a junction): what the global problem enriches.
  std::vector<global::Crack> enriched_cracks(const std::vector<geometry::Polyline> &polylines, const Scene &scene);

  /// Refuses a scene whose initial cracks have a tip closer to the body's boundary (outline or
  /// hole) than the tip enrichment radius: the interaction integral's domain (Moes et al. 1999)
  /// would cross a free edge whose normal has a component along the crack, and K would be wrong.
  /// Refuses too an initial crack whose two tips the mesh, refined at them, does not resolve apart
  /// (global::unresolved_tip_separation).
  void check_tip_radius(const Scene &scene, const GlobalSettings &settings);

  /// The active cells of the refined mesh: the cells of the mean size within the refinement
  /// radius of each initial tip (one if there is none) and its trail, each split into 4^levels.
  double estimated_cells(const Scene &scene, const GlobalSettings &settings);

  /// Refuses refinement settings whose refined mesh (estimated_cells) would exceed `max_cells`
  /// (Scene / Maximum cells) or this machine's memory (global::check_memory).
  void check_refinement(const Scene &scene, const GlobalSettings &settings, double max_cells);

  /// A crack tip under the scene's loading.
  struct TipState
  {
    geometry::Point position, direction;
    double          k1 = 0., k2 = 0.;           ///< [Pa m^1/2] per unit load factor
    double          k_terms = 0.;               ///< per unit load factor (global::StressIntensity::k_terms)
    double          critical_load_factor = 0.; ///< lambda_c; infinity where the tip is at rest (at_rest)
  };

  /// Why the tip does not grow at any load, "" if it grows at lambda_c. Both decisions are taken
  /// at what the interaction integral resolves, not at the sign of its round-off:
  ///  - "has no driving force ..." when |K| = sqrt(K_I^2 + K_II^2) < 1e-2 k_terms: K is then what is
  ///    left of the cancellation of the integral's terms (a crack along the load), and neither G
  ///    nor the kink direction means anything;
  ///  - "is closed (K_I < 0)" when K_I < -1e-2 |K_II|: the integral separates the modes to about
  ///    1 % of the larger one (K within 1 to 2 % of handbook values, tests/global/sif_test.cc), so a
  ///    smaller K_I has no sign and the tip is in mode II (it grows at G = K_II^2 / E', kinked by
  ///    -sign(K_II) 70.5 degrees). The crack faces' contact is not modelled: a closed tip waits.
  std::string at_rest(const TipState &tip);

  /// A refinement around a point: every cell within the refinement radius, `levels` times.
  struct Refinement
  {
    geometry::Point at;
    unsigned int    levels = 0;
  };

  class GlobalProblem
  {
  public:
    /// Throws InvalidParameter for a material out of range.
    GlobalProblem(const Scene &scene, const GlobalSettings &settings);
    ~GlobalProblem();

    /// Meshes the body for the crack's tips (the scene's mesh refined around each tip and around
    /// the earlier tips within the refinement trail of a tip), sets up the enrichment and solves
    /// at lambda_ref: the state of every tip (in the crack's tip order).
    std::vector<TipState> solve(const global::Crack &crack);
    /// The same for several cracks: refined around every tip of every crack, each crack enriched on
    /// its own; the states of every tip, cracks in order, tips in each crack's order.
    std::vector<TipState> solve(const std::vector<global::Crack> &cracks);
    /// Solves the body without a crack at lambda_ref, on the scene's mesh.
    void solve_uncracked();
    /// The refinements solve() made, in order.
    const std::vector<Refinement> &refinements() const { return history; }
    /// Takes the refinements of an earlier run (resume): the next solve() meshes as that run's did.
    void restore(const std::vector<Refinement> &refinements) { history = refinements; }

    /// Displacement per unit load factor at the points, each on its own side of the crack (one
    /// batched point evaluation). Call after solve() and before scale_to().
    std::vector<geometry::Point> displacement_per_unit_load(const std::vector<geometry::Point> &points);

    /// The direction theta [rad] from the tip's direction, within (-pi, pi) less 5 degrees either
    /// side of the crack faces, of the largest hoop stress sigma_tt of the solution on the circle
    /// of radius r about the tip (sigma from the displacement gradient by central differences of
    /// step r / 50, each point on its own side of the crack): where the plate's own field, beyond
    /// K_I and K_II, would turn a crack that leaves the tip over the length r.
    double hoop_direction(const TipState &tip, double r);

    /// The solution at load factor lambda from here on (until the next solve).
    void scale_to(double lambda);
    double load_factor() const { return lambda; }
    /// Load and displacement of the scene's report at the current load factor.
    std::pair<double, double> report() const;

    unsigned int n_dofs() const;
    unsigned int n_enriched_dofs() const;
    void         write_vtu(const std::string &file) const;
    const global::EnrichedElasticity &elasticity() const { return *problem; }

  private:
    /// The scene's mesh refined at the refinements within the trail of a tip, in their order (a
    /// function of the history and the tips, so a resumed run meshes as the uninterrupted one).
    void mesh_for(const std::vector<geometry::Point> &tips);
    void refine(const Refinement &r);
    /// The enriched problem on the current mesh under the scene's conditions.
    void make_problem();
    /// Sets up, assembles and solves the current problem at lambda_ref.
    void solve_current();

    const Scene                                  &scene;
    GlobalSettings                                settings;
    std::unique_ptr<dealii::Triangulation<2, 2>>  tria;
    std::unique_ptr<global::EnrichedElasticity>   problem;
    std::vector<Refinement>                       history;
    std::vector<Refinement>                       applied; ///< the refinements the mesh holds, in order
    double                                        lambda = 1.;
    bool                                          cracked_solve_done = false; ///< a solve with cracks has run
  };

  /// theta_c of the maximum hoop stress criterion (Erdogan & Sih 1963) [rad], in (-pi, pi); 0
  /// when K_II = 0. Evaluated as -2 atan(2 K_II / (K_I + sqrt(K_I^2 + 8 K_II^2))), the textbook
  /// 2 atan((K_I - sqrt(K_I^2 + 8 K_II^2)) / (4 K_II)) without its cancellation for small K_II.
  double kink_angle(double k1, double k2);
} // namespace pumpd::coupling
