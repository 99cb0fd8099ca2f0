#include "boundary_transfer.h"

namespace pumpd::coupling
{
  std::string conditions_left_free(const conditions::Conditions &conditions, const local::PdModel &model)
  {
    const double             h = model.lattice().spacing();
    std::string              names;
    const auto               check = [&](const conditions::Place &place) {
      for (std::size_t i : model.nodes())
        if (model.free_mask()[i] > 0. && conditions::near(place, model.lattice().position(i), h))
          {
            names += (names.empty() ? "" : ", ") + place.name;
            return;
          }
    };
    for (const auto &c : conditions.displacements)
      check(c.place);
    for (const auto &c : conditions.tractions)
      check(c.place);
    for (const auto &c : conditions.forces)
      check(c.place);
    return names;
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

  void BoundaryTransfer::start(double lambda, local::State &s) const
  {
    for (std::size_t i : model.nodes())
      {
        s.ux[i] = lambda * ux[i];
        s.uy[i] = lambda * uy[i];
      }
  }
} // namespace pumpd::coupling
