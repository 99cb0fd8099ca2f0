#include "lefm_growth.h"

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

#include "beam_scene.h"
#include "elasticity.h"
#include "error.h"
#include "path_metrics.h"

namespace pumpd::coupling
{
  using geometry::Point;

  namespace
  {
    constexpr double pi             = 3.14159265358979323846;
    constexpr double infinity       = std::numeric_limits<double>::infinity();
    /// A tip that would end within (look_ahead - 1) da of the outline or a hole's margin goes
    /// there in this step: no sliver of material (and no tiny cell cut) is left in front of it.
    constexpr double look_ahead = 1.5;

    void validate(const LefmGrowthParameters &p)
    {
      require_range("Mesh size", p.mesh_size, 0., 1., "must be in [0, 1] m (0: the mesh file's default)");
      require_positive("Load", p.load);
      require_positive("Growth increment", p.growth_increment);
      require_range("Increment halving angle", p.halving_angle, 0., 90., "must be in [0, 90] degrees (0: fixed increment)");
      if (p.max_steps < 1)
        throw InvalidParameter("Maximum steps", "0", "must be >= 1");
      require_positive("Maximum crack length", p.max_crack_length);
      require_positive("Tip enrichment radius", p.tip_radius);
      require_range("Refinement levels near the tip", p.refinement_levels, 0, 6, "must be in [0, 6]");
      require_positive("Refinement radius", p.refinement_radius);
      require_range("Hole margin", p.hole_margin, 0., 1., "must be in [0, 1] m");
      if (p.output_interval < 1)
        throw InvalidParameter("Output interval", "0", "must be >= 1");
      if (p.initial_crack.size() < 2)
        throw InvalidParameter("Initial crack", to_text(p.initial_crack), "needs at least 2 points");
    }

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
              const LefmGrowthParameters &p)
    {
      if (k1 <= 0.)
        {
          g.grow   = false;
          g.stops  = true;
          g.reason = "closed (K_I <= 0)";
          return;
        }
      double da = p.growth_increment;
      if (p.halving_angle > 0.)
        da /= 1. + std::abs(g.angle) * 180. / pi / p.halving_angle;
      da                 = std::min(da, remaining);
      const Point  n     = {-tip.direction.y, tip.direction.x};
      const Point  e     = std::cos(g.angle) * tip.direction + std::sin(g.angle) * n;
      const double t_out = distance_to_outline(tip.position, e, body.outline);
      double       t_hole = infinity;
      for (const auto &h : body.holes)
        t_hole = std::min(t_hole, distance_to_circle(tip.position, e, h.centre, h.radius + p.hole_margin));
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

  double kink_angle(double k1, double k2)
  {
    const double s = k1 + std::sqrt(k1 * k1 + 8. * k2 * k2);
    if (k2 == 0. || s == 0.)
      return 0.;
    return -2. * std::atan(2. * k2 / s);
  }

  LefmGrowthResult run_lefm_growth(const LefmGrowthParameters &p, std::ostream &out)
  {
    validate(p);
    const auto t0 = std::chrono::steady_clock::now();
    const geometry::Polyline reference = p.published_path.empty() ? geometry::Polyline{} : read_path(p.published_path);

    dealii::Triangulation<2> tria;
    const geometry::Body body =
      read_beam(tria, p.mesh_file, p.mesh_size, {{"Pin support", p.pin}, {"Roller support", p.roller}, {"Load point", p.load_point}});
    std::optional<global::Crack> crack = initial_crack(p.initial_crack, body);

    global::ElasticMaterial material{p.youngs_modulus, p.poisson_ratio, p.plane_strain};
    global::EnrichmentSettings enrichment;
    enrichment.tip_radius = p.tip_radius;
    global::EnrichedElasticity problem(tria, material, enrichment);
    problem.add_dirichlet_vertex(p.pin, {0., 0.}, true, true);
    problem.add_dirichlet_vertex(p.roller, {0., 0.}, false, true);
    problem.add_point_load(p.load_point, {0., -p.load});

    std::unique_ptr<GlobalVtuSeries> series;
    std::ofstream              table;
    if (!p.output_directory.empty())
      {
        std::filesystem::create_directories(p.output_directory);
        series = std::make_unique<GlobalVtuSeries>(p.output_directory);
        write_body(p.output_directory + "/body.csv", body, {{"pin", p.pin}, {"roller", p.roller}, {"load", p.load_point}});
        if (!reference.empty())
          write_path(p.output_directory + "/reference_path.csv", reference);
        table.open(p.output_directory + "/load_steps.csv");
        table << "step,tip,x_m,y_m,crack_length_m,K_I_Pa_sqrt_m,K_II_Pa_sqrt_m,kink_angle_deg,increment_m,dofs,"
                 "solve_seconds,step_seconds\n";
      }
    out << "LEFM growth: " << p.mesh_file << ", " << tria.n_active_cells() << " cells, " << body.holes.size()
        << " holes, initial crack " << crack->length() << " m, da = " << p.growth_increment << " m, up to "
        << p.max_steps << " steps or " << p.max_crack_length << " m\n";

    LefmGrowthResult     result;
    bool                 stopped[2] = {false, false}; // [1]: the tip at the first vertex, [0]: at the last
    for (std::size_t step = 0;; ++step)
      {
        const auto t_step = std::chrono::steady_clock::now();
        refine_at_tips(tria, crack->tips(), p.refinement_radius, p.refinement_levels);
        problem.set_crack(crack);
        problem.setup();
        problem.assemble();
        global::SolverSettings solver;
        if (p.iterative_solver)
          solver.type = global::SolverSettings::Type::cg_amg;
        const auto solve = problem.solve(solver);
        const auto sifs  = problem.stress_intensity_factors();

        // Decide every tip from this solution.
        const double        length    = crack->length();
        const double        remaining = p.max_crack_length - length;
        const bool          at_limit  = step == p.max_steps || remaining <= 1e-6 * p.growth_increment;
        std::vector<Growth> growth;
        for (std::size_t t = 0; t < sifs.size(); ++t)
          {
            const auto &tip = crack->tips()[t];
            Growth      g;
            g.tip   = t;
            g.to    = tip.position;
            g.angle = kink_angle(sifs[t].k1, sifs[t].k2);
            if (at_limit || stopped[tip.vertex == 0])
              g.grow = false;
            else
              plan(g, tip, sifs[t].k1, remaining, body, p);
            growth.push_back(g);
          }
        const bool last = at_limit || std::all_of(growth.begin(), growth.end(), [&](const Growth &g) {
                            return g.stops || stopped[crack->tips()[g.tip].vertex == 0];
                          });

        const double step_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_step).count();
        const double elapsed      = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const double steps_left   = std::min(double(p.max_steps - step), std::ceil(remaining / p.growth_increment));
        const double eta          = last ? 0. : elapsed / double(step + 1) * steps_left;
        for (const auto &g : growth)
          {
            const LefmGrowthStep s{step, g.tip, sifs[g.tip].tip, length, sifs[g.tip].k1, sifs[g.tip].k2, g.angle,
                                   g.grow ? geometry::norm(g.to - sifs[g.tip].tip) : 0., problem.n_dofs(), solve.seconds};
            result.steps.push_back(s);
            out << "step " << std::setw(3) << step << "/" << p.max_steps << "  tip " << g.tip << " at "
                << to_text(s.position) << "  crack " << std::setprecision(4) << length << " m  K_I " << s.k1
                << "  K_II " << s.k2 << "  kink " << std::fixed << std::setprecision(2) << s.kink_angle * 180. / pi
                << " deg  da " << std::defaultfloat << std::setprecision(3) << s.increment << " m  dofs " << s.dofs
                << "  " << std::setprecision(2) << step_seconds << " s  ETA " << std::fixed << std::setprecision(0)
                << eta << " s" << std::defaultfloat << std::setprecision(6) << "\n";
            if (table)
              table << std::setprecision(10) << step << "," << g.tip << "," << s.position.x << "," << s.position.y
                    << "," << length << "," << s.k1 << "," << s.k2 << "," << s.kink_angle * 180. / pi << ","
                    << s.increment << "," << s.dofs << "," << s.solve_seconds << "," << step_seconds << "\n";
          }
        if (series && (step % p.output_interval == 0 || last))
          series->add(problem, step);

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
        if (!p.output_directory.empty())
          write_path(p.output_directory + "/crack_path.csv", crack->vertices());

        const bool growing = std::any_of(crack->tips().begin(), crack->tips().end(),
                                         [&](const global::Tip &t) { return !stopped[t.vertex == 0]; });
        if (last || !growing)
          {
            const std::string end = step == p.max_steps   ? "maximum steps"
                                    : at_limit             ? "maximum crack length"
                                    : crack->tips().empty() ? "the crack cut the body through"
                                                            : "no tip grows";
            result.stop_reason += (result.stop_reason.empty() ? "" : "; ") + end;
            break;
          }
      }
    result.path    = crack->vertices();
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out << "pumpd-metric lefm.seconds_total " << result.seconds << "\n"
        << "pumpd-metric lefm.global_dofs " << (result.steps.empty() ? 0u : result.steps.back().dofs) << "\n";
    if (!reference.empty())
      {
        result.published_deviation = directed_max_distance(reference, result.path);
        out << "pumpd-metric lefm.published_path_max_deviation_m " << result.published_deviation << "\n";
      }
    return result;
  }
} // namespace pumpd::coupling
