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

#include "crack.h"
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
    prm.leave_subsection();
  }

  namespace
  {
    constexpr double pi = 3.14159265358979323846;
    /// A tip that would end within (look_ahead - 1) da of the outline or a hole's margin goes
    /// there in this step: no sliver of material (and no tiny cell cut) is left in front of it.
    constexpr double look_ahead = 1.5;

    /// What happens to one tip in one step.
    struct Growth
    {
      std::size_t tip = 0;
      Point       to;           ///< new tip position
      double      angle = 0.;   ///< theta_c [rad]
      bool        grow  = true; ///< false: no new segment
      bool        stops = false;
      std::string reason;
    };

    /// Where tip grows by the increment da / (1 + |theta_c| / halving angle), at most `remaining`:
    /// tip + da e, e = cos(theta_c) d + sin(theta_c) n; to the outline or to a hole's margin
    /// instead (and it stops) if that comes within look_ahead da along e; nowhere if K_I <= 0.
    void plan(Growth &g, const global::Tip &tip, double k1, double remaining, const geometry::Body &body,
              const LefmGrowthSettings &s)
    {
      if (k1 <= 0.)
        {
          g.grow   = false;
          g.stops  = true;
          g.reason = "closed (K_I <= 0)";
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
      if (t_hole <= look_ahead * da && t_hole < t_out)
        {
          g.grow   = t_hole > 1e-3 * da;
          g.to     = tip.position + t_hole * e;
          g.stops  = true;
          g.reason = "stopped before a hole";
        }
      else if (t_out <= look_ahead * da)
        {
          g.to     = tip.position + t_out * e;
          g.stops  = true;
          g.reason = "reached the outline";
        }
      else
        g.to = tip.position + da * e;
    }
  } // namespace

  LefmGrowthResult run_lefm_growth(const Scene &scene, const LefmGrowthSettings &s, std::ostream &out)
  {
    const auto                   t0  = std::chrono::steady_clock::now();
    const auto                  &box = scene.body.bounding_box();
    std::optional<global::Crack> crack;
    crack.emplace(scene.crack(), scene.body, 1e-8 * std::max(box.width(), box.height()));
    GlobalProblem global(scene, s.global);
    Recorder      recorder(scene);
    CsvFile       table = recorder.table("load_steps.csv", "step,tip,x_m,y_m,crack_length_m,K_I_Pa_sqrt_m,K_II_Pa_sqrt_m,"
                                                     "critical_load_factor,kink_angle_deg,increment_m,dofs,"
                                                     "solve_seconds,step_seconds");
    const double  max_length = s.growth.length_limit();
    out << "LEFM growth: " << scene.mesh_file << ", " << scene.mesh->n_active_cells() << " cells, "
        << scene.body.holes().size() << " holes, initial crack " << crack->length() << " m, da = "
        << s.lefm.growth_increment << " m, up to " << s.lefm.max_steps << " steps\n";

    LefmGrowthResult result;
    bool             stopped[2] = {false, false}; // [1]: the tip at the first vertex, [0]: at the last
    for (std::size_t step = 0;; ++step)
      {
        const auto t_step = std::chrono::steady_clock::now();
        const auto tips   = global.solve(*crack);
        const auto solve_seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t_step).count();

        // Decide every tip from this solution.
        const double        length    = crack->length();
        const double        remaining = max_length - length;
        const bool          at_limit  = step == s.lefm.max_steps || remaining <= 1e-6 * s.lefm.growth_increment;
        std::vector<Growth> growth;
        double              lambda_c = std::numeric_limits<double>::infinity();
        for (std::size_t t = 0; t < tips.size(); ++t)
          {
            const auto &tip = crack->tips()[t];
            Growth      g;
            g.tip   = t;
            g.to    = tip.position;
            g.angle = kink_angle(tips[t].k1, tips[t].k2);
            if (at_limit || stopped[tip.vertex == 0])
              g.grow = false;
            else
              plan(g, tip, tips[t].k1, remaining, scene.body, s);
            if (!stopped[tip.vertex == 0])
              lambda_c = std::min(lambda_c, tips[t].critical_load_factor);
            growth.push_back(g);
          }
        const bool last = at_limit || std::all_of(growth.begin(), growth.end(), [&](const Growth &g) {
                            return g.stops || stopped[crack->tips()[g.tip].vertex == 0];
                          });

        const double step_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_step).count();
        const double elapsed      = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const double ahead        = tips.empty() ? 0. : scene.body.ray_to_outline(tips[0].position, tips[0].direction);
        const double steps_left =
          std::min(double(s.lefm.max_steps - step), std::ceil(std::min(remaining, ahead) / s.lefm.growth_increment));
        const double eta = last ? 0. : elapsed / double(step + 1) * steps_left;
        for (const auto &g : growth)
          {
            const auto          &tip = tips[g.tip];
            const LefmGrowthStep st{step,
                                    g.tip,
                                    tip.position,
                                    length,
                                    tip.k1,
                                    tip.k2,
                                    tip.critical_load_factor,
                                    g.angle,
                                    g.grow ? geometry::norm(g.to - tip.position) : 0.,
                                    global.n_dofs(),
                                    solve_seconds};
            result.steps.push_back(st);
            out << "step " << std::setw(3) << step << "/" << s.lefm.max_steps << "  tip " << g.tip << " at "
                << to_text(st.position) << "  crack " << std::setprecision(4) << length << " m  K_I " << st.k1
                << "  K_II " << st.k2 << "  lambda_c " << st.critical_load_factor << "  kink " << std::fixed
                << std::setprecision(2) << st.kink_angle * 180. / pi << " deg  da " << std::defaultfloat
                << std::setprecision(3) << st.increment << " m  dofs " << st.dofs << "  " << std::setprecision(2)
                << step_seconds << " s  ETA " << std::fixed << std::setprecision(0) << eta << " s" << std::defaultfloat
                << std::setprecision(6) << std::endl;
            table.row(step, g.tip, st.position.x, st.position.y, length, st.k1, st.k2, st.critical_load_factor,
                      st.kink_angle * 180. / pi, st.increment, st.dofs, solve_seconds, step_seconds);
          }
        if (std::isfinite(lambda_c))
          {
            global.scale_to(lambda_c);
            const auto [load, displacement] = global.report();
            recorder.load_displacement(step, lambda_c, load, displacement, length,
                                       tips.empty() ? crack->vertices().back() : tips[0].position);
          }
        if (step % s.lefm.output_interval == 0 || last)
          recorder.global_state(global, double(step));

        // Grow from the last tip to the first: a tip that reaches the outline disappears, and the
        // indices of the tips before it stay valid.
        for (auto g = growth.rbegin(); g != growth.rend(); ++g)
          {
            const bool front = crack->tips()[g->tip].vertex == 0;
            if (g->grow)
              try
                {
                  crack->grow(g->tip, g->to);
                }
              catch (const InvalidParameter &e)
                {
                  g->stops  = true;
                  g->reason = std::string("cannot grow: ") + e.what();
                }
            if (g->stops)
              {
                stopped[front] = true;
                out << "  tip " << g->tip << " " << g->reason << " at " << to_text(g->to) << "\n";
                result.stop_reason += (result.stop_reason.empty() ? "" : "; ") + g->reason;
              }
          }
        if (crack->length() > length)
          ++result.increments;
        recorder.crack_path(crack->vertices());

        const bool growing = std::any_of(crack->tips().begin(), crack->tips().end(),
                                         [&](const global::Tip &t) { return !stopped[t.vertex == 0]; });
        if (last || !growing)
          {
            const std::string end = step == s.lefm.max_steps ? "maximum steps"
                                    : at_limit               ? "maximum crack length"
                                    : crack->tips().empty()  ? "the crack cut the body through"
                                                             : "no tip grows";
            result.stop_reason += (result.stop_reason.empty() ? "" : "; ") + end;
            break;
          }
      }
    result.path    = crack->vertices();
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out << "pumpd-metric lefm.seconds_total " << result.seconds << "\n"
        << "pumpd-metric lefm.global_dofs " << (result.steps.empty() ? 0u : result.steps.back().dofs) << "\n";
    if (!scene.reference_path.empty())
      {
        result.reference_deviation = directed_max_distance(scene.reference_path, result.path);
        out << "pumpd-metric lefm.published_path_max_deviation_m " << result.reference_deviation << "\n";
      }
    out << "end: " << result.stop_reason << "; crack " << geometry::length(result.path) << " m, tip at "
        << to_text(result.path.back()) << ", " << result.seconds << " s\n";
    return result;
  }
} // namespace pumpd::coupling
