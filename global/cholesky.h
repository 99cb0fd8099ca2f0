// A sparse Cholesky solve of the global system: CHOLMOD (SuiteSparse, the package that holds
// deal.II's UMFPACK) factors a symmetric positive definite matrix as L L^T with supernodes, dense
// blocks handed to the system's BLAS, in a fill-reducing order of its choice (AMD or METIS).
// For the enriched elasticity matrix, symmetric and positive definite once the constrained rows
// are condensed, this needs half the work and memory of an LU factorization.
#pragma once

namespace dealii
{
  template <typename Number>
  class SparseMatrix;
  template <typename Number>
  class Vector;
} // namespace dealii

namespace pumpd::global
{
  /// x = A^-1 b for a symmetric positive definite A (both triangles stored, only the upper one is
  /// read). Returns false and leaves x as it was when CHOLMOD finds A not positive definite
  /// (numerically), so the caller can fall back to an LU solve. Throws std::runtime_error when
  /// CHOLMOD fails otherwise (out of memory, a matrix too large for its integers).
  bool solve_cholesky(const dealii::SparseMatrix<double> &A, const dealii::Vector<double> &b,
                      dealii::Vector<double> &x);
} // namespace pumpd::global
