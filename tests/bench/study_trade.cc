// Speed against accuracy on Ingraffea Case II: `pumpd --study
// prm/ingraffea-case2.prm` (the scene's section Study: LEFM growth, the cycle at the default and
// at twelve settings, full PD at horizons 8 and 4 mm, the reference), then its trade.csv,
// trade.md and trade.png copied into docs/. Runs done by an earlier study of the same program are
// reused (out/ingraffea-case2-study/runs.csv); delete that folder to run everything again. The
// study prints trade.coupled_over_fullpd_time, trade.coupled_vs_fullpd_mean_dev_mm,
// trade.coupled_over_lefm_time and trade.lefm_vs_coupled_mean_dev_mm; this test adds the full-PD
// convergence trade.fullpd_path_change_delta8_vs_4_mm and checks that every run ended and that the
// default lies within 1 mm (mean) of full PD.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "csv.h"
#include "metric.h"

TEST(StudyTrade, CaseTwoDefaultWithinOneMillimetreOfFullPd)
{
  const std::string directory = "out/ingraffea-case2-study";
  const std::string command   = std::string(PUMPD_EXECUTABLE) + " --study prm/ingraffea-case2.prm";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  for (const char *file : {"trade.csv", "trade.md", "trade.png"})
    std::filesystem::copy_file(directory + "/" + file, std::string("docs/") + file,
                               std::filesystem::copy_options::overwrite_existing);

  for (auto &row : pumpd::read_csv_rows(directory + "/trade.csv"))
    {
      EXPECT_EQ(row["status"], "ok") << row["run"];
      if (row["run"] == "fullpd-delta8")
        pumpd::test::metric("trade.fullpd_path_change_delta8_vs_4_mm", std::stod(row["mean_vs_fullpd_mm"]));
      if (row["run"] == "default")
        {
          EXPECT_LE(std::stod(row["mean_vs_fullpd_mm"]), 1.);
        }
    }
}
