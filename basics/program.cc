#include "program.h"

#include <elf.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <thread>

#include "hash.h"
#include "text.h"

extern char **environ;

namespace pumpd
{
  namespace
  {
    constexpr int passed_on[] = {SIGINT, SIGTERM, SIGHUP};

    // What the handler passes signals on to (a process, or -a process group; 0: none yet) and the
    // last signal it received.
    volatile std::sig_atomic_t waited_for = 0, received = 0;

    void pass_on(int signal)
    {
      received = signal;
      if (const pid_t target = waited_for; target != 0)
        ::kill(target, signal);
    }

    /// While it lives, SIGINT, SIGTERM and SIGHUP are caught and passed on to the program waited for;
    /// a signal that was ignored stays ignored. The handler does not restart an interrupted wait.
    class PassingOnSignals
    {
    public:
      PassingOnSignals()
      {
        received = 0;
        struct sigaction handler = {};
        handler.sa_handler       = pass_on;
        sigemptyset(&handler.sa_mask);
        for (std::size_t k = 0; k < std::size(passed_on); ++k)
          {
            ::sigaction(passed_on[k], nullptr, &saved[k]);
            if (saved[k].sa_handler != SIG_IGN)
              ::sigaction(passed_on[k], &handler, nullptr);
          }
      }
      ~PassingOnSignals()
      {
        waited_for = 0;
        for (std::size_t k = 0; k < std::size(passed_on); ++k)
          ::sigaction(passed_on[k], &saved[k], nullptr);
      }
      PassingOnSignals(const PassingOnSignals &)            = delete;
      PassingOnSignals &operator=(const PassingOnSignals &) = delete;

      /// From now on signals go to `target`; one that came before it started goes now.
      void pass_to(pid_t target)
      {
        waited_for = target;
        if (const int signal = received; signal != 0)
          ::kill(target, signal);
      }
      int signal() const { return received; }

    private:
      struct sigaction saved[std::size(passed_on)] = {};
    };

    std::string signal_name(int signal)
    {
      return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : signal == SIGHUP ? "SIGHUP"
                                                                                               : "signal " + std::to_string(signal);
    }
  } // namespace

  std::string Interrupted::what() const
  {
    return signal_name(signal) + " while waiting for " + program + " (passed on to it; it has ended)";
  }

  ProgramRun run_program(const std::vector<std::string> &argv, const std::string &log, double time_limit,
                         const Heartbeat &heartbeat)
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
    // Under a time limit the program gets a process group of its own, so that the kill reaches
    // what it started (a wrapper script's gmsh).
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    const bool own_group = time_limit > 0.;
    if (own_group)
      {
        posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
        posix_spawnattr_setpgroup(&attributes, 0);
      }
    PassingOnSignals       signals;
    pid_t                  pid = 0;
    ProgramRun             run;
    run.start_error = posix_spawnp(&pid, args[0], &actions, &attributes, args.data(), environ);
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    ::close(out);
    if (run.start_error != 0)
      {
        if (signals.signal() != 0)
          throw Interrupted{signals.signal(), argv[0]};
        return run;
      }
    signals.pass_to(own_group ? -pid : pid);

    int        status = 0;
    rusage     usage{};
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    const bool polling = time_limit > 0. || heartbeat.interval > 0.;
    double     next_beat = heartbeat.interval;
    bool       killed    = false;
    for (;;)
      {
        const pid_t done = ::wait4(pid, &status, polling ? WNOHANG : 0, &usage);
        if (done == pid)
          break;
        if (done < 0 && errno != EINTR)
          throw std::runtime_error("waiting for " + argv[0] + " failed: " + std::strerror(errno));
        if (done != 0)
          continue;
        const double t = elapsed();
        if (time_limit > 0. && t > time_limit)
          {
            ::kill(-pid, SIGKILL);
            killed     = true;
            time_limit = 0.;
          }
        if (heartbeat.interval > 0. && t >= next_beat)
          {
            heartbeat.tick(t);
            next_beat += heartbeat.interval;
          }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    if (signals.signal() != 0)
      throw Interrupted{signals.signal(), argv[0]};
    if (WIFEXITED(status))
      run.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status))
      run.signal = WTERMSIG(status);
    run.timed_out   = killed && run.signal == SIGKILL;
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

  namespace
  {
    /// The GNU build ID of a 64-bit ELF file (its NT_GNU_BUILD_ID note, found through the program
    /// headers' PT_NOTE segments), in hex; "" if it has none.
    std::string gnu_build_id(const std::string &file)
    {
      std::ifstream in(file, std::ios::binary);
      Elf64_Ehdr    header{};
      const auto    read_at = [&](std::uint64_t offset, void *to, std::size_t bytes) {
        in.seekg(static_cast<std::streamoff>(offset));
        return static_cast<bool>(in.read(static_cast<char *>(to), static_cast<std::streamsize>(bytes)));
      };
      if (!read_at(0, &header, sizeof header) || std::memcmp(header.e_ident, ELFMAG, SELFMAG) != 0 ||
          header.e_ident[EI_CLASS] != ELFCLASS64 || header.e_ident[EI_DATA] != ELFDATA2LSB ||
          header.e_phentsize != sizeof(Elf64_Phdr))
        return "";
      constexpr std::uint64_t largest_note_segment = 1u << 16;
      for (unsigned int i = 0; i < header.e_phnum; ++i)
        {
          Elf64_Phdr segment{};
          if (!read_at(header.e_phoff + i * sizeof segment, &segment, sizeof segment))
            return "";
          if (segment.p_type != PT_NOTE || segment.p_filesz > largest_note_segment)
            continue;
          std::string notes(segment.p_filesz, '\0');
          if (!read_at(segment.p_offset, notes.data(), notes.size()))
            return "";
          // Each note: its header, then its name and its description, each padded to the
          // segment's alignment (4 bytes, or 8 in an 8-aligned note segment).
          const std::uint64_t align  = segment.p_align == 8 ? 8 : 4;
          const auto          padded = [&](std::uint64_t n) { return (n + align - 1) / align * align; };
          for (std::uint64_t at = 0; at + sizeof(Elf64_Nhdr) <= notes.size();)
            {
              Elf64_Nhdr note;
              std::memcpy(&note, notes.data() + at, sizeof note);
              const std::uint64_t name = at + sizeof note, description = name + padded(note.n_namesz);
              if (description + note.n_descsz > notes.size())
                break;
              if (note.n_type == NT_GNU_BUILD_ID && note.n_namesz == 4 && notes.compare(name, 4, std::string("GNU\0", 4)) == 0)
                {
                  const char *digits = "0123456789abcdef";
                  std::string id;
                  for (std::uint64_t k = 0; k < note.n_descsz; ++k)
                    {
                      const auto byte = static_cast<unsigned char>(notes[description + k]);
                      id += {digits[byte >> 4], digits[byte & 15]};
                    }
                  return id;
                }
              at = description + padded(note.n_descsz);
            }
        }
      return "";
    }
  } // namespace

  std::string program_version(const std::string &executable)
  {
    if (const std::string id = gnu_build_id(executable); !id.empty())
      return id;
    const auto bytes = file_contents(executable);
    return bytes ? hex(fnv1a(*bytes)) : "";
  }
} // namespace pumpd
