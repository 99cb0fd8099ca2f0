// Validation 1: a homogeneous strain prescribed through the boundary layer and relaxed gives, at
// nodes beyond the layer, the linear-elastic energy density 1/2 sigma:eps (tolerance 2 %), in
// plane strain and plane stress, for m = 3, 4, 8 and both influence functions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "boundary_layer.h"
#include "integrators.h"
#include "metric.h"
#include "model.h"

using namespace pumpd;
using namespace pumpd::local;

namespace
{
  struct Strain
  {
    const char *name;
    double      exx, eyy, exy;
  };

  // Interior energy density relative error for one strain, after dynamic relaxation.
  double relative_error(const Strain &e, int m, bool plane_strain, Influence influence)
  {
    MaterialParameters p;
    p.plane_strain = plane_strain;
    p.influence    = influence;
    const double delta = 0.004;
    Region       region;
    region.body = geometry::Body(geometry::Box{-1., -1., 1., 1.});
    region.box          = {0., 0., 5. * delta, 5. * delta};
    PdModel model(p, delta, m, region);

    BoundaryLayer layer(model);
    layer.set_target([&](geometry::Point x) {
      return geometry::Point{e.exx * x.x + e.exy * x.y, e.exy * x.x + e.eyy * x.y};
    });
    State s = model.initial_state();
    layer.apply(s, 1.);
    const auto result = DynamicRelaxation(model, 1e-10, 200000).solve(s);
    EXPECT_TRUE(result.converged) << "residual " << result.residual;

    // Nodes at least one horizon away from the layer see only free and layer nodes that follow
    // the affine field.
    const auto   w     = model.energy_density(s);
    const double exact = model.material().elastic_energy_density(e.exx, e.eyy, e.exy);
    const auto  &box   = region.box;
    double       worst = 0.;
    for (std::size_t i : model.nodes())
      {
        const auto x = model.lattice().position(i);
        if (std::min({x.x - box.x_min, box.x_max - x.x, x.y - box.y_min, box.y_max - x.y}) > 2. * delta)
          worst = std::max(worst, std::abs(w[i] - exact) / exact);
      }
    return worst;
  }
} // namespace

TEST(Calibration, HomogeneousStrainEnergyDensity)
{
  const Strain strains[] = {{"uniaxial", 1e-4, 0., 0.}, {"biaxial", 1e-4, 1e-4, 0.}, {"shear", 0., 0., 1e-4}};
  double       worst     = 0.;
  for (const auto &e : strains)
    for (int m : {3, 4, 8})
      for (bool plane_strain : {true, false})
        for (Influence j : {Influence::constant, Influence::linear})
          {
            const double err = relative_error(e, m, plane_strain, j);
            std::cout << e.name << " m=" << m << (plane_strain ? " plane strain " : " plane stress ")
                      << to_string(j) << ": rel. error " << err << "\n";
            EXPECT_LT(err, 0.02);
            worst = std::max(worst, err);
          }
  test::metric("pd.calibration_max_rel_err", worst);
}
