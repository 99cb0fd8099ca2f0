#include "beam_scene.h"

#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>

#include "elasticity.h"
#include "error.h"
#include "mesh.h"

namespace pumpd::coupling
{
  using geometry::Point;

  namespace
  {
    constexpr double infinity         = std::numeric_limits<double>::infinity();
    constexpr double crack_tolerance  = 1e-9; ///< [m]: "on the outline", "touches a hole"
    constexpr double vertex_tolerance = 1e-6; ///< [m]: supports and load on mesh vertices
  } // namespace

  std::string to_text(Point p)
  {
    std::ostringstream s;
    s << "(" << p.x << ", " << p.y << ")";
    return s.str();
  }

  std::string to_text(const geometry::Polyline &line)
  {
    std::ostringstream s;
    for (std::size_t k = 0; k < line.size(); ++k)
      s << (k == 0 ? "" : "; ") << line[k].x << "," << line[k].y;
    return s.str();
  }

  geometry::Body body_of(const dealii::Triangulation<2> &tria)
  {
    const auto &v = tria.get_vertices();
    geometry::Body body{{infinity, infinity, -infinity, -infinity}, {}};
    for (unsigned int i = 0; i < v.size(); ++i)
      if (tria.get_used_vertices()[i])
        {
          body.outline.x_min = std::min(body.outline.x_min, v[i][0]);
          body.outline.y_min = std::min(body.outline.y_min, v[i][1]);
          body.outline.x_max = std::max(body.outline.x_max, v[i][0]);
          body.outline.y_max = std::max(body.outline.y_max, v[i][1]);
        }
    // Union-find over the vertices of hole faces.
    std::map<unsigned int, unsigned int> parent;
    const auto root = [&](unsigned int a) {
      while (parent[a] != a)
        a = parent[a] = parent[parent[a]];
      return a;
    };
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == 5)
          {
            const unsigned int a = face->vertex_index(0), b = face->vertex_index(1);
            parent.emplace(a, a);
            parent.emplace(b, b);
            parent[root(a)] = root(b);
          }
    std::map<unsigned int, std::vector<Point>> rings;
    for (const auto &[i, unused] : parent)
      rings[root(i)].push_back({v[i][0], v[i][1]});
    for (const auto &[r, points] : rings)
      {
        Point c = std::accumulate(points.begin(), points.end(), Point{});
        c       = (1. / points.size()) * c;
        double radius = 0.;
        for (const auto &p : points)
          radius = std::max(radius, geometry::norm(p - c));
        body.holes.push_back({c, radius});
      }
    return body;
  }

  geometry::Body read_beam(dealii::Triangulation<2> &tria, const std::string &mesh_file, double mesh_size,
                           const std::vector<std::pair<std::string, Point>> &named_points)
  {
    global::read_mesh(mesh_file, tria, mesh_size);
    global::require_boundary_ids(tria, {1, 2, 3, 4});
    require_vertices(tria, named_points);
    return body_of(tria);
  }

  void require_vertices(const dealii::Triangulation<2> &tria, const std::vector<std::pair<std::string, Point>> &named)
  {
    for (const auto &[name, x] : named)
      try
        {
          global::find_vertex(tria, x, vertex_tolerance);
        }
      catch (const InvalidParameter &e)
        {
          throw InvalidParameter(name, to_text(x), e.what());
        }
  }

  global::Crack initial_crack(const geometry::Polyline &vertices, const geometry::Body &body)
  {
    try
      {
        return global::Crack(vertices, body, crack_tolerance);
      }
    catch (const InvalidParameter &e)
      {
        throw InvalidParameter("Initial crack", to_text(vertices), e.what());
      }
  }

  void refine_at_tips(dealii::Triangulation<2> &tria, const std::vector<global::Tip> &tips, double radius,
                      unsigned int levels)
  {
    for (unsigned int l = 0; l < levels; ++l)
      {
        bool flagged = false;
        for (const auto &cell : tria.active_cell_iterators())
          for (const auto &t : tips)
            if (cell->level() < int(levels) &&
                cell->center().distance(dealii::Point<2>(t.position.x, t.position.y)) < radius + 0.5 * cell->diameter())
              {
                cell->set_refine_flag();
                flagged = true;
              }
        if (!flagged)
          return;
        tria.execute_coarsening_and_refinement();
      }
  }

  double distance_to_outline(Point x, Point e, const geometry::Box &b)
  {
    double t = infinity;
    if (e.x > 0.)
      t = std::min(t, (b.x_max - x.x) / e.x);
    if (e.x < 0.)
      t = std::min(t, (b.x_min - x.x) / e.x);
    if (e.y > 0.)
      t = std::min(t, (b.y_max - x.y) / e.y);
    if (e.y < 0.)
      t = std::min(t, (b.y_min - x.y) / e.y);
    return std::max(t, 0.);
  }

  // t = -b - sqrt(b^2 - |x - c|^2 + R^2), b = (x - c).e.
  double distance_to_circle(Point x, Point e, Point c, double R)
  {
    const double b = geometry::dot(x - c, e), q = geometry::dot(x - c, x - c) - R * R;
    if (q <= 0.)
      return 0.;
    if (b >= 0. || b * b < q)
      return infinity;
    return -b - std::sqrt(b * b - q);
  }

  double clearance(Point x, const geometry::Body &body)
  {
    const auto &o = body.outline;
    double      d = std::min({x.x - o.x_min, o.x_max - x.x, x.y - o.y_min, o.y_max - x.y});
    for (const auto &hole : body.holes)
      d = std::min(d, geometry::norm(x - hole.centre) - hole.radius);
    return d;
  }

  DamageField damage_field(const local::PdModel &model, const local::State &s)
  {
    const auto &lattice = model.lattice();
    const auto  damage  = model.damage(s);
    DamageField field;
    field.origin  = lattice.position(lattice.index(0, 0));
    field.spacing = lattice.spacing();
    field.nx      = lattice.nx();
    field.ny      = lattice.ny();
    field.values.assign(field.nx * field.ny, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i : model.nodes())
      field.values[lattice.row(i) * field.nx + lattice.column(i)] = damage[i];
    return field;
  }

  Arrival arrive(geometry::Polyline path, const geometry::Body &body, double margin, double reach,
                 std::size_t first_new, double hole_reach)
  {
    for (std::size_t k = first_new == 0 ? 0 : first_new - 1; k + 1 < path.size(); ++k)
      {
        const Point  e = path[k + 1] - path[k];
        const double l = geometry::norm(e);
        if (l == 0.)
          continue;
        const Point u = (1. / l) * e;
        for (const auto &hole : body.holes)
          {
            const double t = distance_to_circle(path[k], u, hole.centre, hole.radius + margin);
            if (t <= l)
              {
                path.resize(k + 1);
                if (t > 1e-9)
                  path.push_back(path[k] + t * u);
                return {path, "reached the hole at " + to_text(hole.centre)};
              }
          }
      }
    if (path.size() > first_new && path.size() >= 2)
      {
        const Point  e = path.back() - path[path.size() - 2];
        const Point  u = (1. / geometry::norm(e)) * e;
        const double t = distance_to_outline(path.back(), u, body.outline);
        if (t <= reach)
          {
            path.back() = path.back() + t * u;
            return {path, "reached the outline"};
          }
        for (const auto &hole : body.holes)
          {
            const double s = distance_to_circle(path.back(), u, hole.centre, hole.radius + margin);
            if (s <= hole_reach)
              {
                path.push_back(path.back() + s * u);
                return {path, "reached the hole at " + to_text(hole.centre)};
              }
          }
      }
    return {path, ""};
  }

  geometry::Polyline read_path(const std::string &file)
  {
    std::ifstream in(file);
    if (!in)
      throw InvalidParameter("Published path", file, "cannot be opened (relative paths start at the current directory)");
    geometry::Polyline path;
    std::string        line;
    while (std::getline(in, line))
      {
        if (line.empty() || line[0] == '#' || std::isalpha(static_cast<unsigned char>(line[0])))
          continue;
        Point p;
        if (std::sscanf(line.c_str(), "%lf,%lf", &p.x, &p.y) != 2)
          throw InvalidParameter("Published path", file, "line \"" + line + "\" is not x,y");
        path.push_back(p);
      }
    if (path.size() < 2)
      throw InvalidParameter("Published path", file, "needs at least 2 points x,y");
    return path;
  }

  void write_path(const std::string &file, const geometry::Polyline &path)
  {
    std::ofstream out(file);
    out << std::setprecision(10) << "x_m,y_m\n";
    for (const auto &p : path)
      out << p.x << "," << p.y << "\n";
  }

  void write_body(const std::string &file, const geometry::Body &body,
                  const std::vector<std::pair<std::string, Point>> &points)
  {
    std::ofstream out(file);
    out << std::setprecision(10) << "shape,x_min_m,y_min_m,x_max_m,y_max_m\n";
    const auto &o = body.outline;
    out << "outline," << o.x_min << "," << o.y_min << "," << o.x_max << "," << o.y_max << "\n";
    for (const auto &h : body.holes)
      out << "hole," << h.centre.x - h.radius << "," << h.centre.y - h.radius << "," << h.centre.x + h.radius << ","
          << h.centre.y + h.radius << "\n";
    for (const auto &[name, x] : points)
      out << name << "," << x.x << "," << x.y << "," << x.x << "," << x.y << "\n";
  }

  GlobalVtuSeries::GlobalVtuSeries(std::string dir, std::string series_name)
    : directory(std::move(dir))
    , name(std::move(series_name))
  {}

  void GlobalVtuSeries::add(const global::EnrichedElasticity &solution, std::size_t step)
  {
    char file[64];
    std::snprintf(file, sizeof(file), "%s_%03zu.vtu", name.c_str(), step);
    solution.write_vtu(directory + "/" + file);
    entries.emplace_back(step, file);
    std::ofstream pvd(directory + "/" + name + ".pvd");
    pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
    for (const auto &[s, f] : entries)
      pvd << "<DataSet timestep=\"" << s << "\" file=\"" << f << "\"/>\n";
    pvd << "</Collection>\n</VTKFile>\n";
  }
} // namespace pumpd::coupling
