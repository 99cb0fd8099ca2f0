// Study (ctest -L study): how thin may the cells at a crack be before K_I goes wrong?
// The SENT strip of global_sif_test (W = 1, [0, 1] x [-2, 2], edge crack a = 0.5 on y = 0, uniform
// traction on the ends, plane strain, E = 1, nu = 0.3; Tada's handbook K_I, quoted to 0.5 %) on
// the 40 x 160 mesh (h = 1/40), with one line of cells made thin, aspect ratio A:
//   row:    the row of cells that holds the crack line, height h / A, the crack at a fraction
//           `at` of its height; the crack row's nodes then have supports the crack cuts into a
//           sliver of area fraction about at / A. Two positions: at = 0.3, and the one just below
//           the Heaviside drop threshold (area fraction 0.9 min_cut_fraction), the worst case of
//           the area rule alone;
//   column: the column of cells that holds the tip, width h / A, the tip at 0.37 of its width.
// The rows and columns around keep cells of about h. Tip enrichment radius 0.15, interaction
// integral over the whole enriched zone (global_sif_test's settings). Prints per case the
// relative error of K_I as pumpd-metric global.sliver_<case>_k_rel_err_at_<A>, and expects it
// within global_sif_test's 1 % for SENT, up to A = 1e9 (the mesh reader refuses thinner cells).
#include <gtest/gtest.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "elasticity.h"
#include "metric.h"
#include "sent_strip.h"

using namespace pumpd;
using namespace pumpd::global;

namespace
{
  const double       pi = std::acos(-1.);
  const double       a  = 0.5;
  const unsigned int n  = 40; // cells across the width
  const double       h  = 1. / n;

  /// Steps of about h from `from` to `to`.
  void steps(std::vector<double> &out, double from, double to)
  {
    const unsigned int k = std::max(1., std::round((to - from) / h));
    out.insert(out.end(), k, (to - from) / k);
  }

  /// Steps of about h over [lower, upper] with one step of `thin` whose lower end lies `below`
  /// under `at`.
  std::vector<double> with_thin_step(double lower, double upper, double at, double thin, double below)
  {
    std::vector<double> out;
    steps(out, lower, at - below);
    out.push_back(thin);
    steps(out, at - below + thin, upper);
    return out;
  }

  /// K_I / K_ref - 1 on the mesh of these x and y steps.
  double sent_error(const std::vector<double> &dx, const std::vector<double> &dy)
  {
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {dx, dy}, dealii::Point<2>(0., -2.), dealii::Point<2>(1., 2.),
                                                      true);
    EnrichmentSettings settings;
    settings.tip_radius = 0.15;
    EnrichedElasticity problem(tria, {1., 0.3, true}, settings);
    const geometry::Body body{{0., -2., 1., 2.}, {}};
    problem.set_crack(Crack({{0., 0.}, {a, 0.}}, body, 1e-12));
    sent_strip::load(problem);
    problem.setup();
    problem.assemble();
    problem.solve();
    const double k_ref = std::sqrt(pi * a) * sent_strip::geometry_factor(a);
    return problem.stress_intensity_factors().at(0).k1 / k_ref - 1.;
  }

  /// The tip 0.37 h right of the nearest vertical mesh line (global_sif_test's generic position).
  std::vector<double> columns() { return with_thin_step(0., 1., a, h, 0.37 * h); }

  double row_error(double aspect, double at)
  {
    const double t = h / aspect;
    return sent_error(columns(), with_thin_step(-2., 2., 0., t, at * t));
  }

  double column_error(double aspect)
  {
    const double t = h / aspect;
    return sent_error(with_thin_step(0., 1., a, t, 0.37 * t), with_thin_step(-2., 2., 0., h, 0.41 * h));
  }

  std::string to_string(double aspect)
  {
    std::ostringstream s;
    s << aspect;
    return s.str();
  }

  void report(const std::string &name, double aspect, double error)
  {
    std::cout << name << ", aspect ratio " << aspect << ": K_I rel. err " << error << "\n";
    test::metric("global.sliver_" + name + "_k_rel_err_at_" + to_string(aspect), error);
    EXPECT_LT(std::abs(error), 0.01) << name << ", aspect ratio " << aspect;
  }

} // namespace

TEST(SliverCells, KOfTheSentStripAgainstTheAspectRatioOfTheCellsAtTheCrack)
{
  const double min_cut_fraction = EnrichmentSettings().min_cut_fraction;
  for (const double aspect : {1., 2., 5., 10., 20., 50., 100., 200., 500., 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9})
    {
      report("row", aspect, row_error(aspect, 0.3));
      // Area fraction of the crack row's upper nodes: at t / (h + t).
      const double worst = 0.9 * min_cut_fraction * (aspect + 1.);
      if (worst < 0.5)
        report("row_worst", aspect, row_error(aspect, worst));
      report("column", aspect, column_error(aspect));
    }
}
