#include "output.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <thread>

#include "error.h"

namespace pumpd
{
  namespace
  {
    struct Reservation
    {
      std::string entry, directory; ///< as the scene file names them
      int         lock = -1;        ///< the lock file, held open for the process's life
    };

    /// This process's reserved output directories, by their canonical path.
    std::map<std::string, Reservation> &reservations()
    {
      static std::map<std::string, Reservation> reserved;
      return reserved;
    }

    std::string canonical(const std::string &directory)
    {
      std::error_code error;
      const auto      path = std::filesystem::weakly_canonical(directory.empty() ? "." : directory, error);
      return error ? directory : path.string();
    }

    /// The process id the holder of the lock wrote into it (it writes it just after locking: a
    /// reader that comes in between waits a moment for it).
    std::string holder_of(int lock)
    {
      for (int attempt = 0; attempt < 50; ++attempt)
        {
          char          text[32] = {};
          const ssize_t n        = pread(lock, text, sizeof(text) - 1, 0);
          if (n > 0 && text[n - 1] == '\n')
            return std::string(text, std::size_t(n - 1));
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
      return "unknown";
    }

    void lock(Reservation &r)
    {
      const std::string file = r.directory + "/.pumpd.lock";
      // Not inherited by the programs a run starts (a study's runs, gmsh): they lock their own.
      const int fd = open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
      if (fd < 0)
        throw InvalidParameter(r.entry, r.directory,
                               "cannot be locked: " + file + ": " + std::strerror(errno));
      if (flock(fd, LOCK_EX | LOCK_NB) != 0)
        {
          const int         error = errno;
          const std::string pid   = error == EWOULDBLOCK ? holder_of(fd) : "";
          close(fd);
          if (error != EWOULDBLOCK)
            throw InvalidParameter(r.entry, r.directory, "cannot be locked: " + file + ": " + std::strerror(error));
          throw InvalidParameter(r.entry, r.directory,
                                 "another pumpd (pid " + pid +
                                   ") writes there: wait for it to end, or give another folder");
        }
      const std::string pid = std::to_string(getpid()) + "\n";
      if (ftruncate(fd, 0) != 0 || pwrite(fd, pid.data(), pid.size(), 0) != ssize_t(pid.size()))
        write_failed(file, errno);
      r.lock = fd;
    }
  } // namespace

  void reserve_output_directory(const std::string &entry, const std::string &directory)
  {
    reservations().emplace(canonical(directory), Reservation{entry, directory});
  }

  void claim_output_directory(const std::string &directory)
  {
    const auto it = reservations().find(canonical(directory));
    if (it != reservations().end() && it->second.lock < 0)
      lock(it->second);
  }

  void write_failed(const std::string &path, int error)
  {
    throw std::runtime_error("cannot write " + path + ": " +
                             (error != 0 ? std::strerror(error) : "the system gave no cause"));
  }

  std::string partial_of(const std::string &path) { return path + ".partial"; }

  void replace_with_partial(const std::string &path)
  {
    if (std::rename(partial_of(path).c_str(), path.c_str()) != 0)
      {
        const int error = errno;
        std::remove(partial_of(path).c_str());
        write_failed(path, error);
      }
  }

  void write_aside(const std::string &path, const std::function<void(std::ostream &)> &text)
  {
    const std::string partial = partial_of(path);
    errno                     = 0;
    std::ofstream out(partial);
    if (!out)
      write_failed(path, errno);
    try
      {
        text(out);
      }
    catch (...)
      {
        out.close();
        std::remove(partial.c_str());
        throw;
      }
    out.close();
    if (!out)
      {
        const int error = errno;
        std::remove(partial.c_str());
        write_failed(path, error);
      }
    replace_with_partial(path);
  }
} // namespace pumpd
