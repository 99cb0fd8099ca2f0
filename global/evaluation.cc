// EnrichedElasticity: what is computed from a solution: point values, error norms against an
// exact field, stress intensity factors (interaction integral), VTU output.
#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "elasticity_impl.h"
#include "error.h"
#include "lefm.h"
#include "vtu.h"

namespace pumpd::global
{
  using namespace dealii;
  using Cell = DoFHandler<2>::active_cell_iterator;

  namespace
  {
    const UpdateFlags field_flags = update_values | update_gradients | update_quadrature_points | update_JxW_values;

    Tensor<2, 2> stress_of(const Tensor<2, 2> &grad, double lambda, double mu)
    {
      const Tensor<2, 2> eps = 0.5 * (grad + transpose(grad));
      Tensor<2, 2>       sigma = 2. * mu * eps;
      sigma[0][0] += lambda * trace(eps);
      sigma[1][1] += lambda * trace(eps);
      return sigma;
    }
  } // namespace

  geometry::Point EnrichedElasticity::Impl::displacement(geometry::Point x, int side_hint) const
  {
    const auto found = GridTools::find_active_cell_around_point(mapping, dof_handler, to_dealii(x));
    const Quadrature<2> point(found.second);
    FEValues<2>         fv(mapping, fe, point, field_flags);
    fv.reinit(found.first);
    Sides side;
    sides_of(x, side_hint, 1e-12 * found.first->diameter(), side);
    std::vector<Tensor<1, 2>> u;
    std::vector<Tensor<2, 2>> grad;
    field(fv, local_functions(found.first), side, u, grad);
    return {u[0][0], u[0][1]};
  }

  void EnrichedElasticity::Impl::for_each_point(
    const std::function<void(const Point &x, int side, const Tensor<1, 2> &u, const Tensor<2, 2> &grad, double JxW)>
      &visit) const
  {
    Sides                     side;
    std::vector<Tensor<1, 2>> u;
    std::vector<Tensor<2, 2>> grad;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        FEValues<2> fv(mapping, fe, quadrature(cell), field_flags);
        fv.reinit(cell);
        sides_at(cell, fv, side);
        field(fv, local_functions(cell), side, u, grad);
        for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
          visit(to_point(fv.quadrature_point(q)), side[q * stride()], u[q], grad[q], fv.JxW(q));
      }
  }

  ErrorNorms EnrichedElasticity::Impl::errors(const SidedField &exact,
                                              const std::function<std::array<double, 4>(geometry::Point, int)> &exact_grad) const
  {
    ErrorNorms   e;
    const double lambda = material.lambda(), mu = material.mu();
    const auto   inner  = [&](const Tensor<2, 2> &g) {
      return scalar_product(stress_of(g, lambda, mu), 0.5 * (g + transpose(g)));
    };
    for_each_point([&](const Point &x, int side, const Tensor<1, 2> &u, const Tensor<2, 2> &grad, double JxW) {
      const auto   ue = exact(x, side);
      const auto   ge = exact_grad(x, side);
      Tensor<2, 2> G;
      G[0][0] = ge[0];
      G[0][1] = ge[1];
      G[1][0] = ge[2];
      G[1][1] = ge[3];
      e.l2 += (std::pow(u[0] - ue.x, 2) + std::pow(u[1] - ue.y, 2)) * JxW;
      e.l2_exact += (ue.x * ue.x + ue.y * ue.y) * JxW;
      e.energy += inner(grad - G) * JxW;
      e.energy_exact += inner(G) * JxW;
    });
    e.l2           = std::sqrt(e.l2);
    e.l2_exact     = std::sqrt(e.l2_exact);
    e.energy       = std::sqrt(e.energy);
    e.energy_exact = std::sqrt(e.energy_exact);
    return e;
  }

  // U = 1/2 int sigma(u_h) : eps(u_h) over the body (per unit thickness).
  double EnrichedElasticity::Impl::strain_energy() const
  {
    double       energy = 0.;
    const double lambda = material.lambda(), mu = material.mu();
    for_each_point([&](const Point &, int, const Tensor<1, 2> &, const Tensor<2, 2> &grad, double JxW) {
      energy += 0.5 * scalar_product(stress_of(grad, lambda, mu), 0.5 * (grad + transpose(grad))) * JxW;
    });
    return energy;
  }

  std::string unresolved_tip_separation(const Crack &crack, double cell_diameter)
  {
    const double half = half_way_to_other_tip(crack);
    if (half >= cell_diameter)
      return "";
    return "its tips lie " + to_text(2. * half, 3) + " m apart, less than twice the cell at a tip (" +
           to_text(cell_diameter, 3) + " m): the interaction integral's domain ends half way between them, so the mesh "
           "cannot give its K";
  }

  // Interaction integral, domain form (Moes, Dolbow & Belytschko 1999, Eq. 34), in the tip frame:
  //   I = int_A [sigma_ij du^aux_i/dx_1 + sigma^aux_ij du_i/dx_1 - sigma_ik eps^aux_ik delta_1j] dq/dx_j dA,
  //   K = E' I / 2 with the auxiliary field of unit K_I (for K_I) or unit K_II (for K_II).
  // q is the Q1 interpolant of a nodal ramp in r = |x_node - tip| (1 inside r_in, 0 outside r_out),
  // so only the cells where q drops contributes: no singular integrand. The ring is placed where
  // the enriched space represents the tip field, away from the blending cells (cells with a
  // function that lacks the branch enrichment of this tip, whose error would enter K):
  //   r_safe = min(tip_radius, min over such cells of their nearest node's distance): every cell
  //            with a node closer than r_safe is fully tip enriched;
  //   r_out  = radius_factor * r_safe (factor <= 1 keeps the ring inside the enriched zone);
  //   r_in   = min(r_out / 2, r_out - 2 h), h the largest diameter of the cells with a node in
  //            [r_out / 2, r_out) (so the ramp spans at least two cells), provided r_in >= h (the
  //            tip cell stays out).
  // Where the zone is too small for that (tip radius of a few cells), the step of the earlier
  // definition: q = 1 at nodes within radius_factor * tip_radius, one ring of cells.
  // ring_of() returns (r_in, r_out); r_in = r_out means the step.
  // Several cracks: the domain of a tip must not hold another crack (its faces, not parallel to
  // the tip's x_1, would add to I), so tip_radius and r_safe are capped by the distance d_other
  // from the tip to the nearest other crack: radius and r_safe at most 0.9 d_other. Nor the
  // crack's own other tip: at most half way to it (half_way_to_other_tip), which a crack shorter
  // than twice the tip radius would otherwise hold.
  // k_terms: E'/2 int |integrand| dA, the larger mode's; for a tip the field drives |K| is of its
  // size, and far below it K is the remainder of the terms' cancellation (a crack along the load).
  std::vector<StressIntensity> EnrichedElasticity::Impl::stress_intensity_factors(double radius_factor) const
  {
    std::vector<StressIntensity> result;
    const double lambda = material.lambda(), mu = material.mu(), kappa = material.kolosov();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    Sides                     side;
    std::vector<Tensor<1, 2>> u;
    std::vector<Tensor<2, 2>> grad;
    const unsigned int        n = stride();
    std::vector<std::pair<unsigned int, std::size_t>> all_tips; // (crack, tip), cracks in order
    for (unsigned int c = 0; c < cracks.size(); ++c)
      for (std::size_t t = 0; t < cracks[c].tips().size(); ++t)
        all_tips.emplace_back(c, t);
    for (const auto &crack_tip : all_tips)
      {
        const unsigned int c     = crack_tip.first;
        const std::size_t  t     = crack_tip.second;
        const Crack       &crack = cracks[c];
        const Tip   &tip   = crack.tips()[t];
        double       tip_radius = settings.tip_radius;
        for (unsigned int o = 0; o < cracks.size(); ++o)
          if (o != c)
            tip_radius = std::min(tip_radius, 0.9 * cracks[o].distance(tip.position));
        tip_radius = std::min(tip_radius, half_way_to_other_tip(crack));
        const double radius = radius_factor * tip_radius;
        Tensor<2, 2> R; // rows: tip direction and its normal
        R[0][0] = tip.direction.x;
        R[0][1] = tip.direction.y;
        R[1][0] = -tip.direction.y;
        R[1][1] = tip.direction.x;
        const auto distance = [&](unsigned int p) { return geometry::norm(to_point(support[nodes[p]]) - tip.position); };
        // r_safe: the nearest node of a cell that is not fully enriched by this tip.
        double r_safe = tip_radius;
        const auto enriched_by_tip = [&](unsigned int p) {
          return std::any_of(enrichment[p].begin(), enrichment[p].end(),
                             [&](const NodeEnrichment &b) { return b.crack == c && b.tip == int(t); });
        };
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            cell->get_dof_indices(dofs);
            bool   full    = true;
            double nearest = std::numeric_limits<double>::max();
            for (unsigned int v = 0; v < 4; ++v)
              for (const auto &[p, w] : parents[dofs[v]])
                {
                  full &= enriched_by_tip(p);
                  nearest = std::min(nearest, distance(p));
                }
            if (!full)
              r_safe = std::min(r_safe, nearest);
          }
        double r_out = radius_factor * r_safe, r_in = r_out;
        {
          double h = 0.;
          for (const auto &cell : dof_handler.active_cell_iterators())
            {
              cell->get_dof_indices(dofs);
              for (unsigned int v = 0; v < 4; ++v)
                {
                  const double r = geometry::norm(to_point(support[dofs[v]]) - tip.position);
                  if (r >= 0.5 * r_out && r < r_out)
                    h = std::max(h, cell->diameter());
                }
            }
          r_in = std::min(0.5 * r_out, r_out - 2. * h);
          if (h == 0. || r_in < h)
            r_out = r_in = radius; // too few cells inside the enriched zone: the one-cell step
        }
        const auto q_at = [&](double r) {
          if (r_out == r_in)
            return r < r_out ? 1. : 0.;
          return std::clamp((r_out - r) / (r_out - r_in), 0., 1.);
        };
        const auto q_of = [&](types::global_dof_index s) {
          double q = 0.;
          for (const auto &[p, w] : parents[s])
            q += w * q_at(distance(p));
          return q;
        };
        double I[2] = {0., 0.}, magnitude[2] = {0., 0.};
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            cell->get_dof_indices(dofs);
            std::array<double, 4> qv;
            bool                  ring = false;
            for (unsigned int v = 0; v < 4; ++v)
              {
                qv[v] = q_of(dofs[v]);
                ring |= qv[v] != qv[0];
              }
            if (!ring)
              continue;
            FEValues<2> fv(mapping, fe, quadrature(cell), field_flags);
            fv.reinit(cell);
            sides_at(cell, fv, side);
            field(fv, local_functions(cell), side, u, grad);
            for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
              {
                Tensor<1, 2> grad_q;
                for (unsigned int v = 0; v < 4; ++v)
                  grad_q += qv[v] * fv.shape_grad(v, q);
                const Tensor<1, 2> dq    = R * grad_q;
                const Tensor<2, 2> G     = R * grad[q] * transpose(R);
                const Tensor<2, 2> sigma = stress_of(G, lambda, mu);
                const Point        rel   = to_point(fv.quadrature_point(q)) - tip.position;
                const double       r     = geometry::norm(rel);
                const double x1 = dot(rel, tip.direction);
                // theta with the sign of the sub-cell's side: it jumps across the crack faces, not
                // across the straight extension of the last segment. The + side lies to the left
                // of the polyline, which is the right of the tip direction at vertex 0.
                const int    orientation = tip.vertex == 0 ? -1 : 1;
                const double theta       = orientation * side[q * n + c] * std::acos(std::clamp(x1 / r, -1., 1.));
                for (int mode = 1; mode <= 2; ++mode)
                  {
                    const auto   aux = lefm::williams(mode, r, theta, mu, kappa);
                    Tensor<2, 2> Ga, Sa;
                    for (unsigned int i = 0; i < 2; ++i)
                      for (unsigned int j = 0; j < 2; ++j)
                        {
                          Ga[i][j] = aux.grad[i][j];
                          Sa[i][j] = aux.stress[i][j];
                        }
                    const Tensor<2, 2> eps_aux = 0.5 * (Ga + transpose(Ga));
                    double             integrand = 0.;
                    for (unsigned int j = 0; j < 2; ++j)
                      {
                        double term = 0.;
                        for (unsigned int i = 0; i < 2; ++i)
                          term += sigma[i][j] * Ga[i][0] + Sa[i][j] * G[i][0];
                        if (j == 0)
                          term -= scalar_product(sigma, eps_aux);
                        integrand += term * dq[j];
                      }
                    I[mode - 1] += integrand * fv.JxW(q);
                    magnitude[mode - 1] += std::abs(integrand) * fv.JxW(q);
                  }
              }
          }
        const double scale = 0.5 * material.effective_modulus();
        result.push_back({tip.position, scale * I[0], scale * I[1], scale * std::max(magnitude[0], magnitude[1])});
      }
    return result;
  }

  // Error indicator: the residual of the traction across faces (Kelly's indicator, in stresses
  // and on the enriched field). Each interior face F = K | K' is visited once, from the finer side
  // where the neighbour is coarser (so a hanging face is a child face), at the 3 Gauss points of
  // F; both cells are evaluated at the same points, each point on its own side of the crack
  // (points on the crack line are skipped). Boundary faces without Dirichlet data contribute
  // sigma_h n - t. eta_K^2 += h_F int_F |jump|^2 for both cells of F.
  std::vector<double> EnrichedElasticity::error_indicators() const
  {
    const Impl         &m      = *impl;
    const double        lambda = m.material.lambda(), mu = m.material.mu();
    std::vector<double> eta2(m.tria.n_active_cells(), 0.);
    const QGauss<1>     gauss(3);
    std::vector<Tensor<1, 2>> u;
    std::vector<Tensor<2, 2>> grad;
    const auto stresses = [&](const Cell &cell, const std::vector<dealii::Point<2>> &x, const Sides &side) {
      std::vector<dealii::Point<2>> ref;
      for (const auto &p : x)
        ref.push_back(m.mapping.transform_real_to_unit_cell(cell, p));
      FEValues<2> fv(m.mapping, m.fe, Quadrature<2>(ref), update_values | update_gradients | update_quadrature_points);
      fv.reinit(cell);
      m.field(fv, m.local_functions(cell), side, u, grad);
      std::vector<Tensor<2, 2>> sigma;
      for (const auto &g : grad)
        sigma.push_back(stress_of(g, lambda, mu));
      return sigma;
    };
    for (const auto &cell : m.dof_handler.active_cell_iterators())
      for (unsigned int f = 0; f < 4; ++f)
        {
          const auto face = cell->face(f);
          std::optional<Cell> other;
          const Impl::Traction *traction = nullptr;
          if (cell->at_boundary(f))
            {
              bool dirichlet = false;
              for (const auto &d : m.dirichlet)
                dirichlet |= d.id == face->boundary_id();
              if (dirichlet)
                continue;
              for (const auto &t : m.tractions)
                if (t.id == face->boundary_id())
                  traction = &t;
            }
          else
            {
              if (cell->neighbor(f)->has_children())
                continue; // visited from the children
              if (!cell->neighbor_is_coarser(f) && cell->neighbor(f)->active_cell_index() < cell->active_cell_index())
                continue; // visited from the neighbour
              other = cell->neighbor(f);
            }
          const dealii::Point<2> a = face->vertex(0), b = face->vertex(1);
          const double           length = a.distance(b);
          Tensor<1, 2>           n;
          n[0] = (b - a)[1] / length;
          n[1] = -(b - a)[0] / length;
          if ((face->center() - cell->center()) * n < 0.)
            n *= -1.;
          std::vector<dealii::Point<2>> x;
          Sides                         side, s;
          std::vector<double>           w;
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              const dealii::Point<2> p = a + gauss.point(q)[0] * (b - a);
              if (std::any_of(m.cracks.begin(), m.cracks.end(), [&](const Crack &c) {
                    return std::abs(c.signed_distance(to_point(p))) < 1e-10 * length;
                  }))
                continue;
              m.sides_of(to_point(p), 1, 0., s);
              x.push_back(p);
              side.insert(side.end(), s.begin(), s.end());
              w.push_back(gauss.weight(q) * length);
            }
          if (x.empty())
            continue;
          const auto   sigma = stresses(cell, x, side);
          double       jump2 = 0.;
          if (other)
            {
              const auto sigma_other = stresses(*other, x, side);
              for (unsigned int q = 0; q < x.size(); ++q)
                jump2 += w[q] * ((sigma[q] - sigma_other[q]) * n).norm_square();
            }
          else
            for (unsigned int q = 0; q < x.size(); ++q)
              {
                Tensor<1, 2> r = sigma[q] * n;
                if (traction)
                  {
                    const auto t = traction->value(to_point(x[q]), geometry::Point{n[0], n[1]});
                    r[0] -= t.x;
                    r[1] -= t.y;
                  }
                jump2 += w[q] * r.norm_square();
              }
          eta2[cell->active_cell_index()] += length * jump2;
          if (other)
            eta2[(*other)->active_cell_index()] += length * jump2;
        }
    for (auto &e : eta2)
      e = std::sqrt(e);
    return eta2;
  }

  // Nodal stress by extrapolation from the 2 x 2 Gauss points, where the Q1 stress is most
  // accurate (Barlow points): with the Gauss points at g = 1/2 -+ 1/(2 sqrt 3) in reference
  // coordinates, the bilinear interpolant of their values takes at the corner next to Gauss
  // point 0 the weights 1 + c (that point) and -c (its neighbour) per direction, c = (sqrt 3 - 1) / 2.
  std::vector<NodalStress> EnrichedElasticity::nodal_stresses() const
  {
    const Impl &m = *impl;
    if (!m.cracks.empty())
      throw std::logic_error("nodal_stresses() is for a body without a crack");
    const double      lambda = m.material.lambda(), mu = m.material.mu();
    const QGauss<1>   line(2);
    std::vector<dealii::Point<2>> points; // lexicographic, as the cell's vertices: (g0, g0), (g1, g0), (g0, g1), (g1, g1)
    for (unsigned int qy = 0; qy < 2; ++qy)
      for (unsigned int qx = 0; qx < 2; ++qx)
        points.emplace_back(line.point(qx)[0], line.point(qy)[0]);
    const double c      = 0.5 * (std::sqrt(3.) - 1.);
    const auto   weight = [c](unsigned int corner, unsigned int q) { return corner == q ? 1. + c : -c; };

    std::vector<NodalStress>  sum(m.tria.n_vertices());
    std::vector<unsigned int> count(m.tria.n_vertices(), 0);
    FEValues<2>               fv(m.mapping, m.fe, Quadrature<2>(points), field_flags);
    std::vector<Tensor<1, 2>> u;
    std::vector<Tensor<2, 2>> grad;
    for (const auto &cell : m.dof_handler.active_cell_iterators())
      {
        fv.reinit(cell);
        m.field(fv, m.local_functions(cell), Sides(points.size() * m.stride(), 1), u, grad);
        std::array<Tensor<2, 2>, 4> sigma;
        for (unsigned int q = 0; q < 4; ++q)
          sigma[q] = stress_of(grad[q], lambda, mu);
        for (unsigned int v = 0; v < 4; ++v)
          {
            Tensor<2, 2> corner;
            for (unsigned int q = 0; q < 4; ++q)
              corner += weight(v % 2, q % 2) * weight(v / 2, q / 2) * sigma[q];
            NodalStress &n = sum[cell->vertex_index(v)];
            n.xx += corner[0][0];
            n.yy += corner[1][1];
            n.xy += corner[0][1];
            n.cell_size = std::max(n.cell_size, cell->diameter());
            ++count[cell->vertex_index(v)];
          }
      }
    std::vector<NodalStress> result;
    for (unsigned int i = 0; i < sum.size(); ++i)
      if (count[i] > 0)
        {
          NodalStress n = sum[i];
          n.at          = to_point(m.tria.get_vertices()[i]);
          n.xx /= count[i];
          n.yy /= count[i];
          n.xy /= count[i];
          result.push_back(n);
        }
    return result;
  }

  void EnrichedElasticity::Impl::write_vtu(const std::string &filename) const
  {
    // Each cell, or each triangle of a cut cell's quadrature partition (the displacement jumps
    // across the crack), is a VTU cell of its own: its corners' displacements and the stress at
    // its centre.
    VtuGrid  grid;
    VtuField displacement{"displacement", 3, {}}, stress{"stress", 3, {}}, von_mises{"von_mises", 1, {}},
      kind{"enrichment", 1, {}, true};
    const double lambda = material.lambda(), mu = material.mu();
    const double nu     = material.plane_strain ? material.poisson_ratio : 0.;
    const auto   add    = [&](FEValues<2> &fv, const std::vector<LocalFunction> &functions, const Sides &piece_sides,
                         int enrichment) {
      const unsigned int        corners = fv.n_quadrature_points - 1;
      std::vector<Tensor<1, 2>> u;
      std::vector<Tensor<2, 2>> grad;
      Sides                     side;
      for (unsigned int q = 0; q <= corners; ++q)
        side.insert(side.end(), piece_sides.begin(), piece_sides.end());
      field(fv, functions, side, u, grad);
      grid.add_cell(std::int64_t(grid.n_points()), corners, corners == 3 ? 5 : 9);
      for (unsigned int q = 0; q < corners; ++q)
        {
          grid.points.insert(grid.points.end(), {fv.quadrature_point(q)[0], fv.quadrature_point(q)[1]});
          displacement.values.insert(displacement.values.end(), {u[q][0], u[q][1], 0.});
        }
      const Tensor<2, 2> sigma = stress_of(grad.back(), lambda, mu);
      const double sx = sigma[0][0], sy = sigma[1][1], sz = nu * (sx + sy), txy = sigma[0][1];
      stress.values.insert(stress.values.end(), {sx, sy, txy});
      von_mises.values.push_back(
        std::sqrt(0.5 * ((sx - sy) * (sx - sy) + (sy - sz) * (sy - sz) + (sz - sx) * (sz - sx)) + 3. * txy * txy));
      kind.values.push_back(enrichment);
    };
    const auto corners_and_centre = [](const std::vector<RefPoint> &corners) {
      std::vector<dealii::Point<2>> points(corners.begin(), corners.end());
      RefPoint                      centre;
      for (const auto &p : corners)
        centre += p / double(corners.size());
      points.push_back(centre);
      return Quadrature<2>(points);
    };
    const UpdateFlags flags = update_values | update_gradients | update_quadrature_points;
    FEValues<2>       whole(mapping, fe,
                      corners_and_centre({RefPoint(0, 0), RefPoint(1, 0), RefPoint(1, 1), RefPoint(0, 1)}), flags);
    const unsigned int n = stride();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const CellData &data      = cells[cell->active_cell_index()];
        const auto      functions = local_functions(cell);
        if (data.cut)
          for (unsigned int t = 0; t < data.triangles.size(); ++t)
            {
              const auto &v = data.triangles[t].vertex;
              FEValues<2> piece(mapping, fe, corners_and_centre({v[0], v[1], v[2]}), flags);
              piece.reinit(cell);
              add(piece, functions,
                  Sides(data.triangle_side.begin() + t * n, data.triangle_side.begin() + (t + 1) * n), 3);
            }
        else
          {
            int enrichment = 0;
            for (const auto &f : functions)
              enrichment = std::max(enrichment, f.kind == 0 ? 1 : f.kind > 0 ? 2 : 0);
            whole.reinit(cell);
            add(whole, functions, cracks.empty() ? Sides(1, 1) : data.side, enrichment);
          }
      }
    grid.point_data     = {std::move(displacement)};
    grid.cell_data      = {std::move(stress), std::move(von_mises), std::move(kind)};
    grid.active_vectors = "displacement";
    pumpd::write_vtu(filename, grid);
  }
} // namespace pumpd::global
