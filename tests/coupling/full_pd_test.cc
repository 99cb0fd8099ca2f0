// The full-domain PD beam (scene full-pd, coupling/full_pd.h), coarse enough for CI: the crack
// starts at the notch and grows upwards (more than 1 cm, its end in the upper half-plane of the
// initial tip); the outputs are written; crack-mouth-opening control traces the snap-back that
// load-point control jumps; bad input is refused naming the parameter. The L-panel without a
// crack cracks at its corner, and its elastic state is in equilibrium (the XFEM's stiffness). The
// unnotched beam cracks up its mid-span to the pad's no-fail zone. A crack that forms inside the
// Brazilian disc is traced through its centre and stops the run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "error.h"
#include "expect_invalid.h"
#include "full_pd.h"
#include "global_problem.h"
#include "metric.h"
#include "scene_file.h"

using namespace pumpd;
using pumpd::test::expect_invalid;
using namespace pumpd::coupling;

namespace
{
  /// A coarse beam: delta = 8 mm, m = 2 (h = 4 mm, ~6300 nodes), a deeper notch than Case II's
  /// (K at the notch rises faster than the bending stress elsewhere: at this coarse horizon the PD
  /// strength ~K_c / sqrt(pi delta) is low and a shallow notch would lose to the top fibre);
  /// no-fail zones of 5 horizons (4 cm) around the supports and the pad.
  coupling::Parameters coarse(const std::string &output = "")
  {
    auto p                         = test::scene_file("prm/ingraffea-case2-fullpd.prm", output);
    p.pd.horizon                   = 0.008;
    p.pd.horizon_over_spacing      = 2;
    p.pd.tolerance                 = 1e-8;
    p.scene.initial_cracks         = "0.1016,0; 0.1016,0.0508";
    p.scene.reference_path         = "";
    p.full_pd.no_fail_horizons     = 5.;
    p.full_pd.max_advance          = 0.;
    p.full_pd.max_steps            = 150;
    p.full_pd.stall_steps          = 4;
    p.full_pd.output_interval      = 1000;
    return p;
  }

  FullPdResult run_case(const coupling::Parameters &p, std::ostream &log)
  {
    return run_full_pd(build_scene(p.scene), p.full_pd_settings(), log);
  }

  /// The coarse beam under the default control (crack-mouth opening), run once for the tests that
  /// read it, its outputs in the temporary directory.
  const FullPdResult &mouth_controlled_run()
  {
    static const FullPdResult result = [] {
      std::ostringstream log;
      auto               r = run_case(coarse("full_pd_test"), log);
      std::cout << log.str();
      return r;
    }();
    return result;
  }
} // namespace

TEST(FullPd, CrackGrowsUpwardsFromTheNotch)
{
  const auto        p                = coarse();
  const std::string output_directory = (std::filesystem::temp_directory_path() / "pumpd_full_pd_test").string();
  const auto       &r                = mouth_controlled_run();

  const geometry::Polyline initial{{0.1016, 0.}, {0.1016, 0.0508}};
  const auto               tip0   = initial.back();
  const auto               end    = r.path.back();
  const double             growth = geometry::length(r.path) - geometry::length(initial);
  std::cout << "stop: " << r.stop_reason << "; growth " << growth << " m, end (" << end.x << ", " << end.y << ")\n";
  EXPECT_GT(growth, 0.01);
  EXPECT_GT(end.y - tip0.y, 0.) << "the crack ends in the upper half-plane of the initial tip";
  for (std::size_t k = initial.size(); k < r.path.size(); ++k)
    EXPECT_GE(r.path[k].y, tip0.y - 0.5 * p.pd.spacing()) << "vertex " << k << " below the tip";
  EXPECT_GT(r.nodes, 5000u);
  EXPECT_GT(r.node_steps, 0.);
  for (const char *file : {"crack_path.csv", "load_steps.csv", "load_displacement.csv", "body.csv", "pd.pvd"})
    EXPECT_TRUE(std::filesystem::exists(output_directory + "/" + file)) << file;
  std::ifstream steps(output_directory + "/load_steps.csv");
  std::string   header;
  std::getline(steps, header);
  EXPECT_EQ(header.rfind("step,control_displacement_m,crack_mouth_opening_m,lambda,load,displacement,crack_length_m", 0), 0u)
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
  const double length0 = 0.0508;

  auto by_load                = coarse();
  by_load.full_pd.control     = "load point";
  by_load.full_pd.stall_steps = 1;
  const auto load_run         = run_case(by_load, log);

  const auto  by_mouth  = coarse();
  const auto &mouth_run = mouth_controlled_run();

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
  EXPECT_LT(largest_step, 2. * by_mouth.pd.horizon);
  EXPECT_GT(first_growth(load_run, length0), 2. * first_growth(mouth_run, length0));
}

// Bad input: a value outside its pattern is refused by the parameter file (each named; the bad
// scene files of tests/coupling/bad_prm), the checks across entries and against the scene here.
TEST(FullPd, BadInputIsRefused)
{
  std::ostringstream log;
  const auto         run_with = [&](const std::function<void(coupling::Parameters &)> &change) {
    return [&log, change] {
      auto p = coarse();
      change(p);
      run_case(p, log);
    };
  };
  expect_invalid(run_with([](auto &p) { p.full_pd.support_radius = 0.2; }), "Support radius",
                 "in [0, half the body's smaller side]");
  expect_invalid(run_with([](auto &p) { p.full_pd.max_increment = 0.001; }), "Maximum increment",
                 "[Minimum increment, 1]");
  expect_invalid(run_with([](auto &p) { p.full_pd.first_increment = 0.2; }), "First increment",
                 "[Minimum increment, Maximum increment]");
  expect_invalid(run_with([](auto &p) { p.full_pd.max_advance = 0.001; }), "Maximum advance",
                 "at least the target advance");
  expect_invalid(run_with([](auto &p) { p.full_pd.gauge_distance = 0.2; }), "Gauge distance",
                 "[0, a quarter of the body's width]");
  expect_invalid(run_with([](auto &p) { p.scene.traction = "top: ty = -lambda"; }), "Traction",
                 "tractions cannot be applied");
  expect_invalid(run_with([](auto &p) { p.scene.displacement += "; left: ux = lambda * 1e-4"; }), "Point force",
                 "not both or several forces");
  expect_invalid(run_with([](auto &p) { p.scene.material.poisson_ratio = 0.35; }), "Poisson's ratio",
                 "bond-based peridynamics has nu = 1/4 in plane strain");
  expect_invalid(run_with([](auto &p) { p.scene.initial_cracks = "0.2,0.05; 0.2,0.1"; }), "Control",
                 "crack-mouth control needs a crack with a mouth");
  // A support radius below a spacing could miss the lattice; so could gauges closer than that.
  expect_invalid(run_with([](auto &p) { p.full_pd.support_radius = 0.001; p.full_pd.no_fail_horizons = 0.; }),
                 "Support radius", "must be 0 or at least the PD spacing");
  expect_invalid(run_with([](auto &p) { p.full_pd.gauge_distance = 0.001; }), "Gauge distance",
                 "must be 0 or at least the PD spacing");
}

// The L-panel without a pre-crack (prm/l-panel-initiation.prm) at delta = 16 mm, m = 2 (h = 8 mm,
// ~2900 nodes): full PD forms its own crack, traced from the boundary point nearest the most damaged
// node there (full_pd.h). Its mouth lies within a horizon of the re-entrant corner, the crack grows
// to the left, into the panel, and not down into the held leg. Once it has formed, the steps are
// taken in the opening of its mouth (the default control): gauges are placed across it, the opening
// rises at every step, every state relaxes to equilibrium, and the crack grows on from the length
// it formed with.
TEST(FullPd, WithoutACrackTheLPanelCracksAtItsCorner)
{
  auto p                    = test::scene_file("prm/l-panel-initiation.prm", "full_pd_lpanel");
  p.pd.horizon              = 0.016;
  p.pd.horizon_over_spacing = 2;
  p.full_pd.max_steps       = 60;
  p.full_pd.output_interval = 1000;
  std::ostringstream log;
  const auto         r = run_case(p, log);
  std::cout << log.str();
  const geometry::Point corner{0.25, 0.25};
  ASSERT_GE(r.path.size(), 2u);
  const double mouth_err = geometry::norm(r.path.front() - corner) / p.pd.horizon;
  std::cout << "path " << geometry::to_text(r.path) << " (" << r.stop_reason << ")\n";
  test::metric("fullpd.lpanel.mouth_from_corner_over_delta", mouth_err);
  EXPECT_LE(mouth_err, 1.);
  EXPECT_LT(r.path.back().x, corner.x - 2. * p.pd.horizon);
  EXPECT_GE(r.path.back().y, corner.y - p.pd.horizon);

  const auto formed =
    std::find_if(r.steps.begin(), r.steps.end(), [](const FullPdStep &st) { return st.crack_length > 0.; });
  ASSERT_NE(formed, r.steps.end());
  ASSERT_GT(r.steps.end() - formed, 2);
  EXPECT_GT(formed->mouth_opening, 0.);
  for (auto st = formed + 1; st != r.steps.end(); ++st)
    {
      EXPECT_GT(st->mouth_opening, (st - 1)->mouth_opening) << "step " << st->step;
      EXPECT_TRUE(st->converged) << "step " << st->step;
    }
  EXPECT_GT(r.steps.back().crack_length, formed->crack_length + 2. * p.pd.horizon);
}

// The unnotched beam (prm/unnotched-beam.prm: depth 5 cm, span 40 cm, a pad at mid-span on the top
// edge) at delta = 8 mm, m = 4 (h = 2 mm, 5500 nodes), bonds linear in compression: the crack forms
// at mid-span on the bottom edge and runs straight up, within the state it forms in, to the pad's
// no-fail zone, where the run stops and says so. Ten horizons would put the whole depth under
// mid-span in that zone; the radius is held to a quarter of the beam's depth, 12.5 mm.
TEST(FullPd, AnUnnotchedBeamCracksUpItsMidSpanToThePad)
{
  auto p                    = test::scene_file("prm/unnotched-beam.prm", "");
  p.method                  = "full-pd";
  p.pd.horizon              = 0.008;
  p.pd.horizon_over_spacing = 4;
  p.pd.compression          = "linear";
  p.full_pd.max_steps       = 60;
  std::ostringstream log;
  const auto         r = run_case(p, log);
  std::cout << log.str();
  const double mid_span = 0.22, depth = 0.05, no_fail_radius = 0.25 * depth;
  ASSERT_GE(r.path.size(), 2u);
  std::cout << "path " << geometry::to_text(r.path) << " (" << r.stop_reason << ")\n";
  test::metric("fullpd.beam.mouth_from_mid_span_over_delta", std::abs(r.path.front().x - mid_span) / p.pd.horizon);
  EXPECT_LE(std::abs(r.path.front().x - mid_span), 0.5 * p.pd.horizon);
  EXPECT_EQ(r.path.front().y, 0.);
  for (const auto &x : r.path)
    EXPECT_LE(std::abs(x.x - mid_span), 0.5 * p.pd.horizon) << geometry::to_text(x);
  EXPECT_NE(r.stop_reason.find("no-fail zone of load"), std::string::npos) << r.stop_reason;
  EXPECT_GE(r.path.back().y, depth - no_fail_radius - p.pd.horizon);
}

// The Brazilian disc (prm/brazilian-disc.prm) in full PD at delta = 4 mm, m = 4 (h = 1 mm), its
// arcs pressed together by displacement (full PD takes no tractions): the tension across the loaded
// diameter breaks the disc inside, away from its rim, before the largest displacement. That crack
// has no mouth: it is traced both ways from its most damaged node, through the centre, where the
// tension is largest, and the run goes on, tracing it from its two tips, until it stops for one
// of the run's reasons (on the disc the ridge forks towards the arcs' ends: crack branching).
TEST(FullPd, ACrackFormedInsideTheDiscIsTracedOnFromItsTips)
{
  auto p                     = test::scene_file("prm/brazilian-disc.prm", "");
  p.method                   = "full-pd";
  p.scene.traction           = "";
  p.scene.displacement       = "top arc: uy = -1e-4 * lambda; bottom arc: uy = 1e-4 * lambda; west: ux = 0";
  p.pd.horizon               = 0.004;
  p.full_pd.control          = "load point";
  p.full_pd.max_displacement = 1e-3;
  std::ostringstream log;
  const auto         r = run_case(p, log);
  std::cout << log.str();
  ASSERT_TRUE(r.interior_crack);
  const auto formed = std::find_if(r.steps.begin(), r.steps.end(), [](const auto &st) { return st.crack_length > 0.; });
  ASSERT_NE(formed, r.steps.end());
  EXPECT_LT(formed + 1, r.steps.end()) << "the run goes on after the crack formed";
  EXPECT_EQ(r.stop_reason.find("a crack formed inside the body"), std::string::npos) << r.stop_reason;
  EXPECT_LT(r.steps.back().displacement, p.full_pd.max_displacement) << r.stop_reason;
  const double radius = 0.05;
  EXPECT_LT(std::abs(r.interior_crack->x), 0.25 * radius) << "the tension lies across the loaded diameter";
  ASSERT_GE(r.path.size(), 3u);
  const auto site = std::find_if(r.path.begin(), r.path.end(), [&](const geometry::Point &x) {
    return geometry::norm(x - *r.interior_crack) < 1e-12;
  });
  ASSERT_NE(site, r.path.end()) << "the trace passes through the place it formed";
  EXPECT_GT(geometry::length({r.path.begin(), site + 1}), p.pd.spacing()) << "traced one way";
  EXPECT_GT(geometry::length({site, r.path.end()}), p.pd.spacing()) << "traced the other way";
  double from_centre = radius;
  for (std::size_t k = 0; k + 1 < r.path.size(); ++k)
    from_centre = std::min(from_centre, geometry::distance_to_segment({0., 0.}, r.path[k], r.path[k + 1]));
  test::metric("fullpd.disc.crack_from_centre_over_delta", from_centre / p.pd.horizon);
  test::metric("fullpd.disc.crack_length_mm", 1e3 * geometry::length(r.path));
  EXPECT_LT(from_centre, p.pd.horizon);
  EXPECT_GT(geometry::length(r.path), 4. * p.pd.horizon);
}

// The L-panel's first, elastic state against the global problem: full PD of the whole panel at
// delta = 8 mm, m = 2 (h = 4 mm, 125 spacings across, ~11 700 nodes) under the scene's load-point
// displacement, relaxed to equilibrium (full_pd.h, "Equilibrium"). Its stiffness at the load point,
// fy / uy, is the uncracked XFEM's within 15 % (a pad of one horizon against a mesh vertex). A state
// relaxed to the scene's box tolerance alone (1e-5) has its bending mode far from equilibrium: the
// panel is then about three times as stiff, its corner stress too high, and the crack leaves the
// corner too early and too steeply.
TEST(FullPd, TheLPanelsElasticStateIsInEquilibrium)
{
  auto p                    = test::scene_file("prm/l-panel-initiation.prm", "");
  p.pd.horizon              = 0.008;
  p.pd.horizon_over_spacing = 2;
  p.full_pd.max_steps       = 1;
  const auto         scene = build_scene(p.scene);
  std::ostringstream log;
  const auto         r = run_full_pd(scene, p.full_pd_settings(), log);
  std::cout << log.str();
  ASSERT_EQ(r.steps.size(), 1u);
  const double pd_stiffness = r.steps.front().load / r.steps.front().reported_displacement;

  GlobalProblem global(scene, p.global);
  global.solve_uncracked();
  const auto [load, displacement] = global.report();
  const double ratio              = pd_stiffness / (load / displacement);
  test::metric("fullpd.lpanel.elastic_stiffness_over_xfem", ratio);
  EXPECT_NEAR(ratio, 1., 0.15);
}
