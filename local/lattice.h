// The uniform PD lattice in a box and the stencil of bond offsets (DESIGN.md, local/).
//
// Nodes sit at cell centres, spacing h, horizon delta = m h. Storage is row-major with m ghost
// columns left and right and m ghost rows on top, row length padded to a multiple of 64, so that
// the half stencil (dy > 0, or dy = 0 and dx > 0) of every real node stays in memory, every bond
// is visited once, and bond bits of one row and offset fill whole 64-bit words.
#pragma once

#include <cstddef>
#include <vector>

#include "geometry.h"

namespace pumpd::local
{
  class LiptonMaterial;

  /// Bond offsets of the half stencil, in lattice units, with their quadrature weights.
  struct Stencil
  {
    int                 reach = 0; ///< m: offsets reach m cells (plus the partial cells at the rim)
    std::vector<int>    dx, dy;
    std::vector<double> length;    ///< |xi| / h
    std::vector<double> ex, ey;    ///< unit bond direction
    /// Partial-volume weight: (1/h^2) int over the neighbour's cell inside the horizon of
    /// J(|xi| / delta) dxi; integrated numerically so that rim cells count with their inside part.
    std::vector<double> weight;

    std::size_t size() const { return dx.size(); }
  };

  /// The half stencil for horizon ratio m and the material's influence function. It depends on
  /// nothing else (lengths in spacings), so it is integrated once per (m, influence function) in
  /// a process and copied after: every PD state of a run builds a model with it.
  Stencil make_half_stencil(int m, const LiptonMaterial &material);

  class Lattice
  {
  public:
    /// Nodes filling the box at spacing h, centred in it. Throws InvalidParameter if h <= 0,
    /// m < 2, or the box holds fewer than 2 m + 1 nodes across either way.
    Lattice(const geometry::Box &box, double spacing, int m);

    double      spacing() const { return h; }
    int         reach() const { return m; }
    std::size_t nx() const { return n_x; }
    std::size_t ny() const { return n_y; }
    std::size_t stride() const { return row_stride; }
    /// Number of stored entries (real and ghost nodes, plus slack for the last row's reach).
    std::size_t storage_size() const { return row_stride * (n_y + m + 1); }
    std::size_t index(std::size_t ix, std::size_t iy) const { return ix + m + row_stride * iy; }
    std::size_t column(std::size_t i) const { return i % row_stride - m; }
    std::size_t row(std::size_t i) const { return i / row_stride; }
    bool        is_real(std::size_t i) const;
    geometry::Point position(std::size_t i) const;
    const geometry::Box &box() const { return b; }

  private:
    geometry::Box b;
    double        h;
    int           m;
    std::size_t   n_x, n_y, row_stride;
    double        x0, y0; ///< position of node (0, 0)
  };
} // namespace pumpd::local
