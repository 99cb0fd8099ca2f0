#include "error.h"

#include <cctype>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace pumpd
{
  std::string to_text(double value, int precision)
  {
    std::ostringstream s;
    s << std::setprecision(precision) << value + 0.; // -0 prints as 0
    return s.str();
  }

  std::string one_line(const std::string &text)
  {
    std::string       s   = text;
    const std::string key = "Additional information:";
    if (const auto k = s.find(key); k != std::string::npos)
      s = s.substr(k + key.size());
    if (const auto k = s.find("Stacktrace:"); k != std::string::npos)
      s = s.substr(0, k);
    std::string out;
    for (const char c : s)
      if (std::isspace(static_cast<unsigned char>(c)))
        {
          if (!out.empty() && out.back() != ' ')
            out += ' ';
        }
      else
        out += c;
    while (!out.empty() && (out.back() == ' ' || out.back() == '-'))
      out.pop_back();
    if (out.size() > 300)
      out = out.substr(0, 297) + "...";
    return out;
  }

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
