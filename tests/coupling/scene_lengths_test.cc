// The length defaults derived from a scene (coupling/scene_lengths.h, derive_lengths in
// parameters.h): the rule on given lengths, the lengths measured on a scene, the decks' lengths at
// the decks' horizon, and which entries keep their values (the file's, the code's, all of them
// under Length defaults = absolute).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "parameter_table.h"
#include "parameters.h"
#include "scene_file.h"
#include "scene_lengths.h"

using namespace pumpd;

namespace
{
  const std::string beam = "tests/regression/ingraffea-case2-coarse.prm";

  std::string text_of(const std::string &file)
  {
    std::ifstream      in(file);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
} // namespace

TEST(SceneLengths, PreferredNumbersRoundDown)
{
  EXPECT_DOUBLE_EQ(coupling::preferred_below(1.5625e-3), 1.5e-3);
  EXPECT_DOUBLE_EQ(coupling::preferred_below(6.35e-3), 6e-3);
  EXPECT_DOUBLE_EQ(coupling::preferred_below(1e-3), 1e-3);
  EXPECT_DOUBLE_EQ(coupling::preferred_below(0.96e-3), 0.8e-3);
  EXPECT_DOUBLE_EQ(coupling::preferred_below(0.0999), 0.08);
}

TEST(SceneLengths, TheRuleTakesTheLeastOfItsBounds)
{
  // A compact-tension specimen 48 mm high, a 20 mm crack, pin holes of 4 mm radius.
  coupling::SceneLengths ct;
  ct.body_side    = 0.048;
  ct.crack_length = 0.020;
  ct.hole_radius  = 0.004;
  const auto delta = coupling::scene_horizon(ct);
  EXPECT_DOUBLE_EQ(delta.value, 1.5e-3); // L / 32 = 1.5 mm: the box (12 mm) a quarter of the side
  EXPECT_EQ(delta.bound, "L / 32");
  const auto da = coupling::scene_growth_increment(ct);
  EXPECT_DOUBLE_EQ(da.value, 0.8e-3); // L / 50 = 0.96 mm, below a / 10 = R / 2 = 2 mm
  EXPECT_EQ(da.bound, "L / 50");
  // A short crack in a large plate: its length bounds both.
  coupling::SceneLengths plate;
  plate.body_side    = 0.5;
  plate.crack_length = 0.008;
  EXPECT_DOUBLE_EQ(coupling::scene_horizon(plate).value, 2e-3);
  EXPECT_EQ(coupling::scene_horizon(plate).bound, "a / 4");
  EXPECT_DOUBLE_EQ(coupling::scene_growth_increment(plate).value, 0.8e-3);
  EXPECT_EQ(coupling::scene_growth_increment(plate).bound, "a / 10");
  // A hole smaller than the crack: half its radius.
  plate.hole_radius = 0.001;
  EXPECT_DOUBLE_EQ(coupling::scene_growth_increment(plate).value, 0.5e-3);
  EXPECT_EQ(coupling::scene_growth_increment(plate).bound, "R / 2");
}

TEST(SceneLengths, MeasuredOnTheIngraffeaBeam)
{
  const auto p      = test::scene_file(beam, "");
  const auto scene  = coupling::build_scene(p.scene);
  const auto l      = coupling::measure_lengths(scene);
  EXPECT_NEAR(l.body_side, 0.2032, 1e-9);   // 8 in high
  EXPECT_NEAR(l.crack_length, 0.0254, 1e-9); // an edge crack of 1 in
  EXPECT_NEAR(l.hole_radius, 0.00635, 1e-5); // holes 0.5 in across (the mesh's polygon's arcs)
  EXPECT_NEAR(l.tip_clearance, 0.0254, 1e-9); // the bottom edge, below the tip
  EXPECT_GT(l.tip_cell, 0.008);               // the cell of the 16 mm mesh at the tip
  EXPECT_LT(l.tip_cell, 0.032);
}

// At the decks' horizon (4 mm, which the beam's scene sets) the rule gives the decks' lengths:
// the defaults of the settings structs, the Ingraffea decks' absolute values.
TEST(SceneLengths, AtTheDecksHorizonTheRuleGivesTheDecksLengths)
{
  auto                   p     = test::scene_file(beam, "");
  const auto             scene = coupling::build_scene(p.scene);
  const coupling::Parameters decks;
  std::ostringstream     out;
  coupling::derive_lengths(p, scene, &out);
  EXPECT_EQ(p.pd.horizon, 0.004);
  EXPECT_DOUBLE_EQ(p.cycle.box.size, decks.cycle.box.size);
  EXPECT_DOUBLE_EQ(p.cycle.box.margin, decks.cycle.box.margin);
  EXPECT_DOUBLE_EQ(p.cycle.box.max_size, decks.cycle.box.max_size);
  EXPECT_DOUBLE_EQ(p.cycle.exchange.max_advance, decks.cycle.exchange.max_advance);
  EXPECT_DOUBLE_EQ(p.cycle.exchange.min_advance, decks.cycle.exchange.min_advance);
  EXPECT_DOUBLE_EQ(p.cycle.exchange.near_distance, decks.cycle.exchange.near_distance);
  EXPECT_DOUBLE_EQ(p.global.tip_radius, decks.global.tip_radius);
  EXPECT_DOUBLE_EQ(p.global.refinement_radius, decks.global.refinement_radius);
  EXPECT_DOUBLE_EQ(p.global.refinement_trail, decks.global.refinement_trail);
  EXPECT_NE(out.str().find("lengths from the scene (L = 203 mm, a = 25.4 mm"), std::string::npos) << out.str();
}

// An entry the file sets keeps its value, and so does one code changed from its default; under
// Length defaults = absolute every entry keeps its default.
TEST(SceneLengths, TheFileAndTheCodeWinOverTheRule)
{
  std::string text = text_of(beam);
  // Without the file's horizon the rule's: L / 32 = 6.35 mm, a / 4 = 6.35 mm, so 6 mm.
  const std::string horizon = "  set Horizon              = 0.004\n";
  ASSERT_NE(text.find(horizon), std::string::npos);
  text.erase(text.find(horizon), horizon.size());
  const auto scene = coupling::build_scene(coupling::parse_parameters(text).scene);

  auto derived = coupling::parse_parameters(text);
  coupling::derive_lengths(derived, scene);
  EXPECT_DOUBLE_EQ(derived.pd.horizon, 0.006);
  EXPECT_DOUBLE_EQ(derived.cycle.box.size, 0.048);
  EXPECT_DOUBLE_EQ(derived.global.tip_radius, 0.009);

  auto with_box = coupling::parse_parameters(text + "subsection Global-local\n  set Box size = 0.05\nend\n");
  with_box.global.tip_radius = 0.007;
  coupling::derive_lengths(with_box, scene);
  EXPECT_DOUBLE_EQ(with_box.pd.horizon, 0.006);
  EXPECT_DOUBLE_EQ(with_box.cycle.box.size, 0.05);      // the file's
  EXPECT_DOUBLE_EQ(with_box.global.tip_radius, 0.007);  // the code's
  EXPECT_DOUBLE_EQ(with_box.cycle.box.margin, 0.012);   // the rule's, from the rule's horizon

  auto absolute = coupling::parse_parameters(text + "subsection Scene\n  set Length defaults = absolute\nend\n");
  coupling::derive_lengths(absolute, scene);
  const coupling::Parameters decks;
  EXPECT_EQ(absolute.pd.horizon, decks.pd.horizon);
  EXPECT_EQ(absolute.cycle.box.size, decks.cycle.box.size);
  EXPECT_EQ(absolute.lefm.growth_increment, decks.lefm.growth_increment);
}

// A study writes each run's scene file from the table of the scene's: a length the scene derives
// stays out of it (derived again in the run) until a rung sets it.
TEST(SceneLengths, AStudyRunsFileLeavesTheDerivedLengthsUnset)
{
  auto table = coupling::ParameterTable::of_file(beam);
  EXPECT_TRUE(table.is_set("Peridynamics/Horizon"));
  EXPECT_FALSE(table.is_set("Global-local/Box size"));
  EXPECT_NE(table.text("Study").find("set Horizon = 0.004"), std::string::npos);
  EXPECT_EQ(table.section("Global-local").find("set Box size"), std::string::npos);
  EXPECT_NE(table.section("Global-local").find("set Box tip position"), std::string::npos); // not a length of the rule
  table.set("Global-local/Box size", "0.048");
  EXPECT_NE(table.section("Global-local").find("set Box size = 0.048"), std::string::npos);
  EXPECT_TRUE(coupling::parse_parameters(table.text("Study")).cycle.scene_file.is_set("Global-local/Box size"));
}
