// The CSV writer and reader: a row of values and one of cells read back by column name, a quoted
// field with commas, a row cut short dropped, a number that is not finite an empty field (read
// back as NaN).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "csv.h"

namespace
{
  const std::string file = (std::filesystem::temp_directory_path() / "pumpd_csv_test.csv").string();
}

TEST(Csv, WrittenAndReadBack)
{
  {
    pumpd::CsvFile csv(file, "run,setting,seconds");
    csv.row("a", "\"m = 4\"", 1.5);
    csv.row({"b", "\"Horizon x 2, Minimum advance x 2\"", "2"});
  }
  std::ofstream(file, std::ios::app) << "c,\"cut"; // a row cut short
  const auto rows = pumpd::read_csv_rows(file);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("run"), "a");
  EXPECT_EQ(rows[0].at("setting"), "m = 4");
  EXPECT_EQ(rows[0].at("seconds"), "1.5");
  EXPECT_EQ(rows[1].at("setting"), "Horizon x 2, Minimum advance x 2");
  EXPECT_EQ(rows[1].at("seconds"), "2");
}

TEST(Csv, NoFileNoRows)
{
  EXPECT_TRUE(pumpd::read_csv_rows("/no/such/file.csv").empty());
}

TEST(Csv, NotFiniteIsAnEmptyField)
{
  {
    pumpd::CsvFile csv(file, "step,critical_load_factor,nan,K_I");
    csv.row(0, std::numeric_limits<double>::infinity(), std::nan(""), -2.5);
  }
  const auto rows = pumpd::read_csv_rows(file);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].at("critical_load_factor"), "");
  EXPECT_EQ(rows[0].at("nan"), "");
  EXPECT_TRUE(std::isnan(pumpd::csv_number(rows[0].at("critical_load_factor"))));
  EXPECT_EQ(pumpd::csv_number(rows[0].at("K_I")), -2.5);
}
