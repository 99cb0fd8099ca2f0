// The ladder of a study (coupling/ladder.h): its syntax, the entries it names, the values it makes.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "expect_invalid.h"
#include "ladder.h"
#include "parameter_table.h"

using namespace pumpd;
using namespace pumpd::coupling;

namespace
{
  /// The parameter table of a scene file with these lines (written to a temporary file).
  ParameterTable table_of(const std::string &text)
  {
    const std::string file = testing::TempDir() + "/ladder_test.prm";
    std::ofstream(file) << text;
    return ParameterTable::of_file(file);
  }

  const char *scene = "subsection Peridynamics\n  set Horizon = 0.004\nend\n"
                      "subsection Global\n  set Refinement levels near the tip = 2\nend\n";
} // namespace

TEST(Ladder, ReadsRungsAndTheirOverrides)
{
  const auto rungs = parse_ladder("half: Horizon x 0.5, Minimum advance x0.5; m4: Horizon over spacing = 4; "
                                  "finer: Refinement levels near the tip + 1; plain:",
                                  "Ladder");
  ASSERT_EQ(rungs.size(), 4u);
  EXPECT_EQ(rungs[0].name, "half");
  EXPECT_EQ(rungs[0].setting, "Horizon x 0.5, Minimum advance x0.5");
  ASSERT_EQ(rungs[0].overrides.size(), 2u);
  EXPECT_EQ(rungs[0].overrides[1].entry, "Minimum advance");
  EXPECT_EQ(rungs[0].overrides[1].operation, 'x');
  EXPECT_EQ(rungs[0].overrides[1].value, "0.5");
  EXPECT_EQ(rungs[1].overrides[0].operation, '=');
  EXPECT_EQ(rungs[2].overrides[0].operation, '+');
  EXPECT_TRUE(rungs[3].overrides.empty());
}

TEST(Ladder, RefusesARungWithoutANameOrAnOverrideOfNoForm)
{
  test::expect_invalid([] { parse_ladder("Horizon x 2", "Ladder"); }, "Ladder", "a rung is \"<name>: <override>");
  test::expect_invalid([] { parse_ladder("my rung: Horizon x 2", "Ladder"); }, "Ladder", "letters, digits");
  test::expect_invalid([] { parse_ladder("big: Horizon twice", "Ladder"); }, "Ladder", "is not an override");
}

TEST(Ladder, MakesTheValuesOfTheRung)
{
  const auto scene_table = table_of(scene);
  const auto rung        = parse_ladder("r: Horizon x 0.5, Refinement levels near the tip + 1, Box size = 0.05", "Ladder");
  const auto p           = apply(scene_table, rung[0], "global-local", "Ladder");
  EXPECT_EQ(p.get("Peridynamics/Horizon"), "0.002");
  EXPECT_EQ(p.get("Global/Refinement levels near the tip"), "3");
  EXPECT_EQ(p.get("Global-local/Box size"), "0.05");
  EXPECT_EQ(p.get("Method/Type"), "global-local");
  EXPECT_EQ(scene_table.get("Peridynamics/Horizon"), "0.004");
}

TEST(Ladder, LooksEntriesUpInTheSectionsOfTheRungsMethod)
{
  const auto scene_table = table_of(scene);
  // Maximum advance: of Global-local for the cycle, of Full PD for a full-PD rung.
  const auto cycle = apply(scene_table, parse_ladder("r: Maximum advance = 0.002", "Ladder")[0], "global-local", "Ladder");
  EXPECT_EQ(cycle.get("Global-local/Maximum advance"), "0.002");
  const auto full = apply(scene_table, parse_ladder("r: Type = full-pd, Maximum advance = 0.002", "Ladder")[0],
                          "global-local", "Ladder");
  EXPECT_EQ(full.get("Method/Type"), "full-pd");
  EXPECT_EQ(full.get("Full PD/Maximum advance"), "0.002");
  EXPECT_EQ(full.get("Global-local/Maximum advance"), scene_table.get("Global-local/Maximum advance"));
}

TEST(Ladder, RefusesAnUnknownAmbiguousOrNonNumericEntry)
{
  const auto scene_table = table_of(scene);
  const auto applied     = [&](const std::string &ladder) {
    return [&scene_table, ladder] { apply(scene_table, parse_ladder(ladder, "Ladder")[0], "global-local", "Ladder"); };
  };
  test::expect_invalid(applied("r: Horizon radius x 2"), "Ladder", "no entry named \"Horizon radius\"");
  // LEFM growth is not read by the cycle.
  test::expect_invalid(applied("r: Growth increment x 2"), "Ladder", "no entry named \"Growth increment\"");
  test::expect_invalid(applied("r: Displacement = top: uy = lambda"), "Ladder",
                       "\"Displacement\" is an entry of several sections (Scene/Boundary conditions/Displacement, "
                       "Scene/Report/Displacement)");
  test::expect_invalid(applied("r: Influence function x 2"), "Ladder", "is not a number");
  test::expect_invalid(applied("r: Global/Horizon = 1"), "Ladder", "no entry \"Global/Horizon\"");
}

TEST(ParameterTable, WritesASceneFileThatReadsBackTheSame)
{
  const auto        scene_table = table_of(scene);
  const std::string text        = scene_table.text("Study");
  EXPECT_EQ(text.find("subsection Study"), std::string::npos);
  EXPECT_NE(text.find("subsection Peridynamics\n"), std::string::npos);
  EXPECT_NE(text.find("  set Horizon = 0.004\n"), std::string::npos);
  EXPECT_EQ(table_of(text).text("Study"), text);
}
