#include "boundary_transfer.h"

#include "pd_conditions.h"

namespace pumpd::coupling
{
  std::vector<local::PrescribedRegion> held_places(const conditions::Conditions &conditions,
                                                   const local::PdModel         &probe)
  {
    const double                         h = probe.lattice().spacing(), horizon = probe.material().horizon();
    std::vector<local::PrescribedRegion> held;
    const auto                           take_in = [&](const conditions::Place &place) {
      for (std::size_t i : probe.nodes())
        if (probe.free_mask()[i] > 0. && conditions::near(place, probe.lattice().position(i), h))
          {
            held.push_back(local::prescribed_region(place, true, true, horizon, horizon));
            if (place.kind == conditions::Place::Kind::point)
              held.back().elastic_margin = horizon;
            return;
          }
    };
    for (const conditions::Place *place : conditions::places(conditions))
      take_in(*place);
    return held;
  }

  BoundaryTransfer::BoundaryTransfer(GlobalProblem &global, const local::PdModel &m)
    : model(m)
    , ux(m.lattice().storage_size(), 0.)
    , uy(ux.size(), 0.)
  {
    std::vector<geometry::Point> x;
    for (std::size_t i : model.nodes())
      x.push_back(model.lattice().position(i));
    const auto u = global.displacement_per_unit_load(x);
    for (std::size_t k = 0; k < x.size(); ++k)
      {
        ux[model.nodes()[k]] = u[k].x;
        uy[model.nodes()[k]] = u[k].y;
      }
  }

  void BoundaryTransfer::apply(double lambda, local::BoundaryLayer &layer) const
  {
    const auto         &nodes = model.boundary_layer();
    std::vector<double> x(nodes.size()), y(nodes.size());
    for (std::size_t k = 0; k < nodes.size(); ++k)
      {
        x[k] = lambda * ux[nodes[k]];
        y[k] = lambda * uy[nodes[k]];
      }
    layer.set_target(x, y);
  }

  void BoundaryTransfer::hold(double lambda, local::State &s) const
  {
    for (std::size_t r = 0; r < model.prescribed_regions().size(); ++r)
      {
        const auto &region = model.prescribed_regions()[r];
        for (std::size_t i : model.prescribed_nodes(r))
          {
            if (region.fix_x)
              s.ux[i] = lambda * ux[i];
            if (region.fix_y)
              s.uy[i] = lambda * uy[i];
          }
      }
  }

  void BoundaryTransfer::start(double lambda, local::State &s) const
  {
    for (std::size_t i : model.nodes())
      {
        s.ux[i] = lambda * ux[i];
        s.uy[i] = lambda * uy[i];
      }
  }
} // namespace pumpd::coupling
