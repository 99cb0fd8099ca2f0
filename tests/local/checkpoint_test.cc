// Checkpoints: a restart continues a run with failing bonds bit for bit, driver attributes
// round-trip, a checkpoint of another lattice or a missing file is refused, and a NaN stops the
// run with the last good state saved.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>

#include <unistd.h>

#include "boundary_layer.h"
#include "checkpoint.h"
#include "error.h"
#include "explicit_run.h"
#include "integrators.h"
#include "model.h"

using namespace pumpd;
using namespace pumpd::local;

namespace
{
  constexpr double delta = 0.004; // m = 4, h = 1 mm
  constexpr int    m     = 4;
  constexpr double yc = 0.05, tip_x = 0.0502; // edge crack from the box's left edge to its middle

  std::string temp_path(const std::string &name)
  {
    return (std::filesystem::temp_directory_path() /
            ("pumpd_checkpoint_test_" + std::to_string(::getpid()) + "_" + name))
      .string();
  }

  MaterialParameters material()
  {
    MaterialParameters p;
    p.break_factor = 3.; // bonds fail at 3 S_c: a short run grows the crack
    return p;
  }

  /// A 40 x 40 node box inside a 0.1 m body with an edge crack to its middle.
  Region cracked_region(double box_size = 0.04)
  {
    Region r;
    r.body = geometry::Body(geometry::Box{0., 0., 0.1, 0.1});
    r.box          = {0.03, 0.03, 0.03 + box_size, 0.03 + box_size};
    r.cracks       = {{{0.03, yc}, {tip_x, yc}}};
    return r;
  }

  /// Plane-strain Mode-I crack-tip displacement (Williams), K = factor K_Ic, tip at (tip_x, yc).
  geometry::Point mode_one(const PdModel &model, double factor, geometry::Point x)
  {
    const auto  &mat   = model.material();
    const double mu    = mat.shear_modulus();
    const double kappa = 3. - 4. * mat.poisson_ratio();
    const double K     = factor * mat.critical_sif();
    const double dx = x.x - tip_x, dy = x.y - yc;
    const double r = std::hypot(dx, dy), t = std::atan2(dy, dx);
    const double a = K / (2. * mu) * std::sqrt(r / (2. * M_PI));
    return {a * std::cos(t / 2) * (kappa - 1. + 2. * std::sin(t / 2) * std::sin(t / 2)),
            a * std::sin(t / 2) * (kappa + 1. - 2. * std::cos(t / 2) * std::cos(t / 2))};
  }

  /// The model, its layer ramped from rest to a Mode-I field of 3 K_Ic, and the integrator at
  /// 0.9 of the stable step. Built from scratch each time, as a restarted process would.
  struct ModeOneRun
  {
    PdModel        model{material(), delta, m, cracked_region()};
    BoundaryLayer  layer{model};
    VelocityVerlet verlet{model, 0.9 * model.stable_time_step()};

    ModeOneRun()
    {
      layer.set_target([&](geometry::Point x) { return mode_one(model, 3., x); });
      layer.start_from(model.initial_state());
    }
  };

  void advance(const ModeOneRun &setup, State &s, std::size_t from, std::size_t to, std::size_t total)
  {
    for (std::size_t n = from + 1; n <= to; ++n)
      setup.verlet.step(s, setup.layer, double(n) / double(total));
  }

  bool all_finite(const std::vector<double> &v)
  {
    for (double x : v)
      if (!std::isfinite(x))
        return false;
    return true;
  }

  /// A free node in the middle of the box.
  std::size_t free_node(const PdModel &model)
  {
    const std::size_t i = model.lattice().index(30, 10);
    EXPECT_EQ(model.free_mask()[i], 1.);
    return i;
  }
} // namespace

// Run A: 2N steps straight. Run B: N steps, checkpoint, restore into a freshly built model, N more.
// Every array and scalar of the state must agree bit for bit; bonds must fail in both halves so
// that the restored bond bits matter.
TEST(Checkpoint, RestartReproducesUninterruptedRun)
{
  constexpr std::size_t N = 150;
  const std::string     path = temp_path("restart.h5");

  ModeOneRun       a;
  State       sa = a.model.initial_state();
  std::size_t intact0 = a.model.intact_bonds(sa);
  a.verlet.initialise(sa);
  advance(a, sa, 0, N, 2 * N);
  const std::size_t intact_half = a.model.intact_bonds(sa);
  advance(a, sa, N, 2 * N, 2 * N);
  const std::size_t intact_end = a.model.intact_bonds(sa);
  std::cout << "intact bonds: " << intact0 << " -> " << intact_half << " -> " << intact_end << "\n";
  EXPECT_LT(intact_half, intact0) << "no bond failed in the first half";
  EXPECT_LT(intact_end, intact_half) << "no bond failed in the second half";
  EXPECT_GT(sa.dissipated, 0.);

  const Attributes written{{"load_step", 7.}, {"ramp", 0.5}, {"crack_length", 0.0202}};
  {
    ModeOneRun b;
    State sb = b.model.initial_state();
    b.verlet.initialise(sb);
    advance(b, sb, 0, N, 2 * N);
    write_checkpoint(path, b.model, sb, written);
  }

  ModeOneRun      c; // a fresh model, as after a restart
  Attributes read;
  State      sc = read_checkpoint(path, c.model, &read);
  EXPECT_EQ(read, written);
  EXPECT_EQ(sc.step, N);
  advance(c, sc, N, 2 * N, 2 * N);

  EXPECT_EQ(sc.ux, sa.ux);
  EXPECT_EQ(sc.uy, sa.uy);
  EXPECT_EQ(sc.vx, sa.vx);
  EXPECT_EQ(sc.vy, sa.vy);
  EXPECT_EQ(sc.fx, sa.fx);
  EXPECT_EQ(sc.fy, sa.fy);
  EXPECT_EQ(sc.broken, sa.broken);
  EXPECT_EQ(sc.time, sa.time);
  EXPECT_EQ(sc.step, sa.step);
  EXPECT_EQ(sc.dissipated, sa.dissipated);
  EXPECT_EQ(sc.external_work, sa.external_work);
  std::filesystem::remove(path);
}

// A checkpoint restored into a model of another lattice (size or spacing) is refused with a
// message that says so; a missing file is refused too.
TEST(Checkpoint, RefusesOtherLatticeAndMissingFile)
{
  const std::string path = temp_path("lattice.h5");
  const PdModel     model(material(), delta, m, cracked_region());
  write_checkpoint(path, model, model.initial_state());

  const PdModel wider(material(), delta, m, cracked_region(0.05)); // 50 x 50 nodes
  try
    {
      read_checkpoint(path, wider);
      ADD_FAILURE() << "checkpoint of a 40 x 40 lattice accepted by a 50 x 50 model";
    }
  catch (const std::runtime_error &e)
    {
      EXPECT_NE(std::string(e.what()).find("another lattice"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("lattice_nx"), std::string::npos) << e.what();
    }

  // Same node count, other spacing: h = 1.5 mm over a 60 mm box.
  Region coarse_region = cracked_region(0.06);
  const PdModel coarse(material(), 1.5 * delta, m, coarse_region);
  ASSERT_EQ(coarse.lattice().nx(), model.lattice().nx());
  try
    {
      read_checkpoint(path, coarse);
      ADD_FAILURE() << "checkpoint accepted by a model of another spacing";
    }
  catch (const std::runtime_error &e)
    {
      EXPECT_NE(std::string(e.what()).find("another lattice"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("lattice_spacing"), std::string::npos) << e.what();
    }

  EXPECT_NO_THROW(read_checkpoint(path, model));
  std::filesystem::remove(path);
  EXPECT_THROW(read_checkpoint(path, model), std::runtime_error);
  EXPECT_THROW(read_checkpoint(temp_path("does_not_exist.h5"), model), std::runtime_error);
}

// A NaN in a free node's displacement is caught after the next force evaluation, and the error
// names the step.
TEST(Checkpoint, NonFiniteStateNamesTheStep)
{
  ModeOneRun setup;
  State s = setup.model.initial_state();
  setup.verlet.initialise(s);
  advance(setup, s, 0, 5, 100);
  EXPECT_NO_THROW(check_finite(setup.model, s));

  const std::size_t i = free_node(setup.model);
  s.ux[i]             = std::numeric_limits<double>::quiet_NaN();
  try
    {
      check_finite(setup.model, s);
      ADD_FAILURE() << "check_finite missed a NaN";
    }
  catch (const NonFiniteState &e)
    {
      EXPECT_NE(std::string(e.what()).find("step 5 ("), std::string::npos) << e.what();
    }
  try
    {
      setup.verlet.step(s, setup.layer, 0.06);
      ADD_FAILURE() << "step went on with a NaN";
    }
  catch (const NonFiniteState &e)
    {
      EXPECT_NE(std::string(e.what()).find("step 6 ("), std::string::npos) << e.what();
    }

  // An infinite displacement fails the (infinitely stretched) bonds, so the forces stay finite;
  // the displacement itself must still be caught.
  State t = setup.model.initial_state();
  setup.verlet.initialise(t);
  t.uy[i] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(setup.verlet.step(t, setup.layer, 0.01), NonFiniteState);

  // Non-finite layer targets are refused before they get into the state.
  BoundaryLayer layer(setup.model);
  std::vector<double> ux(layer.size(), 0.), uy(layer.size(), 0.);
  uy[layer.size() / 2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(layer.set_target(ux, uy), InvalidParameter);
  EXPECT_THROW(layer.set_target([](geometry::Point x) {
                 return geometry::Point{x.x > 0.05 ? std::numeric_limits<double>::infinity() : 0., 0.};
               }),
               InvalidParameter);
}

// run_explicit: a NaN injected by the observer after step 150 stops the run at step 151; the
// error names the step and the checkpoint path, and the checkpoint holds the last good state
// (step 100 with keep_every = 100): finite and equal to the state the observer saw at step 100.
TEST(Checkpoint, FailedRunSavesLastGoodState)
{
  const std::string path = temp_path("failure.h5");
  std::filesystem::remove(path);
  ModeOneRun setup;
  State s = setup.model.initial_state();
  setup.verlet.initialise(s);

  const std::size_t i = free_node(setup.model);
  State             at_100;
  ExplicitRun       run;
  run.steps              = 300;
  run.keep_every         = 100;
  run.failure_checkpoint = path;
  run.observer           = [&](const State &state, std::size_t n) {
    if (n == 100)
      at_100 = state;
    if (n == 150)
      s.ux[i] = std::numeric_limits<double>::quiet_NaN(); // state is s
  };
  std::string message;
  try
    {
      run_explicit(setup.verlet, s, setup.layer, run);
      ADD_FAILURE() << "run_explicit finished with a NaN in the state";
    }
  catch (const NonFiniteState &e)
    {
      message = e.what();
    }
  std::cout << message << "\n";
  EXPECT_NE(message.find("step 151 ("), std::string::npos) << message;
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("(step 100)"), std::string::npos) << message;

  ASSERT_TRUE(std::filesystem::exists(path));
  const State saved = read_checkpoint(path, setup.model);
  EXPECT_LE(saved.step, 151u);
  EXPECT_EQ(saved.step, 100u);
  for (const auto *v : {&saved.ux, &saved.uy, &saved.vx, &saved.vy, &saved.fx, &saved.fy})
    EXPECT_TRUE(all_finite(*v));
  EXPECT_TRUE(std::isfinite(saved.time));
  EXPECT_TRUE(std::isfinite(saved.dissipated));
  EXPECT_TRUE(std::isfinite(saved.external_work));
  EXPECT_EQ(saved.ux, at_100.ux);
  EXPECT_EQ(saved.broken, at_100.broken);
  EXPECT_EQ(saved.time, at_100.time);
  std::filesystem::remove(path);
}
