// The tests of the specimens against handbook solutions (sent_test.cc, compact_tension_test.cc,
// double_cantilever_beam_test.cc): one global solve of a scene and the path measure they share.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>

#include "crack.h"
#include "global_local.h"
#include "global_problem.h"
#include "lefm_growth.h"
#include "metric.h"
#include "parameters.h"
#include "scene.h"

namespace pumpd::test
{
  /// A scene's tip state and report, per unit load factor (linear elasticity).
  struct Solution
  {
    coupling::TipState tip;               ///< K_I, K_II per unit lambda; lambda_c
    double             load         = 0.; ///< the scene's reported load per unit lambda
    double             displacement = 0.; ///< the scene's reported displacement per unit lambda
  };

  /// Solves the scene's crack once (GlobalProblem::solve); `inspect` sees the solved problem at
  /// the reference load factor.
  inline Solution solve(const coupling::Scene &scene, const coupling::GlobalSettings &settings,
                        const std::function<void(const coupling::GlobalProblem &)> &inspect = {})
  {
    coupling::GlobalProblem problem(scene, settings);
    const auto             &box  = scene.body.bounding_box();
    const auto              tips = problem.solve(
      global::Crack(scene.crack(), scene.body, 1e-8 * std::max(box.width(), box.height())));
    if (inspect)
      inspect(problem);
    const auto [load, displacement] = problem.report();
    const double lambda             = problem.load_factor();
    return {tips.at(0), load / lambda, displacement / lambda};
  }

  /// The largest distance of a path's vertices from the line y = y0 [m].
  inline double offset_from(const geometry::Polyline &path, double y0)
  {
    double d = 0.;
    for (const auto &x : path)
      d = std::max(d, std::abs(x.y - y0));
    return d;
  }

  /// A symmetric specimen's crack of length a along y = 0 (mouth at x = 0) grown by LEFM growth
  /// (three increments, each with a kink below half a degree) and by the global-local cycle
  /// (PD m = 4, two exchanges), `scene_at(output directory)` giving the scene (outputs <output>_lefm and
  /// <output>_global_local): both paths stay
  /// within 0.1 mm (LEFM) and 0.5 mm (one PD spacing, global-local) of y = 0. Prints
  /// <prefix>.lefm_path_offset_mm, .gl_path_offset_mm and .path_offset_mm (the larger).
  inline void expect_straight_growth(const std::function<coupling::Parameters(const std::string &)> &scene_at,
                                     double a, const std::string &output, const std::string &prefix)
  {
    auto lefm           = scene_at(output + "_lefm");
    lefm.lefm.max_steps = 3;
    std::ostringstream lefm_log;
    const auto         l =
      coupling::run_lefm_growth(coupling::build_scene(lefm.scene), lefm.lefm_growth_settings(), lefm_log);
    std::cout << lefm_log.str();
    EXPECT_EQ(l.increments, 3u);
    EXPECT_NEAR(l.path.back().x, a + 3 * lefm.lefm.growth_increment, 1e-6);
    for (const auto &s : l.steps)
      EXPECT_LT(std::abs(s.kink_angle), 0.5 * std::acos(-1.) / 180.);
    const double lefm_offset = offset_from(l.path, 0.);
    EXPECT_LT(lefm_offset, 1e-4);

    auto gl                    = scene_at(output + "_global_local");
    gl.pd.horizon_over_spacing = 4;
    gl.cycle.max_exchanges     = 2;
    std::ostringstream gl_log;
    const auto         g =
      coupling::run_global_local(coupling::build_scene(gl.scene), gl.global_local_settings(), gl_log);
    std::cout << gl_log.str();
    ASSERT_EQ(g.exchanges.size(), 2u);
    EXPECT_GT(g.path.back().x, a + 2 * gl.cycle.exchange.min_advance - 1e-9);
    const double gl_offset = offset_from(g.path, 0.);
    EXPECT_LT(gl_offset, 5e-4);

    metric(prefix + ".lefm_path_offset_mm", 1e3 * lefm_offset);
    metric(prefix + ".gl_path_offset_mm", 1e3 * gl_offset);
    metric(prefix + ".path_offset_mm", 1e3 * std::max(lefm_offset, gl_offset));
  }
} // namespace pumpd::test
