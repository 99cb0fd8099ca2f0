// Bad input is refused with one InvalidParameter whose message names the parameter and its allowed
// range ("<name> = <value>: <allowed range>"), before anything is computed with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <memory>
#include <string>

#include "boundary_layer.h"
#include "error.h"
#include "expect_invalid.h"
#include "explicit_run.h"
#include "integrators.h"
#include "lattice.h"
#include "material.h"
#include "model.h"

using namespace pumpd;
using pumpd::test::expect_invalid;
using namespace pumpd::local;

namespace
{
  constexpr double delta = 0.004; // m = 4, h = 1 mm
  constexpr int    m     = 4;

  Region good_region()
  {
    Region r;
    r.body = geometry::Body(geometry::Box{0., 0., 0.1, 0.1});
    r.box          = {0.03, 0.03, 0.07, 0.07};
    return r;
  }

  PdModel make_model(double horizon, int ratio, const Region &region = good_region(),
                     const MaterialParameters &p = {})
  {
    return PdModel(p, horizon, ratio, region);
  }
} // namespace

// delta <= 0 is caught by the material ("Horizon"), h <= 0 by the lattice ("PD spacing h").
TEST(BadInput, HorizonAndSpacingPositive)
{
  for (double horizon : {0., -0.004})
    {
      expect_invalid([&] { LiptonMaterial(MaterialParameters{}, horizon); }, "Horizon", "> 0");
      expect_invalid([&] { make_model(horizon, m); }, "Horizon", "> 0");
    }
  for (double h : {0., -0.001})
    expect_invalid([&] { Lattice(good_region().box, h, m); }, "PD spacing h", "> 0");

  MaterialParameters p;
  p.youngs_modulus = 0.;
  expect_invalid([&] { make_model(delta, m, good_region(), p); }, "Young's modulus", "> 0");
  p                = MaterialParameters{};
  p.break_factor   = 0.5;
  expect_invalid([&] { make_model(delta, m, good_region(), p); }, "Bond break factor", "in [1, 1e6]");
}

// m < 2 must name "Horizon over spacing (m)", whether the lattice is built directly or through
// PdModel (which derives h = delta / m from it).
TEST(BadInput, HorizonRatioAtLeastTwo)
{
  for (int ratio : {1, 0})
    expect_invalid([&] { Lattice(good_region().box, 0.001, ratio); }, "Horizon over spacing (m)", ">= 2");
  for (int ratio : {1, 0, -1})
    {
      SCOPED_TRACE("PdModel with m = " + std::to_string(ratio));
      expect_invalid([&] { make_model(delta, ratio); }, "Horizon over spacing (m)", ">= 2");
    }
  EXPECT_NO_THROW(make_model(delta, 2));
}

// Above the Silling-Askari bound the integrator refuses the step and names the bound; just below
// it a loaded run of a few hundred steps stays finite and bounded by the imposed displacement.
TEST(BadInput, TimeStepAboveStabilityBound)
{
  const PdModel model = make_model(delta, m);
  const double  bound = model.stable_time_step();
  // The bound from its definition, sqrt(2 rho / sum_j c_j / |xi_j|) over the full stencil.
  EXPECT_NEAR(bound, std::sqrt(2. * model.material().parameters().density / model.stiffness_scale()),
              1e-15 * bound);

  for (double dt : {1.01 * bound, 0., -bound})
    expect_invalid([&] { VelocityVerlet(model, dt); }, "PD time step", "Silling-Askari");
  try
    {
      VelocityVerlet(model, 1.01 * bound);
    }
  catch (const InvalidParameter &e)
    {
      // The message quotes the bound: "... must be in (0, <bound>] s ...".
      const std::string what = e.what();
      const auto        at   = what.find("(0, ");
      ASSERT_NE(at, std::string::npos) << what;
      const double quoted = std::strtod(what.c_str() + at + 4, nullptr);
      EXPECT_NEAR(quoted, bound, 1e-5 * bound) << what;
    }

  std::unique_ptr<VelocityVerlet> verlet;
  ASSERT_NO_THROW(verlet = std::make_unique<VelocityVerlet>(model, 0.99 * bound));
  EXPECT_NO_THROW(VelocityVerlet(model, bound));

  // Uniaxial stretch 1e-3 about the box centre, ramped over 300 steps and held for 100.
  const double  eps = 1e-3, xc = 0.05, yc = 0.05;
  BoundaryLayer layer(model);
  layer.set_target([&](geometry::Point x) { return geometry::Point{eps * (x.x - xc), 0.5 * eps * (x.y - yc)}; });
  double imposed = 0.;
  for (const auto &x : layer.positions())
    imposed = std::max(imposed, std::hypot(eps * (x.x - xc), 0.5 * eps * (x.y - yc)));
  State s = model.initial_state();
  verlet->initialise(s);
  for (std::size_t n = 1; n <= 400; ++n)
    ASSERT_NO_THROW(verlet->step(s, layer, std::min(1., n / 300.))) << "step " << n;
  // Free nodes only (the layer holds the imposed values by construction).
  double largest = 0.;
  for (std::size_t i : model.nodes())
    {
      ASSERT_TRUE(std::isfinite(s.ux[i]) && std::isfinite(s.uy[i]));
      largest = std::max(largest, model.free_mask()[i] * std::hypot(s.ux[i], s.uy[i]));
    }
  std::cout << "largest free displacement / largest imposed: " << largest / imposed << "\n";
  // Dynamic overshoot of a ramped load stays well below 2; an unstable step grows exponentially.
  // The free nodes next to the layer move nearly as much as it does.
  EXPECT_LT(largest, 2. * imposed);
  EXPECT_GT(largest, 0.3 * imposed);
}

// The box must lie inside the body and hold 2 m + 1 nodes each way; an inverted box (min > max)
// is not a box.
TEST(BadInput, BoxOutsideBodyOrTooSmall)
{
  Region r = good_region();
  r.box    = {0.2, 0.2, 0.24, 0.24};
  expect_invalid([&] { make_model(delta, m, r); }, "PD box", "inside the body");
  r.box = {0.08, 0.03, 0.12, 0.07}; // sticks out on the right
  expect_invalid([&] { make_model(delta, m, r); }, "PD box", "inside the body");

  r.box = {0.03, 0.03, 0.038, 0.07}; // 8 spacings across, m = 4 needs 9
  expect_invalid([&] { make_model(delta, m, r); }, "PD box", "2 m + 1 = 9");
  r.box = {0.03, 0.03, 0.039, 0.07}; // 9: enough
  EXPECT_NO_THROW(make_model(delta, m, r));

  r.box = {0.07, 0.03, 0.03, 0.07}; // x_min > x_max
  expect_invalid([&] { make_model(delta, m, r); }, "PD box", "");
}

// Crack polylines: every vertex inside the body, at least two vertices.
TEST(BadInput, CrackVerticesAndLength)
{
  Region r = good_region();
  r.cracks = {{{0.03, 0.05}, {0.15, 0.05}}};
  expect_invalid([&] { make_model(delta, m, r); }, "Crack vertex", "inside the body");
  r.cracks = {{{0.03, 0.05}, {0.05, 0.05}}, {{-0.01, 0.05}, {0.04, 0.05}}}; // second one bad
  expect_invalid([&] { make_model(delta, m, r); }, "Crack vertex", "inside the body");

  for (std::size_t n : {1u, 0u})
    {
      r.cracks = {geometry::Polyline(n, geometry::Point{0.04, 0.05})};
      expect_invalid([&] { make_model(delta, m, r); }, "Crack", "at least 2 vertices");
    }
  r.cracks = {{{0.03, 0.05}, {0.05, 0.05}}};
  EXPECT_NO_THROW(make_model(delta, m, r));
}

// Array targets must have one value per layer node.
TEST(BadInput, BoundaryLayerTargetSizes)
{
  const PdModel model = make_model(delta, m);
  BoundaryLayer layer(model);
  const std::size_t n = layer.size();
  ASSERT_GT(n, 0u);
  const std::string allowed = "one value per layer node (" + std::to_string(n) + ")";
  expect_invalid([&] { layer.set_target(std::vector<double>(n - 1), std::vector<double>(n)); },
                 "Boundary-layer displacement", allowed);
  expect_invalid([&] { layer.set_target(std::vector<double>(n), std::vector<double>(n + 1)); },
                 "Boundary-layer displacement", allowed);
  expect_invalid([&] { layer.set_target(std::vector<double>{}, std::vector<double>{}); },
                 "Boundary-layer displacement", allowed);
  EXPECT_NO_THROW(layer.set_target(std::vector<double>(n), std::vector<double>(n)));
}

TEST(BadInput, RelaxationTolerance)
{
  const PdModel model = make_model(delta, m);
  expect_invalid([&] { DynamicRelaxation(model, 0., 100); }, "Relaxation tolerance", "must be in");
  expect_invalid([&] { DynamicRelaxation(model, -1e-6, 100); }, "Relaxation tolerance", "must be in");
  expect_invalid([&] { DynamicRelaxation(model, 1e-8, 0); }, "Relaxation iterations", ">= 1");
  EXPECT_NO_THROW(DynamicRelaxation(model, 1e-8, 100));
}

TEST(BadInput, InfluenceName)
{
  expect_invalid([] { influence_from_string("cubic"); }, "Influence function", "constant|linear");
  EXPECT_EQ(influence_from_string("constant"), Influence::constant);
  EXPECT_EQ(influence_from_string("linear"), Influence::linear);
}

// ExplicitRun::keep_every = 0 must be refused, not divide by zero (run_explicit takes n % 0).
// Run in a child process so that a crash fails this test only.
TEST(BadInput, ExplicitRunKeepEveryZero)
{
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
    {
      const PdModel        model = make_model(delta, m);
      const BoundaryLayer  layer(model);
      const VelocityVerlet verlet(model, 0.9 * model.stable_time_step());
      State                s = model.initial_state();
      verlet.initialise(s);
      ExplicitRun run;
      run.steps      = 10;
      run.keep_every = 0;
      try
        {
          run_explicit(verlet, s, layer, run);
        }
      catch (const InvalidParameter &e)
        {
          std::cerr << e.what() << std::endl;
          std::exit(0);
        }
      std::cerr << "keep_every = 0 accepted" << std::endl;
      std::exit(1);
    },
    ::testing::ExitedWithCode(0), "");
}
