// The global solver's mesh: read a gmsh mesh (.msh, or a .geo meshed on the fly by the gmsh
// executable) into a quadrilateral deal.II triangulation, and check what a scene relies on
// (boundary ids, vertices at supports and load points). Sources: meshes/*.geo.
//
// Conventions (meshes/*.geo): Physical Curve tags become boundary ids (1 bottom, 2 right, 3 top,
// 4 left, 5 holes), the Physical Surface tag becomes the material id. Errors are
// pumpd::InvalidParameter ("<name> = <value>: <allowed>", local/error.h).
#pragma once

#include <deal.II/base/types.h>

#include <string>
#include <vector>

#include "geometry.h"

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace pumpd::global
{
  /// Replaces the content of `tria` with the mesh in `file`:
  /// - `*.msh` (gmsh ASCII format 2 or 4) is read with dealii::GridIn<2>::read_msh;
  /// - `*.geo` is first meshed in 2D by the gmsh executable (the one named by the environment
  ///   variable PUMPD_GMSH, else `gmsh` on the PATH) into a temporary msh2 file; when
  ///   `characteristic_length` > 0 it is passed as `-setnumber h <characteristic_length>`
  ///   (meshes/*.geo: quad edge length in m). Ignored for `.msh`.
  /// Throws InvalidParameter: "Mesh file" (missing, unknown extension, unreadable, cells that
  /// are not quadrilaterals, gmsh not found or failing, with its exit status and first error),
  /// "Mesh characteristic length" (negative or not finite).
  void read_mesh(const std::string &file, dealii::Triangulation<2, 2> &tria,
                 double characteristic_length = 0.);

  /// Throws InvalidParameter ("Mesh boundary id") naming the first of `ids` that no boundary
  /// face of `tria` carries.
  void require_boundary_ids(const dealii::Triangulation<2, 2>             &tria,
                            const std::vector<dealii::types::boundary_id> &ids);

  /// Index of the used vertex of `tria` nearest to `p`, if it is within `tolerance` (m) of `p`;
  /// throws InvalidParameter ("Mesh vertex") otherwise, naming the nearest vertex.
  unsigned int find_vertex(const dealii::Triangulation<2, 2> &tria, const geometry::Point &p,
                           double tolerance);
} // namespace pumpd::global
