// The global-local cycle as a whole on the coarse Case II scene (tests/regression/: the Case I-III
// paths are regression tests there): every output a user looks at is written, one row per
// exchange, the loads are chosen by the code; and an interrupted run resumes bit for bit.
// PD spacing m = 4 here (h = 1 mm, delta = 4 mm) to keep it short.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "global_local.h"
#include "path_metrics.h"
#include "scene_file.h"

using namespace pumpd;
using namespace pumpd::coupling;

namespace
{
  coupling::Parameters coarse(const std::string &output, unsigned int exchanges)
  {
    auto p                          = test::scene_file("tests/regression/ingraffea-case2-coarse.prm", output);
    p.pd.horizon_over_spacing       = 4;
    p.cycle.max_exchanges           = exchanges;
    p.cycle.resolution.kink_tolerance = 0.; // no kink halving (resolution.h): the boxes' horizons are the clearance rule's
    return p;
  }

  GlobalLocalResult run(const coupling::Parameters &p)
  {
    std::ostringstream log;
    const auto         r = run_global_local(build_scene(p.scene), p.global_local_settings(), log);
    std::cout << log.str();
    return r;
  }

  /// The run of `exchanges` exchanges of the parameters `make(output, exchanges)`, and the same
  /// run stopped after `resumed_after` and resumed.
  template <typename Make>
  std::pair<GlobalLocalResult, GlobalLocalResult> whole_and_resumed(const Make &make, const std::string &output,
                                                                    unsigned int exchanges, unsigned int resumed_after)
  {
    auto whole = run(make(output + "_whole", exchanges));
    auto part  = make(output + "_part", resumed_after);
    run(part);
    part.cycle.max_exchanges = exchanges;
    part.cycle.resume        = true;
    return {std::move(whole), run(part)};
  }

  void expect_same_boxes_and_path(const GlobalLocalResult &a, const GlobalLocalResult &b)
  {
    ASSERT_EQ(a.boxes.size(), b.boxes.size());
    for (std::size_t k = 0; k < a.boxes.size(); ++k)
      {
        EXPECT_EQ(a.boxes[k].x_min, b.boxes[k].x_min) << k;
        EXPECT_EQ(a.boxes[k].y_max, b.boxes[k].y_max) << k;
      }
    ASSERT_EQ(a.path.size(), b.path.size());
    for (std::size_t k = 0; k < a.path.size(); ++k)
      {
        EXPECT_EQ(a.path[k].x, b.path[k].x) << k;
        EXPECT_EQ(a.path[k].y, b.path[k].y) << k;
      }
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

// Three exchanges: every output file, a row per exchange and per box, the loads chosen by the
// code (G = G_c at the tip, then PD needs a moderate overload: 0.9 to 3 lambda_c).
TEST(GlobalLocal, OutputsAndLoads)
{
  const auto p = coarse("global_local_outputs", 3);
  const auto r = run(p);
  const auto dir = p.scene.output_directory;
  for (const char *f : {"crack_path.csv", "boxes.csv", "load_steps.csv", "load_displacement.csv", "global.pvd",
                        "pd.pvd", "checkpoint.h5", "body.csv", "reference_path.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
  ASSERT_EQ(r.exchanges.size(), 3u);
  EXPECT_EQ(lines(dir + "/load_steps.csv"), r.exchanges.size() + 1);
  EXPECT_EQ(lines(dir + "/load_displacement.csv"), r.exchanges.size() + 1);
  EXPECT_EQ(lines(dir + "/boxes.csv"), r.boxes.size() + 1);
  for (const auto &e : r.exchanges)
    {
      EXPECT_GE(e.load_factor, 0.9);
      EXPECT_LE(e.load_factor, 3.);
      // The scene reports lambda (N/m: the point force is -lambda) and the load point's deflection.
      EXPECT_EQ(e.load, e.lambda);
      EXPECT_GT(e.displacement, 0.);
    }
}

// Resume: 3 exchanges, then resumed to 5, gives the same crack as 5 uninterrupted exchanges
// (bit for bit: the mesh refinement is replayed from the checkpoint).
TEST(GlobalLocal, ResumedRunMatchesTheUninterruptedOne)
{
  const auto [a, b] = whole_and_resumed(coarse, "global_local", 5, 3);
  ASSERT_EQ(a.path.size(), b.path.size());
  for (std::size_t k = 0; k < a.path.size(); ++k)
    {
      EXPECT_EQ(a.path[k].x, b.path[k].x) << k;
      EXPECT_EQ(a.path[k].y, b.path[k].y) << k;
    }
  EXPECT_EQ(b.exchanges.size(), 2u);
}

// The same with every box at half the horizon (Clearance over horizon at its largest, 20: no
// clearance in the beam holds 20 horizons of 4 mm), resumed after 2 exchanges: the third keeps
// the halved box of the second in the uninterrupted run, and so must the resumed one.
TEST(GlobalLocal, ResumedRunWithHalvedBoxesMatchesTheUninterruptedOne)
{
  const auto halved = [](const std::string &output, unsigned int exchanges) {
    auto p                                    = coarse(output, exchanges);
    p.cycle.resolution.clearance_over_horizon = 20.;
    return p;
  };
  const auto [a, b] = whole_and_resumed(halved, "global_local_halved", 5, 2);
  ASSERT_EQ(a.exchanges.size(), 5u);
  for (const auto &e : a.exchanges)
    EXPECT_EQ(e.horizon, 0.5 * halved("", 1).pd.horizon);
  ASSERT_GE(a.boxes.size(), 3u);
  EXPECT_EQ(a.boxes[2].x_min, a.boxes[1].x_min); // kept: the case this test is about
  expect_same_boxes_and_path(a, b);
}

// Every box at twice the horizon where the coarse Case I beam (no holes) leaves room for it
// (Maximum doublings = 1): the tip starts 25.4 mm above the bottom edge, more than 3 doubled
// horizons, so the first exchanges run in boxes of 8 mm horizon and 64 mm side. Resumed after 2
// exchanges, the run continues in them as the uninterrupted one, bit for bit.
TEST(GlobalLocal, ResumedRunWithDoubledBoxesMatchesTheUninterruptedOne)
{
  const auto doubled = [](const std::string &output, unsigned int exchanges) {
    auto p                           = test::scene_file("tests/regression/ingraffea-case1-coarse.prm", output);
    p.cycle.max_exchanges            = exchanges;
    p.cycle.resolution.max_doublings = 1;
    p.cycle.resolution.kink_tolerance = 0.; // the first box is the doubling's, not the kink's (resolution.h)
    return p;
  };
  const auto [a, b] = whole_and_resumed(doubled, "global_local_doubled", 4, 2);
  const auto p      = doubled("", 1);
  ASSERT_EQ(a.exchanges.size(), 4u);
  for (const auto &e : a.exchanges)
    EXPECT_EQ(e.horizon, 2. * p.pd.horizon);
  // Each box at least the doubled side (less a spacing of its lattice either side), more where it
  // reaches out to the outline.
  for (const auto &box : a.boxes)
    EXPECT_GE(std::min(box.width(), box.height()), 2. * p.cycle.box.size - 4. * p.pd.spacing());
  ASSERT_GE(a.boxes.size(), 3u);
  EXPECT_EQ(a.boxes[2].x_min, a.boxes[1].x_min); // kept across the resume
  expect_same_boxes_and_path(a, b);
}

// Cracks that meet (prm/beam-t-junction.prm: the coarse Case I beam, m = 8): the notch below a
// horizontal interior crack 21 mm above its tip grows up into that crack's face and joins it (its
// trace ends on the face);
// the body stays whole, so the cycle goes on, and the interior crack's right tip, now wedged open
// by the notch (K_II / K_I about -0.8: a kink of about 50 degrees), grows from the junction-enriched
// solution in every exchange after the join. Resumed after the join (the checkpoint holds
// polylines: the junction is found again), the run continues as the uninterrupted one, bit for bit.
TEST(GlobalLocal, TheOtherCrackGrowsAfterAJoinAndAResumedRunFindsTheJunction)
{
  const auto t_scene = [](const std::string &output, unsigned int exchanges) {
    auto p                = test::scene_file("prm/beam-t-junction.prm", output);
    p.cycle.max_exchanges = exchanges;
    return p;
  };
  const auto a = run(t_scene("global_local_t_whole", 8));
  ASSERT_EQ(a.paths.size(), 2u);
  const auto &notch = a.paths[0], &interior = a.paths[1];
  EXPECT_LT(distance_to_polyline(notch.back(), interior), 1e-9) << "the notch ends on the interior crack's face";
  std::size_t joined_at = 0, after = 0;
  bool        joined    = false;
  for (const auto &e : a.exchanges)
    if (e.crack == 0 && e.advance > 0.)
      {
        joined_at = e.exchange;
        joined    = true;
      }
  for (const auto &e : a.exchanges)
    after += e.crack == 1 && e.exchange > joined_at && e.advance > 0.;
  ASSERT_TRUE(joined);
  EXPECT_GE(after, 2u) << "the interior crack grows after the join";
  EXPECT_GT(geometry::length(interior), 0.06 + 2. * 0.004);

  auto part = t_scene("global_local_t_part", joined_at + 2);
  run(part);
  part.cycle.max_exchanges = 8;
  part.cycle.resume        = true;
  const auto b             = run(part);
  ASSERT_EQ(b.paths.size(), 2u);
  for (std::size_t c = 0; c < 2; ++c)
    {
      ASSERT_EQ(a.paths[c].size(), b.paths[c].size()) << c;
      for (std::size_t k = 0; k < a.paths[c].size(); ++k)
        {
          EXPECT_EQ(a.paths[c][k].x, b.paths[c][k].x) << c << ", " << k;
          EXPECT_EQ(a.paths[c][k].y, b.paths[c][k].y) << c << ", " << k;
        }
    }
}

// A tip that starts half a horizon below another crack's face (the T-junction scene, the notch's
// tip 2 mm below the interior crack): the first PD state's ridge reaches the face, an advance
// shorter than the minimum, and the tip joins that crack there rather than wait for a longer one
// that cannot come. Joined, it has no box in the next exchange.
TEST(GlobalLocal, ATipHalfAHorizonBelowAnotherCracksFaceJoinsIt)
{
  auto p                 = test::scene_file("prm/beam-t-junction.prm", "global_local_t_near");
  p.scene.initial_cracks = "0.1016,0; 0.1016,0.0444 | 0.07,0.0464; 0.13,0.0464";
  p.cycle.max_exchanges  = 2;
  p.cycle.resolution.kink_tolerance = 0.; // the first box at the scene's horizon: its ridge reaches the face
  const auto r           = run(p);
  ASSERT_GE(r.exchanges.size(), 1u);
  EXPECT_EQ(r.exchanges[0].crack, 0u);
  EXPECT_EQ(r.exchanges[0].decision, "accept");
  EXPECT_EQ(r.exchanges[0].substeps, 1u);
  EXPECT_NEAR(r.exchanges[0].advance, 0.002, 0.5 * p.pd.spacing());
  for (const auto &e : r.exchanges)
    EXPECT_FALSE(e.exchange == 1 && e.crack == 0) << "the joined tip grows no more";
  ASSERT_EQ(r.paths.size(), 2u);
  EXPECT_LT(distance_to_polyline(r.paths[0].back(), r.paths[1]), 1e-9) << "the notch ends on the interior crack's face";
}

// A doubled box keeps 3 doubled horizons from the other cracks' faces: in the T-junction scene
// the notch's tip is 25.4 mm above the bottom edge (room for 3 horizons of 8 mm) but its doubled
// path, 24 mm long, comes within 21 mm of the interior crack, so the first box keeps 4 mm.
TEST(GlobalLocal, ADoubledBoxKeepsItsClearanceFromTheOtherCracks)
{
  auto p                           = test::scene_file("prm/beam-t-junction.prm", "");
  p.cycle.max_exchanges            = 1;
  p.cycle.resolution.max_doublings = 1;
  p.cycle.resolution.kink_tolerance = 0.; // the first box is the clearance rule's, not the kink's
  const auto r                     = run(p);
  ASSERT_GE(r.exchanges.size(), 1u);
  EXPECT_EQ(r.exchanges[0].horizon, p.pd.horizon);
}
