// Where a crack starts with no crack there (coupling/initiation.h): the largest principal stress
// of the uncracked body against the PD strength in uniaxial stress, sigma_s.
//
// - The candidate sites of synthetic fields: two bumps of sigma_yy within the margin are both
//   listed, largest first, with sigma_1 along y; a third outside it is not, nor one in a disk
//   left out around a point condition; no tension anywhere stops with the message naming the
//   boundary conditions.
// - A strip with a central hole in tension (prm/plate-hole.prm: W = 0.1 m, d = 0.02 m, nominal
//   stress lambda MPa on the ends). The hoop stress on the rim peaks at the two points across the
//   load, sigma_max = K_t sigma_nominal, K_t = 3 in an infinite plate (Kirsch 1898); for the
//   strip, Heywood's fit of Howland's solution (Heywood 1952; Pilkey & Pilkey, Peterson's Stress
//   Concentration Factors, 3rd ed., Eq. 4.1) K_tn = 2 + (1 - d/W)^3 on the net section, so
//   K_t = K_tn / (1 - d/W) = 3.14 on the gross one at d/W = 0.2, and lambda_i = sigma_s / (K_t MPa).
//   Both points within one horizon of the first two sites (the rim's cells are half a horizon);
//   lambda_i within 10 %: the rim's cells, a tenth of the radius, resolve its stress (which falls
//   by 7/3 of the peak per radius from the rim) to about half a percent, and the converged K_t
//   of this strip lies about 1 % above Heywood's (the fit, and the strip's ends 5 d away).
// - An unnotched beam in three-point bending (prm/unnotched-beam.prm: span S = 0.4 m, depth
//   D = 0.05 m, the point force lambda N/m at mid-span). Beam theory: sigma = M c / I =
//   3 lambda S / (2 D^2) at mid-span on the bottom edge. The elastic solution differs from it
//   there by the point force's own field, about -0.133 lambda / D (Timoshenko & Goodier, Theory
//   of Elasticity, the concentrated force on a beam: 1.1 % of M c / I at S / D = 8), and the
//   bilinear cells (20 over the depth) by about as much again; the tolerance, 5 %, leaves room
//   for both. The site within one horizon of (S / 2 + overhang, 0).
// - Ingraffea's deep beam without its crack: the first site at mid-span, not next to the point
//   force (Point clearance).
// - LEFM growth on a scene without a crack prints the sites, writes initiation_sites.csv and
//   stops with one message naming Initial cracks (it has no law for a crack to start; global-local
//   nucleates one: nucleation_test.cc).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>

#include "csv.h"
#include "error.h"
#include "initiation.h"
#include "metric.h"
#include "expect_invalid.h"
#include "scene_file.h"

using namespace pumpd;
using geometry::Point;

namespace
{
  /// Vertices on a grid of spacing h over [0, 1]^2 with sigma_yy = sum of Gaussian bumps.
  std::vector<global::NodalStress> bumps(const std::vector<std::pair<Point, double>> &peaks, double h)
  {
    std::vector<global::NodalStress> field;
    const int                        n = int(std::round(1. / h));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        {
          global::NodalStress s;
          s.at        = {i * h, j * h};
          s.cell_size = std::sqrt(2.) * h;
          for (const auto &[at, height] : peaks)
            s.yy += height * std::exp(-std::pow(geometry::norm(s.at - at) / 0.1, 2));
          field.push_back(s);
        }
    return field;
  }

} // namespace

TEST(CandidateSites, BumpsWithinTheMarginAreListedLargestFirst)
{
  const auto   field  = bumps({{{0.3, 0.5}, 0.95e6}, {{0.7, 0.5}, 1e6}, {{0.5, 0.85}, 0.8e6}}, 0.01);
  const double strength = 2e6, horizon = 0.05;
  const auto   sites  = coupling::candidate_sites(field, strength, 0.1, horizon);
  ASSERT_EQ(sites.size(), 2u);
  EXPECT_LT(geometry::norm(sites[0].position - Point{0.7, 0.5}), 0.011);
  EXPECT_LT(geometry::norm(sites[1].position - Point{0.3, 0.5}), 0.011);
  EXPECT_NEAR(sites[0].ratio, 0.5, 0.01);
  EXPECT_NEAR(sites[0].load_factor, 1. / sites[0].ratio, 1e-12);
  EXPECT_NEAR(std::abs(sites[0].direction.y), 1., 1e-6); // sigma_1 = sigma_yy: a crack along x
  // With the margin 0.25 the third bump comes in; with 0 only the largest.
  EXPECT_EQ(coupling::candidate_sites(field, strength, 0.25, horizon).size(), 3u);
  EXPECT_EQ(coupling::candidate_sites(field, strength, 0., horizon).size(), 1u);
}

TEST(CandidateSites, NoSiteInADiskLeftOut)
{
  // The larger bump lies in a point condition's disk: the smaller one is the first site, and the
  // larger one's flank at the disk's edge (0.78 of its peak) is no site within the margin.
  const auto field = bumps({{{0.3, 0.5}, 0.95e6}, {{0.7, 0.5}, 1e6}}, 0.01);
  const auto sites = coupling::candidate_sites(field, 2e6, 0.1, 0.05, {{{0.7, 0.5}, 0.05}});
  ASSERT_EQ(sites.size(), 1u);
  EXPECT_LT(geometry::norm(sites[0].position - Point{0.3, 0.5}), 0.011);
}

TEST(CandidateSites, NoTensionStopsWithOneMessage)
{
  auto field = bumps({{{0.5, 0.5}, -1e6}}, 0.05);
  EXPECT_NE(test::invalid_message([&] { coupling::candidate_sites(field, 1e6, 0.1, 0.05); })
              .find("Boundary conditions = no tension: the largest principal stress is nowhere positive"),
            std::string::npos);
  for (auto &s : field)
    s.yy = 0.;
  const auto text = test::invalid_message([&] { coupling::candidate_sites(field, 1e6, 0.1, 0.05); });
  std::cout << text << "\n";
  EXPECT_NE(text.find("largest ratio to the strength per unit load factor 0 at (0, 0)"), std::string::npos);
}

TEST(Initiation, PlateWithAHoleStartsAtKirschsPoints)
{
  const auto     p     = test::scene_file("prm/plate-hole.prm", "");
  const auto     scene = coupling::build_scene(p.scene);
  const auto     found = coupling::find_initiation(scene, p.global, p.pd, p.initiation);
  const double   d_over_w = 0.02 / 0.1, kt = (2. + std::pow(1. - d_over_w, 3)) / (1. - d_over_w);
  const double   expected = found.strength / (kt * 1e6);
  const Point    kirsch[] = {{0.04, 0.1}, {0.06, 0.1}};
  const double   delta    = p.pd.horizon;
  ASSERT_GE(found.sites.size(), 2u);
  double position_err = 0.;
  for (int k = 0; k < 2; ++k)
    {
      const auto &s = found.sites[k];
      std::cout << "site " << k + 1 << ": " << geometry::to_text(s.position) << ", lambda_i " << s.load_factor
                << ", sigma_1 per unit load " << s.stress << " Pa along " << geometry::to_text(s.direction) << "\n";
      position_err = std::max(position_err, std::min(geometry::norm(s.position - kirsch[0]),
                                                     geometry::norm(s.position - kirsch[1])) / delta);
      EXPECT_GT(std::abs(s.direction.y), 0.99); // sigma_1 along the load: the crack across it
    }
  // The two sites are the two points, one each.
  EXPECT_GT(geometry::norm(found.sites[0].position - found.sites[1].position), 0.019);
  const double load_err = std::abs(found.sites[0].load_factor / expected - 1.);
  std::cout << "strength " << found.strength << " Pa, K_t " << kt << ", lambda_i " << found.sites[0].load_factor
            << ", expected " << expected << ", " << found.sites.size() << " sites\n";
  test::metric("initiation.hole.position_err_over_delta", position_err);
  test::metric("initiation.hole.load_rel_err", load_err);
  EXPECT_LE(position_err, 1.);
  EXPECT_LT(load_err, 0.10);
}

TEST(Initiation, BeamInBendingStartsAtMidSpanOnTheBottom)
{
  const auto   p     = test::scene_file("prm/unnotched-beam.prm", "");
  const auto   scene = coupling::build_scene(p.scene);
  const auto   found = coupling::find_initiation(scene, p.global, p.pd, p.initiation);
  const double span = 0.4, depth = 0.05, overhang = 0.02;
  const double expected = found.strength / (3. * span / (2. * depth * depth)); // sigma = M c / I at lambda = 1
  ASSERT_GE(found.sites.size(), 1u);
  const auto &s = found.sites[0];
  std::cout << "site 1 of " << found.sites.size() << ": " << geometry::to_text(s.position) << ", lambda_i "
            << s.load_factor << " (beam theory " << expected << "), sigma_1 along " << geometry::to_text(s.direction)
            << "\n";
  const double position_err = geometry::norm(s.position - Point{overhang + span / 2., 0.}) / p.pd.horizon;
  const double load_err     = std::abs(s.load_factor / expected - 1.);
  test::metric("initiation.beam.position_err_over_delta", position_err);
  test::metric("initiation.beam.load_rel_err", load_err);
  EXPECT_LE(position_err, 1.);
  EXPECT_LT(load_err, 0.05);
  EXPECT_GT(std::abs(s.direction.x), 0.99); // the bending stress along the beam: a crack across it
}

TEST(Initiation, DeepBeamStartsAtMidSpanNotAtTheLoadPoint)
{
  // Ingraffea's beam with holes (S / D = 2.25) without its crack: the mesh's largest tension lies
  // next to the point force (the bilinear field of a point force on the surface: the exact one,
  // Flamant's, is compressive), more than twice the bending stress; outside the point clearance
  // the first site is at mid-span on the bottom edge. Both within one cell (8 mm).
  auto p                 = test::scene_file("prm/ingraffea-case2.prm", "");
  p.scene.initial_cracks = "";
  const auto scene       = coupling::build_scene(p.scene);
  const auto found       = coupling::find_initiation(scene, p.global, p.pd, p.initiation);
  ASSERT_GE(found.sites.size(), 1u);
  std::cout << "site 1 of " << found.sites.size() << ": " << geometry::to_text(found.sites[0].position) << "\n";
  EXPECT_LT(geometry::norm(found.sites[0].position - Point{0.254, 0.}), 0.008);
  p.initiation.point_clearance = 0.;
  const auto at_load           = coupling::find_initiation(scene, p.global, p.pd, p.initiation);
  std::cout << "without the clearance: " << geometry::to_text(at_load.sites[0].position) << ", "
            << at_load.sites[0].stress / found.sites[0].stress << " times the stress at mid-span\n";
  EXPECT_LT(geometry::norm(at_load.sites[0].position - Point{0.254, 0.2032}), 0.008);
  EXPECT_GT(at_load.sites[0].stress, 2. * found.sites[0].stress);
}

TEST(Initiation, LefmGrowthListsTheSitesAndStops)
{
  auto p   = test::scene_file("prm/unnotched-beam.prm", "initiation_beam");
  p.method = "lefm-growth";
  std::ostringstream  out;
  const auto          text = test::invalid_message([&] { coupling::run(p, out); });
  std::cout << out.str() << text << "\n";
  EXPECT_EQ(text.rfind("Initial cracks = none: LEFM growth has no law for a crack to start", 0), 0u);
  EXPECT_NE(out.str().find("site 1: (0.22, 0), lambda_i = "), std::string::npos);
  const auto rows = read_csv_rows(p.scene.output_directory + "/initiation_sites.csv");
  ASSERT_GE(rows.size(), 1u);
  EXPECT_NEAR(std::stod(rows[0].at("x_m")), 0.22, 1e-9);
  EXPECT_NEAR(std::stod(rows[0].at("y_m")), 0., 1e-9);
}
