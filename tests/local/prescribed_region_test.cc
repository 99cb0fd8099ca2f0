// Prescribed regions besides the boundary layer (PrescribedRegion, RegionDisplacement): per-
// component masks, a bar pulled through two end pads whose uy is free (rollers), relaxed by dynamic
// relaxation against the analytic uniaxial-stress field (the calibration tolerance, 2 %), the pads'
// reaction against sigma_xx W, a roller that leaves ux free, Verlet's work through moving regions,
// a servo inside the relaxation that holds a gauge at its target, and the refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "boundary_layer.h"
#include "error.h"
#include "expect_invalid.h"
#include "integrators.h"
#include "metric.h"
#include "model.h"

using namespace pumpd;
using pumpd::test::expect_invalid;
using namespace pumpd::local;

namespace
{
  constexpr double delta = 0.004; // m = 4, h = 1 mm
  constexpr int    m     = 4;
  constexpr double length = 0.08, width = 0.02;
  constexpr double strain = 1e-4;

  /// The bar [0, L] x [0, W]: the box is the body, so there is no boundary layer, every edge free.
  Region bar()
  {
    Region r;
    r.body = geometry::Body(geometry::Box{0., 0., length, width});
    r.box          = r.body.bounding_box();
    return r;
  }

  /// End pads one horizon wide with ux prescribed and uy free (rollers), and a pin of uy at the
  /// middle of the left end (removes the rigid translation in y).
  std::vector<PrescribedRegion> pads()
  {
    return {PrescribedRegion::box("Left pad", {0., 0., delta, width}, true, false),
            PrescribedRegion::box("Right pad", {length - delta, 0., length, width}, true, false),
            PrescribedRegion::disk("Centre pin", {0.0005, 0.5 * width}, 0.0011, false, true)};
  }
} // namespace

TEST(PrescribedRegion, MasksPerComponent)
{
  const PdModel model(MaterialParameters{}, delta, m, bar(), pads());
  EXPECT_TRUE(model.boundary_layer().empty());
  ASSERT_EQ(model.prescribed_regions().size(), 3u);
  const auto &fx = model.free_mask_x(), &fy = model.free_mask_y();
  // Pads: 4 columns of 20 nodes; the pin: nodes within 1.1 mm of (0.5, 10) mm, i.e. (0.5, 9.5)
  // and (0.5, 10.5) mm and (1.5, 9.5), (1.5, 10.5) are 1.12 mm away: 2 nodes.
  EXPECT_EQ(model.prescribed_nodes(0).size(), 80u);
  EXPECT_EQ(model.prescribed_nodes(1).size(), 80u);
  EXPECT_EQ(model.prescribed_nodes(2).size(), 2u);
  for (std::size_t i : model.prescribed_nodes(1))
    {
      EXPECT_EQ(fx[i], 0.);
      EXPECT_EQ(fy[i], 1.) << "a roller leaves uy free";
      EXPECT_EQ(model.free_mask()[i], 0.);
    }
  for (std::size_t i : model.prescribed_nodes(2))
    {
      EXPECT_EQ(fx[i], 0.) << "inside the left pad too";
      EXPECT_EQ(fy[i], 0.);
    }
  std::size_t free_nodes = 0;
  for (std::size_t i : model.nodes())
    free_nodes += fx[i] * fy[i] == 1.;
  EXPECT_EQ(free_nodes, model.nodes().size() - 160u);
  EXPECT_EQ(model.constrained_nodes().size(), 160u);
  for (std::size_t i = 0; i < model.lattice().storage_size(); ++i)
    if (!model.lattice().is_real(i))
      {
        EXPECT_EQ(fx[i], 0.);
        EXPECT_EQ(fy[i], 0.);
      }
}

// ux = e x on the pads, uy free: the bar is in uniaxial stress, ux = e x, uy = -nu' e (y - W/2)
// with nu' = lambda / (lambda + 2 mu) = 1/3 (plane strain, lambda = mu), sigma_xx = E' e.
TEST(PrescribedRegion, BarPulledByPadsMatchesUniaxialStress)
{
  const PdModel model(MaterialParameters{}, delta, m, bar(), pads());
  RegionDisplacement left(model, 0), right(model, 1), pin(model, 2);
  const auto         affine = [](geometry::Point x) { return geometry::Point{strain * x.x, 0.}; };
  left.set_target(affine);
  right.set_target(affine);
  pin.set_target(geometry::Point{0., 0.});
  State s = model.initial_state();
  for (const auto *r : {&left, &right, &pin})
    r->apply(s, 1.);
  const auto result = DynamicRelaxation(model, 1e-10, 400000).solve(s);
  EXPECT_TRUE(result.converged) << "residual " << result.residual << " after " << result.iterations;

  // Displacement error relative to the largest displacement e L, both components.
  const double nu = 1. / 3.;
  double       worst_x = 0., worst_y = 0.;
  for (std::size_t i : model.nodes())
    {
      const auto x = model.lattice().position(i);
      worst_x      = std::max(worst_x, std::abs(s.ux[i] - strain * x.x));
      worst_y      = std::max(worst_y, std::abs(s.uy[i] + nu * strain * (x.y - 0.5 * width)));
    }
  const double err = std::max(worst_x, worst_y) / (strain * length);
  std::cout << "DR iterations " << result.iterations << "; max |u - u_exact| / (e L) " << err << " (ux "
            << worst_x / (strain * length) << ", uy " << worst_y / (strain * length)
            << "); uy alone against its own scale nu e W / 2: " << worst_y / (nu * strain * 0.5 * width)
            << " (free lateral surfaces: the PD skin is softer)\n";
  EXPECT_LT(err, 0.02);
  EXPECT_LT(worst_y / (nu * strain * 0.5 * width), 0.2);

  // The rollers moved sideways: uy at the right pad's top and bottom follows the contraction.
  double pad_uy = 0.;
  for (std::size_t i : model.prescribed_nodes(1))
    pad_uy = std::max(pad_uy, std::abs(s.uy[i]));
  EXPECT_GT(pad_uy, 0.5 * nu * strain * 0.5 * width) << "a roller leaves the other component free";

  // Reaction of the right pad: sigma_xx W = E' e W; the left pad pulls back equally.
  const double expected = model.material().effective_modulus() * strain * width;
  const auto   r_right = right.reaction(s), r_left = left.reaction(s);
  std::cout << "reaction right " << r_right.x << " N/m, left " << r_left.x << ", E' e W " << expected << "\n";
  EXPECT_NEAR(r_right.x / expected, 1., 0.05);
  EXPECT_NEAR(r_left.x / expected, -1., 0.05);
  test::metric("pd.prescribed_bar_max_rel_err", err);
  test::metric("pd.prescribed_bar_reaction_rel_err", std::abs(r_right.x / expected - 1.));
}

// A roller on the bottom edge (uy = 0 only) of a block stretched upwards by a pad on its top
// (ux = 0, uy = e H): the block contracts sideways, so the roller's nodes slide (ux != 0, towards
// the middle) and keep uy = 0.
TEST(PrescribedRegion, RollerLeavesUxFree)
{
  Region r;
  r.body = geometry::Body(geometry::Box{0., 0., 0.03, 0.02});
  r.box          = r.body.bounding_box();
  const std::vector<PrescribedRegion> regions = {
    PrescribedRegion::box("Roller", {0., 0., 0.03, 0.002}, false, true),
    PrescribedRegion::box("Top pad", {0., 0.018, 0.03, 0.02}, true, true),
  };
  const PdModel      model(MaterialParameters{}, delta, m, r, regions);
  RegionDisplacement top(model, 1);
  top.set_target(geometry::Point{0., strain * 0.02});
  State s = model.initial_state();
  top.apply(s, 1.);
  const auto result = DynamicRelaxation(model, 1e-8, 200000).solve(s);
  EXPECT_TRUE(result.converged) << "residual " << result.residual;
  double left = 0., right = 0., lift = 0.;
  for (std::size_t i : model.prescribed_nodes(0))
    {
      const auto x = model.lattice().position(i);
      if (x.x < 0.002)
        left = std::max(left, s.ux[i]);
      if (x.x > 0.028)
        right = std::min(right, s.ux[i]);
      lift = std::max(lift, std::abs(s.uy[i]));
    }
  std::cout << "roller ends slide by " << left << " and " << right << " m\n";
  EXPECT_GT(left, 0.1 * strain * 0.015) << "the roller slides inwards (contraction)";
  EXPECT_LT(right, -0.1 * strain * 0.015);
  EXPECT_EQ(lift, 0.);
}

// Velocity Verlet: pads moved by a smooth ramp; the work through their reactions equals the
// stored elastic plus kinetic energy (no damage at this strain).
TEST(PrescribedRegion, VerletWorkThroughRegions)
{
  const PdModel model(MaterialParameters{}, delta, m, bar(), pads());
  RegionDisplacement left(model, 0), right(model, 1);
  left.set_target([](geometry::Point x) { return geometry::Point{strain * x.x, 0.}; });
  right.set_target([](geometry::Point x) { return geometry::Point{strain * x.x, 0.}; });
  State s = model.initial_state();
  left.start_from(s);
  right.start_from(s);
  const BoundaryLayer  layer(model); // empty
  const VelocityVerlet verlet(model, 0.5 * model.stable_time_step());
  verlet.initialise(s);
  const std::size_t steps = 3000;
  for (std::size_t n = 1; n <= steps; ++n)
    {
      const double t = double(n) / steps;
      verlet.step(s, layer, t * t * (3. - 2. * t), {&left, &right});
    }
  const double stored = model.elastic_energy(s) + model.kinetic_energy(s);
  std::cout << "work " << s.external_work << " J/m, elastic + kinetic " << stored << "\n";
  EXPECT_GT(s.external_work, 0.);
  EXPECT_NEAR(stored / s.external_work, 1., 0.02);
  // Pads end where they were sent; the rollers' uy moved freely.
  for (std::size_t i : model.prescribed_nodes(1))
    EXPECT_DOUBLE_EQ(s.ux[i], strain * model.lattice().position(i).x);
}

TEST(PrescribedRegion, BadInputIsRefused)
{
  const MaterialParameters p;
  expect_invalid([&] { PdModel(p, delta, m, bar(), {PrescribedRegion::disk("Pin support", {0.2, 0.2}, 0.004, true, true)}); },
                 "Pin support", "holds no PD node");
  expect_invalid([&] { PdModel(p, delta, m, bar(), {PrescribedRegion::disk("Roller", {0.01, 0.}, 0.004, false, false)}); },
                 "Roller", "fixes ux, uy or both");
  expect_invalid([&] { PdModel(p, delta, m, bar(), {PrescribedRegion::disk("Load", {0.01, 0.}, -1., true, true)}); },
                 "Load", "radius >= 0");
  expect_invalid([&] { PdModel(p, delta, m, bar(), {PrescribedRegion::disk("Load", {0.01, 0.}, NAN, true, true)}); },
                 "Load", "must be finite");
  const PdModel model(p, delta, m, bar(), pads());
  expect_invalid([&] { RegionDisplacement(model, 3); }, "Prescribed region index", "number of prescribed regions (3)");
  RegionDisplacement pad(model, 0);
  expect_invalid([&] { pad.set_target(geometry::Point{INFINITY, 0.}); }, "Left pad displacement", "finite");
}

// No-fail zone (elastic_margin): bonds near a region stay linear elastic. With the zone covering
// the whole bar, a pull to 10 times the inflection stretch damages nothing, breaks nothing, and
// the reaction is the small-strain one scaled (linear response).
TEST(PrescribedRegion, NoFailZoneStaysLinear)
{
  auto regions = pads();
  regions[0].elastic_margin = 1.; // the whole bar
  const PdModel model(MaterialParameters{}, delta, m, bar(), regions);
  EXPECT_GT(model.linear_bond_count(), 0u);
  const double       big = 10. * model.material().inflection_stretch(delta);
  const auto         pull = [&](double e) {
    RegionDisplacement left(model, 0), right(model, 1), pin(model, 2);
    left.set_target([e](geometry::Point x) { return geometry::Point{e * x.x, 0.}; });
    right.set_target([e](geometry::Point x) { return geometry::Point{e * x.x, 0.}; });
    pin.set_target(geometry::Point{0., 0.});
    State s = model.initial_state();
    for (const auto *r : {&left, &right, &pin})
      r->apply(s, 1.);
    EXPECT_TRUE(DynamicRelaxation(model, 1e-10, 400000).solve(s).converged);
    return std::make_pair(right.reaction(s).x / e, s);
  };
  const auto [small_k, small_s] = pull(strain);
  const auto [big_k, big_s]     = pull(big);
  EXPECT_NEAR(big_k / small_k, 1., 1e-6);
  const auto damage = model.damage(big_s);
  EXPECT_EQ(*std::max_element(damage.begin(), damage.end()), 0.);
  EXPECT_EQ(model.intact_bonds(big_s), model.intact_bonds(small_s));
  EXPECT_NEAR(big_s.dissipated, 0., 1e-9 * model.elastic_energy(big_s)) << "failures undone";
  // The elastic energy is the linear one: (1/2) k e^2 L scaled with e^2.
  EXPECT_NEAR(model.elastic_energy(big_s) / model.elastic_energy(small_s), (big / strain) * (big / strain), 1e-4 * (big / strain) * (big / strain));
}

// A servo inside dynamic relaxation (local::Servo): the pads prescribe ux = s x with s unknown,
// and the servo moves s (and the body along the mode x) until the node nearest the bar's middle
// has ux = e x_g. The relaxed bar is then in uniaxial stress with s = e (the calibration
// tolerance, 2 %), and the gauge is within the servo's tolerance of its target.
TEST(PrescribedRegion, ServoHoldsAGaugeAtItsTarget)
{
  const PdModel model(MaterialParameters{}, delta, m, bar(), pads());
  RegionDisplacement left(model, 0), right(model, 1), pin(model, 2);
  pin.set_target(geometry::Point{0., 0.});
  std::size_t gauge = model.nodes().front();
  for (std::size_t i : model.nodes())
    if (geometry::norm(model.lattice().position(i) - geometry::Point{0.5 * length, 0.5 * width}) <
        geometry::norm(model.lattice().position(gauge) - geometry::Point{0.5 * length, 0.5 * width}))
      gauge = i;
  const double x_g = model.lattice().position(gauge).x, target = strain * x_g;

  double     s_pads = 0.5 * strain; // the servo's variable, started off by half
  const auto set_pads = [&](State &st) {
    const auto affine = [s_pads](geometry::Point x) { return geometry::Point{s_pads * x.x, 0.}; };
    left.set_target(affine);
    right.set_target(affine);
    left.apply(st, 1.);
    right.apply(st, 1.);
  };
  State s = model.initial_state();
  set_pads(s);
  pin.apply(s, 1.);
  std::size_t corrections = 0;
  Servo       servo;
  servo.tolerance = 1e-4;
  servo.correct   = [&](State &st) {
    const double error = target - st.ux[gauge];
    if (std::abs(error) < servo.tolerance * target)
      return std::abs(error) / target;
    const double ds = error / x_g;
    for (std::size_t i : model.nodes())
      st.ux[i] += ds * model.lattice().position(i).x;
    s_pads += ds;
    set_pads(st);
    ++corrections;
    return std::abs(target - st.ux[gauge]) / target;
  };
  const auto result = DynamicRelaxation(model, 1e-10, 400000).solve(s, servo);
  EXPECT_TRUE(result.converged) << "residual " << result.residual << ", servo error " << result.servo_error;
  std::cout << "servo: " << corrections << " corrections, " << result.iterations << " DR iterations; s / e "
            << s_pads / strain << ", gauge error " << result.servo_error << "\n";
  EXPECT_GE(corrections, 1u);
  EXPECT_LT(result.servo_error, servo.tolerance);
  EXPECT_NEAR(s_pads / strain, 1., 0.02);
  EXPECT_NEAR(s.ux[gauge] / target, 1., 1e-4);
}
