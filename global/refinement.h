// Adaptive refinement near crack tips (hanging nodes), for refinement studies and to resolve
// the tip region of a coarse body mesh.
#pragma once

#include <vector>

#include "geometry.h"

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace pumpd::global
{
  /// Refines, `levels` times, every active cell that comes within `radius` of one of the points
  /// (the radius is kept fixed, so each level halves the cells inside it).
  void refine_near(dealii::Triangulation<2, 2> &triangulation, const std::vector<geometry::Point> &points,
                   double radius, unsigned int levels);
} // namespace pumpd::global
