// The tests of the specimens that grow a crack (sens_test.cc, l_panel_test.cc,
// hole_rim_crack_test.cc, semicircular_bend_test.cc): what a grown path is measured by.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "body.h"
#include "global_local.h"
#include "lefm_growth.h"
#include "metric.h"
#include "scene_file.h"

namespace pumpd::test
{
  /// The angle [rad] from the initial crack's tip direction (its last segment) to the chord from
  /// its tip to the end of the grown path, in (-pi, pi]: > 0 counter-clockwise.
  inline double chord_angle(const geometry::Polyline &initial, const geometry::Polyline &grown)
  {
    const geometry::Point tip = initial.back(), d = tip - initial[initial.size() - 2], c = grown.back() - tip;
    return std::atan2(geometry::cross(d, c), geometry::dot(d, c));
  }

  /// How much longer the grown path is than the initial crack [m].
  inline double growth(const geometry::Polyline &initial, const geometry::Polyline &grown)
  {
    return geometry::length(grown) - geometry::length(initial);
  }

  /// True if the path's vertices lie in the body and its segments stay in the material, "on the
  /// boundary" within the scene's crack tolerance (1e-8 of the body's larger side: a rim fitted to
  /// the mesh's vertices is a circle to about 1e-10 of its radius, basics/body.h).
  inline bool inside(const geometry::Polyline &path, const geometry::Body &body)
  {
    const double tolerance = 1e-8 * std::max(body.bounding_box().width(), body.bounding_box().height());
    for (std::size_t k = 0; k < path.size(); ++k)
      if ((!body.contains(path[k]) && body.clearance(path[k]) > tolerance) ||
          (k > 0 && body.crosses_boundary(path[k - 1], path[k], tolerance)))
        return false;
    return true;
  }

  inline double degrees(double radians) { return radians * 180. / std::acos(-1.); }

  /// A scene's crack grown by both methods.
  struct GrownInBothMethods
  {
    coupling::Scene             scene;
    coupling::LefmGrowthResult  lefm;
    coupling::GlobalLocalResult gl;
  };

  /// Grows the crack of the scene `file` by LEFM growth (three increments) and by the global-local
  /// cycle (two exchanges; outputs <output>_lefm, <output>_global_local). Both must stop at their
  /// step limit, LEFM having grown more than `lefm_growth` [m] and the cycle more than twice its
  /// minimum advance, both paths inside the body. Prints <prefix>.grew (1 or 0),
  /// .lefm_growth_mm and .gl_growth_mm.
  inline GrownInBothMethods grow_in_both_methods(const std::string &file, const std::string &output,
                                                 const std::string &prefix, double lefm_growth)
  {
    auto p           = scene_file(file, output + "_lefm");
    p.lefm.max_steps = 3;
    GrownInBothMethods r{coupling::build_scene(p.scene), {}, {}};
    r.lefm = coupling::run_lefm_growth(r.scene, p.lefm_growth_settings(), std::cout);

    auto q                = scene_file(file, output + "_global_local");
    q.cycle.max_exchanges = 2;
    r.gl = coupling::run_global_local(coupling::build_scene(q.scene), q.global_local_settings(), std::cout);

    const double lefm_grew = growth(r.scene.crack(), r.lefm.path), gl_grew = growth(r.scene.crack(), r.gl.path);
    std::cout << "LEFM grew " << lefm_grew << " m (" << r.lefm.stop_reason << "), global-local " << gl_grew << " m ("
              << r.gl.stop_reason << ")\n";
    // Each exchange advances at least the minimum advance, scaled with its box's horizon (resolution.h).
    double least_gl_growth = 0.;
    for (const auto &e : r.gl.exchanges)
      least_gl_growth += q.cycle.exchange.min_advance * e.horizon / q.pd.horizon;
    const bool grew = r.lefm.increments == 3 && lefm_grew > lefm_growth && r.gl.exchanges.size() == 2 &&
                      gl_grew > least_gl_growth;
    metric(prefix + ".grew", grew ? 1. : 0.);
    metric(prefix + ".lefm_growth_mm", 1e3 * lefm_grew);
    metric(prefix + ".gl_growth_mm", 1e3 * gl_grew);
    EXPECT_TRUE(grew);
    EXPECT_EQ(r.lefm.stop_reason, "maximum steps");
    EXPECT_EQ(r.gl.stop_reason, "maximum exchanges");
    EXPECT_TRUE(inside(r.lefm.path, r.scene.body));
    EXPECT_TRUE(inside(r.gl.path, r.scene.body));
    return r;
  }
} // namespace pumpd::test
