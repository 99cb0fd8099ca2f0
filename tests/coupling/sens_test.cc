// Single-edge-notch shear (prm/sens.prm, meshes/sens.geo): a 0.1 m square, a notch from the middle
// of the left edge to the centre, the bottom edge held, the top edge sheared (ux = lambda) and
// lifted by a tenth of that; K_I / K_II = 0.22 at the tip.
//
// The first kink against the maximum hoop stress criterion (Erdogan & Sih 1963) of the computed
// K_II / K_I, theta_c = coupling::kink_angle(K_I, K_II) (-70.5 degrees for pure mode II; -66.5 here):
// - LEFM growth: the first increment, measured as the chord from the initial tip to its end;
// - global-local: the first accepted PD increment, measured the same way, the chord from the
//   initial tip to the increment's end (the extracted path turns by at most 45 degrees per step
//   of two spacings, so its first vertex is biased ahead; the chord over the whole increment,
//   two to four horizons long, is not).
// The angles are measured from the initial crack direction, counter-clockwise positive.
//
// theta_c is the limit r -> 0 of the direction of the largest hoop stress sigma_tt(r, theta). The
// PD crack leaves the tip where its bonds fail, one to two horizons out, and there the plate's own
// field (beyond K_I, K_II and the T-stress) has turned that direction by several degrees towards
// the horizontal. The test also measures the hoop stress of the global solution on the circle of
// the increment's length (GlobalProblem::hoop_direction) and
// holds the PD increment to its direction (5 degrees), LEFM to theta_c (3 degrees), the PD
// increment to theta_c within 12 degrees; kink_err_deg reports the worse of the two against
// theta_c. The studies (ctest -L study) measure the PD kink as the horizon shrinks against the
// plate, and the same PD box driven by the Williams field of the computed K_I, K_II alone.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

#include "boundary_layer.h"
#include "box_policy.h"
#include "crack.h"
#include "crack_extraction.h"
#include "exchange.h"
#include "growing_specimen.h"
#include "integrators.h"
#include "lefm.h"
#include "metric.h"
#include "model.h"

using namespace pumpd;

namespace
{
  const std::string scene_file = "prm/sens.prm";

  bool accepted(const coupling::ExchangeRecord &e) { return e.decision == "accept" || e.decision == "truncate"; }
} // namespace

TEST(SingleEdgeNotchShear, FirstKinkAgainstMaximumHoopStress)
{
  // LEFM growth: one increment.
  auto p           = test::scene_file(scene_file, "sens_lefm");
  p.lefm.max_steps = 1;
  const auto scene = coupling::build_scene(p.scene);
  const auto lefm  = coupling::run_lefm_growth(scene, p.lefm_growth_settings(), std::cout);
  ASSERT_GE(lefm.steps.size(), 1u);
  ASSERT_EQ(lefm.increments, 1u);
  const auto  &first      = lefm.steps.front();
  const double lefm_mts   = coupling::kink_angle(first.k1, first.k2);
  const double lefm_kink  = test::chord_angle(scene.crack(), lefm.path);
  const double lefm_error = std::abs(test::degrees(lefm_kink - lefm_mts));

  // Global-local: one exchange.
  auto q                 = test::scene_file(scene_file, "sens_global_local");
  q.cycle.max_exchanges  = 1;
  const auto gl          = coupling::run_global_local(coupling::build_scene(q.scene), q.global_local_settings(), std::cout);
  ASSERT_EQ(gl.exchanges.size(), 1u);
  const auto &exchange = gl.exchanges.front();
  ASSERT_TRUE(accepted(exchange)) << exchange.decision << ": " << gl.stop_reason;
  const double gl_mts   = coupling::kink_angle(exchange.k1, exchange.k2);
  const double gl_kink  = test::chord_angle(scene.crack(), gl.path);
  const double gl_error = std::abs(test::degrees(gl_kink - gl_mts));

  // The hoop stress of the plate's field where the PD increment ends.
  const double            reach = geometry::norm(gl.path.back() - scene.crack().back());
  const global::Crack     crack(scene.crack(), scene.body, 1e-8 * scene.body.bounding_box().width());
  coupling::GlobalProblem global(scene, q.global);
  const auto              tip         = global.solve(crack).front();
  const double            field       = global.hoop_direction(tip, reach);
  const double            field_error = std::abs(test::degrees(gl_kink - field));

  std::cout << "LEFM: K_II / K_I " << first.k2 / first.k1 << ", theta_c " << test::degrees(lefm_mts)
            << " deg, first increment " << test::degrees(lefm_kink) << " deg\n"
            << "global-local: K_II / K_I " << exchange.k2 / exchange.k1 << ", theta_c " << test::degrees(gl_mts)
            << " deg, first PD increment (" << 1e3 * exchange.advance << " mm at " << exchange.load_factor
            << " lambda_c) " << test::degrees(gl_kink) << " deg; the plate's largest hoop stress at "
            << 1e3 * reach << " mm from the tip: " << test::degrees(field) << " deg\n";
  test::metric("scene.sens.mts_kink_deg", test::degrees(lefm_mts));
  test::metric("scene.sens.lefm_kink_deg", test::degrees(lefm_kink));
  test::metric("scene.sens.gl_kink_deg", test::degrees(gl_kink));
  test::metric("scene.sens.lefm_kink_err_deg", lefm_error);
  test::metric("scene.sens.gl_kink_err_deg", gl_error);
  test::metric("scene.sens.kink_err_deg", std::max(lefm_error, gl_error));
  test::metric("scene.sens.field_hoop_deg", test::degrees(field));
  test::metric("scene.sens.gl_kink_err_to_field_hoop_deg", field_error);

  // Mostly mode II, K_II > 0 in the tip frame: the crack kinks down (theta_c < 0), by 60 to 70.5 degrees.
  EXPECT_GT(first.k1, 0.);
  EXPECT_GT(first.k2, 3. * first.k1);
  EXPECT_LT(test::degrees(lefm_mts), -60.);
  EXPECT_NEAR(exchange.k2 / exchange.k1, first.k2 / first.k1, 1e-6 * first.k2 / first.k1); // the same solve
  EXPECT_LT(lefm_error, 3.);
  EXPECT_LT(gl_error, 12.);
  EXPECT_LT(gl_kink, 0.);
  EXPECT_LT(field_error, 5.);
}

namespace
{
  /// The first PD increment of the cycle's first exchange for a PD horizon delta (box 10 delta
  /// centred on the tip, advance 2 to 4 delta, the global mesh refined to delta / 4 at the tip).
  coupling::Parameters at_horizon(double delta, const std::string &output)
  {
    auto p                         = test::scene_file(scene_file, output);
    p.pd.horizon                   = delta;
    p.cycle.box.size               = 10. * delta;
    p.cycle.box.margin             = 2. * delta;
    p.cycle.exchange.min_advance   = 2. * delta;
    p.cycle.exchange.max_advance   = 4. * delta;
    p.cycle.exchange.near_distance = 4. * delta;
    p.cycle.max_exchanges          = 1;
    p.global.refinement_levels     = static_cast<unsigned int>(std::round(3. + std::log2(0.001 / delta)));
    p.global.refinement_radius     = std::max(6. * delta, 0.002);
    p.global.tip_radius            = p.global.refinement_radius;
    return p;
  }

  std::string tag(double delta) { return "_at_delta_" + std::to_string(int(std::round(delta * 1e6))) + "um"; }
} // namespace

// Study (ctest -L study): the global-local first kink against theta_c as the horizon shrinks
// against the plate (delta / L = 0.01, 0.005, 0.0025).
TEST(SingleEdgeNotchShearStudy, DISABLED_KinkAgainstHorizon)
{
  for (const double delta : {0.001, 0.0005, 0.00025})
    {
      const auto p     = at_horizon(delta, "sens_study");
      const auto scene = coupling::build_scene(p.scene);
      const auto gl    = coupling::run_global_local(scene, p.global_local_settings(), std::cout);
      ASSERT_EQ(gl.exchanges.size(), 1u);
      ASSERT_TRUE(accepted(gl.exchanges.front())) << gl.stop_reason;
      const double mts  = coupling::kink_angle(gl.exchanges.front().k1, gl.exchanges.front().k2);
      const double kink = test::chord_angle(scene.crack(), gl.path);
      const global::Crack     crack(scene.crack(), scene.body, 1e-8 * scene.body.bounding_box().width());
      coupling::GlobalProblem global(scene, p.global);
      const auto              tip  = global.solve(crack).front();
      const double            r    = geometry::norm(gl.path.back() - scene.crack().back());
      const double            hoop = global.hoop_direction(tip, r);
      std::cout << "delta " << delta << " m: theta_c " << test::degrees(mts) << " deg, first PD increment "
                << test::degrees(kink) << " deg, the plate's largest hoop stress at " << r << " m "
                << test::degrees(hoop) << " deg\n";
      test::metric("scene.sens.gl_kink_err_deg" + tag(delta), std::abs(test::degrees(kink - mts)));
      test::metric("scene.sens.gl_kink_err_to_field_hoop_deg" + tag(delta), std::abs(test::degrees(kink - hoop)));
    }
}

// Study (ctest -L study): the PD box of the first exchange (delta = 1 mm) driven by the Williams
// field of the computed K_I, K_II alone instead of the global solution, the load raised as in an
// exchange until the crack has grown two horizons: how far PD itself kinks from theta_c.
TEST(SingleEdgeNotchShearStudy, DISABLED_PdBoxUnderTheKFieldAlone)
{
  const auto p     = at_horizon(0.001, "");
  const auto scene = coupling::build_scene(p.scene);
  coupling::GlobalProblem global(scene, p.global);
  const global::Crack     crack(scene.crack(), scene.body, 1e-8 * scene.body.bounding_box().width());
  const auto              tip = global.solve(crack).front();
  auto                    box = p.cycle.box;
  box.horizon                 = p.pd.horizon;
  box.spacing                 = p.pd.spacing();
  coupling::BoxPolicy  policy(scene.body, box);
  const local::PdModel model(p.pd.material(scene.material), p.pd.horizon, p.pd.horizon_over_spacing,
                             local::Region{scene.body, policy.place(tip.position, tip.direction), {crack.vertices()}});
  const double mu = model.material().shear_modulus(), kappa = lefm::kolosov(model.material().poisson_ratio(), true);
  const double mts = coupling::kink_angle(tip.k1, tip.k2);

  local::BoundaryLayer           layer(model);
  const local::DynamicRelaxation relax(model, p.pd.tolerance, p.pd.max_iterations);
  coupling::ExtractionSettings   extraction;
  extraction.threshold = p.pd.crack_damage;
  extraction.horizon   = p.pd.horizon;
  local::State s       = model.initial_state();
  double       kink = 0., previous = 0.;
  for (double f = 0.9; f < 3.; f += 0.05)
    {
      const double lambda = f * tip.critical_load_factor;
      for (std::size_t i : model.nodes())
        {
          s.ux[i] = previous > 0. ? s.ux[i] * lambda / previous : 0.;
          s.uy[i] = previous > 0. ? s.uy[i] * lambda / previous : 0.;
        }
      layer.set_target([&](geometry::Point x) {
        return lefm::williams_displacement(x, tip.position, tip.direction, lambda * tip.k1, lambda * tip.k2, mu, kappa);
      });
      layer.apply(s, 1.);
      relax.solve(s);
      previous        = lambda;
      const auto grew = coupling::extract_crack(coupling::damage_field(model, s), tip.position, tip.direction, extraction);
      if (grew.length() >= 2. * p.pd.horizon)
        {
          kink = test::chord_angle(crack.vertices(), grew.path);
          std::cout << "Williams field of K_I " << tip.k1 << ", K_II " << tip.k2 << " per unit lambda: at " << f
                    << " lambda_c the PD crack grew " << grew.length() << " m at " << test::degrees(kink)
                    << " deg; theta_c " << test::degrees(mts) << " deg\n";
          break;
        }
    }
  ASSERT_NE(kink, 0.) << "no growth of two horizons below 3 lambda_c";
  test::metric("scene.sens.pd_kink_err_deg_k_field_alone", std::abs(test::degrees(kink - mts)));
}
