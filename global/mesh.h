// The global solver's mesh: read a gmsh mesh (.msh, or a .geo meshed on the fly by the gmsh
// executable) into a quadrilateral deal.II triangulation with the names of its physical groups,
// and the body it covers. Sources: meshes/*.geo.
//
// A scene names boundaries, points and regions by their gmsh physical names: a Physical Curve's
// tag is the boundary id of its faces, a Physical Surface's tag the material id of its cells, a
// Physical Point names mesh vertices. Errors are pumpd::InvalidParameter ("<name> = <value>:
// <allowed>", basics/error.h).
#pragma once

#include <deal.II/base/types.h>

#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include "body.h"

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace pumpd::global
{
  /// The physical groups of a mesh by name: boundary ids of curves, material ids of surfaces,
  /// the vertex positions of points.
  struct MeshNames
  {
    std::map<std::string, dealii::types::boundary_id>      boundaries;
    std::map<std::string, dealii::types::material_id>      regions;
    std::map<std::string, std::vector<geometry::Point>>    points;
  };

  /// Replaces the content of `tria` with the mesh in `file` and returns its physical names:
  /// - `*.msh` (gmsh ASCII format 2 or 4; named points need format 2) is read with
  ///   dealii::GridIn<2>::read_msh;
  /// - `*.geo` is first meshed in 2D by the gmsh executable (the one named by the environment
  ///   variable PUMPD_GMSH, else `gmsh` on the PATH) into a temporary msh2 file; when
  ///   `characteristic_length` > 0 it is passed as `-setnumber h <characteristic_length>`
  ///   (meshes/*.geo: quad edge length in m). Ignored for `.msh`. When the environment variable
  ///   PUMPD_MESH_CACHE names a directory, the mesh is kept there and read back, without gmsh,
  ///   by a later run that meshes the same sources (mesh_sources_hash) at the same size with the
  ///   same gmsh program; a .geo whose sources are unknown is meshed every time.
  /// With max_cells > 0, a .geo whose estimated cell count (bounding box area / h^2, from gmsh's
  /// unrolled geometry, before meshing; not on a cache hit) or a mesh whose cell count exceeds
  /// it is refused, and so is one whose global problem would not fit this machine's memory
  /// (check_memory).
  /// With `progress`, while gmsh runs a line there every 10 s: "meshing <file>: <seconds> s, gmsh
  /// log: <its last line>". A signal that interrupts gmsh ends read_mesh with pumpd::Interrupted
  /// (basics/program.h), gmsh and its temporary directory gone.
  /// Throws InvalidParameter: "Mesh file" (missing, not a regular file, unknown extension,
  /// unreadable, cells that are not quadrilaterals, gmsh not found or failing, with its exit status
  /// and first error), "Mesh size" (negative or not finite, or too many cells).
  MeshNames read_mesh(const std::string &file, dealii::Triangulation<2, 2> &tria, double characteristic_length = 0.,
                      double max_cells = 0., std::ostream *progress = nullptr);

  /// A hash (hex) of what a mesh file is made of: a .geo's text, the option file gmsh merges with
  /// it (<file>.opt) and the files it reads (Include, Merge, ShapeFromFile), recursively; any
  /// other file's bytes. Empty if a .geo names a file it reads by an expression (StrCat, ...).
  std::string mesh_sources_hash(const std::string &file);

  /// The peak memory of a run with the enriched global problem on a mesh of `cells` quadrilaterals
  /// [bytes]: the program's own 0.25 GB and 250 n log2 n with n = 2 cells unknowns, the growth of a
  /// sparse direct factorization's fill on a 2D mesh (nested dissection), its constant fitted to
  /// measured runs (docs/global-solver.md).
  double estimated_global_bytes(double cells);

  /// Refuses a mesh of `cells` cells whose global problem (estimated_global_bytes) needs more
  /// than the 0.8 available_memory() it may take: throws InvalidParameter(name, value, what + the
  /// sizes + remedy).
  void check_memory(double cells, const std::string &name, const std::string &value, const std::string &what,
                    const std::string &remedy);

  /// The body the mesh covers: its boundary faces as closed curves (body_from_edges).
  geometry::Body body_of(const dealii::Triangulation<2, 2> &tria);

} // namespace pumpd::global
