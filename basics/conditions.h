// What a scene prescribes on its body (DESIGN.md, "The scene and the methods"). Each condition
// acts on a named place of the mesh: a boundary (a gmsh Physical Curve), a point (a Physical
// Point: mesh vertices) or a region (a Physical Surface). Its values are the scene's expressions
// of x, y and the load factor lambda, which are linear in lambda (checked where the scene is
// read), so a condition holds them per unit lambda: the value at lambda is lambda times the
// field. Two adapters hand the conditions on: global/global_conditions.h (deal.II constraints and loads)
// and local/pd_conditions.h (PD prescribed regions).
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geometry.h"

namespace pumpd::conditions
{
  /// A value per unit load factor, as a function of the position.
  using Field = std::function<double(geometry::Point)>;

  /// A named place of the mesh.
  struct Place
  {
    enum class Kind
    {
      boundary,
      point,
      region
    } kind = Kind::boundary;
    std::string                                 name;
    unsigned int                                id = 0;  ///< boundary id, or material id of a region
    std::vector<geometry::Point>                points;  ///< a point's vertices; a boundary's or region's vertices
    std::vector<std::array<geometry::Point, 2>> edges;   ///< a boundary's faces
    geometry::Box                               box;     ///< bounding box of the place
    std::function<bool(geometry::Point)>        inside;  ///< a region: true in its cells
  };

  /// Displacement components; a component without a field is free.
  struct Displacement
  {
    Place                place;
    std::optional<Field> ux, uy;
  };

  /// Traction on a boundary: t = (tx, ty) - p n, n the outward unit normal (p > 0 presses on the body).
  struct Traction
  {
    Place place;
    Field tx, ty, p;
  };

  /// A force on a point [N per m of thickness].
  struct PointForce
  {
    Place           place;
    geometry::Point force; ///< per unit load factor
  };

  struct Conditions
  {
    std::vector<Displacement> displacements;
    std::vector<Traction>     tractions;
    std::vector<PointForce>   forces;
  };

  /// True if the place lies within `radius` of x: a boundary's face or a point's vertex within
  /// that distance, or x in a region's cells.
  bool near(const Place &place, geometry::Point x, double radius);
  /// The place of every condition: the displacements', then the tractions', then the point forces'.
  std::vector<const Place *> places(const Conditions &conditions);
  /// True if x lies within radius of the place of any of the conditions.
  bool near_any(const Conditions &conditions, geometry::Point x, double radius);
} // namespace pumpd::conditions
