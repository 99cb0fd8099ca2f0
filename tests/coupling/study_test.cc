// pumpd --study (coupling/study.h) on a coarse study of the SENT scene
// (tests/coupling/study/sent-coarse.prm: LEFM growth, the cycle at m = 4 and at m = 3 and 5): the
// table has every run, the recommended setting lies within the tolerance of the finest run, the
// scene is meshed once; the same study again reuses every run and meshes nothing; a run missing from runs.csv (a study interrupted while it
// ran) is run again, and only it.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "csv.h"
#include "metric.h"

namespace
{
  const std::string scene     = "tests/coupling/study/sent-coarse.prm";
  const std::string directory = "out/study-sent/study";

  /// Runs the study, its output into out/study-sent/study.log (its trade.* metrics are the SENT
  /// scene's, not the Case II ones the study label reads); its wall time [s].
  double study()
  {
    const std::string log     = "out/study-sent/study.log";
    std::filesystem::create_directories("out/study-sent");
    const auto        t0      = std::chrono::steady_clock::now();
    const auto        command = std::string(PUMPD_EXECUTABLE) + " --study " + scene + " > " + log + " 2>&1";
    const int         status  = std::system(command.c_str());
    const double      seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::ifstream     in(log);
    EXPECT_EQ(status, 0) << command << "\n" << in.rdbuf();
    return seconds;
  }
} // namespace

TEST(Study, CoarseSentStudyRecommendsWithinTheToleranceAndReusesItsRuns)
{
  std::filesystem::remove_all(directory);
  const double first = study();
  auto         rows  = pumpd::read_csv_rows(directory + "/trade.csv");
  ASSERT_EQ(rows.size(), 4u);
  const std::vector<std::string> names = {"lefm", "default", "m3", "m5"};
  int                            recommended = 0;
  for (std::size_t i = 0; i < rows.size(); ++i)
    {
      EXPECT_EQ(rows[i]["run"], names[i]);
      EXPECT_EQ(rows[i]["status"], "ok") << rows[i]["run"];
      EXPECT_EQ(rows[i]["reused"], "no") << rows[i]["run"];
      EXPECT_FALSE(rows[i]["mean_vs_finest_mm"].empty()) << rows[i]["run"];
      EXPECT_FALSE(rows[i]["peak_load"].empty()) << rows[i]["run"];
      if (rows[i]["recommended"] == "yes")
        {
          ++recommended;
          EXPECT_LE(std::stod(rows[i]["mean_vs_finest_mm"]), 1.) << "tolerance: 1 mm";
        }
    }
  EXPECT_EQ(recommended, 1);
  EXPECT_TRUE(std::filesystem::exists(directory + "/trade.md"));
  EXPECT_TRUE(std::filesystem::exists(directory + "/trade.png"));
  // The study and its four runs mesh the scene once: one mesh in the study's cache.
  const auto meshes = [] {
    std::vector<std::pair<std::string, std::filesystem::file_time_type>> m;
    for (const auto &entry : std::filesystem::directory_iterator(directory + "/meshes"))
      m.emplace_back(entry.path().filename().string(), entry.last_write_time());
    return m;
  };
  const auto meshed = meshes();
  EXPECT_EQ(meshed.size(), 1u);

  const double second = study();
  EXPECT_EQ(meshes(), meshed) << "the same study again meshes nothing";
  for (auto &row : pumpd::read_csv_rows(directory + "/trade.csv"))
    EXPECT_EQ(row["reused"], "yes") << row["run"];
  pumpd::test::metric("study.first_seconds", first);
  pumpd::test::metric("study.reuse_time_fraction", second / first);

  // An interruption while lefm ran: runs.csv without its row.
  std::vector<std::string> lines;
  {
    std::ifstream in(directory + "/runs.csv");
    for (std::string line; std::getline(in, line);)
      if (line.rfind("lefm,", 0) != 0)
        lines.push_back(line);
  }
  std::ofstream out(directory + "/runs.csv");
  for (const auto &line : lines)
    out << line << "\n";
  out.close();
  study();
  for (auto &row : pumpd::read_csv_rows(directory + "/trade.csv"))
    EXPECT_EQ(row["reused"], row["run"] == "lefm" ? "no" : "yes") << row["run"];
}
