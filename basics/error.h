// Errors the PD co-solver raises: bad input names the parameter and its allowed range;
// a non-finite state names the step at which it was found.
#pragma once

#include <stdexcept>
#include <string>

namespace pumpd
{
  /// A parameter outside its allowed range. what(): "<name> = <value>: <allowed range>".
  class InvalidParameter : public std::invalid_argument
  {
  public:
    InvalidParameter(const std::string &name, const std::string &value, const std::string &allowed)
      : std::invalid_argument(name + " = " + value + ": " + allowed)
    {}
  };

  /// A NaN or infinity in the PD state: the run stops.
  class NonFiniteState : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// Throws InvalidParameter unless lower < value (and value < upper where given).
  void require_positive(const std::string &name, double value);
  void require_range(const std::string &name, double value, double lower, double upper,
                     const std::string &allowed);
} // namespace pumpd
