// The global mesh follows the tip (GlobalProblem, Global / Refinement trail): the cells refined
// at earlier tips go back to the mesh's own where the tip has moved on by more than the trail.
// SENT (prm/sent.prm), an edge crack grown straight across from a = 25 mm to a = 45 mm in 5 mm
// steps, one global solve per step:
// - K_I at the last tip with a 10 mm trail against the whole path kept refined: the singular
//   field lives within the tip's enrichment radius (10 mm), behind it the crack's opening is
//   carried exactly by the Heaviside enrichment, so the two agree within 0.5 %, on fewer unknowns;
// - the mesh is a function of the refinement history and the tips: a problem restored from the
//   history of the first four solves (a resumed run) gives the fifth solve's K_I bit for bit.
#include <gtest/gtest.h>

#include <cmath>

#include "crack.h"
#include "global_problem.h"
#include "metric.h"
#include "scene.h"
#include "scene_file.h"

using namespace pumpd;

namespace
{
  struct Grown
  {
    coupling::TipState                tip;
    unsigned int                      dofs = 0;
    std::vector<coupling::Refinement> history_before_last;
    geometry::Polyline                path;
  };

  /// Solves at a = 25, 30, ..., 45 mm; the state of the last tip.
  Grown grow(const coupling::Scene &scene, coupling::GlobalSettings settings, double trail)
  {
    settings.refinement_trail = trail;
    coupling::GlobalProblem problem(scene, settings);
    global::Crack           crack({{0., 0.}, {0.025, 0.}}, scene.body, 1e-10);
    Grown                   g;
    for (int step = 0; step < 5; ++step)
      {
        if (step > 0)
          crack.grow(0, {0.025 + 0.005 * step, 0.});
        if (step == 4)
          g.history_before_last = problem.refinements();
        g.tip = problem.solve(crack).front();
      }
    g.dofs = problem.n_dofs();
    g.path = crack.vertices();
    return g;
  }
} // namespace

TEST(RefinementTrail, TheTipsStressIntensityWithoutTheRefinedPathBehind)
{
  const auto p     = test::scene_file("prm/sent.prm", "");
  const auto scene = coupling::build_scene(p.scene);
  const auto whole = grow(scene, p.global, 1e3);
  const auto trail = grow(scene, p.global, 0.01);
  const double rel = std::abs(trail.tip.k1 / whole.tip.k1 - 1.);
  test::metric("global.trail_k1_rel_change", rel);
  test::metric("global.trail_dofs_over_whole_path", double(trail.dofs) / double(whole.dofs));
  EXPECT_LT(rel, 5e-3);
  EXPECT_LT(trail.dofs, whole.dofs);
  EXPECT_NEAR(trail.tip.k2 / trail.tip.k1, 0., 1e-3);

  coupling::GlobalSettings settings = p.global;
  settings.refinement_trail         = 0.01;
  coupling::GlobalProblem resumed(scene, settings);
  resumed.restore(trail.history_before_last);
  global::Crack crack(trail.path, scene.body, 1e-10);
  EXPECT_EQ(resumed.solve(crack).front().k1, trail.tip.k1);
}
