// The problem of the global convergence test (tests/global/convergence_test.cc), shared by the
// global benchmarks and studies: the exact Williams field of unit K (mode I or II) imposed on
// the square [-1, 1] x [-0.97, 1.03] with an edge crack from the left edge to the tip
// (0.013, 0): the exact displacement on three edges, the exact traction on the edge that holds
// the crack mouth. The crack line and the tip lie at generic positions in every uniform mesh.
#pragma once

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <vector>

#include "elasticity.h"
#include "lefm.h"

namespace pumpd::bench
{
  using global::Crack;
  using global::ElasticMaterial;
  using global::EnrichedElasticity;
  using global::EnrichmentSettings;
  using global::SidedField;

  inline const geometry::Point tip{0.013, 0.};
  inline const double          x_min = -1., y_min = -0.97, x_max = 1., y_max = 1.03;

  /// The exact field: Williams, unit K, in the frame of the tip (crack along -x).
  struct Williams
  {
    int             mode = 1;
    ElasticMaterial material{1., 0.3, true};

    lefm::TipField at(geometry::Point x, int side) const
    {
      const geometry::Point rel = x - tip;
      const double          r   = std::max(geometry::norm(rel), 1e-300);
      return lefm::williams(mode, r, side * std::acos(std::clamp(rel.x / r, -1., 1.)), material.mu(),
                            material.kolosov());
    }
    geometry::Point u(geometry::Point x, int side) const
    {
      const auto f = at(x, side);
      return {f.u[0], f.u[1]};
    }
    SidedField displacement() const
    {
      return [*this](geometry::Point x, int side) { return u(x, side); };
    }
    std::function<std::array<double, 4>(geometry::Point, int)> gradient() const
    {
      return [*this](geometry::Point x, int side) {
        const auto f = at(x, side);
        return std::array<double, 4>{{f.grad[0][0], f.grad[0][1], f.grad[1][0], f.grad[1][1]}};
      };
    }
  };

  /// n x n cells on the square, boundary ids 0 (left, the crack mouth), 1 (right), 2 (bottom), 3 (top).
  inline void make_square(dealii::Triangulation<2> &tria, unsigned int n)
  {
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {n, n}, dealii::Point<2>(x_min, y_min),
                                                      dealii::Point<2>(x_max, y_max), true);
  }

  inline Crack edge_crack()
  {
    const geometry::Body body{{x_min, y_min, x_max, y_max}, {}};
    return Crack({{x_min, 0.}, tip}, body, 1e-12);
  }

  /// The boundary data of the convergence test: the exact displacement on ids 1-3, the exact
  /// traction sigma n (n = (-1, 0)) on id 0, each side of the mouth its own.
  inline void add_williams_boundary_data(EnrichedElasticity &problem, const Williams &field)
  {
    for (unsigned int id = 1; id < 4; ++id)
      problem.add_dirichlet(id, field.displacement());
    problem.add_traction(0, [field](geometry::Point x) {
      const auto f = field.at(x, x.y >= 0. ? 1 : -1);
      return geometry::Point{-f.stress[0][0], -f.stress[1][0]};
    });
  }

  /// The edge crack with the Williams boundary data, set up, assembled and solved.
  inline void solve_williams(EnrichedElasticity &problem, const Williams &field)
  {
    problem.set_crack(edge_crack());
    add_williams_boundary_data(problem, field);
    problem.setup();
    problem.assemble();
    problem.solve();
  }

  inline double seconds_since(std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  inline double median(std::vector<double> v)
  {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  }
} // namespace pumpd::bench
