// The section `Crack growth`, shared by every method: where growth stops besides the outline.
#pragma once

#include <limits>

namespace dealii
{
  class ParameterHandler;
}

namespace pumpd::coupling
{
  struct GrowthSettings
  {
    double max_crack_length = 0.;    ///< [m], the whole polyline; 0: no limit
    double hole_margin      = 0.001; ///< a tip stops this far from a hole [m]

    /// max_crack_length, infinity for no limit.
    double length_limit() const
    {
      return max_crack_length > 0. ? max_crack_length : std::numeric_limits<double>::infinity();
    }
    void add_parameters(dealii::ParameterHandler &prm);
  };
} // namespace pumpd::coupling
