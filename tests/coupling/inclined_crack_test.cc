// Inclined centre crack in a plate under tension (prm/inclined-crack.prm, meshes/inclined-crack.geo):
// a crack of length 2a = 20 mm at 45 degrees through the centre of a plate pulled by clamped grips.
// The scene is symmetric under a half turn about the centre, so the two tips see the same K_I, K_II
// and must grow as images of each other: a path point p of one tip's branch has its image -p on
// the other's.
//
// Checked, for LEFM growth (three increments) and the global-local cycle (a PD box per tip, m = 4,
// three exchanges):
//  - both tips grow at every step or exchange;
//  - asymmetry: the Hausdorff distance between one tip's branch (from the centre) and the half-turn
//    of the other's, within 0.5 % of the growth increment for LEFM (gmsh's mesh is not exactly
//    symmetric: K differs between the tips by about 1e-4) and one PD spacing for global-local
//    (cracks.inclined.asymmetry_over_h);
//  - tips closer than half a box side share one box (a shorter crack);
//  - the first kink: the angle of the first segment of each tip's first accepted increment from
//    the tip's direction, against the maximum hoop stress angle theta_c of the computed K_I, K_II
//    (cracks.inclined.kink_err_deg, the larger of the two tips). LEFM's first kink is theta_c by
//    construction. PD's kink is a property of the nonlocal model: it approaches theta_c as the
//    horizon shrinks against the crack (the studies below print it for delta = 4, 2, 1 mm and for
//    crack half-lengths of 10 to 30 horizons); at this test's delta = 4 mm, m = 4 it is checked
//    within 15 degrees and to turn the same way.
//    A bond fails on its stretch, so the study also prints the kink against the maximum hoop
//    strain criterion (Chang 1981, plane strain: the largest (1 - nu) sigma_tt - nu sigma_rr),
//    and a second study turns the scene against the PD lattice (the kink's lattice dependence).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <vector>

#include "global_local.h"
#include "lefm_growth.h"
#include "metric.h"
#include "path_metrics.h"
#include "program.h"
#include "scene_file.h"

using namespace pumpd;
using geometry::Point;

namespace
{
  const double degree = std::acos(-1.) / 180.;

  /// The branch grown from each end of the crack, each starting at the crack's centre (the
  /// midpoint of the initial crack), the first from the first vertex's end.
  std::array<geometry::Polyline, 2> branches(const geometry::Polyline &path, const geometry::Polyline &initial)
  {
    const Point centre = 0.5 * (initial.front() + initial.back());
    std::size_t first = 0, last = 0;
    for (std::size_t k = 0; k < path.size(); ++k)
      {
        if (geometry::norm(path[k] - initial.front()) < 1e-9)
          first = k;
        if (geometry::norm(path[k] - initial.back()) < 1e-9)
          last = k;
      }
    std::array<geometry::Polyline, 2> b{{geometry::Polyline{centre}, geometry::Polyline{centre}}};
    for (std::size_t k = first + 1; k-- > 0;)
      b[0].push_back(path[k]);
    for (std::size_t k = last; k < path.size(); ++k)
      b[1].push_back(path[k]);
    return b;
  }

  /// Hausdorff distance between one branch and the half-turn of the other about the centre [m].
  double asymmetry(const geometry::Polyline &path, const geometry::Polyline &initial)
  {
    const auto  b      = branches(path, initial);
    const Point centre = b[0].front();
    geometry::Polyline turned;
    for (const auto &p : b[0])
      turned.push_back(2. * centre - p);
    return std::max(coupling::directed_max_distance(turned, b[1]), coupling::directed_max_distance(b[1], turned));
  }

  /// The angle theta in (-pi, pi) of the largest (1 - nu) sigma_tt - nu sigma_rr around the tip
  /// (plane strain hoop strain up to a factor) of the near-tip field K_I, K_II (Williams), by
  /// golden-section search between the kink's side and the crack line [rad].
  double max_hoop_strain_angle(double k1, double k2, double nu)
  {
    const auto strain = [&](double t) {
      const double c = std::cos(0.5 * t), c3 = std::cos(1.5 * t), s = std::sin(0.5 * t), s3 = std::sin(1.5 * t);
      const double tt = 0.25 * k1 * (3. * c + c3) - 0.75 * k2 * (s + s3);
      const double rr = 0.25 * k1 * (5. * c - c3) + 0.25 * k2 * (-5. * s + 3. * s3);
      return (1. - nu) * tt - nu * rr;
    };
    const double g = 0.5 * (std::sqrt(5.) - 1.);
    double       a = k2 > 0. ? -0.5 * std::acos(-1.) : 0., b = k2 > 0. ? 0. : 0.5 * std::acos(-1.);
    for (int i = 0; i < 100; ++i)
      {
        const double x1 = b - g * (b - a), x2 = a + g * (b - a);
        if (strain(x1) > strain(x2))
          b = x2;
        else
          a = x1;
      }
    return 0.5 * (a + b);
  }

  coupling::Parameters inclined(const std::string &output)
  {
    return test::scene_file("prm/inclined-crack.prm", output);
  }

  /// The first exchange of scene p at horizon delta (m = 8; the advances and the box margin
  /// scale with delta), a record per tip.
  std::vector<coupling::ExchangeRecord> first_exchange(coupling::Parameters p, double delta)
  {
    p.pd.horizon                 = delta;
    p.cycle.max_exchanges        = 1;
    p.cycle.exchange.min_advance = delta;
    p.cycle.exchange.max_advance = 2. * delta;
    p.cycle.box.margin           = 2. * delta;
    const auto         scene     = coupling::build_scene(p.scene);
    std::ostringstream log;
    return coupling::run_global_local(scene, p.global_local_settings(), log).exchanges;
  }

  /// The least advance an exchange accepts in a box of the record's horizon (global_local.cc): the
  /// section's minimum advance (scaled with a coarser box), at most half the advance a finer box
  /// allows.
  double least_advance(const coupling::Parameters &p, const coupling::ExchangeRecord &e)
  {
    const double scale = e.horizon / p.pd.horizon;
    return std::min(std::max(scale, 1.) * p.cycle.exchange.min_advance, 0.5 * scale * p.cycle.exchange.max_advance);
  }
} // namespace

TEST(InclinedCrack, LefmGrowthGrowsBothTipsSymmetrically)
{
  auto p           = inclined("inclined_lefm");
  p.lefm.max_steps = 3;
  const auto         scene = coupling::build_scene(p.scene);
  std::ostringstream log;
  const auto         r = coupling::run_lefm_growth(scene, p.lefm_growth_settings(), log);
  std::cout << log.str();
  EXPECT_EQ(r.increments, 3u);
  std::size_t grown[2] = {0, 0};
  for (const auto &s : r.steps)
    if (s.increment > 0.)
      ++grown[s.tip];
  EXPECT_EQ(grown[0], 3u);
  EXPECT_EQ(grown[1], 3u);
  const double a = asymmetry(r.path, scene.crack());
  EXPECT_LT(a, 0.005 * p.lefm.growth_increment);
  test::metric("cracks.inclined.lefm_asymmetry_mm", 1e3 * a);
}

TEST(InclinedCrack, GlobalLocalGrowsBothTipsSymmetricallyWithTheHoopStressKink)
{
  auto p                    = inclined("inclined_global_local");
  p.pd.horizon_over_spacing = 4;
  p.cycle.max_exchanges     = 3;
  const auto         scene  = coupling::build_scene(p.scene);
  std::ostringstream log;
  const auto         r = coupling::run_global_local(scene, p.global_local_settings(), log);
  std::cout << log.str();
  ASSERT_EQ(r.exchanges.size(), 6u); // a record per tip and exchange
  double kink_error = 0.;
  for (const auto &e : r.exchanges)
    {
      EXPECT_EQ(e.decision, "accept") << "exchange " << e.exchange << ", tip end " << e.tip_end;
      EXPECT_GE(e.advance, least_advance(p, e) - 1e-9);
      if (e.exchange == 0)
        {
          // a = 10 mm, theta_c = -53 degrees: the first box's horizon is at most 3 degrees x a /
          // |theta_c| = 0.57 mm (resolution.h), 4 mm / 2^3.
          EXPECT_EQ(e.horizon, p.pd.horizon / 8.);
          EXPECT_LT(e.predicted_kink, -45. * degree); // K_II ~ K_I: theta_c ~ -53 degrees
          EXPECT_LT(e.kink, -30. * degree);
          kink_error = std::max(kink_error, std::abs(e.kink - e.predicted_kink) / degree);
        }
    }
  const double a = asymmetry(r.path, scene.crack()) / p.pd.spacing();
  EXPECT_LT(a, 1.);
  EXPECT_LT(kink_error, 5.); // issue 41: the first kink at the default within 5 degrees of theta_c
  test::metric("cracks.inclined.asymmetry_over_h", a);
  test::metric("cracks.inclined.kink_err_deg", kink_error);
}

// A shorter crack (2a = 10 mm): its tips lie within half a box side of each other, so they share
// one PD box, grow in the same PD states at one load, and stay images of each other.
TEST(InclinedCrack, CloseTipsShareOneBox)
{
  auto p                    = inclined("inclined_shared_box");
  p.pd.horizon_over_spacing = 4;
  p.cycle.max_exchanges     = 1;
  p.scene.initial_cracks    = "-0.0035355,-0.0035355; 0.0035355,0.0035355";
  p.cycle.resolution.kink_tolerance = 0.; // boxes of the scene's horizon, half a side (16 mm) wider than the crack
  const auto         scene  = coupling::build_scene(p.scene);
  std::ostringstream log;
  const auto         r = coupling::run_global_local(scene, p.global_local_settings(), log);
  std::cout << log.str();
  ASSERT_EQ(r.exchanges.size(), 2u);
  const auto &first = r.exchanges[0], &second = r.exchanges[1];
  EXPECT_EQ(first.box.x_min, second.box.x_min);
  EXPECT_EQ(first.box.y_max, second.box.y_max);
  EXPECT_TRUE(first.box.contains(first.tip) && first.box.contains(second.tip));
  EXPECT_EQ(r.boxes.size(), 1u);
  EXPECT_EQ(first.lambda, second.lambda);
  EXPECT_GE(std::min(first.advance, second.advance), p.cycle.exchange.min_advance - 1e-9);
  const double a = asymmetry(r.path, scene.crack()) / p.pd.spacing();
  EXPECT_LT(a, 1.);
  test::metric("cracks.inclined.shared_box_asymmetry_over_h", a);
}

// Study (ctest -L study): the first PD kink against theta_c as the horizon shrinks (m = 8; the
// box, advance and margin scale with it): cracks.inclined.kink_err_deg_delta<delta in um>, and
// against the maximum hoop strain angle: cracks.inclined.kink_err_vs_hoop_strain_deg_delta<...>.
TEST(InclinedCrack, MaximumHoopStrainAngle)
{
  // Pure mode I: straight ahead. K_II = K_I, nu = 1/4: -49.67 degrees (a direct scan of
  // (1 - nu) sigma_tt - nu sigma_rr), against -53.13 for the hoop stress.
  EXPECT_NEAR(max_hoop_strain_angle(1., 0., 0.25), 0., 1e-6);
  EXPECT_NEAR(max_hoop_strain_angle(1., 1., 0.25) / degree, -49.67, 0.01);
  EXPECT_NEAR(max_hoop_strain_angle(1., -1., 0.25) / degree, 49.67, 0.01);
}

TEST(InclinedCrackStudy, DISABLED_KinkAgainstHorizon)
{
  for (const double delta : {0.004, 0.002, 0.001, 0.0005})
    {
      const auto p         = inclined("");
      const auto exchanges = first_exchange(p, delta);
      double     error = 0., strain_error = 0.;
      for (const auto &e : exchanges)
        {
          const double strain_kink = max_hoop_strain_angle(e.k1, e.k2, p.scene.material.poisson_ratio);
          error        = std::max(error, std::abs(e.kink - e.predicted_kink) / degree);
          strain_error = std::max(strain_error, std::abs(e.kink - strain_kink) / degree);
        }
      const auto &first = exchanges.front();
      std::cout << "delta " << delta << " m: first kink " << first.kink / degree << " deg, theta_c (hoop stress) "
                << first.predicted_kink / degree << " deg, hoop strain "
                << max_hoop_strain_angle(first.k1, first.k2, p.scene.material.poisson_ratio) / degree << " deg\n";
      const std::string um = std::to_string(int(std::round(delta * 1e6))) + "um";
      test::metric("cracks.inclined.kink_err_deg_delta" + um, error);
      test::metric("cracks.inclined.kink_err_vs_hoop_strain_deg_delta" + um, strain_error);
    }
}

// Study (ctest -L study): the first PD kink against theta_c as the crack grows against the horizon,
// delta = 1 mm, m = 4 (the box, advance and margin scale with delta as above), crack half-lengths
// a = 10 to 30 mm (a / delta = 10 to 30): cracks.inclined.kink_err_deg_a<a in mm> (the larger of
// the two tips that grew; not printed if neither grew), and over a / delta >= 16 the mean of the
// signed errors kink - theta_c of every tip that grew, cracks.inclined.kink_mean_signed_err_deg_long,
// and the largest error, cracks.inclined.kink_max_err_deg_long: the mean tells whether the kinks
// lean to one side of theta_c (the scene is symmetric under a half turn, so its two tips mirror
// each other and each scene counts twice), the largest how far one scene's kink may lie from it.
TEST(InclinedCrackStudy, DISABLED_KinkAgainstCrackLength)
{
  double      sum = 0., largest = 0.;
  std::size_t n = 0;
  for (const double a : {0.010, 0.016, 0.018, 0.020, 0.022, 0.025, 0.030})
    {
      auto         p = inclined("");
      const double c = a / std::sqrt(2.);
      std::ostringstream crack;
      crack << std::setprecision(17) << -c << "," << -c << "; " << c << "," << c;
      p.scene.initial_cracks    = crack.str();
      p.pd.horizon_over_spacing = 4;
      const double delta        = 0.001;
      double       error        = 0.;
      std::size_t  accepted     = 0;
      for (const auto &e : first_exchange(p, delta))
        {
          std::cout << "a " << 1e3 * a << " mm, tip end " << e.tip_end << ": " << e.decision << ", first kink "
                    << e.kink / degree << " deg, theta_c " << e.predicted_kink / degree << " deg\n";
          if (e.decision != "accept")
            continue;
          const double signed_error = (e.kink - e.predicted_kink) / degree;
          error                     = std::max(error, std::abs(signed_error));
          ++accepted;
          if (a >= 16. * delta - 1e-12)
            {
              sum += signed_error;
              largest = std::max(largest, std::abs(signed_error));
              ++n;
            }
        }
      if (accepted > 0)
        test::metric("cracks.inclined.kink_err_deg_a" + std::to_string(int(std::round(a * 1e3))), error);
    }
  ASSERT_GT(n, 0u);
  test::metric("cracks.inclined.kink_mean_signed_err_deg_long", sum / double(n));
  test::metric("cracks.inclined.kink_max_err_deg_long", largest);
}

// Study (ctest -L study): the same first kink with the scene turned against the PD lattice (the
// global mesh, the crack and the grips turned by phi = 0, 20 and -25 degrees about the centre:
// one gmsh mesh, its nodes turned, so the global solution turns with them; the lattice stays
// axis-parallel), for delta = 4, 2, 1 mm as above: the spread of the kink over the turns and the
// tips that grew, cracks.inclined.kink_lattice_spread_deg_delta<delta in um>, its mean,
// cracks.inclined.kink_mean_deg_delta<...>, and the tips that grew,
// cracks.inclined.kink_lattice_grown_tips_delta<...> (of six).
TEST(InclinedCrackStudy, DISABLED_KinkAgainstLatticeOrientation)
{
  const auto directory = std::filesystem::temp_directory_path() / "pumpd_inclined_turned";
  std::filesystem::create_directories(directory);
  const auto        unturned = inclined("");
  const std::string msh      = (directory / "plate.msh").string();
  std::ostringstream h;
  h << std::setprecision(17) << unturned.scene.mesh_size;
  ASSERT_EQ(pumpd::run_program({"gmsh", "-2", "-format", "msh2", "-setnumber", "h", h.str(), "-o", msh,
                                unturned.scene.mesh_file},
                               (directory / "gmsh.log").string())
              .exit_code,
            0);
  std::vector<std::string> lines;
  {
    std::ifstream in(msh);
    for (std::string line; std::getline(in, line);)
      lines.push_back(line);
  }

  for (const double delta : {0.004, 0.002, 0.001})
    {
      double lowest = 180., highest = -180., sum = 0.;
      int    n = 0;
      for (const double phi : {0., 20., -25.})
        {
          const double      c = std::cos(phi * degree), s = std::sin(phi * degree);
          const std::string name = (directory / ("plate_" + std::to_string(int(phi)) + ".msh")).string();
          {
            // msh2: "$Nodes", the count, then "id x y z" per node.
            std::ofstream out(name);
            out << std::setprecision(17);
            bool in_nodes = false;
            for (std::size_t k = 0; k < lines.size(); ++k)
              {
                std::istringstream node(lines[k]);
                std::size_t        id;
                double             x, y, z;
                if (lines[k] == "$Nodes" || lines[k] == "$EndNodes")
                  in_nodes = lines[k] == "$Nodes";
                else if (in_nodes && (node >> id >> x >> y >> z))
                  {
                    out << id << " " << c * x - s * y << " " << s * x + c * y << " " << z << "\n";
                    continue;
                  }
                out << lines[k] << "\n";
              }
          }
          auto p                       = inclined("");
          p.scene.mesh_file            = name;
          const double a               = 0.00707107;
          const Point  tip             = {a * c - a * s, a * s + a * c};
          std::ostringstream crack, grips;
          crack << std::setprecision(17) << -tip.x << "," << -tip.y << "; " << tip.x << "," << tip.y;
          grips << std::setprecision(17) << "top grip: ux = " << -1e-3 * s << " * lambda, uy = " << 1e-3 * c
                << " * lambda; bottom grip: ux = " << 1e-3 * s << " * lambda, uy = " << -1e-3 * c << " * lambda";
          p.scene.initial_cracks = crack.str();
          p.scene.displacement   = grips.str();
          for (const auto &e : first_exchange(p, delta))
            {
              const double kink = e.kink / degree;
              std::cout << "delta " << delta << " m, turned " << phi << " degrees, tip end " << e.tip_end << ": "
                        << e.decision << ", advance " << e.advance << " m, first kink " << kink << " degrees (theta_c "
                        << e.predicted_kink / degree << ")\n";
              if (e.decision != "accept")
                continue;
              lowest  = std::min(lowest, kink);
              highest = std::max(highest, kink);
              sum += kink;
              ++n;
            }
        }
      ASSERT_GT(n, 0) << "no tip grew at delta " << delta;
      const std::string um = std::to_string(int(std::round(delta * 1e6))) + "um";
      test::metric("cracks.inclined.kink_lattice_grown_tips_delta" + um, n);
      test::metric("cracks.inclined.kink_lattice_spread_deg_delta" + um, highest - lowest);
      test::metric("cracks.inclined.kink_mean_deg_delta" + um, sum / n);
    }
}
