#include "boundary_layer.h"

#include <algorithm>
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

  namespace
  {
    std::size_t checked_region(const PdModel &model, std::size_t region)
    {
      if (region >= model.prescribed_regions().size())
        throw InvalidParameter("Prescribed region index", std::to_string(region),
                               "must be below the model's number of prescribed regions (" +
                                 std::to_string(model.prescribed_regions().size()) + ")");
      return region;
    }
  } // namespace

  RegionDisplacement::RegionDisplacement(const PdModel &m, std::size_t region)
    : model(m)
    , index(checked_region(m, region))
    , x0(nodes().size(), 0.)
    , y0(nodes().size(), 0.)
    , x1(nodes().size(), 0.)
    , y1(nodes().size(), 0.)
  {}

  const PrescribedRegion &RegionDisplacement::region() const { return model.prescribed_regions()[index]; }

  void RegionDisplacement::set_target(geometry::Point u)
  {
    if (!std::isfinite(u.x) || !std::isfinite(u.y))
      throw InvalidParameter(region().name + " displacement", "non-finite value", "must be finite");
    std::fill(x1.begin(), x1.end(), u.x);
    std::fill(y1.begin(), y1.end(), u.y);
  }

  void RegionDisplacement::set_target(const std::function<geometry::Point(geometry::Point)> &displacement)
  {
    const auto &n = nodes();
    for (std::size_t k = 0; k < n.size(); ++k)
      {
        const auto u = displacement(model.lattice().position(n[k]));
        if (!std::isfinite(u.x) || !std::isfinite(u.y))
          throw InvalidParameter(region().name + " displacement", "non-finite value at region node " + std::to_string(k),
                                 "must be finite");
        x1[k] = u.x;
        y1[k] = u.y;
      }
  }

  void RegionDisplacement::set_target(const std::vector<double> &ux, const std::vector<double> &uy)
  {
    if (ux.size() != nodes().size() || uy.size() != nodes().size())
      throw InvalidParameter(region().name + " displacement", std::to_string(ux.size()) + " values",
                             "one per node of the region (" + std::to_string(nodes().size()) + ")");
    x1 = ux;
    y1 = uy;
  }

  void RegionDisplacement::start_from(const State &s)
  {
    const auto &n = nodes();
    for (std::size_t k = 0; k < n.size(); ++k)
      {
        x0[k] = s.ux[n[k]];
        y0[k] = s.uy[n[k]];
      }
  }

  void RegionDisplacement::apply(State &s, double ramp) const
  {
    const auto &n = nodes();
    const auto &r = region();
    for (std::size_t k = 0; k < n.size(); ++k)
      {
        if (r.fix_x)
          s.ux[n[k]] = x0[k] + ramp * (x1[k] - x0[k]);
        if (r.fix_y)
          s.uy[n[k]] = y0[k] + ramp * (y1[k] - y0[k]);
      }
  }
} // namespace pumpd::local
