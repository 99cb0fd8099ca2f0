// Linear elasticity on the whole body with a partition-of-unity enriched crack (XFEM/GFEM),
// in the style of the deal.II tutorials: setup / assemble / solve, then evaluation.
//
// Space (Moes, Dolbow & Belytschko 1999; shifted form: Belytschko et al. 2001), cracks k = 1..n:
//   u(x) = sum_p phi_p(x) [ u_p + sum_k (H_k(x) - H_k(x_p)) b_pk  (p in Heaviside nodes of crack k)
//                               + sum_k sum_j (F_kj(x) - F_kj(x_p)) c_pkj  (p in tip nodes of k) ]
// phi_p: the Q1 hat function of node p; H_k the Heaviside function of crack k's level set, F_kj
// the branch functions of the tip of crack k nearest to node p. Heaviside nodes of crack k:
// support cut completely by crack k, no tip of k in it, and the smaller side of the support at
// least `min_cut_fraction` of it, or int |grad phi_p|^2 over the side the node is not on at least
// `min_cut_fraction` (cells thin across the crack). Tip nodes of crack k: within `tip_radius` of a
// tip of k (geometric enrichment) or on a cell that holds it. A node carries one block per crack (Heaviside or tip):
// a node two cracks cut has two Heaviside blocks. Cut cells: a cell several cracks cut is split
// by the lines of all their pieces in it (cut_cell.h), so each sub-triangle lies on one side of
// every crack and the discontinuous integrands are integrated exactly as for one crack. The enriched
// degrees of freedom are managed here, on top of a scalar Q1 DoFHandler, rather than with
// FE_Enriched: the shift by the nodal value is per node, which FE_Enriched cannot express
// (../shared/notes/xfem-in-deal.ii-9.4.md). Hanging nodes: a cell's basis takes each hanging
// vertex's function through its parents (the hanging-node constraints of the scalar Q1 space),
// each with the parent's own shift, so the enriched space stays conforming under refinement.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "crack.h"
#include "geometry.h"

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace pumpd::global
{
  struct ElasticMaterial
  {
    double youngs_modulus = 1.;
    double poisson_ratio  = 0.3;
    bool   plane_strain   = true;

    double mu() const;
    /// In-plane Lame constant: lambda (plane strain), 2 lambda mu / (lambda + 2 mu) (plane stress).
    double lambda() const;
    /// E / (1 - nu^2) in plane strain, E in plane stress.
    double effective_modulus() const;
    /// Kolosov constant: 3 - 4 nu (plane strain), (3 - nu) / (1 + nu) (plane stress).
    double kolosov() const;
  };

  /// A displacement that may differ on the two faces of the crack: value(x, side), side = +-1
  /// as Crack::side.
  using SidedField = std::function<geometry::Point(geometry::Point x, int side)>;

  struct EnrichmentSettings
  {
    double       tip_radius       = 0.;   ///< [m]; at least the largest cell diameter at a tip
    double       min_cut_fraction = 1e-4; ///< drop H below this support fraction and energy (conditioning)
    unsigned int cut_order        = 4;    ///< Gauss simplex order on cut sub-triangles
    unsigned int tip_order        = 8;    ///< Gauss / Duffy order where branch functions live
    /// Gauss order on tip-enriched cells whose centre lies more than 2.5 diameters from every tip:
    /// the branch functions are smooth there (analytic in a disc of radius r about each point).
    unsigned int far_tip_order = 4;
  };

  /// Linear solver: sparse direct (the default: Cholesky by CHOLMOD, cholesky.h; UMFPACK's LU
  /// where the matrix is not numerically positive definite) or conjugate gradients preconditioned by
  /// algebraic multigrid (Trilinos ML) with the rigid-body modes as near-null space, for large
  /// meshes. CG + AMG needs MPI to be initialised (Utilities::MPI::MPI_InitFinalize; pumpd starts
  /// it when the scene asks for this solver).
  struct SolverSettings
  {
    enum class Type
    {
      direct,
      cg_amg
    } type                      = Type::direct;
    double       tolerance      = 1e-10; ///< relative residual of CG
    unsigned int max_iterations = 10000;
  };

  struct SolveReport
  {
    std::string  solver;
    unsigned int iterations = 0;
    double       seconds    = 0.;
  };

  struct StressIntensity
  {
    geometry::Point tip;
    double          k1 = 0.;
    double          k2 = 0.;
    /// The size of the terms the interaction integral sums, as a K: E' / 2 int |integrand| dA, the
    /// larger of the two modes. K far below it is what is left of their cancellation (a field
    /// that does not drive the tip), not a stress intensity.
    double k_terms = 0.;
  };

  /// Why the mesh cannot give K at the tips of `crack` ("" if it can): the interaction integral's
  /// domain about a tip, which ends half way to the crack's other tip, is smaller than the cell at
  /// the tip (`cell_diameter`). So short a crack, a few cells long, the mesh does not resolve.
  std::string unresolved_tip_separation(const Crack &crack, double cell_diameter);

  /// The stress at a vertex of the mesh [Pa].
  struct NodalStress
  {
    geometry::Point at;
    double          xx = 0., yy = 0., xy = 0.;
    double          cell_size = 0.; ///< largest diameter of the cells that share the vertex [m]
  };

  struct ErrorNorms
  {
    double l2 = 0., l2_exact = 0.;         ///< |u - u_h|_L2 and |u|_L2
    double energy = 0., energy_exact = 0.; ///< energy norm sqrt(int eps:C:eps) of the error and of u
  };

  class EnrichedElasticity
  {
  public:
    /// The triangulation must outlive this object. Throws InvalidParameter for a material out
    /// of range (E <= 0, nu not in [0, 0.5)). A nearly incompressible material in plane strain
    /// (nu > 0.49) is accepted with a warning (warnings(), for the caller to print): bilinear
    /// elements lock volumetrically there and the displacements and K_I come out too small.
    EnrichedElasticity(dealii::Triangulation<2, 2> &triangulation, const ElasticMaterial &material,
                       const EnrichmentSettings &settings);
    ~EnrichedElasticity();

    /// Diagnostics about the problem as set up (e.g. volumetric locking), one sentence each;
    /// empty when there is nothing to warn about.
    const std::vector<std::string> &warnings() const { return warning_list; }

    /// The crack (none: plain elasticity, no enrichment assembled): set_cracks with none or one.
    void set_crack(std::optional<Crack> crack);
    /// The crack when there is exactly one, none otherwise.
    const std::optional<Crack> &crack() const;
    /// Any number of cracks, each with its own enrichment. Cracks must not cross; a crack end on
    /// another crack's face is a junction (Crack::join, Crack::side).
    void set_cracks(std::vector<Crack> cracks);
    const std::vector<Crack> &cracks() const;

    void add_dirichlet(unsigned int boundary_id, SidedField value, bool fix_x = true, bool fix_y = true);
    void add_dirichlet_vertex(geometry::Point at, geometry::Point value, bool fix_x = true, bool fix_y = true);
    /// Every node of the cells with this material id (a named region of the mesh).
    void add_dirichlet_region(unsigned int material_id, std::function<geometry::Point(geometry::Point)> value,
                              bool fix_x = true, bool fix_y = true);
    void add_traction(unsigned int boundary_id, std::function<geometry::Point(geometry::Point)> traction);
    /// A traction that depends on the outward unit normal n too: traction(x, n) (a pressure).
    void add_traction(unsigned int boundary_id, std::function<geometry::Point(geometry::Point, geometry::Point)> traction);
    void add_point_load(geometry::Point at, geometry::Point force);
    void set_body_force(std::function<geometry::Point(geometry::Point)> force);

    /// Enrichment, degrees of freedom, constraints. Throws InvalidParameter if the crack leaves
    /// the mesh, the tip radius is smaller than a cell at a tip, or a named boundary id or vertex
    /// does not exist.
    void        setup();
    void        assemble();
    SolveReport solve(const SolverSettings &solver = {});

    /// Multiplies the solution by `factor`: the problem is linear, so this is the solution for
    /// every load and boundary value multiplied by it (one solve serves every load level).
    void scale_solution(double factor);

    unsigned int n_dofs() const;
    unsigned int n_enriched_dofs() const;
    unsigned int n_heaviside_nodes() const;
    unsigned int n_tip_nodes() const;

    /// u_h at x, on the given side of the crack where x lies on it (slow path: one cell search).
    geometry::Point displacement(geometry::Point x, int side = 1) const;
    /// The mean of the nodal displacements on the faces with this boundary id.
    geometry::Point mean_displacement(unsigned int boundary_id) const;

    /// The force the supports exert on the body at the nodes of a boundary id (or at a vertex):
    /// the internal force a(u_h, phi_p e_c) summed over those nodes p, less the point loads
    /// applied there (tractions on the same boundary are not subtracted) [N/m].
    geometry::Point reaction(unsigned int boundary_id) const;
    geometry::Point reaction_at(geometry::Point vertex) const;
    /// U = 1/2 int sigma(u_h) : eps(u_h) [J/m].
    double strain_energy() const;

    /// Prepares u_h at many points (the PD boundary layer): finds each point's cell once and
    /// builds the sparse interpolation matrix P, so that evaluate_points() is u = P U. side[i]
    /// (+-1, or empty: +1) decides for a point on the crack; elsewhere the level set does.
    /// Valid until the next setup(). Throws InvalidParameter for a point outside the mesh.
    void prepare_point_evaluation(const std::vector<geometry::Point> &points, const std::vector<int> &side = {});
    /// u_h at the prepared points, in their order.
    std::vector<geometry::Point> evaluate_points() const;
    /// Errors against an exact displacement and its gradient (rows du_x/dx, du_x/dy, du_y/dx, du_y/dy).
    ErrorNorms errors(const SidedField &exact, const std::function<std::array<double, 4>(geometry::Point, int)> &grad) const;

    /// The stress at every vertex of a body without a crack, recovered from the cells around it:
    /// each cell's stress at its 2 x 2 Gauss points extrapolated to its corners (the bilinear
    /// interpolant of the four values, in reference coordinates), averaged over the cells that
    /// share the vertex. Throws std::logic_error when a crack is set (its faces would be averaged).
    std::vector<NodalStress> nodal_stresses() const;

    /// K_I, K_II at every tip by the interaction integral (domain form) over the cells within
    /// radius_factor * tip_radius of the tip, and at most half way to the crack's other tip.
    std::vector<StressIntensity> stress_intensity_factors(double radius_factor = 1.) const;

    /// Error indicator per active cell (active_cell_index order), from the solution alone: the
    /// traction residual across faces, eta_K^2 = sum_F h_F int_F |[sigma_h] n|^2 over interior
    /// faces and |sigma_h n - t|^2 over boundary faces without Dirichlet data (Kelly's indicator
    /// on the enriched field). For error-driven adaptive refinement.
    std::vector<double> error_indicators() const;

    /// VTU with cut cells written as their sub-triangles (the opened crack is visible):
    /// displacement, stress, von Mises, enrichment per cell.
    void write_vtu(const std::string &filename) const;

    struct Impl;

  private:
    std::unique_ptr<Impl>    impl;
    std::vector<std::string> warning_list;
  };
} // namespace pumpd::global
