// Validation 4 of the global solver: displacement at many points (the PD boundary layer) through
// the cached interpolation matrix. The problem of the convergence test (mode I Williams field,
// 80 x 80 cells, tip radius 0.3) is solved once; then 10^4 seeded random points (80 % anywhere in
// the square, 10 % exactly on the crack faces behind the tip in +/- pairs with side hints +1 / -1,
// 10 % within 0.05 of the tip) are prepared and evaluated, on one thread.
// Timings (never pass/fail): the preparation (cell search + interpolation matrix) and u = P U
// (median of many repetitions), also with the points in lattice order (how a PD box lists them).
// Pass/fail: the fast values equal EnrichedElasticity::displacement(x, side) to 1e-12, they agree
// with the exact field to the discretisation error, and the faces open as the exact field does.
#include <gtest/gtest.h>

#include <deal.II/base/multithread_info.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <random>

#include "metric.h"
#include "williams_problem.h"

using namespace pumpd;
using namespace pumpd::bench;

namespace
{
  struct PointSet
  {
    std::vector<geometry::Point> x;
    std::vector<int>             side;
    std::vector<char>            on_face;   ///< exactly on a crack face (y = 0 behind the tip)
    std::vector<std::size_t>     face_pair; ///< for a + face point: the index of its - partner
  };

  PointSet make_points(std::size_t n, unsigned int seed)
  {
    std::mt19937_64                        rng(seed);
    std::uniform_real_distribution<double> unit(0., 1.);
    PointSet                               p;
    const auto add = [&](geometry::Point x, int side, bool face) {
      p.x.push_back(x);
      p.side.push_back(side);
      p.on_face.push_back(face);
    };
    // 10 %: on the crack faces, pairs at the same x with hints +1 and -1. Half of them spread
    // uniformly along the crack, half log-uniformly in the distance to the tip (1e-5 ... 1).
    const std::size_t n_pairs = n / 20;
    for (std::size_t k = 0; k < n_pairs; ++k)
      {
        const double d = k % 2 ? (tip.x - x_min) * (1e-3 + (1. - 2e-3) * unit(rng)) : std::pow(10., -5. + 5. * unit(rng));
        const geometry::Point x{tip.x - d, 0.};
        p.face_pair.push_back(p.x.size());
        add(x, 1, true);
        add(x, -1, true);
      }
    // 10 %: near the tip, r log-uniform in [1e-5, 0.05], any angle.
    const double pi = std::acos(-1.);
    for (std::size_t k = 0; k < n / 10; ++k)
      {
        const double r = std::pow(10., -5. + (std::log10(0.05) + 5.) * unit(rng));
        const double a = pi * (2. * unit(rng) - 1.);
        add({tip.x + r * std::cos(a), tip.y + r * std::sin(a)}, unit(rng) < 0.5 ? 1 : -1, false);
      }
    // The rest anywhere in the (closed) square, with random hints (ignored off the crack).
    while (p.x.size() < n)
      add({x_min + (x_max - x_min) * unit(rng), y_min + (y_max - y_min) * unit(rng)}, unit(rng) < 0.5 ? 1 : -1,
          false);
    // Random order (the face pairs stay findable through face_pair, remapped below).
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<std::size_t> where(n);
    PointSet                 shuffled;
    for (std::size_t i = 0; i < n; ++i)
      {
        where[order[i]] = i;
        shuffled.x.push_back(p.x[order[i]]);
        shuffled.side.push_back(p.side[order[i]]);
        shuffled.on_face.push_back(p.on_face[order[i]]);
      }
    for (const auto k : p.face_pair)
      {
        shuffled.face_pair.push_back(where[k]);     // + point
        shuffled.face_pair.push_back(where[k + 1]); // its - partner
      }
    return shuffled;
  }
} // namespace

TEST(GlobalPointEvaluation, TenThousandPoints)
{
  dealii::MultithreadInfo::set_thread_limit(1);
  const unsigned int n_cells = 80;
  const Williams     field{1, {1., 0.3, true}};

  dealii::Triangulation<2> tria;
  make_square(tria, n_cells);
  EnrichmentSettings settings;
  settings.tip_radius = 0.3;
  EnrichedElasticity problem(tria, field.material, settings);
  solve_williams(problem, field);
  const auto sif = problem.stress_intensity_factors();
  std::cout << n_cells << " x " << n_cells << " cells, " << problem.n_dofs() << " dofs, K_I " << sif[0].k1 << "\n";

  const std::size_t n      = 10000;
  const PointSet    points = make_points(n, 20240611u);

  // (a) preparation: median of a few repetitions.
  std::vector<double> t_setup;
  for (int rep = 0; rep < 5; ++rep)
    {
      const auto start = std::chrono::steady_clock::now();
      problem.prepare_point_evaluation(points.x, points.side);
      t_setup.push_back(seconds_since(start));
    }
  // (b) u = P U: median of many repetitions.
  std::vector<geometry::Point> u;
  std::vector<double>          t_eval;
  for (int rep = 0; rep < 301; ++rep)
    {
      const auto start = std::chrono::steady_clock::now();
      u                = problem.evaluate_points();
      t_eval.push_back(seconds_since(start));
    }
  ASSERT_EQ(u.size(), n);
  const double scale = 1e4 / n * 1e3; // ms per 10^4 points
  test::metric("global.point_eval_ms_per_10k", median(t_eval) * scale);
  test::metric("global.point_eval_setup_ms_per_10k", median(t_setup) * scale);

  // The slow path (one cell search and FEValues per point), for reference and as the truth.
  std::vector<geometry::Point> u_slow(n);
  {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < n; ++i)
      u_slow[i] = problem.displacement(points.x[i], points.side[i]);
    test::metric("global.point_eval_slow_ms_per_10k", seconds_since(start) * scale);
  }

  // The same points in lattice order (rows of cells, then x), as a PD box lists its layer: the
  // cell hint of the search is then almost always right.
  {
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    const double h = (y_max - y_min) / n_cells;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      const auto ra = std::floor((points.x[a].y - y_min) / h), rb = std::floor((points.x[b].y - y_min) / h);
      return ra != rb ? ra < rb : points.x[a].x < points.x[b].x;
    });
    std::vector<geometry::Point> xs;
    std::vector<int>             ss;
    for (auto i : order)
      {
        xs.push_back(points.x[i]);
        ss.push_back(points.side[i]);
      }
    std::vector<double> t_sorted;
    for (int rep = 0; rep < 5; ++rep)
      {
        const auto start = std::chrono::steady_clock::now();
        problem.prepare_point_evaluation(xs, ss);
        t_sorted.push_back(seconds_since(start));
      }
    test::metric("global.point_eval_setup_ms_per_10k_lattice_order", median(t_sorted) * scale);
    const auto u_sorted = problem.evaluate_points();
    double     worst = 0., largest = 0.;
    for (std::size_t k = 0; k < n; ++k)
      {
        worst   = std::max(worst, geometry::norm(u_sorted[k] - u[order[k]]));
        largest = std::max(largest, geometry::norm(u[order[k]]));
      }
    // A point on a cell edge may be found in either cell: equal up to rounding.
    EXPECT_LE(worst, 1e-12 * largest) << "the point order changed the values";
  }

  // Correctness (the only pass/fail part).
  double u_max = 0., u_exact_max = 0.;
  for (std::size_t i = 0; i < n; ++i)
    {
      u_max = std::max(u_max, geometry::norm(u_slow[i]));
      const int s = points.on_face[i] ? points.side[i] : points.x[i].y >= 0. ? 1 : -1;
      u_exact_max = std::max(u_exact_max, geometry::norm(field.u(points.x[i], s)));
    }
  double      worst_fast_slow = 0., worst_exact = 0., worst_exact_face = 0., worst_exact_near = 0.;
  std::size_t worst_i = 0, mismatches = 0, mismatch_minus_face = 0, mismatch_plus_face = 0, mismatch_elsewhere = 0;
  double      worst_slow_vs_exact = 0., worst_fast_vs_exact = 0., r_min_mismatch = 1e300, r_max_mismatch = 0.;
  for (std::size_t i = 0; i < n; ++i)
    {
      const double d = geometry::norm(u[i] - u_slow[i]);
      // 1e-12 relative to the point's own value, or to the largest value for a (nearly) zero one.
      const double rel = d / std::max(geometry::norm(u_slow[i]), 1e-3 * u_max);
      if (rel > worst_fast_slow)
        {
          worst_fast_slow = rel;
          worst_i         = i;
        }
      const int    s = points.on_face[i] ? points.side[i] : points.x[i].y >= 0. ? 1 : -1;
      if (rel > 1e-12)
        {
          const auto exact = field.u(points.x[i], s);
          const bool face  = points.on_face[i];
          (face && points.side[i] < 0 ? mismatch_minus_face : face ? mismatch_plus_face : mismatch_elsewhere)++;
          if (face && points.side[i] < 0)
            {
              worst_slow_vs_exact = std::max(worst_slow_vs_exact, geometry::norm(u_slow[i] - exact) / u_exact_max);
              worst_fast_vs_exact = std::max(worst_fast_vs_exact, geometry::norm(u[i] - exact) / u_exact_max);
              r_min_mismatch      = std::min(r_min_mismatch, geometry::norm(points.x[i] - tip));
              r_max_mismatch      = std::max(r_max_mismatch, geometry::norm(points.x[i] - tip));
            }
          if (mismatches++ < 5)
            ADD_FAILURE() << "point " << i << " (" << points.x[i].x << ", " << points.x[i].y << ") side hint "
                          << points.side[i] << (face ? " on the crack face" : "") << ": fast (" << u[i].x << ", "
                          << u[i].y << ") slow (" << u_slow[i].x << ", " << u_slow[i].y << ") exact (" << exact.x
                          << ", " << exact.y << ")";
        }
      const double e = geometry::norm(u[i] - field.u(points.x[i], s)) / u_exact_max;
      worst_exact    = std::max(worst_exact, e);
      if (points.on_face[i])
        worst_exact_face = std::max(worst_exact_face, e);
      if (geometry::norm(points.x[i] - tip) < 0.05)
        worst_exact_near = std::max(worst_exact_near, e);
    }
  std::cout << "fast vs slow: largest relative difference " << worst_fast_slow << " at point " << worst_i << " ("
            << points.x[worst_i].x << ", " << points.x[worst_i].y << "), " << mismatches
            << " points above 1e-12 (" << mismatch_minus_face << " on the - face, " << mismatch_plus_face
            << " on the + face, " << mismatch_elsewhere << " elsewhere)\n";
  if (mismatch_minus_face > 0)
    std::cout << "  - face mismatches at distances " << r_min_mismatch << " ... " << r_max_mismatch
              << " from the tip; error against the exact field there: slow path " << worst_slow_vs_exact
              << ", fast path " << worst_fast_vs_exact << " (relative to max |u|)\n";
  std::cout << "vs exact (relative to max |u| = " << u_exact_max << "): all " << worst_exact << ", on the faces "
            << worst_exact_face << ", within 0.05 of the tip " << worst_exact_near << "\n";
  EXPECT_EQ(mismatches, 0u);
  EXPECT_LT(worst_exact, 0.01);

  // Crack opening at the face pairs: u_y(+) - u_y(-) against the exact (kappa + 1) / mu sqrt(r / 2 pi).
  double opening_max = 0., worst_opening = 0., worst_opening_far = 0.;
  for (std::size_t k = 0; k < points.face_pair.size(); k += 2)
    {
      const std::size_t ip = points.face_pair[k], im = points.face_pair[k + 1];
      const double      exact = field.u(points.x[ip], 1).y - field.u(points.x[im], -1).y;
      opening_max             = std::max(opening_max, exact);
    }
  for (std::size_t k = 0; k < points.face_pair.size(); k += 2)
    {
      const std::size_t ip = points.face_pair[k], im = points.face_pair[k + 1];
      ASSERT_EQ(points.side[ip], 1);
      ASSERT_EQ(points.side[im], -1);
      const double exact    = field.u(points.x[ip], 1).y - field.u(points.x[im], -1).y;
      const double computed = u[ip].y - u[im].y;
      worst_opening         = std::max(worst_opening, std::abs(computed - exact) / opening_max);
      if (tip.x - points.x[ip].x > 0.05)
        worst_opening_far = std::max(worst_opening_far, std::abs(computed - exact) / exact);
      EXPECT_GT(computed, 0.) << "the faces do not open at x = " << points.x[ip].x;
    }
  std::cout << points.face_pair.size() / 2 << " face pairs: opening error " << worst_opening
            << " of the largest opening; more than 0.05 behind the tip, relative to the local opening "
            << worst_opening_far << "\n";
  EXPECT_LT(worst_opening, 0.01);
  EXPECT_LT(worst_opening_far, 0.02);
}
