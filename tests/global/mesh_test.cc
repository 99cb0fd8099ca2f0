// The Ingraffea beam meshes (meshes/*.geo) and their reader (global/mesh.h): all-quad
// triangulations of the right area, the physical names (edges, holes, the supports and the load
// point), the body they cover (straight outline, circular holes), the size override and its
// cell limit, the mesh cache, and the errors the reader raises.
#include <deal.II/grid/reference_cell.h>
#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "error.h"
#include "mesh.h"

namespace
{
  using pumpd::global::body_of;
  using pumpd::global::MeshNames;
  using pumpd::global::read_mesh;

  const std::string beam_geo  = PUMPD_SOURCE_DIR "/meshes/ingraffea-beam.geo";
  const std::string holes_geo = PUMPD_SOURCE_DIR "/meshes/ingraffea-beam-holes.geo";

  constexpr double length      = 0.508;
  constexpr double height      = 0.2032;
  constexpr double hole_radius = 0.00635;
  const double     pi          = std::acos(-1.);

  /// Meshing runs gmsh: every (file, h) is meshed once per test program.
  const dealii::Triangulation<2> &mesh(const std::string &file, double h = 0., MeshNames *names = nullptr)
  {
    static std::map<std::pair<std::string, double>, std::pair<dealii::Triangulation<2>, MeshNames>> cache;
    const auto key = std::make_pair(file, h);
    auto       it  = cache.find(key);
    if (it == cache.end())
      {
        it = cache.emplace(std::piecewise_construct, std::forward_as_tuple(key),
                           std::forward_as_tuple())
               .first;
        it->second.second = read_mesh(file, it->second.first, h);
      }
    if (names)
      *names = it->second.second;
    return it->second.first;
  }

  double area(const dealii::Triangulation<2> &tria)
  {
    double a = 0.;
    for (const auto &cell : tria.active_cell_iterators())
      a += cell->measure();
    return a;
  }

  bool all_quads(const dealii::Triangulation<2> &tria)
  {
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->reference_cell() != dealii::ReferenceCells::Quadrilateral)
        return false;
    return tria.n_active_cells() > 0;
  }

  unsigned int n_boundary_faces(const dealii::Triangulation<2> &tria,
                                dealii::types::boundary_id      id)
  {
    unsigned int n = 0;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == id)
          ++n;
    return n;
  }

  /// what() of the InvalidParameter that f throws; "no exception" / "other exception".
  std::string invalid_parameter(const std::function<void()> &f)
  {
    try
      {
        f();
      }
    catch (const pumpd::InvalidParameter &e)
      {
        return e.what();
      }
    catch (...)
      {
        return "other exception";
      }
    return "no exception";
  }

  bool starts_with(const std::string &s, const std::string &prefix)
  {
    return s.rfind(prefix, 0) == 0;
  }

  /// A file in a fresh directory under the temporary directory, removed at the end.
  class TemporaryFile
  {
  public:
    TemporaryFile(const std::string &name, const std::string &content)
    {
      std::string dir = (std::filesystem::temp_directory_path() / "pumpd-mesh-test-XXXXXX").string();
      if (::mkdtemp(dir.data()) == nullptr)
        throw std::runtime_error("mkdtemp failed");
      directory_ = dir;
      std::ofstream(directory_ / name) << content;
      path_ = (directory_ / name).string();
    }
    ~TemporaryFile()
    {
      std::error_code ignored;
      std::filesystem::remove_all(directory_, ignored);
    }
    const std::string &path() const { return path_; }

  private:
    std::filesystem::path directory_;
    std::string           path_;
  };
} // namespace

TEST(GlobalMesh, BeamIsAllQuadWithTheExactArea)
{
  const auto &tria = mesh(beam_geo);
  EXPECT_TRUE(all_quads(tria));
  EXPECT_GT(tria.n_active_cells(), 1000u);
  std::cout << "pumpd-metric beam_cells " << tria.n_active_cells() << '\n';
  // A polygon: meshed exactly up to round-off.
  EXPECT_NEAR(area(tria), length * height, 1e-12 * length * height);
}

TEST(GlobalMesh, BeamWithHolesLosesThePolygonAreaOfTheHoles)
{
  const auto &tria = mesh(holes_geo);
  EXPECT_TRUE(all_quads(tria));
  std::cout << "pumpd-metric beam_holes_cells " << tria.n_active_cells() << '\n';

  // Each hole is a regular polygon of N edges inscribed in the circle (four arcs, each split
  // evenly); it keeps pi r^2 sin(2 pi / N) / (2 pi / N) of the circle's area as hole, so the
  // mesh has 3 pi r^2 (1 - sin(2 pi / N) / (2 pi / N)) more area than the exact body.
  const unsigned int hole_faces = n_boundary_faces(tria, 5);
  ASSERT_EQ(hole_faces % 3, 0u);
  const unsigned int n = hole_faces / 3;
  EXPECT_GE(n, 16u); // hole_segments in the .geo
  const double circles   = 3 * pi * hole_radius * hole_radius;
  const double exact     = length * height - circles;
  const double angle     = 2 * pi / n;
  const double predicted = circles * (1 - std::sin(angle) / angle);
  const double measured  = area(tria) - exact;
  EXPECT_NEAR(measured, predicted, 1e-9 * length * height) << "N = " << n;
  EXPECT_LT(std::abs(measured), 1e-3 * length * height);
}

TEST(GlobalMesh, PhysicalNames)
{
  MeshNames names;
  mesh(holes_geo, 0., &names);
  const std::map<std::string, dealii::types::boundary_id> curves = {
    {"bottom", 1}, {"right", 2}, {"top", 3}, {"left", 4}, {"holes", 5}};
  EXPECT_EQ(names.boundaries, curves);
  EXPECT_EQ(names.regions.at("beam"), 1u);
  const std::map<std::string, pumpd::geometry::Point> points = {
    {"pin", {0.0254, 0.}}, {"roller", {0.4826, 0.}}, {"load", {0.254, 0.2032}}};
  ASSERT_EQ(names.points.size(), 3u);
  for (const auto &[name, x] : points)
    {
      ASSERT_EQ(names.points.at(name).size(), 1u) << name;
      EXPECT_EQ(names.points.at(name)[0].x, x.x) << name;
      EXPECT_EQ(names.points.at(name)[0].y, x.y) << name;
    }
  // Each named curve holds the faces on its edge.
  for (const auto &cell : mesh(beam_geo).active_cell_iterators())
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary())
        {
          const auto   c  = face->center();
          const double tol = 1e-12;
          const auto   id = face->boundary_id();
          EXPECT_TRUE((id == 1 && std::abs(c[1]) < tol) ||
                      (id == 2 && std::abs(c[0] - length) < tol) ||
                      (id == 3 && std::abs(c[1] - height) < tol) ||
                      (id == 4 && std::abs(c[0]) < tol))
            << "boundary id " << id << " at " << c;
        }
}

// The body the mesh covers: the rectangle as four segments, each hole as one circle through its
// mesh vertices (exact: gmsh puts them on the arcs).
TEST(GlobalMesh, BodyOfTheBeamWithHoles)
{
  const auto body = body_of(mesh(holes_geo));
  EXPECT_EQ(body.outline().pieces.size(), 4u);
  const auto &b = body.bounding_box();
  EXPECT_EQ(b.x_min, 0.);
  EXPECT_EQ(b.y_min, 0.);
  EXPECT_NEAR(b.x_max, length, 1e-15);
  EXPECT_NEAR(b.y_max, height, 1e-15);
  ASSERT_EQ(body.holes().size(), 3u);
  const double ys[] = {0.06985, 0.12065, 0.17145};
  for (const auto &hole : body.holes())
    {
      pumpd::geometry::Circle c;
      ASSERT_TRUE(hole.circle(c));
      EXPECT_NEAR(c.centre.x, 0.1524, 1e-11);
      EXPECT_NEAR(c.radius, hole_radius, 1e-11);
      EXPECT_TRUE(std::any_of(std::begin(ys), std::end(ys), [&](double y) { return std::abs(c.centre.y - y) < 1e-11; }));
    }
  EXPECT_NEAR(body.area(), length * height - 3. * pi * hole_radius * hole_radius, 1e-12);
}

TEST(GlobalMesh, CharacteristicLengthOverride)
{
  const auto coarse = mesh(beam_geo, 0.016).n_active_cells();
  const auto fine   = mesh(beam_geo, 0.008).n_active_cells();
  // The default is h = 0.008.
  EXPECT_EQ(fine, mesh(beam_geo).n_active_cells());
  // Halving h gives about four times the cells.
  EXPECT_GT(fine, 2.5 * coarse);
  EXPECT_LT(fine, 5.5 * coarse);
  EXPECT_TRUE(all_quads(mesh(beam_geo, 0.016)));
}

TEST(GlobalMesh, ReadsMsh)
{
  // The same mesh read back from a .msh file.
  const std::string msh2 = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                           "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
                           "$Elements\n3\n1 3 2 1 1 1 2 3 4\n2 1 2 1 1 1 2\n3 1 2 3 3 3 4\n"
                           "$EndElements\n";
  const TemporaryFile      file("square.msh", msh2);
  dealii::Triangulation<2> tria;
  read_mesh(file.path(), tria);
  EXPECT_EQ(tria.n_active_cells(), 1u);
  EXPECT_NEAR(area(tria), 1., 1e-14);
  std::set<unsigned int> ids;
  for (const auto &face : tria.begin_active()->face_iterators())
    ids.insert(face->boundary_id());
  EXPECT_EQ(ids, (std::set<unsigned int>{0, 1, 3}));
}

TEST(GlobalMesh, Errors)
{
  dealii::Triangulation<2> tria;
  std::string              what;

  what = invalid_parameter([&] { read_mesh("/nonexistent/beam.msh", tria); });
  EXPECT_EQ(what, "Mesh file = /nonexistent/beam.msh: no such file");

  what = invalid_parameter([&] { read_mesh(beam_geo, tria, -1.); });
  EXPECT_TRUE(starts_with(what, "Mesh size = -1: ")) << what;

  // A size that would make too many cells is refused before gmsh meshes (it would run for hours).
  what = invalid_parameter([&] { read_mesh(beam_geo, tria, 1e-5, 5e5); });
  EXPECT_TRUE(starts_with(what, "Mesh size = 1e-05: the mesh would have about")) << what;
  EXPECT_NE(what.find("more than Maximum cells = 5e+05"), std::string::npos) << what;

  const TemporaryFile text("beam.txt", "not a mesh\n");
  what = invalid_parameter([&] { read_mesh(text.path(), tria); });
  EXPECT_TRUE(starts_with(what, "Mesh file = " + text.path() + ": must be")) << what;

  const TemporaryFile truncated("truncated.msh",
                                "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n");
  what = invalid_parameter([&] { read_mesh(truncated.path(), tria); });
  EXPECT_TRUE(starts_with(what, "Mesh file = " + truncated.path() + ": not a readable gmsh mesh"))
    << what;
}

TEST(GlobalMesh, NonQuadCellsAreRejected)
{
  const std::string triangles = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                                "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
                                "$Elements\n2\n1 2 2 1 1 1 2 3\n2 2 2 1 1 1 3 4\n$EndElements\n";
  const TemporaryFile      file("triangles.msh", triangles);
  dealii::Triangulation<2> tria;
  const std::string        what = invalid_parameter([&] { read_mesh(file.path(), tria); });
  EXPECT_TRUE(starts_with(what, "Mesh file = " + file.path() + ": quadrilateral cells only"))
    << what;
  EXPECT_EQ(tria.n_active_cells(), 0u);
}

namespace
{
  /// An environment variable set for the life of the object, then restored.
  class ScopedVariable
  {
  public:
    ScopedVariable(const char *name, const std::string &value)
      : name(name)
    {
      if (const char *old = std::getenv(name))
        saved = old;
      ::setenv(name, value.c_str(), 1);
    }
    ~ScopedVariable()
    {
      if (saved)
        ::setenv(name, saved->c_str(), 1);
      else
        ::unsetenv(name);
    }

  private:
    const char                *name;
    std::optional<std::string> saved;
  };
} // namespace

TEST(GlobalMesh, GmshErrors)
{
  dealii::Triangulation<2> tria;

  const TemporaryFile broken("broken.geo", "Point(1) = {0, 0, 0\n");
  std::string         what = invalid_parameter([&] { read_mesh(broken.path(), tria); });
  EXPECT_TRUE(starts_with(what, "Mesh file = " + broken.path() + ": gmsh failed with exit status"))
    << what;

  {
    const ScopedVariable missing("PUMPD_GMSH", "/nonexistent/gmsh");
    what = invalid_parameter([&] { read_mesh(beam_geo, tria); });
  }
  EXPECT_TRUE(starts_with(what, "Mesh file = " + beam_geo + ": ")) << what;
  EXPECT_NE(what.find("/nonexistent/gmsh"), std::string::npos) << what;
}

TEST(GlobalMesh, CacheKeepsAMeshedGeoUntilItsSourcesOrSizeChange)
{
  namespace fs = std::filesystem;
  // The beam, through a .geo that Includes it, meshed by a gmsh that counts its runs.
  const TemporaryFile top("beam.geo", "Include \"body.geo\";\n");
  const fs::path      directory = fs::path(top.path()).parent_path();
  fs::copy_file(beam_geo, directory / "body.geo");
  const char       *gmsh = std::getenv("PUMPD_GMSH");
  const std::string real = gmsh != nullptr && *gmsh != '\0' ? gmsh : "gmsh";
  std::ofstream(directory / "gmsh") << "#!/bin/sh\necho run >> '" << (directory / "runs").string() << "'\nexec '"
                                    << real << "' \"$@\"\n";
  fs::permissions(directory / "gmsh", fs::perms::owner_all);
  const ScopedVariable counting("PUMPD_GMSH", (directory / "gmsh").string());
  const ScopedVariable cache("PUMPD_MESH_CACHE", (directory / "meshes").string());
  const auto           runs = [&] {
    std::ifstream in(directory / "runs");
    int           n = 0;
    for (std::string line; std::getline(in, line);)
      ++n;
    return n;
  };

  dealii::Triangulation<2> meshed, cached;
  const MeshNames          meshed_names = read_mesh(top.path(), meshed, 0.02);
  EXPECT_EQ(runs(), 2) << "the cell estimate (gmsh -0) and the mesh (gmsh -2)";
  const MeshNames cached_names = read_mesh(top.path(), cached, 0.02);
  EXPECT_EQ(runs(), 2) << "read from the cache";
  ASSERT_EQ(cached.n_active_cells(), meshed.n_active_cells());
  EXPECT_EQ(cached.get_vertices(), meshed.get_vertices());
  EXPECT_EQ(cached_names.boundaries, meshed_names.boundaries);
  EXPECT_EQ(cached_names.regions, meshed_names.regions);
  ASSERT_EQ(cached_names.points.size(), meshed_names.points.size());
  for (const auto &[name, points] : meshed_names.points)
    {
      ASSERT_EQ(cached_names.points.at(name).size(), points.size()) << name;
      for (std::size_t i = 0; i < points.size(); ++i)
        EXPECT_TRUE(cached_names.points.at(name)[i].x == points[i].x && cached_names.points.at(name)[i].y == points[i].y)
          << name;
    }

  read_mesh(top.path(), cached, 0.025);
  EXPECT_EQ(runs(), 4) << "another size";
  std::ofstream(directory / "body.geo", std::ios::app) << "// an edit of the included file\n";
  read_mesh(top.path(), cached, 0.02);
  EXPECT_EQ(runs(), 6) << "an included file changed";
  read_mesh(top.path(), cached, 0.02);
  EXPECT_EQ(runs(), 6);

  for (const auto &entry : fs::directory_iterator(directory / "meshes"))
    std::ofstream(entry.path()) << "not a mesh\n";
  read_mesh(top.path(), cached, 0.02);
  EXPECT_EQ(runs(), 8) << "a cached mesh that cannot be read is meshed again";
  EXPECT_EQ(cached.n_active_cells(), meshed.n_active_cells());

  // A file named by an expression: the sources are unknown, so the .geo is meshed every time.
  std::ofstream(top.path()) << "Include StrCat(CurrentDir, \"body.geo\");\n";
  EXPECT_EQ(pumpd::global::mesh_sources_hash(top.path()), "");
  read_mesh(top.path(), cached, 0.02);
  read_mesh(top.path(), cached, 0.02);
  EXPECT_EQ(runs(), 12);
}
