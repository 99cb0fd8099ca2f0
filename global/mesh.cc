#include "mesh.h"

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/grid/tria.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

#include "error.h"

extern char **environ;

namespace pumpd::global
{
  namespace
  {
    namespace fs = std::filesystem;

    std::string to_text(double v, int precision = 6)
    {
      std::ostringstream s;
      s << std::setprecision(precision) << v;
      return s.str();
    }

    std::string to_text(const geometry::Point &p)
    {
      return "(" + to_text(p.x, 10) + ", " + to_text(p.y, 10) + ")";
    }

    /// One line from an exception text: deal.II's "Additional information" if present,
    /// whitespace collapsed, at most 300 characters.
    std::string one_line(const std::string &text)
    {
      std::string       s   = text;
      const std::string key = "Additional information:";
      if (const auto k = s.find(key); k != std::string::npos)
        s = s.substr(k + key.size());
      if (const auto k = s.find("Stacktrace:"); k != std::string::npos)
        s = s.substr(0, k);
      std::string out;
      for (const char c : s)
        if (std::isspace(static_cast<unsigned char>(c)))
          {
            if (!out.empty() && out.back() != ' ')
              out += ' ';
          }
        else
          out += c;
      while (!out.empty() && (out.back() == ' ' || out.back() == '-'))
        out.pop_back();
      if (out.size() > 300)
        out = out.substr(0, 297) + "...";
      return out;
    }

    /// A directory under the system's temporary directory, removed with its content.
    class TemporaryDirectory
    {
    public:
      TemporaryDirectory()
      {
        std::string name = (fs::temp_directory_path() / "pumpd-mesh-XXXXXX").string();
        if (::mkdtemp(name.data()) == nullptr)
          throw std::runtime_error("cannot create a temporary directory: " +
                                   std::string(std::strerror(errno)));
        path_ = name;
      }
      ~TemporaryDirectory()
      {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
      }
      TemporaryDirectory(const TemporaryDirectory &)            = delete;
      TemporaryDirectory &operator=(const TemporaryDirectory &) = delete;

      const fs::path &path() const { return path_; }

    private:
      fs::path path_;
    };

    /// The first line of gmsh's output that reports an error, else its last non-empty line.
    std::string gmsh_message(const fs::path &log)
    {
      std::ifstream in(log);
      std::string   line, last;
      while (std::getline(in, line))
        {
          if (line.rfind("Error", 0) == 0)
            return one_line(line);
          if (line.find_first_not_of(" \t\r") != std::string::npos)
            last = line;
        }
      return one_line(last);
    }

    /// Runs gmsh on a .geo file; the mesh (msh2) is written to `msh`, its output to `log`.
    void run_gmsh(const std::string &file, double characteristic_length, const fs::path &msh,
                  const fs::path &log)
    {
      const char       *from_env = std::getenv("PUMPD_GMSH");
      const std::string gmsh     = (from_env != nullptr && *from_env != '\0') ? from_env : "gmsh";

      std::vector<std::string> args = {gmsh, "-2", "-format", "msh2"};
      if (characteristic_length > 0.)
        {
          args.insert(args.end(), {"-setnumber", "h", to_text(characteristic_length, 17)});
        }
      args.insert(args.end(), {"-o", msh.string(), file});
      std::vector<char *> argv;
      for (auto &a : args)
        argv.push_back(a.data());
      argv.push_back(nullptr);

      posix_spawn_file_actions_t actions;
      posix_spawn_file_actions_init(&actions);
      posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
      posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                       0644);
      posix_spawn_file_actions_adddup2(&actions, 1, 2);
      pid_t     pid   = 0;
      const int spawn = posix_spawnp(&pid, gmsh.c_str(), &actions, nullptr, argv.data(), environ);
      posix_spawn_file_actions_destroy(&actions);
      if (spawn != 0)
        throw InvalidParameter("Mesh file", file,
                               "meshing a .geo needs the gmsh executable, but '" + gmsh +
                                 "' could not be started (" + std::strerror(spawn) +
                                 "); install gmsh or set PUMPD_GMSH");

      int status = 0;
      while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
          throw InvalidParameter("Mesh file", file,
                                 "waiting for gmsh failed: " + std::string(std::strerror(errno)));

      if (WIFSIGNALED(status))
        throw InvalidParameter("Mesh file", file,
                               "gmsh was killed by signal " + std::to_string(WTERMSIG(status)) +
                                 ": " + gmsh_message(log));
      const int exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      std::error_code ignored;
      if (exit_status == 127 && fs::file_size(log, ignored) == 0)
        throw InvalidParameter("Mesh file", file,
                               "meshing a .geo needs the gmsh executable, but '" + gmsh +
                                 "' was not found; install gmsh or set PUMPD_GMSH");
      if (exit_status != 0)
        throw InvalidParameter("Mesh file", file,
                               "gmsh failed with exit status " + std::to_string(exit_status) +
                                 ": " + gmsh_message(log));
      if (!fs::is_regular_file(msh))
        throw InvalidParameter("Mesh file", file,
                               "gmsh (exit status 0) wrote no mesh: " + gmsh_message(log));
    }

    /// Reads a gmsh .msh into `tria`; `file` is the name the user gave (for messages).
    void read_msh(const fs::path &msh, const std::string &file, dealii::Triangulation<2> &tria)
    {
      std::ifstream in(msh);
      if (!in)
        throw InvalidParameter("Mesh file", file, "cannot be opened");

      tria.clear();
      dealii::GridIn<2> grid_in;
      grid_in.attach_triangulation(tria);
      try
        {
          grid_in.read_msh(in);
        }
      catch (const std::exception &e)
        {
          tria.clear();
          throw InvalidParameter("Mesh file", file,
                                 "not a readable gmsh mesh (" + one_line(e.what()) + ")");
        }

      unsigned int not_quads = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->reference_cell() != dealii::ReferenceCells::Quadrilateral)
          ++not_quads;
      if (not_quads > 0 || tria.n_active_cells() == 0)
        {
          const unsigned int n = tria.n_active_cells();
          tria.clear();
          throw InvalidParameter("Mesh file", file,
                                 "quadrilateral cells only, but " + std::to_string(not_quads) +
                                   " of " + std::to_string(n) +
                                   " cells are not quadrilaterals (recombine the mesh in gmsh)");
        }
    }
  } // namespace

  void read_mesh(const std::string &file, dealii::Triangulation<2> &tria,
                 double characteristic_length)
  {
    if (!std::isfinite(characteristic_length) || characteristic_length < 0.)
      throw InvalidParameter("Mesh characteristic length", to_text(characteristic_length),
                             "must be a finite number >= 0 (0: the .geo file's default)");

    const fs::path path(file);
    std::error_code error;
    if (!fs::is_regular_file(path, error))
      throw InvalidParameter("Mesh file", file, "no such file");

    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });

    if (extension == ".msh")
      read_msh(path, file, tria);
    else if (extension == ".geo")
      {
        const TemporaryDirectory directory;
        const fs::path           msh = directory.path() / "mesh.msh";
        run_gmsh(file, characteristic_length, msh, directory.path() / "gmsh.log");
        read_msh(msh, file, tria);
      }
    else
      throw InvalidParameter("Mesh file", file, "must be a gmsh .msh or .geo file");
  }

  void require_boundary_ids(const dealii::Triangulation<2>                &tria,
                            const std::vector<dealii::types::boundary_id> &ids)
  {
    std::set<dealii::types::boundary_id> present;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          present.insert(face->boundary_id());

    for (const auto id : ids)
      if (present.count(id) == 0)
        {
          std::string list;
          for (const auto p : present)
            list += (list.empty() ? "" : ", ") + std::to_string(p);
          throw InvalidParameter("Mesh boundary id", std::to_string(id),
                                 "no boundary face of the mesh has it (present: " +
                                   (list.empty() ? std::string("none") : list) + ")");
        }
  }

  unsigned int find_vertex(const dealii::Triangulation<2> &tria, const geometry::Point &p,
                           double tolerance)
  {
    if (!std::isfinite(tolerance) || tolerance < 0.)
      throw InvalidParameter("Mesh vertex tolerance", to_text(tolerance),
                             "must be a finite number >= 0");

    const auto  &vertices = tria.get_vertices();
    const auto  &used     = tria.get_used_vertices();
    unsigned int best     = std::numeric_limits<unsigned int>::max();
    double       best_distance = std::numeric_limits<double>::infinity();
    for (unsigned int i = 0; i < vertices.size(); ++i)
      if (used[i])
        {
          const double d = std::hypot(vertices[i][0] - p.x, vertices[i][1] - p.y);
          if (d < best_distance)
            {
              best          = i;
              best_distance = d;
            }
        }

    if (best == std::numeric_limits<unsigned int>::max())
      throw InvalidParameter("Mesh vertex", to_text(p), "the mesh has no vertices");
    if (!(best_distance <= tolerance))
      throw InvalidParameter("Mesh vertex", to_text(p),
                             "no mesh vertex within " + to_text(tolerance) +
                               " m; the nearest is " +
                               to_text(geometry::Point{vertices[best][0], vertices[best][1]}) +
                               " at " + to_text(best_distance) + " m");
    return best;
  }
} // namespace pumpd::global
