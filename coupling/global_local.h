// The global-local cycle (DESIGN.md, "Data flow of one exchange"; reference Sections 3-4):
// enriched global elasticity drives a PD box at each crack tip, the PD damage grows the cracks,
// the extracted paths go back into the global enrichment, and the boxes follow the tips. One
// exchange:
//  1. the global problem (global_problem.h), refined at every tip: XFEM solve of the scene at
//     lambda = 1, K_I, K_II and the critical load factor lambda_c (G = G_c) at every tip: the load
//     is chosen by the code; the resolution rule (resolution.h) picks the horizon of each tip's
//     box from the holes and edges ahead of it;
//  2. BoxPolicy places the PD boxes; each PD body carries every crack as broken bonds, the
//     body's holes and free edges; the boundary transfer (boundary_transfer.h) maps the global
//     displacement per unit load onto its nodes, once per box;
//  3. the exchange (exchange.h): quasi-static PD states along lambda, the ExchangeController
//     raising, repeating or accepting as the extracted advance dictates;
//  4. the increment grows the crack; a tip that reaches a hole (within the hole margin) or the
//     outline stops there, and the run ends when no tip is left. A ligament ahead narrower than 3
//     horizons of the finest box is resolved by no box: the tip grows through it by LEFM instead
//     of 2-3;
//  5. the recorder writes what people look at, and the checkpoint.
// The cracks are polylines, each with one tip (an edge crack) or two (an interior crack). Each
// tip has its own box, controller and horizon; steps 2-3 run per box, every crack broken bonds in
// every box. Tips within half a box side of each other share one box (they grow in the same PD
// states, at one load). A tip gets a box when its G / G_c is at least `Box threshold` at the load
// where the first tip reaches G = G_c; the others wait.
// The exchange's load is the lowest at which a tip grew; a tip that grew within one load
// increment of its own ladder above it grows too (its states cannot tell the two loads apart),
// the increment of any other is discarded and computed again at the next exchange. A tip whose
// increment meets another crack's face, or would within a horizon, joins that crack there; the
// other tips go on until the cracks cut a piece off the body (global/crack_network.h).
#pragma once

#include <cstddef>
#include <iosfwd>
#include <limits>
#include <string>
#include <vector>

#include "box_policy.h"
#include "exchange_controller.h"
#include "global_problem.h"
#include "growth_settings.h"
#include "parameter_table.h"
#include "pd_settings.h"
#include "resolution.h"
#include "scene.h"

namespace dealii
{
  class ParameterHandler;
}

namespace pumpd::coupling
{
  /// The section `Global-local`: the box, the exchange, and the cycle's limits.
  struct CycleSettings
  {
    BoxSettings        box; ///< its horizon and spacing come from the section Peridynamics
    ExchangeSettings   exchange;
    ResolutionSettings resolution; ///< the box's horizon: the section's, or halved near holes and edges
    double           box_threshold      = 0.5; ///< G / G_c a tip needs for a box when the first reaches G_c
    unsigned int     max_exchanges      = 200;
    double           reference_box_area = 0.02258; ///< the fixed box of Ni et al. 2019 [m^2], for a metric
    unsigned int     output_interval    = 1;       ///< global and PD VTU every n exchanges
    bool             resume             = false;
    /// Every entry of the scene file read (read_parameters; none for settings made in code): a
    /// checkpoint keeps those that change results, and a resume must find them unchanged.
    ParameterTable scene_file;

    void add_parameters(dealii::ParameterHandler &prm);
  };

  struct GlobalLocalSettings
  {
    GlobalSettings       global;
    PeridynamicsSettings pd;
    GrowthSettings       growth;
    CycleSettings        cycle;
  };

  struct ExchangeRecord
  {
    std::size_t     exchange = 0;
    std::size_t     crack    = 0; ///< the tip's crack, in the scene's order
    std::size_t     tip_end  = 1; ///< the end of the crack polyline the tip sits at: 0 first vertex, 1 last
    double          lambda               = 0.; ///< the scene's load factor of the accepted state
    double          load_factor          = 0.; ///< lambda / lambda_c
    double          critical_load_factor = 0.; ///< lambda_c: G = G_c at the tip
    double          load = 0., displacement = 0.; ///< the scene's report at lambda
    /// The onset of growth in the box (exchange.h; the tip's lambda_c for an LEFM increment), the
    /// scene's report there; NaN where the tip did not grow.
    double onset_lambda = std::numeric_limits<double>::quiet_NaN(), onset_load = onset_lambda,
           onset_displacement = onset_lambda;
    geometry::Point tip;
    double          crack_length = 0., k1 = 0., k2 = 0.; ///< at lambda, before the increment
    double          advance = 0.;                        ///< [m]
    double          kink = 0.;           ///< of the increment's first segment from the tip direction [rad], + counter-clockwise
    double          predicted_kink = 0.; ///< theta_c of the maximum hoop stress criterion from K_I, K_II [rad]
    double          horizon = 0.;                        ///< delta of the box [m]
    std::string     decision;                            ///< accept | truncate | waits | lefm | ...
    geometry::Box   box;
    std::size_t     pd_nodes = 0, pd_iterations = 0, substeps = 0, repeats = 0;
    std::size_t     onset_substeps = 0; ///< PD states that refined the onset
    std::size_t     unrelaxed = 0; ///< PD states not relaxed within Relaxation max iterations
    unsigned int    dofs = 0, enriched_dofs = 0;
    double          seconds_global = 0., seconds_point_evaluation = 0., seconds_pd = 0., seconds_extraction = 0.;
  };

  struct GlobalLocalResult
  {
    geometry::Polyline              path;  ///< the first crack
    std::vector<geometry::Polyline> paths; ///< every crack, in the scene's order
    std::vector<ExchangeRecord> exchanges;
    std::vector<geometry::Box>  boxes; ///< every box placed, per track
    std::string                 stop_reason;
    double                      seconds       = 0.;
    double                      pd_node_steps = 0.; ///< sum of PD nodes x DR iterations
    double                      mean_box_area = 0.; ///< [m^2]
    /// Against the scene's reference path, our path taken up to its point nearest the reference's
    /// tip: symmetric mean and Hausdorff distance [m]; -1 without one.
    double reference_mean = -1., reference_hausdorff = -1.;
  };

  /// Throws InvalidParameter naming the parameter for bad input, std::runtime_error for an
  /// unreadable checkpoint when resuming.
  GlobalLocalResult run_global_local(const Scene &scene, const GlobalLocalSettings &settings, std::ostream &progress);
} // namespace pumpd::coupling
