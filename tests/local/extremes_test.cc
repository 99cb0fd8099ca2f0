// Stability at the extremes, PD co-solver:
// (a) Velocity Verlet at 0.99 and 1.01 of the Silling-Askari bound: 1.01 is refused
//     (InvalidParameter naming "PD time step"); 0.99 runs 2000 steps of a box stretched through
//     its boundary layer (ramped over 300 steps, then held) and stays bounded: the energy balance
//     elastic + kinetic + dissipated = work of the layer holds to 2 % of the work at every 100th
//     step, and no free node moves more than twice the largest imposed displacement (an unstable
//     step grows exponentially and breaks both within a few hundred steps).
// (b) "Model only what a scene requires": a hole outside the PD box adds no PD node and no bond
//     (same node count, same broken-bond bits as without it), while the same hole inside the box
//     removes nodes (so the comparison can fail).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "boundary_layer.h"
#include "error.h"
#include "integrators.h"
#include "metric.h"
#include "model.h"

using namespace pumpd;
using namespace pumpd::local;

namespace
{
  constexpr double delta = 0.004;
  constexpr int    m     = 4;

  Region region()
  {
    Region r;
    r.body = geometry::Body(geometry::Box{0., 0., 0.1, 0.1});
    r.box          = {0.03, 0.03, 0.07, 0.07};
    return r;
  }
} // namespace

TEST(LocalExtremes, VerletAtOneOhOneOfTheBoundIsRefused)
{
  const PdModel model(MaterialParameters{}, delta, m, region());
  const double  bound = model.stable_time_step();
  try
    {
      VelocityVerlet(model, 1.01 * bound);
      ADD_FAILURE() << "dt = 1.01 x bound accepted";
    }
  catch (const InvalidParameter &e)
    {
      const std::string what = e.what();
      std::cout << what << "\n";
      EXPECT_EQ(what.rfind("PD time step = ", 0), 0u) << what;
    }
}

TEST(LocalExtremes, VerletAtZeroNinetyNineOfTheBoundStaysBoundedFor2000Steps)
{
  const PdModel  model(MaterialParameters{}, delta, m, region());
  const double   bound = model.stable_time_step();
  VelocityVerlet verlet(model, 0.99 * bound);

  // Uniaxial stretch 1e-3 with lateral contraction, about the box centre (elastic: no bond fails).
  const double  eps = 1e-3, xc = 0.05, yc = 0.05;
  BoundaryLayer layer(model);
  layer.set_target([&](geometry::Point x) { return geometry::Point{eps * (x.x - xc), -0.25 * eps * (x.y - yc)}; });
  double imposed = 0.;
  for (const auto &x : layer.positions())
    imposed = std::max(imposed, std::hypot(eps * (x.x - xc), 0.25 * eps * (x.y - yc)));

  State s = model.initial_state();
  verlet.initialise(s);
  double worst_balance = 0., largest = 0.;
  for (std::size_t n = 1; n <= 2000; ++n)
    {
      ASSERT_NO_THROW(verlet.step(s, layer, std::min(1., n / 300.))) << "step " << n;
      if (n % 100 != 0)
        continue;
      const double elastic = model.elastic_energy(s), kinetic = model.kinetic_energy(s);
      ASSERT_TRUE(std::isfinite(elastic) && std::isfinite(kinetic)) << "step " << n;
      ASSERT_GT(s.external_work, 0.) << "step " << n;
      const double balance = std::abs(elastic + kinetic + s.dissipated - s.external_work) / s.external_work;
      worst_balance        = std::max(worst_balance, balance);
      double step_largest  = 0.;
      for (std::size_t i : model.nodes())
        step_largest = std::max(step_largest, model.free_mask()[i] * std::hypot(s.ux[i], s.uy[i]));
      largest = std::max(largest, step_largest);
      if (n % 500 == 0)
        std::cout << "step " << n << ": elastic " << elastic << " J/m, kinetic " << kinetic << " J/m, work "
                  << s.external_work << " J/m, balance error " << balance << ", largest free |u| / imposed "
                  << step_largest / imposed << "\n";
    }
  test::metric("pd.verlet_0.99_bound_energy_balance_rel_err", worst_balance);
  test::metric("pd.verlet_0.99_bound_max_u_over_imposed", largest / imposed);
  EXPECT_LT(worst_balance, 0.02);
  EXPECT_LT(largest, 2. * imposed);
  EXPECT_EQ(s.dissipated, 0.);
}

TEST(LocalExtremes, HoleOutsideTheBoxAddsNoPdNode)
{
  const Region    plain = region();
  Region          far   = plain;
  far.body              = geometry::Body(plain.body.bounding_box(), {{{0.085, 0.085}, 0.006}}); // 15 mm from the box corner, well beyond delta
  Region          near  = plain;
  near.body             = geometry::Body(plain.body.bounding_box(), {{{0.05, 0.05}, 0.006}});
  const PdModel   a(MaterialParameters{}, delta, m, plain), b(MaterialParameters{}, delta, m, far),
    c(MaterialParameters{}, delta, m, near);
  std::cout << "PD nodes: no hole " << a.nodes().size() << ", hole outside the box " << b.nodes().size()
            << ", hole inside " << c.nodes().size() << "\n";
  EXPECT_EQ(a.nodes().size(), b.nodes().size());
  EXPECT_EQ(a.nodes(), b.nodes());
  EXPECT_EQ(a.boundary_layer(), b.boundary_layer());
  EXPECT_EQ(a.initial_state().broken, b.initial_state().broken);
  EXPECT_LT(c.nodes().size(), a.nodes().size());
}
