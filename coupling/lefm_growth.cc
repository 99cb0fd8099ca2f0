#include "lefm_growth.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <ostream>

#include "arrival.h"
#include "crack.h"
#include "crack_network.h"
#include "error.h"
#include "path_metrics.h"
#include "recorder.h"

namespace pumpd::coupling
{
  using geometry::Point;
  namespace Patterns = dealii::Patterns;

  void LefmSettings::add_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("LEFM growth");
    prm.add_parameter("Growth increment", growth_increment, "Crack advance da per step [m].", Patterns::Double(1e-300));
    prm.add_parameter("Increment halving angle", halving_angle,
                      "Adaptive increment: da / (1 + |theta_c| / this) for the kink angle theta_c [deg]; 0: every "
                      "increment is da.",
                      Patterns::Double(0., 90.));
    prm.add_parameter("Maximum steps", max_steps, "Growth increments at most.", Patterns::Integer(1));
    prm.add_parameter("Output interval", output_interval, "Write global_NNN.vtu every n steps (and the last).",
                      Patterns::Integer(1));
    prm.add_parameter("Simultaneous growth tolerance", simultaneous_tolerance,
                      "Several tips: the step's load factor is the smallest critical load factor lambda_c of the "
                      "growing tips, and every tip whose lambda_c is within this relative tolerance of it grows; the "
                      "others wait.",
                      Patterns::Double(0., 1.));
    prm.leave_subsection();
  }

  namespace
  {
    constexpr double pi = 3.14159265358979323846;
    /// A tip that would end within (look_ahead - 1) da of the outline, a hole's margin or another
    /// crack goes there in this step: no sliver of material (and no tiny cell cut) is left in front.
    constexpr double look_ahead = 1.5;

    /// What happens to one tip in one step.
    struct Growth
    {
      std::size_t crack = 0;    ///< index of the crack
      std::size_t tip   = 0;    ///< index of the tip in its crack
      std::size_t flat  = 0;    ///< index over all tips, cracks in order
      Point       to;           ///< new tip position
      double      angle = 0.;   ///< theta_c [rad]
      bool        grow  = true; ///< false: no new segment
      bool        stops = false;
      bool        joins = false; ///< ends on another crack's face
      std::size_t other = 0;     ///< the crack it joins
      std::string reason;
    };

    std::vector<geometry::Polyline> polylines(const std::vector<global::Crack> &cracks)
    {
      std::vector<geometry::Polyline> p;
      for (const auto &c : cracks)
        p.push_back(c.vertices());
      return p;
    }

    /// Where tip grows by the increment da / (1 + |theta_c| / halving angle), at most `remaining`:
    /// tip + da e, e = cos(theta_c) d + sin(theta_c) n; to the outline, a hole's margin or another
    /// crack's face instead (and it stops or joins) if that comes within look_ahead da along e;
    /// nowhere if the tip is at rest (at_rest: closed, or no driving force).
    void plan(Growth &g, const global::Tip &tip, const TipState &state, double remaining, const geometry::Body &body,
              const std::vector<global::Crack> &cracks, const LefmGrowthSettings &s)
    {
      if (const std::string why = at_rest(state); !why.empty())
        {
          g.grow   = false;
          g.stops  = true;
          g.reason = tip_stop(tip.position, why);
          return;
        }
      double da = s.lefm.growth_increment;
      if (s.lefm.halving_angle > 0.)
        da /= 1. + std::abs(g.angle) * 180. / pi / s.lefm.halving_angle;
      da                  = std::min(da, remaining);
      const Point  n      = {-tip.direction.y, tip.direction.x};
      const Point  e      = std::cos(g.angle) * tip.direction + std::sin(g.angle) * n;
      const double t_out  = body.ray_to_outline(tip.position, e);
      const double t_hole = body.ray_to_holes(tip.position, e, s.growth.hole_margin).t;
      const auto [t_face, other] = ray_to_cracks(tip.position, e, look_ahead * da, polylines(cracks), g.crack);
      if (t_face <= look_ahead * da && t_face < t_out && t_face < t_hole)
        {
          g.to     = tip.position + t_face * e;
          g.joins  = true;
          g.other  = other;
          g.stops  = true;
          g.reason = tip_stop(g.to, "joined crack " + std::to_string(other + 1));
        }
      else if (t_hole <= look_ahead * da && t_hole < t_out)
        {
          g.grow   = t_hole > 1e-3 * da;
          g.to     = tip.position + t_hole * e;
          g.stops  = true;
          g.reason = tip_stop(g.to, "stopped before a hole");
        }
      else if (t_out <= look_ahead * da)
        {
          g.to     = tip.position + t_out * e;
          g.stops  = true;
          g.reason = tip_stop(g.to, "reached the outline");
        }
      else
        g.to = tip.position + da * e;
    }

    double total_length(const std::vector<global::Crack> &cracks)
    {
      double length = 0.;
      for (const auto &c : cracks)
        length += c.length();
      return length;
    }

    /// Refuses initial cracks with a tip within the tip enrichment radius of another crack: the
    /// interaction integral's domain would hold that crack (EnrichedElasticity caps it there).
    void check_clearance(const std::vector<global::Crack> &cracks, double tip_radius)
    {
      for (std::size_t c = 0; c < cracks.size(); ++c)
        for (const auto &tip : cracks[c].tips())
          for (std::size_t o = 0; o < cracks.size(); ++o)
            if (o != c && cracks[o].distance(tip.position) < tip_radius)
              throw InvalidParameter("Initial cracks",
                                     to_text(cracks[c].vertices()) + " | " + to_text(cracks[o].vertices()),
                                     "the tip at " + to_text(tip.position) + " lies " +
                                       to_text(cracks[o].distance(tip.position)) +
                                       " m from another crack, within the tip enrichment radius (Global / Tip "
                                       "enrichment radius = " +
                                       to_text(tip_radius) + " m): move the cracks apart or use a smaller radius");
    }
  } // namespace

  LefmGrowthResult run_lefm_growth(const Scene &scene, const LefmGrowthSettings &s, std::ostream &out)
  {
    const auto                 t0  = std::chrono::steady_clock::now();
    const auto                &box       = scene.body.bounding_box();
    const double               tolerance = crack_tolerance(scene);
    if (scene.cracks.empty())
      scene.crack(); // names "Initial cracks"
    std::vector<global::Crack> cracks = enriched_cracks(scene.cracks, scene);
    check_clearance(cracks, s.global.tip_radius);
    if (const double least = 1e-4 * std::max(box.width(), box.height()); s.lefm.growth_increment < least)
      throw InvalidParameter("Growth increment", to_text(s.lefm.growth_increment),
                             "must be at least 1e-4 of the body's larger side (" + to_text(least) + " m)");
    GlobalProblem global(scene, s.global);
    Recorder      recorder(scene);
    CsvFile       table = recorder.table("load_steps.csv", "step,tip,x_m,y_m,crack_length_m,K_I_Pa_sqrt_m,K_II_Pa_sqrt_m,"
                                                     "critical_load_factor,kink_angle_deg,increment_m,dofs,"
                                                     "solve_seconds,step_seconds");
    const double  max_length = s.growth.length_limit();
    out << "LEFM growth: " << scene.mesh_file << ", " << scene.mesh->n_active_cells() << " cells, "
        << scene.body.holes().size() << " holes, ";
    if (cracks.size() == 1)
      out << "initial crack " << cracks.front().length() << " m";
    else
      out << cracks.size() << " initial cracks, " << total_length(cracks) << " m";
    out << ", da = " << s.lefm.growth_increment << " m, up to " << s.lefm.max_steps << " steps\n";

    LefmGrowthResult result;
    // stopped[c][1]: the tip at the first vertex of crack c, [c][0]: at its last.
    std::vector<std::array<bool, 2>> stopped(cracks.size(), {{false, false}});
    const auto is_stopped = [&](std::size_t c, const global::Tip &tip) { return stopped[c][tip.vertex == 0]; };
    bool       joined     = false;
    for (std::size_t step = 0;; ++step)
      {
        const auto t_step = std::chrono::steady_clock::now();
        const auto tips   = global.solve(cracks);
        const auto solve_seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t_step).count();

        // Decide every tip from this solution: the load factor is the smallest lambda_c of the
        // tips still growing; those within the tolerance of it grow, the others wait.
        const double        length    = total_length(cracks);
        const double        remaining = max_length - length;
        const bool          at_limit  = step == s.lefm.max_steps || remaining <= 1e-6 * s.lefm.growth_increment;
        std::vector<Growth> growth;
        double              lambda_c = std::numeric_limits<double>::infinity();
        for (std::size_t c = 0, flat = 0; c < cracks.size(); ++c)
          for (std::size_t t = 0; t < cracks[c].tips().size(); ++t, ++flat)
            {
              Growth g;
              g.crack = c;
              g.tip   = t;
              g.flat  = flat;
              g.to    = cracks[c].tips()[t].position;
              g.angle = kink_angle(tips[flat].k1, tips[flat].k2);
              if (!is_stopped(c, cracks[c].tips()[t]))
                lambda_c = std::min(lambda_c, tips[flat].critical_load_factor);
              growth.push_back(g);
            }
        for (auto &g : growth)
          {
            const auto &tip = cracks[g.crack].tips()[g.tip];
            if (at_limit || is_stopped(g.crack, tip) ||
                tips[g.flat].critical_load_factor > lambda_c * (1. + s.lefm.simultaneous_tolerance))
              g.grow = false;
            else
              plan(g, tip, tips[g.flat], remaining, scene.body, cracks, s);
          }
        const bool last = at_limit || std::all_of(growth.begin(), growth.end(), [&](const Growth &g) {
                            return g.stops || is_stopped(g.crack, cracks[g.crack].tips()[g.tip]);
                          });

        const double step_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_step).count();
        const double elapsed      = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const double ahead        = tips.empty() ? 0. : scene.body.ray_to_outline(tips[0].position, tips[0].direction);
        const double steps_left =
          std::min(double(s.lefm.max_steps - step), std::ceil(std::min(remaining, ahead) / s.lefm.growth_increment));
        const double eta = last ? 0. : elapsed / double(step + 1) * steps_left;
        for (const auto &g : growth)
          {
            const auto          &tip = tips[g.flat];
            const LefmGrowthStep st{step,
                                    g.flat,
                                    tip.position,
                                    length,
                                    tip.k1,
                                    tip.k2,
                                    tip.critical_load_factor,
                                    g.angle,
                                    g.grow ? geometry::norm(g.to - tip.position) : 0.,
                                    global.n_dofs(),
                                    solve_seconds,
                                    g.crack};
            result.steps.push_back(st);
            out << "step " << std::setw(3) << step << "/" << s.lefm.max_steps << "  tip " << g.flat << " at "
                << to_text(st.position) << "  crack " << std::setprecision(4) << length << " m  K_I " << st.k1
                << "  K_II " << st.k2 << "  lambda_c " << st.critical_load_factor << "  kink " << std::fixed
                << std::setprecision(2) << st.kink_angle * 180. / pi << " deg  da " << std::defaultfloat
                << std::setprecision(3) << st.increment << " m  dofs " << st.dofs << "  " << std::setprecision(2)
                << step_seconds << " s  ETA " << std::fixed << std::setprecision(0) << eta << " s" << std::defaultfloat
                << std::setprecision(6) << std::endl;
            table.row(step, g.flat, st.position.x, st.position.y, length, st.k1, st.k2, st.critical_load_factor,
                      st.kink_angle * 180. / pi, st.increment, st.dofs, solve_seconds, step_seconds);
          }
        if (std::isfinite(lambda_c))
          {
            global.scale_to(lambda_c);
            const auto [load, displacement] = global.report();
            recorder.load_displacement(step, lambda_c, load, displacement, length,
                                       tips.empty() ? cracks.front().vertices().back() : tips[0].position);
          }
        if (step % s.lefm.output_interval == 0 || last)
          recorder.global_state(global, double(step));

        // Grow from the last tip to the first: a tip that reaches the outline or joins another
        // crack disappears, and the indices of the tips before it stay valid. A new segment that
        // would cross another crack (grown earlier in this step) ends on it and joins it.
        for (auto g = growth.rbegin(); g != growth.rend(); ++g)
          {
            auto      &crack = cracks[g->crack];
            const auto tip   = crack.tips()[g->tip];
            if (g->grow && !g->joins)
              if (const auto [t, other] = ray_to_cracks(tip.position, g->to - tip.position, 1., polylines(cracks), g->crack);
                  t <= 1.)
                {
                  g->to     = tip.position + t * (g->to - tip.position);
                  g->joins  = true;
                  g->other  = other;
                  g->stops  = true;
                  g->reason = tip_stop(g->to, "joined crack " + std::to_string(other + 1));
                }
            if (g->grow)
              try
                {
                  if (g->joins)
                    crack.join(g->tip, g->to, cracks[g->other]);
                  else
                    crack.grow(g->tip, g->to);
                  joined |= g->joins;
                }
              catch (const InvalidParameter &e)
                {
                  g->stops  = true;
                  g->reason = tip_stop(tip.position, std::string("cannot grow: ") + e.what());
                }
            if (g->stops)
              {
                stopped[g->crack][tip.vertex == 0] = true;
                out << "  tip " << g->flat << ": " << g->reason << "\n";
                result.stop_reason += (result.stop_reason.empty() ? "" : "; ") + g->reason;
              }
          }
        if (total_length(cracks) > length)
          ++result.increments;
        std::vector<geometry::Polyline> paths;
        for (const auto &c : cracks)
          paths.push_back(c.vertices());
        recorder.crack_paths(paths);

        // The run goes on while a tip grows and the body is whole (crack_network.h).
        bool growing = false;
        for (std::size_t c = 0; c < cracks.size(); ++c)
          for (const auto &t : cracks[c].tips())
            growing |= !is_stopped(c, t);
        const bool cut = global::cuts_off_a_piece(cracks, scene.body, tolerance, s.growth.hole_margin);
        if (last || !growing || cut)
          {
            const std::string end = cut ? global::cut_through_message(cracks)
                                    : step == s.lefm.max_steps ? "maximum steps"
                                    : at_limit                 ? "maximum crack length"
                                                               : "no tip grows";
            result.stop_reason += (result.stop_reason.empty() ? "" : "; ") + end;
            break;
          }
      }
    for (const auto &c : cracks)
      result.paths.push_back(c.vertices());
    result.path    = result.paths.front();
    result.joined  = joined;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out << "pumpd-metric lefm.seconds_total " << result.seconds << "\n"
        << "pumpd-metric lefm.global_dofs " << (result.steps.empty() ? 0u : result.steps.back().dofs) << "\n";
    if (!scene.reference_path.empty())
      {
        result.reference_deviation = directed_max_distance(scene.reference_path, result.path);
        out << "pumpd-metric lefm.published_path_max_deviation_m " << result.reference_deviation << "\n";
      }
    out << "end: " << result.stop_reason << "; " << grown_cracks_text(scene.cracks, result.paths, scene.body, tolerance)
        << ", " << result.seconds << " s\n";
    return result;
  }
} // namespace pumpd::coupling
