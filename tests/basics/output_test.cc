// What the writers of a run's files share (basics/output.h): a write that fails names the file
// and the cause and leaves no partial file; a CSV row that does not reach the disk stops the run;
// a reserved output directory is locked by the first file written into it, again by the same
// process at will, and refused to another process with its pid.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "csv.h"
#include "error.h"
#include "output.h"
#include "vtu.h"

using namespace pumpd;

namespace
{
  namespace fs = std::filesystem;

  fs::path fresh_directory(const std::string &name)
  {
    const auto dir = fs::temp_directory_path() / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
  }

  /// The message of the exception `f` throws ("" if none).
  template <class F>
  std::string message_of(F f)
  {
    try
      {
        f();
      }
    catch (const std::exception &e)
      {
        return e.what();
      }
    return "";
  }
} // namespace

TEST(Output, AFailedWriteNamesTheFileAndTheCause)
{
  // A folder that is a file: the file cannot be created.
  const std::string path = (fresh_directory("pumpd_output_test_a") / "plain" / "x.vtu").string();
  std::ofstream(fs::path(path).parent_path()) << "a file\n";
  VtuGrid grid;
  grid.points = {0., 0.};
  grid.add_cell(0, 1, 1);
  EXPECT_EQ(message_of([&] { write_vtu(path, grid); }), "cannot write " + path + ": Not a directory");
}

TEST(Output, AWriteAsideThatFailsLeavesNothing)
{
  const auto        dir  = fresh_directory("pumpd_output_test_b");
  const std::string path = (dir / "series.pvd").string();
  EXPECT_EQ(message_of([&] { write_aside(path, [](std::ostream &) { throw std::runtime_error("interrupted"); }); }),
            "interrupted");
  EXPECT_TRUE(fs::is_empty(dir));
  write_aside(path, [](std::ostream &out) { out << "complete\n"; });
  EXPECT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(partial_of(path)));
}

TEST(Output, ACsvRowOnAFullDiskStopsTheRun)
{
  // /dev/full takes the file and fails every write with ENOSPC: the header's already.
  EXPECT_EQ(message_of([] { CsvFile("/dev/full", "a,b"); }), "cannot write /dev/full: No space left on device");
}

TEST(Output, AReservedDirectoryIsLockedByItsFirstFile)
{
  const auto        dir  = fresh_directory("pumpd_output_test_c");
  const std::string lock = (dir / ".pumpd.lock").string();
  reserve_output_directory("Scene / Output directory", dir.string());
  EXPECT_FALSE(fs::exists(lock)); // reserved: nothing written yet
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t other = fork();
  if (other == 0)
    {
      // Another process: waits until this one holds the lock, then claims the directory.
      char c;
      close(ready[1]);
      if (read(ready[0], &c, 1) != 1)
        _exit(2);
      reserve_output_directory("Scene / Output directory", dir.string());
      const std::string refused = message_of([&] { CsvFile((dir / "rows.csv").string(), "a"); });
      const std::string expected = "Scene / Output directory = " + dir.string() + ": another pumpd (pid " +
                                   std::to_string(getppid()) + ") writes there: wait for it to end, or give another folder";
      _exit(refused == expected ? 0 : 1);
    }
  close(ready[0]);
  CsvFile first((dir / "rows.csv").string(), "a");
  CsvFile again((dir / "more.csv").string(), "b"); // the same process: its lock already
  std::string pid;
  std::ifstream(lock) >> pid;
  EXPECT_EQ(pid, std::to_string(getpid()));
  ASSERT_EQ(write(ready[1], "x", 1), 1);
  int status = 0;
  ASSERT_EQ(waitpid(other, &status, 0), other);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the other process was not refused as expected";
  // A sub-directory is another directory: not locked by this one's lock.
  fs::create_directories(dir / "run");
  EXPECT_NO_THROW(CsvFile((dir / "run" / "rows.csv").string(), "a"));
}
