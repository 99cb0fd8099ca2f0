// Validation 5 of the global solver: uniform against adaptive refinement near the tip. The
// problem of the convergence test (mode I Williams field, exact K_I = 1, K_II = 0), geometric tip
// enrichment of fixed radius 0.3. Uniform: 10 ... 160 cells per side. Adaptive: 10 x 10 cells,
// then refine_near(tip, radius, levels) for levels = 1 ... 4 (hanging nodes), with the
// refinement radius 0.5 (the enriched zone and the J-integral ring resolved; the curve of the
// metric) and 1.0 (most of the square: shows what limits the first curve). PUMPD_STUDY_MAX_LEVEL
// raises the last level (5 takes about 5 minutes: 10^5 unknowns, 6 * 10^4 of them enriched).
// Each run: DoFs, |K_I - 1| (interaction integral over the default domain, radius factor 1; also
// 0.5 and 2 in the CSV), K_II, energy and L2 errors; the curves go to study_refinement.csv (in the
// working directory, the build's tests/bench/).
// amr_dof_saving = DoFs of the finest uniform run / DoFs at which the radius-0.5 adaptive curve
// reaches the finest uniform K_I error (log-log interpolation between the two adaptive runs around
// it); nan if it never does. Nothing here is pass/fail except that every run gives a finite K_I.
#include <gtest/gtest.h>

#include <deal.II/base/multithread_info.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

#include "metric.h"
#include "refinement.h"
#include "williams_problem.h"

using namespace pumpd;
using namespace pumpd::bench;

namespace
{
  const double tip_radius = 0.3;

  struct RefinementRun
  {
    std::string  kind;
    unsigned int parameter = 0;  ///< cells per side (uniform) or levels (adaptive)
    double       radius    = 0.; ///< refinement radius (adaptive)
    unsigned int cells = 0, dofs = 0, enriched_dofs = 0;
    double       k1 = 0., k2 = 0., k1_half = 0., k1_double = 0., energy = 0., l2 = 0., seconds = 0.;
    double       k1_error() const { return std::abs(k1 - 1.); }
    std::string  tag() const
    {
      std::ostringstream s;
      s << "global.refinement." << kind;
      if (kind == "uniform")
        s << "_n" << parameter;
      else
        s << "_r" << radius << "_l" << parameter;
      return s.str();
    }
  };

  RefinementRun solve(dealii::Triangulation<2> &tria, const std::string &kind, unsigned int parameter, double radius)
  {
    const auto         start = std::chrono::steady_clock::now();
    const Williams     field{1, {1., 0.3, true}};
    EnrichmentSettings settings;
    settings.tip_radius = tip_radius;
    EnrichedElasticity problem(tria, field.material, settings);
    solve_williams(problem, field);
    const auto    err = problem.errors(field.displacement(), field.gradient());
    const auto    sif = problem.stress_intensity_factors();
    RefinementRun run;
    run.kind          = kind;
    run.parameter     = parameter;
    run.radius        = radius;
    run.cells         = tria.n_active_cells();
    run.dofs          = problem.n_dofs();
    run.enriched_dofs = problem.n_enriched_dofs();
    run.k1            = sif.at(0).k1;
    run.k2            = sif.at(0).k2;
    run.k1_half       = problem.stress_intensity_factors(0.5).at(0).k1;
    run.k1_double     = problem.stress_intensity_factors(2.).at(0).k1;
    run.energy        = err.energy / err.energy_exact;
    run.l2            = err.l2 / err.l2_exact;
    run.seconds       = seconds_since(start);
    std::ostringstream line;
    line << std::setw(8) << kind;
    if (kind == "uniform")
      line << " n = " << std::setw(3) << parameter << "           ";
    else
      line << " radius " << radius << " levels " << parameter;
    line << ": cells " << std::setw(6) << run.cells << ", dofs " << std::setw(7) << run.dofs << " (enriched "
         << std::setw(6) << run.enriched_dofs << "), |K_I - 1| " << std::setprecision(3) << run.k1_error()
         << " (J radius x0.5: " << std::abs(run.k1_half - 1.) << ", x2: " << std::abs(run.k1_double - 1.)
         << "), K_II " << run.k2 << ", energy " << run.energy << ", L2 " << run.l2 << ", " << run.seconds << " s";
    std::cout << line.str() << std::endl;
    return run;
  }

  /// DoFs at which the curve first reaches the K_I error target (log-log interpolation), nan if never.
  double dofs_to_reach(const std::vector<RefinementRun> &curve, double target)
  {
    for (std::size_t k = 0; k < curve.size(); ++k)
      if (curve[k].k1_error() <= target)
        {
          if (k == 0)
            {
              std::cout << "  the coarsest run of the curve already reaches it: the saving is a lower bound\n";
              return curve[0].dofs;
            }
          const RefinementRun &a = curve[k - 1], &b = curve[k];
          const double s = (std::log(target) - std::log(a.k1_error())) / (std::log(b.k1_error()) - std::log(a.k1_error()));
          const double dofs = std::exp(std::log(double(a.dofs)) + s * (std::log(double(b.dofs)) - std::log(double(a.dofs))));
          std::cout << "  reached between levels " << a.parameter << " and " << b.parameter << ": " << dofs
                    << " dofs by log-log interpolation\n";
          return dofs;
        }
    std::cout << "  never reached: the smallest K_I error of the curve is " << curve.back().k1_error() << " at "
              << curve.back().dofs << " dofs\n";
    return std::numeric_limits<double>::quiet_NaN();
  }
} // namespace

TEST(GlobalRefinementStudy, UniformAgainstAdaptiveNearTip)
{
  dealii::MultithreadInfo::set_thread_limit(1);
  unsigned int max_level = 4;
  if (const char *env = std::getenv("PUMPD_STUDY_MAX_LEVEL"))
    max_level = std::max(1, std::atoi(env));

  std::vector<RefinementRun> uniform;
  for (unsigned int n : {10u, 20u, 40u, 80u, 160u})
    {
      dealii::Triangulation<2> tria;
      make_square(tria, n);
      uniform.push_back(solve(tria, "uniform", n, 0.));
    }
  std::vector<std::vector<RefinementRun>> adaptive;
  for (const double radius : {0.5, 1.0})
    {
      adaptive.emplace_back();
      for (unsigned int levels = 1; levels <= max_level; ++levels)
        {
          dealii::Triangulation<2> tria;
          make_square(tria, 10);
          global::refine_near(tria, {tip}, radius, levels);
          adaptive.back().push_back(solve(tria, "adaptive", levels, radius));
        }
    }

  std::ofstream csv("study_refinement.csv");
  csv << "kind,parameter,refine_radius,cells,dofs,enriched_dofs,k1,k1_error,k2,k1_j_radius_x0.5,k1_j_radius_x2,"
         "energy_rel_error,l2_rel_error,seconds\n";
  csv << std::setprecision(12);
  std::vector<const std::vector<RefinementRun> *> curves = {&uniform};
  for (const auto &c : adaptive)
    curves.push_back(&c);
  for (const auto *curve : curves)
    for (const auto &r : *curve)
      {
        csv << r.kind << "," << r.parameter << "," << r.radius << "," << r.cells << "," << r.dofs << ","
            << r.enriched_dofs << "," << r.k1 << "," << r.k1_error() << "," << r.k2 << "," << r.k1_half << ","
            << r.k1_double << "," << r.energy << "," << r.l2 << "," << r.seconds << "\n";
        test::metric(r.tag() + ".dofs", r.dofs);
        test::metric(r.tag() + ".k1_error", r.k1_error());
        test::metric(r.tag() + ".energy_error", r.energy);
        EXPECT_TRUE(std::isfinite(r.k1));
      }

  const RefinementRun &finest = uniform.back();
  const double         target = finest.k1_error();
  std::cout << "finest uniform run: " << finest.dofs << " dofs, |K_I - 1| = " << target << "\n";
  std::cout << "adaptive, refinement radius 0.5:\n";
  const double saving = finest.dofs / dofs_to_reach(adaptive[0], target);
  std::cout << "adaptive, refinement radius 1.0:\n";
  const double saving_wide = finest.dofs / dofs_to_reach(adaptive[1], target);
  test::metric("global.amr_dof_saving", saving);
  test::metric("global.amr_dof_saving_radius_1", saving_wide);
}
