#include "cholesky.h"

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <cholmod.h>
#include <omp.h>

#include <stdexcept>
#include <string>

namespace pumpd::global
{
  namespace
  {
    /// CHOLMOD's workspace and the objects of one solve, released however the solve ends. CHOLMOD
    /// prints nothing: a matrix not positive definite is an answer (the caller's fallback), and
    /// the errors are thrown.
    struct Cholmod
    {
      cholmod_common  c;
      cholmod_sparse *U = nullptr;
      cholmod_factor *L = nullptr;
      cholmod_dense  *B = nullptr, *X = nullptr;

      Cholmod()
      {
        cholmod_start(&c);
        c.print      = 0;
        c.supernodal = CHOLMOD_SUPERNODAL;
      }
      ~Cholmod()
      {
        cholmod_free_dense(&X, &c);
        cholmod_free_dense(&B, &c);
        cholmod_free_factor(&L, &c);
        cholmod_free_sparse(&U, &c);
        cholmod_finish(&c);
      }
      Cholmod(const Cholmod &)            = delete;
      Cholmod &operator=(const Cholmod &) = delete;

      /// Throws std::runtime_error naming `step` if it returned nothing or CHOLMOD reports an
      /// error (out of memory, a matrix too large for its integers).
      void check(const void *result, const std::string &step) const
      {
        if (result != nullptr && c.status >= CHOLMOD_OK)
          return;
        const std::string why = c.status == CHOLMOD_OUT_OF_MEMORY ? "out of memory" :
                                c.status == CHOLMOD_TOO_LARGE     ? "the matrix is too large" :
                                                                    "status " + std::to_string(c.status);
        throw std::runtime_error("CHOLMOD: " + step + " failed: " + why);
      }
    };

    /// CHOLMOD opens an OpenMP parallel region each time it clears, copies or assembles a
    /// supernode: one per supernode step, each too small to pay for waking a thread that waits
    /// passively (coupling/main.cc). While one lives, every parallel region of the process runs
    /// on one thread (libgomp's max-active-levels is process-wide). The regions split loops
    /// without sums, so the factor is the same either way.
    class OpenMpOnOneThread
    {
    public:
      OpenMpOnOneThread()
        : levels(omp_get_max_active_levels())
      {
        omp_set_max_active_levels(0);
      }
      ~OpenMpOnOneThread() { omp_set_max_active_levels(levels); }
      OpenMpOnOneThread(const OpenMpOnOneThread &)            = delete;
      OpenMpOnOneThread &operator=(const OpenMpOnOneThread &) = delete;

    private:
      const int levels;
    };

    /// The upper triangle of A in compressed columns: by symmetry, column j holds the entries
    /// (i, j), i <= j, of row j.
    void upper_triangle(const dealii::SparseMatrix<double> &A, Cholmod &cm)
    {
      const std::size_t n   = A.m();
      std::size_t       nnz = 0;
      for (std::size_t j = 0; j < n; ++j)
        for (auto it = A.begin(j); it != A.end(j); ++it)
          nnz += it->column() <= j;
      cm.U = cholmod_allocate_sparse(n, n, nnz, 0, 1, 1, CHOLMOD_REAL, &cm.c);
      cm.check(cm.U, "allocating the matrix");
      auto       *Up = static_cast<int *>(cm.U->p);
      auto       *Ui = static_cast<int *>(cm.U->i);
      auto       *Ux = static_cast<double *>(cm.U->x);
      std::size_t k  = 0;
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
    }
  } // namespace

  bool solve_cholesky(const dealii::SparseMatrix<double> &A, const dealii::Vector<double> &b,
                      dealii::Vector<double> &x)
  {
    const OpenMpOnOneThread one_thread;
    Cholmod                 cm;
    upper_triangle(A, cm);
    cm.L = cholmod_analyze(cm.U, &cm.c);
    cm.check(cm.L, "the analysis (fill-reducing ordering)");
    cholmod_factorize(cm.U, cm.L, &cm.c);
    cm.check(cm.L, "the factorization");
    if (cm.c.status != CHOLMOD_OK || cm.L->minor != cm.L->n)
      return false; // not positive definite
    cm.B = cholmod_allocate_dense(b.size(), 1, b.size(), CHOLMOD_REAL, &cm.c);
    cm.check(cm.B, "allocating the right-hand side");
    auto *Bx = static_cast<double *>(cm.B->x);
    for (unsigned int i = 0; i < b.size(); ++i)
      Bx[i] = b(i);
    cm.X = cholmod_solve(CHOLMOD_A, cm.L, cm.B, &cm.c);
    cm.check(cm.X, "the triangular solves");
    const auto *Xx = static_cast<const double *>(cm.X->x);
    x.reinit(b.size());
    for (unsigned int i = 0; i < b.size(); ++i)
      x(i) = Xx[i];
    return true;
  }
} // namespace pumpd::global
