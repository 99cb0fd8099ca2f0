// Validation 3 of the global solver: degenerate positions of the crack relative to the mesh.
// The SENT specimen of sif_test.cc (strip [0, 1] x [-2, 2], edge crack from the left edge at
// mid-height, a/W = 0.5, sigma = 1 on the top and bottom edges, plane strain, nu = 0.3) on UNIFORM
// meshes of square cells, so that the mesh lines are known exactly:
//   odd mesh  41 x 164, h = 1/41: lines at x = i h, y = j h; x = a = 0.5 is the middle of a column;
//   even mesh 40 x 160, h = 1/40: lines at x = i h, y = j h; (0.5, 0) is a vertex.
// Cases: (i) the crack runs along a row of element edges; (ii) the crack crosses a mesh vertex;
// (iii) the tip lies on a vertex; (iv) the tip lies in the middle of an edge; (v) the crack line is
// 1e-8 h from a mesh line (cut fraction 1e-8); (vi) the tip is 1e-8 h from a vertex; and some
// combinations. The inclined cracks have slope 0.02 or 0.0137 (K_I changes by < 0.05 % from the
// straight crack's).
// The crack lines lie within h of mid-height (immaterial in a strip of half-height 2).
// Each case must set up, assemble and solve without an exception, give finite displacements (at
// points on both crack faces, at the tip, ahead of it and far away) with a positive crack opening,
// and K_I within 2 % of the reference: the same a with the crack line and the tip at a generic
// position (odd mesh, crack at y = 0.37 h), computed here; the even-mesh cases are compared with it
// too (no generic tip position at x = 0.5 exists on the even mesh; h differs by 2.5 %). Tip
// enrichment radius and q-function radius 0.1 (4 cells) throughout.
// A second test checks that displacement(x, side) at a point exactly on a crack face returns that
// face's value, in the Heaviside and in the tip-enriched region, against the batched evaluation.
#include <gtest/gtest.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "elasticity.h"
#include "sent_strip.h"

using namespace pumpd;
using namespace pumpd::global;

namespace
{
  constexpr double a = 0.5;

  struct Case
  {
    std::string        name;
    unsigned int       n; ///< cells across the width (41: odd mesh, 40: even mesh)
    geometry::Polyline crack;
  };

  struct Outcome
  {
    double       k1 = 0., k2 = 0.;
    unsigned int dofs = 0, heaviside = 0, tip = 0;
  };

  /// The crack's y at x, on its (straight) polyline.
  double crack_y(const geometry::Polyline &c, double x)
  {
    const auto &p = c.front(), &q = c.back();
    return p.y + (q.y - p.y) * (x - p.x) / (q.x - p.x);
  }

  /// The SENT strip's loads; then set up, assemble and solve.
  void solve_sent(EnrichedElasticity &problem)
  {
    sent_strip::load(problem);
    problem.setup();
    problem.assemble();
    problem.solve();
  }

  Outcome run(const Case &c)
  {
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {c.n, 4 * c.n}, dealii::Point<2>(0., -2.),
                                                      dealii::Point<2>(1., 2.), true);
    EnrichmentSettings settings;
    settings.tip_radius = 0.1;
    EnrichedElasticity problem(tria, {1., 0.3, true}, settings);
    problem.set_crack(Crack(c.crack, {{0., -2., 1., 2.}, {}}, 1e-12));
    solve_sent(problem);

    // Finite displacements at the tip, just ahead of it and far away (displacement(), one cell
    // search each), and on both faces at x = 0.2 (Heaviside region) and 0.45 (tip region), exactly
    // on the crack line, through the batched evaluation with a side for each point; the crack must
    // open there.
    const geometry::Point tip = c.crack.back();
    for (const geometry::Point &p : {tip, tip + geometry::Point{0.013, 0.}, geometry::Point{0.9, 1.7}})
      {
        const auto u = problem.displacement(p);
        EXPECT_TRUE(std::isfinite(u.x) && std::isfinite(u.y)) << "at (" << p.x << ", " << p.y << ")";
      }
    std::vector<geometry::Point> faces;
    for (double x : {0.2, 0.45})
      faces.insert(faces.end(), 2, geometry::Point{x, crack_y(c.crack, x)});
    problem.prepare_point_evaluation(faces, {1, -1, 1, -1});
    const auto u = problem.evaluate_points();
    for (unsigned int i = 0; i < faces.size(); ++i)
      EXPECT_TRUE(std::isfinite(u[i].x) && std::isfinite(u[i].y)) << "at x = " << faces[i].x;
    for (unsigned int i = 0; i < faces.size(); i += 2)
      EXPECT_GT(u[i].y - u[i + 1].y, 0.) << "crack opening at x = " << faces[i].x;

    const auto sif = problem.stress_intensity_factors(1.);
    EXPECT_EQ(sif.size(), 1u);
    return {sif.at(0).k1, sif.at(0).k2, problem.n_dofs(), problem.n_heaviside_nodes(), problem.n_tip_nodes()};
  }
} // namespace

TEST(GlobalRobustness, DegenerateCrackPositions)
{
  const double h_odd = 1. / 41., h_even = 1. / 40.;
  const Case   reference{"generic: odd mesh, crack at y = 0.37 h, tip inside a cell", 41,
                         {{0., 0.37 * h_odd}, {a, 0.37 * h_odd}}};
  // Inclined crack ending at (0.5, 0) with slope 0.0137: it meets no other vertex.
  const double s = 0.0137;
  const std::vector<Case> cases = {
    {"(i) along the edge row y = 0 (odd mesh; tip at mid-edge)", 41, {{0., 0.}, {a, 0.}}},
    {"(ii) slope 0.02 through the vertex (10 h, 0) (odd mesh)", 41, {{0., -0.2 * h_odd}, {a, 0.21 * h_odd}}},
    {"(iii) slope 0.0137, tip on the vertex (0.5, 0) (even mesh)", 40, {{0., -s * a}, {a, 0.}}},
    {"(i+iii) along y = 0, tip on the vertex (0.5, 0) (even mesh)", 40, {{0., 0.}, {a, 0.}}},
    {"(iv) y = h/2, tip at the middle of a vertical edge (even mesh)", 40, {{0., 0.5 * h_even}, {a, 0.5 * h_even}}},
    {"(iv) slope 0.0137, tip at the middle of a horizontal edge (odd mesh)", 41, {{0., -s * a}, {a, 0.}}},
    {"(v) y = 1e-8 h above the edge row y = 0 (odd mesh)", 41, {{0., 1e-8 * h_odd}, {a, 1e-8 * h_odd}}},
    {"(vi) slope 0.0137, tip 1e-8 h from the vertex (0.5, 0) (even mesh)", 40,
     {{0., -s * a}, {a + 0.6e-8 * h_even, 0.8e-8 * h_even}}},
    {"(v+vi) y = 1e-8 h, tip 1e-8 h above the vertex (0.5, 0) (even mesh)", 40,
     {{0., 1e-8 * h_even}, {a, 1e-8 * h_even}}},
  };

  const auto print = [](const std::string &name, const Outcome &o, double k_ref) {
    std::cout << name << ": K_I " << o.k1 << " (" << (o.k1 / k_ref - 1.) * 100. << " % from the reference), K_II "
              << o.k2 << ", " << o.dofs << " dofs, " << o.heaviside << " Heaviside nodes, " << o.tip << " tip nodes\n";
  };
  const Outcome ref = run(reference);
  print(reference.name, ref, ref.k1);
  for (const auto &c : cases)
    {
      SCOPED_TRACE(c.name);
      Outcome o;
      try
        {
          o = run(c);
        }
      catch (const std::exception &e)
        {
          ADD_FAILURE() << "exception: " << e.what();
          continue;
        }
      print(c.name, o, ref.k1);
      EXPECT_TRUE(std::isfinite(o.k1) && std::isfinite(o.k2));
      EXPECT_LT(std::abs(o.k1 / ref.k1 - 1.), 0.02);
    }
}

// EnrichedElasticity::displacement(x, side) at a point exactly on a crack face must give that
// face's value, as the batched evaluation (prepare_point_evaluation with a side per point) does.
// Checked in the Heaviside region (x = 0.2) and in the tip-enriched region (x = 0.45, within the
// tip radius 0.1 of the tip at 0.5), generic crack position. Tolerance 1e-10 relative.
TEST(GlobalRobustness, DisplacementOnCrackFaceHonoursSide)
{
  dealii::Triangulation<2> tria;
  dealii::GridGenerator::subdivided_hyper_rectangle(tria, {41, 164}, dealii::Point<2>(0., -2.),
                                                    dealii::Point<2>(1., 2.), true);
  EnrichmentSettings settings;
  settings.tip_radius = 0.1;
  EnrichedElasticity problem(tria, {1., 0.3, true}, settings);
  const double y = 0.37 / 41.;
  problem.set_crack(Crack({{0., y}, {a, y}}, {{0., -2., 1., 2.}, {}}, 1e-12));
  solve_sent(problem);
  for (double x : {0.2, 0.45})
    {
      const geometry::Point on{x, y};
      problem.prepare_point_evaluation({on, on}, {1, -1});
      const auto batched = problem.evaluate_points();
      for (int side : {1, -1})
        {
          const auto   u        = problem.displacement(on, side);
          const auto   expected = batched[side > 0 ? 0 : 1];
          const double scale    = geometry::norm(expected);
          std::cout << "x = " << x << ", side " << side << ": displacement() (" << u.x << ", " << u.y
                    << "), batched (" << expected.x << ", " << expected.y << ")\n";
          EXPECT_NEAR(u.x, expected.x, 1e-10 * scale) << "x = " << x << ", side " << side;
          EXPECT_NEAR(u.y, expected.y, 1e-10 * scale) << "x = " << x << ", side " << side;
        }
    }
}
