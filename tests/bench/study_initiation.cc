// The L-shaped panel without a pre-crack (prm/l-panel-initiation.prm) by the global-local method
// (the crack nucleated at the re-entrant corner, then grown: coupling/nucleation.h) and by full PD
// of the whole panel (the crack forms and is traced by itself: coupling/full_pd.h). Label study
// (not in CI): full PD of the panel takes minutes. Both at delta = 8 mm, m = 4 (h = 2 mm; full PD
// at the scene's delta = 4 mm, m = 8 has about 750k nodes); the cycle's box, margin and advances
// at twice the scene's, as the horizon is, and the horizon fixed (resolution rule `fixed`: no
// halving near the corner and the left edge), so that both methods see the same PD material.
// The arbiter: LEFM growth (coupling/lefm_growth.h: XFEM and the maximum hoop stress, the scene's
// section LEFM growth) from the first 6 mm of the nucleated crack, the path a linear elastic
// brittle panel takes from the corner.
// Outputs under <build>/tests/bench/study_initiation_output/.
// Metrics: initiation.lpanel.vs_fullpd_mean_mm (symmetric mean distance of the two paths over the
// shorter one's extent, coupling/path_metrics.h), initiation.lpanel.gl_vs_lefm_mean_mm and
// initiation.lpanel.fullpd_vs_lefm_mean_mm (each against LEFM's),
// initiation.lpanel.coupled_over_fullpd_time, the mouths' distance from the corner and each
// method's crack length.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <string>

#include "full_pd.h"
#include "lefm_growth.h"
#include "metric.h"
#include "nucleation.h"
#include "parameters.h"
#include "path_metrics.h"

using namespace pumpd;

namespace
{
  coupling::Parameters panel(const std::string &run)
  {
    auto p                    = coupling::read_parameters("prm/l-panel-initiation.prm");
    p.scene.output_directory  = std::string(PUMPD_BINARY_DIR) + "/study_initiation_output/" + run;
    p.pd.horizon              = 0.008;
    p.pd.horizon_over_spacing = 4;
    p.cycle.box.size          = 0.064;
    p.cycle.box.margin        = 0.016;
    p.cycle.box.max_size      = 0.128;
    p.cycle.exchange.max_advance = 0.016;
    p.cycle.exchange.min_advance = 0.008;
    p.cycle.exchange.near_distance = 0.016;
    p.cycle.resolution.rule        = "fixed";
    std::filesystem::remove_all(p.scene.output_directory);
    return p;
  }

  double seconds_since(std::chrono::steady_clock::time_point t)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }
} // namespace

TEST(StudyInitiation, LPanelGlobalLocalAgainstFullPd)
{
  const geometry::Point corner{0.25, 0.25};
  const auto            gl_prm = panel("global_local");
  auto                  t      = std::chrono::steady_clock::now();
  const auto gl = coupling::run_global_local_from_initiation(coupling::build_scene(gl_prm.scene),
                                                             gl_prm.global_local_settings(), gl_prm.initiation, std::cout);
  const double gl_seconds = seconds_since(t);

  const auto pd_prm = panel("full_pd");
  t                 = std::chrono::steady_clock::now();
  const auto pd     = coupling::run_full_pd(coupling::build_scene(pd_prm.scene), pd_prm.full_pd_settings(), std::cout);
  const double pd_seconds = seconds_since(t);

  ASSERT_GE(gl.path.size(), 2u);
  ASSERT_GE(pd.path.size(), 2u);
  const auto lefm_prm = panel("lefm");
  auto       lefm_scene = coupling::build_scene(lefm_prm.scene);
  lefm_scene.cracks     = {coupling::truncate(gl.path, 0.006)};
  const auto lefm       = coupling::run_lefm_growth(lefm_scene, lefm_prm.lefm_growth_settings(), std::cout);

  const auto d = coupling::trade_distance(gl.path, pd.path);
  std::cout << "global-local: " << geometry::to_text(gl.path) << " (" << gl.stop_reason << ")\nfull PD: "
            << geometry::to_text(pd.path) << " (" << pd.stop_reason << ")\nLEFM: " << geometry::to_text(lefm.path)
            << " (" << lefm.stop_reason << ")\n";
  test::metric("initiation.lpanel.vs_fullpd_mean_mm", 1e3 * d.mean);
  test::metric("initiation.lpanel.gl_vs_lefm_mean_mm", 1e3 * coupling::trade_distance(gl.path, lefm.path).mean);
  test::metric("initiation.lpanel.fullpd_vs_lefm_mean_mm", 1e3 * coupling::trade_distance(pd.path, lefm.path).mean);
  test::metric("initiation.lpanel.vs_fullpd_hausdorff_mm", 1e3 * d.hausdorff);
  test::metric("initiation.lpanel.coupled_over_fullpd_time", gl_seconds / pd_seconds);
  test::metric("initiation.lpanel.gl_mouth_from_corner_mm", 1e3 * geometry::norm(gl.path.front() - corner));
  test::metric("initiation.lpanel.fullpd_mouth_from_corner_mm", 1e3 * geometry::norm(pd.path.front() - corner));
  test::metric("initiation.lpanel.gl_crack_length_mm", 1e3 * geometry::length(gl.path));
  test::metric("initiation.lpanel.fullpd_crack_length_mm", 1e3 * geometry::length(pd.path));
  EXPECT_LT(geometry::norm(pd.path.front() - corner), 2. * pd_prm.pd.horizon);
}
