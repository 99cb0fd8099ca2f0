// Validation 3: energy balance of a dynamic run with growing damage. A notched strip is pulled
// apart by its boundary layers with velocity Verlet until the crack runs through most of it;
// the work of the layers must equal elastic + kinetic + dissipated energy within 2 % at every
// sampled time once the work is appreciable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "boundary_layer.h"
#include "explicit_run.h"
#include "integrators.h"
#include "metric.h"
#include "model.h"

using namespace pumpd;
using namespace pumpd::local;

TEST(EnergyBalance, WorkEqualsStoredKineticAndDissipated)
{
  MaterialParameters p;
  const int    m = 4;
  const double delta = 0.004, h = delta / m;
  const double width = 12. * delta, height = 8. * delta, notch = 3. * delta;
  Region       region;
  region.body = geometry::Body(geometry::Box{-h, -1., width, 1.});
  region.box          = {0., -0.5 * height, width, 0.5 * height};
  region.cracks       = {{{-h, 0.}, {notch, 0.}}};
  PdModel model(p, delta, m, region);

  BoundaryLayer layer(model);
  const double  opening = 2.5e-4; // about five times the opening at which the crack starts
  layer.set_target([&](geometry::Point x) { return geometry::Point{0., x.y > 0 ? opening / 2 : -opening / 2}; });
  State s = model.initial_state();

  const VelocityVerlet verlet(model, 0.5 * model.stable_time_step());
  verlet.initialise(s);
  const std::size_t intact = model.intact_bonds(s);

  ExplicitRun run;
  run.steps = 6000;
  // Smooth start and end of the pull (no velocity jump of the layer).
  run.ramp = [&](std::size_t n) {
    const double t = double(n) / run.steps;
    return t * t * (3. - 2. * t);
  };
  double worst = 0.;
  run.observer = [&](const State &st, std::size_t n) {
    if (n % 200 != 0)
      return;
    const double stored  = model.elastic_energy(st) + model.kinetic_energy(st) + st.dissipated;
    const double balance = std::abs(st.external_work - stored) / st.external_work;
    if (n > run.steps / 10)
      worst = std::max(worst, balance);
  };
  run_explicit(verlet, s, layer, run);

  const double failed_fraction = 1. - double(model.intact_bonds(s)) / intact;
  std::cout << "work " << s.external_work << " J/m, elastic " << model.elastic_energy(s)
            << ", kinetic " << model.kinetic_energy(s) << ", dissipated " << s.dissipated
            << "; failed bonds " << 100. * failed_fraction << " %\n";
  EXPECT_GT(s.dissipated, 0.5 * p.fracture_energy * (width - notch)) << "the crack did not grow";
  EXPECT_LT(worst, 0.02);
  test::metric("pd.energy_balance_rel_err", worst);
}
