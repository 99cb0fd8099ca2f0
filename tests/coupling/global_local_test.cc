// Coarse versions of the Ingraffea cases through the whole global-local cycle (regressions, each
// well under 3 minutes): PD spacing m = 4 (h = 1 mm, delta = 4 mm), global mesh size 16 mm
// (8 mm in the crack band, 2 mm at the tip). The full-resolution runs are prm/ingraffea-case*.prm
// and the study `study_coupling`. Tolerances are stated where they are asserted.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "beam_scene.h"
#include "global_local.h"
#include "metric.h"
#include "path_metrics.h"

using namespace pumpd;
using namespace pumpd::coupling;

namespace
{
  const std::string source = PUMPD_SOURCE_DIR;

  GlobalLocalParameters coarse(int case_number, const std::string &output)
  {
    GlobalLocalParameters p;
    p.mesh_file     = source + (case_number == 1 ? "/meshes/ingraffea-beam.geo" : "/meshes/ingraffea-beam-holes.geo");
    p.mesh_size     = 0.016;
    p.initial_crack = case_number == 3 ? geometry::Polyline{{0.127, 0.}, {0.127, 0.0381}}
                                       : geometry::Polyline{{0.1016, 0.}, {0.1016, 0.0254}};
    p.material.youngs_modulus  = 2.4e9;
    p.material.fracture_energy = 500.;
    p.horizon                  = 0.004;
    p.horizon_ratio            = 4;
    p.output_directory         = output;
    if (case_number < 3)
      p.published_path = source + "/data/published-paths/case" + std::to_string(case_number) + "-pum-pd-64-loadstep100.csv";
    return p;
  }

  std::string output_directory(const std::string &name)
  {
    const auto dir = std::filesystem::temp_directory_path() / ("pumpd_global_local_test_" + name);
    std::filesystem::remove_all(dir);
    return dir.string();
  }

  std::size_t lines(const std::string &file)
  {
    std::ifstream in(file);
    std::size_t   n = 0;
    for (std::string line; std::getline(in, line);)
      ++n;
    return n;
  }
} // namespace

// Case II: the crack leaves the initial tip towards the load, passes the lower hole and ends at
// the middle one, along the full-PD path (data/reference-paths/case2-fullpd.csv: the converged
// path of the trade study). Here at m = 8: at m = 4 on this coarse global mesh the PD crack
// follows the lattice's vertical rows for 20 mm and passes left of the middle hole. Measured:
// 0.5 mm mean, 2.2 mm Hausdorff from full PD. Regression bounds: mean < 1 mm, Hausdorff < 3 mm
// (the default resolution is 0.52 mm from full PD, the finest coupled run 1.28 mm). The published
// PUM-PD path is further from full PD (4.5 mm): its distance is printed, not asserted.
TEST(GlobalLocal, CaseTwoCoarseFollowsTheFullPdPathIntoTheMiddleHole)
{
  std::ostringstream log;
  const auto         dir = output_directory("case2");
  auto               p   = coarse(2, dir);
  p.horizon_ratio        = 8;
  const auto r           = run_global_local(p, log);
  const auto reference   = read_path(source + "/data/reference-paths/case2-fullpd.csv");
  const auto full_pd     = published_distance(r.path, reference, 1e-4);
  std::cout << log.str();
  EXPECT_NE(r.stop_reason.find("reached the hole at (0.1524, 0.12065)"), std::string::npos) << r.stop_reason;
  EXPECT_LT(full_pd.mean, 0.001);
  EXPECT_LT(full_pd.hausdorff, 0.003);
  test::metric("coupling.case2_coarse.fullpd_mean_dev_mm", 1e3 * full_pd.mean);
  test::metric("coupling.case2_coarse.fullpd_hausdorff_mm", 1e3 * full_pd.hausdorff);
  test::metric("coupling.case2_coarse.mean_dev_mm", 1e3 * r.published_mean);
  test::metric("coupling.case2_coarse.hausdorff_mm", 1e3 * r.published_hausdorff);
  // Every output a user looks at, one row per exchange / box.
  for (const char *f : {"crack_path.csv", "boxes.csv", "load_steps.csv", "global.pvd", "pd.pvd", "checkpoint.h5",
                        "body.csv", "reference_path.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
  EXPECT_EQ(lines(dir + "/load_steps.csv"), r.exchanges.size() + 1);
  EXPECT_EQ(lines(dir + "/boxes.csv"), r.boxes.size() + 1);
  // The load is chosen by the code: G = G_c at the tip, then PD needs a moderate overload.
  for (const auto &e : r.exchanges)
    {
      EXPECT_GE(e.load_factor, 0.9);
      EXPECT_LE(e.load_factor, 3.);
    }
}

// Case I (no holes), up to where the published path ends (y = 0.14). Our path curves less
// towards the load point than the published one, and more so the closer the cycle comes to full
// PD on Case II (README): at this resolution mean 10.7 mm, Hausdorff 27 mm from the published
// path. No converged Case I reference exists here, so this is a regression only: the measured
// coarse values plus 25 %.
TEST(GlobalLocal, CaseOneCoarseRegressionAgainstThePublishedPath)
{
  std::ostringstream log;
  auto               p = coarse(1, output_directory("case1"));
  p.max_crack_length   = 0.16; // past the published path's end
  const auto r         = run_global_local(p, log);
  std::cout << log.str();
  EXPECT_LT(r.published_mean, 1.25 * 0.0107);
  EXPECT_LT(r.published_hausdorff, 1.25 * 0.0274);
  test::metric("coupling.case1_coarse.mean_dev_mm", 1e3 * r.published_mean);
  test::metric("coupling.case1_coarse.hausdorff_mm", 1e3 * r.published_hausdorff);
}

// Case III: the longer crack nearer the holes. No published path; the crack must end cleanly at
// a hole (at this resolution the middle one), and the exchange controller must have shortened
// the advance near the holes.
TEST(GlobalLocal, CaseThreeCoarseEndsAtAHole)
{
  std::ostringstream log;
  const auto         r = run_global_local(coarse(3, output_directory("case3")), log);
  std::cout << log.str();
  EXPECT_NE(r.stop_reason.find("reached the hole"), std::string::npos) << r.stop_reason;
  // Within the near distance (8 mm) of a hole the advance per exchange is halved (4 mm); the
  // last exchange, which arrives, may add the ligament of up to a horizon to the hole.
  const geometry::Point holes[] = {{0.1524, 0.06985}, {0.1524, 0.12065}, {0.1524, 0.17145}};
  ASSERT_FALSE(r.exchanges.empty());
  EXPECT_LE(r.exchanges.back().advance, 0.004 + 0.004 + 1e-9);
  for (std::size_t n = 0; n + 1 < r.exchanges.size(); ++n)
    for (const auto &c : holes)
      if (geometry::norm(r.exchanges[n].tip - c) - 0.00635 < 0.008 - 1e-4)
        {
          EXPECT_LE(r.exchanges[n].advance, 0.004 + 1e-9) << "exchange " << n;
        }
  test::metric("coupling.case3_coarse.tip_x_mm", 1e3 * r.path.back().x);
  test::metric("coupling.case3_coarse.tip_y_mm", 1e3 * r.path.back().y);
}

// Resume: 3 exchanges, then resumed to 5, gives the same crack as 5 uninterrupted exchanges
// (bit for bit: the mesh refinement is replayed from the checkpoint).
TEST(GlobalLocal, ResumedRunMatchesTheUninterruptedOne)
{
  std::ostringstream log;
  auto               whole = coarse(2, output_directory("whole"));
  whole.max_exchanges      = 5;
  const auto a             = run_global_local(whole, log);
  auto       part          = coarse(2, output_directory("part"));
  part.max_exchanges       = 3;
  run_global_local(part, log);
  part.max_exchanges = 5;
  part.resume        = true;
  const auto b       = run_global_local(part, log);
  ASSERT_EQ(a.path.size(), b.path.size());
  for (std::size_t k = 0; k < a.path.size(); ++k)
    {
      EXPECT_EQ(a.path[k].x, b.path[k].x) << k;
      EXPECT_EQ(a.path[k].y, b.path[k].y) << k;
    }
  EXPECT_EQ(b.exchanges.size(), 2u);
}
