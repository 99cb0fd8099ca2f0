#include "refinement.h"

#include <deal.II/grid/tria.h>

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
} // namespace pumpd::global
