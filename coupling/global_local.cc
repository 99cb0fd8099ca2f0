#include "global_local.h"

#include <deal.II/grid/tria.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>

#include "beam_scene.h"
#include "boundary_layer.h"
#include "crack_extraction.h"
#include "cycle_checkpoint.h"
#include "elasticity.h"
#include "error.h"
#include "integrators.h"
#include "model.h"
#include "path_metrics.h"
#include "vtu_output.h"

namespace pumpd::coupling
{
  using geometry::Point;
  using Clock = std::chrono::steady_clock;

  namespace
  {
    double seconds_since(Clock::time_point t)
    {
      return std::chrono::duration<double>(Clock::now() - t).count();
    }

    void validate(const GlobalLocalParameters &p)
    {
      require_range("Mesh size", p.mesh_size, 0., 1., "must be in [0, 1] m (0: the mesh file's default)");
      require_positive("Reference load", p.reference_load);
      require_range("Poisson's ratio", p.poisson_ratio, 0., 0.4999, "must be in [0, 0.5)");
      require_positive("Tip enrichment radius", p.tip_radius);
      require_range("Refinement levels near the tip", p.refinement_levels, 0, 6, "must be in [0, 6]");
      require_positive("Refinement radius", p.refinement_radius);
      require_positive("Horizon", p.horizon);
      if (p.horizon_ratio < 2)
        throw InvalidParameter("Horizon over spacing", std::to_string(p.horizon_ratio),
                               "must be an integer >= 2: the horizon spans at least two PD spacings");
      require_range("Crack damage threshold", p.crack_damage, 0.05, 0.95, "must be in [0.05, 0.95]");
      if (p.max_exchanges < 1)
        throw InvalidParameter("Maximum exchanges", "0", "must be >= 1");
      require_positive("Maximum crack length", p.max_crack_length);
      require_range("Hole margin", p.hole_margin, 0., 1., "must be in [0, 1] m");
      require_positive("Reference box area", p.reference_box_area);
      if (p.output_interval < 1)
        throw InvalidParameter("Output interval", "0", "must be >= 1");
      if (p.initial_crack.size() < 2)
        throw InvalidParameter("Initial crack", to_text(p.initial_crack), "needs at least 2 points");
      if (p.exchange.min_advance < 2. * p.horizon / p.horizon_ratio)
        throw InvalidParameter("Minimum advance", std::to_string(p.exchange.min_advance),
                               "must be at least two PD spacings (" + std::to_string(2. * p.horizon / p.horizon_ratio) +
                                 " m): a shorter advance is within the noise of the extracted tip");
    }

    /// The initial crack: inside the body, clear of the holes (global::Crack checks both), one tip.
    global::Crack checked_crack(const geometry::Polyline &vertices, const geometry::Body &body)
    {
      global::Crack crack = initial_crack(vertices, body);
      if (crack.tips().size() != 1)
        throw InvalidParameter("Initial crack", to_text(vertices),
                               "must be an edge crack (one end on the outline, one tip): the cycle grows one tip");
      return crack;
    }

    void write_boxes(const std::string &file, const std::vector<geometry::Box> &boxes)
    {
      std::ofstream out(file);
      out << std::setprecision(10) << "exchange,x_min_m,y_min_m,x_max_m,y_max_m,moved\n";
      for (std::size_t k = 0; k < boxes.size(); ++k)
        {
          const auto &b     = boxes[k];
          const bool  moved = k == 0 || b.x_min != boxes[k - 1].x_min || b.y_min != boxes[k - 1].y_min ||
                             b.x_max != boxes[k - 1].x_max || b.y_max != boxes[k - 1].y_max;
          out << k << "," << b.x_min << "," << b.y_min << "," << b.x_max << "," << b.y_max << "," << moved << "\n";
        }
    }

    const char *load_steps_header =
      "exchange,load_N_per_m,load_factor,critical_load_N_per_m,load_point_displacement_m,tip_x_m,tip_y_m,"
      "crack_length_m,K_I_Pa_sqrt_m,K_II_Pa_sqrt_m,advance_m,decision,pd_nodes,pd_substeps,pd_repeats,"
      "pd_iterations,dofs,seconds_global,seconds_point_evaluation,seconds_pd,seconds_extraction\n";

    void write_record(std::ostream &out, const ExchangeRecord &r)
    {
      out << std::setprecision(10) << r.exchange << "," << r.load << "," << r.load_factor << "," << r.critical_load
          << "," << r.load_point_displacement << "," << r.tip.x << "," << r.tip.y << "," << r.crack_length << ","
          << r.k1 << "," << r.k2 << "," << r.advance << "," << r.decision << "," << r.pd_nodes << "," << r.substeps
          << "," << r.repeats << "," << r.pd_iterations << "," << r.dofs << "," << r.seconds_global << ","
          << r.seconds_point_evaluation << "," << r.seconds_pd << "," << r.seconds_extraction << "\n";
    }

    const char *to_text(ExchangeController::Decision d)
    {
      switch (d)
        {
          case ExchangeController::Decision::raise:
            return "raise";
          case ExchangeController::Decision::repeat:
            return "repeat";
          case ExchangeController::Decision::accept:
            return "accept";
          case ExchangeController::Decision::truncate:
            return "truncate";
          case ExchangeController::Decision::too_small:
            return "too-small";
        }
      return "";
    }
  } // namespace

  GlobalLocalResult run_global_local(const GlobalLocalParameters &parameters, std::ostream &out)
  {
    GlobalLocalParameters p = parameters;
    validate(p);
    const double h = p.horizon / p.horizon_ratio;
    p.box.horizon  = p.horizon;
    p.box.spacing  = h;
    const auto t0  = Clock::now();
    const geometry::Polyline reference = p.published_path.empty() ? geometry::Polyline{} : read_path(p.published_path);

    dealii::Triangulation<2> tria;
    const geometry::Body body =
      read_beam(tria, p.mesh_file, p.mesh_size, {{"Pin support", p.pin}, {"Roller support", p.roller}, {"Load point", p.load_point}});
    std::optional<global::Crack> crack = checked_crack(p.initial_crack, body);
    BoxPolicy                    policy(body, p.box);
    ExchangeController           controller(p.exchange);

    const std::string checkpoint = p.output_directory.empty() ? "" : p.output_directory + "/checkpoint.h5";
    CycleState        cycle;
    if (p.resume)
      {
        if (checkpoint.empty())
          throw InvalidParameter("Resume", "true", "needs an output directory holding checkpoint.h5");
        cycle = read_cycle_checkpoint(checkpoint);
        crack.emplace(cycle.crack, body, 1e-9);
        for (const auto &x : cycle.refined_at)
          refine_at_tips(tria, {global::Tip{x, {1., 0.}, 0}}, p.refinement_radius, p.refinement_levels);
        policy.restore(cycle.boxes);
        controller.restore(cycle.load_factor);
        out << "resuming after exchange " << cycle.exchanges << ": crack " << crack->length() << " m\n";
      }

    const global::ElasticMaterial material{p.material.youngs_modulus, p.poisson_ratio, p.material.plane_strain};
    global::EnrichmentSettings    enrichment;
    enrichment.tip_radius = p.tip_radius;
    global::EnrichedElasticity problem(tria, material, enrichment);
    problem.add_dirichlet_vertex(p.pin, {0., 0.}, true, true);
    problem.add_dirichlet_vertex(p.roller, {0., 0.}, false, true);
    problem.add_point_load(p.load_point, {0., -p.reference_load});
    global::SolverSettings solver;
    if (p.iterative_solver)
      solver.type = global::SolverSettings::Type::cg_amg;

    std::unique_ptr<GlobalVtuSeries>  global_series;
    std::unique_ptr<local::PvdSeries> pd_series;
    std::ofstream                     table;
    if (!p.output_directory.empty())
      {
        std::filesystem::create_directories(p.output_directory);
        global_series = std::make_unique<GlobalVtuSeries>(p.output_directory);
        pd_series     = std::make_unique<local::PvdSeries>(p.output_directory, "pd");
        write_body(p.output_directory + "/body.csv", body, {{"pin", p.pin}, {"roller", p.roller}, {"load", p.load_point}});
        if (!reference.empty())
          write_path(p.output_directory + "/reference_path.csv", reference);
        const std::string steps = p.output_directory + "/load_steps.csv";
        table.open(steps, p.resume ? std::ios::app : std::ios::trunc);
        if (!p.resume)
          table << load_steps_header;
      }

    // Where a grown path ends: a hole within its margin, or the outline or a hole within a horizon.
    const auto arrival_of = [&](const geometry::Polyline &path) {
      return arrive(path, body, p.hole_margin, p.horizon, 0, p.horizon);
    };
    ExtractionSettings extraction;
    extraction.threshold = p.crack_damage;
    extraction.horizon   = p.horizon;
    const double e_prime = material.effective_modulus();
    out << "global-local: " << p.mesh_file << ", " << body.holes.size() << " holes, initial crack " << crack->length()
        << " m; PD delta " << p.horizon << " m, m = " << p.horizon_ratio << ", box " << p.box.size
        << " m; K_c = " << std::sqrt(e_prime * p.material.fracture_energy) << " Pa m^1/2\n";

    GlobalLocalResult result;
    double            box_area_sum = 0.;
    std::size_t       n            = cycle.exchanges;
    const double      length0      = crack->length();
    for (; !cycle.finished; ++n)
      {
        if (n >= p.max_exchanges)
          {
            result.stop_reason = "maximum exchanges";
            break;
          }
        const double length = crack->length();
        if (length >= p.max_crack_length - 1e-9)
          {
            result.stop_reason = "maximum crack length";
            break;
          }
        ExchangeRecord record;
        record.exchange = n;

        // 1. Global solve at the reference load; the critical load from G = G_c.
        auto t = Clock::now();
        refine_at_tips(tria, crack->tips(), p.refinement_radius, p.refinement_levels);
        cycle.refined_at.push_back(crack->tips().front().position);
        problem.set_crack(crack);
        problem.setup();
        problem.assemble();
        problem.solve(solver);
        const auto        sif = problem.stress_intensity_factors().front();
        const global::Tip tip = crack->tips().front();
        record.tip            = tip.position;
        record.crack_length   = length;
        record.dofs           = problem.n_dofs();
        record.enriched_dofs  = problem.n_enriched_dofs();
        if (sif.k1 <= 0.)
          {
            result.stop_reason = "the crack closes under the load (K_I <= 0)";
            break;
          }
        const double g_ref   = (sif.k1 * sif.k1 + sif.k2 * sif.k2) / e_prime;
        record.critical_load = p.reference_load * std::sqrt(p.material.fracture_energy / g_ref);
        record.seconds_global = seconds_since(t);

        // 2. The box, the PD body in it, the global displacement per unit load at its nodes.
        t                        = Clock::now();
        const geometry::Box box  = policy.place(tip.position, tip.direction);
        record.box               = box;
        local::Region region{body, box, {crack->vertices()}};
        const local::PdModel model(p.material, p.horizon, p.horizon_ratio, region);
        std::vector<Point>   x;
        for (std::size_t i : model.nodes())
          x.push_back(model.lattice().position(i));
        problem.prepare_point_evaluation(x);
        const auto u_ref = problem.evaluate_points();
        std::vector<double> ux(model.lattice().storage_size(), 0.), uy(ux.size(), 0.); // per unit load
        for (std::size_t k = 0; k < x.size(); ++k)
          {
            ux[model.nodes()[k]] = u_ref[k].x / p.reference_load;
            uy[model.nodes()[k]] = u_ref[k].y / p.reference_load;
          }
        record.seconds_point_evaluation = seconds_since(t);
        record.pd_nodes                 = model.nodes().size();
        box_area_sum += box.width() * box.height();

        // 3. PD states at rising load until the crack grows (ExchangeController).
        local::BoundaryLayer           layer(model);
        const local::DynamicRelaxation relax(model, p.tolerance, p.max_iterations);
        std::vector<double>            layer_x(layer.size()), layer_y(layer.size());
        const double                   allowed =
          std::min(controller.allowed_advance(clearance(tip.position, body)), p.max_crack_length - length);
        local::State                   s      = model.initial_state();
        double                         lambda = controller.start();
        for (std::size_t i : model.nodes())
          {
            s.ux[i] = lambda * record.critical_load * ux[i];
            s.uy[i] = lambda * record.critical_load * uy[i];
          }
        local::State                  saved = s;
        double                        saved_lambda = lambda, state_lambda = lambda;
        CrackIncrement                increment;
        ExchangeController::Decision  decision = ExchangeController::Decision::raise;
        std::string                   branching;
        for (;;)
          {
            t = Clock::now();
            // Start from the last equilibrium scaled to the new load (exact while the box is elastic).
            for (std::size_t i : model.nodes())
              {
                s.ux[i] *= lambda / state_lambda;
                s.uy[i] *= lambda / state_lambda;
              }
            const double load = lambda * record.critical_load;
            for (std::size_t k = 0; k < layer.size(); ++k)
              {
                layer_x[k] = load * ux[model.boundary_layer()[k]];
                layer_y[k] = load * uy[model.boundary_layer()[k]];
              }
            layer.set_target(layer_x, layer_y);
            layer.apply(s, 1.);
            const auto relaxed = relax.solve(s);
            local::check_finite(model, s);
            state_lambda = lambda;
            record.pd_iterations += relaxed.iterations;
            ++record.substeps;
            result.pd_node_steps += double(relaxed.iterations) * double(model.nodes().size());
            record.seconds_pd += seconds_since(t);

            t = Clock::now();
            try
              {
                increment = extract_crack(damage_field(model, s), tip.position, tip.direction, extraction);
              }
            catch (const CrackBranching &e)
              {
                branching = e.what();
              }
            record.seconds_extraction += seconds_since(t);
            if (!branching.empty())
              break;
            const bool arrives = increment.path.size() > 1 && !arrival_of(increment.path).reason.empty();
            decision = controller.judge(increment.length(), allowed, arrives);
            out << "    PD at " << std::setprecision(4) << lambda << " P_c: " << relaxed.iterations
                << " DR iterations, advance " << increment.length() << " m -> " << to_text(decision) << "\n"
                << std::setprecision(6);
            if (decision == ExchangeController::Decision::raise)
              {
                saved        = s;
                saved_lambda = lambda;
                lambda       = controller.load_factor();
              }
            else if (decision == ExchangeController::Decision::repeat)
              {
                s            = saved;
                state_lambda = saved_lambda;
                lambda       = controller.load_factor();
                ++record.repeats;
              }
            else
              break;
          }
        record.load_factor             = lambda;
        record.load                    = lambda * record.critical_load;
        record.k1                      = sif.k1 * record.load / p.reference_load;
        record.k2                      = sif.k2 * record.load / p.reference_load;
        problem.scale_solution(record.load / p.reference_load);
        record.load_point_displacement = -problem.displacement(p.load_point).y;
        record.decision                = branching.empty() ? to_text(decision) : "branching";

        // 4. The increment into the global crack; arrival at a hole or the outline ends it.
        std::string stop;
        if (!branching.empty())
          stop = "crack branching in the PD box, refused: " + branching;
        else if (decision == ExchangeController::Decision::too_small)
          {
            std::ostringstream reason;
            reason << "the load is too small to grow the crack: no growth up to " << p.exchange.max_load_factor << " P_c";
            stop = reason.str();
          }
        else
          {
            const auto arrival = arrival_of(truncate(increment.path, allowed));
            for (std::size_t k = 1; k < arrival.path.size(); ++k)
              if (geometry::norm(arrival.path[k] - crack->vertices().back()) > 1e-3 * h)
                crack->grow(0, arrival.path[k]);
            record.advance = crack->length() - length;
            stop           = arrival.reason;
          }

        const bool last = !stop.empty() || n + 1 >= p.max_exchanges || crack->length() >= p.max_crack_length - 1e-9;
        result.exchanges.push_back(record);
        if (table)
          {
            write_record(table, record);
            table.flush();
          }
        if (!p.output_directory.empty())
          {
            if ((n % p.output_interval == 0) || last)
              {
                global_series->add(problem, n);
                pd_series->add(model, s);
              }
            write_path(p.output_directory + "/crack_path.csv", crack->vertices());
            write_boxes(p.output_directory + "/boxes.csv", policy.history());
            cycle.exchanges   = n + 1;
            cycle.load_factor = controller.load_factor();
            cycle.finished    = !stop.empty();
            cycle.crack       = crack->vertices();
            cycle.boxes       = policy.history();
            write_cycle_checkpoint(checkpoint, cycle);
          }

        const double grown = crack->length() - length0;
        const double eta   = grown > 0. ? seconds_since(t0) / grown * (p.max_crack_length - crack->length()) : 0.;
        out << "exchange " << std::setw(3) << n << "  load " << std::setprecision(4) << record.load << " N/m ("
            << record.load_factor << " P_c)  crack " << crack->length() << " m  +" << 1e3 * record.advance
            << " mm  tip " << to_text(crack->vertices().back()) << "  box [" << box.x_min << ", " << box.x_max
            << "] x [" << box.y_min << ", " << box.y_max << "]" << (policy.moved() ? " new" : "") << "  "
            << record.pd_nodes << " PD nodes, " << record.substeps << " states, " << record.pd_iterations
            << " DR its  ETA <= " << std::fixed << std::setprecision(0) << eta << " s" << std::defaultfloat
            << std::setprecision(6) << "\n";
        if (!stop.empty())
          {
            result.stop_reason = stop;
            out << "  stop: " << stop << "\n";
            break;
          }
      }

    if (result.stop_reason.empty() && cycle.finished) // resumed from the checkpoint of a run that had stopped
      result.stop_reason = "nothing to resume: the checkpointed run had already stopped after exchange " +
                           std::to_string(cycle.exchanges) + " (its reason: the last row of load_steps.csv)";
    result.path    = crack->vertices();
    result.boxes   = policy.history();
    result.seconds = seconds_since(t0);
    if (!result.exchanges.empty())
      result.mean_box_area = box_area_sum / double(result.exchanges.size());
    if (!reference.empty())
      {
        const auto d = published_distance(result.path, reference, 0.1 * h);
        result.published_mean      = d.mean;
        result.published_hausdorff = d.hausdorff;
        out << "pumpd-metric coupling.mean_dev_mm " << 1e3 * d.mean << "\n"
            << "pumpd-metric coupling.hausdorff_mm " << 1e3 * d.hausdorff << "\n";
      }
    double seconds[4] = {0., 0., 0., 0.};
    for (const auto &r : result.exchanges)
      {
        seconds[0] += r.seconds_global;
        seconds[1] += r.seconds_point_evaluation;
        seconds[2] += r.seconds_pd;
        seconds[3] += r.seconds_extraction;
      }
    out << "pumpd-metric coupling.seconds_global " << seconds[0] << "\n"
        << "pumpd-metric coupling.seconds_point_evaluation " << seconds[1] << "\n"
        << "pumpd-metric coupling.seconds_pd " << seconds[2] << "\n"
        << "pumpd-metric coupling.seconds_extraction " << seconds[3] << "\n";
    // What the scene modelled, against the whole beam: PD nodes over a full-domain PD lattice of
    // the same spacing (body area / h^2), enriched over all global unknowns (last solve).
    double pd_nodes = 0.;
    for (const auto &r : result.exchanges)
      pd_nodes += double(r.pd_nodes) / double(result.exchanges.size());
    double body_area = body.outline.width() * body.outline.height();
    for (const auto &hole : body.holes)
      body_area -= 3.14159265358979323846 * hole.radius * hole.radius;
    if (!result.exchanges.empty())
      out << "pumpd-metric scene.pd_nodes_over_fullpd_nodes " << pd_nodes / (body_area / (h * h)) << "\n"
          << "pumpd-metric scene.enriched_dof_fraction "
          << double(result.exchanges.back().enriched_dofs) / double(result.exchanges.back().dofs) << "\n"
          << "pumpd-metric coupling.global_dofs " << result.exchanges.back().dofs << "\n";
    out << "pumpd-metric coupling.seconds_total " << result.seconds << "\n";
    out << "pumpd-metric coupling.box_area_ratio " << result.mean_box_area / p.reference_box_area << "\n"
        << "pumpd-metric coupling.pd_node_steps " << result.pd_node_steps << "\n"
        << "end: " << result.stop_reason << "; crack " << crack->length() << " m, tip at "
        << to_text(crack->vertices().back()) << ", " << result.seconds << " s\n";
    return result;
  }
} // namespace pumpd::coupling
