// Issue 45, the tips' states (scenes in tests/coupling/bad_prm/ on centre-crack-plate.geo, a 0.2 m
// square plate with a centre crack):
// - pure mode II (pure-shear-crack.prm): K_I is round-off against K_II, the tips are not closed
//   and kink by the maximum hoop stress's -sign(K_II) 2 atan(1 / sqrt 2) = -+70.53 degrees; both
//   tips grow in LEFM growth and go to PD boxes in the global-local cycle;
// - a crack along the load (crack-along-load.prm): no driving force at either tip, no lambda_c;
// - a crack shorter than twice the tip enrichment radius (short-crack.prm, 2a = 5 mm, and 2 mm,
//   on cells of 2 mm refined twice): K_I of Griffith's sigma sqrt(pi a) to 1 % (the plate's
//   finite width adds 0.02 %);
// - a closed tip (the same crack in compression): its critical_load_factor in load_steps.csv is an
//   empty field, and the study's records read such a field back as NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>

#include "csv.h"
#include "error.h"
#include "global_local.h"
#include "global_problem.h"
#include "lefm_growth.h"
#include "scene_file.h"
#include "study_record.h"

using namespace pumpd;

namespace
{
  const double pi      = std::acos(-1.);
  const double mode_ii = 2. * std::atan(1. / std::sqrt(2.)); // 70.53 degrees

  const std::string pure_shear = "tests/coupling/bad_prm/pure-shear-crack.prm";

  /// Every tip's state of the scene's initial cracks.
  std::vector<coupling::TipState> initial_tips(const coupling::Parameters &p)
  {
    const auto              scene = coupling::build_scene(p.scene);
    coupling::GlobalProblem global(scene, p.global);
    return global.solve(coupling::enriched_cracks(scene.cracks, scene));
  }

  double length(const std::vector<geometry::Polyline> &cracks)
  {
    double l = 0.;
    for (const auto &c : cracks)
      l += geometry::length(c);
    return l;
  }
} // namespace

TEST(Tips, PureModeIIIsNotClosedAndKinksByTheMaximumHoopStress)
{
  const auto tips = initial_tips(test::scene_file(pure_shear, ""));
  ASSERT_EQ(tips.size(), 2u);
  for (const auto &t : tips)
    {
      std::cout << "tip " << t.position.x << ": K_I " << t.k1 << ", K_II " << t.k2 << ", K_I / |K_II| "
                << t.k1 / std::abs(t.k2) << ", |K| of the terms " << std::hypot(t.k1, t.k2) / t.k_terms << ", kink " << coupling::kink_angle(t.k1, t.k2) * 180. / pi << " deg\n";
      EXPECT_EQ(coupling::at_rest(t), "");
      EXPECT_TRUE(std::isfinite(t.critical_load_factor));
      EXPECT_LT(std::abs(t.k1), 1e-2 * std::abs(t.k2)); // pure mode II to the integral's resolution
      // The maximum hoop stress direction of pure mode II, to 0.5 degrees.
      EXPECT_NEAR(coupling::kink_angle(t.k1, t.k2), -std::copysign(mode_ii, t.k2), 0.5 * pi / 180.);
    }
}

TEST(Tips, PureModeIIGrowsInBothMethods)
{
  auto p           = test::scene_file(pure_shear, "tips_pure_shear_lefm");
  const auto scene = coupling::build_scene(p.scene);
  const auto lefm  = coupling::run_lefm_growth(scene, p.lefm_growth_settings(), std::cout);
  // Both tips grew by the increment, kinked: each adds at least half of it.
  EXPECT_GT(length(lefm.paths), length(scene.cracks) + p.lefm.growth_increment) << lefm.stop_reason;
  EXPECT_EQ(lefm.stop_reason.find("closed"), std::string::npos) << lefm.stop_reason;

  auto q                = test::scene_file(pure_shear, "tips_pure_shear_global_local");
  q.cycle.max_exchanges = 1;
  const auto gl         = coupling::run_global_local(coupling::build_scene(q.scene), q.global_local_settings(), std::cout);
  // The cycle sends both tips to PD boxes (what PD makes of the shear is its own: the bond-based
  // damage branches, and the extractor refuses that).
  EXPECT_GE(gl.exchanges.size(), 2u) << gl.stop_reason;
  EXPECT_EQ(gl.stop_reason.find("closed"), std::string::npos) << gl.stop_reason;
  EXPECT_EQ(gl.stop_reason.find("no tip grows"), std::string::npos) << gl.stop_reason;
}

TEST(Tips, ACrackAlongTheLoadHasNoDrivingForce)
{
  const auto tips = initial_tips(test::scene_file("tests/coupling/bad_prm/crack-along-load.prm", ""));
  ASSERT_EQ(tips.size(), 2u);
  for (const auto &t : tips)
    {
      std::cout << "tip " << t.position.x << ": |K| " << std::hypot(t.k1, t.k2) << ", of the terms " << t.k_terms
                << ": " << std::hypot(t.k1, t.k2) / t.k_terms << "\n";
      EXPECT_NE(coupling::at_rest(t).find("has no driving force"), std::string::npos) << coupling::at_rest(t);
      EXPECT_FALSE(std::isfinite(t.critical_load_factor));
    }
}

TEST(Tips, ACrackShorterThanTheTipRadiusGetsGriffithsK)
{
  for (const double a : {0.0025, 0.001})
    {
      auto p                 = test::scene_file("tests/coupling/bad_prm/short-crack.prm", "");
      p.scene.initial_cracks = to_text(-a) + ",0; " + to_text(a) + ",0";
      const double griffith  = std::sqrt(pi * a); // sigma = lambda = 1 Pa
      for (const auto &t : initial_tips(p))
        {
          std::cout << "2a = " << 2. * a << " m, tip " << t.position.x << ": K_I / sigma sqrt(pi a) - 1 = "
                    << t.k1 / griffith - 1. << ", |K| of the terms " << std::hypot(t.k1, t.k2) / t.k_terms << "\n";
          EXPECT_NEAR(t.k1 / griffith, 1., 0.01);
        }
    }
}

TEST(Tips, StudyRecordsReadAnEmptyFieldBackAsNotANumber)
{
  const std::string file = (std::filesystem::temp_directory_path() / "pumpd_tips_runs.csv").string();
  std::filesystem::remove(file);
  coupling::append_record(file, {"lefm", "k", "lefm-growth", "ok", 1.5, 20., 0., 1000., std::nan("")});
  const auto records = coupling::read_records(file);
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].wall_seconds, 1.5);
  EXPECT_EQ(records[0].global_dofs, 1000.);
  EXPECT_TRUE(std::isnan(records[0].pd_seconds));
}

TEST(Tips, AClosedTipsCriticalLoadFactorIsAnEmptyField)
{
  auto p           = test::scene_file("tests/coupling/bad_prm/short-crack.prm", "tips_closed");
  p.scene.traction = "top: ty = -lambda"; // compression: K_I = -sigma sqrt(pi a)
  const auto r     = coupling::run_lefm_growth(coupling::build_scene(p.scene), p.lefm_growth_settings(), std::cout);
  EXPECT_NE(r.stop_reason.find("is closed (K_I < 0)"), std::string::npos) << r.stop_reason;
  const auto rows = read_csv_rows(p.scene.output_directory + "/load_steps.csv");
  ASSERT_EQ(rows.size(), 2u); // step 0, both tips
  for (const auto &row : rows)
    {
      EXPECT_EQ(row.at("critical_load_factor"), "");
      EXPECT_TRUE(std::isnan(csv_number(row.at("critical_load_factor"))));
      EXPECT_LT(csv_number(row.at("K_I_Pa_sqrt_m")), 0.);
    }
}
