// The CSV writer and reader: a row of values and one of cells read back by column name, a quoted
// field with commas, a row cut short dropped.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

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
