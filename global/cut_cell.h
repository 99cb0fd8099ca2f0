// Integration on cells the crack cuts (DESIGN.md, global/: "cut cells integrated on sub-cells
// on each side of the crack; tip cells with a quadrature that handles the 1/sqrt(r) gradients").
//
// Works in the reference square. The unit square is split by the lines of the crack pieces that
// cross the cell into convex polygons (no polygon then contains a discontinuity); a polygon that
// touches a crack tip is fanned from the tip, so every triangle there has the tip as vertex 0 and
// gets a Duffy rule (singular vertex 0, exact for 1/r integrands); the other polygons are fanned
// from a vertex and get Gauss simplex rules.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>

#include <array>
#include <vector>

namespace pumpd::global
{
  using RefPoint = dealii::Point<2>;

  struct SubTriangle
  {
    std::array<RefPoint, 3> vertex;
    bool                    singular = false; ///< vertex 0 is a crack tip
  };

  /// Splits the unit square by the crack pieces (segments in reference coordinates) and fans
  /// polygons that contain one of the tips from that tip. Slivers of zero area are dropped.
  std::vector<SubTriangle> subdivide_unit_square(const std::vector<std::array<RefPoint, 2>> &pieces,
                                                 const std::vector<RefPoint>               &tips);

  /// Quadrature on the unit square made of one rule per sub-triangle: Gauss simplex of order
  /// `order` (collapsed Gauss above 4), or Duffy (beta = 1, `order` points each way, the singular
  /// vertex at the tip) on singular triangles. The triangle
  /// each point comes from is recorded in `triangle_of_point` (same length as the rule).
  dealii::Quadrature<2> sub_triangle_quadrature(const std::vector<SubTriangle> &triangles, unsigned int order,
                                                std::vector<unsigned int> &triangle_of_point);
} // namespace pumpd::global
