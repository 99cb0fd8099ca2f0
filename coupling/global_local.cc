#include "global_local.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>

#include "arrival.h"
#include "boundary_transfer.h"
#include "crack.h"
#include "crack_network.h"
#include "cycle_checkpoint.h"
#include "error.h"
#include "exchange.h"
#include "path_metrics.h"
#include "recorder.h"

namespace pumpd::coupling
{
  using geometry::Point;
  using Clock            = std::chrono::steady_clock;
  using Decision         = ExchangeController::Decision;

  namespace
  {
    double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

    const char *load_steps_header =
      "exchange,lambda,load_factor,critical_load_factor,load,displacement,tip_x_m,tip_y_m,crack_length_m,K_I_Pa_sqrt_m,"
      "K_II_Pa_sqrt_m,advance_m,decision,pd_nodes,pd_substeps,pd_repeats,pd_iterations,dofs,seconds_global,"
      "seconds_point_evaluation,seconds_pd,seconds_extraction,horizon_m,tip_end,kink_deg,predicted_kink_deg,crack,"
      "onset_lambda,onset_load,pd_onset_substeps";

    void write_row(CsvFile &table, const ExchangeRecord &r)
    {
      table.row(r.exchange, r.lambda, r.load_factor, r.critical_load_factor, r.load, r.displacement, r.tip.x, r.tip.y,
                r.crack_length, r.k1, r.k2, r.advance, r.decision, r.pd_nodes, r.substeps, r.repeats, r.pd_iterations,
                r.dofs, r.seconds_global, r.seconds_point_evaluation, r.seconds_pd, r.seconds_extraction, r.horizon,
                r.tip_end, r.kink * 180. / M_PI, r.predicted_kink * 180. / M_PI, r.crack, r.onset_lambda, r.onset_load,
                r.onset_substeps);
    }

    void write_boxes(CsvFile &table, const std::vector<geometry::Box> &boxes, std::size_t track)
    {
      for (std::size_t k = 0; k < boxes.size(); ++k)
        {
          const auto &b     = boxes[k];
          const bool  moved = k == 0 || b.x_min != boxes[k - 1].x_min || b.y_min != boxes[k - 1].y_min ||
                             b.x_max != boxes[k - 1].x_max || b.y_max != boxes[k - 1].y_max;
          table.row(k, b.x_min, b.y_min, b.x_max, b.y_max, moved, track % 2, track / 2);
        }
    }

    void print_summary(const GlobalLocalResult &r, const Scene &scene, double h, double reference_box_area,
                       std::ostream &out)
    {
      double seconds[4] = {0., 0., 0., 0.}, pd_nodes = 0., states = 0., iterations = 0., unrelaxed = 0.;
      for (const auto &e : r.exchanges)
        {
          seconds[0] += e.seconds_global;
          seconds[1] += e.seconds_point_evaluation;
          seconds[2] += e.seconds_pd;
          seconds[3] += e.seconds_extraction;
          pd_nodes += double(e.pd_nodes) / double(r.exchanges.size());
          states += double(e.substeps);
          iterations += double(e.pd_iterations);
          unrelaxed += double(e.unrelaxed);
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
      out << "pumpd-metric pd.unrelaxed_states " << unrelaxed << "\n";
      // The loads the cycle predicts: the onset of growth at the first exchange that grew, and the largest.
      double first_growth = std::numeric_limits<double>::quiet_NaN(), peak = first_growth;
      for (const auto &e : r.exchanges)
        if (e.advance > 0. && std::isfinite(e.onset_load))
          {
            first_growth = std::isnan(first_growth) ? e.onset_load : first_growth;
            peak         = std::isnan(peak) ? e.onset_load : std::max(peak, e.onset_load);
          }
      if (!std::isnan(first_growth))
        out << "pumpd-metric coupling.first_growth_load " << first_growth << "\n"
            << "pumpd-metric coupling.peak_load " << peak << "\n";
      if (unrelaxed > 0.)
        std::cerr << "warning: " << unrelaxed << " of " << states
                  << " PD states did not relax within Relaxation max iterations: their damage, and the crack path "
                     "taken from it, are not equilibrium results; raise Relaxation max iterations"
                  << std::endl;
      out << "pumpd-metric coupling.seconds_total " << r.seconds << "\n"
          << "pumpd-metric coupling.box_area_ratio " << r.mean_box_area / reference_box_area << "\n"
          << "pumpd-metric coupling.pd_node_steps " << r.pd_node_steps << "\n"
          << "end: " << r.stop_reason << "; "
          << grown_cracks_text(scene.cracks, r.paths, scene.body, crack_tolerance(scene)) << ", " << r.seconds << " s\n";
    }
  } // namespace

  namespace
  {
    /// The end of its crack's polyline a tip sits at (0: its first vertex, 1: its last): a tip keeps
    /// it while the crack grows and when the other tip stops.
    std::size_t end_of(const global::Tip &tip) { return tip.vertex == 0 ? 0 : 1; }

    /// A tip's track: 2 c + its end, c the crack's index in the scene's order.
    std::size_t track_of(std::size_t crack, const global::Tip &tip) { return 2 * crack + end_of(tip); }

    BoxSettings box_settings(const GlobalLocalSettings &s)
    {
      BoxSettings b = s.cycle.box;
      b.horizon     = s.pd.horizon;
      b.spacing     = s.pd.spacing();
      return b;
    }

    /// What the cycle keeps for one end of a crack: the box that follows its tip, the
    /// controller of its exchanges, its box's horizon, and whether the tip has stopped.
    struct TipTrack
    {
      TipTrack(const Scene &scene, const GlobalLocalSettings &s)
        : boxes(scene.body, box_settings(s))
        , controller(s.cycle.exchange)
        , pd(s.pd)
      {}

      /// The box's lengths over the section's: 2^-halvings.
      double length_scale() const { return std::ldexp(1., -halvings); }

      BoxPolicy            boxes;
      ExchangeController   controller;
      PeridynamicsSettings pd;           ///< of this tip's box
      int                  halvings = 0; ///< its horizon: the section's / 2^halvings (< 0: doubled)
      bool                 stopped  = false;
    };

    /// One tip's part of an exchange: its state under the global solve, its increment and the
    /// decision on it; the PD body and its last state where the tip leads a box.
    struct TipExchange
    {
      std::size_t                   track = 0; ///< 2 crack + end
      TipState                      tip;
      ExchangeRecord                record;
      geometry::Polyline            increment; ///< from the tip
      Decision                      decision = Decision::raise;
      std::string                   branching;
      std::optional<local::PdModel> model;  ///< of the box it leads; none where it shares one or grew by LEFM
      local::State                  state;  ///< the box's last PD state
      std::size_t                   box = 0; ///< the index of the part that leads its box (itself if it leads)
      bool                          by_lefm = false;
      bool                          grows   = false; ///< its increment goes into the crack at this exchange's load
      std::string                   stop;            ///< why the tip stopped at this exchange ("" while it goes on)
    };

    /// One run of the cycle: its parts (global problem, a box and a controller per tip, recorder)
    /// and the steps of an exchange, each a member function; run() is the loop over them.
    class Cycle
    {
    public:
      Cycle(const Scene &scene, const GlobalLocalSettings &settings, std::ostream &out);
      GlobalLocalResult run();

    private:
      /// "" or why no exchange may start: the exchange or crack length limit.
      std::string limit_reached(std::size_t n) const;
      /// The global problem: every tip's K and critical load factor, and the tips that get a box
      /// (the box threshold); "" or why the run stops.
      std::string solve_global(std::size_t n, std::vector<TipExchange> &parts);
      /// Why the run stops when no tip that goes on grows at any load: the tips stopped before, and
      /// why each other is at rest (at_rest). `track` holds the track of each state.
      std::string at_rest_stop(const std::vector<TipState> &states, const std::vector<std::size_t> &track) const;
      /// The horizon of this tip's box (resolution.h), chosen by the path ahead of it: the PD
      /// settings, the box and the advance follow it.
      void resolve(TipExchange &part);
      /// True at a tip of an initial crack that has not grown.
      bool initial_tip(geometry::Point position) const
      {
        const double tolerance = crack_tolerance(scene);
        return std::any_of(scene.cracks.begin(), scene.cracks.end(), [&](const geometry::Polyline &c) {
          return norm(c.front() - position) <= tolerance || norm(c.back() - position) <= tolerance;
        });
      }
      /// The tips (indices into parts) that share each box: tips within half a box side of each
      /// other, the one with the smallest lambda_c first (it leads: the box's load is in its
      /// lambda_c); a tip whose ligament no box resolves is alone.
      std::vector<std::vector<std::size_t>> share_boxes(const std::vector<TipExchange> &parts) const;
      /// The box around its tips and the PD body in it (the whole crack as broken bonds, the
      /// places of the scene's conditions it takes in held to the global displacement), at the
      /// finest horizon its tips' resolution asks for.
      void pd_body(const std::vector<std::size_t> &box, std::vector<TipExchange> &parts);
      /// The track whose box policy and controller a box uses: the lowest of its tips', so that
      /// a shared box keeps one history while the tip with the smallest lambda_c may change.
      std::size_t owner(const std::vector<std::size_t> &box, const std::vector<TipExchange> &parts) const
      {
        std::size_t t = parts[box.front()].track;
        for (std::size_t m : box)
          t = std::min(t, parts[m].track);
        return t;
      }
      /// The mapping of the global displacement onto the body's nodes.
      BoundaryTransfer transfer_to(TipExchange &lead);
      /// The PD states along the load until the crack grows at a tip of the box (exchange.h).
      void exchange(const BoundaryTransfer &transfer, const std::vector<std::size_t> &box,
                    std::vector<TipExchange> &parts);
      /// The load of the exchange and the tips that grow at it (README, "Several tips"); the
      /// accepted increments into the crack; "" or why the run stops (branching, no growth, every
      /// tip stopped at a hole or the outline).
      std::string grow(std::vector<TipExchange> &parts);
      /// The tip's increment into its crack, cut where it arrives at a hole, the outline or
      /// another crack's face (it joins it there): sets why the tip stops, if it does.
      void grow_tip(TipExchange &part);
      /// True if the ligament ahead of the tip (to the outline or a hole, along its direction) is
      /// narrower than Clearance over horizon of the finest box, or the tip lies that close to a
      /// place of the scene's conditions (its box would hold the place: held_places): no PD box
      /// resolves it.
      bool ligament_unresolved(const TipState &tip) const;
      /// One LEFM increment of a box horizon along the maximum hoop stress direction at lambda_c
      /// (as lefm_growth.h), to the outline or the hole where the ligament ends.
      void grow_by_lefm(TipExchange &part);
      /// The files for people and the checkpoint; a progress line per tip.
      void write(std::size_t n, const std::vector<TipExchange> &parts, const std::string &stop);
      /// The result: path, boxes, distances from the reference path; the summary metrics.
      GlobalLocalResult finish();

      /// Where a grown path ends: a hole within its margin, or the outline or a hole within a horizon.
      Arrival arrival_of(const geometry::Polyline &path, double horizon) const
      {
        return arrive(path, scene.body, s.growth.hole_margin, horizon, 0, horizon);
      }
      /// The index in its crack's tips() of the tip of this track.
      std::size_t tip_index(std::size_t track) const;
      geometry::Point end_vertex(std::size_t track) const
      {
        const auto &v = cracks[track / 2].vertices();
        return track % 2 == 0 ? v.front() : v.back();
      }
      /// The cracks' total length [m].
      double crack_length() const;
      std::vector<geometry::Polyline> polylines() const;

      const Scene                    &scene;
      const GlobalLocalSettings      &s;
      std::ostream                   &out;
      const double                    h, max_length;
      const local::MaterialParameters material;
      std::vector<global::Crack>      cracks;
      GlobalProblem                   global;
      std::vector<TipTrack>           tracks; ///< per end of each crack: 2 crack + end
      CycleState                      state;  ///< before the recorder: a refused resume writes nothing
      Recorder                        recorder;
      std::string                     checkpoint;
      CsvFile                         steps;
      GlobalLocalResult               result;
      double                          box_area_sum = 0., length0 = 0.;
      std::size_t                     boxes_placed = 0;
      std::vector<std::string>        stopped_tips; ///< why each tip that stopped did, in order
      Clock::time_point               t0 = Clock::now();
    };

    /// The scene's cracks (an edge crack has one tip, an interior crack two; an end on another
    /// crack's face is a junction: a scene's T, or a crack that joined another before a resume).
    std::vector<global::Crack> the_cracks(const std::vector<geometry::Polyline> &polylines, const Scene &scene)
    {
      if (polylines.empty())
        throw InvalidParameter("Initial cracks", "none", "the global-local cycle grows a crack: give one");
      return enriched_cracks(polylines, scene);
    }

    /// The scene file's entries that change the cycle's results: every entry of the sections it
    /// reads but those that only extend a run (Maximum exchanges, Maximum crack length), say how
    /// often or where it writes (Output interval, Output directory), Resume itself, and the mesh
    /// file's name (its cells and vertices are in the geometry fingerprint).
    std::vector<std::pair<std::string, std::string>> results_entries(const ParameterTable &file)
    {
      const std::vector<std::string> read = {"Method/",        "Scene/",      "Global/",     "Peridynamics/",
                                             "Crack growth/", "Initiation/", "Global-local/"};
      const std::vector<std::string> left_out = {
        "Global-local/Maximum exchanges", "Crack growth/Maximum crack length", "Global-local/Output interval",
        "Scene/Output directory",         "Global-local/Resume",               "Scene/Mesh file"};
      std::vector<std::pair<std::string, std::string>> entries;
      for (const auto &[path, value] : file.all())
        if (std::any_of(read.begin(), read.end(), [&](const auto &s) { return path.rfind(s, 0) == 0; }) &&
            std::find(left_out.begin(), left_out.end(), path) == left_out.end())
          entries.emplace_back(path, value);
      return entries;
    }

    /// "" if the two lists of entries agree, else the first entry that differs: in the
    /// checkpoint's run (`then`) against this one (`now`).
    std::string first_difference(const std::vector<std::pair<std::string, std::string>> &then,
                                 const std::vector<std::pair<std::string, std::string>> &now)
    {
      const auto value_in = [](const auto &entries, const std::string &path) -> std::optional<std::string> {
        for (const auto &[p, v] : entries)
          if (p == path)
            return v;
        return std::nullopt;
      };
      const auto shown = [](const std::optional<std::string> &v) { return v ? *v : std::string("(no such entry)"); };
      for (const auto *entries : {&then, &now})
        for (const auto &[path, value] : *entries)
          if (const auto a = value_in(then, path), b = value_in(now, path); a != b)
            return path + " = " + shown(a) + " there, " + shown(b) + " here";
      return "";
    }

    /// A new run's state, or with Resume the one in the output directory's checkpoint.h5, which
    /// the same scene must have written: the same geometry and the same entries that change results.
    CycleState starting_state(const Scene &scene, const CycleSettings &settings)
    {
      const std::uint64_t fingerprint = geometry_fingerprint(scene);
      CycleState          state;
      state.scene   = fingerprint;
      state.entries = results_entries(settings.scene_file);
      if (!settings.resume)
        return state;
      if (scene.output_directory.empty())
        throw InvalidParameter("Resume", "true", "needs an output directory holding checkpoint.h5");
      const std::string checkpoint = scene.output_directory + "/checkpoint.h5";
      CycleState        saved;
      try
        {
          saved = read_cycle_checkpoint(checkpoint);
        }
      catch (const std::runtime_error &e)
        {
          throw InvalidParameter("Resume", "true",
                                 std::string(e.what()) + " (needs the checkpoint.h5 a global-local run of this "
                                                         "scene wrote in its output directory)");
        }
      const std::string resume_it = ": resume the scene that wrote it, or set Resume = false";
      if (const std::string entry = first_difference(saved.entries, state.entries); !entry.empty())
        throw InvalidParameter("Resume", "true",
                               checkpoint + " was written by a run of another scene (" + entry + ")" + resume_it);
      if (saved.scene != fingerprint)
        throw InvalidParameter("Resume", "true",
                               checkpoint + " was written by a run of another scene (its mesh or initial cracks "
                                            "differ)" + resume_it);
      return saved;
    }

    Cycle::Cycle(const Scene &sc, const GlobalLocalSettings &settings, std::ostream &progress)
      : scene(sc)
      , s(settings)
      , out(progress)
      , h(settings.pd.spacing())
      , max_length(settings.growth.length_limit())
      , material(settings.pd.material(sc.material))
      , cracks(the_cracks(sc.cracks, sc))
      , global(sc, settings.global)
      , tracks(2 * sc.cracks.size(), TipTrack(sc, settings))
      , state(starting_state(sc, settings.cycle))
      , recorder(sc, settings.cycle.resume ? std::optional(state.outputs) : std::nullopt)
      , checkpoint(recorder.writes() ? recorder.path("checkpoint.h5") : "")
    {
      if (s.cycle.exchange.min_advance < 2. * h)
        throw InvalidParameter("Minimum advance", std::to_string(s.cycle.exchange.min_advance),
                               "must be at least two PD spacings (" + std::to_string(2. * h) +
                                 " m): a shorter advance is within the noise of the extracted tip");
      std::vector<Point> tips;
      for (const auto &c : cracks)
        for (const auto &t : c.tips())
          tips.push_back(t.position);
      for (std::size_t i = 0; i < tips.size(); ++i)
        for (std::size_t j = i + 1; j < tips.size(); ++j)
          if (norm(tips[i] - tips[j]) < s.pd.horizon)
            throw InvalidParameter("Initial cracks", to_text(tips[i]) + " and " + to_text(tips[j]),
                                   "two tips lie within one horizon (" + pumpd::to_text(s.pd.horizon, 3) +
                                     " m) of each other: PD cannot resolve them apart; give cracks whose tips are at "
                                     "least a horizon apart");
      if (s.cycle.resume)
        {
          if (state.cracks.size() != cracks.size())
            throw InvalidParameter("Resume", "true",
                                   "the checkpoint holds " + std::to_string(state.cracks.size()) +
                                     " cracks, the scene " + std::to_string(cracks.size()));
          cracks = the_cracks(state.cracks, scene);
          global.restore(state.refinements);
          for (std::size_t e = 0; e < tracks.size(); ++e)
            {
              const auto &saved = state.ends[e];
              tracks[e].halvings = saved.halvings;
              tracks[e].stopped  = saved.stopped;
              tracks[e].boxes.restore(saved.boxes, tracks[e].length_scale());
              tracks[e].controller.restore(saved.load_factor);
            }
          // As the checkpoint has them: the run may have stopped after writing later ones.
          recorder.crack_paths(polylines());
          out << "resuming after exchange " << state.exchanges << ": cracks " << crack_length() << " m\n";
        }
      steps   = recorder.table("load_steps.csv", load_steps_header);
      length0 = crack_length();
      out << "global-local: " << scene.mesh_file << ", " << scene.body.holes().size() << " holes, "
          << cracks.size() << (cracks.size() == 1 ? " crack " : " cracks ") << crack_length() << " m with "
          << tips.size() << (tips.size() == 1 ? " tip" : " tips") << "; PD delta " << s.pd.horizon
          << " m, m = " << s.pd.horizon_over_spacing << ", box " << s.cycle.box.size
          << " m; K_c = " << scene.material.critical_sif() << " Pa m^1/2\n";
    }

    GlobalLocalResult Cycle::run()
    {
      for (std::size_t n = state.exchanges; !state.finished; ++n)
        {
          std::vector<TipExchange> parts;
          std::string              stop = limit_reached(n);
          if (stop.empty())
            stop = solve_global(n, parts);
          if (!stop.empty())
            {
              result.stop_reason = stop;
              break;
            }
          for (auto &part : parts)
            resolve(part);
          const auto boxes = share_boxes(parts);
          for (const auto &box : boxes)
            if (!ligament_unresolved(parts[box.front()].tip))
              pd_body(box, parts);
          for (const auto &box : boxes)
            if (ligament_unresolved(parts[box.front()].tip))
              grow_by_lefm(parts[box.front()]);
            else
              exchange(transfer_to(parts[box.front()]), box, parts);
          stop = grow(parts);
          write(n, parts, stop);
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
      if (crack_length() >= max_length - 1e-9)
        return "maximum crack length";
      return "";
    }

    GlobalLocalResult Cycle::finish()
    {
      if (result.stop_reason.empty() && state.finished) // resumed from the checkpoint of a run that had stopped
        result.stop_reason = "nothing to resume: the checkpointed run had already stopped after exchange " +
                             std::to_string(state.exchanges) + " (its reason: the last row of load_steps.csv)";
      result.path  = cracks.front().vertices();
      result.paths = polylines();
      for (const auto &track : tracks)
        result.boxes.insert(result.boxes.end(), track.boxes.history().begin(), track.boxes.history().end());
      result.seconds = seconds_since(t0);
      if (boxes_placed > 0)
        result.mean_box_area = box_area_sum / double(boxes_placed);
      if (!scene.reference_path.empty())
        {
          const auto d               = published_distance(result.path, scene.reference_path, 0.1 * h);
          result.reference_mean      = d.mean;
          result.reference_hausdorff = d.hausdorff;
        }
      print_summary(result, scene, h, s.cycle.reference_box_area, out);
      return result;
    }

    std::size_t Cycle::tip_index(std::size_t track) const
    {
      const auto &tips = cracks[track / 2].tips();
      for (std::size_t t = 0; t < tips.size(); ++t)
        if (end_of(tips[t]) == track % 2)
          return t;
      throw std::logic_error("no tip at this end of the crack");
    }

    double Cycle::crack_length() const
    {
      double length = 0.;
      for (const auto &c : cracks)
        length += c.length();
      return length;
    }

    std::vector<geometry::Polyline> Cycle::polylines() const
    {
      std::vector<geometry::Polyline> p;
      for (const auto &c : cracks)
        p.push_back(c.vertices());
      return p;
    }

    std::string Cycle::solve_global(std::size_t n, std::vector<TipExchange> &parts)
    {
      const auto   t      = Clock::now();
      const auto   states = global.solve(cracks);
      const double solved = seconds_since(t);
      std::vector<std::size_t> track; // of each state: the cracks' tips in order
      for (std::size_t c = 0; c < cracks.size(); ++c)
        for (const auto &tip : cracks[c].tips())
          track.push_back(track_of(c, tip));
      double first = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < states.size(); ++k)
        if (!tracks[track[k]].stopped)
          first = std::min(first, states[k].critical_load_factor);
      if (!std::isfinite(first))
        return at_rest_stop(states, track);
      // G scales with lambda^2: at lambda = first a tip has G / G_c = (first / lambda_c)^2.
      for (std::size_t k = 0; k < states.size(); ++k)
        {
          const double g = std::pow(first / states[k].critical_load_factor, 2);
          if (tracks[track[k]].stopped || g < s.cycle.box_threshold)
            continue;
          TipExchange part;
          part.track                         = track[k];
          part.tip                           = states[k];
          part.record.exchange               = n;
          part.record.crack                  = track[k] / 2;
          part.record.tip_end                = track[k] % 2;
          part.record.crack_length           = crack_length();
          part.record.tip                    = part.tip.position;
          part.record.critical_load_factor   = part.tip.critical_load_factor;
          part.record.dofs                   = global.n_dofs();
          part.record.enriched_dofs          = global.n_enriched_dofs();
          part.record.seconds_global         = parts.empty() ? solved : 0.;
          part.record.predicted_kink         = kink_angle(part.tip.k1, part.tip.k2);
          parts.push_back(std::move(part));
        }
      return "";
    }

    std::string Cycle::at_rest_stop(const std::vector<TipState> &states, const std::vector<std::size_t> &track) const
    {
      std::string stop;
      for (const auto &reason : stopped_tips)
        stop += reason + "; ";
      for (std::size_t k = 0; k < states.size(); ++k)
        if (!tracks[track[k]].stopped)
          stop += tip_stop(states[k].position, at_rest(states[k])) + "; ";
      return stop + "no tip grows";
    }

    void Cycle::resolve(TipExchange &part)
    {
      auto      &track     = tracks[part.track];
      const auto clearance = [&](double scale) {
        if (!track.boxes.fits(scale))
          return 0.;
        const double reach = scale * (s.cycle.exchange.max_advance + s.pd.horizon);
        double       c     = std::min(clearance_ahead(scene.body, part.tip.position, part.tip.direction, reach, 0.5 * h),
                                      track.boxes.smallest_hole_within_reach(part.tip.position, part.tip.direction, scale));
        if (scale > 1.)
          {
            std::vector<geometry::Polyline> others;
            for (std::size_t k = 0; k < cracks.size(); ++k)
              if (k != part.track / 2)
                others.push_back(cracks[k].vertices());
            c = std::min(c, clearance_ahead(others, part.tip.position, part.tip.direction, reach, 0.5 * h));
          }
        return c;
      };
      track.halvings = horizon_halvings(s.cycle.resolution, s.pd.horizon, clearance);
      if (initial_tip(part.tip.position))
        {
          const auto &crack = cracks[part.track / 2];
          const double kink = part.record.predicted_kink;
          const int    k    = std::max(
            kink_halvings(s.cycle.resolution, s.pd.horizon, kink, crack.length() / double(crack.tips().size())),
            field_kink_halvings(s.cycle.resolution, s.pd.horizon, kink,
                                [&](double r) { return global.hoop_direction(part.tip, r); }));
          if (k > 0)
            track.halvings = std::max(track.halvings, k);
        }
      track.pd.horizon       = track.length_scale() * s.pd.horizon;
      part.record.horizon    = track.pd.horizon;
    }

    std::vector<std::vector<std::size_t>> Cycle::share_boxes(const std::vector<TipExchange> &parts) const
    {
      std::vector<std::vector<std::size_t>> boxes;
      for (std::size_t k = 0; k < parts.size(); ++k)
        {
          const auto near = [&](std::size_t m) {
            const double side = s.cycle.box.size * std::min(tracks[parts[k].track].length_scale(),
                                                              tracks[parts[m].track].length_scale());
            return norm(parts[k].tip.position - parts[m].tip.position) < 0.5 * side;
          };
          auto shared = boxes.end();
          if (!ligament_unresolved(parts[k].tip))
            shared = std::find_if(boxes.begin(), boxes.end(), [&](const std::vector<std::size_t> &box) {
              return !ligament_unresolved(parts[box.front()].tip) && std::all_of(box.begin(), box.end(), near);
            });
          if (shared == boxes.end())
            boxes.push_back({k});
          else
            shared->push_back(k);
        }
      for (auto &box : boxes)
        std::stable_sort(box.begin(), box.end(), [&](std::size_t a, std::size_t b) {
          return parts[a].tip.critical_load_factor < parts[b].tip.critical_load_factor;
        });
      return boxes;
    }

    void Cycle::pd_body(const std::vector<std::size_t> &box, std::vector<TipExchange> &parts)
    {
      const auto   t    = Clock::now();
      TipExchange &lead = parts[box.front()];
      int finest = tracks[lead.track].halvings;
      for (std::size_t m : box)
        finest = std::max(finest, tracks[parts[m].track].halvings);
      std::vector<Point> tips, directions, turns;
      for (std::size_t m : box)
        {
          auto &track         = tracks[parts[m].track];
          track.halvings      = finest;
          track.pd.horizon    = track.length_scale() * s.pd.horizon;
          parts[m].record.horizon = track.pd.horizon;
          parts[m].box        = box.front();
          tips.push_back(parts[m].tip.position);
          const Point  d = parts[m].tip.direction, n{-d.y, d.x};
          const double kink = parts[m].record.predicted_kink;
          directions.push_back(d);
          turns.push_back(std::cos(kink) * d + std::sin(kink) * n);
        }
      auto &track     = tracks[owner(box, parts)];
      lead.record.box = track.boxes.place(tips, directions, turns, track.length_scale());
      const local::Region region{scene.body, lead.record.box, polylines()};
      lead.model.emplace(material, track.pd.horizon, track.pd.horizon_over_spacing, region);
      if (auto held = held_places(scene.conditions, *lead.model); !held.empty())
        lead.model.emplace(material, track.pd.horizon, track.pd.horizon_over_spacing, region, held);
      for (std::size_t m : box)
        {
          parts[m].record.box      = lead.record.box;
          parts[m].record.pd_nodes = lead.model->nodes().size();
        }
      lead.record.seconds_point_evaluation = seconds_since(t);
      box_area_sum += lead.record.box.width() * lead.record.box.height();
      ++boxes_placed;
    }

    BoundaryTransfer Cycle::transfer_to(TipExchange &lead)
    {
      const auto       t = Clock::now();
      BoundaryTransfer transfer(global, *lead.model);
      lead.record.seconds_point_evaluation += seconds_since(t);
      return transfer;
    }

    void Cycle::exchange(const BoundaryTransfer &transfer, const std::vector<std::size_t> &box,
                         std::vector<TipExchange> &parts)
    {
      TipExchange          &lead  = parts[box.front()];
      auto                 &track = tracks[owner(box, parts)];
      const double          scale = track.length_scale();
      // A doubled box's minimum advance doubles (an increment shorter than its horizon comes out
      // straight ahead); a halved box keeps the section's, capped at half its allowed advance.
      const double advance_scale = std::max(1., scale);
      std::vector<TipState>                        tips;
      std::vector<double>                          allowed;
      std::vector<std::vector<geometry::Polyline>> faces;
      for (std::size_t m : box)
        {
          tips.push_back(parts[m].tip);
          faces.emplace_back();
          for (std::size_t c = 0; c < cracks.size(); ++c)
            if (c != parts[m].track / 2)
              faces.back().push_back(cracks[c].vertices());
          allowed.push_back(std::min(scale * track.controller.allowed_advance(
                                               scene.body.clearance(parts[m].tip.position) / scale),
                                     max_length - lead.record.crack_length));
        }
      auto outcome = run_exchange(
        *lead.model, transfer, track.controller, tips, allowed, faces,
        [&](const geometry::Polyline &path) { return !arrival_of(path, track.pd.horizon).reason.empty(); }, track.pd,
        out, "lambda_c", advance_scale);
      result.pd_node_steps += outcome.node_steps;
      const double lambda = outcome.load_factor * lead.tip.critical_load_factor;
      for (std::size_t k = 0; k < box.size(); ++k)
        {
          auto &part   = parts[box[k]];
          auto &record = part.record;
          if (k < outcome.increments.size())
            part.increment = truncate(outcome.increments[k].path, allowed[k]);
          part.decision  = outcome.decision;
          part.branching = outcome.branching;
          // The controller judged the tip that went farthest; another tip of the box grows with it
          // only by an advance the controller would accept on its own: one that reaches a hole,
          // the outline or another crack's face (within its allowed advance, as every tip's is
          // when the farthest one's is), or one at least the minimum advance.
          const bool reaches = k < outcome.reaches.size() && outcome.reaches[k];
          const bool below   = !reaches && geometry::length(part.increment) <
                                             std::min(advance_scale * s.cycle.exchange.min_advance, 0.5 * allowed[k]) *
                                               (1. - 1e-12);
          if (part.decision == Decision::accept && below && part.branching.empty())
            part.decision = Decision::raise;
          record.pd_iterations      = outcome.iterations;
          record.substeps           = outcome.states;
          record.unrelaxed          = outcome.unrelaxed;
          record.repeats            = outcome.repeats;
          record.lambda             = lambda;
          record.load_factor        = lambda / part.tip.critical_load_factor;
          record.onset_lambda       = outcome.onset_load_factor * lead.tip.critical_load_factor;
          record.onset_substeps     = outcome.onset_states;
          record.k1                 = part.tip.k1 * lambda;
          record.k2                 = part.tip.k2 * lambda;
          record.decision           = !outcome.branching.empty()     ? "branching" :
                                      part.decision == Decision::raise ? "no growth" :
                                                                         to_text(part.decision);
        }
      lead.record.seconds_pd         = outcome.seconds_pd;
      lead.record.seconds_extraction = outcome.seconds_extraction;
      lead.state                     = std::move(outcome.state);
    }

    std::string Cycle::grow(std::vector<TipExchange> &parts)
    {
      for (const auto &part : parts)
        if (!part.branching.empty())
          return "crack branching in the PD box, refused: " + part.branching;
      const auto grew = [](const TipExchange &part) {
        return part.decision == Decision::accept || part.decision == Decision::truncate;
      };
      for (auto &part : parts)
        {
          global.scale_to(part.record.lambda);
          std::tie(part.record.load, part.record.displacement) = global.report();
          if (std::isfinite(part.record.onset_lambda))
            {
              global.scale_to(part.record.onset_lambda);
              std::tie(part.record.onset_load, part.record.onset_displacement) = global.report();
            }
        }
      // The exchange's load: the lowest at which a tip grew. A tip that grew within one load
      // increment of its own ladder above it grows too: its states cannot tell the two loads apart.
      double lambda = std::numeric_limits<double>::infinity();
      for (const auto &part : parts)
        if (grew(part))
          lambda = std::min(lambda, part.record.lambda);
      if (!std::isfinite(lambda))
        {
          std::ostringstream reason;
          reason << "the load is too small to grow the crack: no growth up to " << s.cycle.exchange.max_load_factor
                 << " lambda_c";
          return reason.str();
        }
      for (auto &part : parts)
        {
          part.grows = grew(part) && part.record.lambda <=
                                       lambda + s.cycle.exchange.load_increment * part.tip.critical_load_factor;
          if (!part.grows)
            {
              if (grew(part))
                part.record.decision = "waits";
              continue;
            }
          const double before = crack_length();
          part.increment      = truncate(part.increment, max_length - before);
          const auto  &path   = part.increment;
          grow_tip(part);
          part.record.advance = crack_length() - before;
          if (path.size() > 1)
            part.record.kink = std::atan2(geometry::cross(part.tip.direction, path[1] - path[0]),
                                          geometry::dot(part.tip.direction, path[1] - path[0]));
          if (!part.stop.empty() && part.by_lefm)
            part.stop += " (the last ligament, narrower than " +
                         pumpd::to_text(s.cycle.resolution.clearance_over_horizon, 3) +
                         " horizons of the finest PD box, grown by LEFM: maximum hoop stress at G = G_c)";
          if (!part.stop.empty())
            {
              tracks[part.track].stopped = true;
              stopped_tips.push_back(part.stop);
            }
        }
      global.scale_to(lambda);
      // The run goes on while a tip goes on and the body is whole (crack_network.h).
      if (global::cuts_off_a_piece(cracks, scene.body, crack_tolerance(scene), s.growth.hole_margin))
        stopped_tips.push_back(global::cut_through_message(cracks));
      else
        for (std::size_t c = 0; c < cracks.size(); ++c)
          for (const auto &tip : cracks[c].tips())
            if (!tracks[track_of(c, tip)].stopped)
              return "";
      std::string stop;
      for (const auto &reason : stopped_tips)
        stop += (stop.empty() ? "" : "; ") + reason;
      return stop;
    }

    void Cycle::grow_tip(TipExchange &part)
    {
      const std::size_t track   = part.track;
      const double      horizon = tracks[track].pd.horizon;
      const auto        arrival = arrival_of(part.increment, horizon);
      // Another crack's face met by the increment, or within a horizon ahead of the new tip (a
      // ligament PD does not resolve, as at a hole): the tip joins that crack there.
      const auto others = polylines();
      auto       face   = first_crossing(arrival.path, others, track / 2);
      if (!face && arrival.reason.empty() && arrival.path.size() > 1)
        face = face_ahead(arrival.path, others, track / 2, horizon);
      auto &crack = cracks[track / 2];
      for (std::size_t k = 1; k < arrival.path.size() && (!face || k <= face->segment); ++k)
        if (geometry::norm(arrival.path[k] - end_vertex(track)) > 1e-3 * h)
          crack.grow(tip_index(track), arrival.path[k]);
      if (!face)
        {
          part.stop = arrival.reason;
          return;
        }
      crack.join(tip_index(track), face->at, cracks[face->crack]);
      part.stop   = "crack " + std::to_string(track / 2 + 1) + " joined crack " + std::to_string(face->crack + 1) +
                  " at " + to_text(face->at);
    }

    bool Cycle::ligament_unresolved(const TipState &tip) const
    {
      const auto  &r        = s.cycle.resolution;
      const double finest   = std::ldexp(s.pd.horizon, r.rule == "clearance" ? -int(r.max_halvings) : 0);
      const double ligament = std::min(scene.body.ray_to_outline(tip.position, tip.direction),
                                       scene.body.ray_to_holes(tip.position, tip.direction, 0.).t);
      const double clearance = r.clearance_over_horizon * finest;
      return ligament < clearance || conditions::near_any(scene.conditions, tip.position, clearance);
    }

    void Cycle::grow_by_lefm(TipExchange &part)
    {
      const auto  &tip   = part.tip;
      const double angle = kink_angle(tip.k1, tip.k2);
      const Point  n{-tip.direction.y, tip.direction.x};
      const Point  e = std::cos(angle) * tip.direction + std::sin(angle) * n;
      part.increment = {tip.position, tip.position + tracks[part.track].pd.horizon * e};
      part.decision  = Decision::accept;
      part.by_lefm   = true;
      auto &record                = part.record;
      record.decision             = "lefm";
      record.load_factor          = 1.;
      record.lambda               = tip.critical_load_factor;
      record.onset_lambda         = tip.critical_load_factor;
      record.k1                   = tip.k1 * record.lambda;
      record.k2                   = tip.k2 * record.lambda;
    }

    void Cycle::write(std::size_t n, const std::vector<TipExchange> &parts, const std::string &stop)
    {
      const bool last = !stop.empty() || n + 1 >= s.cycle.max_exchanges || crack_length() >= max_length - 1e-9;
      for (const auto &part : parts)
        {
          result.exchanges.push_back(part.record);
          write_row(steps, part.record);
        }
      // The onset of growth of the tip that grew first: the load at which the crack starts to grow.
      for (const auto &part : parts)
        if (part.grows)
          {
            const auto &r = part.record;
            recorder.load_displacement(n, r.onset_lambda, r.onset_load, r.onset_displacement, crack_length(),
                                       end_vertex(part.track));
            break;
          }
      if (n % s.cycle.output_interval == 0 || last)
        {
          recorder.global_state(global, double(n));
          for (const auto &part : parts)
            if (part.model)
              recorder.pd_state(*part.model, part.state);
        }
      recorder.crack_paths(polylines());
      if (recorder.writes())
        {
          CsvFile boxes_table(recorder.path("boxes.csv"), "box,x_min_m,y_min_m,x_max_m,y_max_m,moved,tip_end,crack");
          state.exchanges = n + 1;
          state.finished  = !stop.empty();
          state.cracks    = polylines();
          state.ends.resize(tracks.size());
          for (std::size_t e = 0; e < tracks.size(); ++e)
            {
              write_boxes(boxes_table, tracks[e].boxes.history(), e);
              state.ends[e] = {tracks[e].boxes.history(), tracks[e].controller.load_factor(), tracks[e].halvings,
                               tracks[e].stopped};
            }
          state.refinements = global.refinements();
          state.outputs     = recorder.lengths();
          write_cycle_checkpoint(checkpoint, state);
        }

      // ETA: the growth rate so far against what is left to grow (to the length limit, or to the
      // boundary ahead of the tip that has farthest to go).
      const double grown = crack_length() - length0;
      double       ahead = 0.;
      for (std::size_t c = 0; c < cracks.size(); ++c)
        for (const auto &tip : cracks[c].tips())
          if (!tracks[track_of(c, tip)].stopped)
            ahead = std::max(ahead, scene.body.ray_to_outline(tip.position, tip.direction));
      ahead            = std::min(max_length - crack_length(), ahead);
      const double eta = grown > 0. ? seconds_since(t0) / grown * ahead : 0.;
      for (const auto &part : parts)
        {
          const auto &record = part.record;
          const auto &box    = record.box;
          out << "exchange " << std::setw(3) << n;
          if (tracks.size() > 2)
            out << " crack " << part.track / 2 + 1;
          if (parts.size() > 1)
            out << " tip " << part.track % 2;
          out << "  lambda " << std::setprecision(4) << record.lambda << " (" << record.load_factor
              << " lambda_c)  crack " << crack_length() << " m  +" << 1e3 * record.advance << " mm  tip "
              << to_text(end_vertex(part.track)) << "  ";
          if (part.model)
            out << "box [" << box.x_min << ", " << box.x_max << "] x [" << box.y_min << ", " << box.y_max << "]"
                << (tracks[part.track].boxes.moved() ? " new" : "") << "  delta " << 1e3 * record.horizon << " mm, "
                << record.pd_nodes << " PD nodes, " << record.substeps << " states, " << record.pd_iterations
                << " DR its" << (record.unrelaxed > 0 ? " (" + std::to_string(record.unrelaxed) + " not relaxed)" : "");
          else if (part.by_lefm)
            out << "LEFM increment (ligament below " << s.cycle.resolution.clearance_over_horizon
                << " horizons of the finest box)";
          else
            out << "in the box of tip " << parts[part.box].track % 2;
          if (part.record.decision == "waits")
            out << "  waits: grew above this exchange's load";
          if (!part.stop.empty() && !last)
            out << "  stops: " << part.stop;
          out << "  ETA <= " << std::fixed << std::setprecision(0) << eta << " s" << std::defaultfloat
              << std::setprecision(6) << std::endl;
        }
    }
  } // namespace

  GlobalLocalResult run_global_local(const Scene &scene, const GlobalLocalSettings &settings, std::ostream &progress)
  {
    return Cycle(scene, settings, progress).run();
  }
} // namespace pumpd::coupling
