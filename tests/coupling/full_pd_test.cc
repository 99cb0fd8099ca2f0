// The full-domain PD beam (scene full-pd, coupling/full_pd.h), coarse enough for CI: the crack
// starts at the notch and grows upwards (more than 1 cm, its end in the upper half-plane of the
// initial tip); the outputs are written; crack-mouth-opening control traces the snap-back that
// load-point control jumps; bad input is refused naming the parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "error.h"
#include "expect_invalid.h"
#include "full_pd.h"
#include "metric.h"

using namespace pumpd;
using pumpd::test::expect_invalid;
using namespace pumpd::coupling;

namespace
{
  /// A coarse beam: delta = 8 mm, m = 2 (h = 4 mm, ~6300 nodes), a deeper notch than Case II's
  /// (K at the notch rises faster than the bending stress elsewhere: at this coarse horizon the PD
  /// strength ~K_c / sqrt(pi delta) is low and a shallow notch would lose to the top fibre).
  FullPdParameters coarse()
  {
    FullPdParameters p;
    p.horizon          = 0.008;
    p.horizon_ratio    = 2;
    p.tolerance        = 1e-8;
    p.initial_crack    = {{0.1016, 0.}, {0.1016, 0.0508}};
    p.max_steps        = 150;
    p.stall_steps      = 4;
    p.output_interval  = 1000;
    return p;
  }

  /// The coarse beam under the default control (crack-mouth opening), run once for the tests that
  /// read it, its outputs in the temporary directory.
  const FullPdResult &mouth_controlled_run()
  {
    static const FullPdResult result = [] {
      FullPdParameters p = coarse();
      p.output_directory = (std::filesystem::temp_directory_path() / "pumpd_full_pd_test").string();
      std::filesystem::remove_all(p.output_directory);
      std::ostringstream log;
      auto               r = run_full_pd(p, log);
      std::cout << log.str();
      return r;
    }();
    return result;
  }
} // namespace

TEST(FullPd, CrackGrowsUpwardsFromTheNotch)
{
  const FullPdParameters p = coarse();
  const std::string      output_directory =
    (std::filesystem::temp_directory_path() / "pumpd_full_pd_test").string();
  const auto &r = mouth_controlled_run();

  const auto   tip0   = p.initial_crack.back();
  const auto   end    = r.path.back();
  const double growth = geometry::length(r.path) - geometry::length(p.initial_crack);
  std::cout << "stop: " << r.stop_reason << "; growth " << growth << " m, end (" << end.x << ", " << end.y << ")\n";
  EXPECT_GT(growth, 0.01);
  EXPECT_GT(end.y - tip0.y, 0.) << "the crack ends in the upper half-plane of the initial tip";
  for (std::size_t k = p.initial_crack.size(); k < r.path.size(); ++k)
    EXPECT_GE(r.path[k].y, tip0.y - 0.5 * p.horizon / p.horizon_ratio) << "vertex " << k << " below the tip";
  EXPECT_GT(r.nodes, 5000u);
  EXPECT_GT(r.node_steps, 0.);
  for (const char *file : {"crack_path.csv", "load_steps.csv", "body.csv", "pd.pvd"})
    EXPECT_TRUE(std::filesystem::exists(output_directory + "/" + file)) << file;
  std::ifstream steps(output_directory + "/load_steps.csv");
  std::string   header;
  std::getline(steps, header);
  EXPECT_EQ(header.rfind("step,load_point_displacement_m,crack_mouth_opening_m,load_N_per_m,crack_length_m", 0), 0u)
    << header;
  test::metric("fullpd.test_growth_m", growth);
}

// Crack-mouth-opening control against load-point control on the coarse beam. Under load-point
// displacement the first state with growth jumps far (the load-displacement curve snaps back, and
// dynamic relaxation lands on a distant state); under crack-mouth control the opening rises at
// every step, the traced path turns back in the load-point displacement (the snap-back), and no
// step grows the crack by more than two horizons.
TEST(FullPd, CrackMouthControlTracesTheSnapBack)
{
  std::ostringstream log;
  const auto         first_growth = [](const FullPdResult &r, double length0) {
    for (const auto &st : r.steps)
      if (st.crack_length > length0 + 1e-9)
        return st.crack_length - length0;
    return 0.;
  };
  const double length0 = geometry::length(coarse().initial_crack);

  FullPdParameters by_load = coarse();
  by_load.control          = FullPdParameters::Control::load_point;
  by_load.stall_steps      = 1;
  const auto load_run      = run_full_pd(by_load, log);

  const FullPdParameters by_mouth  = coarse();
  const auto            &mouth_run = mouth_controlled_run();

  double largest_step = 0., previous_length = length0;
  bool   turned_back  = false;
  for (std::size_t k = 1; k < mouth_run.steps.size(); ++k)
    {
      const auto &a = mouth_run.steps[k - 1], &b = mouth_run.steps[k];
      EXPECT_GT(b.mouth_opening, a.mouth_opening) << "step " << b.step;
      turned_back = turned_back || (b.displacement < a.displacement && b.crack_length > a.crack_length);
      if (b.crack_length > previous_length)
        largest_step = std::max(largest_step, b.crack_length - previous_length);
      previous_length = std::max(previous_length, b.crack_length);
    }
  std::cout << "first growth: load-point control " << 1e3 * first_growth(load_run, length0)
            << " mm, crack-mouth control " << 1e3 * first_growth(mouth_run, length0) << " mm; largest step "
            << 1e3 * largest_step << " mm; steps " << load_run.steps.size() << " and " << mouth_run.steps.size()
            << "\n";
  EXPECT_TRUE(turned_back) << "the load-point displacement never decreased while the crack grew";
  EXPECT_GT(previous_length - length0, 0.01);
  EXPECT_LT(largest_step, 2. * by_mouth.horizon);
  EXPECT_GT(first_growth(load_run, length0), 2. * first_growth(mouth_run, length0));
}

TEST(FullPd, BadInputIsRefused)
{
  std::ostringstream log;
  const auto         run = [&](const std::function<void(FullPdParameters &)> &change) {
    return [&log, change] {
      FullPdParameters p = coarse();
      change(p);
      run_full_pd(p, log);
    };
  };
  expect_invalid(run([](auto &p) { p.outline = {0., 0., 0., 0.2}; }), "Beam outline", "positive width and height");
  expect_invalid(run([](auto &p) { p.holes = {{{0.6, 0.1}, 0.01}}; }), "Holes", "inside the beam outline");
  expect_invalid(run([](auto &p) { p.holes = {{{0.2, 0.1}, 0.}}; }), "Holes", "radius > 0");
  expect_invalid(run([](auto &p) { p.initial_crack = {{0.1, 0.}}; }), "Initial crack", "at least 2 points");
  expect_invalid(run([](auto &p) { p.initial_crack = {{0.6, 0.}, {0.6, 0.02}}; }), "Initial crack", "inside the beam outline");
  expect_invalid(run([](auto &p) { p.load_point = {0.254, 0.3}; }), "Load point", "on or inside the beam outline");
  expect_invalid(run([](auto &p) { p.support_radius = -0.001; }), "Support radius", "in [0, half the beam's smaller side]");
  expect_invalid(run([](auto &p) { p.support_radius = 0.01, p.no_fail_radius = 0.005; }), "No-fail radius",
                 "[Support radius, half the beam's smaller side]");
  expect_invalid(run([](auto &p) { p.horizon = 0.; }), "Horizon", "> 0");
  expect_invalid(run([](auto &p) { p.horizon_ratio = 1; }), "Horizon over spacing", ">= 2");
  expect_invalid(run([](auto &p) { p.crack_damage = 0.99; }), "Crack damage threshold", "[0.05, 0.95]");
  expect_invalid(run([](auto &p) { p.onset_stretch_ratio = 1.5; }), "Onset stretch ratio", "[0.001, 1]");
  expect_invalid(run([](auto &p) { p.min_increment = 0.; }), "Minimum increment", "[1e-6, 1]");
  expect_invalid(run([](auto &p) { p.max_increment = 0.001; }), "Maximum increment", "[Minimum increment, 1]");
  expect_invalid(run([](auto &p) { p.first_increment = 0.2; }), "First increment",
                 "[Minimum increment, Maximum increment]");
  expect_invalid(run([](auto &p) { p.target_advance = -1.; }), "Target advance", ">= 0 m");
  expect_invalid(run([](auto &p) { p.max_advance = 0.001; }), "Maximum advance", "at least the target advance");
  expect_invalid(run([](auto &p) { p.max_displacement = 0.; }), "Maximum displacement", "> 0");
  expect_invalid(run([](auto &p) { p.max_steps = 0; }), "Maximum steps", ">= 1");
  expect_invalid(run([](auto &p) { p.stall_steps = 0; }), "Stall steps", ">= 1");
  expect_invalid(run([](auto &p) { p.hole_margin = 0.2; }), "Hole margin", "[0, 0.1] m");
  expect_invalid(run([](auto &p) { p.output_interval = 0; }), "Output interval", ">= 1");
  expect_invalid(run([](auto &p) { p.servo_gain = 0.; }), "Servo gain", "[1e-6, 1]");
  expect_invalid(run([](auto &p) { p.gauge_distance = 0.2; }), "Gauge distance", "[0, a quarter of the beam's width]");
  expect_invalid(run([](auto &p) { p.published_path = "no-such-path.csv"; }), "Published path", "cannot be opened");
  // A support region that holds no node: the pin off the body's material (inside a hole).
  expect_invalid(run([](auto &p) { p.pin = {0.1524, 0.12065}; p.support_radius = 0.002; p.no_fail_radius = 0.; }),
                 "Pin support", "holds no PD node");
}
