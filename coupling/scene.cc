#include "scene.h"

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "crack.h"
#include "error.h"
#include "hash.h"
#include "mesh.h"
#include "output.h"
#include "path_metrics.h"
#include "text.h"

namespace pumpd::coupling
{
  using geometry::Point;
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  double Material::effective_modulus() const
  {
    return plane_strain ? youngs_modulus / (1. - poisson_ratio * poisson_ratio) : youngs_modulus;
  }

  double Material::critical_sif() const { return std::sqrt(effective_modulus() * fracture_energy); }

  const geometry::Polyline &Scene::crack() const
  {
    if (cracks.size() != 1)
      throw InvalidParameter("Initial cracks", std::to_string(cracks.size()) + " cracks",
                             "this method grows exactly one crack (LEFM growth, global-local and full PD grow several)");
    return cracks.front();
  }

  void SceneSettings::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    prm.add_parameter("Mesh file", mesh_file,
                      "The specimen's mesh: a gmsh .geo (meshed by gmsh into quadrilaterals) or .msh (all "
                      "quadrilaterals). Its physical names (Physical Curve, Point, Surface) name the places the "
                      "boundary conditions and the report refer to; its boundary is the body (outline and holes). "
                      "Relative paths start at the current directory.",
                      Patterns::FileName());
    prm.add_parameter("Mesh size", mesh_size,
                      "h passed to gmsh for a .geo (-setnumber h) [m]; 0: the file's default.", Patterns::Double(0., 1.));
    prm.add_parameter("Maximum cells", max_cells,
                      "A .geo whose mesh would have more cells (estimated before gmsh runs as its bounding box area / "
                      "Mesh size^2), or a mesh that has more, is refused.",
                      Patterns::Double(1., 1e8));
    prm.add_parameter("Initial cracks", initial_cracks,
                      "Crack polylines \"x1,y1; x2,y2; ...\" [m], several separated by |. An end on the outline or on "
                      "a hole's rim is a mouth, an end on another crack's face a junction (lefm-growth and global-local), "
                      "every other end a tip; vertices inside the body, segments crossing neither the outline nor a "
                      "hole; two cracks do not cross and keep at least a tenth of the mesh cell apart where they come "
                      "closest, but at a junction. LEFM growth, global-local and full PD grow several "
                      "cracks. Empty: no crack; global-local and full PD start one where the material first fails "
                      "(section Initiation), LEFM growth lists where one would start and stops.",
                      Patterns::Anything());
    prm.add_parameter("Length defaults", length_defaults,
                      "scene: the length entries a scene file leaves unset (Peridynamics: Horizon; Global-local: Box "
                      "size, Box margin, Maximum box size, Maximum and Minimum advance, Near distance; LEFM growth: "
                      "Growth increment; Global: Tip enrichment radius, Refinement radius and trail) are derived from "
                      "the scene's own lengths (README, \"Lengths\"; the run prints them); absolute: each entry's "
                      "default, the lengths of the published Ingraffea decks (a beam 508 x 203 mm: horizon 4 mm, box "
                      "32 mm, growth increment 4 mm). An entry the file sets is kept under either.",
                      Patterns::Selection("scene|absolute"));
    prm.add_parameter("Output directory", output_directory,
                      "Where the results go (created if missing); empty: the run writes nothing.", Patterns::DirectoryName());
    prm.add_parameter("Reference path", reference_path,
                      "Optional CSV of a path to compare with (x,y [m] per line, # comments): copied to "
                      "reference_path.csv, distances printed. Empty: none.",
                      Patterns::Anything());

    prm.enter_subsection("Material");
    prm.add_parameter("Young's modulus", material.youngs_modulus,
                      "E [Pa] (SI units: from soft polymers to diamond).", Patterns::Double(1e3, 1e13));
    prm.add_parameter("Poisson's ratio", material.poisson_ratio,
                      "nu. The methods with peridynamics need bond-based PD's value: 1/4 in plane strain, 1/3 in "
                      "plane stress.",
                      Patterns::Double(0., 0.4999));
    prm.add_parameter("Fracture energy", material.fracture_energy,
                      "Critical energy release rate G_c [J/m^2] (SI units: from gels to tough metals).",
                      Patterns::Double(1e-4, 1e7));
    prm.add_parameter("Density", material.density, "rho [kg/m^3] (SI units: from foams to the heaviest metals).",
                      Patterns::Double(1., 1e5));
    prm.add_parameter("Plane strain", material.plane_strain, "true: plane strain; false: plane stress.", Patterns::Bool());
    prm.leave_subsection();

    prm.enter_subsection("Boundary conditions");
    prm.add_parameter("Displacement", displacement,
                      "\"<place>: ux = <f>, uy = <f>; ...\": prescribed displacement components [m] on a named "
                      "boundary, point or region (a component not given is free). <f> is an expression of x, y and "
                      "the load factor lambda (deal.II FunctionParser; pi is known), linear in lambda.",
                      Patterns::Anything());
    prm.add_parameter("Traction", traction,
                      "\"<boundary>: tx = <f>, ty = <f>, p = <f>; ...\": traction [Pa] on a named boundary, t = (tx, "
                      "ty) - p n with n the outward normal (p > 0 presses on the body: a bearing pressure), linear "
                      "in lambda.",
                      Patterns::Anything());
    prm.add_parameter("Point force", point_force,
                      "\"<point>: fx = <f>, fy = <f>; ...\": force [N per m of thickness] on a named point, linear "
                      "in lambda.",
                      Patterns::Anything());
    prm.leave_subsection();

    prm.enter_subsection("Report");
    prm.add_parameter("Load", report_load,
                      "The load of load_displacement.csv: lambda, or \"<place>: fx\" (or fy, -fx, -fy): the reaction "
                      "force on a named boundary or point that holds a displacement condition [N/m].",
                      Patterns::Anything());
    prm.add_parameter("Displacement", report_displacement,
                      "The displacement of load_displacement.csv: \"<place>: ux\" (or uy, -ux, -uy): at a named "
                      "point, or the mean over a named boundary [m]; empty: 2 U / lambda (U the strain energy), the "
                      "displacement work-conjugate to lambda when lambda scales forces.",
                      Patterns::Anything());
    prm.leave_subsection();
    prm.leave_subsection();
  }

  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    /// Splits at `separator` outside parentheses.
    std::vector<std::string> split_outside_parentheses(const std::string &text, char separator)
    {
      std::vector<std::string> parts(1);
      int                      depth = 0;
      for (const char c : text)
        {
          depth += c == '(' ? 1 : c == ')' ? -1 : 0;
          if (c == separator && depth == 0)
            parts.emplace_back();
          else
            parts.back() += c;
        }
      return parts;
    }

    /// A scene text as a message echoes it: whole up to 80 characters, else its start and its
    /// length, so that the reason after it fits the message's one line (one_line: 300 characters).
    std::string echoed(const std::string &text)
    {
      return text.size() <= 80 ? text : text.substr(0, 60) + "... (" + std::to_string(text.size()) + " characters)";
    }

    /// f(x, y, lambda) of an expression; InvalidParameter(entry, ...) if it does not parse.
    std::function<double(Point, double)> compile(const std::string &expression, const std::string &entry)
    {
      auto f = std::make_shared<dealii::FunctionParser<2>>(1);
      // deal.II's parser writes a five-line report to std::cerr before it throws: kept out of the
      // one-line message, which takes the parser's reason from the exception.
      struct Silenced
      {
        std::ostringstream sink;
        std::streambuf    *saved = std::cerr.rdbuf(sink.rdbuf());
        ~Silenced() { std::cerr.rdbuf(saved); }
      };
      try
        {
          const Silenced silenced;
          f->initialize("x,y,lambda", expression, {{"pi", pi}}, true);
          f->set_time(1.);
          f->value(dealii::Point<2>(0., 0.));
        }
      catch (const std::exception &e)
        {
          std::string       why = e.what();
          const std::string key = "The parser said: ";
          if (const auto k = why.find(key); k != std::string::npos)
            why = why.substr(k + key.size());
          if (const auto k = why.find("Stacktrace:"); k != std::string::npos)
            why = why.substr(0, k);
          throw InvalidParameter(entry, echoed(expression), "not an expression of x, y and lambda (" + one_line(why) + ")");
        }
      return [f](Point x, double lambda) {
        f->set_time(lambda);
        return f->value(dealii::Point<2>(x.x, x.y));
      };
    }

    /// Point location in a mesh that stays alive as long as the locator (the cache goes first).
    struct Locator
    {
      std::shared_ptr<const dealii::Triangulation<2>>  tria;
      std::unique_ptr<dealii::GridTools::Cache<2>>     cache;
      explicit Locator(std::shared_ptr<const dealii::Triangulation<2>> t)
        : tria(std::move(t))
        , cache(std::make_unique<dealii::GridTools::Cache<2>>(*tria))
      {}
      ~Locator() { cache.reset(); }
    };

    /// The named places of the mesh.
    class Places
    {
    public:
      Places(std::shared_ptr<const dealii::Triangulation<2>> t, global::MeshNames n)
        : tria(*t)
        , names(std::move(n))
        , locator(std::make_shared<Locator>(std::move(t)))
      {}

      conditions::Place find(const std::string &entry, const std::string &text, const std::string &name,
                             std::set<conditions::Place::Kind> allowed) const
      {
        using Kind = conditions::Place::Kind;
        check_unambiguous(entry, text, name, allowed);
        conditions::Place place;
        place.name = name;
        if (const auto b = names.boundaries.find(name); b != names.boundaries.end() && allowed.count(Kind::boundary))
          {
            place.kind = Kind::boundary;
            place.id   = b->second;
            for (const auto &cell : tria.active_cell_iterators())
              for (const auto &face : cell->face_iterators())
                if (face->at_boundary() && face->boundary_id() == place.id)
                  place.edges.push_back({{Point{face->vertex(0)[0], face->vertex(0)[1]},
                                          Point{face->vertex(1)[0], face->vertex(1)[1]}}});
            if (place.edges.empty())
              throw InvalidParameter(entry, text, "the curve \"" + name + "\" holds no boundary face of the mesh");
            for (const auto &e : place.edges)
              place.points.insert(place.points.end(), e.begin(), e.end());
          }
        else if (const auto p = names.points.find(name); p != names.points.end() && allowed.count(Kind::point))
          {
            place.kind   = Kind::point;
            place.points = p->second;
          }
        else if (const auto r = names.regions.find(name); r != names.regions.end() && allowed.count(Kind::region))
          {
            place.kind = Kind::region;
            place.id   = r->second;
            for (const auto &cell : tria.active_cell_iterators())
              if (cell->material_id() == place.id)
                for (const auto v : cell->vertex_indices())
                  place.points.push_back({cell->vertex(v)[0], cell->vertex(v)[1]});
            const auto id = place.id;
            place.inside  = [l = locator, id](Point x) {
              const auto found = dealii::GridTools::find_active_cell_around_point(*l->cache, dealii::Point<2>(x.x, x.y));
              return found.first.state() == dealii::IteratorState::valid && found.first->material_id() == id;
            };
          }
        else
          {
            // A name of the wrong kind (a traction on a point, a point force on a curve) is a
            // different mistake from a name the mesh does not have.
            const std::string kind = names.boundaries.count(name) ? "boundary (Physical Curve)"
                                     : names.points.count(name)   ? "point (Physical Point)"
                                     : names.regions.count(name)  ? "region (Physical Surface)"
                                                                  : "";
            if (!kind.empty())
              throw InvalidParameter(entry, text, "\"" + name + "\" is a " + kind + ", but this entry takes a " + kinds(allowed));
            // Messages fold runs of spaces into one, so the spaces are shown as '_'.
            if (const auto spaced = differing_in_spaces(name))
              throw InvalidParameter(entry, text, "the mesh has no place named \"" + name +
                                                    "\", but one that differs only in spaces (each space as _: " +
                                                    underscored(name) + " here, " + underscored(*spaced) +
                                                    " in the mesh): names match exactly; rename one");
            throw InvalidParameter(entry, text, "the mesh has no " + kinds(allowed) + " named \"" + name + "\" (it names " + listing() + ")");
          }
        std::sort(place.points.begin(), place.points.end(),
                  [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
        place.points.erase(std::unique(place.points.begin(), place.points.end(),
                                       [](Point a, Point b) { return a.x == b.x && a.y == b.y; }),
                           place.points.end());
        place.box = {place.points.front().x, place.points.front().y, place.points.front().x, place.points.front().y};
        for (const auto &x : place.points)
          place.box = {std::min(place.box.x_min, x.x), std::min(place.box.y_min, x.y), std::max(place.box.x_max, x.x),
                       std::max(place.box.y_max, x.y)};
        return place;
      }

    private:
      /// gmsh lets a curve, a point and a surface share a physical name; an entry that takes more
      /// than one of those kinds could not tell which is meant.
      void check_unambiguous(const std::string &entry, const std::string &text, const std::string &name,
                             const std::set<conditions::Place::Kind> &allowed) const
      {
        using Kind = conditions::Place::Kind;
        std::set<Kind> named;
        if (names.boundaries.count(name))
          named.insert(Kind::boundary);
        if (names.points.count(name))
          named.insert(Kind::point);
        if (names.regions.count(name))
          named.insert(Kind::region);
        std::set<Kind> taken;
        std::set_intersection(named.begin(), named.end(), allowed.begin(), allowed.end(), std::inserter(taken, taken.end()));
        if (taken.size() > 1)
          throw InvalidParameter(entry, text, "the mesh names a " + kinds(taken, " and a ") + " \"" + name +
                                                "\", and this entry takes either: give them different physical names "
                                                "in the .geo");
      }

      /// A name of the mesh equal to `name` once leading, trailing and repeated spaces are dropped.
      std::optional<std::string> differing_in_spaces(const std::string &name) const
      {
        const auto squeezed = [](const std::string &s) {
          std::istringstream words(s);
          std::string        out, word;
          while (words >> word)
            out += (out.empty() ? "" : " ") + word;
          return out;
        };
        std::optional<std::string> found;
        const auto                 look = [&](const auto &group) {
          for (const auto &named : group)
            if (squeezed(named.first) == squeezed(name))
              found = named.first;
        };
        look(names.boundaries);
        look(names.points);
        look(names.regions);
        return found;
      }

      static std::string underscored(std::string name)
      {
        std::replace_if(name.begin(), name.end(), [](unsigned char c) { return std::isspace(c); }, '_');
        return name;
      }

      static std::string kinds(const std::set<conditions::Place::Kind> &allowed, const std::string &separator = " or ")
      {
        std::string s;
        for (const auto k : allowed)
          s += (s.empty() ? "" : separator) + std::string(k == conditions::Place::Kind::boundary ? "boundary (Physical Curve)"
                                                       : k == conditions::Place::Kind::point  ? "point (Physical Point)"
                                                                                               : "region (Physical Surface)");
        return s;
      }

      std::string listing() const
      {
        std::string s;
        for (const auto &[n, id] : names.boundaries)
          s += (s.empty() ? "\"" : ", \"") + n + "\" (boundary)";
        for (const auto &[n, p] : names.points)
          s += (s.empty() ? "\"" : ", \"") + n + "\" (point)";
        for (const auto &[n, id] : names.regions)
          s += (s.empty() ? "\"" : ", \"") + n + "\" (region)";
        return s.empty() ? "nothing: add physical names to the .geo" : s;
      }

      const dealii::Triangulation<2> &tria;
      global::MeshNames               names;
      std::shared_ptr<Locator>        locator;
    };

    /// One condition of an entry: its place and its "name = expression" assignments.
    struct Parsed
    {
      std::string                        text, place;
      std::map<std::string, std::string> values;
    };

    std::vector<Parsed> parse_entry(const std::string &entry, const std::string &text,
                                    const std::set<std::string> &variables)
    {
      std::vector<Parsed> out;
      if (trim(text).empty())
        return out;
      std::string allowed;
      for (const auto &v : variables)
        allowed += (allowed.empty() ? "" : ", ") + v;
      for (const auto &item : split_outside_parentheses(text, ';'))
        {
          Parsed p;
          p.text           = trim(item);
          const auto colon = p.text.find(':');
          if (p.text.empty())
            throw InvalidParameter(entry, text, "an empty condition between two ';'");
          if (colon == std::string::npos || trim(p.text.substr(0, colon)).empty())
            throw InvalidParameter(entry, p.text, "a condition names its place first: \"<name>: " + *variables.begin() + " = ...\"");
          p.place = trim(p.text.substr(0, colon));
          if (trim(p.text.substr(colon + 1)).empty())
            {
              out.push_back(p); // "<name>:" alone: the entry's check says which components it takes
              continue;
            }
          for (const auto &assignment : split_outside_parentheses(p.text.substr(colon + 1), ','))
            {
              const auto eq = assignment.find('=');
              const auto variable = trim(assignment.substr(0, eq));
              if (eq == std::string::npos || !variables.count(variable) || trim(assignment.substr(eq + 1)).empty())
                throw InvalidParameter(entry, p.text, "\"" + trim(assignment) + "\" must be \"<v> = <expression>\" with <v> one of " + allowed);
              if (p.values.count(variable))
                throw InvalidParameter(entry, p.text, variable + " is given twice");
              p.values[variable] = trim(assignment.substr(eq + 1));
            }
          out.push_back(p);
        }
      return out;
    }

    /// A point where a condition's field is checked, and what it is of the place (for a message).
    struct CheckedPoint
    {
      Point       x;
      const char *what;
    };

    /// The point at (xi, eta) of the unit square in a cell: deal.II's bilinear map of its vertices
    /// 0 (0, 0), 1 (1, 0), 2 (0, 1), 3 (1, 1).
    Point in_cell(const dealii::Triangulation<2>::active_cell_iterator &cell, double xi, double eta)
    {
      const auto v = [&](unsigned int k) { return Point{cell->vertex(k)[0], cell->vertex(k)[1]}; };
      return (1. - xi) * (1. - eta) * v(0) + xi * (1. - eta) * v(1) + (1. - xi) * eta * v(2) + xi * eta * v(3);
    }

    /// Where the methods take a condition's field, beyond its place's vertices: the global problem
    /// takes a traction at Gauss points of its faces (8 on a face, the rule of its assembly, and
    /// as many on each part a crack cuts a face into); full PD takes a displacement at lattice
    /// nodes anywhere in a region's cells, in a band along a boundary's faces, in a disk about a
    /// point's vertex. No finite set holds all of these; this one holds the vertices, each face's
    /// midpoint and 8 Gauss points, and the centre, the edge midpoints and 2 x 2 Gauss points of
    /// each cell PD nodes can lie in (a region's cells; with `pd_nodes` the cells along a boundary
    /// or about a point): a term that vanishes at every vertex, as one periodic in the cell size
    /// does, shows there (one of period h/2 vanishes at the midpoints and centres too, not at the
    /// Gauss points).
    std::vector<CheckedPoint> checked_points(const conditions::Place &place, const dealii::Triangulation<2> &tria,
                                             bool pd_nodes)
    {
      using Kind = conditions::Place::Kind;
      std::vector<CheckedPoint> points;
      for (const Point x : place.points)
        points.push_back({x, "a vertex"});
      const auto to_point = [](const dealii::Point<2> &p) { return Point{p[0], p[1]}; };
      const dealii::QGauss<1> face_rule(8);
      const dealii::QGauss<2> cell_rule(2);
      std::vector<bool>       edge_taken(tria.n_raw_faces(), false); // an edge two cells share, once
      const auto              add_cell = [&](const auto &cell) {
        points.push_back({to_point(cell->center()), "the centre of a cell"});
        for (const auto &q : cell_rule.get_points())
          points.push_back({in_cell(cell, q[0], q[1]), "a Gauss point of a cell"});
        for (const auto f : cell->face_indices())
          if (!edge_taken[cell->face_index(f)])
            {
              edge_taken[cell->face_index(f)] = true;
              points.push_back({to_point(cell->face(f)->center()), "the midpoint of a cell's edge"});
            }
      };
      const auto at_place_point = [&](const auto &cell) {
        const double tolerance = 1e-9 * cell->diameter();
        for (const auto v : cell->vertex_indices())
          for (const Point x : place.points)
            if (geometry::norm(to_point(cell->vertex(v)) - x) <= tolerance)
              return true;
        return false;
      };
      for (const auto &cell : tria.active_cell_iterators())
        {
          bool holds_pd_nodes = false;
          if (place.kind == Kind::region)
            holds_pd_nodes = cell->material_id() == place.id;
          else if (place.kind == Kind::point)
            holds_pd_nodes = pd_nodes && at_place_point(cell);
          else
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == place.id)
                {
                  holds_pd_nodes = pd_nodes;
                  const Point a = to_point(cell->face(f)->vertex(0)), b = to_point(cell->face(f)->vertex(1));
                  points.push_back({0.5 * (a + b), "the midpoint of a face"});
                  for (const auto &q : face_rule.get_points())
                    points.push_back({a + q[0] * (b - a), "a Gauss point of a face"});
                }
          if (holds_pd_nodes)
            add_cell(cell);
        }
      return points;
    }

    /// The field per unit lambda of an expression, checked to be finite and linear in lambda at
    /// the points. A message names the entry, the assignment and the point (short enough that the
    /// one line holds all three).
    conditions::Field linear_field(const std::string &entry, const Parsed &p, const std::string &variable,
                                   const std::vector<CheckedPoint> &points)
    {
      const std::string &expression = p.values.at(variable);
      const auto         f          = compile(expression, entry);
      const std::string  assignment = p.place + ": " + variable + " = " + echoed(expression);
      for (const auto &point : points)
        {
          const Point  x  = point.x;
          const double f0 = f(x, 0.), f1 = f(x, 1.), f2 = f(x, 2.);
          const double scale = std::max({std::abs(f1), std::abs(f2), 1e-300});
          const auto   where = [&] {
            return to_text(x) + ", " + point.what + " of " + p.place + ", it is " + to_text(f0, 4) + ", " + to_text(f1, 4) +
                   ", " + to_text(f2, 4) + " at lambda = 0, 1, 2";
          };
          if (!std::isfinite(f0) || !std::isfinite(f1) || !std::isfinite(f2))
            throw InvalidParameter(entry, assignment,
                                   variable + " must be finite wherever the methods take it (on and about its place): at " +
                                     where());
          if (std::abs(f0) > 1e-12 * scale || std::abs(f2 - 2. * f1) > 1e-9 * scale)
            throw InvalidParameter(entry, assignment,
                                   variable + " must be proportional to the load factor lambda (the methods scale the "
                                              "whole loading with it): at " + where());
        }
      return [f](Point x) { return f(x, 1.); };
    }

    void read_conditions(const SceneSettings &s, const Places &places, const dealii::Triangulation<2> &tria,
                         conditions::Conditions &out)
    {
      using Kind = conditions::Place::Kind;
      for (const auto &p : parse_entry("Displacement", s.displacement, {"ux", "uy"}))
        {
          conditions::Displacement d;
          d.place = places.find("Displacement", p.text, p.place, {Kind::boundary, Kind::point, Kind::region});
          const auto at = checked_points(d.place, tria, true);
          if (p.values.count("ux"))
            d.ux = linear_field("Displacement", p, "ux", at);
          if (p.values.count("uy"))
            d.uy = linear_field("Displacement", p, "uy", at);
          if (p.values.empty())
            throw InvalidParameter("Displacement", p.text, "names no component: give ux, uy or both");
          out.displacements.push_back(d);
        }
      for (const auto &p : parse_entry("Traction", s.traction, {"tx", "ty", "p"}))
        {
          conditions::Traction t;
          t.place = places.find("Traction", p.text, p.place, {Kind::boundary});
          if (p.values.empty())
            throw InvalidParameter("Traction", p.text, "names no component: give tx, ty or p");
          const auto zero = [](Point) { return 0.; };
          const auto at   = checked_points(t.place, tria, false);
          t.tx = p.values.count("tx") ? linear_field("Traction", p, "tx", at) : zero;
          t.ty = p.values.count("ty") ? linear_field("Traction", p, "ty", at) : zero;
          t.p  = p.values.count("p") ? linear_field("Traction", p, "p", at) : zero;
          out.tractions.push_back(t);
        }
      for (const auto &p : parse_entry("Point force", s.point_force, {"fx", "fy"}))
        {
          conditions::PointForce f;
          f.place = places.find("Point force", p.text, p.place, {Kind::point});
          if (p.values.empty())
            throw InvalidParameter("Point force", p.text, "names no component: give fx, fy or both");
          const Point x = f.place.points.front();
          const std::vector<CheckedPoint> at = {{x, "the vertex"}};
          f.force = {p.values.count("fx") ? linear_field("Point force", p, "fx", at)(x) : 0.,
                     p.values.count("fy") ? linear_field("Point force", p, "fy", at)(x) : 0.};
          out.forces.push_back(f);
        }
      if (out.tractions.empty() && out.forces.empty() &&
          std::none_of(out.displacements.begin(), out.displacements.end(), [](const conditions::Displacement &d) {
            return std::any_of(d.place.points.begin(), d.place.points.end(), [&](Point x) {
              return (d.ux && (*d.ux)(x) != 0.) || (d.uy && (*d.uy)(x) != 0.);
            });
          }))
        throw InvalidParameter("Boundary conditions", "no load",
                               "nothing loads the body: give a Traction, a Point force or a Displacement that lambda "
                               "scales (nonzero at lambda = 1)");
    }

    /// Two displacement conditions prescribing different values of one component at one vertex,
    /// or a point force on a prescribed component.
    void check_conflicts(const conditions::Conditions &c)
    {
      std::map<std::pair<double, double>, std::array<std::pair<std::string, double>, 2>> fixed;
      const auto add = [&](const Point &x, int component, const std::string &name, double value) {
        auto &slot = fixed[{x.x, x.y}][component];
        if (slot.first.empty())
          slot = {name, value};
        else if (std::abs(slot.second - value) > 1e-12 * std::max(std::abs(slot.second), std::abs(value)))
          throw InvalidParameter("Displacement", slot.first + " and " + name,
                                 "both prescribe u" + std::string(component == 0 ? "x" : "y") + " at the vertex " +
                                   to_text(x) + " with different values (" + to_text(slot.second) + " and " +
                                   to_text(value) + " at lambda = 1): one vertex takes one value");
      };
      for (const auto &d : c.displacements)
        for (const auto &x : d.place.points)
          {
            if (d.ux)
              add(x, 0, d.place.name, (*d.ux)(x));
            if (d.uy)
              add(x, 1, d.place.name, (*d.uy)(x));
          }
      for (const auto &f : c.forces)
        for (const auto &x : f.place.points)
          if (const auto it = fixed.find({x.x, x.y}); it != fixed.end())
            for (int k = 0; k < 2; ++k)
              if (!it->second[k].first.empty() && (k == 0 ? f.force.x : f.force.y) != 0.)
                throw InvalidParameter("Point force", f.place.name,
                                       "acts on u" + std::string(k == 0 ? "x" : "y") + " at " + to_text(x) +
                                         ", which the displacement condition on " + it->second[k].first +
                                         " prescribes: a prescribed component takes no force");
    }

    /// Rigid motions (a, b, theta): u = (a - theta (y - y0), b + theta (x - x0)) that every
    /// prescribed component allows; refused naming them (the body would float).
    void check_rigid_motion(const conditions::Conditions &c, const geometry::Body &body)
    {
      const geometry::Box box   = body.bounding_box();
      const Point         o     = {0.5 * (box.x_min + box.x_max), 0.5 * (box.y_min + box.y_max)};
      const double        scale = std::max(box.width(), box.height());
      double              M[3][3] = {};
      const auto          row = [&](double r0, double r1, double r2) {
        const double r[3] = {r0, r1, r2};
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            M[i][j] += r[i] * r[j];
      };
      for (const auto &d : c.displacements)
        for (const auto &x : d.place.points)
          {
            const double X = (x.x - o.x) / scale, Y = (x.y - o.y) / scale;
            if (d.ux)
              row(1., 0., -Y);
            if (d.uy)
              row(0., 1., X);
          }
      // Eigenvectors of the symmetric 3 x 3 M by Jacobi rotations; a zero eigenvalue is a free motion.
      double V[3][3] = {{1., 0., 0.}, {0., 1., 0.}, {0., 0., 1.}};
      for (int sweep = 0; sweep < 50; ++sweep)
        for (int p = 0; p < 3; ++p)
          for (int q = p + 1; q < 3; ++q)
            {
              if (std::abs(M[p][q]) < 1e-300)
                continue;
              const double theta = 0.5 * std::atan2(2. * M[p][q], M[q][q] - M[p][p]);
              const double cs = std::cos(theta), sn = std::sin(theta);
              for (int k = 0; k < 3; ++k)
                {
                  const double mkp = M[k][p], mkq = M[k][q];
                  M[k][p] = cs * mkp - sn * mkq;
                  M[k][q] = sn * mkp + cs * mkq;
                }
              for (int k = 0; k < 3; ++k)
                {
                  const double mpk = M[p][k], mqk = M[q][k];
                  M[p][k] = cs * mpk - sn * mqk;
                  M[q][k] = sn * mpk + cs * mqk;
                }
              for (int k = 0; k < 3; ++k)
                {
                  const double vkp = V[k][p], vkq = V[k][q];
                  V[k][p] = cs * vkp - sn * vkq;
                  V[k][q] = sn * vkp + cs * vkq;
                }
            }
      const double largest = std::max({M[0][0], M[1][1], M[2][2], 1e-300});
      std::string  free;
      for (int k = 0; k < 3; ++k)
        if (M[k][k] <= 1e-10 * largest || M[k][k] <= 0.)
          {
            const double a = V[0][k], b = V[1][k], t = V[2][k];
            std::ostringstream s;
            s << std::setprecision(4);
            if (std::abs(t) < 1e-6)
              s << "translation along (" << a / std::hypot(a, b) << ", " << b / std::hypot(a, b) << ")";
            else
              s << "rotation about " << to_text(Point{o.x - scale * b / t, o.y + scale * a / t});
            free += (free.empty() ? "" : ", ") + s.str();
          }
      if (!free.empty())
        throw InvalidParameter("Displacement", c.displacements.empty() ? "(none)" : "the displacement conditions",
                               "the body is not held against rigid motion, free: " + free +
                                 "; prescribe more components (e.g. ux and uy at one point and uy at another)");
    }

    /// True if vertex k of `line` is an end of it that lies within `tolerance` of `other` (a junction).
    bool junction_end(const geometry::Polyline &line, std::size_t k, const geometry::Polyline &other, double tolerance)
    {
      return (k == 0 || k + 1 == line.size()) && distance_to_polyline(line[k], other) <= tolerance;
    }

    /// The line with its junction ends on `other` pulled back along their segments by a millionth
    /// of the segment: what must neither touch nor cross `other`.
    geometry::Polyline short_of_junctions(geometry::Polyline line, const geometry::Polyline &other, double tolerance)
    {
      const std::size_t last = line.size() - 1;
      if (junction_end(line, last, other, tolerance))
        line[last] = line[last] - 1e-6 * (line[last] - line[last - 1]);
      if (junction_end(line, 0, other, tolerance))
        line[0] = line[0] - 1e-6 * (line[0] - line[1]);
      return line;
    }

    /// The smallest distance between two polylines that do not cross, and the vertex where it is
    /// taken (the nearest points of two disjoint segments include an end of one of them); a
    /// junction end (on the other polyline) does not count.
    std::pair<double, Point> polyline_gap(const geometry::Polyline &a, const geometry::Polyline &b, double tolerance)
    {
      std::pair<double, Point> best{std::numeric_limits<double>::infinity(), Point{}};
      for (const auto &[from, to] : {std::pair{&a, &b}, std::pair{&b, &a}})
        for (std::size_t k = 0; k < from->size(); ++k)
          if (!junction_end(*from, k, *to, tolerance))
            for (std::size_t s = 0; s + 1 < to->size(); ++s)
              if (const double d = geometry::distance_to_segment((*from)[k], (*to)[s], (*to)[s + 1]); d < best.first)
                best = {d, (*from)[k]};
      return best;
    }

    std::vector<geometry::Polyline> read_cracks(const std::string &text, const geometry::Body &body,
                                                const dealii::Triangulation<2> &tria, double tolerance)
    {
      std::vector<geometry::Polyline> cracks;
      if (trim(text).empty())
        return cracks;
      for (const auto &line : split_outside_parentheses(text, '|'))
        {
          geometry::Polyline crack;
          for (const auto &point : split_outside_parentheses(line, ';'))
            {
              double x = 0., y = 0.;
              char   rest = 0;
              if (std::sscanf(point.c_str(), " %lf , %lf %c", &x, &y, &rest) != 2)
                throw InvalidParameter("Initial cracks", trim(line), "\"" + trim(point) + "\" is not a point x,y");
              crack.push_back({x, y});
            }
          if (crack.size() < 2)
            throw InvalidParameter("Initial cracks", trim(line), "a crack needs at least 2 points");
          try
            {
              global::Crack(crack, body, tolerance);
            }
          catch (const InvalidParameter &e)
            {
              // A crack in other units than the mesh lies off the body's box altogether: say where the body is.
              const geometry::Box box = body.bounding_box();
              const bool off_box = std::any_of(crack.begin(), crack.end(), [&](Point p) { return !box.contains(p, tolerance); });
              throw InvalidParameter("Initial cracks", trim(line),
                                     std::string(e.what()) +
                                       (off_box ? " (the body spans " + to_text(box) + ", in metres as every length)" : ""));
            }
          // An end off the boundary by less than a tenth of the cell it lies in was meant as a mouth.
          for (const Point end : {crack.front(), crack.back()})
            {
              const double d = body.clearance(end);
              if (d <= tolerance)
                continue;
              const auto cell =
                dealii::GridTools::find_active_cell_around_point(tria, dealii::Point<2>(end.x, end.y));
              if (cell.state() == dealii::IteratorState::valid && d < 0.1 * cell->diameter())
                throw InvalidParameter("Initial cracks", trim(line),
                                       "the end " + to_text(end) + " is " + to_text(d) +
                                         " m from the boundary: a mouth must lie on the outline or a hole's rim "
                                         "(within " + to_text(tolerance) + " m), a tip at least a tenth of its cell (" +
                                         to_text(0.1 * cell->diameter()) + " m) from it");
            }
          cracks.push_back(crack);
        }
      // Two cracks must keep apart by a tenth of the mesh cell where they come closest (closer,
      // the Heaviside enrichment of one node's support could not tell them apart), except at a
      // junction: an end of one on the other's face, as a crack that grew into another ends.
      for (std::size_t a = 0; a < cracks.size(); ++a)
        for (std::size_t b = a + 1; b < cracks.size(); ++b)
          {
            const std::string        pair = to_text(cracks[a]) + " | " + to_text(cracks[b]);
            const geometry::Polyline short_a = short_of_junctions(cracks[a], cracks[b], tolerance),
                                     short_b = short_of_junctions(cracks[b], cracks[a], tolerance);
            for (std::size_t s = 0; s + 1 < short_a.size(); ++s)
              if (geometry::segment_crosses_polyline(short_a[s], short_a[s + 1], short_b))
                throw InvalidParameter("Initial cracks", pair,
                                       "two cracks touch or cross: an end of one may lie on the other's face (a "
                                       "junction), no more; give a crack that crosses another as two");
            const auto [gap, at] = polyline_gap(cracks[a], cracks[b], tolerance);
            const auto cell = dealii::GridTools::find_active_cell_around_point(tria, dealii::Point<2>(at.x, at.y));
            const double limit = cell.state() == dealii::IteratorState::valid ? 0.1 * cell->diameter() : 0.;
            if (gap < limit)
              throw InvalidParameter("Initial cracks", pair,
                                     "two cracks come within " + to_text(gap) + " m of each other at " + to_text(at) +
                                       ", less than a tenth of the mesh cell there (" + to_text(limit) +
                                       " m): move them apart or give them as one polyline");
          }
      return cracks;
    }

    /// "<place>: <sign><component>", the component one of `components`.
    void parse_report(const std::string &entry, const std::string &text, const Places &places,
                      const std::array<std::string, 2> &components, conditions::Place &place, int &component,
                      double &sign)
    {
      const auto colon = text.find(':');
      std::string c    = colon == std::string::npos ? "" : trim(text.substr(colon + 1));
      sign             = 1.;
      if (!c.empty() && c[0] == '-')
        sign = -1., c = trim(c.substr(1));
      if (colon == std::string::npos || (c != components[0] && c != components[1]))
        throw InvalidParameter(entry, text,
                               "must be \"<name>: " + components[0] + "\" (or " + components[1] + ", with an optional -)");
      component = c == components[0] ? 0 : 1;
      place     = places.find(entry, text, trim(text.substr(0, colon)),
                              {conditions::Place::Kind::boundary, conditions::Place::Kind::point});
    }
  } // namespace

  void make_output_directory(const std::string &entry, const std::string &directory)
  {
    if (directory.empty())
      return;
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (!error && !std::filesystem::is_directory(directory))
      error = std::make_error_code(std::errc::not_a_directory);
    if (!error)
      {
        const std::string probe = directory + "/.pumpd-write-test";
        errno = 0;
        if (!std::ofstream(probe))
          error = std::error_code(errno != 0 ? errno : EACCES, std::generic_category());
        std::error_code ignored;
        std::filesystem::remove(probe, ignored);
      }
    if (error)
      throw InvalidParameter(entry, directory,
                             "cannot be used (" + error.message() +
                               "): a folder this user can create and write to, or empty to write nothing");
    reserve_output_directory(entry, directory);
  }

  namespace
  {
    /// A reference path must lie about the body (a path in millimetres, say, does not) and have a
    /// length.
    void check_reference_path(const std::string &file, const Scene &scene)
    {
      const auto &path = scene.reference_path;
      if (path.empty())
        return;
      const auto  &box    = scene.body.bounding_box();
      const double margin = 0.1 * std::hypot(box.width(), box.height());
      for (const Point p : path)
        if (!box.contains(p, margin))
          throw InvalidParameter("Reference path", file,
                                 "the point " + to_text(p) +
                                   " lies outside the body's bounding box by more than a tenth of its diagonal (x,y in "
                                   "metres, as the mesh)");
      if (geometry::length(path) <= 0.)
        throw InvalidParameter("Reference path", file, "has zero length: its points coincide");
    }
  } // namespace

  namespace
  {
    /// Warns where the body's size lies outside that of solid specimens and structures in metres
    /// (1 mm to 10 m across): a mesh drawn in millimetres, or in metres for a scene in
    /// millimetres, still runs, at a size a thousand times off.
    void warn_of_scale(const geometry::Body &body, std::ostream *progress)
    {
      const geometry::Box box  = body.bounding_box();
      const double        size = std::max(box.width(), box.height());
      if (progress == nullptr || (size >= 1e-3 && size <= 10.))
        return;
      *progress << "warning: Mesh file: the body measures " << pumpd::to_text(size, 3) << " m across ("
                << to_text(box) << "); every length of a scene is in metres (the mesh, Initial cracks, the "
                << "sections' lengths): a mesh drawn in millimetres needs Mesh.ScalingFactor = 0.001 in its .geo\n";
      progress->flush();
    }
  } // namespace

  Scene build_scene(const SceneSettings &s, std::ostream *progress)
  {
    Scene scene;
    scene.mesh_file        = s.mesh_file;
    scene.material         = s.material;
    scene.output_directory = s.output_directory;
    if (!s.reference_path.empty())
      scene.reference_path = read_path(s.reference_path);
    if (s.mesh_file.empty())
      throw InvalidParameter("Mesh file", "(empty)", "a scene needs a mesh: a gmsh .geo or .msh file");

    auto tria  = std::make_shared<dealii::Triangulation<2>>();
    auto names = global::read_mesh(s.mesh_file, *tria, s.mesh_size, s.max_cells, progress);
    try
      {
        scene.body = global::body_of(*tria);
      }
    catch (const InvalidParameter &e)
      {
        throw InvalidParameter("Mesh file", s.mesh_file, e.what());
      }
    scene.mesh = tria;
    warn_of_scale(scene.body, progress);
    const Places places(tria, std::move(names));
    read_conditions(s, places, *tria, scene.conditions);
    check_conflicts(scene.conditions);
    check_rigid_motion(scene.conditions, scene.body);
    const geometry::Box box = scene.body.bounding_box();
    scene.cracks            = read_cracks(s.initial_cracks, scene.body, *tria, 1e-8 * std::max(box.width(), box.height()));

    if (trim(s.report_load) != "lambda")
      {
        scene.report.load_is_lambda = false;
        parse_report("Report load", s.report_load, places, {{"fx", "fy"}}, scene.report.load_place,
                     scene.report.load_component, scene.report.load_sign);
        const bool held = std::any_of(scene.conditions.displacements.begin(), scene.conditions.displacements.end(),
                                      [&](const conditions::Displacement &d) {
                                        return d.place.name == scene.report.load_place.name &&
                                               (scene.report.load_component == 0 ? d.ux.has_value() : d.uy.has_value());
                                      });
        if (!held)
          throw InvalidParameter("Report load", s.report_load,
                                 "a reaction needs a displacement condition on that place and component");
        scene.report.load_name = trim(s.report_load);
      }
    if (!trim(s.report_displacement).empty())
      {
        scene.report.work_conjugate = false;
        parse_report("Report displacement", s.report_displacement, places, {{"ux", "uy"}},
                     scene.report.displacement_place, scene.report.displacement_component,
                     scene.report.displacement_sign);
        scene.report.displacement_name = trim(s.report_displacement);
      }
    check_reference_path(s.reference_path, scene);
    return scene;
  }

  std::uint64_t geometry_fingerprint(const Scene &scene)
  {
    std::string bytes;
    const auto  add = [&bytes](const auto value) {
      bytes.append(reinterpret_cast<const char *>(&value), sizeof(value));
    };
    for (const auto &v : scene.mesh->get_vertices())
      {
        add(v[0]);
        add(v[1]);
      }
    for (const auto &cell : scene.mesh->active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        add(std::uint64_t(cell->vertex_index(v)));
    for (const auto &crack : scene.cracks)
      {
        add(std::uint64_t(crack.size()));
        for (const auto &p : crack)
          {
            add(p.x);
            add(p.y);
          }
      }
    return fnv1a(bytes);
  }

  geometry::Polyline read_path(const std::string &file)
  {
    if (const auto kind = special_file_kind(file); !kind.empty())
      throw InvalidParameter("Reference path", file, "is " + kind + ", not a regular file (a CSV of x,y lines)");
    std::ifstream in(file);
    if (!in)
      throw InvalidParameter("Reference path", file, "cannot be opened (relative paths start at the current directory)");
    geometry::Polyline path;
    std::string        line;
    while (std::getline(in, line))
      {
        if (line.empty() || line[0] == '#' || std::isalpha(static_cast<unsigned char>(line[0])))
          continue;
        Point p;
        if (std::sscanf(line.c_str(), "%lf,%lf", &p.x, &p.y) != 2)
          throw InvalidParameter("Reference path", file, "line \"" + line + "\" is not x,y");
        path.push_back(p);
      }
    if (path.size() < 2)
      throw InvalidParameter("Reference path", file, "needs at least 2 points x,y");
    return path;
  }

} // namespace pumpd::coupling
