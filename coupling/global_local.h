// The global-local cycle (DESIGN.md, "Data flow of one load step"; reference Sections 3-4):
// enriched global elasticity drives a PD box at the crack tip, the PD damage field grows the
// crack, the extracted path goes back into the global enrichment, and the box follows the tip.
//
// One exchange:
//  1. global: XFEM solve for the current crack under a reference load P_ref; K_I, K_II at the
//     tip; the critical load P_c = P_ref sqrt(G_c / G(P_ref)), G = (K_I^2 + K_II^2) / E'
//     (linear elasticity: the load is chosen by the code, not by a schedule);
//  2. BoxPolicy places the PD box; the PD body carries the whole crack behind the tip as broken
//     bonds, its holes and free edges; one batched point evaluation gives the global displacement
//     per unit load at every PD node (each node on its own side of the crack);
//  3. ExchangeController: quasi-static PD states (dynamic relaxation) with the boundary layer at
//     lambda P_c u_global, lambda raised / repeated / accepted as the extracted advance dictates;
//  4. CrackExtractor: the damage ridge from the tip becomes new polyline vertices; a tip that
//     reaches a hole (within the hole margin) or the outline stops there, and the run ends.
// The growth needs one tip: an edge crack (the Ingraffea beams); other cracks are refused.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "box_policy.h"
#include "exchange_controller.h"
#include "geometry.h"
#include "material.h"

namespace pumpd::coupling
{
  struct GlobalLocalParameters
  {
    // Body, loading, global discretisation (as lefm-growth).
    std::string        mesh_file;
    double             mesh_size = 0.;
    geometry::Polyline initial_crack;
    double             poisson_ratio = 0.25;  ///< global nu; bond-based PD has 1/4 (plane strain)
    geometry::Point    pin{0.0254, 0.};
    geometry::Point    roller{0.4826, 0.};
    geometry::Point    load_point{0.254, 0.2032};
    double             reference_load    = 1e5;   ///< P_ref [N/m]
    double             tip_radius        = 0.006;
    unsigned int       refinement_levels = 2;
    double             refinement_radius = 0.008;
    bool               iterative_solver  = false;
    // Peridynamics.
    local::MaterialParameters material;            ///< E, G_c, rho, plane strain (global E too)
    double                    horizon        = 0.004;
    int                       horizon_ratio  = 8;
    double                    tolerance      = 1e-5;
    std::size_t               max_iterations = 200000;
    double                    crack_damage   = 0.3;
    // Cycle.
    BoxSettings        box;              ///< horizon and spacing are set from the above
    ExchangeSettings   exchange;
    std::size_t        max_exchanges    = 200;
    double             max_crack_length = 0.3;
    double             hole_margin      = 0.001;
    double             reference_box_area = 0.127 * 0.1778; ///< the fixed box of Ni et al. 2019 [m^2]
    std::string        output_directory;
    std::string        published_path;
    std::size_t        output_interval = 1; ///< global/PD VTU every n exchanges
    bool               resume          = false;
  };

  struct ExchangeRecord
  {
    std::size_t     exchange = 0;
    double          load = 0., load_factor = 0., critical_load = 0.; ///< [N/m], lambda, P_c
    double          load_point_displacement = 0.;                    ///< downwards [m]
    geometry::Point tip;
    double          crack_length = 0., k1 = 0., k2 = 0.; ///< at the load, before the increment
    double          advance = 0.;                        ///< [m]
    std::string     decision;                            ///< accept | truncate | ...
    geometry::Box   box;
    std::size_t     pd_nodes = 0, pd_iterations = 0, substeps = 0, repeats = 0;
    unsigned int    dofs = 0, enriched_dofs = 0;
    double          seconds_global = 0., seconds_point_evaluation = 0., seconds_pd = 0., seconds_extraction = 0.;
  };

  struct GlobalLocalResult
  {
    geometry::Polyline          path;
    std::vector<ExchangeRecord> exchanges;
    std::vector<geometry::Box>  boxes;
    std::string                 stop_reason;
    double                      seconds = 0.;
    double                      pd_node_steps = 0.; ///< sum of PD nodes x DR iterations
    double                      mean_box_area = 0.; ///< [m^2]
    /// Against the published path, our path taken up to its point nearest the published tip:
    /// symmetric mean and Hausdorff distance [m]; -1 without one.
    double published_mean = -1., published_hausdorff = -1.;
  };

  /// Throws InvalidParameter naming the parameter for bad input (see validate() in the .cc),
  /// std::runtime_error for an unreadable checkpoint when resuming.
  GlobalLocalResult run_global_local(const GlobalLocalParameters &parameters, std::ostream &progress);
} // namespace pumpd::coupling
