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

  /// A value for a message: `precision` significant digits (std::to_string prints 5e-9 as 0.000000).
  std::string to_text(double value, int precision = 6);

  /// One line from an exception text: deal.II's "Additional information" if present, its
  /// stack trace dropped, whitespace collapsed, at most 300 characters.
  std::string one_line(const std::string &text);

  /// Throws InvalidParameter unless lower < value (and value < upper where given).
  void require_positive(const std::string &name, double value);
  void require_range(const std::string &name, double value, double lower, double upper,
                     const std::string &allowed);
} // namespace pumpd
