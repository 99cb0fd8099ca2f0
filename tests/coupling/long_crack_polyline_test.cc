// A crack given as a long polyline, as a digitised experimental path is (issue 45, point 13): the
// SENT scene's edge crack (prm/sent.prm, a/W = 0.5) written with 3000 collinear vertices is the
// same crack as its two-vertex form, so the global problem gives the same K within the last
// digits of the interaction integral, and the crack geometry's cost stays near-linear in the
// vertices (basics/segment_tree.h), so the solve ends.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "error.h"
#include "metric.h"
#include "scene_file.h"
#include "specimen.h"

using namespace pumpd;

namespace
{
  /// K_I per unit load of prm/sent.prm with its crack from (0, 0) to (0.05, 0) in `vertices` vertices.
  double k1_with(std::size_t vertices)
  {
    auto        p = test::scene_file("prm/sent.prm", "");
    std::string crack;
    for (std::size_t k = 0; k < vertices; ++k)
      crack += (k ? "; " : "") + pumpd::to_text(0.05 * double(k) / double(vertices - 1), 17) + ",0";
    p.scene.initial_cracks = crack;
    const auto scene       = coupling::build_scene(p.scene);
    EXPECT_EQ(scene.crack().size(), vertices);
    return test::solve(scene, p.global).tip.k1;
  }
} // namespace

TEST(LongCrackPolyline, ThreeThousandVerticesGiveTheKOfTwo)
{
  const double two = k1_with(2), many = k1_with(3000);
  test::metric("reliability.long_polyline.k_rel_diff", std::abs(many / two - 1.));
  EXPECT_NEAR(many / two, 1., 1e-3);
}
