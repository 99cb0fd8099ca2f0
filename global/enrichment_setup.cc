// EnrichedElasticity::setup: which cells the crack cuts, which nodes are enriched and how, the
// numbering of the unknowns, the constraints and the sparsity pattern.
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "elasticity_impl.h"
#include "error.h"

namespace pumpd::global
{
  using namespace dealii;

  namespace
  {
    using Cell = DoFHandler<2>::active_cell_iterator;

    /// Cell corners in counter-clockwise order (deal.II numbers them lexicographically).
    std::array<Point, 4> corners(const Cell &cell)
    {
      return {{to_point(cell->vertex(0)), to_point(cell->vertex(1)), to_point(cell->vertex(3)),
               to_point(cell->vertex(2))}};
    }

    /// The part of segment [a, b] inside the convex polygon (Cyrus-Beck); false if none.
    bool clip_segment(Point a, Point b, const std::array<Point, 4> &poly, Point &p, Point &q)
    {
      double       t0 = 0., t1 = 1.;
      const Point  d  = b - a;
      for (std::size_t e = 0; e < 4; ++e)
        {
          const Point  edge   = poly[(e + 1) % 4] - poly[e];
          const Point  inward = {-edge.y, edge.x};
          const double num    = dot(inward, a - poly[e]);
          const double den    = dot(inward, d);
          if (std::abs(den) < 1e-300)
            {
              if (num < 0.)
                return false;
              continue;
            }
          const double t = -num / den;
          if (den > 0.)
            t0 = std::max(t0, t);
          else
            t1 = std::min(t1, t);
        }
      if (t1 - t0 <= 1e-12)
        return false;
      p = a + t0 * d;
      q = a + t1 * d;
      return true;
    }

    bool inside(Point x, const std::array<Point, 4> &poly, double tol)
    {
      for (std::size_t e = 0; e < 4; ++e)
        {
          const Point edge = poly[(e + 1) % 4] - poly[e];
          if (cross(edge, x - poly[e]) < -tol * geometry::norm(edge))
            return false;
        }
      return true;
    }

    /// The point of the cell's boundary nearest to x (x outside the cell).
    Point nearest_on_polygon(Point x, const std::array<Point, 4> &poly)
    {
      Point  best;
      double d = 1e300;
      for (std::size_t e = 0; e < 4; ++e)
        {
          const Point  a = poly[e], ab = poly[(e + 1) % 4] - a;
          const double t = std::clamp(dot(x - a, ab) / dot(ab, ab), 0., 1.);
          const Point  p = a + t * ab;
          if (geometry::norm(x - p) < d)
            {
              d    = geometry::norm(x - p);
              best = p;
            }
        }
      return best;
    }

    RefPoint to_unit(const MappingQ1<2> &mapping, const Cell &cell, Point x)
    {
      RefPoint r = mapping.transform_real_to_unit_cell(cell, to_dealii(x));
      for (unsigned int d = 0; d < 2; ++d)
        r[d] = std::clamp(r[d], 0., 1.);
      return r;
    }
  } // namespace

  unsigned int EnrichedElasticity::Impl::count(NodeKind k) const
  {
    return std::count(kind.begin(), kind.end(), k);
  }

  void EnrichedElasticity::Impl::setup()
  {
    dof_handler.distribute_dofs(fe);
    AffineConstraints<double> hanging;
    DoFTools::make_hanging_node_constraints(dof_handler, hanging);
    hanging.close();
    support.resize(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support);

    // Nodes and the parents of every scalar dof.
    std::vector<int> node_of(dof_handler.n_dofs(), -1);
    nodes.clear();
    for (unsigned int s = 0; s < dof_handler.n_dofs(); ++s)
      if (!hanging.is_constrained(s))
        {
          node_of[s] = nodes.size();
          nodes.push_back(s);
        }
    parents.assign(dof_handler.n_dofs(), {});
    for (unsigned int s = 0; s < dof_handler.n_dofs(); ++s)
      if (node_of[s] >= 0)
        parents[s] = {{unsigned(node_of[s]), 1.}};
      else
        for (const auto &[p, w] : *hanging.get_constraint_entries(s))
          parents[s].push_back({unsigned(node_of[p]), w});

    const unsigned int n_nodes = nodes.size();
    kind.assign(n_nodes, NodeKind::standard);
    node_tip.assign(n_nodes, 0);
    node_side.assign(n_nodes, 1);
    node_branch.assign(n_nodes, {});
    cells.assign(tria.n_active_cells(), CellData());
    const double diameter_scale = GridTools::minimal_cell_diameter(tria);

    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    if (crack)
      {
        for (const auto &v : crack->vertices())
          {
            bool in_mesh = true;
            try
              {
                in_mesh = GridTools::find_active_cell_around_point(mapping, tria, to_dealii(v)).first.state() ==
                          IteratorState::valid;
              }
            catch (...)
              {
                in_mesh = false;
              }
            if (!in_mesh)
              throw InvalidParameter("Crack vertex", "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ")",
                                     "must lie inside the mesh");
          }

        // Pass 1: crack pieces and tips per cell; tip nodes.
        const auto &vertices = crack->vertices();
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            CellData  &data = cells[cell->active_cell_index()];
            const auto poly = corners(cell);
            std::vector<std::array<RefPoint, 2>> pieces;
            for (std::size_t s = 0; s + 1 < vertices.size(); ++s)
              {
                Point p, q;
                if (clip_segment(vertices[s], vertices[s + 1], poly, p, q))
                  pieces.push_back({{to_unit(mapping, cell, p), to_unit(mapping, cell, q)}});
              }
            // Tips in the cell, and tips within one cell diameter of it (their nearest point of
            // the cell): sub-triangles are fanned from these points and get Duffy rules, so the
            // 1/sqrt(r) gradients are integrated almost-polar wherever they are (nearly) singular.
            std::vector<RefPoint> tips, near_tips;
            for (const auto &t : crack->tips())
              if (inside(t.position, poly, 1e-12))
                tips.push_back(to_unit(mapping, cell, t.position));
              else
                {
                  const Point nearest = nearest_on_polygon(t.position, poly);
                  if (geometry::norm(t.position - nearest) < cell->diameter())
                    near_tips.push_back(to_unit(mapping, cell, nearest));
                }
            data.cut     = !pieces.empty();
            data.has_tip = !tips.empty();
            data.side    = crack->side(to_point(cell->center()));
            near_tips.insert(near_tips.end(), tips.begin(), tips.end());
            if (data.cut || !near_tips.empty())
              data.triangles = subdivide_unit_square(pieces, near_tips);
            data.subdivided = !data.triangles.empty();
            if (data.has_tip)
              {
                if (settings.tip_radius < cell->diameter())
                  throw InvalidParameter("Tip enrichment radius", std::to_string(settings.tip_radius),
                                         "must be at least the diameter of the cell at the tip (" +
                                           std::to_string(cell->diameter()) + " m)");
                cell->get_dof_indices(dofs);
                for (auto s : dofs)
                  for (const auto &pw : parents[s])
                    kind[pw.first] = NodeKind::tip;
              }
          }
        for (unsigned int p = 0; p < n_nodes; ++p)
          {
            const Point x = to_point(support[nodes[p]]);
            node_tip[p]   = crack->nearest_tip(x);
            if (geometry::norm(x - crack->tips()[node_tip[p]].position) <= settings.tip_radius)
              kind[p] = NodeKind::tip;
          }

        // Pass 2: quadrature of cut cells, areas of each side in every node's support.
        std::vector<double> area_plus(n_nodes, 0.), area_minus(n_nodes, 0.);
        std::vector<char>   support_cut(n_nodes, 0), support_tip(n_nodes, 0);
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            CellData &data = cells[cell->active_cell_index()];
            cell->get_dof_indices(dofs);
            for (auto s : dofs)
              for (const auto &pw : parents[s])
                data.tip_enriched |= kind[pw.first] == NodeKind::tip;
            for (const auto &tip : crack->tips())
              data.near_tip |= geometry::norm(to_point(cell->center()) - tip.position) < 2.5 * cell->diameter();
            double plus = 0., minus = 0.;
            if (data.subdivided)
              {
                data.quadrature = sub_triangle_quadrature(
                  data.triangles, data.tip_enriched && data.near_tip ? settings.tip_order : settings.cut_order, data.triangle_of_point);
                for (const auto &tri : data.triangles)
                  {
                    const RefPoint c = (1. / 3.) * (tri.vertex[0] + tri.vertex[1] + tri.vertex[2]);
                    data.triangle_side.push_back(crack->side(to_point(mapping.transform_unit_to_real_cell(cell, c))));
                  }
              }
            if (data.cut)
              {
                FEValues<2> fv(mapping, fe, data.quadrature, update_JxW_values);
                fv.reinit(cell);
                for (unsigned int q = 0; q < data.quadrature.size(); ++q)
                  (data.triangle_side[data.triangle_of_point[q]] > 0 ? plus : minus) += fv.JxW(q);
              }
            else
              (data.side > 0 ? plus : minus) += cell->measure();
            for (auto s : dofs)
              for (const auto &pw : parents[s])
                {
                  area_plus[pw.first] += plus;
                  area_minus[pw.first] += minus;
                  support_cut[pw.first] |= data.cut;
                  support_tip[pw.first] |= data.has_tip;
                }
          }
        for (unsigned int p = 0; p < n_nodes; ++p)
          {
            node_side[p] = crack->side(to_point(support[nodes[p]]));
            if (kind[p] == NodeKind::tip)
              {
                const auto b = crack->branch_functions(to_point(support[nodes[p]]), node_tip[p]);
                node_branch[p] = b.value;
              }
            else if (support_cut[p] && !support_tip[p] &&
                     std::min(area_plus[p], area_minus[p]) >= settings.min_cut_fraction * (area_plus[p] + area_minus[p]))
              kind[p] = NodeKind::heaviside;
          }
      }

    // Unknowns: (u_x, u_y) of every node, then 2 per Heaviside node and 8 per tip node.
    n_dofs = 2 * n_nodes;
    enriched_start.assign(n_nodes, 0);
    for (unsigned int p = 0; p < n_nodes; ++p)
      if (kind[p] != NodeKind::standard)
        {
          enriched_start[p] = n_dofs;
          n_dofs += kind[p] == NodeKind::heaviside ? 2 : 8;
        }

    // Dirichlet constraints. On a Heaviside node the jump of the boundary data across the crack
    // sets the enriched unknown, so that each side interpolates its own boundary data; branch
    // unknowns on the boundary are set to zero.
    constraints.clear();
    const auto constrain = [&](unsigned int dof, double value) {
      if (!constraints.is_constrained(dof))
        {
          constraints.add_line(dof);
          constraints.set_inhomogeneity(dof, value);
        }
    };
    const auto constrain_node = [&](unsigned int p, const Point &own, const Point &other, bool fx, bool fy) {
      const std::array<bool, 2>   fix = {{fx, fy}};
      const std::array<double, 2> u = {{own.x, own.y}}, w = {{other.x, other.y}};
      for (unsigned int c = 0; c < 2; ++c)
        {
          if (!fix[c])
            continue;
          constrain(2 * p + c, u[c]);
          if (kind[p] == NodeKind::heaviside)
            constrain(enriched_start[p] + c, (w[c] - u[c]) / (-2. * node_side[p]));
          else if (kind[p] == NodeKind::tip)
            for (unsigned int j = 0; j < 4; ++j)
              constrain(enriched_start[p] + 2 * j + c, 0.);
        }
    };
    for (const auto &bc : dirichlet)
      {
        bool found = false;
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == bc.id)
              {
                found = true;
                for (unsigned int v = 0; v < 2; ++v)
                  {
                    const auto s = cell->face(f)->vertex_dof_index(v, 0);
                    for (const auto &pw : parents[s])
                      {
                        const unsigned int p = pw.first;
                        const Point        x = to_point(support[nodes[p]]);
                        constrain_node(p, bc.value(x, node_side[p]), bc.value(x, -node_side[p]), bc.fix_x, bc.fix_y);
                      }
                  }
              }
        if (!found)
          throw InvalidParameter("Dirichlet boundary id", std::to_string(bc.id), "no boundary face of the mesh has this id");
      }
    for (const auto &bc : region_dirichlet)
      {
        bool found = false;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->material_id() == bc.material_id)
            {
              found = true;
              cell->get_dof_indices(dofs);
              for (const auto s : dofs)
                for (const auto &pw : parents[s])
                  {
                    const Point u = bc.value(to_point(support[nodes[pw.first]]));
                    constrain_node(pw.first, u, u, bc.fix_x, bc.fix_y);
                  }
            }
        if (!found)
          throw InvalidParameter("Dirichlet region (material id)", std::to_string(bc.material_id), "no cell has it");
      }
    for (const auto &bc : vertex_dirichlet)
      {
        const double tol = 1e-6 * diameter_scale;
        bool         found = false;
        for (unsigned int p = 0; p < n_nodes && !found; ++p)
          if (geometry::norm(to_point(support[nodes[p]]) - bc.at) <= tol)
            {
              constrain_node(p, bc.value, bc.value, bc.fix_x, bc.fix_y);
              found = true;
            }
        if (!found)
          throw InvalidParameter("Dirichlet vertex", "(" + std::to_string(bc.at.x) + ", " + std::to_string(bc.at.y) + ")",
                                 "must be a vertex of the mesh");
      }
    constraints.close();

    DynamicSparsityPattern dsp(n_dofs);
    for (const auto &cell : dof_handler.active_cell_iterators())
      constraints.add_entries_local_to_global(unknowns_of(local_functions(cell)), dsp, false);
    sparsity.copy_from(dsp);
    matrix.reinit(sparsity);
    rhs.reinit(n_dofs);
    solution.reinit(n_dofs);
  }

  std::vector<LocalFunction> EnrichedElasticity::Impl::local_functions(const Cell &cell) const
  {
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    cell->get_dof_indices(dofs);
    std::map<unsigned int, std::array<double, 4>> weight; // node -> weight of each vertex function
    for (unsigned int v = 0; v < dofs.size(); ++v)
      for (const auto &[p, w] : parents[dofs[v]])
        weight[p][v] += w;
    std::vector<LocalFunction> out;
    for (const auto &[p, w] : weight)
      {
        out.push_back({2 * p, -1, 0, 0., w});
        if (kind[p] == NodeKind::heaviside)
          out.push_back({enriched_start[p], 0, 0, double(node_side[p]), w});
        else if (kind[p] == NodeKind::tip)
          for (int j = 0; j < 4; ++j)
            out.push_back({enriched_start[p] + 2 * j, j + 1, node_tip[p], node_branch[p][j], w});
      }
    return out;
  }

  const Quadrature<2> &EnrichedElasticity::Impl::quadrature(const Cell &cell) const
  {
    const CellData &data = cells[cell->active_cell_index()];
    if (data.subdivided)
      return data.quadrature;
    if (!data.tip_enriched)
      return gauss;
    return data.near_tip ? gauss_tip : gauss_far_tip;
  }

  int EnrichedElasticity::Impl::side_at(const Cell &cell, unsigned int q, const dealii::Point<2> &x) const
  {
    const CellData &data = cells[cell->active_cell_index()];
    return data.cut ? data.triangle_side[data.triangle_of_point[q]] : crack->side(to_point(x));
  }
} // namespace pumpd::global
