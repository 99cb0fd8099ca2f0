// Prescribed displacement on the boundary layer (nodes within one horizon of an interior box
// edge), ramped from a start value u0 to a target u1: u(ramp) = u0 + ramp (u1 - u0), ramp in [0, 1].
// The target comes from a callback (an analytic field) or from arrays (the global solution
// evaluated at positions()). RegionDisplacement does the same for one prescribed region of the
// model (a support, a loading pad), on the components that region fixes only.
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

  /// The prescribed displacement of PdModel::prescribed_regions()[region], ramped like the layer:
  /// u(ramp) = u0 + ramp (u1 - u0) on the fixed components; free components are never written.
  class RegionDisplacement
  {
  public:
    /// Throws InvalidParameter if the model has no such region.
    RegionDisplacement(const PdModel &model, std::size_t region);

    const PrescribedRegion         &region() const;
    const std::vector<std::size_t> &nodes() const { return model.prescribed_nodes(index); }
    std::size_t                     size() const { return nodes().size(); }

    /// The same displacement for every node of the region (a rigid pad, a support at zero).
    void set_target(geometry::Point displacement);
    void set_target(const std::function<geometry::Point(geometry::Point)> &displacement);
    /// Per node of the region, in the order of nodes(). Throws InvalidParameter for a wrong size.
    void set_target(const std::vector<double> &ux, const std::vector<double> &uy);
    /// The ramp starts from the region's displacement in s.
    void start_from(const State &s);
    /// Writes the ramped displacement into the fixed components of the region's nodes.
    void apply(State &s, double ramp) const;
    /// Force the region exerts on the body [N/m] (PdModel::reaction).
    geometry::Point reaction(const State &s) const { return model.reaction(s, index); }

  private:
    const PdModel      &model;
    std::size_t         index;
    std::vector<double> x0, y0, x1, y1;
  };
} // namespace pumpd::local
