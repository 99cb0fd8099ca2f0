#include "program.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

extern char **environ;

namespace pumpd
{
  ProgramRun run_program(const std::vector<std::string> &argv, const std::string &log)
  {
    std::vector<char *> args;
    for (const auto &a : argv)
      args.push_back(const_cast<char *>(a.c_str()));
    args.push_back(nullptr);

    const auto t0  = std::chrono::steady_clock::now();
    const int  out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (out < 0)
      throw std::runtime_error("cannot write " + log + ": " + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, out, STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, out, STDERR_FILENO);
    pid_t      pid = 0;
    ProgramRun run;
    run.start_error = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(out);
    if (run.start_error != 0)
      return run;

    int    status = 0;
    rusage usage{};
    while (::wait4(pid, &status, 0, &usage) < 0)
      if (errno != EINTR)
        throw std::runtime_error("waiting for " + argv[0] + " failed: " + std::strerror(errno));
    if (WIFEXITED(status))
      run.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status))
      run.signal = WTERMSIG(status);
    run.seconds     = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    run.peak_memory = double(usage.ru_maxrss) / 1024.; // kB on Linux
    return run;
  }

  std::string last_line(const std::string &file)
  {
    std::ifstream in(file);
    std::string   line, last;
    while (std::getline(in, line))
      if (line.find_first_not_of(" \t\r") != std::string::npos)
        last = line;
    return last;
  }

  std::string this_executable() { return std::filesystem::read_symlink("/proc/self/exe").string(); }
} // namespace pumpd
