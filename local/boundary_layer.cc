#include "boundary_layer.h"

#include <cmath>

#include "error.h"

namespace pumpd::local
{
  BoundaryLayer::BoundaryLayer(const PdModel &m)
    : model(m)
    , nodes(m.boundary_layer())
    , x0(nodes.size(), 0.)
    , y0(nodes.size(), 0.)
    , x1(nodes.size(), 0.)
    , y1(nodes.size(), 0.)
  {}

  std::vector<geometry::Point> BoundaryLayer::positions() const
  {
    std::vector<geometry::Point> p;
    p.reserve(nodes.size());
    for (std::size_t i : nodes)
      p.push_back(model.lattice().position(i));
    return p;
  }

  void BoundaryLayer::set_target(const std::function<geometry::Point(geometry::Point)> &displacement)
  {
    std::vector<double> ux(nodes.size()), uy(nodes.size());
    for (std::size_t n = 0; n < nodes.size(); ++n)
      {
        const auto u = displacement(model.lattice().position(nodes[n]));
        ux[n]        = u.x;
        uy[n]        = u.y;
      }
    set_target(ux, uy);
  }

  void BoundaryLayer::set_target(const std::vector<double> &ux, const std::vector<double> &uy)
  {
    if (ux.size() != nodes.size() || uy.size() != nodes.size())
      throw InvalidParameter("Boundary-layer displacement", std::to_string(ux.size()) + " values",
                             "must give one value per layer node (" + std::to_string(nodes.size()) + ")");
    for (std::size_t n = 0; n < nodes.size(); ++n)
      if (!std::isfinite(ux[n]) || !std::isfinite(uy[n]))
        throw InvalidParameter("Boundary-layer displacement", "non-finite value at layer node " + std::to_string(n),
                               "must be finite");
    x1 = ux;
    y1 = uy;
  }

  void BoundaryLayer::start_from(const State &s)
  {
    for (std::size_t n = 0; n < nodes.size(); ++n)
      {
        x0[n] = s.ux[nodes[n]];
        y0[n] = s.uy[nodes[n]];
      }
  }

  void BoundaryLayer::apply(State &s, double ramp) const
  {
    for (std::size_t n = 0; n < nodes.size(); ++n)
      {
        s.ux[nodes[n]] = x0[n] + ramp * (x1[n] - x0[n]);
        s.uy[nodes[n]] = y0[n] + ramp * (y1[n] - y0[n]);
      }
  }
} // namespace pumpd::local
