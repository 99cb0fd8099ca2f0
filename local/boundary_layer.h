// Prescribed displacement on the boundary layer (nodes within one horizon of an interior box
// edge), ramped from a start value u0 to a target u1: u(ramp) = u0 + ramp (u1 - u0), ramp in [0, 1].
// The target comes from a callback (an analytic field) or from arrays (the global solution
// evaluated at positions()).
#pragma once

#include <functional>
#include <vector>

#include "geometry.h"
#include "model.h"

namespace pumpd::local
{
  class BoundaryLayer
  {
  public:
    explicit BoundaryLayer(const PdModel &model);

    /// Node positions of the layer, in the order the array setter expects.
    std::vector<geometry::Point> positions() const;
    std::size_t                  size() const { return nodes.size(); }

    void set_target(const std::function<geometry::Point(geometry::Point)> &displacement);
    /// Throws InvalidParameter if the sizes differ from size() or a value is not finite.
    void set_target(const std::vector<double> &ux, const std::vector<double> &uy);
    /// The ramp starts from the layer's displacement in s.
    void start_from(const State &s);
    /// Writes the ramped displacement into the layer nodes of s.
    void apply(State &s, double ramp) const;

  private:
    const PdModel           &model;
    std::vector<std::size_t> nodes;
    std::vector<double>      x0, y0, x1, y1;
  };
} // namespace pumpd::local
