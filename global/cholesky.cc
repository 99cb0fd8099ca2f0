#include "cholesky.h"

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <cholmod.h>

#include <stdexcept>

namespace pumpd::global
{
  namespace
  {
    /// CHOLMOD's workspace, released however the solve ends.
    struct Common
    {
      cholmod_common c;
      Common() { cholmod_start(&c); }
      ~Common() { cholmod_finish(&c); }
    };

    /// The upper triangle of A in compressed columns: by symmetry, column j holds the entries
    /// (i, j), i <= j, of row j.
    cholmod_sparse *upper_triangle(const dealii::SparseMatrix<double> &A, cholmod_common &c)
    {
      const std::size_t n   = A.m();
      std::size_t       nnz = 0;
      for (std::size_t j = 0; j < n; ++j)
        for (auto it = A.begin(j); it != A.end(j); ++it)
          nnz += it->column() <= j;
      cholmod_sparse *U  = cholmod_allocate_sparse(n, n, nnz, 0, 1, 1, CHOLMOD_REAL, &c);
      auto           *Up = static_cast<int *>(U->p);
      auto           *Ui = static_cast<int *>(U->i);
      auto           *Ux = static_cast<double *>(U->x);
      std::size_t     k  = 0;
      for (std::size_t j = 0; j < n; ++j)
        {
          Up[j] = int(k);
          for (auto it = A.begin(j); it != A.end(j); ++it)
            if (it->column() <= j)
              {
                Ui[k] = int(it->column());
                Ux[k] = it->value();
                ++k;
              }
        }
      Up[n] = int(k);
      return U;
    }
  } // namespace

  bool solve_cholesky(const dealii::SparseMatrix<double> &A, const dealii::Vector<double> &b,
                      dealii::Vector<double> &x)
  {
    Common          common;
    cholmod_common &c = common.c;
    c.supernodal      = CHOLMOD_SUPERNODAL;
    cholmod_sparse *U = upper_triangle(A, c);
    cholmod_factor *L = cholmod_analyze(U, &c);
    cholmod_factorize(U, L, &c);
    const bool positive_definite = c.status == CHOLMOD_OK && L->minor == L->n;
    if (positive_definite)
      {
        cholmod_dense *B  = cholmod_allocate_dense(b.size(), 1, b.size(), CHOLMOD_REAL, &c);
        auto          *Bx = static_cast<double *>(B->x);
        for (unsigned int i = 0; i < b.size(); ++i)
          Bx[i] = b(i);
        cholmod_dense *X = cholmod_solve(CHOLMOD_A, L, B, &c);
        if (X == nullptr)
          throw std::runtime_error("CHOLMOD: the triangular solves failed (status " + std::to_string(c.status) + ")");
        const auto *Xx = static_cast<const double *>(X->x);
        x.reinit(b.size());
        for (unsigned int i = 0; i < b.size(); ++i)
          x(i) = Xx[i];
        cholmod_free_dense(&X, &c);
        cholmod_free_dense(&B, &c);
      }
    cholmod_free_factor(&L, &c);
    cholmod_free_sparse(&U, &c);
    return positive_definite;
  }
} // namespace pumpd::global
