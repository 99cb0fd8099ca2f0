#include "child_process.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <stdexcept>

namespace pumpd::coupling
{
  ChildRun run_child(const std::string &program, const std::vector<std::string> &arguments, const std::string &log)
  {
    std::vector<char *> argv{const_cast<char *>(program.c_str())};
    for (const auto &a : arguments)
      argv.push_back(const_cast<char *>(a.c_str()));
    argv.push_back(nullptr);

    const auto t0  = std::chrono::steady_clock::now();
    const int  out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0)
      throw std::runtime_error("cannot write " + log);
    const pid_t pid = ::fork();
    if (pid == 0)
      {
        ::dup2(out, STDOUT_FILENO);
        ::dup2(out, STDERR_FILENO);
        ::execv(program.c_str(), argv.data());
        ::_exit(127);
      }
    ::close(out);
    if (pid < 0)
      throw std::runtime_error("cannot start " + program);
    int     status = 0;
    rusage  usage{};
    ChildRun run;
    if (::wait4(pid, &status, 0, &usage) == pid && WIFEXITED(status))
      run.exit_code = WEXITSTATUS(status);
    run.seconds     = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    run.peak_memory = double(usage.ru_maxrss) / 1024.; // kB on Linux
    return run;
  }

  std::string this_executable() { return std::filesystem::read_symlink("/proc/self/exe").string(); }
} // namespace pumpd::coupling
