// L-shaped panel (prm/l-panel.prm, meshes/l-panel.geo): a 0.5 m square without its lower-right
// quarter, held along its bottom edge, the short leg pushed up near its end; a 10 mm pre-crack
// leaves the re-entrant corner (0.25, 0.25) to the left.
// - The PD body at the corner: a PdModel on the scene's body and a box around the corner has no
//   node in the cut-out (x > 0.25, y < 0.25) and no bond across it, while pairs of its nodes
//   whose segment would cut the corner exist (the check is not empty).
// - A box edge along the cut-out's side is free surface below the corner: no boundary layer there.
// - The crack grows from the corner in both methods: LEFM growth (three increments) and the
//   global-local cycle (two exchanges), to the left, inside the body.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "growing_specimen.h"
#include "metric.h"
#include "model.h"

using namespace pumpd;
using geometry::Point;

namespace
{
  const std::string scene_file = "prm/l-panel.prm";
  const Point       corner{0.25, 0.25};

  /// In the open cut-out x > 0.25, y < 0.25.
  bool in_cutout(Point p) { return p.x > corner.x && p.y < corner.y; }

  /// True if some stretch of the segment [a, b] (ends outside the cut-out) lies in the open
  /// cut-out: the t in (0, 1) with x(t) > 0.25 and those with y(t) < 0.25 overlap.
  bool cuts_corner(Point a, Point b)
  {
    double lo = 0., hi = 1.;
    const auto keep = [&](double start, double slope, bool above) { // start + t slope > 0 (above) or < 0
      if (slope == 0.)
        {
          if (above ? start <= 0. : start >= 0.)
            hi = -1.;
          return;
        }
      const double t = -start / slope;
      if ((slope > 0.) == above)
        lo = std::max(lo, t);
      else
        hi = std::min(hi, t);
    };
    keep(a.x - corner.x, b.x - a.x, true);
    keep(a.y - corner.y, b.y - a.y, false);
    return hi - lo > 1e-12;
  }
} // namespace

TEST(LPanel, PdBodyAtTheCornerHasNoNodeInTheCutoutAndNoBondAcrossIt)
{
  const auto p     = test::scene_file(scene_file, "");
  const auto scene = coupling::build_scene(p.scene);
  // A box of the cycle's size centred on the corner: a quarter of it is cut-out.
  const double          half = 0.5 * p.cycle.box.size;
  const geometry::Box   box{corner.x - half, corner.y - half, corner.x + half, corner.y + half};
  const local::PdModel  model(p.pd.material(scene.material), p.pd.horizon, p.pd.horizon_over_spacing,
                              local::Region{scene.body, box, scene.cracks});
  const auto           &lattice = model.lattice();
  const auto           &stencil = model.stencil();

  std::size_t quarter_nodes = 0;
  for (std::size_t iy = 0; iy < lattice.ny(); ++iy)
    for (std::size_t ix = 0; ix < lattice.nx(); ++ix)
      quarter_nodes += in_cutout(lattice.position(lattice.index(ix, iy)));
  std::vector<char> material(lattice.storage_size(), 0);
  for (std::size_t i : model.nodes())
    {
      material[i] = 1;
      EXPECT_FALSE(in_cutout(lattice.position(i))) << lattice.position(i).x << ", " << lattice.position(i).y;
    }
  // Three quarters of the lattice carry material, the cut-out's quarter none.
  EXPECT_EQ(model.nodes().size() + quarter_nodes, lattice.nx() * lattice.ny());
  EXPECT_GT(quarter_nodes, lattice.nx() * lattice.ny() / 5);

  std::size_t across = 0, bonds = 0, candidates = 0;
  for (std::size_t k = 0; k < stencil.size(); ++k)
    {
      const std::ptrdiff_t off = stencil.dx[k] + std::ptrdiff_t(lattice.stride()) * stencil.dy[k];
      for (std::size_t i : model.nodes())
        {
          const std::size_t j = i + off;
          if (!material[j])
            continue;
          const bool cuts = cuts_corner(lattice.position(i), lattice.position(j));
          candidates += cuts;
          if (model.bond_exists(k, i))
            {
              ++bonds;
              across += cuts;
            }
        }
    }
  std::cout << model.nodes().size() << " PD nodes, " << quarter_nodes << " lattice sites in the cut-out; " << bonds
            << " bonds, " << candidates << " node pairs within a horizon whose segment cuts the corner, " << across
            << " of them bonded\n";
  EXPECT_GT(candidates, 100u);
  EXPECT_EQ(across, 0u);
  EXPECT_GT(bonds, 10 * model.nodes().size());
}

// A box whose right edge runs along the cut-out's side x = 0.25 (as BoxPolicy places the first one,
// its edges on lattice lines): within a horizon of that edge, the nodes below the corner have free
// surface beyond it and stay free, those above it have the arm beyond it and form the boundary layer.
TEST(LPanel, BoundaryLayerOnlyWhereTheBodyGoesOnAcrossTheBoxEdge)
{
  const auto            p     = test::scene_file(scene_file, "");
  const auto            scene = coupling::build_scene(p.scene);
  const double          size  = p.cycle.box.size;
  const geometry::Box   box{corner.x - size, corner.y - 0.5 * size, corner.x, corner.y + 0.5 * size};
  const local::PdModel  model(p.pd.material(scene.material), p.pd.horizon, p.pd.horizon_over_spacing,
                              local::Region{scene.body, box, scene.cracks});
  std::vector<char>     layer(model.lattice().storage_size(), 0);
  for (std::size_t i : model.boundary_layer())
    layer[i] = 1;
  std::size_t below = 0, below_in_layer = 0, above = 0, above_in_layer = 0;
  for (std::size_t i : model.nodes())
    {
      const Point x = model.lattice().position(i);
      if (corner.x - x.x >= p.pd.horizon || x.y - box.y_min < p.pd.horizon || box.y_max - x.y < p.pd.horizon)
        continue; // not near the right edge only
      (x.y < corner.y ? below : above) += 1;
      (x.y < corner.y ? below_in_layer : above_in_layer) += layer[i];
    }
  std::cout << "within a horizon of the box edge x = 0.25: " << below_in_layer << " of " << below
            << " nodes below the corner in the layer, " << above_in_layer << " of " << above << " above it\n";
  EXPECT_GT(below, 0u);
  EXPECT_EQ(below_in_layer, 0u);
  EXPECT_GT(above, 0u);
  EXPECT_EQ(above_in_layer, above);
}

TEST(LPanel, GrowsFromTheCornerInBothMethods)
{
  const auto r = test::grow_in_both_methods(scene_file, "l_panel", "scene.lpanel", 0.01);
  for (const auto *path : {&r.lefm.path, &r.gl.path})
    {
      EXPECT_EQ(path->front().x, corner.x); // the mouth stays at the corner
      EXPECT_EQ(path->front().y, corner.y);
      EXPECT_LT(path->back().x, r.scene.crack().back().x - 0.001); // to the left, away from the corner
      EXPECT_GE(path->back().y, corner.y); // and not down into the held leg
    }
}
