#include "global_local.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>

#include "arrival.h"
#include "boundary_transfer.h"
#include "crack.h"
#include "cycle_checkpoint.h"
#include "error.h"
#include "exchange.h"
#include "path_metrics.h"
#include "recorder.h"

namespace pumpd::coupling
{
  using geometry::Point;
  using Clock            = std::chrono::steady_clock;
  namespace Patterns     = dealii::Patterns;
  using Decision         = ExchangeController::Decision;

  void CycleSettings::add_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Global-local");
    prm.add_parameter("Box size", box.size,
                      "Side of the square PD box [m]: at least 4 horizons plus the box margin, at most the body's "
                      "smaller side.",
                      Patterns::Double(1e-300));
    prm.add_parameter("Box tip position", box.behind,
                      "The tip sits this fraction of the box side from the box's rear (along the crack).",
                      Patterns::Double(0.05, 0.95));
    prm.add_parameter("Box margin", box.margin,
                      "The box moves ahead once the tip has less than this much free lattice ahead [m].",
                      Patterns::Double(1e-300));
    prm.add_parameter("Maximum box size", box.max_size,
                      "A box grows to take in a nearby hole up to this side [m], at least the box size.",
                      Patterns::Double(1e-300));
    prm.add_parameter("First load factor", exchange.first_load_factor,
                      "lambda / lambda_c of the first PD state of an exchange (lambda_c: G = G_c at the tip).",
                      Patterns::Double(0.05, 10.));
    prm.add_parameter("Load increment", exchange.load_increment, "dlambda / lambda_c between PD states.",
                      Patterns::Double(1e-4, 1.));
    prm.add_parameter("Minimum load increment", exchange.min_load_increment,
                      "A too-long advance halves the load increment down to this, then the advance is truncated; at "
                      "most the load increment.",
                      Patterns::Double(1e-6, 1.));
    prm.add_parameter("Maximum load factor", exchange.max_load_factor,
                      "No growth up to lambda = this lambda_c: the run stops (the load is too small); at least the "
                      "first load factor.",
                      Patterns::Double(0.05, 100.));
    prm.add_parameter("Maximum advance", exchange.max_advance, "da_max: the longest crack advance per exchange [m].",
                      Patterns::Double(1e-300));
    prm.add_parameter("Minimum advance", exchange.min_advance,
                      "An advance below this is no growth [m], at least two PD spacings and at most da_max / 2. A "
                      "short advance is mostly straight ahead: the increment must be long enough for the PD crack to "
                      "turn.",
                      Patterns::Double(0.));
    prm.add_parameter("Near distance", exchange.near_distance,
                      "Within this of a hole or the outline the advance per exchange is da_max / 2 [m].",
                      Patterns::Double(0., 1.));
    prm.add_parameter("Start below the last load", exchange.start_below_accepted,
                      "false: every exchange's PD states start at the first load factor (below lambda_c), so the "
                      "rebuilt box forms its process zone before the crack grows; true: one load increment below "
                      "the last accepted load (fewer PD states, but the crack then runs within one relaxation and "
                      "turns less).",
                      Patterns::Bool());
    prm.add_parameter("Maximum exchanges", max_exchanges, "Global-local exchanges at most.", Patterns::Integer(1));
    prm.add_parameter("Reference box area", reference_box_area,
                      "Area of the fixed PD box the moving box is compared with [m^2] (a metric); default: Ni et al. "
                      "(2019), 0.127 m x 0.1778 m.",
                      Patterns::Double(1e-300));
    prm.add_parameter("Output interval", output_interval,
                      "Write global and PD VTU every n exchanges (and the last).", Patterns::Integer(1));
    prm.add_parameter("Resume", resume,
                      "true: continue from checkpoint.h5 in the output directory (written after every exchange).",
                      Patterns::Bool());
    resolution.add_parameters(prm);
    prm.leave_subsection();
  }

  namespace
  {
    double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

    /// The scene's crack, which must have one tip: the cycle grows one.
    global::Crack one_tip_crack(const Scene &scene)
    {
      const auto   &vertices = scene.crack();
      const auto   &box      = scene.body.bounding_box();
      global::Crack crack(vertices, scene.body, 1e-8 * std::max(box.width(), box.height()));
      if (crack.tips().size() != 1)
        throw InvalidParameter("Initial cracks", to_text(vertices),
                               "the global-local cycle grows one tip: give an edge crack (one end on the outline or "
                               "a hole's rim)");
      return crack;
    }

    const char *load_steps_header =
      "exchange,lambda,load_factor,critical_load_factor,load,displacement,tip_x_m,tip_y_m,crack_length_m,K_I_Pa_sqrt_m,"
      "K_II_Pa_sqrt_m,advance_m,decision,pd_nodes,pd_substeps,pd_repeats,pd_iterations,dofs,seconds_global,"
      "seconds_point_evaluation,seconds_pd,seconds_extraction,horizon_m";

    void write_row(CsvFile &table, const ExchangeRecord &r)
    {
      table.row(r.exchange, r.lambda, r.load_factor, r.critical_load_factor, r.load, r.displacement, r.tip.x, r.tip.y,
                r.crack_length, r.k1, r.k2, r.advance, r.decision, r.pd_nodes, r.substeps, r.repeats, r.pd_iterations,
                r.dofs, r.seconds_global, r.seconds_point_evaluation, r.seconds_pd, r.seconds_extraction, r.horizon);
    }

    void write_boxes(CsvFile table, const std::vector<geometry::Box> &boxes)
    {
      for (std::size_t k = 0; k < boxes.size(); ++k)
        {
          const auto &b     = boxes[k];
          const bool  moved = k == 0 || b.x_min != boxes[k - 1].x_min || b.y_min != boxes[k - 1].y_min ||
                             b.x_max != boxes[k - 1].x_max || b.y_max != boxes[k - 1].y_max;
          table.row(k, b.x_min, b.y_min, b.x_max, b.y_max, moved);
        }
    }

    void print_summary(const GlobalLocalResult &r, const Scene &scene, double h, double reference_box_area,
                       std::ostream &out)
    {
      double seconds[4] = {0., 0., 0., 0.}, pd_nodes = 0., states = 0., iterations = 0.;
      for (const auto &e : r.exchanges)
        {
          seconds[0] += e.seconds_global;
          seconds[1] += e.seconds_point_evaluation;
          seconds[2] += e.seconds_pd;
          seconds[3] += e.seconds_extraction;
          pd_nodes += double(e.pd_nodes) / double(r.exchanges.size());
          states += double(e.substeps);
          iterations += double(e.pd_iterations);
        }
      if (r.reference_mean >= 0.)
        out << "pumpd-metric coupling.mean_dev_mm " << 1e3 * r.reference_mean << "\n"
            << "pumpd-metric coupling.hausdorff_mm " << 1e3 * r.reference_hausdorff << "\n";
      out << "pumpd-metric coupling.seconds_global " << seconds[0] << "\n"
          << "pumpd-metric coupling.seconds_point_evaluation " << seconds[1] << "\n"
          << "pumpd-metric coupling.seconds_pd " << seconds[2] << "\n"
          << "pumpd-metric coupling.seconds_extraction " << seconds[3] << "\n";
      // What the scene modelled, against the whole body: PD nodes over a full-domain PD lattice of
      // the same spacing (body area / h^2), enriched over all global unknowns (last solve).
      if (!r.exchanges.empty())
        out << "pumpd-metric scene.pd_nodes_over_fullpd_nodes " << pd_nodes / (scene.body.area() / (h * h)) << "\n"
            << "pumpd-metric scene.enriched_dof_fraction "
            << double(r.exchanges.back().enriched_dofs) / double(r.exchanges.back().dofs) << "\n"
            << "pumpd-metric coupling.global_dofs " << r.exchanges.back().dofs << "\n"
            << "pumpd-metric pd.dr_iterations_per_state " << iterations / std::max(1., states) << "\n";
      out << "pumpd-metric coupling.seconds_total " << r.seconds << "\n"
          << "pumpd-metric coupling.box_area_ratio " << r.mean_box_area / reference_box_area << "\n"
          << "pumpd-metric coupling.pd_node_steps " << r.pd_node_steps << "\n"
          << "end: " << r.stop_reason << "; crack " << geometry::length(r.path) << " m, tip at "
          << to_text(r.path.back()) << ", " << r.seconds << " s\n";
    }
  } // namespace

  namespace
  {
    /// One run of the cycle: its parts (global problem, box policy, controller, recorder) and
    /// the steps of an exchange, each a member function; run() is the loop over them.
    class Cycle
    {
    public:
      Cycle(const Scene &scene, const GlobalLocalSettings &settings, std::ostream &out);
      GlobalLocalResult run();

    private:
      /// "" or why no exchange may start: the exchange or crack length limit.
      std::string limit_reached(std::size_t n) const;
      /// The global problem: the tip's K and critical load factor; "" or why the run stops.
      std::string solve_global(ExchangeRecord &record, TipState &tip);
      /// The horizon of this exchange's box (resolution.h), chosen by the path ahead of the tip:
      /// the PD settings, the box, the advance and the global refinement at the tip follow it.
      void resolve(ExchangeRecord &record);
      /// The box around the tip and the PD body in it (the crack behind the tip as broken bonds).
      local::PdModel pd_body(const TipState &tip, ExchangeRecord &record);
      /// The mapping of the global displacement onto the body's nodes.
      BoundaryTransfer transfer_to(const local::PdModel &model, ExchangeRecord &record);
      /// The PD states along the load until the crack grows (exchange.h).
      ExchangeOutcome exchange(const local::PdModel &model, const BoundaryTransfer &transfer, const TipState &tip,
                               ExchangeRecord &record);
      /// The accepted increment into the crack; "" or why the run stops (a hole, the outline, ...).
      std::string grow(const ExchangeOutcome &outcome, ExchangeRecord &record);
      /// True if the ligament ahead of the tip (to the outline or a hole, along its direction) is
      /// narrower than Clearance over horizon of the finest box: no PD box resolves it.
      bool ligament_unresolved(const TipState &tip) const;
      /// One LEFM increment of a box horizon along the maximum hoop stress direction at lambda_c
      /// (as lefm_growth.h), to the outline or the hole where the ligament ends.
      std::string grow_by_lefm(const TipState &tip, ExchangeRecord &record);
      /// The files for people and the checkpoint; the progress line. `model` and `outcome` are
      /// those of the PD exchange, none for an LEFM increment.
      void write(const ExchangeRecord &record, const local::PdModel *model, const ExchangeOutcome *outcome,
                 const std::string &stop);
      /// The result: path, boxes, distances from the reference path; the summary metrics.
      GlobalLocalResult finish();

      /// The box's lengths over the section's: 2^-halvings.
      double length_scale() const { return std::ldexp(1., -int(halvings)); }
      /// Where a grown path ends: a hole within its margin, or the outline or a hole within a horizon.
      Arrival arrival_of(const geometry::Polyline &path) const
      {
        return arrive(path, scene.body, s.growth.hole_margin, pd.horizon, 0, pd.horizon);
      }

      const Scene                    &scene;
      const GlobalLocalSettings      &s;
      std::ostream                   &out;
      const double                    h, max_length;
      const local::MaterialParameters material;
      PeridynamicsSettings            pd;                 ///< of this exchange's box
      unsigned int                    halvings     = 0;   ///< its horizon: the section's / 2^halvings
      std::optional<global::Crack>    crack;
      GlobalProblem                   global;
      BoxPolicy                       boxes;
      ExchangeController              controller;
      Recorder                        recorder;
      std::string                     checkpoint;
      CycleState                      state;
      CsvFile                         steps;
      GlobalLocalResult               result;
      double                          box_area_sum = 0., length0 = 0.;
      Clock::time_point               t0 = Clock::now();
    };

    BoxSettings box_settings(const GlobalLocalSettings &s)
    {
      BoxSettings b = s.cycle.box;
      b.horizon     = s.pd.horizon;
      b.spacing     = s.pd.spacing();
      return b;
    }

    Cycle::Cycle(const Scene &sc, const GlobalLocalSettings &settings, std::ostream &progress)
      : scene(sc)
      , s(settings)
      , out(progress)
      , h(settings.pd.spacing())
      , max_length(settings.growth.length_limit())
      , material(settings.pd.material(sc.material))
      , pd(settings.pd)
      , crack(one_tip_crack(sc))
      , global(sc, settings.global)
      , boxes(sc.body, box_settings(settings))
      , controller(settings.cycle.exchange)
      , recorder(sc, settings.cycle.resume)
      , checkpoint(recorder.writes() ? recorder.path("checkpoint.h5") : "")
    {
      if (s.cycle.exchange.min_advance < 2. * h)
        throw InvalidParameter("Minimum advance", std::to_string(s.cycle.exchange.min_advance),
                               "must be at least two PD spacings (" + std::to_string(2. * h) +
                                 " m): a shorter advance is within the noise of the extracted tip");
      if (s.cycle.resume)
        {
          if (checkpoint.empty())
            throw InvalidParameter("Resume", "true", "needs an output directory holding checkpoint.h5");
          state = read_cycle_checkpoint(checkpoint);
          crack.emplace(state.crack, scene.body, 1e-8 * std::max(scene.body.bounding_box().width(), scene.body.bounding_box().height()));
          global.restore(state.refinements);
          // The last exchange's halvings: its refinement's levels beyond the section's.
          const int last_halvings =
            state.refinements.empty() ? 0 : int(state.refinements.back().levels) - int(s.global.refinement_levels);
          boxes.restore(state.boxes, std::ldexp(1., -std::max(0, last_halvings)));
          controller.restore(state.load_factor);
          out << "resuming after exchange " << state.exchanges << ": crack " << crack->length() << " m\n";
        }
      steps   = recorder.table("load_steps.csv", load_steps_header);
      length0 = crack->length();
      out << "global-local: " << scene.mesh_file << ", " << scene.body.holes().size() << " holes, initial crack "
          << crack->length() << " m; PD delta " << s.pd.horizon << " m, m = " << s.pd.horizon_over_spacing << ", box "
          << s.cycle.box.size << " m; K_c = " << scene.material.critical_sif() << " Pa m^1/2\n";
    }

    GlobalLocalResult Cycle::run()
    {
      for (std::size_t n = state.exchanges; !state.finished; ++n)
        {
          ExchangeRecord record;
          record.exchange     = n;
          record.crack_length = crack->length();
          TipState    tip;
          std::string stop = limit_reached(n);
          if (stop.empty())
            {
              resolve(record);
              stop = solve_global(record, tip);
            }
          if (!stop.empty())
            {
              result.stop_reason = stop;
              break;
            }
          if (ligament_unresolved(tip))
            {
              stop = grow_by_lefm(tip, record);
              write(record, nullptr, nullptr, stop);
            }
          else
            {
              const local::PdModel   model    = pd_body(tip, record);
              const BoundaryTransfer transfer = transfer_to(model, record);
              const ExchangeOutcome  outcome  = exchange(model, transfer, tip, record);
              stop                            = grow(outcome, record);
              write(record, &model, &outcome, stop);
            }
          if (!stop.empty())
            {
              result.stop_reason = stop;
              out << "  stop: " << stop << "\n";
              break;
            }
        }
      return finish();
    }

    std::string Cycle::limit_reached(std::size_t n) const
    {
      if (n >= s.cycle.max_exchanges)
        return "maximum exchanges";
      if (crack->length() >= max_length - 1e-9)
        return "maximum crack length";
      return "";
    }

    GlobalLocalResult Cycle::finish()
    {
      if (result.stop_reason.empty() && state.finished) // resumed from the checkpoint of a run that had stopped
        result.stop_reason = "nothing to resume: the checkpointed run had already stopped after exchange " +
                             std::to_string(state.exchanges) + " (its reason: the last row of load_steps.csv)";
      result.path    = crack->vertices();
      result.boxes   = boxes.history();
      result.seconds = seconds_since(t0);
      if (!result.exchanges.empty())
        result.mean_box_area = box_area_sum / double(result.exchanges.size());
      if (!scene.reference_path.empty())
        {
          const auto d               = published_distance(result.path, scene.reference_path, 0.1 * h);
          result.reference_mean      = d.mean;
          result.reference_hausdorff = d.hausdorff;
        }
      print_summary(result, scene, h, s.cycle.reference_box_area, out);
      return result;
    }

    std::string Cycle::solve_global(ExchangeRecord &record, TipState &tip)
    {
      const auto t                = Clock::now();
      tip                         = global.solve(*crack, halvings).front();
      record.tip                  = tip.position;
      record.critical_load_factor = tip.critical_load_factor;
      record.dofs                 = global.n_dofs();
      record.enriched_dofs        = global.n_enriched_dofs();
      record.seconds_global       = seconds_since(t);
      return tip.k1 > 0. ? "" : "the crack closes under the load (K_I <= 0)";
    }

    void Cycle::resolve(ExchangeRecord &record)
    {
      const auto  &tip       = crack->tips().front();
      const double reach     = s.cycle.exchange.max_advance + s.pd.horizon;
      const double clearance = std::min(clearance_ahead(scene.body, tip.position, tip.direction, reach, 0.5 * h),
                                        boxes.smallest_hole_within_reach(tip.position, tip.direction));
      halvings               = horizon_halvings(s.cycle.resolution, s.pd.horizon, clearance);
      pd.horizon             = length_scale() * s.pd.horizon;
      record.horizon         = pd.horizon;
    }

    local::PdModel Cycle::pd_body(const TipState &tip, ExchangeRecord &record)
    {
      const auto t = Clock::now();
      record.box   = boxes.place(tip.position, tip.direction, length_scale());
      local::PdModel model(material, pd.horizon, pd.horizon_over_spacing,
                           local::Region{scene.body, record.box, {crack->vertices()}});
      record.pd_nodes                 = model.nodes().size();
      record.seconds_point_evaluation = seconds_since(t);
      box_area_sum += record.box.width() * record.box.height();
      return model;
    }

    BoundaryTransfer Cycle::transfer_to(const local::PdModel &model, ExchangeRecord &record)
    {
      const auto       t = Clock::now();
      BoundaryTransfer transfer(global, model);
      record.seconds_point_evaluation += seconds_since(t);
      return transfer;
    }

    ExchangeOutcome Cycle::exchange(const local::PdModel &model, const BoundaryTransfer &transfer, const TipState &tip,
                                    ExchangeRecord &record)
    {
      const double allowed =
        std::min(length_scale() * controller.allowed_advance(scene.body.clearance(tip.position) / length_scale()),
                 max_length - record.crack_length);
      auto outcome = run_exchange(model, transfer, controller, tip, allowed,
                                  [&](const geometry::Polyline &path) { return !arrival_of(path).reason.empty(); },
                                  pd, out);
      outcome.increment.path = truncate(outcome.increment.path, allowed);
      record.pd_iterations      = outcome.iterations;
      record.substeps           = outcome.states;
      record.repeats            = outcome.repeats;
      record.seconds_pd         = outcome.seconds_pd;
      record.seconds_extraction = outcome.seconds_extraction;
      result.pd_node_steps += outcome.node_steps;
      record.load_factor = outcome.load_factor;
      record.lambda      = outcome.load_factor * tip.critical_load_factor;
      record.k1          = tip.k1 * record.lambda;
      record.k2          = tip.k2 * record.lambda;
      record.decision    = outcome.branching.empty() ? to_text(outcome.decision) : "branching";
      global.scale_to(record.lambda);
      std::tie(record.load, record.displacement) = global.report();
      return outcome;
    }

    std::string Cycle::grow(const ExchangeOutcome &outcome, ExchangeRecord &record)
    {
      if (!outcome.branching.empty())
        return "crack branching in the PD box, refused: " + outcome.branching;
      if (outcome.decision == Decision::too_small)
        {
          std::ostringstream reason;
          reason << "the load is too small to grow the crack: no growth up to " << s.cycle.exchange.max_load_factor
                 << " lambda_c";
          return reason.str();
        }
      const auto arrival = arrival_of(outcome.increment.path);
      for (std::size_t k = 1; k < arrival.path.size(); ++k)
        if (geometry::norm(arrival.path[k] - crack->vertices().back()) > 1e-3 * h)
          crack->grow(0, arrival.path[k]);
      record.advance = crack->length() - record.crack_length;
      return arrival.reason;
    }

    bool Cycle::ligament_unresolved(const TipState &tip) const
    {
      const auto  &r        = s.cycle.resolution;
      const double finest   = std::ldexp(s.pd.horizon, r.rule == "clearance" ? -int(r.max_halvings) : 0);
      const double ligament = std::min(scene.body.ray_to_outline(tip.position, tip.direction),
                                       scene.body.ray_to_holes(tip.position, tip.direction, 0.).t);
      return ligament < r.clearance_over_horizon * finest;
    }

    std::string Cycle::grow_by_lefm(const TipState &tip, ExchangeRecord &record)
    {
      const double angle   = kink_angle(tip.k1, tip.k2);
      const Point  n{-tip.direction.y, tip.direction.x};
      const Point  e       = std::cos(angle) * tip.direction + std::sin(angle) * n;
      const auto   arrival = arrival_of({tip.position, tip.position + pd.horizon * e});
      for (std::size_t k = 1; k < arrival.path.size(); ++k)
        if (geometry::norm(arrival.path[k] - crack->vertices().back()) > 1e-3 * h)
          crack->grow(0, arrival.path[k]);
      record.decision    = "lefm";
      record.load_factor = 1.;
      record.lambda      = tip.critical_load_factor;
      record.k1          = tip.k1 * record.lambda;
      record.k2          = tip.k2 * record.lambda;
      record.advance     = crack->length() - record.crack_length;
      global.scale_to(record.lambda);
      std::tie(record.load, record.displacement) = global.report();
      if (arrival.reason.empty())
        return "";
      return arrival.reason + " (the last ligament, narrower than " +
             pumpd::to_text(s.cycle.resolution.clearance_over_horizon, 3) +
             " horizons of the finest PD box, grown by LEFM: maximum hoop stress at G = G_c)";
    }

    void Cycle::write(const ExchangeRecord &record, const local::PdModel *model, const ExchangeOutcome *outcome,
                      const std::string &stop)
    {
      const std::size_t n    = record.exchange;
      const bool        last = !stop.empty() || n + 1 >= s.cycle.max_exchanges || crack->length() >= max_length - 1e-9;
      result.exchanges.push_back(record);
      write_row(steps, record);
      const bool accepted = !outcome || (outcome->branching.empty() && (outcome->decision == Decision::accept ||
                                                                        outcome->decision == Decision::truncate));
      if (accepted)
        recorder.load_displacement(n, record.lambda, record.load, record.displacement, crack->length(),
                                   crack->vertices().back());
      if (n % s.cycle.output_interval == 0 || last)
        {
          recorder.global_state(global, double(n));
          if (model)
            recorder.pd_state(*model, outcome->state);
        }
      recorder.crack_path(crack->vertices());
      if (recorder.writes())
        {
          write_boxes(CsvFile(recorder.path("boxes.csv"), "exchange,x_min_m,y_min_m,x_max_m,y_max_m,moved"), boxes.history());
          state.exchanges   = n + 1;
          state.load_factor = controller.load_factor();
          state.finished    = !stop.empty();
          state.crack       = crack->vertices();
          state.boxes       = boxes.history();
          state.refinements = global.refinements();
          write_cycle_checkpoint(checkpoint, state);
        }

      // ETA: the growth rate so far against what is left to grow (to the length limit, or to the
      // boundary ahead of the tip).
      const double grown = crack->length() - length0;
      const double ahead = std::min(max_length - crack->length(),
                                    crack->tips().empty() ? 0. : scene.body.ray_to_outline(crack->tips()[0].position,
                                                                                           crack->tips()[0].direction));
      const double eta = grown > 0. ? seconds_since(t0) / grown * ahead : 0.;
      const auto  &box = record.box;
      out << "exchange " << std::setw(3) << n << "  lambda " << std::setprecision(4) << record.lambda << " ("
          << record.load_factor << " lambda_c)  crack " << crack->length() << " m  +" << 1e3 * record.advance
          << " mm  tip " << to_text(crack->vertices().back()) << "  ";
      if (model)
        out << "box [" << box.x_min << ", " << box.x_max << "] x [" << box.y_min << ", " << box.y_max << "]"
            << (boxes.moved() ? " new" : "") << "  delta " << 1e3 * record.horizon << " mm, " << record.pd_nodes
            << " PD nodes, " << record.substeps << " states, " << record.pd_iterations << " DR its";
      else
        out << "LEFM increment (ligament below " << s.cycle.resolution.clearance_over_horizon
            << " horizons of the finest box)";
      out << "  ETA <= " << std::fixed << std::setprecision(0) << eta << " s" << std::defaultfloat
          << std::setprecision(6) << std::endl;
    }
  } // namespace

  GlobalLocalResult run_global_local(const Scene &scene, const GlobalLocalSettings &settings, std::ostream &progress)
  {
    return Cycle(scene, settings, progress).run();
  }
} // namespace pumpd::coupling
