// EnrichedElasticity: displacement at many points through a cached interpolation matrix
// (../shared/notes/xfem-in-deal.ii-9.4.md: GridTools::Cache + a cell hint, then u = P U).
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <cmath>
#include <optional>

#include "elasticity_impl.h"
#include "error.h"

namespace pumpd::global
{
  using namespace dealii;

  void EnrichedElasticity::Impl::prepare_point_evaluation(const std::vector<Point> &points,
                                                          const std::vector<int>   &side_hint)
  {
    GridTools::Cache<2> cache(tria, mapping);
    auto                hint = tria.begin_active();
    PointMatrix         P;
    P.row_start.push_back(0);
    for (std::size_t i = 0; i < points.size(); ++i)
      {
        std::pair<Triangulation<2>::active_cell_iterator, dealii::Point<2>> found;
        try
          {
            found = GridTools::find_active_cell_around_point(cache, to_dealii(points[i]), hint);
          }
        catch (...)
          {
            found.first = tria.end();
          }
        // A point of the body may lie just outside the mesh: between a curved outline's arc and
        // the chord of a boundary face (the sagitta, face length^2 / (8 R), a few percent of the
        // face). It is evaluated in the boundary cell next to it, whose fields are extended over
        // up to a tenth of the cell.
        if (found.first == tria.end())
          try
            {
              found = GridTools::find_active_cell_around_point(cache, to_dealii(points[i]), hint, {}, 0.1);
            }
          catch (...)
            {
              found.first = tria.end();
            }
        if (found.first == tria.end())
          throw InvalidParameter("Evaluation point",
                                 "(" + std::to_string(points[i].x) + ", " + std::to_string(points[i].y) + ")",
                                 "must lie inside the mesh");
        hint = found.first;
        const DoFHandler<2>::active_cell_iterator cell(&tria, found.first->level(), found.first->index(), &dof_handler);
        const double xi = found.second[0], eta = found.second[1];
        // Q1 shape functions at the reference point, deal.II's vertex order.
        const std::array<double, 4> N = {{(1. - xi) * (1. - eta), xi * (1. - eta), (1. - xi) * eta, xi * eta}};
        Sides side;
        sides_of(points[i], side_hint.empty() || side_hint[i] >= 0 ? 1 : -1, 1e-12 * cell->diameter(), side);
        std::vector<std::optional<BranchValues>>     branch(2 * stride());
        std::vector<std::pair<unsigned int, double>> row;
        for (const auto &fn : local_functions(cell))
          {
            const int s = side[fn.crack];
            double    g = 1.;
            auto     &b = branch[2 * fn.crack + fn.tip];
            if (fn.kind == 0)
              g = s - fn.shift;
            else if (fn.kind > 0)
              {
                if (!b)
                  b = branch_on_side(cracks[fn.crack], points[i], fn.tip, s);
                g = b->value[fn.kind - 1] - fn.shift;
              }
            double phi = 0.;
            for (unsigned int v = 0; v < 4; ++v)
              phi += fn.weight[v] * N[v] * g;
            if (phi != 0.)
              row.push_back({fn.dof, phi});
          }
        for (unsigned int c = 0; c < 2; ++c)
          {
            for (const auto &[dof, phi] : row)
              {
                P.column.push_back(dof + c);
                P.value.push_back(phi);
              }
            P.row_start.push_back(P.column.size());
          }
      }
    point_matrix = std::move(P);
  }

  std::vector<Point> EnrichedElasticity::Impl::evaluate_points() const
  {
    const auto        &P = point_matrix;
    const std::size_t  n = (P.row_start.size() - 1) / 2;
    std::vector<Point> u(n);
    for (std::size_t i = 0; i < n; ++i)
      {
        double ux = 0., uy = 0.;
        for (unsigned int k = P.row_start[2 * i]; k < P.row_start[2 * i + 1]; ++k)
          ux += P.value[k] * solution(P.column[k]);
        for (unsigned int k = P.row_start[2 * i + 1]; k < P.row_start[2 * i + 2]; ++k)
          uy += P.value[k] * solution(P.column[k]);
        u[i] = {ux, uy};
      }
    return u;
  }
} // namespace pumpd::global
