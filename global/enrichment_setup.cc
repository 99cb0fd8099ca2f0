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

  std::vector<std::vector<double>>
  EnrichedElasticity::Impl::far_side_energy(const std::vector<std::vector<char>> &wanted) const
  {
    const unsigned int               n_cracks = cracks.size();
    std::vector<std::vector<double>> energy(n_cracks, std::vector<double>(nodes.size(), 0.));
    const auto any = [](const std::vector<char> &v) { return std::find(v.begin(), v.end(), 1) != v.end(); };
    if (std::none_of(wanted.begin(), wanted.end(), any))
      return energy;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        std::map<std::pair<unsigned int, unsigned int>, std::array<double, 4>> weights; // (crack, node): per vertex
        for (unsigned int v = 0; v < 4; ++v)
          for (const auto &[p, w] : parents[dofs[v]])
            for (unsigned int c = 0; c < n_cracks; ++c)
              if (wanted[c][p])
                weights[{c, p}][v] += w;
        if (weights.empty())
          continue;
        const CellData &data = cells[cell->active_cell_index()];
        FEValues<2>     fv(mapping, fe, data.subdivided ? data.quadrature : Quadrature<2>(gauss),
                           update_gradients | update_JxW_values);
        fv.reinit(cell);
        for (const auto &[key, weight] : weights)
          {
            const auto [c, p] = key;
            const int own     = cracks[c].side(to_point(support[nodes[p]]));
            for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
              {
                const int side = data.cut_by[c] ? data.triangle_side[data.triangle_of_point[q] * n_cracks + c] : data.side[c];
                if (side == own)
                  continue;
                Tensor<1, 2> grad;
                for (unsigned int v = 0; v < 4; ++v)
                  grad += weight[v] * fv.shape_grad(v, q);
                energy[c][p] += grad.norm_square() * fv.JxW(q);
              }
          }
      }
    return energy;
  }

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

    const unsigned int n_nodes = nodes.size(), n_cracks = cracks.size();
    kind.assign(n_nodes, NodeKind::standard);
    enrichment.assign(n_nodes, {});
    cells.assign(tria.n_active_cells(), CellData());
    const double diameter_scale = GridTools::minimal_cell_diameter(tria);

    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &crack : cracks)
      for (const auto &v : crack.vertices())
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

    // Pass 1: crack pieces and tips per cell; tip nodes. A cell several cracks cut is split by the
    // lines of all their pieces, so every sub-triangle lies on one side of each crack.
    // node_tip[c][p]: the tip of crack c whose branch functions node p carries, -1 none;
    // tip_in_cell[cell][c]: a tip of crack c lies in the cell.
    std::vector<std::vector<int>>  node_tip(n_cracks, std::vector<int>(n_nodes, -1));
    std::vector<std::vector<char>> tip_in_cell(cells.size(), std::vector<char>(n_cracks, 0));
    std::vector<std::vector<char>> tip_cell_node(n_cracks, std::vector<char>(n_nodes, 0));
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cracks.empty())
          break;
        CellData  &data = cells[cell->active_cell_index()];
        const auto poly = corners(cell);
        data.cut_by.assign(n_cracks, 0);
        std::vector<std::array<RefPoint, 2>> pieces;
        // Tips in the cell, and tips within one cell diameter of it (their nearest point of
        // the cell): sub-triangles are fanned from these points and get Duffy rules, so the
        // 1/sqrt(r) gradients are integrated almost-polar wherever they are (nearly) singular.
        std::vector<RefPoint> tips, near_tips;
        for (unsigned int c = 0; c < n_cracks; ++c)
          {
            const auto &vertices = cracks[c].vertices();
            for (std::size_t s = 0; s + 1 < vertices.size(); ++s)
              {
                Point p, q;
                if (clip_segment(vertices[s], vertices[s + 1], poly, p, q))
                  {
                    pieces.push_back({{to_unit(mapping, cell, p), to_unit(mapping, cell, q)}});
                    data.cut_by[c] = 1;
                  }
              }
            for (const auto &t : cracks[c].tips())
              if (inside(t.position, poly, 1e-12))
                {
                  tips.push_back(to_unit(mapping, cell, t.position));
                  tip_in_cell[cell->active_cell_index()][c] = 1;
                }
              else
                {
                  const Point nearest = nearest_on_polygon(t.position, poly);
                  if (geometry::norm(t.position - nearest) < cell->diameter())
                    near_tips.push_back(to_unit(mapping, cell, nearest));
                }
            data.side.push_back(cracks[c].side(to_point(cell->center())));
          }
        data.cut     = !pieces.empty();
        data.has_tip = !tips.empty();
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
            for (unsigned int c = 0; c < n_cracks; ++c)
              if (tip_in_cell[cell->active_cell_index()][c])
                if (const std::string why = unresolved_tip_separation(cracks[c], cell->diameter()); !why.empty())
                  throw InvalidParameter("Crack", geometry::to_text(cracks[c].vertices()),
                                         why + "; refine the mesh at the tips");
            cell->get_dof_indices(dofs);
            for (unsigned int c = 0; c < n_cracks; ++c)
              if (tip_in_cell[cell->active_cell_index()][c])
                for (auto s : dofs)
                  for (const auto &pw : parents[s])
                    tip_cell_node[c][pw.first] = 1;
          }
      }
    for (unsigned int c = 0; c < n_cracks; ++c)
      if (!cracks[c].tips().empty())
        for (unsigned int p = 0; p < n_nodes; ++p)
          {
            const Point       x = to_point(support[nodes[p]]);
            const std::size_t t = cracks[c].nearest_tip(x);
            if (tip_cell_node[c][p] || geometry::norm(x - cracks[c].tips()[t].position) <= settings.tip_radius)
              {
                node_tip[c][p] = t;
                kind[p]        = NodeKind::tip;
              }
          }

    // Pass 2: quadrature of cut cells, areas of each side of each crack in every node's support.
    std::vector<std::vector<double>> area_plus(n_cracks, std::vector<double>(n_nodes, 0.)),
      area_minus(n_cracks, std::vector<double>(n_nodes, 0.));
    std::vector<std::vector<char>> support_cut(n_cracks, std::vector<char>(n_nodes, 0)),
      support_tip(n_cracks, std::vector<char>(n_nodes, 0));
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cracks.empty())
          break;
        CellData &data = cells[cell->active_cell_index()];
        cell->get_dof_indices(dofs);
        for (auto s : dofs)
          for (const auto &pw : parents[s])
            data.tip_enriched |= kind[pw.first] == NodeKind::tip;
        for (const auto &crack : cracks)
          for (const auto &tip : crack.tips())
            data.near_tip |= geometry::norm(to_point(cell->center()) - tip.position) < 2.5 * cell->diameter();
        if (data.subdivided)
          {
            data.quadrature = sub_triangle_quadrature(
              data.triangles, data.tip_enriched && data.near_tip ? settings.tip_order : settings.cut_order, data.triangle_of_point);
            for (const auto &tri : data.triangles)
              {
                const RefPoint c = (1. / 3.) * (tri.vertex[0] + tri.vertex[1] + tri.vertex[2]);
                const Point    x = to_point(mapping.transform_unit_to_real_cell(cell, c));
                for (const auto &crack : cracks)
                  data.triangle_side.push_back(crack.side(x));
              }
          }
        std::vector<double> JxW;
        if (data.cut)
          {
            FEValues<2> fv(mapping, fe, data.quadrature, update_JxW_values);
            fv.reinit(cell);
            JxW = fv.get_JxW_values();
          }
        for (unsigned int c = 0; c < n_cracks; ++c)
          {
            double plus = 0., minus = 0.;
            if (data.cut_by[c])
              for (unsigned int q = 0; q < JxW.size(); ++q)
                (data.triangle_side[data.triangle_of_point[q] * n_cracks + c] > 0 ? plus : minus) += JxW[q];
            else
              (data.side[c] > 0 ? plus : minus) += cell->measure();
            for (auto s : dofs)
              for (const auto &pw : parents[s])
                {
                  area_plus[c][pw.first] += plus;
                  area_minus[c][pw.first] += minus;
                  support_cut[c][pw.first] |= data.cut_by[c];
                  support_tip[c][pw.first] |= tip_in_cell[cell->active_cell_index()][c];
                }
          }
      }
    // Pass 3: the Heaviside blocks. A block whose support the crack cuts into a part of less than
    // min_cut_fraction of its area is dropped (conditioning), unless its shifted function still
    // carries energy there: int |grad phi_p|^2 over the side the node is not on (dimensionless,
    // about 8/3 over a whole support of square cells) of at least min_cut_fraction. Without the
    // block, the jump across that part is carried by the other nodes' blocks and the node's
    // hat function strains the part by it. In a cell of ordinary shape a part of small area is
    // thin against the cell too, phi_p is small on it and the strain energy as small as its
    // area; in a cell thin across the crack it is a fair part of the cell, phi_p is not small on
    // it, and the strained part acts as a spring that holds the crack shut.
    std::vector<std::vector<char>> barely_cut(n_cracks, std::vector<char>(n_nodes, 0));
    for (unsigned int p = 0; p < n_nodes; ++p)
      for (unsigned int c = 0; c < n_cracks; ++c)
        barely_cut[c][p] = node_tip[c][p] < 0 && support_cut[c][p] && !support_tip[c][p] &&
                           std::min(area_plus[c][p], area_minus[c][p]) <
                             settings.min_cut_fraction * (area_plus[c][p] + area_minus[c][p]);
    const auto far_energy = far_side_energy(barely_cut);
    for (unsigned int p = 0; p < n_nodes; ++p)
      for (unsigned int c = 0; c < n_cracks; ++c)
        {
          const Point x = to_point(support[nodes[p]]);
          if (node_tip[c][p] >= 0)
            enrichment[p].push_back({c, node_tip[c][p], 0, cracks[c].branch_functions(x, node_tip[c][p]).value});
          else if (support_cut[c][p] && !support_tip[c][p] &&
                   (!barely_cut[c][p] || far_energy[c][p] >= settings.min_cut_fraction))
            {
              enrichment[p].push_back({c, -1, 0, {{double(cracks[c].side(x)), 0., 0., 0.}}});
              if (kind[p] == NodeKind::standard)
                kind[p] = NodeKind::heaviside;
            }
        }

    // Unknowns: (u_x, u_y) of every node, then per node 2 per Heaviside block and 8 per tip block.
    n_dofs = 2 * n_nodes;
    for (auto &blocks : enrichment)
      for (auto &b : blocks)
        {
          b.start = n_dofs;
          n_dofs += b.tip < 0 ? 2 : 8;
        }

    // Dirichlet constraints. On a Heaviside block the jump of the boundary data across its crack
    // sets the enriched unknown, so that each side interpolates its own boundary data (value(x, s):
    // the data on side s of that crack; the standard unknown takes the node's side of the first
    // crack); branch unknowns on the boundary are set to zero.
    constraints.clear();
    const auto constrain = [&](unsigned int dof, double value) {
      if (!constraints.is_constrained(dof))
        {
          constraints.add_line(dof);
          constraints.set_inhomogeneity(dof, value);
        }
    };
    const auto constrain_node = [&](unsigned int p, const std::function<Point(int)> &value, bool fx, bool fy) {
      const std::array<bool, 2> fix = {{fx, fy}};
      const Point               x   = to_point(support[nodes[p]]);
      const Point               own = value(cracks.empty() ? 1 : cracks[0].side(x));
      const std::array<double, 2> u = {{own.x, own.y}};
      for (unsigned int c = 0; c < 2; ++c)
        {
          if (!fix[c])
            continue;
          constrain(2 * p + c, u[c]);
          for (const auto &b : enrichment[p])
            if (b.tip < 0)
              {
                const int    s = int(b.shift[0]);
                const Point  here = value(s), other = value(-s);
                const double jump = c == 0 ? other.x - here.x : other.y - here.y;
                constrain(b.start + c, jump / (-2. * s));
              }
            else
              for (unsigned int j = 0; j < 4; ++j)
                constrain(b.start + 2 * j + c, 0.);
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
                        constrain_node(p, [&](int side) { return bc.value(x, side); }, bc.fix_x, bc.fix_y);
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
                    constrain_node(pw.first, [u](int) { return u; }, bc.fix_x, bc.fix_y);
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
              constrain_node(p, [&](int) { return bc.value; }, bc.fix_x, bc.fix_y);
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
        out.push_back({2 * p, -1, 0, 0, 0., w});
        for (const auto &b : enrichment[p])
          if (b.tip < 0)
            out.push_back({b.start, 0, 0, b.crack, b.shift[0], w});
          else
            for (int j = 0; j < 4; ++j)
              out.push_back({b.start + 2 * j, j + 1, unsigned(b.tip), b.crack, b.shift[j], w});
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

  void EnrichedElasticity::Impl::sides_at(const Cell &cell, const FEValuesBase<2> &fv, Sides &side) const
  {
    const CellData    &data = cells[cell->active_cell_index()];
    const unsigned int n    = stride();
    side.assign(fv.n_quadrature_points * n, 1);
    for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
      for (unsigned int c = 0; c < cracks.size(); ++c)
        side[q * n + c] = data.cut && data.cut_by[c] ? data.triangle_side[data.triangle_of_point[q] * n + c]
                                                     : cracks[c].side(to_point(fv.quadrature_point(q)));
  }

  void EnrichedElasticity::Impl::sides_of(const Point &x, int on_crack, double tolerance, Sides &side) const
  {
    side.assign(stride(), 1);
    for (unsigned int c = 0; c < cracks.size(); ++c)
      {
        const double phi = cracks[c].signed_distance(x);
        side[c] = std::abs(phi) < tolerance && !cracks[c].beyond_junction(x) ? on_crack : cracks[c].side(x);
      }
  }
} // namespace pumpd::global
