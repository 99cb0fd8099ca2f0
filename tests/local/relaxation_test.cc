// Dynamic relaxation against an equilibrium known exactly: an affine displacement u = E x + omega
// e_z x x prescribed on the boundary layer of a box inside the body. Every free node then has its
// full stencil, and each bond xi meets its mirror -xi at the same stretch, so the affine field is
// in equilibrium under any bond law; relaxed from zero inside, the free nodes must reach it (max
// error 1e-6 of the largest displacement, at tolerance 1e-10). Also the bound behind the fictitious
// density rho = Lambda / 4: no displacement field stores more than Lambda |u|^2 (u.K u).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "boundary_layer.h"
#include "integrators.h"
#include "metric.h"
#include "model.h"

using namespace pumpd;
using namespace pumpd::local;

namespace
{
  constexpr double delta = 0.004;

  PdModel plate(int m)
  {
    Region region;
    region.body = geometry::Body(geometry::Box{-1., -1., 1., 1.});
    region.box  = {0., 0., 12. * delta, 8. * delta};
    return PdModel(MaterialParameters{}, delta, m, region);
  }

  geometry::Point affine(geometry::Point x)
  {
    const double exx = 1e-4, eyy = -3e-5, exy = 4e-5, omega = 2e-4;
    return {exx * x.x + exy * x.y - omega * x.y, exy * x.x + eyy * x.y + omega * x.x};
  }
} // namespace

TEST(DynamicRelaxation, ReachesTheAffineEquilibrium)
{
  for (int m : {4, 8})
    {
      const PdModel model = plate(m);
      BoundaryLayer layer(model);
      layer.set_target(affine);
      State s = model.initial_state();
      layer.apply(s, 1.);
      const auto result = DynamicRelaxation(model, 1e-10, 100000).solve(s);
      ASSERT_TRUE(result.converged) << "m = " << m << ": residual " << result.residual;

      double error = 0., largest = 0.;
      for (std::size_t i : model.nodes())
        {
          const auto u = affine(model.lattice().position(i));
          error        = std::max(error, std::hypot(s.ux[i] - u.x, s.uy[i] - u.y));
          largest      = std::max(largest, std::hypot(u.x, u.y));
        }
      std::cout << "m = " << m << ": " << model.nodes().size() << " nodes, " << result.iterations
                << " iterations, max error " << error / largest << " of the largest displacement\n";
      EXPECT_LT(error, 1e-6 * largest) << "m = " << m;
      test::metric("pd.relaxation_affine_iterations_m" + std::to_string(m), double(result.iterations));
    }
}

TEST(DynamicRelaxation, StiffnessBoundedByTheScale)
{
  const PdModel model = plate(8);
  State         s     = model.initial_state();
  // A checkerboard in x, a stripe pattern in y and a smooth field: the lattice's stiffest modes
  // and a soft one, all small enough to stay linear.
  for (std::size_t i : model.nodes())
    {
      const auto   x = model.lattice().position(i);
      const double h = model.lattice().spacing();
      const long   p = std::lround(x.x / h), q = std::lround(x.y / h);
      s.ux[i]        = 1e-9 * ((p + q) % 2 == 0 ? 1. : -1.);
      s.uy[i]        = 1e-9 * (p % 2 == 0 ? 1. : -1.) + 1e-9 * std::sin(x.x / delta);
    }
  model.compute_forces(s);
  double uKu = 0., u2 = 0.;
  for (std::size_t i : model.nodes())
    {
      uKu -= s.ux[i] * s.fx[i] + s.uy[i] * s.fy[i];
      u2 += s.ux[i] * s.ux[i] + s.uy[i] * s.uy[i];
    }
  const double ratio = uKu / (model.stiffness_scale() * u2);
  std::cout << "u.K u / (Lambda |u|^2) = " << ratio << "\n";
  EXPECT_GT(ratio, 0.);
  EXPECT_LE(ratio, 1.);
}
