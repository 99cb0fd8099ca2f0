// The sparse Cholesky solve (global/cholesky.h) on matrices with a known answer:
// - the 1D Laplacian tridiag(-1, 2, -1) of size n, symmetric positive definite, against the
//   solution x_i = i (i = 1..n), whose right-hand side is 0 except b_n = n + 1;
// - the same matrix with its sign flipped in one diagonal entry (indefinite): the solve says so
//   and leaves x as it was, for the caller's LU fall-back.
#include <gtest/gtest.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include "cholesky.h"

using namespace dealii;

namespace
{
  const unsigned int n = 200;

  void laplacian(SparsityPattern &pattern, SparseMatrix<double> &A)
  {
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i > 0 ? i - 1 : 0); j <= std::min(i + 1, n - 1); ++j)
        dsp.add(i, j);
    pattern.copy_from(dsp);
    A.reinit(pattern);
    for (unsigned int i = 0; i < n; ++i)
      {
        A.set(i, i, 2.);
        if (i > 0)
          A.set(i, i - 1, -1.);
        if (i + 1 < n)
          A.set(i, i + 1, -1.);
      }
  }
} // namespace

TEST(Cholesky, SolvesThePositiveDefiniteLaplacian)
{
  SparsityPattern      pattern;
  SparseMatrix<double> A;
  laplacian(pattern, A);
  Vector<double> b(n), x;
  b(n - 1) = n + 1.;
  ASSERT_TRUE(pumpd::global::solve_cholesky(A, b, x));
  ASSERT_EQ(x.size(), n);
  for (unsigned int i = 0; i < n; ++i)
    EXPECT_NEAR(x(i), i + 1., 1e-10 * n);
}

TEST(Cholesky, RefusesAnIndefiniteMatrix)
{
  SparsityPattern      pattern;
  SparseMatrix<double> A;
  laplacian(pattern, A);
  A.set(n / 2, n / 2, -2.);
  Vector<double> b(n), x(3);
  b = 1.;
  x = 7.;
  EXPECT_FALSE(pumpd::global::solve_cholesky(A, b, x));
  EXPECT_EQ(x.size(), 3u);
  EXPECT_EQ(x(0), 7.);
}
