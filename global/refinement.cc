#include "refinement.h"

#include <deal.II/grid/grid_refinement.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <stdexcept>

namespace pumpd::global
{
  void refine_near(dealii::Triangulation<2, 2> &tria, const std::vector<geometry::Point> &points, double radius,
                   unsigned int levels)
  {
    for (unsigned int l = 0; l < levels; ++l)
      {
        for (const auto &cell : tria.active_cell_iterators())
          for (const auto &p : points)
            if (cell->center().distance(dealii::Point<2>(p.x, p.y)) < radius + 0.5 * cell->diameter())
              cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
      }
  }

  void refine_by_indicator(dealii::Triangulation<2, 2> &tria, const std::vector<double> &indicator, double fraction)
  {
    if (indicator.size() != tria.n_active_cells())
      throw std::invalid_argument("refine_by_indicator: one indicator per active cell expected");
    dealii::Vector<double> eta(indicator.begin(), indicator.end());
    dealii::GridRefinement::refine_and_coarsen_fixed_number(tria, eta, fraction, 0.);
    tria.execute_coarsening_and_refinement();
  }
} // namespace pumpd::global
