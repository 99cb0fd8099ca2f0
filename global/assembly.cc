// EnrichedElasticity: the enriched basis at quadrature points, assembly of
// a(u, v) = int lambda div u div v + 2 mu eps(u):eps(v) and of the loads, and the direct solve.
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <set>

#include "blas_threads.h"
#include "cholesky.h"
#include "elasticity_impl.h"
#include "error.h"

namespace pumpd::global
{
  using namespace dealii;
  using Cell = DoFHandler<2>::active_cell_iterator;

  void EnrichedElasticity::Impl::evaluate(const FEValuesBase<2> &fv, const std::vector<LocalFunction> &functions,
                                          const Sides &side, BasisValues &out) const
  {
    const unsigned int nq = fv.n_quadrature_points, nf = functions.size(), n = stride();
    out.value.assign(nf, std::vector<double>(nq, 0.));
    out.grad.assign(nf, std::vector<Tensor<1, 2>>(nq));
    std::vector<std::optional<BranchValues>> branch(2 * n); // per tip (2 crack + tip), at the current point
    for (unsigned int q = 0; q < nq; ++q)
      {
        std::fill(branch.begin(), branch.end(), std::nullopt);
        for (unsigned int f = 0; f < nf; ++f)
          {
            const LocalFunction &fn = functions[f];
            const int            s  = side[q * n + fn.crack];
            double               g  = 1.; // psi(x) - psi(x_p)
            Tensor<1, 2>         grad_psi;
            auto                &b  = branch[2 * fn.crack + fn.tip];
            if (fn.kind == 0)
              g = s - fn.shift;
            else if (fn.kind > 0)
              {
                if (!b)
                  b = branch_on_side(cracks[fn.crack], to_point(fv.quadrature_point(q)), fn.tip, s);
                g           = b->value[fn.kind - 1] - fn.shift;
                const auto d = b->gradient[fn.kind - 1];
                grad_psi[0] = d.x;
                grad_psi[1] = d.y;
              }
            double       value = 0.;
            Tensor<1, 2> grad;
            for (unsigned int v = 0; v < 4; ++v)
              if (fn.weight[v] != 0.)
                {
                  const double N = fv.shape_value(v, q);
                  value += fn.weight[v] * N * g;
                  grad += fn.weight[v] * (fv.shape_grad(v, q) * g + N * grad_psi);
                }
            out.value[f][q] = value;
            out.grad[f][q]  = grad;
          }
      }
  }

  void EnrichedElasticity::Impl::field(const FEValuesBase<2> &fv, const std::vector<LocalFunction> &functions,
                                       const Sides &side, std::vector<Tensor<1, 2>> &u,
                                       std::vector<Tensor<2, 2>> &grad) const
  {
    BasisValues basis;
    evaluate(fv, functions, side, basis);
    const unsigned int nq = fv.n_quadrature_points;
    u.assign(nq, Tensor<1, 2>());
    grad.assign(nq, Tensor<2, 2>());
    for (unsigned int f = 0; f < functions.size(); ++f)
      for (unsigned int c = 0; c < 2; ++c)
        {
          const double U = solution(functions[f].dof + c);
          for (unsigned int q = 0; q < nq; ++q)
            {
              u[q][c] += U * basis.value[f][q];
              grad[q][c] += U * basis.grad[f][q];
            }
        }
  }

  void EnrichedElasticity::Impl::assemble()
  {
    matrix = 0.;
    rhs    = 0.;
    const double      lambda = material.lambda(), mu = material.mu();
    const UpdateFlags flags  = update_values | update_gradients | update_quadrature_points | update_JxW_values;
    FEValues<2>       fv_plain(mapping, fe, gauss, flags), fv_tip(mapping, fe, gauss_tip, flags),
      fv_far_tip(mapping, fe, gauss_far_tip, flags);
    BasisValues       basis;
    Sides             side;
    FullMatrix<double> K;
    Vector<double>     F;

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const auto       functions = local_functions(cell);
        const CellData  &data      = cells[cell->active_cell_index()];
        std::optional<FEValues<2>> fv_cut;
        FEValues<2>     *fv = !data.tip_enriched ? &fv_plain : data.near_tip ? &fv_tip : &fv_far_tip;
        if (data.subdivided)
          fv = &fv_cut.emplace(mapping, fe, data.quadrature, flags);
        fv->reinit(cell);
        const unsigned int nq = fv->n_quadrature_points, nf = functions.size();
        sides_at(cell, *fv, side);
        evaluate(*fv, functions, side, basis);

        K.reinit(2 * nf, 2 * nf);
        F.reinit(2 * nf);
        for (unsigned int q = 0; q < nq; ++q)
          {
            const double JxW = fv->JxW(q);
            for (unsigned int a = 0; a < nf; ++a)
              {
                const Tensor<1, 2> &ga = basis.grad[a][q];
                for (unsigned int b = 0; b < nf; ++b)
                  {
                    const Tensor<1, 2> &gb = basis.grad[b][q];
                    const double        gg = ga * gb;
                    for (unsigned int c = 0; c < 2; ++c)
                      for (unsigned int d = 0; d < 2; ++d)
                        K(2 * a + c, 2 * b + d) +=
                          (lambda * ga[c] * gb[d] + mu * (ga[d] * gb[c] + (c == d ? gg : 0.))) * JxW;
                  }
              }
            if (body_force)
              {
                const auto b = body_force(to_point(fv->quadrature_point(q)));
                for (unsigned int a = 0; a < nf; ++a)
                  {
                    F(2 * a) += b.x * basis.value[a][q] * JxW;
                    F(2 * a + 1) += b.y * basis.value[a][q] * JxW;
                  }
              }
          }
        constraints.distribute_local_to_global(K, F, unknowns_of(functions), matrix, rhs);
      }

    // Tractions on boundary faces. A face crack mouths cut is integrated on its parts between the
    // crossings (the traction and the enriched functions jump there); the sides of each point come
    // from the cracks' level sets.
    const QGauss<1>  face_rule(settings.tip_order);
    const UpdateFlags face_flags =
      update_values | update_gradients | update_quadrature_points | update_JxW_values | update_normal_vectors;
    for (const auto &bc : tractions)
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == bc.id)
            {
              // The crossings of every crack with the face, at parameters t of a + t (b - a).
              const Point         a = to_point(cell->face(f)->vertex(0)), b = to_point(cell->face(f)->vertex(1));
              std::vector<double> crossings;
              for (const auto &crack : cracks)
                {
                  const auto &v = crack.vertices();
                  for (std::size_t s = 0; s + 1 < v.size(); ++s)
                    {
                      const Point  d = b - a, e = v[s + 1] - v[s];
                      const double den = cross(d, e);
                      if (std::abs(den) < 1e-14 * geometry::norm(d) * geometry::norm(e))
                        continue;
                      const double t = cross(v[s] - a, e) / den, u = cross(v[s] - a, d) / den;
                      if (t > 1e-12 && t < 1. - 1e-12 && u >= 0. && u <= 1.)
                        crossings.push_back(t);
                    }
                }
              Quadrature<1> rule = face_rule;
              if (!crossings.empty())
                {
                  std::sort(crossings.begin(), crossings.end());
                  crossings.insert(crossings.begin(), 0.);
                  crossings.push_back(1.);
                  std::vector<dealii::Point<1>> points;
                  std::vector<double>           weights;
                  for (std::size_t k = 0; k + 1 < crossings.size(); ++k)
                    {
                      const double lo = crossings[k], hi = crossings[k + 1];
                      for (unsigned int q = 0; q < face_rule.size(); ++q)
                        {
                          points.emplace_back(lo + (hi - lo) * face_rule.point(q)[0]);
                          weights.push_back((hi - lo) * face_rule.weight(q));
                        }
                    }
                  rule = Quadrature<1>(points, weights);
                }
              FEFaceValues<2> fv_face(mapping, fe, rule, face_flags);
              fv_face.reinit(cell, f);
              const auto functions = local_functions(cell);
              side.assign(rule.size() * stride(), 1);
              for (unsigned int q = 0; q < rule.size(); ++q)
                for (unsigned int c = 0; c < cracks.size(); ++c)
                  side[q * stride() + c] = cracks[c].side(to_point(fv_face.quadrature_point(q)));
              BasisValues face_basis;
              evaluate(fv_face, functions, side, face_basis);
              F.reinit(2 * functions.size());
              for (unsigned int q = 0; q < rule.size(); ++q)
                {
                  const auto t = bc.value(to_point(fv_face.quadrature_point(q)), geometry::Point{fv_face.normal_vector(q)[0], fv_face.normal_vector(q)[1]});
                  for (unsigned int a = 0; a < functions.size(); ++a)
                    {
                      F(2 * a) += t.x * face_basis.value[a][q] * fv_face.JxW(q);
                      F(2 * a + 1) += t.y * face_basis.value[a][q] * fv_face.JxW(q);
                    }
                }
              constraints.distribute_local_to_global(F, unknowns_of(functions), rhs);
            }

    // Point loads act on the standard unknowns of their node: every enriched function vanishes
    // at the nodes (shifted enrichment), so the nodal force is all there is.
    for (const auto &load : point_loads)
      {
        const double tol = 1e-6 * GridTools::minimal_cell_diameter(tria);
        bool         found = false;
        for (unsigned int p = 0; p < nodes.size() && !found; ++p)
          if (geometry::norm(to_point(support[nodes[p]]) - load.at) <= tol)
            {
              found = true;
              if (!constraints.is_constrained(2 * p))
                rhs(2 * p) += load.force.x;
              if (!constraints.is_constrained(2 * p + 1))
                rhs(2 * p + 1) += load.force.y;
            }
        if (!found)
          throw InvalidParameter("Point load position", "(" + std::to_string(load.at.x) + ", " + std::to_string(load.at.y) + ")",
                                 "must be a vertex of the mesh");
      }
  }

  std::vector<unsigned int> EnrichedElasticity::Impl::boundary_nodes(unsigned int boundary_id) const
  {
    std::set<unsigned int> found;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == boundary_id)
          for (unsigned int v = 0; v < 2; ++v)
            for (const auto &pw : parents[cell->face(f)->vertex_dof_index(v, 0)])
              found.insert(pw.first);
    return {found.begin(), found.end()};
  }

  // R_c = sum_{p in set} a(u_h, phi_p e_c) - f_c(p): the standard function phi_p of each node is
  // in the enriched space, so the discrete equilibrium a(u_h, v) = f(v) fails on it by exactly the
  // force the constraints exert there.
  geometry::Point EnrichedElasticity::Impl::reaction(const std::vector<unsigned int> &node_set) const
  {
    const std::set<unsigned int> in_set(node_set.begin(), node_set.end());
    const double                 lambda = material.lambda(), mu = material.mu();
    const UpdateFlags            flags  = update_values | update_gradients | update_quadrature_points | update_JxW_values;
    geometry::Point              force;
    BasisValues                  basis;
    Sides                        side;
    std::vector<Tensor<1, 2>>    u;
    std::vector<Tensor<2, 2>>    grad;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const auto functions = local_functions(cell);
        if (std::none_of(functions.begin(), functions.end(),
                         [&](const LocalFunction &f) { return f.kind < 0 && in_set.count(f.dof / 2); }))
          continue;
        FEValues<2> fv(mapping, fe, quadrature(cell), flags);
        fv.reinit(cell);
        sides_at(cell, fv, side);
        evaluate(fv, functions, side, basis);
        field(fv, functions, side, u, grad);
        for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
          {
            const Tensor<2, 2> eps   = 0.5 * (grad[q] + transpose(grad[q]));
            Tensor<2, 2>       sigma = 2. * mu * eps;
            sigma[0][0] += lambda * trace(eps);
            sigma[1][1] += lambda * trace(eps);
            for (unsigned int f = 0; f < functions.size(); ++f)
              if (functions[f].kind < 0 && in_set.count(functions[f].dof / 2))
                {
                  const Tensor<1, 2> t = sigma * basis.grad[f][q];
                  force.x += t[0] * fv.JxW(q);
                  force.y += t[1] * fv.JxW(q);
                }
          }
      }
    const double tol = 1e-6 * GridTools::minimal_cell_diameter(tria);
    for (const auto &load : point_loads)
      for (const auto p : node_set)
        if (geometry::norm(to_point(support[nodes[p]]) - load.at) <= tol)
          force = force - load.force;
    return force;
  }

  namespace
  {
    /// Rows and columns [begin, end) of a sparse matrix as a matrix of their own.
    void extract_block(const SparseMatrix<double> &m, unsigned int begin, unsigned int end, SparsityPattern &pattern,
                       SparseMatrix<double> &block)
    {
      DynamicSparsityPattern dsp(end - begin);
      for (unsigned int i = begin; i < end; ++i)
        for (auto it = m.begin(i); it != m.end(i); ++it)
          if (it->column() >= begin && it->column() < end)
            dsp.add(i - begin, it->column() - begin);
      pattern.copy_from(dsp);
      block.reinit(pattern);
      for (unsigned int i = begin; i < end; ++i)
        for (auto it = m.begin(i); it != m.end(i); ++it)
          if (it->column() >= begin && it->column() < end)
            block.set(i - begin, it->column() - begin, it->value());
    }

    /// diag(AMG(A_ss), A_ee^-1) applied to a vector ordered [standard | enriched].
    struct BlockJacobi
    {
      const TrilinosWrappers::PreconditionAMG &amg;
      const SparseDirectUMFPACK               &enriched;
      unsigned int                             n_standard, n;

      void vmult(Vector<double> &dst, const Vector<double> &src) const
      {
        Vector<double> s(n_standard), d(n_standard);
        for (unsigned int i = 0; i < n_standard; ++i)
          s(i) = src(i);
        amg.vmult(d, s);
        for (unsigned int i = 0; i < n_standard; ++i)
          dst(i) = d(i);
        if (n > n_standard)
          {
            Vector<double> e(n - n_standard);
            for (unsigned int i = n_standard; i < n; ++i)
              e(i - n_standard) = src(i);
            enriched.solve(e);
            for (unsigned int i = n_standard; i < n; ++i)
              dst(i) = e(i - n_standard);
          }
      }
    };
  } // namespace

  SolveReport EnrichedElasticity::Impl::solve(const SolverSettings &settings_)
  {
    const auto  start = std::chrono::steady_clock::now();
    SolveReport report;
    use_single_threaded_blas();
    if (settings_.type == SolverSettings::Type::direct)
      {
        // Symmetric diagonal scaling D A D y = D f, D = diag(A)^-1/2, x = D y: the enriched
        // unknowns' diagonals are orders of magnitude below the standard ones; scaled, every
        // diagonal is 1, for the Cholesky factorization and for the LU fallback, whose diagonal
        // pivots (and with them its fill-reducing ordering) need it.
        Vector<double> scale(n_dofs), scaled_rhs(rhs);
        for (unsigned int i = 0; i < n_dofs; ++i)
          scale(i) = matrix.diag_element(i) > 0. ? 1. / std::sqrt(matrix.diag_element(i)) : 1.;
        SparseMatrix<double> scaled(matrix.get_sparsity_pattern());
        scaled.copy_from(matrix);
        for (unsigned int i = 0; i < n_dofs; ++i)
          for (auto it = scaled.begin(i); it != scaled.end(i); ++it)
            it->value() *= scale(i) * scale(it->column());
        scaled_rhs.scale(scale);
        report.solver = "Cholesky (CHOLMOD)";
        if (!solve_cholesky(scaled, scaled_rhs, solution))
          {
            SparseDirectUMFPACK direct;
            direct.initialize(scaled);
            direct.vmult(solution, scaled_rhs);
            report.solver = "UMFPACK (not positive definite for Cholesky)";
          }
        solution.scale(scale);
      }
    else
      {
        if (!Utilities::MPI::job_supports_mpi())
          throw std::logic_error("CG + AMG (Trilinos) needs MPI: create a Utilities::MPI::MPI_InitFinalize in main()");
        // Unknowns are ordered [standard | enriched]. Block-Jacobi preconditioner: AMG on the
        // standard block (rigid-body near-null space), a direct solve on the enriched block,
        // whose functions are not smooth and would defeat AMG's coarsening.
        const unsigned int n_standard = 2 * nodes.size();
        SparseMatrix<double> standard_block, enriched_block;
        SparsityPattern      standard_pattern, enriched_pattern;
        extract_block(matrix, 0, n_standard, standard_pattern, standard_block);
        extract_block(matrix, n_standard, n_dofs, enriched_pattern, enriched_block);

        TrilinosWrappers::SparseMatrix A;
        A.reinit(standard_block);
        Epetra_MultiVector modes(A.trilinos_matrix().DomainMap(), 3);
        for (unsigned int p = 0; p < nodes.size(); ++p)
          {
            const auto &x    = support[nodes[p]];
            modes[0][2 * p]     = 1.;
            modes[1][2 * p + 1] = 1.;
            modes[2][2 * p]     = -x[1];
            modes[2][2 * p + 1] = x[0];
          }
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.higher_order_elements = false;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        Teuchos::ParameterList              list;
        std::unique_ptr<Epetra_MultiVector> unused;
        data.set_parameters(list, unused, A.trilinos_matrix());
        list.set("null space: type", "pre-computed");
        list.set("null space: dimension", 3);
        list.set("null space: vectors", modes.Values());
        TrilinosWrappers::PreconditionAMG amg;
        amg.initialize(A.trilinos_matrix(), list);
        SparseDirectUMFPACK enriched_solver;
        if (n_dofs > n_standard)
          enriched_solver.initialize(enriched_block);

        BlockJacobi preconditioner{amg, enriched_solver, n_standard, n_dofs};
        SolverControl            control(settings_.max_iterations, settings_.tolerance * rhs.l2_norm());
        SolverCG<Vector<double>> cg(control);
        solution = 0.;
        cg.solve(matrix, solution, rhs, preconditioner);
        report.solver     = "CG + AMG";
        report.iterations = control.last_step();
      }
    constraints.distribute(solution);
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
  }
} // namespace pumpd::global
