#include "mesh.h"

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/grid/tria.h>

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
#include <map>
#include <optional>
#include <ostream>
#include <regex>
#include <set>
#include <sstream>

#include <unistd.h>

#include "error.h"
#include "hash.h"
#include "memory.h"
#include "program.h"
#include "text.h"

namespace pumpd::global
{
  namespace
  {
    namespace fs = std::filesystem;

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

    /// The first line of gmsh's output that reports an error, else its last non-blank line.
    std::string gmsh_message(const fs::path &log)
    {
      std::ifstream in(log);
      for (std::string line; std::getline(in, line);)
        if (line.rfind("Error", 0) == 0)
          return one_line(line);
      return one_line(last_line(log));
    }

    /// The gmsh command: the environment variable PUMPD_GMSH, else `gmsh` on the PATH.
    std::string gmsh_command()
    {
      const char *from_env = std::getenv("PUMPD_GMSH");
      return (from_env != nullptr && *from_env != '\0') ? from_env : "gmsh";
    }

    /// gmsh's command line for `mode` ("-2": mesh in 2D, msh2; "-0": the unrolled geometry) at
    /// `characteristic_length`, without the output and the .geo file.
    std::vector<std::string> gmsh_arguments(const std::string &mode, double characteristic_length)
    {
      std::vector<std::string> args = {gmsh_command(), mode};
      if (mode == "-2")
        args.insert(args.end(), {"-format", "msh2"});
      if (characteristic_length > 0.)
        args.insert(args.end(), {"-setnumber", "h", to_text(characteristic_length, 17)});
      return args;
    }

    /// Runs gmsh on a .geo file in `mode` (gmsh_arguments) into `out`, its output into `log`; with
    /// `progress`, a line there every 10 s while gmsh runs (a large .geo takes minutes).
    void run_gmsh(const std::string &file, const std::string &mode, double characteristic_length,
                  const fs::path &out, const fs::path &log, std::ostream *progress)
    {
      std::vector<std::string> args = gmsh_arguments(mode, characteristic_length);
      const std::string        gmsh = args.front();
      args.insert(args.end(), {"-o", out.string(), file});
      Heartbeat heartbeat;
      if (progress != nullptr)
        heartbeat = {10., [&](double seconds) {
                       *progress << "meshing " << file << ": " << to_text(std::floor(seconds)) << " s, gmsh log: "
                                 << one_line(last_line(log.string())) << std::endl;
                     }};
      // A .geo that never finishes (a loop without end) must not hang the run.
      const double     time_limit = 600.;
      const ProgramRun run        = run_program(args, log.string(), time_limit, heartbeat);
      if (run.timed_out)
        throw InvalidParameter("Mesh file", file,
                               "gmsh did not finish within " + to_text(time_limit) +
                                 " s: check the .geo (a loop without end?), or use a larger Mesh size");
      if (run.start_error != 0)
        throw InvalidParameter("Mesh file", file,
                               "meshing a .geo needs the gmsh executable, but '" + gmsh +
                                 "' could not be started (" + std::strerror(run.start_error) +
                                 "); install gmsh or set PUMPD_GMSH");
      if (run.signal != 0)
        throw InvalidParameter("Mesh file", file,
                               "gmsh was killed by signal " + std::to_string(run.signal) +
                                 ": " + gmsh_message(log));
      std::error_code ignored;
      if (run.exit_code == 127 && fs::file_size(log, ignored) == 0)
        throw InvalidParameter("Mesh file", file,
                               "meshing a .geo needs the gmsh executable, but '" + gmsh +
                                 "' was not found; install gmsh or set PUMPD_GMSH");
      if (run.exit_code != 0)
        throw InvalidParameter("Mesh file", file,
                               "gmsh failed with exit status " + std::to_string(run.exit_code) +
                                 ": " + gmsh_message(log));
      if (!fs::is_regular_file(out))
        throw InvalidParameter("Mesh file", file,
                               "gmsh (exit status 0) wrote nothing: " + gmsh_message(log));
    }

    /// A file's extension in lower case (".geo", ".msh").
    std::string extension_of(const fs::path &file)
    {
      std::string extension = file.extension().string();
      std::transform(extension.begin(), extension.end(), extension.begin(),
                     [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      return extension;
    }

    /// The program a command names: as it is with a '/', else the first executable of that name
    /// in the PATH's directories; empty if there is none.
    fs::path program_of(const std::string &command)
    {
      if (command.find('/') != std::string::npos)
        return command;
      const char        *path = std::getenv("PATH");
      std::istringstream directories(path != nullptr ? path : "");
      for (std::string directory; std::getline(directories, directory, ':');)
        {
          const fs::path candidate = fs::path(directory.empty() ? "." : directory) / command;
          if (::access(candidate.c_str(), X_OK) == 0 && fs::is_regular_file(candidate))
            return candidate;
        }
      return {};
    }

    /// Chains the sources of a mesh file into `h`: a .geo's text, the option file gmsh merges
    /// with it (<file>.opt), and the files it reads (Include, Merge, ShapeFromFile), recursively;
    /// any other file's bytes. None if a .geo names a file it reads by an expression (StrCat,
    /// ...): its sources are then unknown.
    std::optional<std::uint64_t> chain_sources(const fs::path &file, std::uint64_t h, std::set<fs::path> &seen)
    {
      std::error_code error;
      const fs::path  canonical = fs::weakly_canonical(file, error);
      if (!seen.insert(error ? file : canonical).second)
        return h;
      const auto text = file_contents(file.string());
      h               = fnv1a(text.value_or("missing " + file.string()), h);
      if (const auto options = file_contents(file.string() + ".opt"))
        h = fnv1a(*options, h);
      if (!text || extension_of(file) != ".geo")
        return h;
      static const std::regex reads(R"re(\b(Include|Merge|ShapeFromFile)\b\s*\(?\s*("([^"]*)")?)re");
      for (std::sregex_iterator m(text->begin(), text->end(), reads), end; m != end; ++m)
        {
          if (!(*m)[2].matched)
            return std::nullopt;
          const fs::path named   = (*m)[3].str();
          const auto     chained = chain_sources(named.is_absolute() ? named : file.parent_path() / named, h, seen);
          if (!chained)
            return std::nullopt;
          h = *chained;
        }
      return h;
    }

    /// Where a .geo meshed at `characteristic_length` is kept between runs: a file in the
    /// directory named by the environment variable PUMPD_MESH_CACHE (pumpd --study sets it to its
    /// output directory's meshes/), named by the hash of the .geo's sources, gmsh's command line
    /// and gmsh's program version; empty without a cache, or where the sources or gmsh are unknown.
    fs::path cached_mesh(const std::string &file, double characteristic_length)
    {
      const char *directory = std::getenv("PUMPD_MESH_CACHE");
      const auto  gmsh      = program_of(gmsh_command());
      if (directory == nullptr || *directory == '\0' || gmsh.empty())
        return {};
      std::uint64_t h = fnv1a(program_version(gmsh.string()));
      for (const auto &argument : gmsh_arguments("-2", characteristic_length))
        h = fnv1a(argument + '\0', h);
      std::set<fs::path> seen;
      const auto         sources = chain_sources(file, h, seen);
      return sources ? fs::path(directory) / (hex(*sources) + ".msh") : fs::path();
    }

    /// Copies a mesh into the cache: written aside under a unique name, then renamed, so that a
    /// run reading the cache sees a whole file or none. A cache that cannot be written is left as
    /// it is.
    void keep_in_cache(const fs::path &msh, const fs::path &cached)
    {
      std::error_code ignored;
      fs::create_directories(cached.parent_path(), ignored);
      std::string part = cached.string() + ".XXXXXX";
      const int   fd   = ::mkstemp(part.data());
      if (fd < 0)
        return;
      ::close(fd);
      if (fs::copy_file(msh, part, fs::copy_options::overwrite_existing, ignored))
        fs::rename(part, cached, ignored);
      fs::remove(part, ignored);
    }

    /// Cells a .geo would be meshed into, before meshing: the area of the bounding box of its
    /// points over h^2, h the characteristic length (else the smallest one of its points). The
    /// geometry comes from gmsh's unrolled .geo (gmsh -0: every coordinate evaluated).
    double estimated_cells(const std::string &file, double characteristic_length, const fs::path &directory,
                           std::ostream *progress)
    {
      const fs::path unrolled = directory / "geometry.geo_unrolled";
      run_gmsh(file, "-0", characteristic_length, unrolled, directory / "gmsh-0.log", progress);
      std::ifstream in(unrolled);
      std::string   line;
      double        x_min = std::numeric_limits<double>::infinity(), x_max = -x_min, y_min = x_min, y_max = -x_min;
      double        smallest = x_min;
      std::map<std::string, double> constants;
      while (std::getline(in, line))
        {
          double x, y, z;
          char   size[64] = {};
          if (std::sscanf(line.c_str(), "Point(%*d) = {%lf, %lf, %lf, %63[^}]}", &x, &y, &z, size) >= 3)
            {
              x_min = std::min(x_min, x), x_max = std::max(x_max, x);
              y_min = std::min(y_min, y), y_max = std::max(y_max, y);
              const std::string s(size);
              const auto        c = constants.find(s);
              const double      v = c != constants.end() ? c->second : std::atof(size);
              if (v > 0.)
                smallest = std::min(smallest, v);
            }
          char   name[64] = {};
          double value    = 0.;
          if (std::sscanf(line.c_str(), "%63[A-Za-z_0-9] = %lf;", name, &value) == 2)
            constants[name] = value;
        }
      const double h = characteristic_length > 0. ? characteristic_length : smallest;
      if (!(x_max > x_min) || !(y_max > y_min) || !(h > 0.) || !std::isfinite(h))
        return 0.;
      return (x_max - x_min) * (y_max - y_min) / (h * h);
    }

    /// The named physical groups of a gmsh ASCII mesh ($PhysicalNames; the nodes of point
    /// elements for named points, msh2 only).
    MeshNames read_names(const fs::path &msh, const std::string &file)
    {
      std::ifstream                                   in(msh);
      std::string                                     line;
      std::map<unsigned int, std::string>             point_name;
      std::map<std::size_t, geometry::Point>          node;
      std::map<std::string, std::vector<std::size_t>> point_nodes;
      MeshNames                                       names;
      double                                          version = 0.;
      while (std::getline(in, line))
        if (line == "$MeshFormat")
          in >> version;
        else if (line == "$PhysicalNames")
          {
            std::size_t n = 0;
            in >> n;
            for (std::size_t k = 0; k < n; ++k)
              {
                int          dim = 0;
                unsigned int tag = 0;
                std::string  quoted;
                in >> dim >> tag;
                std::getline(in, quoted);
                const auto a = quoted.find('"'), b = quoted.rfind('"');
                const auto name = a != std::string::npos && b > a ? quoted.substr(a + 1, b - a - 1) : quoted;
                if (dim == 0)
                  point_name[tag] = name;
                else if (dim == 1)
                  names.boundaries[name] = tag;
                else if (dim == 2)
                  names.regions[name] = tag;
              }
          }
        else if (line == "$Nodes" && version < 4.)
          {
            std::size_t n = 0;
            in >> n;
            for (std::size_t k = 0; k < n; ++k)
              {
                std::size_t id;
                double      x, y, z;
                in >> id >> x >> y >> z;
                node[id] = {x, y};
              }
          }
        else if (line == "$Elements" && version < 4.)
          {
            std::size_t n = 0;
            in >> n;
            std::getline(in, line);
            for (std::size_t k = 0; k < n && std::getline(in, line); ++k)
              {
                std::istringstream e(line);
                std::size_t        id = 0, type = 0, tags = 0, first_node = 0;
                unsigned int       physical = 0;
                e >> id >> type >> tags;
                if (type != 15 || tags == 0)
                  continue;
                e >> physical;
                for (std::size_t t = 1; t < tags; ++t)
                  e >> id;
                e >> first_node;
                if (point_name.count(physical))
                  point_nodes[point_name[physical]].push_back(first_node);
              }
          }
      for (const auto &[tag, name] : point_name)
        {
          if (version >= 4.)
            throw InvalidParameter("Mesh file", file,
                                   "the named point \"" + name + "\" needs a gmsh msh2 file (gmsh -format msh2)");
          for (const auto id : point_nodes[name])
            names.points[name].push_back(node.at(id));
        }
      return names;
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
          // deal.II reads the cells of the physical groups only: a mesh without a Physical
          // Surface has none.
          if (std::string(e.what()).find("did not find any cells") != std::string::npos)
            throw InvalidParameter("Mesh file", file,
                                   "the mesh has no 2D cells that deal.II reads: name the body's surface with "
                                   "Physical Surface(\"...\") = {...} in the .geo");
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

    /// Reads the cached mesh `cached` of `file`: false if there is none, or if it cannot be read
    /// (it is then removed, and the caller meshes the .geo again).
    bool read_cached(const fs::path &cached, const std::string &file, dealii::Triangulation<2> &tria, MeshNames &names)
    {
      std::error_code error;
      if (cached.empty() || !fs::is_regular_file(cached, error))
        return false;
      try
        {
          read_msh(cached, file, tria);
          names = read_names(cached, file);
          return true;
        }
      catch (const InvalidParameter &)
        {
          fs::remove(cached, error);
          return false;
        }
    }
  } // namespace

  MeshNames read_mesh(const std::string &file, dealii::Triangulation<2> &tria, double characteristic_length,
                      double max_cells, std::ostream *progress)
  {
    if (!std::isfinite(characteristic_length) || characteristic_length < 0.)
      throw InvalidParameter("Mesh size", to_text(characteristic_length),
                             "must be a finite number >= 0 (0: the .geo file's default)");

    const fs::path path(file);
    std::error_code error;
    if (const auto kind = special_file_kind(file); !kind.empty())
      throw InvalidParameter("Mesh file", file, "is " + kind + ", not a regular file (a gmsh .msh or .geo file)");
    if (!fs::is_regular_file(path, error))
      throw InvalidParameter("Mesh file", file, "no such file");

    const std::string extension = extension_of(path);

    const auto too_many = [&](double cells, const std::string &how) {
      if (max_cells <= 0.)
        return;
      const std::string remedy = ": use a larger Mesh size (cells scale with 1 / size^2)";
      if (cells > max_cells)
        throw InvalidParameter("Mesh size", to_text(characteristic_length),
                               how + " " + to_text(cells, 3) + " cells, more than Maximum cells = " +
                                 to_text(max_cells, 3) + remedy);
      check_memory(cells, "Mesh size", to_text(characteristic_length), how + " " + to_text(cells, 3) + " cells",
                   remedy);
    };
    MeshNames names;
    if (extension == ".msh")
      {
        read_msh(path, file, tria);
        names = read_names(path, file);
      }
    else if (extension == ".geo")
      {
        const fs::path cached = cached_mesh(file, characteristic_length);
        if (!read_cached(cached, file, tria, names))
          {
            const TemporaryDirectory directory;
            too_many(estimated_cells(file, characteristic_length, directory.path(), progress),
                     "the mesh would have about (bounding box / size^2)");
            const fs::path msh = directory.path() / "mesh.msh";
            run_gmsh(file, "-2", characteristic_length, msh, directory.path() / "gmsh.log", progress);
            read_msh(msh, file, tria);
            names = read_names(msh, file);
            if (!cached.empty())
              keep_in_cache(msh, cached);
          }
      }
    else
      throw InvalidParameter("Mesh file", file, "must be a gmsh .msh or .geo file");
    too_many(tria.n_active_cells(), "the mesh has");
    return names;
  }

  double estimated_global_bytes(double cells)
  {
    const double n = 2. * std::max(cells, 1.);
    return 0.25e9 + 250. * n * std::log2(std::max(n, 2.));
  }

  void check_memory(double cells, const std::string &name, const std::string &value, const std::string &what,
                    const std::string &remedy)
  {
    const double needed = estimated_global_bytes(cells), available = 0.8 * available_memory();
    const double gib    = 1024. * 1024. * 1024.;
    if (needed > available)
      throw InvalidParameter(name, value,
                             what + ": the global problem needs about " + to_text(needed / gib, 3) +
                               " GiB, more than the " + to_text(available / gib, 3) +
                               " GiB this machine can give it" + remedy);
  }

  geometry::Body body_of(const dealii::Triangulation<2> &tria)
  {
    std::vector<geometry::Point> vertices;
    for (const auto &v : tria.get_vertices())
      vertices.push_back({v[0], v[1]});
    std::vector<std::array<std::size_t, 2>> edges;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          edges.push_back({{face->vertex_index(0), face->vertex_index(1)}});
    return geometry::body_from_edges(vertices, edges);
  }

  std::string mesh_sources_hash(const std::string &file)
  {
    std::set<fs::path> seen;
    const auto         h = chain_sources(file, fnv1a_offset, seen);
    return h ? hex(*h) : "";
  }

} // namespace pumpd::global
