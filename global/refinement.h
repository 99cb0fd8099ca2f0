// Adaptive refinement (hanging nodes): geometric, near crack tips (to resolve the tip region of a
// coarse body mesh), or driven by an error indicator (EnrichedElasticity::error_indicators()).
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

  /// Refines the `fraction` of the active cells with the largest indicators (one value per active
  /// cell, in active_cell_index order; deal.II's GridRefinement::refine_and_coarsen_fixed_number,
  /// no coarsening). The enrichment must be set up again afterwards (EnrichedElasticity::setup()
  /// on a new object or after the mesh change).
  void refine_by_indicator(dealii::Triangulation<2, 2> &triangulation, const std::vector<double> &indicator,
                           double fraction);
} // namespace pumpd::global
