#include "error.h"

#include <cmath>
#include <sstream>

namespace pumpd
{
  namespace
  {
    std::string to_text(double v)
    {
      std::ostringstream s;
      s << v;
      return s.str();
    }
  } // namespace

  void require_positive(const std::string &name, double value)
  {
    if (!(value > 0.) || !std::isfinite(value))
      throw InvalidParameter(name, to_text(value), "must be a finite number > 0");
  }

  void require_range(const std::string &name, double value, double lower, double upper,
                     const std::string &allowed)
  {
    if (!(value >= lower && value <= upper))
      throw InvalidParameter(name, to_text(value), allowed);
  }
} // namespace pumpd
