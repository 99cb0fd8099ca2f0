// run_program: exit status, signal, a program that cannot start, its output in the log, stdin
// from /dev/null; last_line; program_version (the build ID, else the bytes).
#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "program.h"

namespace
{
  const std::string log_file = (std::filesystem::temp_directory_path() / "pumpd_program_test.log").string();
}

TEST(RunProgram, ExitStatusAndOutput)
{
  const auto run = pumpd::run_program({"sh", "-c", "echo first; echo second >&2; echo; exit 3"}, log_file);
  EXPECT_EQ(run.start_error, 0);
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_EQ(run.signal, 0);
  EXPECT_GT(run.peak_memory, 0.);
  EXPECT_EQ(pumpd::last_line(log_file), "second");
}

TEST(RunProgram, ReadsNothingFromStdin)
{
  EXPECT_EQ(pumpd::run_program({"/bin/sh", "-c", "cat"}, log_file).exit_code, 0);
}

TEST(RunProgram, KilledBySignal)
{
  const auto run = pumpd::run_program({"/bin/sh", "-c", "kill -9 $$"}, log_file);
  EXPECT_EQ(run.exit_code, -1);
  EXPECT_EQ(run.signal, 9);
}

TEST(RunProgram, KilledAtItsTimeLimit)
{
  const auto run = pumpd::run_program({"/bin/sh", "-c", "sleep 30"}, log_file, 0.2);
  EXPECT_TRUE(run.timed_out);
  EXPECT_EQ(run.signal, 9);
}

TEST(RunProgram, WithinItsTimeLimit)
{
  const auto run = pumpd::run_program({"/bin/sh", "-c", "exit 4"}, log_file, 30.);
  EXPECT_FALSE(run.timed_out);
  EXPECT_EQ(run.exit_code, 4);
}

TEST(RunProgram, NotStarted)
{
  const auto run = pumpd::run_program({"/no/such/program"}, log_file);
  EXPECT_EQ(run.start_error, ENOENT);
  EXPECT_EQ(run.exit_code, -1);
}

TEST(RunProgram, LogNotWritable)
{
  EXPECT_THROW(pumpd::run_program({"true"}, "/no/such/directory/log"), std::runtime_error);
}

TEST(LastLine, NoneInAnEmptyFile)
{
  std::ofstream(log_file) << " \n\t\n";
  EXPECT_EQ(pumpd::last_line(log_file), "");
  EXPECT_EQ(pumpd::last_line("/no/such/file"), "");
}

TEST(ProgramVersion, TheBuildIdOfAnElfExecutable)
{
  const std::string self = pumpd::this_executable();
  const auto        run =
    pumpd::run_program({"sh", "-c", "command -v readelf >/dev/null && readelf -n '" + self + "' | sed -n 's/.*Build ID: //p'"},
                       log_file);
  ASSERT_EQ(run.exit_code, 0) << "readelf (binutils) not found";
  const std::string build_id = pumpd::last_line(log_file);
  ASSERT_EQ(build_id.size(), 40u) << "this test program has no SHA-1 build ID (CMakeLists.txt links with --build-id=sha1)";
  EXPECT_EQ(pumpd::program_version(self), build_id);
}

TEST(ProgramVersion, TheBytesOfAnyOtherFile)
{
  std::ofstream(log_file) << "#!/bin/sh\necho version 1\n";
  const std::string first = pumpd::program_version(log_file);
  EXPECT_EQ(first.size(), 16u);
  EXPECT_EQ(pumpd::program_version(log_file), first);
  std::ofstream(log_file) << "#!/bin/sh\necho version 2\n";
  EXPECT_NE(pumpd::program_version(log_file), first);
  EXPECT_EQ(pumpd::program_version("/no/such/program"), "");
}
