// What the beam scenes (lefm-growth, global-local) share: the body read from the mesh, the
// supports and load checked against its vertices, refinement along the crack, rays to the
// outline and the holes, and the files a run writes for people (paths, body, VTU series).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "crack.h"
#include "crack_extraction.h"
#include "geometry.h"
#include "model.h"

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace pumpd::global
{
  class EnrichedElasticity;
}

namespace pumpd::coupling
{
  std::string to_text(geometry::Point p);
  std::string to_text(const geometry::Polyline &line);

  /// The body of the mesh: the bounding box as outline, and each connected ring of faces with
  /// boundary id 5 (meshes/*.geo: holes) as the circle about its vertices' centroid through the
  /// farthest of them (the mesh's hole is a polygon inscribed in that circle).
  geometry::Body body_of(const dealii::Triangulation<2, 2> &tria);

  /// A beam scene's mesh read into tria (boundary ids 1-4 required: the outline), its body, and
  /// the named points (supports, load) checked to be mesh vertices.
  geometry::Body read_beam(dealii::Triangulation<2, 2> &tria, const std::string &mesh_file, double mesh_size,
                           const std::vector<std::pair<std::string, geometry::Point>> &named_points);

  /// Throws InvalidParameter(name, ...) for each named point that is not a mesh vertex.
  void require_vertices(const dealii::Triangulation<2, 2> &tria,
                        const std::vector<std::pair<std::string, geometry::Point>> &named_points);

  /// The initial crack checked against the body: InvalidParameter("Initial crack", ...) if not.
  global::Crack initial_crack(const geometry::Polyline &vertices, const geometry::Body &body);

  /// The cells within `radius` of a tip are refined until they reach `levels` (the mesh file's
  /// cells are level 0): along a growing crack the mesh is refined once, never coarsened.
  void refine_at_tips(dealii::Triangulation<2, 2> &tria, const std::vector<global::Tip> &tips, double radius,
                      unsigned int levels);

  /// Distance along the unit ray x + t e, t >= 0, from x inside the box to its boundary.
  double distance_to_outline(geometry::Point x, geometry::Point e, const geometry::Box &b);
  /// First t >= 0 with |x + t e - c| = R for the unit e (0 if x is inside the circle, infinity
  /// if the ray misses it).
  double distance_to_circle(geometry::Point x, geometry::Point e, geometry::Point c, double R);

  /// Distance from x to the nearest hole's circle or outline edge.
  double clearance(geometry::Point x, const geometry::Body &body);

  /// The PD damage on the lattice (crack extraction's input), NaN where there is no material.
  DamageField damage_field(const local::PdModel &model, const local::State &s);

  /// Where a grown crack path ends its growth: cut where it first comes within `margin` of a hole
  /// (segments from first_new - 1 on: the new ones), or extended to the outline when its last
  /// segment, continued, meets it within `reach`, or to a hole (its margin) within `hole_reach`:
  /// in the PD box a ligament shorter than a horizon is spanned by every bond, so it is not
  /// resolved and a tip heading into a hole that close has reached it. reason: "" while the tip
  /// goes on.
  struct Arrival
  {
    geometry::Polyline path;
    std::string        reason;
  };
  Arrival arrive(geometry::Polyline path, const geometry::Body &body, double margin, double reach,
                 std::size_t first_new = 0, double hole_reach = 0.);

  /// Reference path (x, y per line; lines starting with '#' or a letter are skipped). Throws
  /// InvalidParameter("Published path", ...) if it cannot be read.
  geometry::Polyline read_path(const std::string &file);
  void               write_path(const std::string &file, const geometry::Polyline &path);

  /// body.csv for scripts/plot_crack_path.py: outline and holes as bounding boxes (a hole is the
  /// circle inscribed in its box), the named points (supports, load) as points (min = max).
  void write_body(const std::string &file, const geometry::Body &body,
                  const std::vector<std::pair<std::string, geometry::Point>> &points);

  /// A growing series of <name>_NNN.vtu of the global solution, indexed by <name>.pvd (rewritten
  /// at each add).
  class GlobalVtuSeries
  {
  public:
    GlobalVtuSeries(std::string directory, std::string name = "global");
    void add(const global::EnrichedElasticity &solution, std::size_t step);

  private:
    std::string                                      directory, name;
    std::vector<std::pair<std::size_t, std::string>> entries;
  };
} // namespace pumpd::coupling
