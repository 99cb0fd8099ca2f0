// run_program: exit status, signal, a program that cannot start, its output in the log, stdin
// from /dev/null, its heartbeat, a signal to this process passed on to it; last_line;
// program_version (the build ID, else the bytes).
#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

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

TEST(RunProgram, HeartbeatWhileItRuns)
{
  std::vector<double>      ticks;
  std::vector<std::string> seen;
  const pumpd::Heartbeat   heartbeat{0.3, [&](double seconds) {
                                      ticks.push_back(seconds);
                                      seen.push_back(pumpd::last_line(log_file));
                                    }};
  const auto run = pumpd::run_program({"/bin/sh", "-c", "echo working; sleep 1"}, log_file, 0., heartbeat);
  EXPECT_EQ(run.exit_code, 0);
  // About 1 s / 0.3 s ticks, each at least its interval after the one before, the log readable.
  ASSERT_GE(ticks.size(), 2u);
  EXPECT_LE(ticks.size(), 4u);
  for (std::size_t k = 0; k < ticks.size(); ++k)
    {
      EXPECT_GE(ticks[k], 0.3 * double(k + 1));
      EXPECT_EQ(seen[k], "working");
    }
}

// The program sends SIGTERM to this process: it is passed on to the program (which ends by it,
// before its sleep is over) and the wait ends with Interrupted; this process lives on.
TEST(RunProgram, SignalPassedOnAndReportedAsInterrupted)
{
  const auto t0 = std::chrono::steady_clock::now();
  try
    {
      pumpd::run_program({"/bin/sh", "-c", "kill -TERM $PPID; sleep 30"}, log_file);
      FAIL() << "no Interrupted";
    }
  catch (const pumpd::Interrupted &interrupted)
    {
      EXPECT_EQ(interrupted.signal, SIGTERM);
      EXPECT_EQ(interrupted.what(), "SIGTERM while waiting for /bin/sh (passed on to it; it has ended)");
    }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10.);
  // The handler is gone with the wait: SIGTERM's own action is back.
  struct sigaction now = {};
  ::sigaction(SIGTERM, nullptr, &now);
  EXPECT_EQ(now.sa_handler, SIG_DFL);
}

// Under a time limit the program has a process group of its own: a signal reaches what it started.
TEST(RunProgram, SignalReachesWhatTheProgramStarted)
{
  const std::string pid_file = log_file + ".pid";
  std::filesystem::remove(pid_file);
  EXPECT_THROW(pumpd::run_program({"/bin/sh", "-c", "sleep 30 & echo $! > " + pid_file + "; kill -TERM $PPID; wait"},
                                  log_file, 60.),
               pumpd::Interrupted);
  std::ifstream in(pid_file);
  int           sleeper = 0;
  ASSERT_TRUE(in >> sleeper);
  // Gone, or a zombie that its new parent has not reaped yet, a moment after.
  const auto running = [&] {
    std::ifstream stat("/proc/" + std::to_string(sleeper) + "/stat");
    std::string   pid, name, state;
    return stat >> pid >> name >> state && state != "Z";
  };
  for (int k = 0; k < 50 && running(); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_FALSE(running()) << "the program's child " << sleeper << " still runs";
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
