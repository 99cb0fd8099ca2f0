// A crack that starts where there was none (coupling/nucleation.h): the PD box at the first
// initiation site forms a crack, which the global-local cycle then grows.
//
// - The mouth and direction on a plain body: a site near an edge or a hole's rim opens at the
//   nearest boundary point, perpendicular to sigma_1 into the material; a site more than a horizon
//   inside the body has none (an interior crack with two tips: brazilian_disc_test.cc).
//   Sites within half a box side of one before them are the same site.
// - The unnotched beam in three-point bending (prm/unnotched-beam.prm): the crack starts at
//   mid-span on the bottom edge (within a horizon) and grows up, within a horizon of the mid-span
//   line, at least three horizons; nucleation.csv holds its path and load factor.
// - The L-shaped panel without a pre-crack (prm/l-panel-initiation.prm): the first site is the
//   re-entrant corner (within half a cell), the crack starts there and grows into the panel, to
//   the left and not down into the held leg.
// - The strip with a hole (prm/plate-hole.prm): two sites on the rim, mirror images; both are
//   checked and both form a crack within one load increment, so two cracks start, one at each
//   Kirsch point (mouths within a horizon), and grow together across the load (within 10 degrees
//   of x over their first three horizons). The scene is symmetric about x = 0.05: the second
//   crack's path mirrored about it lies within two PD spacings of the first's (Hausdorff, tips
//   included). Each crack's tip is read off the damage on its own box's lattice, and each box's
//   states stop at their own load of the ladder, so the two tips may differ by about a spacing
//   per exchange.
// - A scene that does not break up to the Maximum load factor says so in one message, with the
//   elastic sigma_1 / sigma_s at the site and the largest bond stretch seen.
// Coarse settings (m = 4, two exchanges after the nucleation) keep each run well under a minute.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>

#include "csv.h"
#include "error.h"
#include "metric.h"
#include "nucleation.h"
#include "path_metrics.h"
#include "expect_invalid.h"
#include "scene_file.h"

using namespace pumpd;
using geometry::Point;

namespace
{

  /// Coarse settings for CI: m = 4, the exchanges after the nucleation limited to `exchanges`.
  coupling::Parameters coarse(const std::string &file, const std::string &output, unsigned int exchanges)
  {
    auto p                    = test::scene_file(file, output);
    p.pd.horizon_over_spacing = 4;
    p.cycle.max_exchanges     = exchanges;
    return p;
  }

  struct Run
  {
    coupling::Scene             scene;
    coupling::GlobalLocalResult result;
    geometry::Polyline          nucleated; ///< the first crack of nucleation.csv
    std::size_t                 cracks = 0; ///< the initial cracks of nucleation.csv
    double                      lambda = 0., lambda_over_lambda_i = 0.;
  };

  Run run(const coupling::Parameters &p)
  {
    Run r{coupling::build_scene(p.scene), {}, {}, 0};
    r.result    = coupling::run_global_local_from_initiation(r.scene, p.global_local_settings(), p.initiation, std::cout);
    const auto rows = read_csv_rows(p.scene.output_directory + "/nucleation.csv");
    for (const auto &row : rows)
      {
        r.cracks = std::max<std::size_t>(r.cracks, std::stoul(row.at("crack")));
        if (row.at("crack") == "1")
          r.nucleated.push_back({std::stod(row.at("x_m")), std::stod(row.at("y_m"))});
      }
    if (!rows.empty())
      {
        r.lambda               = std::stod(rows[0].at("lambda"));
        r.lambda_over_lambda_i = std::stod(rows[0].at("lambda_over_lambda_i"));
      }
    std::cout << "nucleated " << geometry::to_text(r.nucleated) << " at lambda " << r.lambda << " ("
              << r.lambda_over_lambda_i << " lambda_i); grown " << geometry::to_text(r.result.path) << "\n";
    return r;
  }

  /// The point at arc length s along the path (its end if shorter).
  Point at_length(const geometry::Polyline &path, double s)
  {
    for (std::size_t k = 1; k < path.size(); ++k)
      {
        const double l = geometry::norm(path[k] - path[k - 1]);
        if (s <= l)
          return path[k - 1] + (s / l) * (path[k] - path[k - 1]);
        s -= l;
      }
    return path.back();
  }
} // namespace

TEST(NucleationMouth, NearestBoundaryPointAndTheDirectionIntoTheMaterial)
{
  const geometry::Body body(geometry::Box{0., 0., 1., 0.5}, {{{0.5, 0.25}, 0.1}});
  const double         delta = 0.01;
  const Point          bottom = coupling::nucleation_mouth(body, {0.3, 0.004}, delta).value();
  EXPECT_NEAR(bottom.x, 0.3, 1e-12);
  EXPECT_NEAR(bottom.y, 0., 1e-12);
  // sigma_1 along x at the bottom edge: the crack runs up, into the body.
  const Point up = coupling::opening_direction(body, bottom, {1., 0.}, delta);
  EXPECT_NEAR(up.y, 1., 1e-12);
  // East of the hole, on its rim: sigma_1 along y, the crack runs east, away from the hole.
  const Point rim = coupling::nucleation_mouth(body, {0.605, 0.25}, delta).value();
  EXPECT_NEAR(rim.x, 0.6, 1e-12);
  EXPECT_NEAR(rim.y, 0.25, 1e-12);
  EXPECT_NEAR(coupling::opening_direction(body, rim, {0., 1.}, delta).x, 1., 1e-12);
}

TEST(NucleationMouth, AnInteriorSiteHasNone)
{
  const geometry::Body body(geometry::Box{0., 0., 1., 0.5});
  EXPECT_FALSE(coupling::nucleation_mouth(body, {0.3, 0.2}, 0.01));
  EXPECT_TRUE(coupling::nucleation_mouth(body, {0.3, 0.009}, 0.01));
}

TEST(NucleationSites, ThoseWithinADistanceOfOneBeforeAreTheSameSite)
{
  std::vector<coupling::InitiationSite> sites(4);
  sites[0].position = {0., 0.};
  sites[1].position = {0.02, 0.};  // within 0.03 of the first
  sites[2].position = {0.05, 0.};  // a site of its own
  sites[3].position = {0.07, 0.};  // within 0.03 of the third
  EXPECT_EQ(coupling::distinct_sites(sites, 0.03), (std::vector<std::size_t>{0, 2}));
}

TEST(Nucleation, BeamCrackStartsAtMidSpanAndGrowsUp)
{
  const auto   p     = coarse("prm/unnotched-beam.prm", "nucleation_beam", 2);
  const auto   r     = run(p);
  const double delta = p.pd.horizon, mid = 0.22;
  ASSERT_GE(r.nucleated.size(), 2u);
  const double position_err = geometry::norm(r.nucleated.front() - Point{mid, 0.}) / delta;
  double       off_line     = 0.;
  for (const auto &x : r.result.path)
    off_line = std::max(off_line, std::abs(x.x - mid));
  const double rise = r.result.path.back().y - r.result.path.front().y;
  test::metric("initiation.beam.position_err_over_delta", position_err);
  test::metric("initiation.beam.rise_over_delta", rise / delta);
  test::metric("initiation.beam.off_midspan_over_delta", off_line / delta);
  test::metric("initiation.beam.load_over_lambda_i", r.lambda_over_lambda_i);
  EXPECT_LE(position_err, 1.);
  EXPECT_GE(geometry::length(r.nucleated), p.cycle.exchange.min_advance - 1e-9);
  EXPECT_GE(r.lambda_over_lambda_i, p.initiation.first_load_factor);
  EXPECT_GE(rise, 3. * delta);
  EXPECT_LE(off_line, delta);
  EXPECT_NEAR(r.result.path.front().x, r.nucleated.front().x, 1e-9); // the cycle grew the nucleated crack
}

TEST(Nucleation, LPanelCrackStartsAtTheReentrantCorner)
{
  const auto  p      = coarse("prm/l-panel-initiation.prm", "nucleation_lpanel", 2);
  const Point corner{0.25, 0.25};
  const auto  found  = coupling::find_initiation(coupling::build_scene(p.scene), p.global, p.pd, p.initiation);
  ASSERT_GE(found.sites.size(), 1u);
  std::cout << "site 1 of " << found.sites.size() << ": " << geometry::to_text(found.sites[0].position) << "\n";
  EXPECT_LT(geometry::norm(found.sites[0].position - corner), 0.5 * p.scene.mesh_size);

  const auto r = run(p);
  ASSERT_GE(r.nucleated.size(), 2u);
  const double position_err = geometry::norm(r.nucleated.front() - corner) / p.pd.horizon;
  test::metric("initiation.lpanel.position_err_over_delta", position_err);
  test::metric("initiation.lpanel.growth_mm", 1e3 * geometry::length(r.result.path));
  EXPECT_LE(position_err, 1.);
  EXPECT_LT(r.result.path.back().x, corner.x - 2. * p.pd.horizon); // into the panel, to the left
  EXPECT_GE(r.result.path.back().y, corner.y - p.pd.horizon);      // not down into the held leg
  EXPECT_GT(geometry::length(r.result.path), geometry::length(r.nucleated));
}

TEST(Nucleation, PlateWithAHoleTwoCracksStartAtKirschsPointsAcrossTheLoad)
{
  const auto   p     = coarse("prm/plate-hole.prm", "nucleation_hole", 2);
  const auto   r     = run(p);
  const double delta = p.pd.horizon, h = p.pd.spacing();
  test::metric("initiation.hole.cracks_formed", double(r.cracks));
  ASSERT_EQ(r.cracks, 2u);
  ASSERT_EQ(r.result.paths.size(), 2u);
  ASSERT_GE(r.nucleated.size(), 2u);
  double position_err = 0., angle = 0.;
  for (const auto &path : r.result.paths)
    {
      const Point mouth = path.front();
      position_err      = std::max(position_err, std::min(geometry::norm(mouth - Point{0.04, 0.1}),
                                                          geometry::norm(mouth - Point{0.06, 0.1})) / delta);
      const Point chord = at_length(path, 3. * delta) - mouth;
      angle             = std::max(angle, std::abs(std::atan2(chord.y, std::abs(chord.x))) * 180. / M_PI);
      EXPECT_GT(std::abs(chord.x), 2. * delta); // away from the hole
    }
  // One crack at each point: the mouths on either side of the hole.
  EXPECT_LT((r.result.paths[0].front().x - 0.05) * (r.result.paths[1].front().x - 0.05), 0.);
  // The second mirrored about the hole's vertical axis onto the first.
  geometry::Polyline mirrored;
  for (const auto &x : r.result.paths[1])
    mirrored.push_back({0.1 - x.x, x.y});
  const double asymmetry = coupling::path_distance(r.result.paths[0], mirrored, 0.1 * h).hausdorff / h;
  std::cout << "grown: " << geometry::to_text(r.result.paths[0]) << " | " << geometry::to_text(r.result.paths[1])
            << "; lengths " << geometry::length(r.result.paths[0]) << ", " << geometry::length(r.result.paths[1]) << "\n";
  test::metric("initiation.hole.nucleated_position_err_over_delta", position_err);
  test::metric("initiation.hole.first_horizons_angle_deg", angle);
  test::metric("initiation.hole.asymmetry_over_h", asymmetry);
  EXPECT_LE(position_err, 1.);
  EXPECT_LT(angle, 10.);
  EXPECT_LE(asymmetry, 2.);
  EXPECT_GT(geometry::length(r.result.paths[0]), geometry::length(r.nucleated)); // the cycle grew them
}

TEST(Nucleation, ASceneThatDoesNotBreakSaysSo)
{
  auto p                            = coarse("prm/unnotched-beam.prm", "nucleation_never", 1);
  p.cycle.exchange.max_load_factor  = 0.85;
  const auto         scene          = coupling::build_scene(p.scene);
  std::ostringstream out;
  const auto         text = test::invalid_message(
    [&] { coupling::run_global_local_from_initiation(scene, p.global_local_settings(), p.initiation, out); });
  std::cout << out.str() << text << "\n";
  EXPECT_EQ(text.rfind("Maximum load factor = 0.85: no crack formed at the first initiation site (0.22, 0) up to this "
                       "many times lambda_i",
                       0),
            0u);
  EXPECT_NE(text.find("the elastic sigma_1 / sigma_s there reached 0.85"), std::string::npos);
  EXPECT_NE(text.find("the largest bond stretch over its critical one"), std::string::npos);
}
