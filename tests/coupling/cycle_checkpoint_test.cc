// The cycle checkpoint (coupling/cycle_checkpoint.h) round-trips exactly and refuses files that
// are missing, not cycle checkpoints, or damaged (one flipped bit).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "cycle_checkpoint.h"

using namespace pumpd::coupling;

namespace
{
  CycleState example()
  {
    CycleState s;
    s.scene       = 0xfedcba9876543210ull;
    s.exchanges   = 17;
    s.finished    = true;
    s.cracks      = {{{0.1016, 0.}, {0.1016, 0.0254}, {0.10184914583, 0.02683101623}}, {{0.3, 0.}, {0.3, 0.01}}};
    s.refinements = {{{0.1016, 0.0254}, 2}, {{0.10184914583, 0.02683101623}, 3}};
    s.ends        = {{{{0.07, 0.01, 0.09, 0.03}}, 0.95, 0, true},
                     {{{0.0855, 0.0155, 0.118, 0.048}, {0.0905, 0.0265, 0.123, 0.059}}, 1.0999999999999999, 1, false},
                     {},
                     {{{0.29, 0., 0.31, 0.02}}, 1.05, -1, false}}; // a doubled box
    s.entries = {{"Scene/Material/Young's modulus", "2.4e9"}, {"Scene/Displacement", "top: uy = 1e-3 * lambda"}};
    s.outputs = {{"load_steps.csv", 1847}, {"global.pvd", 6}};
    return s;
  }
} // namespace

TEST(CycleCheckpoint, RoundTripIsExact)
{
  const auto dir = std::filesystem::temp_directory_path() / "pumpd_cycle_checkpoint_test";
  std::filesystem::create_directories(dir);
  const CycleState  s    = example();
  const std::string file = (dir / "checkpoint.h5").string();
  write_cycle_checkpoint(file, s);
  const auto r = read_cycle_checkpoint(file);
  EXPECT_EQ(r.scene, s.scene);
  EXPECT_EQ(r.exchanges, s.exchanges);
  EXPECT_EQ(r.finished, s.finished);
  ASSERT_EQ(r.ends.size(), s.ends.size());
  for (std::size_t e = 0; e < s.ends.size(); ++e)
    {
      EXPECT_EQ(r.ends[e].load_factor, s.ends[e].load_factor);
      EXPECT_EQ(r.ends[e].halvings, s.ends[e].halvings);
      EXPECT_EQ(r.ends[e].stopped, s.ends[e].stopped);
      ASSERT_EQ(r.ends[e].boxes.size(), s.ends[e].boxes.size());
      if (!s.ends[e].boxes.empty())
        {
          EXPECT_EQ(r.ends[e].boxes.back().y_max, s.ends[e].boxes.back().y_max);
        }
    }
  ASSERT_EQ(r.cracks.size(), s.cracks.size());
  for (std::size_t c = 0; c < s.cracks.size(); ++c)
    {
      ASSERT_EQ(r.cracks[c].size(), s.cracks[c].size());
      for (std::size_t k = 0; k < s.cracks[c].size(); ++k)
        {
          EXPECT_EQ(r.cracks[c][k].x, s.cracks[c][k].x);
          EXPECT_EQ(r.cracks[c][k].y, s.cracks[c][k].y);
        }
    }
  ASSERT_EQ(r.refinements.size(), 2u);
  EXPECT_EQ(r.refinements[1].at.y, s.refinements[1].at.y);
  EXPECT_EQ(r.refinements[1].levels, 3u);
  EXPECT_EQ(r.entries, s.entries);
  EXPECT_EQ(r.outputs, s.outputs);
  std::filesystem::remove_all(dir);
}

// One bit of the tip's x flipped in the file: refused, naming the file, not resumed from a tip
// elsewhere.
TEST(CycleCheckpoint, RefusesAFlippedBit)
{
  const auto dir = std::filesystem::temp_directory_path() / "pumpd_cycle_checkpoint_flipped";
  std::filesystem::create_directories(dir);
  const CycleState  s    = example();
  const std::string file = (dir / "checkpoint.h5").string();
  write_cycle_checkpoint(file, s);
  std::ifstream in(file, std::ios::binary);
  std::string   bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  in.close();
  const double tip_x = s.cracks[0].back().x;
  const auto   at    = bytes.find(std::string(reinterpret_cast<const char *>(&tip_x), sizeof(tip_x)));
  ASSERT_NE(at, std::string::npos);
  bytes[at] ^= 1;
  std::ofstream(file, std::ios::binary) << bytes;
  try
    {
      read_cycle_checkpoint(file);
      ADD_FAILURE() << "a damaged checkpoint was read";
    }
  catch (const std::runtime_error &e)
    {
      EXPECT_EQ(std::string(e.what()),
                "cycle checkpoint: " + file + ": its contents do not match their checksum: the file is damaged");
    }
  std::filesystem::remove_all(dir);
}

TEST(CycleCheckpoint, RefusesMissingOrForeignFiles)
{
  EXPECT_THROW(read_cycle_checkpoint("/nonexistent/checkpoint.h5"), std::runtime_error);
  const auto file = (std::filesystem::temp_directory_path() / "pumpd_not_a_checkpoint.h5").string();
  std::ofstream(file) << "not hdf5\n";
  EXPECT_THROW(read_cycle_checkpoint(file), std::runtime_error);
  std::filesystem::remove(file);
}
